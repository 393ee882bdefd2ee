// RenderBuffers through JS: views into wasm memory and dirty ranges after edits.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { hedge, grid, sample } from './support.mjs';

test('the buffers are views into wasm memory holding every triangle of the mesh', () => {
  const mesh = grid(4);
  const render = mesh.createRenderBuffers({ normals: 'computed' });
  const layout = render.layout;
  assert.equal(layout.interleaved, true);
  assert.equal(layout.stride, 6);
  assert.equal(layout.normal, 3);
  const sizes = render.sizes();
  const vertices = render.vertices;
  const indices = render.indices;
  assert.equal(vertices.buffer, hedge.module.HEAPU8.buffer, 'a view, not a copy');
  assert.equal(indices.buffer, hedge.module.HEAPU8.buffer);
  assert.equal(indices.length, sizes.indexCount);
  assert.equal(sizes.triangles, 32);
  assert.equal(vertices.length, sizes.vertexSlots * layout.stride);
  // Each render vertex holds its mesh vertex's position, and the flat grid's normal is +z.
  const source = render.vertexSource;
  for (let r = 0; r < sizes.vertexSlots; ++r) {
    const p = mesh.position(source[r]);
    assert.deepEqual(Array.from(vertices.subarray(r * 6, r * 6 + 3)), p);
    assert.ok(Math.abs(vertices[r * 6 + 5] - 1) < 1e-6);
  }
  render.dispose();
  mesh.dispose();
});

test('an edit syncs only its dirty ranges, which hold the edit', () => {
  const mesh = grid(8);
  const render = mesh.createRenderBuffers();
  // The buffers are built with the render object: the first sync has nothing to do.
  assert.equal(render.sync().vertexRanges.length, 0);
  const total = render.sizes().bufferBytes;
  const v = mesh.splitFace(40);
  const result = render.sync();
  assert.equal(result.full, false);
  assert.ok(result.vertexRanges.length >= 2 && result.indexRanges.length >= 2);
  assert.ok(result.vertexBytes + result.indexBytes > 0);
  assert.ok(
    result.vertexBytes + result.indexBytes < total / 4,
    `${result.vertexBytes + result.indexBytes} of ${total} bytes`,
  );
  // The new vertex's render vertex lies in a dirty range, with its position.
  const source = render.vertexSource;
  const stride = render.layout.stride;
  const rv = source.indexOf(v);
  assert.ok(rv >= 0);
  let covered = false;
  for (let k = 0; k < result.vertexRanges.length; k += 2)
    covered ||=
      rv >= result.vertexRanges[k] && rv < result.vertexRanges[k] + result.vertexRanges[k + 1];
  assert.ok(covered);
  const views = render.dirtyViews(result);
  assert.equal(views.vertices.length, result.vertexRanges.length / 2);
  assert.equal(
    views.vertices.reduce((n, a) => n + a.byteLength, 0),
    result.vertexBytes,
  );
  assert.equal(
    views.indices.reduce((n, a) => n + a.byteLength, 0),
    result.indexBytes,
  );
  assert.deepEqual(
    Array.from(render.vertices.subarray(rv * stride, rv * stride + 3)),
    mesh.position(v),
  );
  // The face's triangles name the new vertex's render vertex.
  const [slot, count] = render.faceTriangles(40);
  assert.equal(count, 1);
  assert.ok(Array.from(render.indices.subarray(3 * slot, 3 * slot + 3)).includes(rv));
  // Nothing changed since: an empty sync.
  const none = render.sync();
  assert.equal(none.vertexRanges.length + none.indexRanges.length, 0);
  const all = render.rebuild();
  assert.ok(all.full);
  assert.equal(all.indexBytes, 4 * render.sizes().indexCount);
  assert.deepEqual(mesh.validate(), []);
  render.dispose();
  mesh.dispose();
});

test('a transaction syncs many edits once; compact removes free slots', () => {
  const mesh = grid(4);
  const render = mesh.createRenderBuffers({ interleaved: false, normals: 'none' });
  assert.equal(render.layout.interleaved, false);
  render.begin();
  mesh.splitFace(0);
  mesh.splitFace(5);
  assert.equal(render.sync().vertexRanges.length, 0, 'nothing inside a transaction');
  const result = render.commit();
  assert.ok(result.facesSynced >= 6);
  let h = 0;
  while (!mesh.canCollapse(h)) ++h;
  mesh.collapse(h);
  render.sync();
  render.compact();
  assert.equal(render.sizes().freeTriangleSlots, 0);
  assert.equal(render.sizes().triangles, mesh.counts().faces);
  assert.deepEqual(mesh.validate(), []);
  render.dispose();
  mesh.dispose();
});

