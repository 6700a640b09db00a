// topay-viz as Foxglove sees it (docs/viewer.md), on a real recorded demo log:
//   - serverInfo (replay: capability "time", metadata.mode "replay") and an advertise of the 17
//     channels, each encoding "json" / schemaEncoding "jsonschema" / schemaName topay.viz.<Name>;
//   - @foxglove/ws-protocol's FoxgloveClient subscribes to every channel and collects for ~8 s at
//     --speed 4: every payload is UTF-8 JSON that conforms to its channel's advertised schema
//     (json_schema.mjs) and has every property the schema names; frames carry a log time within
//     the log; scans and map blocks decode to whole points / indices; every channel the demo
//     produces has at least one message (/sim/contacts may have none in a clean run);
//   - a second client sending garbage (non-JSON text, a binary frame, an unknown op, a subscribe
//     to channel 9999) gets one status per request, stays connected and is still served, and the
//     first client keeps receiving;
//   - SIGINT stops topay-viz with exit code 0.
//
//   TOPAY_VIZ=build/bin/topay-viz TOPAY_DEMO_LOG=.../graph.lcmlog node --test tests/web/foxglove_client.test.mjs
// Skipped (with the reason) when the binary, the log or web/node_modules' packages are missing.

import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { missingProperties, validate } from './json_schema.mjs';
import { TOPICS, missingInputs, startViz, waitFor, webPackage } from './viz_support.mjs';

const SPEED = 4;
const COLLECT_MS = 8000;
const MAY_BE_EMPTY = new Set(['/sim/contacts']);

const skip = missingInputs({ viz: true, log: true, packages: ['ws', '@foxglove/ws-protocol'] });
const { FoxgloveClient } = webPackage('@foxglove/ws-protocol') || {};
const WebSocket = webPackage('ws');

let viz;           // startViz()
let client;        // the well-behaved FoxgloveClient
let serverInfo;
const channels = [];  // advertised
const received = new Map();  // topic -> [{ timestampNs, bytes, at (arrival, ms) }]
const statuses = [];         // to the well-behaved client
let collectStart;
let vizStart;

function connect(url) {
  const ws = new WebSocket(url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]);
  return new FoxgloveClient({ ws });
}

before(async () => {
  if (skip) return;
  vizStart = Date.now();
  viz = await startViz(['--speed', String(SPEED)]);
  client = connect(viz.wsUrl);
  client.on('serverInfo', (info) => (serverInfo = info));
  client.on('status', (status) => statuses.push(status));
  client.on('advertise', (list) => channels.push(...list));
  const bySubscription = new Map();
  client.on('message', ({ subscriptionId, timestamp, data }) => {
    const channel = bySubscription.get(subscriptionId);
    const bytes = new Uint8Array(data.buffer, data.byteOffset, data.byteLength).slice();
    received.get(channel.topic).push({ timestampNs: timestamp, bytes, at: Date.now() });
  });
  await waitFor(() => serverInfo && channels.length >= TOPICS.length, { what: 'serverInfo and advertise' });
  for (const channel of channels) {
    received.set(channel.topic, []);
    bySubscription.set(client.subscribe(channel.id), channel);
  }
  collectStart = Date.now();
});

after(async () => {
  client?.close();
  if (viz) await viz.stop();  // the last test checks the exit; this is for a failed run
});

test('serverInfo says replay; the 17 channels of docs/viewer.md are advertised as JSON with JSON schemas', { skip }, () => {
  assert.equal(serverInfo.name, 'topay-viz');
  assert.ok(serverInfo.capabilities.includes('time'), `capabilities ${serverInfo.capabilities}`);
  assert.equal(serverInfo.metadata?.mode, 'replay');
  assert.deepEqual(channels.map((c) => c.topic).sort(), [...TOPICS].sort());
  assert.equal(new Set(channels.map((c) => c.id)).size, TOPICS.length, 'channel ids are unique');
  for (const c of channels) {
    assert.equal(c.encoding, 'json', c.topic);
    assert.equal(c.schemaEncoding, 'jsonschema', c.topic);
    assert.match(c.schemaName, /^topay\.viz\.[A-Z][A-Za-z]+$/, c.topic);
    const schema = JSON.parse(c.schema);
    assert.equal(schema.type, 'object', c.topic);
    assert.ok(Object.keys(schema.properties).length > 0, c.topic);
    assert.deepEqual(validate(schema, {}), [], `${c.topic}: the schema uses only what json_schema.mjs checks`);
  }
});

