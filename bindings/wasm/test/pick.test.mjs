// Picking: the face, edge and vertex under a ray, against a brute-force reference.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { hedge, grid, octahedron } from './support.mjs';

test('a ray down onto the grid hits the triangle below it, with the nearest edge and corner', () => {
  const mesh = grid(4);
  // Over square (1, 2), close to its lower edge and to corner (1, 2) lies in the lower triangle.
  const hit = mesh.pick([1.3, 2.1, 5], [0, 0, -1]);
  assert.ok(hit);
  assert.ok(Math.abs(hit.t - 5) < 1e-6);
  assert.deepEqual(
    hit.point.map((x) => Math.round(x * 1e5) / 1e5),
    [1.3, 2.1, 0],
  );
  const corners = mesh.face(hit.face).vertices.map((v) => mesh.position(v));
  // The triangle (1,2) (2,2) (2,3): below the diagonal.
  assert.deepEqual(corners.map((p) => p.slice(0, 2)).sort(), [
    [1, 2],
    [2, 2],
    [2, 3],
  ]);
  const edge = mesh
    .edge(hit.edge)
    .vertices.map((v) => mesh.position(v).slice(0, 2))
    .sort();
  assert.deepEqual(edge, [
    [1, 2],
    [2, 2],
  ]);
  assert.equal(hit.edge, hit.halfedge >> 1);
  assert.equal(mesh.halfedge(hit.halfedge).face, hit.face);
  assert.deepEqual(mesh.position(hit.vertex).slice(0, 2), [1, 2]);
  assert.ok(Math.abs(hit.edgeDistance - 0.1) < 1e-6);
  assert.equal(mesh.pick([10, 10, 5], [0, 0, -1]), null);
  assert.equal(mesh.pick([1, 1, 5], [0, 0, 0]), null);
  mesh.dispose();
});

test('pick agrees with a brute-force scan of every triangle; pickMany with pick', () => {
  const mesh = octahedron();
  mesh.subdivide('loop', 3);
  const { positions, indices } = mesh.toArrays();
  const faceOf = [];
  for (let f = 0; f < mesh.counts().faces; ++f) faceOf.push(f);
  let seed = 7;
  const rnd = () => ((seed = (seed * 16807) % 2147483647) / 2147483647) * 2 - 1;
  const rays = new Float32Array(6 * 200);
  for (let i = 0; i < 200; ++i) {
    // From above, toward a point inside the closed surface: each ray must hit it.
    const o = [rnd() * 3, rnd() * 3, 3 + rnd()];
    const target = [rnd() * 0.15, rnd() * 0.15, rnd() * 0.15];
    const d = [target[0] - o[0], target[1] - o[1], target[2] - o[2]];
    rays.set([...o, ...d], 6 * i);
  }
  const many = mesh.pickMany(rays);
  let hits = 0;
  for (let i = 0; i < 200; ++i) {
    const o = rays.subarray(6 * i, 6 * i + 3);
    const d = rays.subarray(6 * i + 3, 6 * i + 6);
    const hit = mesh.pick(o, d);
    assert.equal(many[i], hit ? hit.face : -1);
    // Brute force: the nearest triangle crossed (Moller-Trumbore in double).
    let best = Infinity;
    for (let t = 0; t < indices.length; t += 3) {
      const [a, b, c] = [0, 1, 2].map((k) =>
        positions.subarray(3 * indices[t + k], 3 * indices[t + k] + 3),
      );
      const e1 = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
      const e2 = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
      const p = [
        d[1] * e2[2] - d[2] * e2[1],
        d[2] * e2[0] - d[0] * e2[2],
        d[0] * e2[1] - d[1] * e2[0],
      ];
      const det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
      if (Math.abs(det) < 1e-12) continue;
      const s = [o[0] - a[0], o[1] - a[1], o[2] - a[2]];
      const u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
      const q = [
        s[1] * e1[2] - s[2] * e1[1],
        s[2] * e1[0] - s[0] * e1[2],
        s[0] * e1[1] - s[1] * e1[0],
      ];
      const v = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
      const t2 = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
      if (u >= 0 && v >= 0 && u + v <= 1 && t2 >= 0) best = Math.min(best, t2);
    }
    if (best === Infinity) {
      assert.equal(hit, null);
    } else {
      hits++;
      assert.ok(hit && Math.abs(hit.t - best) < 1e-5, `ray ${i}: ${hit && hit.t} vs ${best}`);
    }
  }
  assert.equal(hits, 200);
  assert.equal(mesh.pick([0, 0, 3], [1, 0, 0]), null, 'a ray that passes by');
  mesh.dispose();
});

test('picking follows edits: the tree is updated from the change log', () => {
  const mesh = grid(4);
  const before = mesh.pick([1.3, 2.1, 5], [0, 0, -1]);
  const v = mesh.splitFace(before.face);
  const after = mesh.pick([1.3, 2.1, 5], [0, 0, -1]);
  assert.ok(mesh.face(after.face).vertices.includes(v));
  mesh.setPosition(v, [1.6, 2.3, 1]);
  const lifted = mesh.pick([1.6, 2.3, 5], [0, 0, -1]);
  assert.ok(Math.abs(lifted.t - 4) < 1e-6, `t ${lifted.t}`);
  assert.equal(lifted.vertex, v);
  mesh.subdivide('midpoint');
  const sub = mesh.pick([0.1, 0.1, 5], [0, 0, -1]);
  assert.ok(sub.face < mesh.counts().faces);
  assert.deepEqual(mesh.validate(), []);
  mesh.dispose();
});
