// The three.js adapter (three.js): BufferGeometry to hedge and back with groups, uvs, normals and
// colours; syncBufferGeometry marking exactly the ranges a sync rewrote; hedgeRaycast giving the
// hits three.js's own raycast gives.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { HedgeError, hedge, sample, threeAdapter } from './support.mjs';

const loaded = await threeAdapter();
const skip = loaded ? false : 'three.js is not installed (npm ci in web/)';
const { THREE, adapter } = loaded ?? {};
const { fromBufferGeometry, toBufferGeometry, syncBufferGeometry, hedgeRaycast, isHedgeGeometry } =
  adapter ?? {};

// The drawn triangles of a geometry, each as a canonical string of its material and its corners'
// position, uv, normal and colour (rounded), sorted: what a renderer shows, whatever the vertex
// order and numbering.
function drawnTriangles(geometry) {
  const index = geometry.index;
  const at = (name, i) => {
    const a = geometry.getAttribute(name);
    if (!a) return '';
    const values = [];
    // -0.0000 and 0.0000 are one value: welding the seam of a sphere keeps one of the two.
    for (let k = 0; k < a.itemSize; ++k)
      values.push(
        a
          .getComponent(i, k)
          .toFixed(4)
          .replace(/^-(0\.0+)$/, '$1'),
      );
    return values.join(' ');
  };
  const corner = (i) => ['position', 'uv', 'normal', 'color'].map((n) => at(n, i)).join('|');
  const count = index ? index.count : geometry.getAttribute('position').count;
  const vertex = (e) => (index ? index.getX(e) : e);
  const groups = geometry.groups.length ? geometry.groups : [{ start: 0, count, materialIndex: 0 }];
  const out = [];
  for (const g of groups)
    for (let e = g.start; e < Math.min(g.start + g.count, count); e += 3) {
      const v = [vertex(e), vertex(e + 1), vertex(e + 2)];
      if (v[0] === v[1] && v[1] === v[2]) continue; // a free slot
      const c = v.map(corner);
      const first = c.indexOf([...c].sort()[0]); // rotate to a canonical first corner
      out.push(`${g.materialIndex}: ${[0, 1, 2].map((k) => c[(first + k) % 3]).join(' / ')}`);
    }
  return out.sort();
}

// A box of six materials (one group per side) with uvs, normals and a colour per vertex.
function colouredBox(colourWidth = 3) {
  const geometry = new THREE.BoxGeometry(1, 2, 3, 2, 1, 1);
  const n = geometry.getAttribute('position').count;
  const colours = new Float32Array(n * colourWidth);
  for (let i = 0; i < colours.length; ++i) colours[i] = ((i * 37) % 101) / 100;
  geometry.setAttribute('color', new THREE.BufferAttribute(colours, colourWidth));
  return geometry;
}

test(
  'a BufferGeometry goes to hedge and back with its groups, uvs, normals and colours',
  { skip },
  () => {
    for (const colourWidth of [3, 4]) {
      const box = colouredBox(colourWidth);
      const mesh = fromBufferGeometry(hedge, box);
      assert.deepEqual(mesh.validate(), []);
      // The 12 vertices of the box's sides are welded into one closed surface.
      assert.equal(mesh.counts().faces, box.index.count / 3);
      assert.equal(mesh.counts().vertices, 12);
      const back = toBufferGeometry(mesh);
      assert.equal(back.groups.length, 6);
      assert.equal(back.getAttribute('color').itemSize, 4);
      const expected = drawnTriangles(box).map((t) =>
        colourWidth === 3 ? t.replace(/(\|[^|/]+ [^|/]+ [^|/ ]+)( \/|$)/g, '$1 1.0000$2') : t,
      );
      assert.deepEqual(drawnTriangles(back), expected);
      assert.deepEqual(mesh.validate(), []);
      mesh.dispose();
    }
  },
);