test('views go stale when wasm memory grows and are taken again', () => {
  const mesh = grid(2);
  const render = mesh.createRenderBuffers();
  const stale = render.vertices;
  const before = hedge.memoryBytes;
  // Enough to grow memory: a mesh of a few million floats.
  const big = grid(400);
  assert.ok(hedge.memoryBytes > before, 'memory grew');
  assert.equal(stale.length, 0, 'a view over the old memory is detached');
  const fresh = render.vertices;
  assert.ok(fresh.length > 0);
  assert.equal(fresh.buffer, hedge.module.HEAPU8.buffer);
  big.dispose();
  render.dispose();
  mesh.dispose();
});

test('a render outlives the disposal of its mesh', () => {
  const mesh = grid(2);
  const render = mesh.createRenderBuffers();
  mesh.dispose();
  assert.equal(render.sizes().triangles, 8);
  assert.equal(render.sync().vertexRanges.length, 0);
  render.dispose();
  render.dispose();
  assert.throws(
    () => render.sizes(),
    (e) => e.kind === 'bad-handle',
  );
});

test('an algorithm that renumbers everything makes the next sync full, with the new triangles', () => {
  const mesh = grid(3);
  const render = mesh.createRenderBuffers();
  mesh.subdivide('loop');
  const result = render.sync();
  assert.equal(result.full, true);
  assert.equal(render.sizes().triangles, 4 * 18);
  assert.equal(result.indexBytes, 4 * render.sizes().indexCount);
  mesh.decimate({ ratio: 0.5 });
  assert.equal(render.sync().full, true);
  assert.equal(render.sizes().triangles, mesh.counts().faces);
  assert.deepEqual(mesh.validate(), []);
  render.dispose();
  mesh.dispose();
});

test('texture coordinates from a file reach the vertex layout, UV seams as separate render vertices', () => {
  const mesh = hedge.fromFile(sample('spot_triangulated.obj'), 'spot.obj');
  const render = mesh.createRenderBuffers({ normals: 'computed' });
  const layout = render.layout;
  assert.equal(layout.stride, 8);
  assert.equal(layout.texcoord, 6);
  const sizes = render.sizes();
  assert.ok(sizes.vertices > mesh.counts().vertices, 'seams split vertices');
  // Every render vertex carries one of the file's vt pairs.
  const uvs = new Set(
    new TextDecoder()
      .decode(sample('spot_triangulated.obj'))
      .split('\n')
      .filter((l) => l.startsWith('vt '))
      .map((l) =>
        l
          .trim()
          .split(/\s+/)
          .slice(1, 3)
          .map((x) => Math.fround(Number(x)))
          .join(' '),
      ),
  );
  const v = render.vertices;
  for (let r = 0; r < sizes.vertexSlots; ++r)
    assert.ok(uvs.has(`${v[r * 8 + 6]} ${v[r * 8 + 7]}`), `render vertex ${r}`);
  render.dispose();
  mesh.dispose();
});

test('pickTriangles finds the face under a ray and its triangle slots as of the last sync', () => {
  const mesh = grid(4);
  const render = mesh.createRenderBuffers();
  render.sync();
  const hit = render.pickTriangles([1.25, 2.6, 1], [0, 0, -1]);
  const pick = mesh.pick([1.25, 2.6, 1], [0, 0, -1]);
  assert.equal(hit.face, pick.face);
  assert.ok(Math.abs(hit.t - 1) < 1e-6);
  assert.deepEqual(
    hit.point.map((x) => Math.round(x * 1e6) / 1e6),
    [1.25, 2.6, 0],
  );
  assert.deepEqual([hit.first, hit.count], render.faceTriangles(hit.face));
  assert.equal(render.pickTriangles([1.25, 2.6, 1], [0, 0, 1]), null);
  // A face made after the last sync has no slots yet.
  mesh.splitFace(hit.face, [1.25, 2.6, 0]);
  let fresh = 0;
  for (const [dx, dy] of [
    [0.2, 0],
    [-0.2, 0],
    [0, 0.2],
    [0, -0.2],
  ]) {
    const h = render.pickTriangles([1.25, 2.6, 1], [dx, dy, -1]);
    if (h.face >= 32) {
      assert.equal(h.count, 0, `face ${h.face} is newer than the last sync`);
      fresh += 1;
    }
  }
  assert.ok(fresh > 0);
  render.sync();
  const synced = render.pickTriangles([1.25, 2.6, 1], [0.01, 0.2, -1]);
  assert.equal(synced.count, 1);
  assert.deepEqual([synced.first, synced.count], render.faceTriangles(synced.face));
  assert.deepEqual(mesh.validate(), []);
  render.dispose();
  mesh.dispose();
});
