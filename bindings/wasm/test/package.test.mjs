// The npm package: one loadHedge() that works under node without globals, the single-file variant,
// and the version shared with CMakeLists.txt.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { dist, hedge } from './support.mjs';

const root = new URL('../../../', import.meta.url);
const text = (url) => readFileSync(url, 'utf8');

function triangle(loaded) {
  return loaded.fromBuffers({
    positions: new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0]),
    indices: new Uint32Array([0, 1, 2]),
  });
}

test('loadHedge() of hedge.js works under node and sets no globals', async () => {
  const { loadHedge } = await import(new URL('hedge.js', dist).href);
  const loaded = await loadHedge();
  assert.equal(globalThis.require, undefined);
  assert.equal(globalThis.__dirname, undefined);
  const mesh = triangle(loaded);
  mesh.splitEdge(0);
  assert.deepEqual(mesh.validate(), []);
  mesh.dispose();
});

test('the module has no node code of its own: no require, no __dirname', () => {
  const module = text(new URL('hedge.mjs', dist));
  assert.equal(module.includes('__dirname'), false);
  assert.equal(/\brequire\("(fs|path)"\)/.test(module), false);
});

test('under node, locateFile says where to read hedge.wasm, and a wrong place is named', async () => {
  const { loadHedge } = await import(new URL('hedge.js', dist).href);
  const path = fileURLToPath(new URL('hedge.wasm', dist));
  const loaded = await loadHedge({ locateFile: () => path });
  const mesh = triangle(loaded);
  assert.deepEqual(mesh.validate(), []);
  mesh.dispose();
  await assert.rejects(loadHedge({ locateFile: () => '/nonexistent/hedge.wasm' }), {
    message: /loadHedge: cannot read the WebAssembly module file:\/\/\/nonexistent\/hedge\.wasm/,
  });
});

test('the single-file variant embeds the wasm and loads under node without reading a file', async () => {
  const module = text(new URL('hedge.single.mjs', dist));
  assert.equal(module.includes('new URL("hedge.wasm"'), false);
  assert.ok(module.includes('data:application/octet-stream;base64,'));
  const entry = text(new URL('hedge.single.js', dist));
  assert.equal(entry.includes("'./hedge.mjs'"), false);
  const single = await import(new URL('hedge.single.js', dist).href);
  // A locateFile that fails shows that nothing is read from disk.
  const loaded = await single.loadHedge({
    locateFile: () => assert.fail('the single-file module located a file'),
  });
  const mesh = triangle(loaded);
  mesh.splitEdge(0);
  assert.deepEqual(mesh.validate(), []);
  assert.equal(loaded.version, hedge.version);
  mesh.dispose();
});

test('the package, the module and CMakeLists.txt have one version', () => {
  const pkg = JSON.parse(text(new URL('bindings/wasm/package.json', root)));
  const project = /project\(hedge VERSION (\d+\.\d+\.\d+)/.exec(
    text(new URL('CMakeLists.txt', root)),
  );
  assert.ok(project, 'CMakeLists.txt: project(hedge VERSION x.y.z) not found');
  assert.equal(pkg.version, project[1]);
  assert.equal(hedge.version, project[1]);
  assert.equal(pkg.engines.node, '>=18');
});
