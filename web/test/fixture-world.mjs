// Hand-made messages for every topay-viz channel (docs/viewer.md), for the page's development and
// end-to-end tests only (not part of the built page): a Tables-like occupancy map of about
// `voxels` voxels, a 9-link robot with boxes / cylinders / spheres driven along a trajectory,
// candidate paths, a goal, contacts, plots and status panels.

import * as THREE from 'three';

export const RES = 0.05;
export const ORIGIN = [-10, -10, 0];
export const DIMS = [400, 400, 50];
const EDGE = 16;
const [NX, NY, NZ] = DIMS;

// ---------------------------------------------------------------- map

function voxelIndex(i, j, k) {
  return i + NX * (j + NY * k);
}

function addBoxVoxels(set, min, max) {
  const lo = min.map((v, a) => Math.max(0, Math.floor((v - ORIGIN[a]) / RES)));
  const hi = max.map((v, a) => Math.min(DIMS[a] - 1, Math.ceil((v - ORIGIN[a]) / RES) - 1));
  for (let k = lo[2]; k <= hi[2]; k++)
    for (let j = lo[1]; j <= hi[1]; j++)
      for (let i = lo[0]; i <= hi[0]; i++) set.add(voxelIndex(i, j, k));
}

/** Static world: room walls, tables, boxes, then random clutter up to `target` voxels. */
export function makeWorld(target = 50000, seed = 7) {
  const set = new Set();
  const wall = 1.2;
  addBoxVoxels(set, [-8, -8, 0], [8, -7.96, wall]);
  addBoxVoxels(set, [-8, 7.96, 0], [8, 8, wall]);
  addBoxVoxels(set, [-8, -8, 0], [-7.96, 8, wall]);
  addBoxVoxels(set, [7.96, -8, 0], [8, 8, wall]);
  const tables = [[-4, 3], [0, 4.5], [4, 3], [-4, -3.5], [3.5, -4], [5.5, 0.5]];
  for (const [x, y] of tables) {
    addBoxVoxels(set, [x - 0.8, y - 0.4, 0.72], [x + 0.8, y + 0.4, 0.77]);
    for (const [dx, dy] of [[-0.75, -0.35], [0.75, -0.35], [-0.75, 0.35], [0.75, 0.35]])
      addBoxVoxels(set, [x + dx - 0.025, y + dy - 0.025, 0], [x + dx + 0.025, y + dy + 0.025, 0.72]);
    addBoxVoxels(set, [x - 0.15, y - 0.1, 0.77], [x + 0.15, y + 0.1, 0.97]);  // a box on the table
  }
  let state = seed;
  const random = () => {
    state = (state * 1103515245 + 12345) % 2147483648;
    return state / 2147483648;
  };
  while (set.size < target) {
    const x = -7 + 14 * random(), y = -7 + 14 * random();
    if (Math.abs(y) < 1.2) continue;  // keep the robot's corridor free
    const s = 0.2 + 0.3 * random();
    addBoxVoxels(set, [x, y, 0], [x + s, y + s, s * (1 + random())]);
  }
  return set;
}

/** Block key string "bi,bj,bk" -> Set of local indices, from a set of voxel indices. */
export function toBlocks(voxels, into = new Map()) {
  for (const v of voxels) {
    const i = v % NX, j = Math.floor(v / NX) % NY, k = Math.floor(v / (NX * NY));
    const key = `${Math.floor(i / EDGE)},${Math.floor(j / EDGE)},${Math.floor(k / EDGE)}`;
    let block = into.get(key);
    if (!block) into.set(key, (block = []));
    block.push((i % EDGE) + EDGE * ((j % EDGE) + EDGE * (k % EDGE)));
  }
  return into;
}

export function encodeBlock(key, locals) {
  const array = Uint16Array.from(locals || []);
  return {
    key: key.split(',').map(Number),
    occupied: array.length ? Buffer.from(array.buffer, array.byteOffset, array.byteLength).toString('base64') : '',
  };
}

export function mapMessage(t, seq, blocks, keys, reset, total) {
  return {
    map_seq: seq, t, resolution_m: RES, origin_W_m: ORIGIN, dims: DIMS, block_edge: EDGE, reset,
    blocks: keys.map((key) => encodeBlock(key, blocks.get(key))), occupied_total: total,
  };
}

/** Voxel centres (x, y, z triplets) of a voxel set, for the fake scans. */
export function centres(voxels) {
  const out = new Float32Array(3 * voxels.size);
  let n = 0;
  for (const v of voxels) {
    const i = v % NX, j = Math.floor(v / NX) % NY, k = Math.floor(v / (NX * NY));
    out[n++] = ORIGIN[0] + (i + 0.5) * RES;
    out[n++] = ORIGIN[1] + (j + 0.5) * RES;
    out[n++] = ORIGIN[2] + (k + 0.5) * RES;
  }
  return out;
}

