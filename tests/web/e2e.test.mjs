// The page in headless Chromium (playwright-core, Debian's /usr/bin/chromium) against topay-viz
// replaying a real recorded demo log (--paused):
//   - the page connects, shows the replay bar, and the replay starts paused at the log's start;
//   - scrubbing the time slider (input/change events at 25 %, a mouse click on the track at about
//     75 %) moves the server's clock (window.__topayViz.playback.t follows, the time label too),
//     and the scene follows it: more map voxels at 75 % than at 25 %;
//   - playing at 4x draws every layer: robot meshes, map voxels, scan points, trajectory, candidate
//     paths and plot samples;
//   - unticking #layer-map hides the map (layers.map false, the rendered view changes) and
//     ticking it shows it again;
//   - no uncaught errors or console errors in the page (a throwing message handler logs one);
//     SIGINT stops topay-viz with exit 0.
// Saves a screenshot to $TOPAY_TEST_OUT/viewer.png (printed).
//
//   TOPAY_VIZ=... TOPAY_DEMO_LOG=... TOPAY_WEB_ROOT=build/web node --test tests/web/e2e.test.mjs
// Skipped (with the reason) without Chromium, playwright-core in web/node_modules, the built page,
// the binary or the log.

import assert from 'node:assert/strict';
import { mkdirSync, statSync } from 'node:fs';
import { join } from 'node:path';
import { after, before, test } from 'node:test';
import { CHROMIUM_ARGS, missingInputs, paths, startViz, waitFor, webPackage } from './viz_support.mjs';

const skip = missingInputs({ viz: true, log: true, page: true, chromium: true, packages: ['playwright-core'] });

let viz;
let browser;
let page;
const pageErrors = [];

const hooks = (fn, arg) => page.evaluate(fn, arg);
const pageWait = (fn, arg, timeout = 20000) => page.waitForFunction(fn, arg, { timeout, polling: 100 });
const playback = () => hooks(() => window.__topayViz.playback);
const counts = () => hooks(() => window.__topayViz.counts());

/** Waits until the page's counts stop changing (the latched channels re-sent after a seek are drawn). */
async function settledCounts() {
  let last = '';
  let same = 0;
  return waitFor(async () => {
    const now = JSON.stringify(await counts());
    same = now === last ? same + 1 : 0;
    last = now;
    return same >= 4 && JSON.parse(now);  // unchanged for 1 s
  }, { everyMs: 250, what: 'the scene to settle' });
}

/** Waits for the replay clock at t after the seek number `seeks`, then for the scene. */
async function afterSeek(t, seeks) {
  await pageWait(([t, seeks]) => {
    const p = window.__topayViz.playback;
    return p.seeks > seeks && Math.abs(p.t - t) < 0.3;
  }, [t, seeks], 5000);
  return settledCounts();
}

before(async () => {
  if (skip) return;
  viz = await startViz(['--paused', '--web-root', paths.webRoot]);
  const { chromium } = webPackage('playwright-core');
  browser = await chromium.launch({ executablePath: paths.chromium, args: CHROMIUM_ARGS });
  page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  page.on('pageerror', (error) => pageErrors.push(error.message));
  page.on('console', (message) => message.type() === 'error' && pageErrors.push(`console: ${message.text()}`));
  await page.goto(viz.url);
});

after(async () => {
  await browser?.close();
  if (viz) await viz.stop();
});

test('the page connects; the replay bar shows a paused replay at the log start', { skip }, async () => {
  await pageWait(() => window.__topayViz?.connected === true && window.__topayViz.playback?.mode === 'replay');
  assert.equal(await hooks(() => window.__topayViz.webgl), true, 'WebGL');
  assert.equal(await page.isVisible('#replay-bar'), true);
  const p = await playback();
  assert.equal(p.playing, false);
  assert.ok(p.end_t - p.start_t > 5, `a log of ${p.end_t - p.start_t} s`);
  assert.ok(Math.abs(p.t - p.start_t) < 0.5, `paused at the start: t - start_t = ${p.t - p.start_t}`);
  assert.equal(await page.isDisabled('#play'), false);
  assert.equal(await page.isDisabled('#pause'), true);
  await pageWait(() => window.__topayViz.topics['/robot/description'] > 0);  // latched, even at the start
});

