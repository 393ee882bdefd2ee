// The top-level README's three.js quick start, run as written: its js block is copied into a fresh
// folder whose node_modules holds this build as the package hedge-mesh and three.js from the
// playground's npm packages, then run under node. Skipped when three.js is not installed. Node
// keeps the links' paths (--preserve-symlinks), so the package finds its peer three.js in the
// folder's node_modules, as it would in a project that installed both.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import {
  existsSync,
  mkdirSync,
  mkdtempSync,
  readFileSync,
  rmSync,
  symlinkSync,
  writeFileSync,
} from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { dist } from './support.mjs';

const root = new URL('../../../', import.meta.url);
const three = fileURLToPath(new URL('web/node_modules/three', root));

test('the README quick start for three.js runs as written', { skip: !existsSync(three) }, () => {
  const readme = readFileSync(new URL('README.md', root), 'utf8');
  const start = readme.indexOf('## JavaScript and three.js (npm)');
  assert.ok(start >= 0, 'the README has its three.js section');
  const open = readme.indexOf('```js\n', start);
  const block = readme.slice(open + 6, readme.indexOf('```\n', open + 6));
  for (const step of [
    'loadHedge',
    'fromBufferGeometry',
    'hedgeRaycast',
    'syncBufferGeometry',
    'fracture',
  ])
    assert.ok(block.includes(step), `the quick start shows ${step}`);
  assert.ok(block.split('\n').length <= 30, 'the quick start is at most 30 lines');
  const folder = mkdtempSync(join(tmpdir(), 'hedge-readme-'));
  try {
    mkdirSync(join(folder, 'node_modules'));
    symlinkSync(fileURLToPath(dist), join(folder, 'node_modules', 'hedge-mesh'));
    symlinkSync(three, join(folder, 'node_modules', 'three'));
    writeFileSync(join(folder, 'quick.mjs'), block);
    const out = execFileSync(
      process.execPath,
      ['--preserve-symlinks', '--preserve-symlinks-main', 'quick.mjs'],
      { cwd: folder, encoding: 'utf8' },
    );
    const shards = /^(\d+) shards; the first weighs ([0-9.]+)/m.exec(out);
    assert.ok(shards, `the quick start prints its shards: ${out}`);
    assert.ok(Number(shards[1]) > 1 && Number(shards[2]) > 0, out);
  } finally {
    rmSync(folder, { recursive: true, force: true });
  }
});
