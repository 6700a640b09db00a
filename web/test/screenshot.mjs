#!/usr/bin/env node
// Development aid: starts the fixture, opens the page in headless Chromium, waits, prints
// window.__topayViz (counts, fps, topics) and saves a screenshot.
//   node web/test/screenshot.mjs [--out shot.png] [--voxels 50000] [--wait 6000] [--mode replay|live]

import { startFixture } from './fixture-server.mjs';
import { launch } from './browser.mjs';

const args = Object.fromEntries(process.argv.slice(2).reduce((pairs, arg, i, all) =>
  (arg.startsWith('--') ? [...pairs, [arg.slice(2), all[i + 1]]] : pairs), []));
const fixture = await startFixture({ port: 0, voxels: Number(args.voxels || 50000), mode: args.mode || 'replay', root: args.root });
const browser = await launch();
try {
  const page = await browser.newPage({ viewport: { width: 1600, height: 1000 } });
  page.on('console', (message) => console.log(`[page ${message.type()}] ${message.text()}`));
  page.on('pageerror', (error) => console.log(`[page error] ${error.message}`));
  await page.goto(fixture.url);
  await page.waitForTimeout(Number(args.wait || 6000));
  const state = await page.evaluate(() => {
    const v = window.__topayViz;
    return { connected: v.connected, fps: v.fps, frames: v.frames, webgl: v.webgl, counts: v.counts(),
      topics: v.topics, playback: v.playback, layers: v.layers };
  });
  console.log(JSON.stringify(state, null, 1));
  await page.screenshot({ path: args.out || '/tmp/topay-viz.png' });
} finally {
  await browser.close();
  await fixture.close();
}
