// Deprecated names (kept for one release): Render and mesh.createRender() still work, as aliases of
// RenderBuffers and mesh.createRenderBuffers(), and loadHedgeNode() of loadHedge() under node; the
// next release removes them and this test.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { grid } from './support.mjs';

const dist = process.env.HEDGE_WASM_DIST
  ? new URL(`file://${process.env.HEDGE_WASM_DIST.replace(/\/?$/, '/')}`)
  : new URL('../../../build/wasm/dist/', import.meta.url);
const api = await import(new URL('node.js', dist).href);

test('Render is RenderBuffers, and createRender() makes one', () => {
  assert.equal(api.Render, api.RenderBuffers);
  const mesh = grid(2);
  const render = mesh.createRender({ normals: 'none' });
  assert.ok(render instanceof api.RenderBuffers);
  assert.equal(render.indices.length, mesh.createRenderBuffers().indices.length);
  mesh.dispose();
});
test('loadHedgeNode() is loadHedge() under node', async () => {
  const loaded = await api.loadHedgeNode();
  assert.ok(loaded instanceof api.Hedge);
  const mesh = loaded.fromBuffers({
    positions: new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0]),
    indices: new Uint32Array([0, 1, 2]),
  });
  assert.deepEqual(mesh.validate(), []);
  mesh.dispose();
});
// End of deprecated names
