// Building meshes from typed arrays and from file bytes, queries, and errors.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { hedge, HedgeError, sample, grid, gridArrays, octahedron, cube } from './support.mjs';

test('a grid from typed arrays has the counts of its construction and its positions', () => {
  const input = gridArrays(3);
  const mesh = hedge.fromBuffers(input);
  const c = mesh.counts();
  assert.equal(c.vertices, 16);
  assert.equal(c.faces, 18);
  // 3 x 4 horizontal + 4 x 3 vertical + 9 diagonals.
  assert.equal(c.edges, 33);
  assert.equal(c.halfedges, 66);
  assert.deepEqual(Array.from(mesh.positions), Array.from(input.positions));
  assert.deepEqual(mesh.position(5), [1, 1, 0]);
  assert.equal(mesh.isTriangleMesh(), true);
  assert.deepEqual(mesh.validate(), []);
  mesh.dispose();
});

test('polygons come in through faceSizes', () => {
  const mesh = cube();
  assert.deepEqual(
    { v: mesh.counts().vertices, e: mesh.counts().edges, f: mesh.counts().faces },
    { v: 8, e: 12, f: 6 },
  );
  assert.equal(mesh.isTriangleMesh(), false);
  for (let f = 0; f < 6; ++f) assert.equal(mesh.face(f).vertices.length, 4);
  assert.deepEqual(mesh.validate(), []);
  mesh.dispose();
});

test('half-edge records are consistent: twin, next, prev, origin and face', () => {
  const mesh = grid(2);
  const { halfedges } = mesh.counts();
  for (let h = 0; h < halfedges; ++h) {
    const r = mesh.halfedge(h);
    assert.equal(r.twin, h ^ 1);
    assert.equal(r.edge, h >> 1);
    assert.equal(mesh.halfedge(r.next).origin, r.target);
    assert.equal(mesh.halfedge(r.prev).target, r.origin);
    assert.equal(mesh.halfedge(r.next).prev, h);
    assert.equal(mesh.halfedge(r.twin).origin, r.target);
    assert.equal(r.boundary, r.face === -1);
    if (r.face !== -1) assert.ok(mesh.face(r.face).halfedges.includes(h));
  }
  mesh.dispose();
});

test('the one-ring of an interior vertex and the half-edges of a face', () => {
  const mesh = octahedron();
  const ring = mesh.oneRing(4); // the top: neighbours 0, 1, 2, 3
  assert.equal(ring.halfedges.length, 4);
  assert.deepEqual([...ring.vertices].sort(), [0, 1, 2, 3]);
  assert.equal(ring.faces.filter((f) => f >= 0).length, 4);
  for (let k = 0; k < 4; ++k) {
    const h = mesh.halfedge(ring.halfedges[k]);
    assert.equal(h.origin, 4);
    assert.equal(h.target, ring.vertices[k]);
    assert.equal(h.face, ring.faces[k]);
  }
  assert.equal(mesh.vertex(4).valence, 4);
  assert.equal(mesh.vertex(4).boundary, false);
  const face = mesh.face(0);
  assert.deepEqual([...face.vertices].sort(), [0, 2, 4]);
  for (let k = 0; k < 3; ++k)
    assert.equal(mesh.halfedge(face.halfedges[k]).next, face.halfedges[(k + 1) % 3]);
  const edge = mesh.edge(face.edges[0]);
  assert.deepEqual(edge.halfedges, [2 * face.edges[0], 2 * face.edges[0] + 1]);
  assert.ok(edge.faces.includes(0));
  mesh.dispose();
});

test('a grid corner is a boundary vertex with a boundary gap in its ring', () => {
  const mesh = grid(2);
  const ring = mesh.oneRing(0);
  assert.equal(mesh.vertex(0).boundary, true);
  assert.ok(ring.faces.includes(-1));
  mesh.dispose();
});

