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
  for (let i = 0; i < 10; ++i) for (const o of buildAndUse()) o.dispose();
  const inUse = hedge.heapBytesInUse();
  const memory = hedge.memoryBytes;
  const perMesh = (() => {
    const objects = buildAndUse();
    const bytes = hedge.heapBytesInUse() - inUse;
    for (const o of objects) o.dispose();
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
