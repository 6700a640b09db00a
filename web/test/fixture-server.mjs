#!/usr/bin/env node
// A development / test stand-in for topay-viz (docs/viewer.md), NOT part of the built page: serves
// a built page over HTTP and, on the same port, the Foxglove WebSocket protocol (through
// @foxglove/ws-protocol's FoxgloveServer) with hand-made messages on every channel. Latched
// channels are re-sent to each new subscriber; in --mode replay it runs a replay clock that obeys
// {"op": "x-topay-playback"} (play / pause / speed / seek, a seek re-sends the latched channels).
//
//   node web/test/fixture-server.mjs [--port 8765] [--root DIR] [--mode replay|live] [--voxels 50000]
//                                    [--static-map]   (no box moving through the map at 2 Hz)
// Without --root it builds the page into a temporary folder first (web/build.mjs).
// As a module: startFixture(options) -> { port, url, close() }.

import { execFileSync } from 'node:child_process';
import { createReadStream, existsSync, statSync } from 'node:fs';
import http from 'node:http';
import { tmpdir } from 'node:os';
import { dirname, extname, join, normalize, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import wsProtocol from '@foxglove/ws-protocol';
import { WebSocketServer } from 'ws';
import * as world from './fixture-world.mjs';

const { FoxgloveServer, StatusLevel } = wsProtocol;
const here = dirname(fileURLToPath(import.meta.url));

const TOPICS = {
  '/robot/description': ['RobotDescription', true],
  '/robot/state': ['RobotState', true],
  '/map/blocks': ['MapBlocks', true],
  '/lidar/scan': ['Scan', true],
  '/planner/trajectory': ['Trajectory', true],
  '/planner/paths': ['CandidatePaths', true],
  '/planner/status': ['PlannerStatus', true],
  '/goal': ['Goal', true],
  '/sim/contacts': ['Contacts', true],
  '/plot/state': ['PlotSample', false],
  '/tracker/status': ['TrackerStatus', true],
  '/mission/status': ['MissionStatus', true],
  '/graph/status': ['GraphStatus', true],
  '/can/drives': ['DriveStatus', true],
  '/sim/status': ['SimStatus', true],
  '/viz/stats': ['VizStats', true],
  '/viz/playback': ['Playback', true],
};

const MIME = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8', '.map': 'application/json', '.png': 'image/png',
};

function serveStatic(root) {
  return (request, response) => {
    const path = decodeURIComponent(new URL(request.url, 'http://x').pathname);
    let file = normalize(join(root, path === '/' ? 'index.html' : path));
    if (!file.startsWith(root) || !existsSync(file) || !statSync(file).isFile()) {
      response.writeHead(404, { 'content-type': 'text/plain' });
      response.end('not found');
      return;
    }
    response.writeHead(200, { 'content-type': MIME[extname(file)] || 'application/octet-stream' });
    createReadStream(file).pipe(response);
  };
}

/** A replay clock (or the wall clock in live mode). */
class Clock {
  constructor(mode, startT, lengthS) {
    this.mode = mode;
    this.startT = startT;
    this.endT = startT + lengthS;
    this.playing = true;
    this.speed = 1;
    this.anchorWall = Date.now() / 1000;
    this.anchorT = startT;
  }

  now() {
    const wall = Date.now() / 1000;
    if (this.mode === 'live') return wall;
    const t = this.anchorT + (this.playing ? (wall - this.anchorWall) * this.speed : 0);
    if (t >= this.endT) {
      this.#rebase(this.endT);
      this.playing = false;
      return this.endT;
    }
    return t;
  }

