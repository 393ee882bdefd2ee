// Mesh.fractureSolid() and Mesh.solidFractureRefusal(): closed pieces whose volumes and the rest add
// up to the object, bonds, determinism, refusals (an open mesh, bad arguments) and 'auto'.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { hedge, HedgeError, grid, sample, threeAdapter } from './support.mjs';

const three = await threeAdapter();

//! Enclosed volume of a closed mesh from its triangulated arrays (double precision).
function volume(mesh) {
  const { positions: p, indices: t } = mesh.toArrays({ triangulate: true });
  let sum = 0;
  for (let i = 0; i < t.length; i += 3) {
    const [a, b, c] = [t[i] * 3, t[i + 1] * 3, t[i + 2] * 3];
    sum +=
      p[a] * (p[b + 1] * p[c + 2] - p[b + 2] * p[c + 1]) -
      p[a + 1] * (p[b] * p[c + 2] - p[b + 2] * p[c]) +
      p[a + 2] * (p[b] * p[c + 1] - p[b + 1] * p[c]);
  }
  return sum / 6;
}

//! A closed triangle mesh: every live half-edge has a face (3 per triangle).
function closed(mesh) {
  const c = mesh.counts();
  return mesh.isTriangleMesh() && c.halfedges === 3 * c.faces;
}

const spot = () => hedge.fromFile(sample('spot_triangulated.obj'), 'spot_triangulated.obj');
// A point on spot's surface: where a ray down the y axis from above the body meets it.
function impactOn(mesh) {
  const hit = mesh.pick([0, 2, 0.1], [0, -1, 0]);
  assert.ok(hit, 'the ray meets spot');
  return hit.point;
}
const disposeAll = (result) => result.pieces.forEach((p) => p.dispose());

test('a stone strike on spot gives closed pieces, and their volumes and the rest add up to spot', () => {
  const mesh = spot();
  const before = volume(mesh);
  assert.ok(before > 0);
  const at = impactOn(mesh);
  assert.equal(mesh.solidFractureRefusal(at), null);
  const result = mesh.fractureSolid(at, { material: 'stone', seed: 3, radiusFraction: 0.2 });
  assert.equal(result.kind, 'solid');
  assert.ok(result.pieces.length >= 2, `${result.pieces.length} pieces`);
  assert.ok(result.radius > 0);
  assert.ok(result.impactFace >= 0);
  const sec = result.seconds;
  for (const stage of [
    'locate',
    'cells',
    'clip',
    'cap',
    'assemble',
    'perPiece',
    'fracture',
    'pack',
  ])
    assert.ok(sec[stage] >= 0, stage);
  let sum = 0;
  for (const piece of result.pieces) {
    assert.deepEqual(piece.mesh.validate(), []);
    assert.ok(closed(piece.mesh), 'the piece is closed');
    assert.equal(piece.faces, piece.mesh.counts().faces);
    const v = volume(piece.mesh);
    assert.ok(piece.volume > 0 && Math.abs(v - piece.volume) <= 1e-4 * piece.volume);
    assert.ok(Math.abs(piece.mass - piece.volume) <= 1e-9 * piece.volume, 'density 1');
    assert.ok(piece.capArea > 0, 'every piece has a cap');
    assert.deepEqual(piece.centroid, piece.centreOfMass);
    assert.equal(piece.inertia.length, 9);
    const hullVertices = piece.hull.positions.length / 3;
    assert.equal(piece.hull.indices.length / 3, 2 * hullVertices - 4, 'a closed hull');
    sum += piece.volume;
  }
  assert.deepEqual(mesh.validate(), []);
  assert.ok(closed(mesh), 'the remaining object is closed');
  const rest = volume(mesh);
  assert.ok(
    Math.abs(sum + rest - before) <= 1e-5 * before,
    `pieces ${sum} + rest ${rest} vs ${before}`,
  );
  disposeAll(result);
  mesh.dispose();
});

