// Running out of wasm memory (2 GB) halfway through an algorithm leaves the mesh as it was. In a
// file of its own: node runs each test file in its own process, and wasm memory never shrinks.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { hedge, octahedron } from './support.mjs';

test('a subdivision past what wasm memory holds throws out-of-memory and changes nothing', () => {
  const mesh = octahedron();
  mesh.subdivide('midpoint', 6); // 32,768 faces
  const render = mesh.createRenderBuffers();
  const counts = mesh.counts();
  const positions = new Float32Array(mesh.positions);
  // Six more steps would make 134 million faces: more than 2 GB.
  assert.throws(
    () => mesh.subdivide('midpoint', 6),
    (e) => e.kind === 'out-of-memory' && /memory/.test(e.message),
  );
  assert.deepEqual(mesh.counts(), counts);
  assert.deepEqual(new Float32Array(mesh.positions), positions);
  assert.deepEqual(mesh.validate(), []);
  // The mesh, its render buffers and picking still work.
  mesh.splitFace(0);
  assert.equal(
    render.sync().full,
    false,
    'subdivide() changed nothing (its strong guarantee, no copy put back): the sync is incremental',
  );
  assert.equal(render.sizes().triangles, counts.faces + 2);
  assert.ok(mesh.pick([0.1, 0.1, 5], [0, 0, -1]));
  assert.deepEqual(mesh.validate(), []);
  render.dispose();
  mesh.dispose();
});