test('a non-indexed geometry is welded, and the groups it has survive edits', { skip }, () => {
  const sphere = new THREE.SphereGeometry(1, 12, 8).toNonIndexed();
  const triangles = sphere.getAttribute('position').count / 3;
  sphere.addGroup(0, (triangles / 2) * 3, 0);
  sphere.addGroup((triangles / 2) * 3, (triangles / 2) * 3, 3);
  const mesh = fromBufferGeometry(hedge, sphere, { weld: 'epsilon' });
  assert.deepEqual(mesh.validate(), []);
  assert.ok(mesh.counts().vertices < triangles, 'the corners were welded');
  assert.deepEqual(
    drawnTriangles(toBufferGeometry(mesh, { normals: 'attribute' })),
    drawnTriangles(sphere),
  );
  mesh.subdivide('loop', 1);
  const after = toBufferGeometry(mesh);
  assert.deepEqual(
    after.groups.map((g) => g.materialIndex),
    [0, 3],
  );
  assert.equal(drawnTriangles(after).length, (4 * mesh.counts().faces) / 4);
  assert.equal(drawnTriangles(after).filter((t) => t.startsWith('3:')).length, 2 * triangles);
  assert.deepEqual(mesh.validate(), []);
  mesh.dispose();
});

test('a bad geometry throws a HedgeError saying what is wrong, and makes no mesh', { skip }, () => {
  const before = hedge.heapBytesInUse();
  const bad = (make, pattern, kind = 'invalid-argument') =>
    assert.throws(
      make,
      (e) => e instanceof HedgeError && e.kind === kind && pattern.test(e.message),
      String(pattern),
    );
  bad(
    () => fromBufferGeometry(hedge, null),
    /^fromBufferGeometry: geometry must be a THREE\.BufferGeometry, got null/,
  );
  bad(() => fromBufferGeometry({}, new THREE.BufferGeometry()), /hedge must be the loaded module/);
  bad(() => fromBufferGeometry(hedge, new THREE.BufferGeometry()), /no 'position' attribute/);
  const box = new THREE.BoxGeometry();
  box.groups[2].materialIndex = 70000;
  bad(() => fromBufferGeometry(hedge, box), /group 2: materialIndex 70000 is not in \[0, 65535\]/);
  const odd = new THREE.BoxGeometry();
  odd.groups[1].start += 1;
  bad(
    () => fromBufferGeometry(hedge, odd),
    /group 1 \(start 7, count 6\) does not hold whole triangles/,
  );
  const flat = new THREE.BoxGeometry();
  flat.setAttribute('uv', new THREE.BufferAttribute(new Float32Array(24 * 3), 3));
  bad(() => fromBufferGeometry(hedge, flat), /attribute 'uv' has 3 components, expected 2/);
  const nan = new THREE.BoxGeometry();
  nan.getAttribute('position').setX(5, NaN);
  bad(() => fromBufferGeometry(hedge, nan), /vertex 5 has a non-finite coordinate/);
  const out = new THREE.BoxGeometry();
  out.index.setX(7, 24);
  bad(
    () => fromBufferGeometry(hedge, out),
    /index 7 \(triangle 2\) is 24, but there are 24 vertices/,
  );
  bad(() => toBufferGeometry({}), /^toBufferGeometry: mesh must be a hedge Mesh/);
  bad(
    () => syncBufferGeometry(new THREE.BufferGeometry()),
    /^syncBufferGeometry: geometry must be made by toBufferGeometry/,
  );
  assert.ok(hedge.heapBytesInUse() <= before + 4096, 'nothing was left behind');
});

// Copies of every array of a geometry's attributes and index, to compare after a sync.
function snapshot(geometry) {
  const arrays = new Map();
  for (const name of ['position', 'normal', 'uv', 'color']) {
    const a = geometry.getAttribute(name);
    if (a) arrays.set(name, (a.isInterleavedBufferAttribute ? a.data : a).array.slice());
  }
  arrays.set('index', geometry.index.array.slice());
  return arrays;
}

// Checks that the arrays changed only inside `ranges` ([{start, count}] in array elements) and hold
// the RenderBuffers' data there.
function checkOnlyRanges(before, after, ranges, truth, what) {
  const inside = new Uint8Array(after.length);
  for (const { start, count } of ranges) inside.fill(1, start, start + count);
  for (let i = 0; i < after.length; ++i) {
    if (inside[i]) assert.equal(after[i], truth[i], `${what}[${i}] was not copied`);
    else assert.equal(after[i], before[i], `${what}[${i}] changed outside the dirty ranges`);
  }
}

