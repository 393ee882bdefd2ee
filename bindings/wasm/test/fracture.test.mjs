// Mesh.fracture(): shards with their meshes, hulls and mass properties; determinism, conservation
// of area, refusals, the render sync of the remaining mesh, and memory.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { hedge, HedgeError, grid, gridArrays, sample } from './support.mjs';

//! Area of a mesh from its triangulated arrays (double precision).
function area(mesh) {
  const { positions: p, indices: t } = mesh.toArrays({ triangulate: true });
  let sum = 0;
  for (let i = 0; i < t.length; i += 3) {
    const [a, b, c] = [t[i] * 3, t[i + 1] * 3, t[i + 2] * 3];
    const u = [p[b] - p[a], p[b + 1] - p[a + 1], p[b + 2] - p[a + 2]];
    const v = [p[c] - p[a], p[c + 1] - p[a + 1], p[c + 2] - p[a + 2]];
    sum +=
      Math.hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]) /
      2;
  }
  return sum;
}

//! Everything a shard holds, as plain arrays, for comparing two runs.
function snapshot(shard) {
  const a = shard.mesh.toArrays();
  return {
    positions: Array.from(a.positions),
    indices: Array.from(a.indices),
    centroid: shard.centroid,
    area: shard.area,
    volume: shard.volume,
    mass: shard.mass,
    inertia: Array.from(shard.inertia),
    hull: [Array.from(shard.hull.positions), Array.from(shard.hull.indices)],
  };
}

const disposeAll = (result) => result.shards.forEach((s) => s.dispose());

test('a glass strike on a plate gives valid shards whose areas and the rest add up to the plate', () => {
  const mesh = grid(30);
  const before = area(mesh);
  assert.ok(Math.abs(before - 900) < 1e-9);
  const result = mesh.fracture([15.3, 14.6, 0], { material: 'glass', seed: 7 });
  assert.ok(
    result.shards.length >= 20 && result.shards.length <= 40,
    `${result.shards.length} shards`,
  );
  assert.ok(result.impactFace >= 0);
  assert.deepEqual(
    result.impactPoint.map((x) => Math.round(x * 10) / 10),
    [15.3, 14.6, 0],
  );
  const sec = result.seconds;
  const stages = sec.locate + sec.scatter + sec.cut + sec.detach + sec.hulls;
  for (const stage of ['locate', 'scatter', 'cut', 'detach', 'hulls', 'pack'])
    assert.ok(sec[stage] >= 0, stage);
  assert.ok(
    stages > 0 && stages <= sec.fracture * 1.001,
    `stages ${stages} s within the call's ${sec.fracture} s`,
  );
  let shardArea = 0;
  for (const shard of result.shards) {
    assert.deepEqual(shard.mesh.validate(), []);
    assert.equal(shard.faces, shard.mesh.counts().faces);
    const a = area(shard.mesh);
    assert.ok(Math.abs(a - shard.area) <= 1e-5 * a, `shard area ${shard.area} vs its mesh ${a}`);
    shardArea += shard.area;
    // Open shards (no thickness) weigh as a thin shell: a mass and a positive-definite inertia;
    // a hull all the same (a thin slab).
    assert.equal(shard.closed, false);
    assert.ok(shard.shellThickness > 0);
    assert.ok(Math.abs(shard.volume - shard.area * shard.shellThickness) <= 1e-9 * shard.volume);
    assert.ok(shard.mass > 0 && shard.principalMoments[0] > 0);
    const hullVertices = shard.hull.positions.length / 3;
    assert.ok(hullVertices >= 4);
    assert.equal(
      shard.hull.indices.length / 3,
      2 * hullVertices - 4,
      'the hull is a closed triangle mesh',
    );
  }
  const rest = area(mesh);
  assert.ok(
    Math.abs(shardArea + rest - before) <= 1e-5 * before,
    `${shardArea} + ${rest} vs ${before}`,
  );
  assert.deepEqual(mesh.validate(), []);
  disposeAll(result);
  mesh.dispose();
});

test('the same seed gives the same shards; another seed other shards', () => {
  const run = (seed) => {
    const mesh = grid(24);
    const result = mesh.fracture([12.2, 11.7, 0], { material: 'ice', seed, thickness: 0.1 });
    const shards = result.shards.map(snapshot);
    const rest = Array.from(mesh.toArrays().indices);
    disposeAll(result);
    assert.deepEqual(mesh.validate(), []);
    mesh.dispose();
    return { shards, rest };
  };
  const a = run(42);
  const b = run(42);
  assert.ok(a.shards.length > 5);
  assert.deepEqual(a, b);
  const c = run(43);
  assert.notDeepEqual(a.shards, c.shards);
});