  #rebase(t) {
    this.anchorWall = Date.now() / 1000;
    this.anchorT = Math.min(this.endT, Math.max(this.startT, t));
  }

  command(message) {
    const t = this.now();
    switch (message.command) {
      case 'play': this.#rebase(t); this.playing = true; break;
      case 'pause': this.#rebase(t); this.playing = false; break;
      case 'speed': this.#rebase(t); this.speed = Number(message.speed) || 1; break;
      case 'seek': this.#rebase(Number(message.t)); break;
      default: return false;
    }
    return true;
  }

  playback() {
    return { mode: this.mode, t: this.now(), start_t: this.startT, end_t: this.endT, playing: this.playing, speed: this.speed };
  }
}

export async function startFixture(options = {}) {
  const mode = options.mode || 'replay';
  let root = options.root;
  if (!root) {
    root = join(tmpdir(), 'topay-viz-fixture-web');
    execFileSync(process.execPath, [join(here, '..', 'build.mjs'), '--out', root], { stdio: 'inherit' });
  }
  root = resolve(root);

  const bootT = Date.now() / 1000;
  const clock = new Clock(mode, bootT - 5, 300);
  const server = new FoxgloveServer({ name: 'topay-viz fixture' });
  const channels = {};  // topic -> channel id
  for (const [topic, [name]] of Object.entries(TOPICS)) {
    channels[topic] = server.addChannel({
      topic, encoding: 'json', schemaName: `topay.viz.${name}`, schemaEncoding: 'jsonschema',
      schema: JSON.stringify({ title: `topay.viz.${name}`, type: 'object' }),
    });
  }
  const latched = new Map();  // channel id -> { payload: Buffer, t }
  const clients = new Map();  // connection -> Map(channel id -> subscription id)
  let framesSent = 0, bytesSent = 0;

  const frame = (subscriptionId, t, payload) => {
    const header = Buffer.alloc(13);
    header.writeUInt8(0x01, 0);
    header.writeUInt32LE(subscriptionId, 1);
    header.writeBigUInt64LE(BigInt(Math.round(t * 1e6)) * 1000n, 5);
    return Buffer.concat([header, payload]);
  };

  const publish = (topic, message, t = clock.now()) => {
    const id = channels[topic];
    const payload = Buffer.from(JSON.stringify(message));
    if (topic === '/map/blocks' && !message.reset) {
      latched.set(id, { payload: Buffer.from(JSON.stringify(fullMap(t))), t });  // latched as a full reset
    } else if (TOPICS[topic][1]) {
      latched.set(id, { payload, t });
    }
    server.sendMessage(id, BigInt(Math.round(t * 1e6)) * 1000n, payload);
    for (const subscriptions of clients.values()) {
      if (subscriptions.has(id)) {
        framesSent++;
        bytesSent += payload.length + 13;
      }
    }
  };

  // ---------------------------------------------------------------- the world
  const staticVoxels = world.makeWorld(options.voxels ?? 50000);
  const staticBlocks = world.toBlocks(staticVoxels);
  const points = world.centres(staticVoxels);
  let mapSeq = 1;
  let movingKeys = [];
  let blocks = staticBlocks;
  let occupied = staticVoxels.size;

  const fullMap = (t) => world.mapMessage(t, mapSeq, blocks, [...blocks.keys()], true, occupied);
  const description = world.robotDescription();
  let trajectory = null;
  let trajectoryStart = 0;
  const newTrajectory = (t) => {
    trajectoryStart = t;
    const id = 100 + Math.floor((t - clock.startT) / 23);
    trajectory = world.trajectoryMessage(t, id, id - 88);
  };

  const publishLatchedWorld = (t) => {
    publish('/robot/description', description, t);
    publish('/map/blocks', fullMap(t), t);
    newTrajectory(t - ((t - clock.startT) % 23));
    publish('/planner/trajectory', trajectory, t);
    publish('/planner/paths', world.pathsMessage(t, trajectory), t);
    publish('/goal', world.goalMessage(t, trajectory), t);
    publish('/sim/contacts', world.contactsMessage(t), t);
  };

  /** The box that moves in front of the wall: re-sends the blocks it leaves and enters. */
  const moveBox = (t) => {
    const x = -2 + 1.5 * Math.sin(t * 0.5);
    const dynamic = new Set();
    const y0 = -6.0;
    for (let i = 0; i < 8; i++) for (let j = 0; j < 8; j++) for (let k = 0; k < 8; k++) {
      const vi = Math.floor((x - world.ORIGIN[0]) / world.RES) + i;
      const vj = Math.floor((y0 - world.ORIGIN[1]) / world.RES) + j;
      dynamic.add(vi + world.DIMS[0] * (vj + world.DIMS[1] * k));
    }
    const merged = new Map([...staticBlocks].map(([key, list]) => [key, list.slice()]));
    const extra = new Set([...dynamic].filter((v) => !staticVoxels.has(v)));
    world.toBlocks(extra, merged);
    const moved = world.toBlocks(extra);
    const keys = new Set([...movingKeys, ...moved.keys()]);
    // A key the box left and that has no static voxels is sent as "" (the block is now empty).
    blocks = merged;
    occupied = staticVoxels.size + extra.size;
    movingKeys = [...moved.keys()];
    mapSeq++;
    publish('/map/blocks', world.mapMessage(t, mapSeq, blocks, [...keys], false, occupied), t);
  };

  // ---------------------------------------------------------------- timers
  let lastT = clock.now();
  const timers = [];
  const every = (ms, fn) => timers.push(setInterval(() => {
    try {
      fn(clock.now());
    } catch (error) {
      console.error(error);
    }
  }, ms));

  publishLatchedWorld(clock.now());
  every(33, (t) => {
    if (t < lastT - 0.5) publishLatchedWorld(t);  // the clock went back: a seek
    lastT = t;
    const along = (t - trajectoryStart) % 23;
    if (t - trajectoryStart >= 23) {
      newTrajectory(t);
      publish('/planner/trajectory', trajectory, t);
      publish('/planner/paths', world.pathsMessage(t, trajectory), t);
      publish('/goal', world.goalMessage(t, trajectory), t);
    }
    const p = world.plan(along);
    const fk = world.forwardKinematics(p.x, p.y, p.yaw, p.q);
    publish('/robot/state', {
      t, x_m: p.x, y_m: p.y, yaw_rad: p.yaw, v_mps: along < 20 ? p.v : 0, omega_radps: along < 20 ? p.omega : 0,
      q_rad: p.q, gripper: 0.04, links: fk.links, p_WE_m: fk.p_WE_m,
    }, t);
  });
  every(50, (t) => {
    const along = (t - trajectoryStart) % 23;
    const p = world.plan(along);
    const active = along < 20;
    const noise = () => (Math.random() - 0.5) * 0.02;
    publish('/plot/state', {
      t, trajectory_id: active ? trajectory.trajectory_id : 0,
      v_mps: (active ? p.v : 0) + noise(), omega_radps: (active ? p.omega : 0) + noise(),
      q_rad: p.q.map((q) => q + noise()),
      v_plan_mps: active ? p.v : null, omega_plan_radps: active ? p.omega : null,
      a_plan_mps2: active ? p.a : null, beta_plan_radps2: active ? p.beta : null,
      q_plan_rad: active ? p.q : null,
    }, t);
  });
  every(200, (t) => {
    const p = world.plan((t - trajectoryStart) % 23);
    publish('/lidar/scan', world.scanMessage(t, [p.x + 0.15 * Math.cos(p.yaw), p.y + 0.15 * Math.sin(p.yaw), 0.5], points), t);
  });
  every(100, (t) => {
    publish('/planner/status', world.plannerStatus(t, trajectory), t);
    publish('/tracker/status', world.trackerStatus(t, trajectory, (t - trajectoryStart) % 23), t);
    publish('/mission/status', world.missionStatus(t, clock.startT), t);
  });
  every(200, (t) => publish('/can/drives', world.driveStatus(t), t));
  every(500, (t) => {
    publish('/sim/status', world.simStatus(t, clock.startT), t);
    if (options.movingBox !== false) moveBox(t);
  });
  every(250, (t) => publish('/viz/playback', clock.playback(), t));
  every(1000, (t) => {
    publish('/graph/status', world.graphStatus(t), t);
    publish('/viz/stats', {
      t, clients: clients.size, lcm_messages: Math.floor((t - clock.startT) * 400), lcm_malformed: 0,
      frames_sent: framesSent, frames_dropped: 0, bytes_sent: bytesSent, bytes_per_s: 250000,
    }, t);
  });

  // ---------------------------------------------------------------- connections
  const httpServer = http.createServer(serveStatic(root));
  const wss = new WebSocketServer({ server: httpServer, handleProtocols: (protocols) => server.handleProtocols(protocols) });
  server.on('error', (error) => {
    if (!/x-topay-playback/.test(error.message)) console.error('fixture:', error.message);
  });
  wss.on('connection', (connection, request) => {
    const subscriptions = new Map();
    clients.set(connection, subscriptions);
    server.handleConnection(connection, `${request.socket.remoteAddress}:${request.socket.remotePort}`);
    server.sendStatus({ level: StatusLevel.INFO, message: `topay-viz fixture (${mode})` }, connection);
    connection.on('close', () => clients.delete(connection));
    connection.on('message', (data, isBinary) => {
      if (isBinary) return;
      let message;
      try {
        message = JSON.parse(data.toString());
      } catch {
        return;
      }
      if (message.op === 'subscribe') {
        // FoxgloveServer has registered them; send each new subscriber the latched message.
        for (const { id, channelId } of message.subscriptions || []) {
          subscriptions.set(channelId, id);
          const last = latched.get(channelId);
          if (last) connection.send(frame(id, last.t, last.payload));
        }
      } else if (message.op === 'unsubscribe') {
        for (const [channelId, id] of subscriptions) {
          if ((message.subscriptionIds || []).includes(id)) subscriptions.delete(channelId);
        }
      } else if (message.op === 'x-topay-playback') {
        if (mode !== 'replay') {
          server.sendStatus({ level: StatusLevel.WARNING, message: 'live mode: playback commands are ignored' }, connection);
          return;
        }
        if (!clock.command(message)) return;
        if (message.command === 'seek') {
          lastT = clock.now();
          publishLatchedWorld(lastT);
        }
        publish('/viz/playback', clock.playback());
      }
    });
  });

  await new Promise((ok) => httpServer.listen(options.port ?? 8765, options.host ?? '127.0.0.1', ok));
  const port = httpServer.address().port;
  return {
    port,
    url: `http://127.0.0.1:${port}/`,
    voxels: staticVoxels.size,
    close: () => new Promise((ok) => {
      for (const timer of timers) clearInterval(timer);
      for (const client of wss.clients) client.terminate();
      wss.close();
      httpServer.close(() => ok());
    }),
  };
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const options = {};
  const argv = process.argv.slice(2);
  for (let i = 0; i < argv.length; i++) {
    const [key, value] = [argv[i], argv[i + 1]];
    if (key === '--port') options.port = Number(value), i++;
    else if (key === '--root') options.root = value, i++;
    else if (key === '--mode') options.mode = value, i++;
    else if (key === '--voxels') options.voxels = Number(value), i++;
    else if (key === '--host') options.host = value, i++;
    else if (key === '--static-map') options.movingBox = false;
    else {
      console.error('usage: fixture-server.mjs [--port 8765] [--root DIR] [--mode replay|live] [--voxels N] [--host H] [--static-map]');
      process.exit(2);
    }
  }
  const fixture = await startFixture(options);
  console.log(`topay-viz fixture: ${fixture.url} (${options.mode || 'replay'}, ${fixture.voxels} map voxels)`);
}
