// Memory: 1,000 meshes built and dropped do not grow the wasm heap, through dispose() and through
// the garbage collector (FinalizationRegistry; needs node --expose-gc, as test/run passes).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { hedge, gridArrays } from './support.mjs';

const input = gridArrays(20); // 441 vertices, 800 triangles: about 100 KB of heap per mesh with its render

function buildAndUse() {
  const mesh = hedge.fromBuffers(input);
  mesh.pick([3.3, 4.1, 1], [0, 0, -1]);
  const render = mesh.createRenderBuffers();
  mesh.splitFace(3);
  render.sync();
  return [mesh, render];
}

test('1,000 meshes built and disposed leave the heap as it was', () => {
  // Warm up: the allocator's own structures, embind's type tables.
  // The render first: disposing the mesh under it would warn (see the last test).
  for (let i = 0; i < 10; ++i) for (const o of buildAndUse().reverse()) o.dispose();
  const inUse = hedge.heapBytesInUse();
  const memory = hedge.memoryBytes;
  const perMesh = (() => {
    const objects = buildAndUse();
    const bytes = hedge.heapBytesInUse() - inUse;
    for (const o of objects.reverse()) o.dispose();
    return bytes;
  })();
  assert.ok(perMesh > 50_000, `a mesh holds ${perMesh} bytes`);
  for (let i = 0; i < 1000; ++i) {
    const [mesh, render] = buildAndUse();
    render.dispose();
    mesh.dispose();
  }
  assert.equal(hedge.heapBytesInUse(), inUse, 'every byte came back');
  assert.equal(hedge.memoryBytes, memory, 'wasm memory did not grow');
});

const collect = async () => {
  for (let i = 0; i < 5; ++i) {
    globalThis.gc();
    await new Promise((resolve) => setTimeout(resolve, 10));
  }
};

test(
  '1,000 meshes dropped without dispose are freed by the garbage collector',
  { skip: typeof globalThis.gc !== 'function' && 'needs node --expose-gc' },
  async () => {
    await collect();
    const inUse = hedge.heapBytesInUse();
    let peak = 0;
    for (let batch = 0; batch < 10; ++batch) {
      for (let i = 0; i < 100; ++i) buildAndUse(); // dropped at once
      peak = Math.max(peak, hedge.heapBytesInUse());
      await collect();
    }
    await collect();
    const after = hedge.heapBytesInUse();
    // 100 live meshes at a time at most (about 10 MB); afterwards all were freed.
    assert.ok(
      peak - inUse > 100 * 50_000 * 0.5,
      `the batches were allocated (${peak - inUse} bytes)`,
    );
    assert.ok(after - inUse < 200_000, `the heap is back to ${after} bytes from ${inUse}`);
  },
);

// The lifetime rule: a RenderBuffers shares its mesh, so Mesh.dispose() under a live one frees
// nothing, and says so (hedge.warnings) instead of leaving the memory held in silence.
test('disposing a mesh under a live RenderBuffers warns and frees nothing until the render goes', (t) => {
  const warned = [];
  t.mock.method(console, 'warn', (message) => warned.push(String(message)));
  const inUse = hedge.heapBytesInUse();
  const mesh = hedge.fromBuffers(input);
  const render = mesh.createRenderBuffers();
  render.sync();
  const held = hedge.heapBytesInUse();
  mesh.dispose();
  assert.equal(warned.length, 1, 'one warning');
  assert.match(warned[0], /Mesh\.dispose\(\) with 1 live RenderBuffers/);
  // Only the handle's few bytes came back, not the mesh's.
  const freed = held - hedge.heapBytesInUse();
  assert.ok(freed < (held - inUse) / 20, `the dispose freed ${freed} of ${held - inUse} bytes`);
  assert.equal(render.sync().full, false, 'the RenderBuffers still works');
  render.dispose();
  assert.equal(hedge.heapBytesInUse(), inUse, 'freed with the RenderBuffers');

  // The right order, a disposed render, and hedge.warnings = false: no warning.
  const second = hedge.fromBuffers(input);
  second.createRenderBuffers().dispose();
  second.dispose();
  const third = hedge.fromBuffers(input);
  const thirdRender = third.createRenderBuffers();
  hedge.warnings = false;
  try {
    third.dispose();
  } finally {
    hedge.warnings = true;
    thirdRender.dispose();
  }
  assert.equal(warned.length, 1, `warnings: ${warned.join(' | ')}`);
  assert.equal(hedge.heapBytesInUse(), inUse, 'every byte came back');
  assert.equal(mesh.disposed && second.disposed && third.disposed, true);
});