test("each file format goes through hedge's own readers", () => {
  // Counts from the files themselves: the tetrahedron of tet.obj, the OFF and PLY headers, and
  // the icosahedron of the binary STL (welded: 12 vertices, 30 edges, 20 faces).
  const tet = hedge.fromFile(sample('tet.obj'), 'tet.obj');
  const text = new TextDecoder().decode(sample('tet.obj'));
  assert.equal(tet.counts().vertices, text.split('\n').filter((l) => l.startsWith('v ')).length);
  assert.equal(tet.counts().faces, text.split('\n').filter((l) => l.startsWith('f ')).length);

  const offBytes = sample('anchor.off');
  const header = new TextDecoder()
    .decode(offBytes.subarray(0, 200))
    .split('\n')
    .filter((l) => l.trim() && !l.startsWith('#'));
  const [nv, nf] = (header[0].trim() === 'OFF' ? header[1] : header[0].replace(/^OFF/, ''))
    .trim()
    .split(/\s+/)
    .map(Number);
  const off = hedge.fromFile(offBytes, 'anchor.off');
  assert.equal(off.counts().faces, nf);
  assert.equal(off.counts().vertices, nv);

  const plyBytes = sample('bob_small.ply');
  const plyHeader = new TextDecoder().decode(plyBytes.subarray(0, 600));
  const plyFaces = Number(/element face (\d+)/.exec(plyHeader)[1]);
  const ply = hedge.fromFile(
    plyBytes.buffer.slice(plyBytes.byteOffset, plyBytes.byteOffset + plyBytes.byteLength),
    'bob_small.ply',
  );
  assert.equal(ply.counts().faces, plyFaces);

  const stl = hedge.fromFile(sample('icosahedron_binary.stl'), 'icosahedron_binary.stl');
  assert.deepEqual([stl.counts().vertices, stl.counts().edges, stl.counts().faces], [12, 30, 20]);

  for (const m of [tet, off, ply, stl]) {
    assert.deepEqual(m.validate(), []);
    m.dispose();
  }
});

test('toArrays gives back what fromBuffers took', () => {
  const input = gridArrays(2);
  const mesh = hedge.fromBuffers(input);
  const out = mesh.toArrays();
  assert.deepEqual(Array.from(out.positions), Array.from(input.positions));
  assert.deepEqual(Array.from(out.indices).length, input.indices.length);
  assert.equal(out.faceSizes, null);
  const again = hedge.fromBuffers(out);
  assert.deepEqual(again.counts(), mesh.counts());
  mesh.dispose();
  again.dispose();
});

test('a hostile glTF reads no other file, and deep or amplifying JSON is refused', () => {
  const head =
    '{"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],' +
    '"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],' +
    '"bufferViews":[{"buffer":0,"byteLength":36}],';
  const file = (meshes, buffers, extra = '') =>
    new TextEncoder().encode(head + '"meshes":' + meshes + ',"buffers":' + buffers + extra + '}');
  const one = '[{"primitives":[{"attributes":{"POSITION":0}}]}]';
  // Positions (0,0,0) (1,0,0) (0,1,0).
  const embedded =
    '[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]';
  const triangle = hedge.fromFile(file(one, embedded), 'tri.gltf');
  assert.equal(triangle.counts().faces, 1);
  triangle.dispose();
  // Bytes from a page have no folder: external buffers are off.
  assert.throws(
    () => hedge.fromFile(file(one, '[{"byteLength":36,"uri":"tri.bin"}]'), 'tri.gltf'),
    (e) =>
      e.kind === 'io' &&
      /tri\.gltf: buffer 0: .*reading external buffers is turned off/.test(e.message),
  );
  assert.throws(
    () => hedge.fromFile(file(one, '[{"byteLength":36,"uri":"../../etc/passwd"}]'), 'tri.gltf'),
    (e) => e.kind === 'io' && /turned off/.test(e.message),
  );
  assert.throws(
    () =>
      hedge.fromFile(
        file(one, embedded, ',"extras":' + '['.repeat(17000) + ']'.repeat(17000)),
        'deep.gltf',
      ),
    (e) =>
      e.kind === 'io' &&
      /deep\.gltf: malformed glTF: JSON nested deeper than 64 levels/.test(e.message),
  );
  // 1,000 primitives sharing one accessor of 30,000 indices: 30M corners from 120 KB, refused.
  const shared = new TextEncoder().encode(
    '{"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],' +
      '"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},' +
      '{"bufferView":1,"componentType":5123,"count":30000,"type":"SCALAR"}],' +
      '"bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":60000}],' +
      '"meshes":[{"primitives":[' +
      Array(1000).fill('{"attributes":{"POSITION":0},"indices":1}').join(',') +
      ']}],' +
      '"buffers":[{"byteLength":60036,"uri":"data:application/octet-stream;base64,' +
      'A'.repeat(80048) +
      '"}]}',
  );
  assert.throws(
    () => hedge.fromFile(shared, 'shared.gltf'),
    (e) => e.kind === 'io' && /shared\.gltf: .*more than the read budget/.test(e.message),
  );
});

