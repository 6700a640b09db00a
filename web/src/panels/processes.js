// The process table from /graph/status.

import { RowTable, stateClass } from './table.js';
import { any, num } from '../util/format.js';

const HEALTH = { '-1': '—', 0: 'OK', 1: 'WARN', 2: 'ERROR' };
const HEALTH_CLASS = { 0: 'good', 1: 'warn', 2: 'bad' };

export class ProcessTable {
  constructor(table, caption) {
    this.caption = caption;
    this.rows = new RowTable(table, [
      ['process', (p) => p.name],
      ['state', (p) => p.state_name ?? any(p.state), (p) => stateClass(p.state_name)],
      ['pid', (p) => any(p.pid)],
      ['restarts', (p) => any(p.restarts), (p) => (p.restarts > 0 ? 'warn' : '')],
      ['cpu %', (p) => num(p.cpu_percent, 1)],
      ['rss', (p) => (typeof p.rss_kB === 'number' ? `${(p.rss_kB / 1024).toFixed(1)} MB` : '—')],
      ['hb age', (p) => (p.heartbeat_age_s < 0 ? '—' : `${num(p.heartbeat_age_s, 1)} s`),
        (p) => (p.heartbeat_age_s > 3 ? 'bad' : '')],
      ['health', (p) => HEALTH[p.health] ?? any(p.health), (p) => HEALTH_CLASS[p.health] || ''],
    ]);
  }

  update(message) {
    this.caption.textContent = message.graph_name ? `graph ${message.graph_name}` : '';
    this.rows.update(message.processes || []);
  }
}