test('bonds name touching pieces (or the remaining object) with positive cap area, sorted', () => {
  const mesh = spot();
  const result = mesh.fractureSolid(impactOn(mesh), { seed: 5, radiusFraction: 0.2 });
  const n = result.pieces.length;
  assert.ok(result.bonds.length >= n - 1, `${result.bonds.length} bonds for ${n} pieces`);
  let remaining = 0;
  let previous = [-1, -1];
  for (const { a, b, area } of result.bonds) {
    assert.ok(Number.isInteger(a) && a >= 0 && a < n);
    if (b === null) ++remaining;
    else assert.ok(Number.isInteger(b) && b > a && b < n);
    assert.ok(area > 0);
    const key = [a, b === null ? Infinity : b];
    assert.ok(key[0] > previous[0] || (key[0] === previous[0] && key[1] > previous[1]), 'sorted');
    previous = key;
  }
  assert.ok(remaining >= 1, 'some piece touches the remaining object');
  // A piece's bonds share no more than its cap.
  for (let i = 0; i < n; ++i) {
    const shared = result.bonds.filter((b) => b.a === i).reduce((s, b) => s + b.area, 0);
    assert.ok(shared <= result.pieces[i].capArea * (1 + 1e-6));
  }
  disposeAll(result);
  mesh.dispose();
});

test('the same strike gives the same pieces', () => {
  const run = () => {
    const mesh = spot();
    const result = mesh.fractureSolid(impactOn(mesh), { seed: 11, radiusFraction: 0.15 });
    const out = result.pieces.map((p) => {
      const a = p.mesh.toArrays();
      return [Array.from(a.positions), Array.from(a.indices), p.volume, Array.from(p.inertia)];
    });
    const bonds = result.bonds;
    disposeAll(result);
    mesh.dispose();
    return { out, bonds };
  };
  assert.deepEqual(run(), run());
});

test('caps carry the inner submesh, so render buffers group them apart', () => {
  const mesh = spot();
  const result = mesh.fractureSolid(impactOn(mesh), { seed: 2, innerSubmesh: 4 });
  const render = result.pieces[0].mesh.createRenderBuffers();
  render.sync();
  const ranges = render.submeshes();
  assert.equal(ranges.length, 5, 'submeshes 0 (the outer faces) to 4 (the caps)');
  assert.ok(ranges[0].indexCount > 0 && ranges[4].indexCount > 0);
  render.dispose();
  disposeAll(result);
  mesh.dispose();
});

test(
  'three.js: a piece becomes a BufferGeometry with a group for its caps, drawn by the inner material',
  { skip: three ? false : 'three.js is not installed (npm ci in web/)' },
  () => {
    const { toBufferGeometry } = three.adapter;
    const mesh = spot();
    const result = mesh.fractureSolid(impactOn(mesh), { seed: 4, innerSubmesh: 1 });
    for (const piece of result.pieces) {
      const geometry = toBufferGeometry(piece.mesh);
      const groups = geometry.groups.map((g) => g.materialIndex);
      assert.ok(groups.includes(1), `the caps' group (materialIndex 1) among ${groups}`);
      const caps = geometry.groups.find((g) => g.materialIndex === 1);
      assert.ok(caps.count > 0 && caps.count % 3 === 0);
      geometry.dispose();
    }
    // The remaining object's new caps are drawn by the inner material too.
    const rest = toBufferGeometry(mesh);
    assert.ok(rest.groups.some((g) => g.materialIndex === 1));
    rest.dispose();
    disposeAll(result);
    mesh.dispose();
  },
);