test('a malformed file throws a HedgeError naming the file and line, and the module keeps working', () => {
  const bad = new TextEncoder().encode('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 oops\n');
  assert.throws(
    () => hedge.fromFile(bad, 'broken.obj'),
    (e) =>
      e instanceof HedgeError &&
      e instanceof Error &&
      e.kind === 'io' &&
      /broken\.obj:4/.test(e.message),
  );
  const truncated = sample('icosahedron_binary.stl').subarray(0, 200);
  assert.throws(
    () => hedge.fromFile(truncated, 'cut.stl'),
    (e) => e.kind === 'io' && /cut\.stl/.test(e.message),
  );
  assert.throws(
    () => hedge.fromFile(bad, 'mesh.xyz'),
    (e) => e.kind === 'io' && /xyz/.test(e.message),
  );
  const mesh = grid(1);
  assert.equal(mesh.counts().faces, 2);
  mesh.dispose();
});

test('bad typed-array input is refused with a clear message', () => {
  assert.throws(
    () =>
      hedge.fromBuffers({
        positions: new Float32Array([0, 0, 0, 1, 0, 0, 0, NaN, 0]),
        indices: new Uint32Array([0, 1, 2]),
      }),
    (e) => e.kind === 'invalid-argument' && /finite|NaN/i.test(e.message),
  );
  assert.throws(
    () =>
      hedge.fromBuffers({
        positions: new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0]),
        indices: new Uint32Array([0, 1, 7]),
      }),
    (e) => e.kind === 'invalid-argument' && /7/.test(e.message),
  );
  assert.throws(
    () =>
      hedge.fromBuffers({
        positions: new Float32Array([0, 0, 0, 1, 0]),
        indices: new Uint32Array([0, 1, 2]),
      }),
    (e) => e.kind === 'invalid-argument' && /3 per vertex/.test(e.message),
  );
  // Three triangles on one edge: not a manifold, refused under the strict policy.
  const fan = {
    positions: new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1]),
    indices: new Uint32Array([0, 1, 2, 1, 0, 3, 0, 1, 4]),
  };
  assert.throws(
    () => hedge.fromBuffers({ ...fan, policy: 'strict' }),
    (e) => e.kind === 'topology',
  );
  const repaired = hedge.fromBuffers(fan);
  assert.ok(repaired.buildReport().repairs > 0);
  assert.deepEqual(repaired.validate(), []);
  repaired.dispose();
});

test('queries on dead elements and disposed meshes throw', () => {
  const mesh = grid(1);
  assert.throws(
    () => mesh.halfedge(1000),
    (e) => e.kind === 'bad-handle' && /halfedge 1000 is out of range/.test(e.message),
  );
  assert.throws(
    () => mesh.vertex(-1),
    (e) => e.kind === 'bad-handle',
  );
  assert.throws(
    () => mesh.setPosition(0, [0, NaN, 0]),
    (e) => e.kind === 'invalid-argument' && /finite/.test(e.message),
  );
  mesh.dispose();
  mesh.dispose(); // idempotent
  assert.equal(mesh.disposed, true);
  assert.throws(
    () => mesh.counts(),
    (e) => e instanceof HedgeError && e.kind === 'bad-handle' && /disposed/.test(e.message),
  );
});

