// Local operations with their checks and refusal reasons, and the algorithms.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { hedge, grid, octahedron, tetrahedron, cube, sample } from './support.mjs';

function interiorEdge(mesh) {
  for (let e = 0; e < mesh.counts().edgeSlots; ++e) if (!mesh.edge(e).boundary) return e;
  throw new Error('no interior edge');
}

test('splitEdge of an interior edge adds a vertex, three edges and two faces at the point', () => {
  const mesh = grid(2);
  const before = mesh.counts();
  const e = interiorEdge(mesh);
  const [a, b] = mesh.edge(e).vertices;
  const v = mesh.splitEdge(e);
  const after = mesh.counts();
  assert.equal(after.vertices, before.vertices + 1);
  assert.equal(after.edges, before.edges + 3);
  assert.equal(after.faces, before.faces + 2);
  const pa = mesh.position(a);
  const pb = mesh.position(b);
  assert.deepEqual(
    mesh.position(v),
    [0, 1, 2].map((k) => (pa[k] + pb[k]) / 2),
  );
  assert.equal(mesh.vertex(v).valence, 4);
  const w = mesh.splitEdge(e, [0.25, 0.25, 0]);
  assert.deepEqual(mesh.position(w), [0.25, 0.25, 0]);
  assert.deepEqual(mesh.validate(), []);
  mesh.dispose();
});

test('flip turns an edge to join the tips of its triangles', () => {
  const mesh = octahedron();
  const e = 0;
  const { halfedges, vertices } = mesh.edge(e);
  const tips = halfedges.map((h) => mesh.halfedge(mesh.halfedge(h).next).target);
  assert.equal(mesh.canFlip(e), true);
  assert.equal(mesh.refusal('flip', e), null);
  assert.equal(mesh.flip(e), e);
  assert.deepEqual([...mesh.edge(e).vertices].sort(), [...tips].sort());
  assert.ok(!mesh.edge(e).vertices.includes(vertices[0]));
  assert.deepEqual(mesh.validate(), []);
  mesh.dispose();
});

test('a refused flip says why and changes nothing', () => {
  const mesh = grid(1);
  const boundary = [0, 1, 2, 3, 4].find((e) => mesh.edge(e).boundary);
  const before = Array.from(mesh.positions);
  assert.match(mesh.refusal('flip', boundary), /boundary/);
  assert.equal(mesh.canFlip(boundary), false);
  assert.throws(
    () => mesh.flip(boundary),
    (e) =>
      e.kind === 'refused' &&
      /boundary/.test(e.message) &&
      e.refusal === mesh.refusal('flip', boundary),
  );
  assert.equal(mesh.lastRefusal, mesh.refusal('flip', boundary));
  assert.deepEqual(Array.from(mesh.positions), before);
  assert.equal(mesh.counts().edges, 5);
  assert.deepEqual(mesh.validate(), []);

  const tet = tetrahedron();
  // Every end of a tetrahedron's edges is an interior vertex of valence 3.
  assert.match(tet.refusal('flip', 0), /valence 3|already joined/);
  assert.throws(
    () => tet.flip(0),
    (e) => e.kind === 'refused',
  );
  // A collapse would leave two triangles on the same three vertices.
  assert.equal(tet.canCollapse(0), false);
  const reason = tet.refusal('collapse', 0);
  assert.ok(reason && reason.length > 20, reason);
  assert.throws(
    () => tet.collapse(0),
    (e) => e.kind === 'refused' && e.message.includes(reason),
  );
  assert.deepEqual(tet.counts().faces, 4);
  assert.deepEqual(tet.validate(), []);

  const quads = cube();
  assert.match(quads.refusal('flip', 0), /not a triangle/);
  mesh.dispose();
  tet.dispose();
  quads.dispose();
});

test('collapse merges the origin into the target, which keeps its place or moves to the point', () => {
  const mesh = grid(3);
  const before = mesh.counts();
  // The half-edge from interior vertex 5 (1,1) to 6 (2,1).
  const h = mesh.oneRing(5).halfedges.find((x) => mesh.halfedge(x).target === 6);
  assert.equal(mesh.canCollapse(h), true);
  const v = mesh.collapse(h, [1.5, 1, 0]);
  assert.equal(v, 6);
  assert.deepEqual(mesh.position(6), [1.5, 1, 0]);
  const after = mesh.counts();
  assert.equal(after.vertices, before.vertices - 1);
  assert.equal(after.faces, before.faces - 2);
  assert.equal(after.edges, before.edges - 3);
  assert.throws(
    () => mesh.vertex(5),
    (e) => e.kind === 'bad-handle' && e.message === 'vertex 5 is deleted',
  );
  assert.deepEqual(mesh.validate(), []);
  mesh.garbageCollection();
  assert.equal(mesh.counts().vertexSlots, after.vertices);
  assert.deepEqual(mesh.validate(), []);
  mesh.dispose();
});

test('the link condition is named when a collapse would pinch the surface', () => {
  const mesh = octahedron();
  // Collapse the top into a neighbour, then the remaining ring is a valence-3 configuration.
  mesh.collapse(mesh.oneRing(4).halfedges[0]);
  let refusedOne = null;
  for (let h = 0; h < mesh.counts().halfedgeSlots; ++h) {
    if (mesh.refusal('collapse', h) !== null && !/not live/.test(mesh.refusal('collapse', h))) {
      refusedOne = mesh.refusal('collapse', h);
      break;
    }
  }
  assert.ok(refusedOne, 'some collapse of the collapsed octahedron is refused');
  assert.match(refusedOne, /link condition|too few edges|boundary/);
  assert.deepEqual(mesh.validate(), []);
  mesh.dispose();
});