export function scanMessage(t, sensor, points, maxPoints = 3000) {
  const [sx, sy, sz] = sensor;
  const picked = [];
  for (let p = 0; p < points.length; p += 3) {
    const dx = points[p] - sx, dy = points[p + 1] - sy, dz = points[p + 2] - sz;
    if (dx * dx + dy * dy < 36 && Math.abs(dz) < 3) picked.push(dx, dy, dz);
  }
  const stride = Math.max(1, Math.ceil(picked.length / 3 / maxPoints));
  const cm = [];
  for (let p = 0; p < picked.length; p += 3 * stride)
    for (let a = 0; a < 3; a++) cm.push(Math.round(picked[p + a] * 100 + (Math.random() - 0.5) * 2));
  const array = Int16Array.from(cm);
  return {
    t, p_WS_m: sensor, count: array.length / 3, points_total: picked.length / 3,
    points_cm: Buffer.from(array.buffer).toString('base64'),
  };
}

// ---------------------------------------------------------------- robot

const GREY = [0.55, 0.58, 0.62, 1];
const ORANGE = [0.95, 0.55, 0.15, 1];
const DARK = [0.2, 0.22, 0.25, 1];
const ID = [1, 0, 0, 0];
// Joint i: offset from the previous frame, then a rotation about AXES[i].
const MOUNT = [0.1, 0, 0.42];
const OFFSETS = [[0, 0, 0], [0, 0, 0.12], [0, 0, 0.25], [0, 0, 0.1], [0, 0, 0.25], [0, 0, 0.1], [0, 0, 0.1]];
const AXES = ['z', 'y', 'z', 'y', 'z', 'y', 'z'];
const GRIPPER_OFFSET = [0, 0, 0.08];
const EE_OFFSET = [0, 0, 0.12];

function visual(shape, size, p, rgba, quat = ID) {
  return { shape, size_m: size, p_LV_m: p, quat_LV: quat, rgba };
}

export function robotDescription() {
  const joint_names = ['q1', 'q2', 'q3', 'q4', 'q5', 'q6', 'q7'];
  const halfTurnX = [Math.SQRT1_2, Math.SQRT1_2, 0, 0];  // a cylinder lying along y
  return {
    name: 'topay-fixture-robot',
    joint_names,
    base: { radius_m: 0.32, height_m: 0.35 },
    links: [
      { name: 'base_link', visuals: [
        visual('cylinder', [0.64, 0.64, 0.3], [0, 0, 0.2], GREY),
        visual('box', [0.3, 0.3, 0.1], [0.1, 0, 0.37], DARK),
        visual('cylinder', [0.2, 0.2, 0.05], [0, 0.3, 0.1], DARK, halfTurnX),
        visual('cylinder', [0.2, 0.2, 0.05], [0, -0.3, 0.1], DARK, halfTurnX),
      ] },
      { name: 'link1', visuals: [visual('cylinder', [0.12, 0.12, 0.12], [0, 0, 0.06], ORANGE)] },
      { name: 'link2', visuals: [visual('box', [0.1, 0.1, 0.25], [0, 0, 0.125], GREY)] },
      { name: 'link3', visuals: [visual('cylinder', [0.09, 0.09, 0.1], [0, 0, 0.05], ORANGE)] },
      { name: 'link4', visuals: [visual('sphere', [0.11, 0.11, 0.11], [0, 0, 0], ORANGE),
        visual('box', [0.08, 0.08, 0.25], [0, 0, 0.125], GREY)] },
      { name: 'link5', visuals: [visual('cylinder', [0.08, 0.08, 0.1], [0, 0, 0.05], ORANGE)] },
      { name: 'link6', visuals: [visual('box', [0.07, 0.07, 0.1], [0, 0, 0.05], GREY)] },
      { name: 'link7', visuals: [visual('sphere', [0.08, 0.08, 0.08], [0, 0, 0.04], ORANGE)] },
      { name: 'gripper', visuals: [visual('box', [0.12, 0.04, 0.03], [0, 0, 0.015], DARK),
        visual('box', [0.015, 0.03, 0.08], [0.045, 0, 0.07], DARK),
        visual('box', [0.015, 0.03, 0.08], [-0.045, 0, 0.07], DARK)] },
    ],
  };
}

const AXIS = { x: new THREE.Vector3(1, 0, 0), y: new THREE.Vector3(0, 1, 0), z: new THREE.Vector3(0, 0, 1) };