test('with a thickness each shard is a closed solid with its mass properties and a hull around it', () => {
  const mesh = grid(20);
  const density = 2.5;
  const thickness = 0.25;
  const result = mesh.fracture([10.4, 9.7, 0], { material: 'stone', seed: 1, thickness, density });
  assert.ok(result.shards.length >= 3);
  for (const shard of result.shards) {
    assert.deepEqual(shard.mesh.validate(), []);
    assert.equal(shard.closed, true);
    // A flat slab of the front's area, the thickness deep.
    assert.ok(
      Math.abs(shard.volume - shard.area * thickness) <= 1e-4 * shard.volume,
      `${shard.volume} vs ${shard.area * thickness}`,
    );
    assert.ok(Math.abs(shard.mass - density * shard.volume) <= 1e-9 * shard.mass);
    assert.ok(
      Math.abs(shard.centreOfMass[2] + thickness / 2) < 1e-5,
      'the centre of mass is mid-depth',
    );
    const [i0, i1, i2] = shard.principalMoments;
    assert.ok(i0 > 0 && i0 <= i1 && i1 <= i2);
    assert.ok(Math.abs(shard.inertia[1] - shard.inertia[3]) < 1e-9, 'the tensor is symmetric');
    // Every vertex of the shard lies in its hull (inside every face plane, within a tolerance).
    const { positions: hp, indices: ht } = shard.hull;
    const p = shard.mesh.positions;
    for (let t = 0; t < ht.length; t += 3) {
      const [a, b, c] = [ht[t] * 3, ht[t + 1] * 3, ht[t + 2] * 3];
      const u = [hp[b] - hp[a], hp[b + 1] - hp[a + 1], hp[b + 2] - hp[a + 2]];
      const v = [hp[c] - hp[a], hp[c + 1] - hp[a + 1], hp[c + 2] - hp[a + 2]];
      const n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
      const len = Math.hypot(...n);
      for (let k = 0; k < p.length; k += 3) {
        const d =
          ((p[k] - hp[a]) * n[0] + (p[k + 1] - hp[a + 1]) * n[1] + (p[k + 2] - hp[a + 2]) * n[2]) /
          len;
        assert.ok(d < 1e-4, `a shard vertex lies ${d} outside its hull`);
      }
    }
  }
  assert.deepEqual(mesh.validate(), []);
  disposeAll(result);
  mesh.dispose();
});

test('a strike on a closed sample breaks it and leaves a valid mesh', () => {
  const mesh = hedge.fromFile(sample('spot_triangulated.obj'), 'spot_triangulated.obj');
  const before = area(mesh);
  const p = mesh.position(100);
  const result = mesh.fracture(p, { material: 'wood', seed: 5 });
  assert.ok(result.shards.length > 1);
  let sum = area(mesh);
  for (const shard of result.shards) {
    assert.deepEqual(shard.mesh.validate(), []);
    sum += shard.area;
  }
  assert.ok(Math.abs(sum - before) <= 1e-5 * before);
  assert.deepEqual(mesh.validate(), []);
  disposeAll(result);
  mesh.dispose();
});

// The library's test FractureMaterial.TheDefaultStrikeOnSpotThatEveryBindingChecks gives these
// numbers: the binding's defaults are the library's.
test("the default strike on spot gives the library's shards", () => {
  const mesh = hedge.fromFile(sample('spot_triangulated.obj'), 'spot_triangulated.obj');
  const result = mesh.fracture([0.380073, -0.0641595, 0.195141]);
  assert.equal(result.shards.length, 40);
  const sum = (f) => result.shards.reduce((total, s) => total + f(s), 0);
  assert.ok(Math.abs(sum((s) => s.area) - 0.498213) < 1e-6, `area ${sum((s) => s.area)}`);
  assert.ok(Math.abs(sum((s) => s.mass) - 0.00838123) < 1e-8, `mass ${sum((s) => s.mass)}`);
  assert.ok(Math.abs(result.breakRadius - 0.336452) < 1e-6, `break radius ${result.breakRadius}`);
  disposeAll(result);
  mesh.dispose();
});

test('the remaining mesh reaches its RenderBuffers as a partial sync', () => {
  const mesh = grid(60);
  const render = mesh.createRenderBuffers();
  render.sync();
  const triangles = render.sizes().triangles;
  const result = mesh.fracture([30.5, 30.25, 0], { seed: 2 });
  const sync = render.sync();
  assert.equal(sync.full, false);
  assert.ok(sync.indexRanges.length > 0);
  assert.ok(sync.indexBytes < (triangles * 12) / 4, `${sync.indexBytes} index bytes rewritten`);
  assert.equal(render.sizes().triangles, mesh.counts().faces);
  assert.deepEqual(mesh.validate(), []);
  disposeAll(result);
  render.dispose();
  mesh.dispose();
});