test('splitFace fans a triangle into three about its centroid', () => {
  const mesh = grid(1);
  const v = mesh.splitFace(0);
  const c = mesh.counts();
  assert.equal(c.faces, 4);
  assert.equal(c.vertices, 5);
  assert.equal(mesh.vertex(v).valence, 3);
  const p = mesh.position(v);
  assert.ok(Math.abs(p[0] - 2 / 3) < 1e-6 && Math.abs(p[1] - 1 / 3) < 1e-6, `centroid ${p}`);
  assert.throws(
    () => mesh.splitFace(99),
    (e) => e.kind === 'bad-handle' && /face 99/.test(e.message),
  );
  assert.equal(mesh.refusal('splitFace', 99), 'the face is not live');
  assert.equal(mesh.whyNot('splitFace', 99), 'the face is not live'); // the deprecated alias
  assert.equal(mesh.refusal('splitFace', 0), null);
  assert.throws(
    () => mesh.refusal('explode', 0),
    (e) => e.kind === 'invalid-argument' && /explode/.test(e.message),
  );
  assert.deepEqual(mesh.validate(), []);
  mesh.dispose();
});

test('subdivide: each scheme gives its face count', () => {
  const expected = { loop: 32, midpoint: 32, 'catmull-clark': 24, sqrt3: 24, 'split-faces': 24 };
  for (const [scheme, faces] of Object.entries(expected)) {
    const mesh = octahedron();
    mesh.subdivide(scheme);
    assert.equal(mesh.counts().faces, faces, scheme);
    assert.deepEqual(mesh.validate(), [], scheme);
    mesh.dispose();
  }
  const quads = cube();
  quads.subdivide('catmull-clark', 2);
  assert.equal(quads.counts().faces, 6 * 16);
  assert.deepEqual(quads.validate(), []);
  assert.throws(
    () => quads.subdivide('loop'),
    (e) => e.kind === 'invalid-argument' && /triangle/.test(e.message),
  );
  assert.throws(
    () => quads.subdivide('butterfly'),
    (e) => e.kind === 'invalid-argument' && /butterfly/.test(e.message),
  );
  quads.dispose();
});

test('smooth: each method moves vertices toward their neighbours and keeps the counts', () => {
  for (const method of ['uniform', 'taubin', 'cotangent', 'implicit']) {
    const mesh = octahedron();
    mesh.subdivide('loop', 2);
    const counts = mesh.counts();
    // Pull one vertex out; smoothing must pull it back in.
    const p = mesh.position(0);
    mesh.setPosition(0, [p[0] * 2, p[1] * 2, p[2] * 2]);
    const spike = Math.hypot(...mesh.position(0));
    mesh.smooth({ method, iterations: 5, lambda: method === 'implicit' ? 1 : 0.5 });
    assert.ok(Math.hypot(...mesh.position(0)) < spike, method);
    assert.deepEqual(mesh.counts(), counts, method);
    assert.deepEqual(mesh.validate(), [], method);
    mesh.dispose();
  }
  const mesh = grid(2);
  assert.throws(
    () => mesh.smooth({ method: 'uniform', lambda: 2 }),
    (e) => e.kind === 'invalid-argument' && /lambda/.test(e.message),
  );
  assert.throws(
    () => mesh.smooth({ method: 'wiggle' }),
    (e) => e.kind === 'invalid-argument',
  );
  mesh.dispose();
});

test('decimate by a ratio reaches the target face count', () => {
  const mesh = octahedron();
  mesh.subdivide('loop', 3); // 512 faces
  const faces = mesh.counts().faces;
  const result = mesh.decimate({ ratio: 0.25 });
  assert.ok(result.faces <= Math.round(faces * 0.25), `${result.faces} faces`);
  assert.ok(result.faces > 8);
  assert.equal(mesh.counts().faces, result.faces);
  assert.ok(result.collapses > 0);
  assert.deepEqual(mesh.validate(), []);
  assert.throws(
    () => mesh.decimate({ ratio: 0 }),
    (e) => e.kind === 'invalid-argument',
  );
  mesh.dispose();
});

test('decimate says why it stopped and holds the normal limit when asked', () => {
  // Spot to 20 vertices: the 60-degree normal limit alone stops the run short, unless relaxed.
  const held = hedge.fromFile(sample('spot_triangulated.obj'), 'spot.obj');
  const strict = held.decimate({ targetVertices: 20, relaxNormalChange: false });
  assert.equal(strict.stop, 'no_legal_collapse');
  assert.ok(strict.refused.normal > 0 && strict.vertices > 20, JSON.stringify(strict));
  assert.deepEqual(Object.keys(strict.refused).sort(), ['normal', 'shape', 'topology']);
  assert.deepEqual(held.validate(), []);
  const mesh = hedge.fromFile(sample('spot_triangulated.obj'), 'spot.obj');
  const relaxed = mesh.decimate({ targetVertices: 20 });
  assert.equal(relaxed.stop, 'target_reached');
  assert.ok(relaxed.collapses > strict.collapses, `${relaxed.collapses} <= ${strict.collapses}`);
  assert.deepEqual(mesh.validate(), []);
  const again = octahedron();
  again.subdivide('loop', 2);
  assert.equal(again.decimate({ maxError: 1e-12 }).stop, 'error_bound');
  assert.deepEqual(again.validate(), []);
  for (const m of [mesh, held, again]) m.dispose();
});

test('clone is independent of its original', () => {
  const mesh = grid(2);
  const copy = mesh.clone();
  mesh.splitFace(0);
  assert.equal(copy.counts().faces, 8);
  assert.equal(mesh.counts().faces, 10);
  mesh.dispose();
  assert.deepEqual(copy.validate(), []);
  copy.dispose();
});