let at25;
let at75;
test('scrubbing the time slider moves the replay clock and the scene', { skip }, async () => {
  const p0 = await playback();
  const span = p0.end_t - p0.start_t;

  // 25 %: set the slider's value and send the events a drag sends.
  const t25 = p0.start_t + 0.25 * span;
  await hooks((t) => {
    const slider = document.getElementById('slider');
    slider.value = String(t);
    slider.dispatchEvent(new Event('input', { bubbles: true }));
    slider.dispatchEvent(new Event('change', { bubbles: true }));
  }, t25);
  at25 = await afterSeek(t25, p0.seeks);
  assert.equal((await playback()).playing, false, 'a seek keeps the replay paused');
  assert.match(await page.textContent('#time-label'), new RegExp(`\\(${(t25 - p0.start_t).toFixed(1)} / ${span.toFixed(1)} s\\)`));

  // About 75 %: a click on the slider's track, as a user would.
  const box = await page.locator('#slider').boundingBox();
  const p1 = await playback();
  await page.mouse.click(box.x + 0.75 * box.width, box.y + box.height / 2);
  const t75 = await hooks(() => Number(document.getElementById('slider').value));
  const fraction = (t75 - p0.start_t) / span;
  assert.ok(fraction > 0.65 && fraction < 0.85, `the click put the slider at ${(100 * fraction).toFixed(1)} %`);
  at75 = await afterSeek(t75, p1.seeks);
  assert.match(await page.textContent('#time-label'), new RegExp(`\\(${(t75 - p0.start_t).toFixed(1)} / ${span.toFixed(1)} s\\)`));

  console.log(`counts at 25 %: ${JSON.stringify(at25)}`);
  console.log(`counts at 75 %: ${JSON.stringify(at75)}`);
  assert.ok(at75.mapVoxels > at25.mapVoxels, `map voxels at 75 % (${at75.mapVoxels}) > at 25 % (${at25.mapVoxels})`);
  assert.ok(at75.robotMeshes > 0, 'the robot is drawn after a seek');
});

test('playing at 4x draws every layer', { skip }, async () => {
  const p0 = await playback();
  await hooks((t) => {  // back to 25 %: enough log left to play for a few seconds
    const slider = document.getElementById('slider');
    slider.value = String(t);
    slider.dispatchEvent(new Event('change', { bubbles: true }));
  }, p0.start_t + 0.25 * (p0.end_t - p0.start_t));
  await pageWait((seeks) => window.__topayViz.playback.seeks > seeks, p0.seeks, 5000);
  await page.selectOption('#speed', '4');
  await pageWait(() => window.__topayViz.playback.speed === 4, undefined, 5000);
  await page.click('#play');
  await pageWait(() => window.__topayViz.playback.playing === true, undefined, 5000);
  const t0 = (await playback()).t;
  await pageWait(() => {
    const c = window.__topayViz.counts();
    return c.robotMeshes > 0 && c.mapVoxels > 0 && c.scanPoints > 0 && c.trajectoryPoints > 0 &&
      c.candidatePaths > 0 && c.plotSamples > 0;
  }, undefined, 30000).catch(() => {});  // the assertion below names what is missing
  const c = await counts();
  console.log(`counts while playing: ${JSON.stringify(c)}`);
  for (const key of ['robotMeshes', 'mapVoxels', 'scanPoints', 'trajectoryPoints', 'candidatePaths', 'plotSamples']) {
    assert.ok(c[key] > 0, `${key} = ${c[key]}`);
  }
  await pageWait((t0) => window.__topayViz.playback.t > t0 + 1, t0, 10000);  // the clock runs (1 log s)
  await page.click('#pause');
  await pageWait(() => window.__topayViz.playback.playing === false, undefined, 5000);
});

test('the map checkbox hides the map and shows it again', { skip }, async () => {
  const frame = async () => {  // the next frame drawn
    const n = await hooks(() => window.__topayViz.frames);
    await pageWait((n) => window.__topayViz.frames > n + 1, n, 5000);
  };
  const layers = () => hooks(() => ({ ...window.__topayViz.layers }));
  assert.equal((await layers()).map, true);
  await frame();
  const withMap = await page.locator('#viewport').screenshot();
  await page.click('#layer-map');
  assert.equal(await page.isChecked('#layer-map'), false);
  const hidden = await layers();
  assert.equal(hidden.map, false, 'layers.map');
  assert.ok(hidden.robot && hidden.scan && hidden.paths, `the other layers stay: ${JSON.stringify(hidden)}`);
  await frame();
  const withoutMap = await page.locator('#viewport').screenshot();
  assert.notDeepEqual(withoutMap, withMap, 'the view changed without the map');
  await page.click('#layer-map');
  assert.equal((await layers()).map, true);
  await frame();
});

test('screenshot; no errors in the page', { skip }, async () => {
  mkdirSync(paths.testOut, { recursive: true });
  const file = join(paths.testOut, 'viewer.png');
  await page.screenshot({ path: file });
  console.log(`screenshot: ${file}`);
  assert.ok(statSync(file).size > 20000, 'a screenshot with something in it');
  const { fps, frames } = await hooks(() => ({ fps: window.__topayViz.fps, frames: window.__topayViz.frames }));
  console.log(`page: ${frames} frames, ${fps.toFixed(1)} fps`);
  assert.deepEqual(pageErrors, []);
});

test('SIGINT stops topay-viz with exit code 0', { skip }, async () => {
  await browser.close();
  browser = null;
  const { code, signal, output } = await viz.stop();
  viz = null;
  assert.equal(signal, null, output);
  assert.equal(code, 0, output);
});
