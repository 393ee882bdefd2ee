// Raycasting a three.js mesh under node, rays per millisecond: hedge's adapter (hedgeRaycast,
// three.js's raycast through hedge's picking tree), three-mesh-bvh's acceleratedRaycast (with
// firstHitOnly, as hedgeRaycast reports the nearest hit only) and three.js's own raycast (every
// triangle tested), all through THREE.Raycaster.intersectObject on the same triangles, with the
// building of each tree timed too. Meshes: data/ samples, and ../shared/meshes/armadillo.obj when
// present.
//
//   bindings/wasm/build && (cd web && npm ci) && node bench/wasm_three_raycast.mjs [--runs N] [--rays N]
//
// The rays are drawn as bench/locate draws them: from a point on a sphere of the bounding box's
// diagonal around its centre, toward a uniform point of the box (about half of them hit). Each run
// casts the same rays with each raycast in turn; the table gives the median of the runs (after one
// untimed run that lets the JIT compile). three.js's own raycast casts the first tenth of the rays
// (it tests every triangle).
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { performance } from 'node:perf_hooks';
import { readFileSync } from 'node:fs';

const root = new URL('../', import.meta.url);
const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(name);
  return i >= 0 && i + 1 < args.length ? Number(args[i + 1]) : fallback;
};
const runs = option('--runs', 7);
const rayCount = option('--rays', 2000);

// The module, the adapter and three.js (support.mjs links web/node_modules beside the build, where
// the adapter finds 'three'); three-mesh-bvh from web/node_modules, over the same three.js.
const { hedge, threeAdapter } = await import(new URL('bindings/wasm/test/support.mjs', root).href);
const loaded = await threeAdapter();
const bvhPath = new URL('web/node_modules/three-mesh-bvh/src/index.js', root);
if (!loaded || !existsSync(bvhPath)) {
  console.error('three and three-mesh-bvh are needed: (cd web && npm ci)');
  process.exit(1);
}
const { THREE, adapter } = loaded;
const { computeBoundsTree, acceleratedRaycast } = await import(bvhPath.href);

const meshes = [
  fileURLToPath(new URL('data/spot_triangulated.obj', root)),
  fileURLToPath(new URL('data/bob_small.ply', root)),
  fileURLToPath(new URL('data/elephant-with-holes.off', root)),
];
const shared = fileURLToPath(new URL('../shared/meshes/armadillo.obj', root));
if (existsSync(shared)) meshes.push(shared);

// A seeded generator (xorshift32) and the rays of bench/locate.
function makeRays(box, n) {
  let state = 2024;
  const unit = () => {
    state ^= state << 13;
    state ^= state >>> 17;
    state ^= state << 5;
    return (state >>> 0) / 4294967296;
  };
  const gauss = () => Math.sqrt(-2 * Math.log(1 - unit())) * Math.cos(2 * Math.PI * unit());
  const centre = box.getCenter(new THREE.Vector3());
  const size = box.getSize(new THREE.Vector3());
  const out = [];
  for (let i = 0; i < n; ++i) {
    const origin = new THREE.Vector3(gauss(), gauss(), gauss())
      .normalize()
      .multiplyScalar(size.length())
      .add(centre);
    const target = new THREE.Vector3(unit(), unit(), unit()).multiply(size).add(box.min);
    out.push(new THREE.Ray(origin, target.sub(origin).normalize()));
  }
  return out;
}

const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

// Casts `rays` at each case's object (through its raycast) once per run, the cases taking turns
// so that a change of the machine's load hits them alike; returns per case the rays per
// millisecond of the median run and the share of rays that hit.
function measure(cases) {
  const once = ({ object, rays, firstHitOnly }) => {
    const raycaster = new THREE.Raycaster();
    raycaster.firstHitOnly = firstHitOnly;
    const hits = [];
    let hit = 0;
    const t0 = performance.now();
    for (const ray of rays) {
      raycaster.ray.copy(ray);
      hits.length = 0;
      raycaster.intersectObject(object, false, hits);
      if (hits.length) hit += 1;
    }
    return { ms: performance.now() - t0, hit };
  };
  for (const c of cases) once(c);
  const times = cases.map(() => []);
  const hits = cases.map(() => 0);
  for (let r = 0; r < runs; ++r)
    cases.forEach((c, i) => {
      const run = once(c);
      times[i].push(run.ms);
      hits[i] = run.hit;
    });
  return cases.map((c, i) => ({
    raysPerMs: c.rays.length / median(times[i]),
    hits: hits[i] / c.rays.length,
  }));
}

const rows = [];
for (const path of meshes) {
  const name = path.split('/').pop();
  const mesh = hedge.fromFile(readFileSync(path), name);
  const render = mesh.createRenderBuffers();
  const material = new THREE.MeshBasicMaterial({ side: THREE.DoubleSide });
  // hedge raycasts its live geometry; three.js and three-mesh-bvh a packed copy of it (no spare
  // slots), the same triangles.
  const ours = new THREE.Mesh(adapter.toBufferGeometry(mesh, { renderBuffers: render }), material);
  ours.raycast = adapter.hedgeRaycast;
  const copy = adapter.toBufferGeometry(mesh);
  const plain = new THREE.Mesh(copy, material);
  const accelerated = new THREE.Mesh(copy.clone(), material);
  accelerated.raycast = acceleratedRaycast;
  for (const o of [ours, plain, accelerated]) o.updateMatrixWorld(true);
  const triangles = mesh.counts().faces;

  let t0 = performance.now();
  mesh.pick([0, 0, 0], [0, 0, 1]); // builds hedge's tree
  const hedgeBuild = performance.now() - t0;
  t0 = performance.now();
  accelerated.geometry.boundsTree = computeBoundsTree.call(accelerated.geometry);
  const bvhBuild = performance.now() - t0;

  const rays = makeRays(copy.boundingBox, rayCount);
  const [h, b, p] = measure([
    { object: ours, rays, firstHitOnly: false },
    { object: accelerated, rays, firstHitOnly: true },
    { object: plain, rays: rays.slice(0, Math.max(10, rays.length / 10)), firstHitOnly: false },
  ]);
  rows.push({ name, triangles, h, b, p, hedgeBuild, bvhBuild });
  render.dispose();
  mesh.dispose();
}

const fmt = (x) => (x >= 100 ? x.toFixed(0) : x >= 10 ? x.toFixed(1) : x.toFixed(2));
console.log(
  `node ${process.version}, ${runs} runs of ${rayCount} rays (three.js's own: a tenth), median\n`,
);
console.log(
  '| mesh | triangles | hedgeRaycast | three-mesh-bvh (firstHitOnly) | three.js | hedge / three-mesh-bvh | tree build: hedge / three-mesh-bvh |',
);
console.log('| --- | --- | --- | --- | --- | --- | --- |');
for (const r of rows)
  console.log(
    `| ${r.name} | ${r.triangles.toLocaleString('en')} | ${fmt(r.h.raysPerMs)} | ${fmt(r.b.raysPerMs)} | ${fmt(r.p.raysPerMs)} | ${(r.h.raysPerMs / r.b.raysPerMs).toFixed(2)}x | ${r.hedgeBuild.toFixed(1)} ms / ${r.bvhBuild.toFixed(1)} ms |`,
  );
console.log('\nrays per millisecond; hit rates (hedge, three-mesh-bvh, three.js):');
for (const r of rows)
  console.log(
    `  ${r.name}: ${[r.h, r.b, r.p].map((x) => `${(x.hits * 100).toFixed(1)}%`).join(', ')}`,
  );
