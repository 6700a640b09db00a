#!/usr/bin/env node
// Benchmark (not a test): the page's frame rate, the server's bandwidth and its CPU while a log
// replays at speed 1 into headless Chromium (software GL) at 1280x800.
//
//   node tests/web/fps_bench.mjs --log FILE --viz build/bin/topay-viz --web build/web [--seconds 20] [--speed 1]
//
// topay-viz starts paused; once the page is connected and has the robot, play is pressed and
// then, every second: window.__topayViz.fps (frames drawn over the last second), bytes_per_s of the
// latest /viz/stats (this script's own Foxglove client, subscribed to /viz/stats only: a few
// hundred bytes a second of it are this client's), and topay-viz's CPU over that second
// (/proc/PID/stat utime + stime). Prints one JSON object: median, p95 (and min / p5 for fps) of
// each series, topay-viz's CPU over the whole run, and the page's counts at the end.

import { CHROMIUM_ARGS, cpuSeconds, missingInputs, paths, startViz, waitFor, webPackage } from './viz_support.mjs';

function parseArgs(argv) {
  const options = { log: paths.log, viz: paths.viz, web: paths.webRoot, seconds: 20, speed: 1 };
  for (let i = 0; i < argv.length; i += 2) {
    const key = argv[i].replace(/^--/, '');
    if (!(key in options) || argv[i + 1] === undefined) {
      console.error('usage: fps_bench.mjs --log FILE --viz BIN --web DIR [--seconds 20] [--speed 1]');
      process.exit(2);
    }
    options[key] = typeof options[key] === 'number' ? Number(argv[i + 1]) : argv[i + 1];
  }
  return options;
}

function quantile(values, q) {
  if (values.length === 0) return null;
  const sorted = [...values].sort((a, b) => a - b);
  const at = (sorted.length - 1) * q;
  const lo = Math.floor(at), hi = Math.ceil(at);
  return sorted[lo] + (sorted[hi] - sorted[lo]) * (at - lo);
}
const round = (x, digits = 1) => (x === null ? null : Number(x.toFixed(digits)));
const summary = (values, extra = {}) => ({ median: round(quantile(values, 0.5)), p95: round(quantile(values, 0.95)), ...extra });

const options = parseArgs(process.argv.slice(2));
Object.assign(paths, { viz: options.viz, log: options.log, webRoot: options.web });
const missing = missingInputs({ viz: true, log: true, page: true, chromium: true, packages: ['playwright-core', 'ws', '@foxglove/ws-protocol'] });
if (missing) {
  console.error(`fps_bench: ${missing}`);
  process.exit(77);
}
const { chromium } = webPackage('playwright-core');
const { FoxgloveClient } = webPackage('@foxglove/ws-protocol');
const WebSocket = webPackage('ws');

const viz = await startViz(['--paused', '--speed', String(options.speed), '--web-root', options.web]);
const browser = await chromium.launch({ executablePath: paths.chromium, args: CHROMIUM_ARGS });
let stats = null;
const client = new FoxgloveClient({ ws: new WebSocket(viz.wsUrl, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]) });
try {
  client.on('advertise', (channels) => {
    const c = channels.find((channel) => channel.topic === '/viz/stats');
    if (c) client.subscribe(c.id);
  });
  client.on('message', ({ data }) => {
    stats = JSON.parse(Buffer.from(data.buffer, data.byteOffset, data.byteLength).toString('utf8'));
  });

  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  await page.goto(viz.url);
  await page.waitForFunction(() => window.__topayViz?.connected && window.__topayViz.playback?.mode === 'replay' &&
    window.__topayViz.counts().robotMeshes > 0, undefined, { timeout: 30000 });
  if (!(await page.evaluate(() => window.__topayViz.playback.playing))) await page.click('#play');
  await page.waitForFunction(() => window.__topayViz.playback.playing, undefined, { timeout: 5000 });

  const fps = [], bandwidth = [], cpu = [];
  const wall0 = Date.now(), cpu0 = cpuSeconds(viz.pid);
  let [wallPrev, cpuPrev] = [wall0, cpu0];
  for (let second = 1; second <= options.seconds; second++) {
    await waitFor(() => Date.now() >= wall0 + 1000 * second, { everyMs: 20, what: 'the next second' });
    const [wall, used] = [Date.now(), cpuSeconds(viz.pid)];
    fps.push(await page.evaluate(() => window.__topayViz.fps));
    if (stats) bandwidth.push(stats.bytes_per_s);
    cpu.push((100 * (used - cpuPrev) * 1000) / (wall - wallPrev));
    [wallPrev, cpuPrev] = [wall, used];
  }
  const wallS = (Date.now() - wall0) / 1000;
  const end = await page.evaluate(() => ({
    counts: window.__topayViz.counts(), frames: window.__topayViz.frames, playback: window.__topayViz.playback,
  }));
  const result = {
    log: options.log,
    seconds: round(wallS),
    speed: options.speed,
    viewport: '1280x800',
    log_time_played_s: round(end.playback.t - end.playback.start_t),
    fps: summary(fps, { min: round(Math.min(...fps)), p5: round(quantile(fps, 0.05)) }),
    bytes_per_s: summary(bandwidth),
    viz_cpu_percent: summary(cpu, { overall: round((100 * (cpuSeconds(viz.pid) - cpu0)) / wallS) }),
    frames: end.frames,
    counts: end.counts,
    samples: { fps: fps.map((x) => round(x)), bytes_per_s: bandwidth.map((x) => Math.round(x)), viz_cpu_percent: cpu.map((x) => round(x)) },
  };
  const lines = Object.entries(result).map(([key, value]) => `  ${JSON.stringify(key)}: ${JSON.stringify(value)}`);
  console.log(`{\n${lines.join(',\n')}\n}`);  // JSON, a line per key
} finally {
  client.close();
  await browser.close();
  const { code } = await viz.stop();
  if (code !== 0) console.error(`fps_bench: topay-viz exited with code ${code}`);
}