test('syncBufferGeometry copies and marks exactly the ranges a sync rewrote', { skip }, () => {
  for (const interleaved of [false, true]) {
    const mesh = hedge.fromFile(sample('spot_triangulated.obj'), 'spot_triangulated.obj');
    const render = mesh.createRenderBuffers({ interleaved, normals: 'computed' });
    const geometry = toBufferGeometry(mesh, { renderBuffers: render });
    const before = snapshot(geometry);
    mesh.splitEdge(10);
    mesh.flip(100);
    const expected = render.sync();
    const upload = syncBufferGeometry(geometry, render, expected);
    assert.equal(upload.full, false);
    assert.ok(expected.vertexRanges.length > 0 && expected.indexRanges.length > 0);
    const pairs = (flat, width) => {
      const out = [];
      for (let k = 0; k < flat.length; k += 2)
        out.push({ start: flat[k] * width, count: flat[k + 1] * width });
      return out;
    };
    const layout = render.layout;
    const streams = interleaved
      ? [['position', layout.stride, render.vertices]]
      : [
          ['position', 3, render.vertices],
          ['normal', 3, render.normals],
        ];
    for (const [name, width, truth] of streams) {
      const a = geometry.getAttribute(name);
      const target = a.isInterleavedBufferAttribute ? a.data : a;
      assert.deepEqual(target.updateRanges, pairs(expected.vertexRanges, width), name);
      checkOnlyRanges(before.get(name), target.array, target.updateRanges, truth, name);
    }
    const index = geometry.index;
    assert.deepEqual(index.updateRanges, pairs(expected.indexRanges, 1));
    checkOnlyRanges(before.get('index'), index.array, index.updateRanges, render.indices, 'index');
    assert.equal(geometry.drawRange.count, render.sizes().indexCount);

    // A sync that rebuilds (subdivision renumbers everything) refills the geometry whole.
    mesh.subdivide('loop', 1);
    const full = syncBufferGeometry(geometry, render);
    assert.equal(full.full, true);
    assert.deepEqual(
      Array.from(geometry.index.array.subarray(0, render.sizes().indexCount)),
      Array.from(render.indices),
    );
    assert.deepEqual(
      drawnTriangles(geometry),
      drawnTriangles(toBufferGeometry(mesh, { normals: 'computed', interleaved })),
    );
    assert.deepEqual(mesh.validate(), []);
    render.dispose();
    mesh.dispose();
  }
});

// Rays as bench/locate draws them: from a sphere around the box toward a point of the box; or
// `inside`, from near the box's centre in any direction (they meet back faces first).
function rays(box, n, seed, inside = false) {
  let state = seed;
  const unit = () => {
    state ^= state << 13;
    state ^= state >>> 17;
    state ^= state << 5;
    return (state >>> 0) / 4294967296;
  };
  const centre = box.getCenter(new THREE.Vector3());
  const radius = box.getSize(new THREE.Vector3()).length();
  const out = [];
  for (let i = 0; i < n; ++i) {
    const origin = new THREE.Vector3(unit() - 0.5, unit() - 0.5, unit() - 0.5)
      .normalize()
      .multiplyScalar(radius)
      .add(centre);
    const target = new THREE.Vector3(unit(), unit(), unit())
      .multiply(box.getSize(new THREE.Vector3()))
      .add(box.min);
    if (inside) {
      const size = box.getSize(new THREE.Vector3()).multiplyScalar(0.1);
      origin
        .set(unit() - 0.5, unit() - 0.5, unit() - 0.5)
        .multiply(size)
        .add(centre);
    }
    out.push(new THREE.Ray(origin, target.sub(origin).normalize()));
  }
  return out;
}

// Casts `n` rays at `object` with three.js's raycast and with hedgeRaycast; the nearest hits must
// be the same triangle (or one at the same distance, a tie) at the same distance. Returns the hits.
function compareRaycasts(object, n, seed, inside = false) {
  object.updateMatrixWorld(true);
  const box = new THREE.Box3().setFromObject(object);
  const raycaster = new THREE.Raycaster();
  let hits = 0;
  for (const ray of rays(box, n, seed, inside)) {
    raycaster.ray.copy(ray);
    object.raycast = THREE.Mesh.prototype.raycast;
    const theirs = raycaster.intersectObject(object, false);
    object.raycast = hedgeRaycast;
    const ours = raycaster.intersectObject(object, false);
    assert.ok(ours.length <= 1, 'one hit at most');
    if (theirs.length === 0) {
      assert.equal(ours.length, 0, `a hit where three.js has none: ${JSON.stringify(ray)}`);
      continue;
    }
    assert.equal(ours.length, 1, `no hit where three.js has one: ${JSON.stringify(ray)}`);
    const [a, b] = [theirs[0], ours[0]];
    assert.ok(Math.abs(a.distance - b.distance) < 1e-5, `distance ${b.distance} != ${a.distance}`);
    const same = theirs.find((t) => t.faceIndex === b.faceIndex);
    assert.ok(
      a.faceIndex === b.faceIndex || (same && Math.abs(same.distance - a.distance) < 1e-9),
      `triangle ${b.faceIndex} != ${a.faceIndex}`,
    );
    if (a.faceIndex === b.faceIndex) {
      assert.ok(a.point.distanceTo(b.point) < 1e-5);
      assert.deepEqual([b.face.a, b.face.b, b.face.c], [a.face.a, a.face.b, a.face.c]);
      assert.ok(a.face.normal.distanceTo(b.face.normal) < 1e-6);
      assert.equal(b.face.materialIndex, a.face.materialIndex);
      if (a.uv) assert.ok(a.uv.distanceTo(b.uv) < 1e-5);
      if (a.normal) assert.ok(a.normal.distanceTo(b.normal) < 1e-5);
    }
    hits += 1;
  }
  return hits;
}