test('a client sending garbage gets a status per request and is still served; the others are not disturbed', { skip }, async () => {
  const before = received.get('/viz/playback').length;
  const ws = new WebSocket(viz.wsUrl, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]);
  const texts = [];
  const frames = [];
  ws.on('message', (data, isBinary) => (isBinary ? frames.push(data) : texts.push(JSON.parse(data.toString()))));
  await new Promise((ok, fail) => ws.once('open', ok).once('error', fail));
  assert.equal(ws.protocol, FoxgloveClient.SUPPORTED_SUBPROTOCOL);
  await waitFor(() => texts.some((m) => m.op === 'advertise'), { what: 'advertise to the garbage client' });
  const playbackId = texts.find((m) => m.op === 'advertise').channels.find((c) => c.topic === '/viz/playback').id;

  const statusesNow = () => texts.filter((m) => m.op === 'status');
  const requests = [
    ['non-JSON text', () => ws.send('{"op": subscribe, this is not JSON')],
    ['a binary frame', () => ws.send(Buffer.from([0x01, 0xff, 0xff, 0xff, 0xff, 0x00]), { binary: true })],
    ['an unknown op', () => ws.send(JSON.stringify({ op: 'x-no-such-op', x: 1 }))],
    ['a subscribe to channel 9999', () => ws.send(JSON.stringify({ op: 'subscribe', subscriptions: [{ id: 7, channelId: 9999 }] }))],
  ];
  for (const [what, send] of requests) {
    const count = statusesNow().length;
    send();
    await waitFor(() => statusesNow().length > count, { timeoutMs: 5000, what: `a status answering ${what}` });
    const status = statusesNow().at(-1);
    assert.ok(status.level === 1 || status.level === 2, `${what}: level ${status.level} (warning or error)`);
    assert.ok(typeof status.message === 'string' && status.message.length > 0, `${what}: a message`);
  }
  assert.match(statusesNow().at(-1).message, /9999/);
  assert.equal(frames.filter((f) => f[0] === 0x01).length, 0, 'nothing was subscribed yet, so no message data');
  assert.ok(frames.every((f) => f[0] === 0x02 && f.length === 9), 'only Time frames (capability "time")');

  // Still connected and served: a valid subscribe gets the latched /viz/playback at once.
  ws.send(JSON.stringify({ op: 'subscribe', subscriptions: [{ id: 8, channelId: playbackId }] }));
  await waitFor(() => frames.some((f) => f[0] === 0x01 && f.readUInt32LE(1) === 8), { timeoutMs: 5000, what: 'data on the valid subscription' });
  ws.close();

  // The well-behaved client kept receiving (/viz/playback comes at 4 Hz).
  await waitFor(() => received.get('/viz/playback').length >= before + 2, { timeoutMs: 5000, what: 'more /viz/playback to the first client' });
  assert.equal(statuses.filter((s) => s.level >= 1).length, 0, 'the first client got no warnings or errors');
});