function pose(matrix) {
  const p = new THREE.Vector3(), q = new THREE.Quaternion(), s = new THREE.Vector3();
  matrix.decompose(p, q, s);
  return { p_WL_m: [p.x, p.y, p.z], quat_WL: [q.w, q.x, q.y, q.z] };
}

/** Link poses (description order) and p_WE for a base pose and joint angles. */
export function forwardKinematics(x, y, yaw, q) {
  const base = new THREE.Matrix4().makeRotationZ(yaw).setPosition(x, y, 0);
  const links = [pose(base)];
  const frame = base.clone().multiply(new THREE.Matrix4().makeTranslation(...MOUNT));
  const step = new THREE.Matrix4();
  for (let i = 0; i < 7; i++) {
    frame.multiply(step.makeTranslation(...OFFSETS[i]));
    frame.multiply(step.makeRotationAxis(AXIS[AXES[i]], q[i] || 0));
    links.push(pose(frame));
  }
  frame.multiply(step.makeTranslation(...GRIPPER_OFFSET));
  links.push(pose(frame));
  const ee = new THREE.Vector3(...EE_OFFSET).applyMatrix4(frame);
  return { links, p_WE_m: [ee.x, ee.y, ee.z] };
}

// ---------------------------------------------------------------- trajectory

export const TRAJ_DURATION_S = 20;
const SAMPLE_DT = 0.1;

/** The planned base pose, velocities and joints at time s along the trajectory. */
export function plan(s) {
  const u = Math.min(1, Math.max(0, s / TRAJ_DURATION_S));
  const x = -6 + 12 * u;
  const y = 0.6 * Math.sin(2 * Math.PI * u);
  const dx = 12 / TRAJ_DURATION_S;
  const dy = (0.6 * 2 * Math.PI / TRAJ_DURATION_S) * Math.cos(2 * Math.PI * u);
  const ddy = -(0.6 * (2 * Math.PI / TRAJ_DURATION_S) ** 2) * Math.sin(2 * Math.PI * u);
  const yaw = Math.atan2(dy, dx);
  const v = Math.hypot(dx, dy);
  const omega = (dx * ddy) / (dx * dx + dy * dy);
  const q = [0.6 * Math.sin(0.5 * s), 0.5 + 0.3 * Math.sin(0.3 * s), 0.4 * Math.cos(0.4 * s),
    1.2 + 0.3 * Math.sin(0.6 * s), 0.3 * Math.sin(0.7 * s), 0.6 + 0.2 * Math.cos(0.5 * s), 0.5 * Math.sin(0.9 * s)];
  const a = -0.2 * Math.sin(2 * Math.PI * u);
  const beta = 0.3 * Math.cos(2 * Math.PI * u);
  return { x, y, yaw, v, omega, a, beta, q };
}

export function trajectoryMessage(startT, id, goalId) {
  const base_path_m = [], ee_path_m = [];
  const samples = { t_s: [], v_mps: [], omega_radps: [], a_mps2: [], beta_radps2: [], q_rad: [] };
  for (let s = 0; s <= TRAJ_DURATION_S + 1e-9; s += SAMPLE_DT) {
    const p = plan(s);
    base_path_m.push([p.x, p.y]);
    ee_path_m.push(forwardKinematics(p.x, p.y, p.yaw, p.q).p_WE_m);
    samples.t_s.push(s);
    samples.v_mps.push(p.v);
    samples.omega_radps.push(p.omega);
    samples.a_mps2.push(p.a);
    samples.beta_radps2.push(p.beta);
    samples.q_rad.push(p.q);
  }
  return { trajectory_id: id, goal_id: goalId, start_t: startT, duration_s: TRAJ_DURATION_S, base_path_m, ee_path_m, samples };
}

export function pathsMessage(t, trajectory) {
  const chosen = trajectory.base_path_m.filter((_, i) => i % 5 === 0);
  const bent = (dy) => chosen.map(([x, y], i) => [x, y + dy * Math.sin((Math.PI * i) / (chosen.length - 1))]);
  return {
    t, goal_id: trajectory.goal_id, trajectory_id: trajectory.trajectory_id,
    paths: [
      { points_m: chosen, length_m: 12.4, chosen: true, source: 'front-end' },
      { points_m: bent(2.5), length_m: 14.1, chosen: false, source: 'front-end' },
      { points_m: bent(-2.2), length_m: 13.8, chosen: false, source: 'warm-start' },
    ],
  };
}

export function goalMessage(t, trajectory) {
  const end = plan(TRAJ_DURATION_S);
  const q = new THREE.Quaternion().setFromEuler(new THREE.Euler(Math.PI, 0, end.yaw));
  return { t, goal_id: trajectory.goal_id, p_WE_m: trajectory.ee_path_m.at(-1), quat_WE: [q.w, q.x, q.y, q.z] };
}

