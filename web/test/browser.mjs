// Headless Chromium (Debian's /usr/bin/chromium) through playwright-core, for the page's tests.
// No browser is downloaded: CHROMIUM overrides the executable.

import { existsSync } from 'node:fs';
import { chromium } from 'playwright-core';

export const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
export const HAVE_CHROMIUM = existsSync(CHROMIUM);

/** Launches headless Chromium (software GL: --disable-gpu); `extra` adds command-line flags. */
export function launch(extra = []) {
  return chromium.launch({
    executablePath: CHROMIUM,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync', ...extra],
  });
}