test('arguments of the wrong type are refused before they reach the module', () => {
  const mesh = grid(2);
  assert.throws(
    () => hedge.fromBuffers({ positions: 'abc', indices: new Uint32Array(3) }),
    (e) => e.kind === 'invalid-argument',
  );
  assert.throws(
    () => mesh.setPosition(0, ['a', 0, 0]),
    (e) => e.kind === 'invalid-argument' && /^setPosition: point must be/.test(e.message),
  );
  assert.throws(
    () => mesh.setPosition(0, [NaN, 0, 0]),
    (e) => e.kind === 'invalid-argument' && /finite/.test(e.message),
  );
  assert.throws(
    () => mesh.setPosition(0, [1, 2]),
    (e) => e.kind === 'invalid-argument',
  );
  assert.equal(mesh.pick([NaN, 0, 1], [0, 0, -1]), null, 'a NaN origin finds nothing');
  assert.throws(
    () => mesh.pick(['x', 0, 1], [0, 0, -1]),
    (e) => e.kind === 'invalid-argument' && /^pick: origin must be/.test(e.message),
  );
  assert.throws(
    () => mesh.pickMany(new Float32Array(6), [0]),
    (e) => e.kind === 'invalid-argument',
  );
  assert.throws(
    () => mesh.pickMany(new Float32Array(12), new Int32Array(1)),
    (e) => e.kind === 'invalid-argument' && /2 entries/.test(e.message),
  );
  assert.deepEqual(mesh.position(0), [0, 0, 0]);
  // Still working after all that.
  assert.equal(mesh.pick([0.5, 0.2, 1], [0, 0, -1]).face, 0);
  assert.deepEqual(mesh.validate(), []);
  mesh.dispose();
});

test('engine streams: welded positions, attributes per corner and one submesh per triangle', () => {
  // Two triangles of a square whose shared edge is a seam: its vertices come twice, with other uvs.
  const streams = {
    positions: new Float32Array([0, 0, 0, 1, 0, 0, 1, 1, 0, 1, 1, 0, 0, 1, 0, 0, 0, 0]),
    indices: new Uint32Array([0, 1, 2, 3, 4, 5]),
    texcoords: new Float32Array([0, 0, 1, 0, 1, 1, 0.5, 0.5, 0, 1, 0, 0.5]),
    colors: new Float32Array(24).fill(0.5),
    submeshes: new Int32Array([0, 2]),
  };
  const mesh = hedge.fromEngineStreams(streams);
  assert.deepEqual([mesh.counts().vertices, mesh.counts().faces], [4, 2]);
  const render = mesh.createRenderBuffers();
  assert.equal(render.sizes().vertices, 6, 'the seam keeps both sets of uvs');
  const submeshes = render.submeshes();
  assert.deepEqual(
    submeshes.map((s) => s.empty),
    [false, true, false],
  );
  assert.deepEqual(
    submeshes.map((s) => s.indexStart <= s.indexStart + s.indexCount),
    [true, true, true],
  );
  assert.equal(submeshes[2].indexStart + submeshes[2].indexCount, render.sizes().indexCount);
  assert.deepEqual(mesh.validate(), []);
  render.dispose();
  mesh.dispose();

  const refused = (change, message) =>
    assert.throws(
      () => hedge.fromEngineStreams({ ...streams, ...change }),
      (e) => e instanceof HedgeError && e.kind === 'invalid-argument' && message.test(e.message),
      String(message),
    );
  refused({ texcoords: new Float32Array(11) }, /^texcoords: 11 floats is not 2 per vertex for 6/);
  refused({ colors: new Float32Array(18) }, /^colors: 18 floats is not 4 per vertex for 6/);
  refused({ submeshes: new Int32Array([0]) }, /^submeshes: 1 ids is not one per triangle for 2/);
  refused({ submeshes: new Int32Array([0, 70000]) }, /70000/);
  refused({ indices: new Uint32Array([0, 1]) }, /^indices: 2 entries is not 3 per triangle/);
  refused({ weld: 'loose' }, /^fromEngineStreams: unknown weld 'loose'/);
});
