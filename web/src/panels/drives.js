// The CAN bus and its drives from /can/drives (the LCM drive_status_t by field name: the per-drive
// values are parallel arrays).

import { KeyValueTable, RowTable, stateClass } from './table.js';
import { any, num } from '../util/format.js';

const BASE_MODES = { '-1': 'unknown', 0: 'standby', 1: 'CAN command', 2: 'quick stop', 3: 'fault' };

function hex(value, digits) {
  if (typeof value !== 'number' || value < 0) return '—';
  return `0x${value.toString(16).toUpperCase().padStart(digits, '0')}`;
}

function age(seconds) {
  return typeof seconds === 'number' && seconds >= 0 ? `${num(seconds, 2)} s` : '—';
}

export class DrivesPanel {
  constructor(container, table) {
    this.bus = new KeyValueTable(container, [
      ['bridge', (m) => m.state_name ?? any(m.state), (m) => stateClass(m.state_name)],
      ['stop reason', (m) => m.stop_reason || '—', (m) => (m.stop_reason ? 'warn' : '')],
      ['bus', (m) => `${m.can_url || '—'} ${m.bus_state || ''}`, (m) => stateClass(m.bus_state)],
      ['bus load', (m) => `${num(m.bus_load_percent, 1)} %`],
      ['frames', (m) => `${any(m.frames_sent)} tx, ${any(m.frames_received)} rx`],
      ['errors', (m) => `${any(m.error_frames)} error frames, ${any(m.bus_off_count)} bus-off, ` +
        `${any(m.tx_refused)} refused, ${any(m.frames_malformed)} malformed`,
      (m) => (m.error_frames > 0 || m.bus_off_count > 0 ? 'warn' : '')],
      ['command age', (m) => age(m.command_age_s), (m) => (m.command_age_s > 0.5 ? 'warn' : '')],
      ['latency / jitter p99', (m) => `${num(m.command_latency_p99_ms)} / ${num(m.cycle_jitter_p99_ms)} ms`],
      ['base', (m) => `${BASE_MODES[m.base_mode] ?? any(m.base_mode)}, faults: ${m.base_faults || '—'}`,
        (m) => (m.base_fault_bits ? 'bad' : '')],
      ['base status', (m) => `${age(m.base_status_age_s)}, battery ${num(m.base_battery_v, 1)} V`],
    ]);
    this.drives = new RowTable(table, [
      ['joint', (d) => d.joint_name],
      ['node', (d) => any(d.node_id)],
      ['CiA 402', (d) => d.drive_state, (d) => stateClass(d.drive_state)],
      ['NMT', (d) => d.nmt_state, (d) => stateClass(d.nmt_state)],
      ['statusword', (d) => hex(d.statusword, 4)],
      ['EMCY', (d) => (d.last_emcy_code ? hex(d.last_emcy_code, 4) : '—'), (d) => (d.last_emcy_code ? 'bad' : '')],
      ['heartbeat', (d) => age(d.heartbeat_age_s), (d) => (d.heartbeat_age_s > 1 ? 'bad' : '')],
    ]);
  }

  update(m) {
    this.bus.update(m);
    if (Array.isArray(m.drives)) {  // tolerate a server that sends per-drive objects
      this.drives.update(m.drives);
      return;
    }
    const n = m.num_drives ?? (m.node_id || []).length;
    const drives = [];
    for (let i = 0; i < n; i++) {
      drives.push({
        joint_name: m.joint_name?.[i], node_id: m.node_id?.[i], drive_state: m.drive_state?.[i],
        nmt_state: m.nmt_state?.[i], statusword: m.statusword?.[i],
        last_emcy_code: m.last_emcy_code?.[i], heartbeat_age_s: m.heartbeat_age_s?.[i],
      });
    }
    this.drives.update(drives);
  }
}