test('hedgeRaycast hits what three.js hits, on every side, moved and after edits', { skip }, () => {
  for (const file of ['spot_triangulated.obj', 'fandisk_quads.off']) {
    const mesh = hedge.fromFile(sample(file), file);
    const render = mesh.createRenderBuffers();
    const geometry = toBufferGeometry(mesh, { renderBuffers: render });
    const object = new THREE.Mesh(geometry, new THREE.MeshBasicMaterial());
    object.position.set(0.3, -2, 5);
    object.rotation.set(0.4, 1.1, -0.2);
    object.scale.set(2, 0.5, 1.5);
    let hits = 0;
    for (const side of [THREE.FrontSide, THREE.BackSide, THREE.DoubleSide]) {
      object.material.side = side;
      hits += compareRaycasts(object, 300, 7 + side);
      // From inside, the faces met first are culled by a front-side material.
      compareRaycasts(object, 100, 17 + side, true);
    }
    assert.ok(hits > 300, `${file}: only ${hits} of 900 rays hit`);
    // After edits, synced, the hits follow the new surface.
    mesh.smooth({ method: 'taubin', iterations: 3 });
    mesh.splitFace(3);
    syncBufferGeometry(geometry, render);
    object.material.side = THREE.FrontSide;
    const after = compareRaycasts(object, 300, 99);
    assert.ok(after > 50, `${file}: ${after} of 300 rays hit after the edits`);
    // Near and far, and a geometry that is not hedge's, which falls back to three.js's raycast.
    const centre = new THREE.Box3().setFromObject(object).getCenter(new THREE.Vector3());
    const raycaster = new THREE.Raycaster(centre.setZ(50), new THREE.Vector3(0, 0, -1));
    object.raycast = hedgeRaycast;
    const [hit] = raycaster.intersectObject(object, false);
    assert.ok(hit);
    raycaster.far = hit.distance - 1e-3;
    assert.equal(raycaster.intersectObject(object, false).length, 0);
    const plain = new THREE.Mesh(new THREE.BoxGeometry(), new THREE.MeshBasicMaterial());
    plain.raycast = hedgeRaycast;
    assert.equal(isHedgeGeometry(plain.geometry), false);
    assert.equal(isHedgeGeometry(geometry), true);
    plain.updateMatrixWorld(true);
    assert.equal(
      new THREE.Raycaster(new THREE.Vector3(0, 0, 5), new THREE.Vector3(0, 0, -1)).intersectObject(
        plain,
      ).length,
      2,
    );
    assert.deepEqual(mesh.validate(), []);
    render.dispose();
    // Without its RenderBuffers the geometry is three.js's again.
    assert.equal(isHedgeGeometry(geometry), false);
    assert.equal(raycaster.intersectObject(object, false).length, 0);
    raycaster.far = Infinity;
    object.material.side = THREE.DoubleSide;
    assert.ok(raycaster.intersectObject(object, false).length >= 2, "three.js's raycast, all hits");
    mesh.dispose();
  }
});

test('an array of materials: the hit carries the group its triangle is drawn in', { skip }, () => {
  const box = colouredBox();
  const mesh = fromBufferGeometry(hedge, box);
  const render = mesh.createRenderBuffers();
  const materials = [0, 1, 2, 3, 4, 5].map(() => new THREE.MeshBasicMaterial());
  const object = new THREE.Mesh(toBufferGeometry(mesh, { renderBuffers: render }), materials);
  assert.ok(compareRaycasts(object, 200, 5) > 100);
  assert.deepEqual(mesh.validate(), []);
  render.dispose();
  mesh.dispose();
});