// A 10 x 10 plate of n x n squares broken at its middle: the share of its area that breaks. A preset
// in edge lengths breaks a quarter of it each time the resolution doubles; a preset as it is (a
// fraction of the diagonal) or a break radius in model units about the same share at every
// resolution.
test('the presets and breakRadius break the same share of an object at every resolution', () => {
  const share = (n, options) => {
    const arrays = gridArrays(n);
    const mesh = hedge.fromBuffers({
      positions: arrays.positions.map((x) => (x * 10) / n),
      indices: arrays.indices,
    });
    const result = mesh.fracture([5.03, 4.98, 0], { seed: 2, ...options });
    const broken = result.shards.reduce((sum, s) => sum + s.area, 0);
    assert.deepEqual(mesh.validate(), []);
    disposeAll(result);
    mesh.dispose();
    return broken / 100;
  };
  const edges = { units: 'edge_lengths', radius: 7 };
  assert.ok(share(80, edges) < share(20, edges) / 8);
  const coarse = share(20, {});
  assert.ok(Math.abs(share(80, {}) - coarse) < 0.1 * coarse, `${share(80, {})} vs ${coarse}`);
  assert.ok(
    Math.abs(share(80, { units: 'model', radius: 2 }) - share(20, { units: 'model', radius: 2 })) <
      0.02,
  );
  for (const n of [10, 20, 80]) {
    const s = share(n, { breakRadius: 2 });
    assert.ok(s > 0.12 && s < 0.24, `share at ${n}: ${s}`);
  }
});

test('bad strikes throw a HedgeError and leave the mesh unchanged', () => {
  const mesh = grid(10);
  const before = Array.from(mesh.toArrays().indices);
  const refused = (impact, options, pattern) => {
    assert.throws(
      () => mesh.fracture(impact, options),
      (e) => e instanceof HedgeError && pattern.test(e.message),
    );
  };
  refused([NaN, 1, 0], {}, /impact.*not finite/);
  refused([1, Infinity, 0], {}, /not finite/);
  refused([5, 5, 3], {}, /from the nearest face/);
  refused([5, 5], {}, /^fracture: impact must be \[x, y, z\]/);
  refused([5, 5, 0], { material: 'glas' }, /unknown material 'glas'/);
  refused([5, 5, 0], { seed: -1 }, /seed/);
  refused([5, 5, 0], { seed: 1.5 }, /seed/);
  refused([5, 5, 0], { density: 0, thickness: 0.1 }, /density/);
  refused([5, 5, 0], { breakRadius: -1 }, /radius must be finite and positive/);
  refused([5, 5, 0], { breakRadius: '2' }, /breakRadius must be a number/);
  refused(
    [5, 5, 0],
    { units: 'metres' },
    /units must be one of diagonal_fraction, model, edge_lengths/,
  );
  refused(
    [5, 5, 0],
    { radius: -1 },
    /radius \(the break radius, in diagonal_fraction\) must be finite/,
  );
  refused([5, 5, 0], { shellThickness: -1 }, /shell_thickness/);
  refused(
    [5, 5, 0],
    { material: { rings: [{ points: 4, spacing: 1 }], absolute: true } },
    /absolute was replaced by units and radius/,
  );
  refused([5, 5, 0], { material: { rings: [{ points: 4, spacing: -1 }] } }, /rings\[0\]\.spacing/);
  refused([5, 5, 0], { material: { rings: [{ points: 2.5, spacing: 1 }] } }, /rings\[0\]\.points/);
  refused([5, 5, 0], { material: { rings: 'many' } }, /rings must be an array/);
  assert.deepEqual(Array.from(mesh.toArrays().indices), before);
  assert.deepEqual(mesh.validate(), []);
  // A custom material works once it is right.
  const result = mesh.fracture([5, 5, 0], {
    material: { name: 'tile', rings: [{ points: 5, spacing: 1.5, jitter: 0.3 }] },
  });
  assert.ok(result.shards.length >= 2 && result.shards.length <= 5);
  assert.deepEqual(mesh.validate(), []);
  disposeAll(result);
  mesh.dispose();
});

test('repeated strikes with their shards disposed leave the heap as it was', () => {
  const strike = () => {
    const mesh = grid(20);
    const result = mesh.fracture([10.3, 9.6, 0], { seed: 9, thickness: 0.1 });
    assert.ok(result.shards.length > 10);
    disposeAll(result);
    mesh.dispose();
  };
  for (let i = 0; i < 5; ++i) strike();
  const inUse = hedge.heapBytesInUse();
  const memory = hedge.memoryBytes;
  for (let i = 0; i < 200; ++i) strike();
  assert.equal(hedge.heapBytesInUse(), inUse, 'every byte came back');
  assert.equal(hedge.memoryBytes, memory, 'wasm memory did not grow');
  // And strikes on one mesh free what each gives out.
  const mesh = grid(130);
  // Small strikes (7 edge lengths) that do not overlap.
  const small = { units: 'edge_lengths', radius: 7 };
  mesh.fracture([125.2, 125.3, 0], small).shards.forEach((s) => s.dispose());
  const base = hedge.heapBytesInUse();
  let bytes = 0;
  for (let i = 0; i < 30; ++i) {
    const before = hedge.heapBytesInUse();
    const result = mesh.fracture([10.3 + (i % 6) * 20, 10.6 + Math.floor(i / 6) * 20, 0], {
      seed: i,
      ...small,
    });
    bytes = Math.max(bytes, hedge.heapBytesInUse() - before);
    disposeAll(result);
  }
  assert.ok(bytes > 0);
  assert.ok(
    hedge.heapBytesInUse() - base < 2_000_000,
    `the mesh's own growth: ${hedge.heapBytesInUse() - base} bytes`,
  );
  assert.deepEqual(mesh.validate(), []);
  mesh.dispose();
});
