#!/usr/bin/env node
// Builds the topay-viz page: bundles src/main.js (three, uPlot and the CSS included) into
// DIR/app.js + DIR/app.css and copies index.html, so DIR works offline with no CDN.
//   node web/build.mjs --out DIR [--dev]     (--dev: no minification, inline source map)

import { copyFile, mkdir } from 'node:fs/promises';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
let build;
try {
  ({ build } = await import('esbuild'));
} catch (error) {
  console.error(`build.mjs: cannot load esbuild (${error.code || error.message}); run \`npm ci\` in ${here}`);
  process.exit(1);
}

function parseArgs(argv) {
  const args = { out: null, dev: false };
  for (let i = 0; i < argv.length; i++) {
    const arg = argv[i];
    if (arg === '--out') args.out = argv[++i];
    else if (arg.startsWith('--out=')) args.out = arg.slice('--out='.length);
    else if (arg === '--dev') args.dev = true;
    else if (arg === '-h' || arg === '--help') {
      console.log('usage: node build.mjs --out DIR [--dev]');
      process.exit(0);
    } else {
      console.error(`build.mjs: unknown argument ${arg}`);
      process.exit(2);
    }
  }
  if (!args.out) {
    console.error('build.mjs: --out DIR is required');
    process.exit(2);
  }
  return args;
}

const args = parseArgs(process.argv.slice(2));
const out = resolve(args.out);
await mkdir(out, { recursive: true });
try {
  await build({
    entryPoints: [join(here, 'src', 'main.js')],
    bundle: true,
    outfile: join(out, 'app.js'),   // the imported CSS goes to app.css beside it
    format: 'iife',
    target: ['es2022'],
    minify: !args.dev,
    sourcemap: args.dev ? 'inline' : false,
    legalComments: 'eof',
    logLevel: 'warning',
    absWorkingDir: here,
    nodePaths: [join(here, 'node_modules')],
  });
} catch {
  process.exit(1);  // esbuild printed the errors
}
await copyFile(join(here, 'index.html'), join(out, 'index.html'));
