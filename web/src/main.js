// The topay-viz page: wires the connection to the 3D layers and the panels (docs/viewer.md).

import * as THREE from 'three';
import 'uplot/dist/uPlot.min.css';
import './style.css';
import { Connection, defaultUrl } from './connection.js';
import { installHooks } from './hooks.js';
import { Viewer } from './scene/viewer.js';
import { MapLayer } from './scene/map.js';
import { ScanLayer } from './scene/scan.js';
import { RobotLayer } from './scene/robot.js';
import { TrajectoryLayer } from './scene/trajectory.js';
import { PathsLayer } from './scene/paths.js';
import { GoalLayer } from './scene/goal.js';
import { ContactsLayer } from './scene/contacts.js';
import { LayerToggles } from './panels/layers.js';
import { Plots } from './panels/plots.js';
import { ReplayBar } from './panels/replay.js';
import { MissionPanel, plannerPanel, robotPanel, simPanel, trackerPanel, vizPanel } from './panels/status.js';
import { ProcessTable } from './panels/processes.js';
import { DrivesPanel } from './panels/drives.js';

const PANEL_REFRESH_MS = 200;  // text panels: 5 Hz is plenty to read, and each repaint costs
const $ = (id) => document.getElementById(id);

const viewer = new Viewer($('viewport'), $('webgl-error'));
const layers = {
  map: new MapLayer(),
  scan: new ScanLayer(),
  robot: new RobotLayer(),
  trajectory: new TrajectoryLayer(),
  paths: new PathsLayer(),
  goal: new GoalLayer(),
  contacts: new ContactsLayer(),
};
// Each layer sits in its own group so the checkbox and the layer's own visibility don't clash.
// The map is in the cached static scene (re-rendered only when it or the camera changes).
const STATIC_LAYERS = new Set(['map']);
const layerRoots = {};
for (const [name, layer] of Object.entries(layers)) {
  const root = new THREE.Group();
  root.name = name;
  root.add(layer.object);
  (STATIC_LAYERS.has(name) ? viewer.staticScene : viewer.scene).add(root);
  layerRoots[name] = root;
}
const toggles = new LayerToggles(layerRoots, (name) => {
  if (STATIC_LAYERS.has(name)) viewer.invalidateStatic();
});

const plots = new Plots({
  v: $('plot-v'), omega: $('plot-omega'), accel: $('plot-accel'), joints: $('plot-joints'),
  jointSelect: $('joint-select'),
});

// Panels keep the latest message of their topic and are redrawn at most every PANEL_REFRESH_MS.
const panels = {
  '/robot/state': robotPanel($('robot-status')),
  '/planner/status': plannerPanel($('planner-status')),
  '/tracker/status': trackerPanel($('tracker-status')),
  '/mission/status': new MissionPanel($('mission-status'), $('mission-progress'), $('mission-progress-label')),
  '/sim/status': simPanel($('sim-status')),
  '/graph/status': new ProcessTable($('process-table'), $('graph-name')),
  '/can/drives': new DrivesPanel($('can-status'), $('drive-table')),
};
const latest = {};
const dirty = new Set();
const viz = vizPanel($('viz-stats'));
let vizStats = null;

const topics = {};
const statuses = [];
let playback = null;
let messages = 0;

let connection;
const replay = new ReplayBar({
  bar: $('replay-bar'), mode: $('mode'), play: $('play'), pause: $('pause'), speed: $('speed'),
  slider: $('slider'), timeLabel: $('time-label'),
}, (message) => connection.send(message), () => {
  // A seek re-sends every latched channel as it stood then (the map as a reset); a channel that had
  // no message yet at that time sends nothing, so drop what only the old time had.
  dropDrawn();
});

// What was drawn for another time: a seek (ours, or another client's: Playback's seek counter)
// resends every latched channel as it stood at the new time right after; a channel that had no
// message yet by then sends nothing, so everything is dropped first.
function dropDrawn() {
  for (const name of ['map', 'scan', 'trajectory', 'paths', 'goal', 'contacts']) layers[name].clear();
}

const handlers = {
  '/robot/description': (m) => {
    layers.robot.setDescription(m);
    plots.setJointNames(m.joint_names);
    $('robot-name').textContent = m.name || '';
  },
  '/robot/state': (m) => layers.robot.setState(m),
  '/map/blocks': (m) => layers.map.apply(m),
  '/lidar/scan': (m) => layers.scan.apply(m),
  '/planner/trajectory': (m) => layers.trajectory.apply(m),
  '/planner/paths': (m) => layers.paths.apply(m),
  '/goal': (m) => layers.goal.apply(m),
  '/sim/contacts': (m) => layers.contacts.apply(m),
  '/plot/state': (m) => plots.add(m),
  '/viz/stats': (m) => {
    vizStats = m;
  },
  '/viz/playback': (m) => {
    if (playback && m.seeks !== undefined && m.seeks !== playback.seeks) dropDrawn();
    playback = m;
    replay.update(m);
  },
};
for (const topic of Object.keys(panels)) {
  const draw = handlers[topic];
  handlers[topic] = (m) => {
    draw?.(m);
    latest[topic] = m;
    dirty.add(topic);
  };
}

function showStatus(level, text) {
  const names = ['info', 'warning', 'error'];
  statuses.push({ level, text, at: Date.now() });
  if (statuses.length > 50) statuses.shift();
  const log = $('status-log');
  const line = document.createElement('div');
  line.className = `status-${names[level] || 'info'}`;
  line.textContent = `${new Date().toLocaleTimeString()} ${names[level] || level}: ${text}`;
  log.prepend(line);
  while (log.childElementCount > 6) log.lastElementChild.remove();
}

const url = defaultUrl(window.location);
connection = new Connection(url, {
  topics: new Set(Object.keys(handlers)),
  onMessage(topic, payload) {
    messages++;
    topics[topic] = (topics[topic] || 0) + 1;
    try {
      handlers[topic](payload);
    } catch (error) {
      console.error(`${topic}:`, error);
    }
  },
  onStatus: showStatus,
  onConnected(connected) {
    const el = $('conn-status');
    el.textContent = connected ? `connected: ${url}` : `disconnected, reconnecting: ${url}`;
    el.className = connected ? 'badge good' : 'badge bad';
  },
  onServerInfo(info) {
    $('server-name').textContent = info.name || '';
    // topay-viz says its mode in the metadata; /viz/playback (latched) follows and drives the bar.
    if (!playback && info.metadata?.mode) {
      $('mode').textContent = info.metadata.mode === 'replay' ? 'REPLAY' : 'LIVE';
    }
  },
});
$('conn-status').textContent = `connecting: ${url}`;

const hooks = installHooks({
  connection, viewer, layers, plots, toggles, topics, statuses, playback: () => playback,
});

let lastPanels = 0;
viewer.onFrame((now) => {
  if (layers.map.update()) viewer.invalidateStatic();
  layers.scan.update();
  plots.update(now);
  if (now - lastPanels < PANEL_REFRESH_MS) return;
  lastPanels = now;
  for (const topic of dirty) panels[topic].update(latest[topic]);
  dirty.clear();
  viz.update({ stats: vizStats, fps: viewer.fps, messages, counts: hooks.counts() });
});

connection.start();