test('every message decodes and conforms to its schema; the demo channels all have messages', { skip }, async () => {
  const silent = () => TOPICS.filter((t) => !MAY_BE_EMPTY.has(t) && received.get(t).length === 0);
  await waitFor(() => Date.now() - collectStart >= COLLECT_MS && silent().length === 0,
    { timeoutMs: COLLECT_MS + 20000, what: `a message on each demo channel (none yet on ${silent().join(', ')})` })
    .catch(() => {});  // the assertion below names the silent channels
  assert.deepEqual(silent(), [], 'channels without a message');

  const decoder = new TextDecoder('utf-8', { fatal: true });
  const span = JSON.parse(decoder.decode(received.get('/viz/playback')[0].bytes));
  const summary = {};
  for (const channel of channels) {
    const schema = JSON.parse(channel.schema);
    const messages = received.get(channel.topic);
    summary[channel.topic] = messages.length;
    messages.forEach(({ timestampNs, bytes }, i) => {
      const where = `${channel.topic} #${i}`;
      let payload;
      assert.doesNotThrow(() => (payload = JSON.parse(decoder.decode(bytes))), `${where}: UTF-8 JSON`);
      assert.deepEqual(validate(schema, payload), [], `${where}: conforms to ${channel.schemaName}`);
      assert.deepEqual(missingProperties(schema, payload), [], `${where}: has every property of ${channel.schemaName}`);
      // The frame's log time is a time of the log (/viz/stats: the server's clock). It is not
      // always the payload's t: the log event's time, up to ~1 s later (docs/viewer.md says utime).
      const logT = Number(timestampNs) * 1e-9;
      if (channel.topic !== '/viz/stats') {
        assert.ok(logT >= span.start_t - 1e-3 && logT <= span.end_t + 1e-3, `${where}: log time ${logT} outside the log ${JSON.stringify(span)}`);
      }
      checkContent(channel.topic, payload, where);
    });
  }
  console.log(`messages per channel in ${((Date.now() - collectStart) / 1000).toFixed(1)} s: ${JSON.stringify(summary)}`);

  // Cross-channel facts of the demo.
  const last = (topic) => JSON.parse(decoder.decode(received.get(topic).at(-1).bytes));
  const description = last('/robot/description');
  const state = last('/robot/state');
  assert.equal(state.links.length, description.links.length, 'a pose per described link');
  assert.equal(state.q_rad.length, description.joint_names.length, 'q in joint_names order');
  const firstMap = JSON.parse(decoder.decode(received.get('/map/blocks')[0].bytes));
  assert.equal(firstMap.reset, true, 'a new subscriber gets the map as a reset');
  const playback = last('/viz/playback');
  assert.equal(playback.mode, 'replay');
  assert.equal(playback.speed, SPEED);
  assert.ok(playback.start_t < playback.end_t && playback.t >= playback.start_t && playback.t <= playback.end_t + 1e-6,
    `playback ${JSON.stringify(playback)}`);
  // The replay starts at the log's start and runs at about SPEED: log time <= SPEED x wall time.
  for (const { bytes, at } of received.get('/viz/playback')) {
    const p = JSON.parse(decoder.decode(bytes));
    const wallS = (at - vizStart) / 1000;
    assert.ok(p.t - p.start_t <= SPEED * wallS + 1, `log time ${(p.t - p.start_t).toFixed(1)} s after ${wallS.toFixed(1)} s at ${SPEED}x`);
  }
  assert.ok(playback.t - playback.start_t > 0.5 * SPEED * COLLECT_MS / 1000 || playback.t >= playback.end_t - 1e-3,
    `the replay clock moved at about ${SPEED}x: ${JSON.stringify(playback)}`);
  const stats = last('/viz/stats');
  assert.ok(stats.clients >= 1 && stats.frames_sent > 0 && stats.bytes_sent > 0, `stats ${JSON.stringify(stats)}`);
});

// What a schema cannot say: base64 arrays hold whole items, counts match.
function checkContent(topic, m, where) {
  const bytes = (b64) => Buffer.from(b64, 'base64').length;
  if (topic === '/lidar/scan') {
    assert.equal(bytes(m.points_cm), 6 * m.count, `${where}: 3 int16 per point`);
    assert.ok(m.count <= m.points_total, `${where}: count ${m.count} <= points_total ${m.points_total}`);
  } else if (topic === '/map/blocks') {
    assert.equal(m.block_edge, 16, where);
    for (const block of m.blocks) {
      assert.equal(block.key.length, 3, `${where}: block key`);
      assert.equal(bytes(block.occupied) % 2, 0, `${where}: uint16 indices`);
    }
    assert.ok(m.occupied_total >= 0, where);
  } else if (topic === '/planner/trajectory') {
    assert.equal(m.ee_path_m.length, m.base_path_m.length, `${where}: ee and base paths sampled alike`);
    assert.equal(m.samples.t_s.length, m.base_path_m.length, `${where}: a sample per path point`);
  } else if (topic === '/planner/paths') {
    assert.ok(m.paths.filter((p) => p.chosen).length <= 1, `${where}: at most one chosen path`);
  } else if (topic === '/viz/playback') {
    assert.ok(m.mode === 'replay', where);
  }
}

test('SIGINT stops topay-viz with exit code 0', { skip }, async () => {
  client.close();
  const { code, signal, output } = await viz.stop();
  viz = null;
  assert.equal(signal, null, output);
  assert.equal(code, 0, output);
});

