// Deprecated names (kept for one release): Render and mesh.createRender() still work, as aliases of
// RenderBuffers and mesh.createRenderBuffers(); the next release removes them and this test.
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
// End of deprecated names
