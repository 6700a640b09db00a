// Time plots of /plot/state (uPlot): v and ω measured vs planned, a and β planned, the joints
// measured (solid) vs planned (dashed). Keeps the last WINDOW_S seconds of message time; a plan
// value of null is a gap. Redrawn at most every REDRAW_MS, and only when samples arrived.

import uPlot from 'uplot';

const WINDOW_S = 60;
const REDRAW_MS = 100;
const JOINT_COLORS = ['#e6194b', '#3cb44b', '#ffe119', '#4363d8', '#f58231', '#911eb4', '#42d4f4',
  '#f032e6', '#bfef45'];

function series(label, stroke, dash) {
  return { label, stroke, width: 1.5, dash, spanGaps: false, points: { show: false } };
}

const AXES = [
  { stroke: '#aab', grid: { stroke: '#2c313a' }, ticks: { stroke: '#2c313a' } },
  { stroke: '#aab', grid: { stroke: '#2c313a' }, ticks: { stroke: '#2c313a' }, size: 50 },
];

/** One uPlot with its own columns (x = time in seconds since the epoch). */
class Plot {
  constructor(container, title, seriesList) {
    this.container = container;
    this.columns = [[]];
    for (let i = 0; i < seriesList.length; i++) this.columns.push([]);
    this.uplot = new uPlot({
      title,
      width: Math.max(200, container.clientWidth),
      height: 170,
      scales: { x: { time: true } },
      axes: AXES,
      legend: { live: true },
      cursor: { drag: { x: false, y: false } },
      series: [{ label: 't' }, ...seriesList],
    }, this.columns, container);
  }

  push(t, values) {
    this.columns[0].push(t);
    for (let i = 0; i < values.length; i++) this.columns[i + 1].push(values[i]);
  }

  /** Drops samples older than tMin, or everything (tMin = Infinity). */
  trim(tMin) {
    const x = this.columns[0];
    let cut = 0;
    while (cut < x.length && x[cut] < tMin) cut++;
    if (cut === 0) return;
    for (const column of this.columns) column.splice(0, cut);
  }

  redraw() {
    this.uplot.setData(this.columns);
  }

  resize() {
    this.uplot.setSize({ width: Math.max(200, this.container.clientWidth), height: 170 });
  }
}

function value(x) {
  return typeof x === 'number' && Number.isFinite(x) ? x : null;
}

export class Plots {
  constructor(elements) {
    this.elements = elements;
    this.samples = 0;
    this.lastT = -Infinity;
    this.dirty = false;
    this.lastRedraw = 0;
    this.jointNames = null;
    this.v = new Plot(elements.v, 'v (m/s)', [series('measured', '#4fc3f7'), series('planned', '#ffa630', [6, 4])]);
    this.omega = new Plot(elements.omega, 'ω (rad/s)',
      [series('measured', '#4fc3f7'), series('planned', '#ffa630', [6, 4])]);
    this.accel = new Plot(elements.accel, 'planned a (m/s²), β (rad/s²)',
      [series('a', '#ff6f61'), series('β', '#b39ddb')]);
    this.joints = null;  // made at the first sample, when the joint count is known
    elements.jointSelect.addEventListener('change', () => this.#showJoints());
    new ResizeObserver(() => this.#resize()).observe(elements.v.parentElement);
  }

  setJointNames(names) {
    this.jointNames = names;
  }

  #makeJoints(n) {
    const list = [];
    const name = (i) => this.jointNames?.[i] || `q${i + 1}`;
    for (let i = 0; i < n; i++) list.push(series(name(i), JOINT_COLORS[i % JOINT_COLORS.length]));
    for (let i = 0; i < n; i++) list.push(series(`${name(i)} plan`, JOINT_COLORS[i % JOINT_COLORS.length], [6, 4]));
    this.joints = new Plot(this.elements.joints, 'joints (rad): measured solid, planned dashed', list);
    this.jointCount = n;
    const select = this.elements.jointSelect;
    select.replaceChildren();
    select.add(new Option('all joints', 'all'));
    for (let i = 0; i < n; i++) select.add(new Option(name(i), String(i)));
  }

  #showJoints() {
    if (!this.joints) return;
    const choice = this.elements.jointSelect.value;
    for (let i = 0; i < this.jointCount; i++) {
      const show = choice === 'all' || choice === String(i);
      this.joints.uplot.setSeries(1 + i, { show });
      this.joints.uplot.setSeries(1 + this.jointCount + i, { show });
    }
  }

  #all() {
    return this.joints ? [this.v, this.omega, this.accel, this.joints] : [this.v, this.omega, this.accel];
  }

  #resize() {
    for (const plot of this.#all()) plot.resize();
  }

  add(m) {
    const t = m.t;
    if (typeof t !== 'number') return;
    if (t < this.lastT - 0.5) {  // the clock went back (a replay seek): start over
      for (const plot of this.#all()) plot.trim(Infinity);
      this.samples = 0;
    }
    this.lastT = t;
    const q = m.q_rad || [];
    if (!this.joints && q.length > 0) this.#makeJoints(q.length);
    this.v.push(t, [value(m.v_mps), value(m.v_plan_mps)]);
    this.omega.push(t, [value(m.omega_radps), value(m.omega_plan_radps)]);
    this.accel.push(t, [value(m.a_plan_mps2), value(m.beta_plan_radps2)]);
    if (this.joints) {
      const values = new Array(2 * this.jointCount);
      const plan = m.q_plan_rad || [];
      for (let i = 0; i < this.jointCount; i++) {
        values[i] = value(q[i]);
        values[this.jointCount + i] = value(plan[i]);
      }
      this.joints.push(t, values);
    }
    const tMin = t - WINDOW_S;
    for (const plot of this.#all()) plot.trim(tMin);
    this.samples = this.v.columns[0].length;
    this.dirty = true;
  }

  /** Redraws if samples arrived and REDRAW_MS passed (call every frame). */
  update(now) {
    if (!this.dirty || now - this.lastRedraw < REDRAW_MS) return;
    this.dirty = false;
    this.lastRedraw = now;
    for (const plot of this.#all()) plot.redraw();
  }
}
