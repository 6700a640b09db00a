// Shared by the tests/web scripts: where things are (environment variables set by
// tests/web/CMakeLists.txt, with defaults for a run by hand), the npm packages of web/ (loaded from
// web/node_modules, which `npm ci` in web/ installs: tests/web has no node_modules of its own),
// starting and stopping topay-viz, and waiting for a condition.
//
//   TOPAY_VIZ        the topay-viz binary              (default <repo>/build/bin/topay-viz)
//   TOPAY_DEMO_LOG   the recorded demo log             (default <repo>/build/test_out/web/demo/seed-1/graph.lcmlog)
//   TOPAY_WEB_ROOT   the built page (index.html, app.js)  (default <repo>/build/web)
//   TOPAY_WEB_DIR    web/ sources with node_modules/   (default <repo>/web)
//   TOPAY_TEST_OUT   artefacts (screenshot)            (default <repo>/build/test_out/web)
//   CHROMIUM         the browser                       (default /usr/bin/chromium)

import { spawn } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const repo = resolve(dirname(fileURLToPath(import.meta.url)), '..', '..');

export const paths = {
  viz: process.env.TOPAY_VIZ || join(repo, 'build', 'bin', 'topay-viz'),
  log: process.env.TOPAY_DEMO_LOG || join(repo, 'build', 'test_out', 'web', 'demo', 'seed-1', 'graph.lcmlog'),
  webRoot: process.env.TOPAY_WEB_ROOT || join(repo, 'build', 'web'),
  webDir: process.env.TOPAY_WEB_DIR || join(repo, 'web'),
  testOut: process.env.TOPAY_TEST_OUT || join(repo, 'build', 'test_out', 'web'),
  chromium: process.env.CHROMIUM || '/usr/bin/chromium',
};

// The channels of docs/viewer.md, in the order topay-viz advertises them.
export const TOPICS = ['/robot/description', '/robot/state', '/map/blocks', '/lidar/scan', '/planner/trajectory',
  '/planner/paths', '/planner/status', '/goal', '/sim/contacts', '/plot/state', '/tracker/status',
  '/mission/status', '/graph/status', '/can/drives', '/sim/status', '/viz/stats', '/viz/playback'];

export const CHROMIUM_ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync'];

const requireFromWeb = createRequire(join(paths.webDir, 'package.json'));

/** An npm package of web/ (from web/node_modules), or null if it is not installed. */
export function webPackage(name) {
  try {
    return requireFromWeb(name);
  } catch {
    return null;
  }
}

/** Why the given inputs are not there, or false when they all are: a test's `skip` option (not '':
 * node:test would run a test with `skip: ''` and still report it skipped, failures hidden). */
export function missingInputs({ viz = false, log = false, page = false, chromium = false, packages = [] }) {
  const why = [];
  if (viz && !existsSync(paths.viz)) why.push(`no topay-viz binary at ${paths.viz} (TOPAY_VIZ)`);
  if (log && !existsSync(paths.log)) {
    why.push(`no demo log at ${paths.log} (TOPAY_DEMO_LOG; web.record_demo_log did not record one)`);
  }
  if (page && !['index.html', 'app.js'].every((f) => existsSync(join(paths.webRoot, f)))) {
    why.push(`the page is not built in ${paths.webRoot} (TOPAY_WEB_ROOT; node web/build.mjs --out DIR)`);
  }
  if (chromium && !existsSync(paths.chromium)) why.push(`no Chromium at ${paths.chromium} (CHROMIUM)`);
  for (const name of packages) {
    if (!webPackage(name)) why.push(`npm package ${name} missing in ${paths.webDir}/node_modules (cd web && npm ci)`);
  }
  return why.length > 0 ? why.join('; ') : false;
}

/**
 * Starts `topay-viz --log LOG --port 0 ...args` and resolves once it printed
 * "topay-viz: serving http://HOST:PORT/": { url, wsUrl, port, pid, stop(), output() }. stop()
 * sends SIGINT and resolves with { code, signal, output }.
 */
export function startViz(args, { viz = paths.viz, log = paths.log, timeoutMs = 30000 } = {}) {
  const child = spawn(viz, ['--log', log, '--port', '0', ...args], { stdio: ['ignore', 'pipe', 'pipe'] });
  let output = '';
  const exited = new Promise((done) => child.on('exit', (code, signal) => done({ code, signal })));
  const stop = async () => {
    if (child.exitCode === null && child.signalCode === null) child.kill('SIGINT');
    const timer = setTimeout(() => child.kill('SIGKILL'), 10000);
    const result = await exited;
    clearTimeout(timer);
    return { ...result, output };
  };
  return new Promise((ok, fail) => {
    const timer = setTimeout(() => {
      child.kill('SIGKILL');
      fail(new Error(`topay-viz did not print "serving" within ${timeoutMs} ms:\n${output}`));
    }, timeoutMs);
    const onData = (chunk) => {
      output += chunk;
      const m = /topay-viz: serving (http:\/\/([^/\s]+):(\d+)\/)/.exec(output);
      if (m && timer) {
        clearTimeout(timer);
        const [, url, host, port] = m;
        ok({ url, wsUrl: `ws://${host}:${port}/`, port: Number(port), pid: child.pid, stop, output: () => output });
      }
    };
    child.stdout.on('data', onData);
    child.stderr.on('data', (chunk) => (output += chunk));
    child.on('error', (error) => {
      clearTimeout(timer);
      fail(error);
    });
    exited.then(({ code, signal }) => {
      clearTimeout(timer);
      fail(new Error(`topay-viz exited (code ${code}, signal ${signal}) before serving:\n${output}`));
    });
  });
}

/** Polls `condition()` (sync or async) every `everyMs` until it is truthy; rejects after timeoutMs with `what`. */
export async function waitFor(condition, { timeoutMs = 20000, everyMs = 100, what = 'condition' } = {}) {
  const deadline = Date.now() + timeoutMs;
  for (;;) {
    const value = await condition();
    if (value) return value;
    if (Date.now() > deadline) throw new Error(`timed out after ${timeoutMs} ms waiting for ${what}`);
    await new Promise((r) => setTimeout(r, everyMs));
  }
}

/** user + system CPU seconds of a process so far (/proc/PID/stat, fields 14 and 15). */
export function cpuSeconds(pid) {
  const stat = readFileSync(`/proc/${pid}/stat`, 'utf8');
  const fields = stat.slice(stat.lastIndexOf(')') + 2).split(' ');  // fields from 3 (state) on
  const ticks = Number(fields[11]) + Number(fields[12]);
  return ticks / 100;  // USER_HZ is 100 on Linux
}
