// The key-value status panels: robot, planner, tracker, mission (with its progress bar), sim and
// the viewer's own statistics.

import { KeyValueTable, stateClass } from './table.js';
import { any, bytes, clock, num } from '../util/format.js';

const state = (m) => m.state_name ?? any(m.state);
const stateCls = (m) => stateClass(m.state_name);

export function robotPanel(container) {
  return new KeyValueTable(container, [
    ['time', (m) => clock(m.t)],
    ['x, y', (m) => `${num(m.x_m)} m, ${num(m.y_m)} m`],
    ['yaw', (m) => `${num(m.yaw_rad)} rad`],
    ['v, ω', (m) => `${num(m.v_mps)} m/s, ${num(m.omega_radps)} rad/s`],
    ['q', (m) => (m.q_rad || []).map((q) => num(q)).join(' ')],
    ['gripper', (m) => any(m.gripper)],
    ['p_WE', (m) => (m.p_WE_m || []).map((x) => num(x)).join(', ')],
  ]);
}

export function plannerPanel(container) {
  return new KeyValueTable(container, [
    ['state', state, stateCls],
    ['goal / trajectory', (m) => `${any(m.goal_id)} / ${any(m.trajectory_id)}`],
    ['front end', (m) => `${num(m.front_end_ms, 1)} ms`],
    ['sampling', (m) => `${num(m.sampling_ms, 1)} ms`],
    ['optimization', (m) => `${num(m.optimization_ms, 1)} ms`],
    ['total', (m) => `${num(m.total_ms, 1)} ms`],
    ['replans', (m) => any(m.replans)],
    ['failure', (m) => m.failure_reason || '—', (m) => (m.failure_reason ? 'bad' : '')],
    ['detail', (m) => m.detail || '—'],
  ]);
}

export function trackerPanel(container) {
  return new KeyValueTable(container, [
    ['state', state, stateCls],
    ['goal / trajectory', (m) => `${any(m.goal_id)} / ${any(m.trajectory_id)}`],
    ['t along', (m) => `${num(m.t_along_s)} s`],
    ['position error', (m) => `${num(m.position_error_m, 3)} m`],
    ['yaw error', (m) => `${num(m.yaw_error_rad, 3)} rad`],
    ['joint error', (m) => `${num(m.joint_error_rad, 3)} rad`],
    ['solve', (m) => `${num(m.solve_ms, 2)} ms`],
  ]);
}

export class MissionPanel {
  constructor(container, progress, progressLabel) {
    this.progress = progress;
    this.progressLabel = progressLabel;
    this.table = new KeyValueTable(container, [
      ['mission', (m) => m.mission || '—'],
      ['state', state, stateCls],
      ['step', (m) => `${(m.step_index ?? 0) + 1} / ${any(m.num_steps)}: ${m.step || '—'}`],
      ['goal', (m) => any(m.goal_id)],
      ['attempts', (m) => any(m.attempts)],
      ['elapsed', (m) => `${num(m.elapsed_s, 1)} s`],
      ['detail', (m) => m.detail || '—'],
    ]);
  }

  update(m) {
    this.table.update(m);
    const total = Math.max(0, m.num_steps || 0);
    const done = m.state_name === 'SUCCEEDED' ? total : Math.min(total, Math.max(0, m.step_index || 0));
    this.progress.max = Math.max(1, total);
    this.progress.value = done;
    this.progressLabel.textContent = `${done} / ${total} steps`;
  }
}

export function simPanel(container) {
  return new KeyValueTable(container, [
    ['sim time', (m) => `${num(m.sim_time_s, 1)} s`],
    ['real-time factor', (m) => `${num(m.real_time_factor)} (target ${num(m.target_rate)})`],
    ['plant steps', (m) => `${any(m.plant_steps)} (${any(m.late_steps)} late)`],
    ['lateness p99', (m) => `${num(m.step_lateness_p99_us, 0)} µs`],
    ['commands', (m) => `${any(m.commands_accepted)} ok, ${any(m.commands_rejected)} rejected, ` +
      `${any(m.command_timeouts)} timeouts`],
    ['contacts', (m) => `${any(m.contact_events)} events, max depth ${num(m.max_depth_m, 3)} m`,
      (m) => (m.in_contact ? 'bad' : '')],
    ['in contact', (m) => any(m.in_contact), (m) => (m.in_contact ? 'bad' : 'good')],
    ['scans', (m) => any(m.scans)],
    ['world events', (m) => `${any(m.events_applied)}, ${any(m.boxes_present)} boxes present`],
  ]);
}

/** The server's /viz/stats plus the page's own numbers (fps, messages, drawn counts). */
export function vizPanel(container) {
  return new KeyValueTable(container, [
    ['clients', (m) => any(m.stats?.clients)],
    ['LCM messages', (m) => `${any(m.stats?.lcm_messages)} (${any(m.stats?.lcm_malformed)} malformed)`],
    ['frames', (m) => `${any(m.stats?.frames_sent)} sent, ${any(m.stats?.frames_dropped)} dropped`,
      (m) => (m.stats?.frames_dropped > 0 ? 'warn' : '')],
    ['bytes', (m) => `${bytes(m.stats?.bytes_sent)}, ${bytes(m.stats?.bytes_per_s)}/s`],
    ['page fps', (m) => num(m.fps, 1)],
    ['page messages', (m) => any(m.messages)],
    ['map', (m) => `${any(m.counts.mapVoxels)} voxels in ${any(m.counts.mapBlocks)} blocks`],
    ['scan', (m) => `${any(m.counts.scanPoints)} points`],
  ]);
}