export function contactsMessage(t) {
  const contacts = [
    { t: t - 40, body: 'link4', box_id: 3, depth_m: 0.004, p_W_m: [-3.2, 2.7, 0.8], radius_m: 0.06 },
    { t: t - 30, body: 'base_link', box_id: 5, depth_m: 0.01, p_W_m: [3.1, -3.6, 0.2], radius_m: 0.32 },
    { t: t - 12, body: 'gripper', box_id: 1, depth_m: 0.002, p_W_m: [0.2, 4.1, 0.9], radius_m: 0.05 },
    { t: t - 3, body: 'link6', box_id: 8, depth_m: 0.003, p_W_m: [4.4, 2.8, 0.85], radius_m: 0.05 },
  ];
  return { count: 7, contacts };
}

// ---------------------------------------------------------------- status panels

export function plannerStatus(t, trajectory) {
  return {
    t, state: 2, state_name: 'SUCCEEDED', goal_id: trajectory.goal_id, trajectory_id: trajectory.trajectory_id,
    failure_reason: '', front_end_ms: 41.7, sampling_ms: 88.2, optimization_ms: 153.9, total_ms: 290.4,
    replans: 1, detail: 'replanned: a box appeared ahead',
  };
}

export function trackerStatus(t, trajectory, along) {
  return {
    t, state: 1, state_name: 'TRACKING', trajectory_id: trajectory.trajectory_id, goal_id: trajectory.goal_id,
    t_along_s: along, position_error_m: 0.012 + 0.005 * Math.sin(t), yaw_error_rad: 0.008,
    joint_error_rad: 0.004, solve_ms: 1.8,
  };
}

export function missionStatus(t, startT) {
  return {
    t, mission: 'tables-pick-and-place', state: 1, state_name: 'RUNNING', step_index: 2, num_steps: 5,
    step: 'goto shelf', goal_id: 12, attempts: 1, elapsed_s: t - startT, detail: 'planning accepted',
  };
}

export function graphStatus(t) {
  const names = ['topay-sim', 'topay-mapper', 'topay-planner', 'topay-tracker', 'topay-canbridge',
    'topay-mission', 'topay-viz'];
  return {
    t, graph_name: 'sim-tables',
    processes: names.map((name, i) => ({
      name, state: i === 5 ? 3 : 2, state_name: i === 5 ? 'BACKOFF' : 'RUNNING', pid: 4100 + i,
      restarts: i === 5 ? 2 : 0, cpu_percent: 3 + 11 * i, rss_kB: 20000 + 15000 * i,
      heartbeat_age_s: i === 6 ? -1 : 0.3 + 0.1 * i, health: i === 6 ? -1 : i === 1 ? 1 : 0,
    })),
  };
}

export function driveStatus(t) {
  const n = 7;
  const range = (f) => Array.from({ length: n }, (_, i) => f(i));
  return {
    t, state: 2, state_name: 'RUNNING', stop_reason: '', can_url: 'udp://239.255.1.1:9000',
    bus_state: 'error-active', frames_sent: Math.floor(t * 10) % 1000000, frames_received: Math.floor(t * 12) % 1000000,
    error_frames: 0, bus_off_count: 0, tx_refused: 0, frames_malformed: 0, frames_unknown: 0,
    bus_load_percent: 23.4, command_age_s: 0.012, commands_received: 12345, commands_rejected: 0,
    clamp_count: 3, command_latency_p99_ms: 0.8, cycle_jitter_p99_ms: 0.3,
    base_mode: 1, base_fault_bits: 0, base_faults: 'none', base_status_age_s: 0.01, base_battery_v: 48.3,
    num_drives: n, node_id: range((i) => 11 + i), joint_name: range((i) => `q${i + 1}`),
    drive_state: range((i) => (i === 3 ? 'Switched on' : 'Operation enabled')),
    nmt_state: range(() => 'operational'), statusword: range((i) => (i === 3 ? 0x0233 : 0x1237)),
    last_emcy_code: range((i) => (i === 3 ? 0x8611 : 0)), heartbeat_age_s: range((i) => 0.05 + 0.01 * i),
  };
}

export function simStatus(t, startT) {
  return {
    t, sim_time_s: t - startT, real_time_factor: 0.99, target_rate: 1, plant_steps: Math.floor((t - startT) * 1000),
    late_steps: 4, step_lateness_p99_us: 120, commands_accepted: 40000, commands_rejected: 0, command_timeouts: 0,
    contact_events: 7, contact_steps: 41, max_depth_m: 0.01, in_contact: false, scans: Math.floor((t - startT) * 10),
    events_applied: 2, boxes_present: 14,
  };
}