test('an open mesh is refused with a reason, unchanged; kind auto breaks it by surface fracture', () => {
  // Struck near its border, so that the broken region meets the plate's boundary.
  const plate = grid(20);
  const before = plate.toArrays();
  const why = plate.solidFractureRefusal([1.2, 1.7, 0]);
  assert.match(why, /open|boundary/);
  assert.equal(plate.solidFractureRefusalCode([1.2, 1.7, 0]), 'open');
  assert.throws(
    () => plate.fractureSolid([1.2, 1.7, 0]),
    (e) =>
      e instanceof HedgeError && e.kind === 'invalid-argument' && /open|boundary/.test(e.message),
  );
  assert.deepEqual(plate.toArrays(), before, 'a refused strike leaves the mesh as it was');
  const auto = plate.fractureSolid([1.2, 1.7, 0], { kind: 'auto', material: 'glass', seed: 1 });
  assert.equal(auto.kind, 'surface');
  assert.equal(auto.refusal, why);
  assert.ok(auto.shards.length > 0);
  assert.deepEqual(plate.validate(), []);
  // A bad option is an error with 'auto' too, not a reason to break the surface.
  const faces = plate.counts().faces;
  assert.throws(
    () => plate.fractureSolid([1.2, 1.7, 0], { kind: 'auto', radiusFraction: 0 }),
    (e) =>
      e instanceof HedgeError && e.kind === 'invalid-argument' && /radius_fraction/.test(e.message),
  );
  assert.equal(plate.counts().faces, faces);
  // So is any refusal that is not about the mesh's shape: the impact off the surface.
  assert.equal(auto.refusalCode, 'open');
  assert.equal(plate.solidFractureRefusalCode([1.2, 1.7, 3]), 'off_surface');
  assert.throws(
    () => plate.fractureSolid([1.2, 1.7, 3], { kind: 'auto' }),
    (e) =>
      e instanceof HedgeError &&
      e.kind === 'invalid-argument' &&
      /fracture_solid: the impact/.test(e.message),
  );
  assert.equal(plate.counts().faces, faces);
  auto.shards.forEach((s) => s.dispose());
  plate.dispose();
  // A closed mesh with 'auto' breaks solid.
  const mesh = spot();
  assert.equal(mesh.solidFractureRefusalCode(impactOn(mesh)), 'none');
  const solid = mesh.fractureSolid(impactOn(mesh), { kind: 'auto', seed: 1 });
  assert.equal(solid.kind, 'solid');
  disposeAll(solid);
  mesh.dispose();
});

test('bad arguments throw invalid-argument naming the call, the mesh unchanged', () => {
  const mesh = spot();
  const at = impactOn(mesh);
  const before = mesh.toArrays();
  const invalid = (fn, pattern) =>
    assert.throws(fn, (e) => {
      assert.ok(e instanceof HedgeError, String(e));
      assert.equal(e.kind, 'invalid-argument');
      assert.match(e.message, pattern);
      return true;
    });
  invalid(() => mesh.fractureSolid(null), /fractureSolid: impact must be \[x, y, z\]/);
  invalid(() => mesh.fractureSolid([0, 0]), /fractureSolid: impact/);
  invalid(() => mesh.fractureSolid([NaN, 0, 0]), /not finite/);
  invalid(() => mesh.fractureSolid(at, { radius: 'big' }), /options\.radius must be a number/);
  invalid(() => mesh.fractureSolid(at, { hulls: 1 }), /options\.hulls must be a boolean/);
  invalid(() => mesh.fractureSolid(at, { kind: 'liquid' }), /unknown kind 'liquid'/);
  invalid(() => mesh.fractureSolid(at, { material: 'cheese' }), /fractureSolid: unknown material/);
  invalid(
    () => mesh.fractureSolid(at, { material: { rings: 3 } }),
    /fractureSolid: material\.rings/,
  );
  invalid(() => mesh.fractureSolid(at, { seed: 1.5 }), /seed must be a whole number/);
  invalid(() => mesh.fractureSolid(at, { innerSubmesh: -2 }), /innerSubmesh/);
  invalid(() => mesh.fractureSolid(at, { density: -1 }), /density/);
  invalid(() => mesh.fractureSolid(at, { radius: -1 }), /radius/);
  invalid(() => mesh.fractureSolid([50, 50, 50]), /./);
  invalid(() => mesh.solidFractureRefusal(undefined), /solidFractureRefusal: impact/);
  assert.match(mesh.solidFractureRefusal(at, { density: -1 }), /density/);
  assert.equal(mesh.solidFractureRefusalCode(at, { density: -1 }), 'bad_option');
  invalid(() => mesh.solidFractureRefusalCode(undefined), /solidFractureRefusalCode: impact/);
  assert.deepEqual(mesh.toArrays(), before);
  mesh.dispose();
});

test('pieces free their wasm memory', () => {
  const mesh = spot();
  const at = impactOn(mesh);
  const clone = mesh.clone();
  const heap = hedge.heapBytesInUse();
  for (let i = 0; i < 3; ++i) {
    const copy = clone.clone();
    disposeAll(copy.fractureSolid(at, { seed: i }));
    copy.dispose();
  }
  assert.ok(hedge.heapBytesInUse() <= heap + 64 * 1024, 'no leak');
  clone.dispose();
  mesh.dispose();
});
