// End-to-end checks of the built page against the fixture server in Debian's headless Chromium:
//   node --test web/test/page.test.mjs   (skipped when /usr/bin/chromium or CHROMIUM is missing)
// SCREENSHOT=file.png keeps a screenshot of the replay test's page.

import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { after, before, describe, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { HAVE_CHROMIUM, launch } from './browser.mjs';
import { startFixture } from './fixture-server.mjs';

const web = join(dirname(fileURLToPath(import.meta.url)), '..');
const out = mkdtempSync(join(tmpdir(), 'topay-viz-web-'));
const TOPICS = ['/robot/description', '/robot/state', '/map/blocks', '/lidar/scan', '/planner/trajectory',
  '/planner/paths', '/planner/status', '/goal', '/sim/contacts', '/plot/state', '/tracker/status',
  '/mission/status', '/graph/status', '/can/drives', '/sim/status', '/viz/stats', '/viz/playback'];

before(() => {
  execFileSync(process.execPath, [join(web, 'build.mjs'), '--out', out], { stdio: 'inherit' });
});
after(() => rmSync(out, { recursive: true, force: true }));

test('build writes index.html, app.js and app.css with nothing fetched from elsewhere', () => {
  for (const file of ['index.html', 'app.js', 'app.css']) assert.ok(existsSync(join(out, file)), file);
  const html = readFileSync(join(out, 'index.html'), 'utf8');
  assert.doesNotMatch(html, /(src|href)="(https?:)?\/\//);
  assert.match(html, /src="app\.js"/);
});

const viz = (page, expression) => page.evaluate(expression);
const waitFor = (page, fn, arg, timeout = 20000) => page.waitForFunction(fn, arg, { timeout, polling: 100 });

describe('page in headless Chromium', { skip: !HAVE_CHROMIUM && 'no Chromium' }, () => {
  let browser;
  before(async () => {
    browser = await launch();
  });
  after(async () => {
    await browser?.close();
  });

  test('replay fixture: draws every layer, fills the panels, drives the replay clock', async () => {
    const fixture = await startFixture({ port: 0, root: out, mode: 'replay', voxels: 50000 });
    const page = await browser.newPage({ viewport: { width: 1600, height: 1000 } });
    const errors = [];
    page.on('pageerror', (error) => errors.push(error.message));
    try {
      await page.goto(fixture.url);
      await waitFor(page, () => {
        const v = window.__topayViz;
        if (!v?.connected) return false;
        const c = v.counts();
        return c.mapVoxels >= 45000 && c.scanPoints > 0 && c.robotMeshes > 0 && c.trajectoryPoints > 0 &&
          c.candidatePaths > 0 && c.goal === 1 && c.contacts > 0 && c.plotSamples > 5;
      });
      const counts = await viz(page, () => window.__topayViz.counts());
      assert.ok(counts.mapBlocks > 100, `mapBlocks ${counts.mapBlocks}`);
      assert.equal(counts.robotMeshes, 15);
      assert.equal(counts.trajectoryPoints, 201);
      assert.equal(counts.eePathPoints, 201);
      assert.equal(counts.candidatePaths, 3);
      assert.equal(counts.contacts, 4);
      assert.equal(await viz(page, () => window.__topayViz.webgl), true);
      await waitFor(page, (topics) => topics.every((t) => window.__topayViz.topics[t] > 0), TOPICS);

      // Panels.
      await waitFor(page, () => document.querySelector('#drive-table tbody')?.rows.length === 7);
      assert.match(await page.textContent('#planner-status'), /SUCCEEDED/);
      assert.match(await page.textContent('#mission-status'), /goto shelf/);
      assert.equal(await page.getAttribute('#mission-progress', 'max'), '5');
      assert.match(await page.textContent('#drive-table'), /0x1237/);
      assert.equal(await page.locator('#process-table tbody tr').count(), 7);
      assert.equal(await page.locator('#plots canvas').count() >= 4, true);

      // Layers.
      await page.click('#layer-map');
      assert.equal(await viz(page, () => window.__topayViz.layers.map), false);
      await page.click('#layer-map');
      assert.equal(await viz(page, () => window.__topayViz.layers.map), true);

      // Replay bar: pause, speed, seek.
      assert.equal(await page.isVisible('#replay-bar'), true);
      assert.equal((await viz(page, () => window.__topayViz.playback)).mode, 'replay');
      await page.click('#pause');
      await waitFor(page, () => window.__topayViz.playback.playing === false, undefined, 5000);
      await page.selectOption('#speed', '4');
      await waitFor(page, () => window.__topayViz.playback.speed === 4, undefined, 5000);
      const target = await page.evaluate(() => {
        const p = window.__topayViz.playback;
        const t = p.start_t + 0.5 * (p.end_t - p.start_t);
        const slider = document.getElementById('slider');
        slider.value = String(t);
        slider.dispatchEvent(new Event('input', { bubbles: true }));
        slider.dispatchEvent(new Event('change', { bubbles: true }));
        return t;
      });
      await waitFor(page, (t) => Math.abs(window.__topayViz.playback.t - t) < 1, target, 5000);
      assert.match(await page.textContent('#time-label'), /150\.0 \/ 300\.0 s/);
      await page.click('#play');
      await waitFor(page, () => window.__topayViz.playback.playing === true, undefined, 5000);
      // The seek re-sent the latched channels (the map as a reset): everything is back.
      await waitFor(page, () => {
        const c = window.__topayViz.counts();
        return c.mapVoxels >= 45000 && c.trajectoryPoints === 201 && c.goal === 1 && c.contacts === 4;
      });

      const { fps, frames } = await viz(page, () => ({ fps: window.__topayViz.fps, frames: window.__topayViz.frames }));
      console.log(`# fps ${fps.toFixed(1)} after ${frames} frames (50k-voxel fixture map)`);
      assert.ok(frames > 10 && fps > 0, `fps ${fps}`);
      if (process.env.SCREENSHOT) await page.screenshot({ path: process.env.SCREENSHOT });
      assert.deepEqual(errors, []);
    } finally {
      await page.close();
      await fixture.close();
    }
  });

  test('live fixture: no replay bar, playback commands answered with a warning', async () => {
    const fixture = await startFixture({ port: 0, root: out, mode: 'live', voxels: 5000 });
    const page = await browser.newPage();
    try {
      await page.goto(fixture.url);
      await waitFor(page, () => window.__topayViz?.playback?.mode === 'live');
      assert.equal(await page.isVisible('#replay-bar'), false);
      await page.evaluate(() => { document.getElementById('pause').click(); });  // hidden: click in script
      await waitFor(page, () => window.__topayViz.statuses.some((s) => s.level === 1), undefined, 5000);
    } finally {
      await page.close();
      await fixture.close();
    }
  });

  test('reconnects when the server comes back', async () => {
    const first = await startFixture({ port: 0, root: out, voxels: 5000 });
    const port = first.port;
    const page = await browser.newPage();
    try {
      await page.goto(first.url);
      await waitFor(page, () => window.__topayViz?.connected === true);
      await first.close();
      await waitFor(page, () => window.__topayViz.connected === false, undefined, 5000);
      const second = await startFixture({ port, root: out, voxels: 5000 });
      try {
        await waitFor(page, () => window.__topayViz.connected === true, undefined, 15000);
        await waitFor(page, () => window.__topayViz.counts().mapVoxels >= 5000);
      } finally {
        await second.close();
      }
    } finally {
      await page.close();
    }
  });

  test('without WebGL the page shows an error and the panels still work', async () => {
    const noGl = await launch(['--disable-webgl', '--disable-3d-apis']);
    const fixture = await startFixture({ port: 0, root: out, voxels: 5000 });
    try {
      const page = await noGl.newPage();
      const errors = [];
      page.on('pageerror', (error) => errors.push(error.message));
      await page.goto(fixture.url);
      await waitFor(page, () => window.__topayViz?.connected === true && window.__topayViz.counts().mapVoxels > 0);
      assert.equal(await page.isVisible('#webgl-error'), true);
      assert.equal(await viz(page, () => window.__topayViz.webgl), false);
      await waitFor(page, () => /SUCCEEDED/.test(document.getElementById('planner-status').textContent));
      assert.deepEqual(errors, []);
    } finally {
      await noGl.close();
      await fixture.close();
    }
  });
});
