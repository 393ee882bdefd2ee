// BVH picking in WebAssembly under node: 500 rays per frame against a mesh of about 80,000
// triangles (../shared/meshes/armadillo.obj when present, else data/icosahedron_binary.stl after
// six Loop steps: 81,920 triangles), as a page picks under the mouse. Reports the median time of a
// frame of 500 rays through Mesh.pick() (one call per ray, with the nearest edge and vertex) and
// through Mesh.pickMany() (one call per frame), and the tree's build time.
//
//   bindings/wasm/build && node bench/wasm_picking.mjs [--mesh FILE] [--subdivide N] [--frames N]
//
// The rays are drawn as bench/locate draws them: from a point on a sphere of the bounding box's
// diagonal around its centre, toward a uniform point of the box. The native counterpart is
// bench/locate's ray/bvh_sah (per ray; times 500 for a frame).
import { readFileSync, existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { performance } from 'node:perf_hooks';

const root = new URL('../', import.meta.url);
const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(name);
  return i >= 0 && i + 1 < args.length ? args[i + 1] : fallback;
};
const dist = process.env.HEDGE_WASM_DIST
  ? new URL(`file://${process.env.HEDGE_WASM_DIST.replace(/\/?$/, '/')}`)
  : new URL('build/wasm/dist/', root);
const { loadHedge } = await import(new URL('hedge.js', dist).href);
const hedge = await loadHedge();

const shared = fileURLToPath(new URL('../shared/meshes/armadillo.obj', root));
let path = option('--mesh', existsSync(shared) ? shared : null);
let steps = Number(option('--subdivide', path ? 0 : 6));
if (!path) path = fileURLToPath(new URL('data/icosahedron_binary.stl', root));
const frames = Number(option('--frames', 101));
const warmup = 5; // frames run first, untimed, so that the JIT has compiled the loop
const raysPerFrame = 500;

const mesh = hedge.fromFile(readFileSync(path), path);
if (steps > 0) mesh.subdivide('loop', steps);
const faces = mesh.counts().faces;

// A seeded generator (xorshift32) and Gaussian samples (Box-Muller) for the rays.
let state = 2024;
const unit = () => {
  state ^= state << 13;
  state ^= state >>> 17;
  state ^= state << 5;
  return (state >>> 0) / 4294967296;
};
const gauss = () => Math.sqrt(-2 * Math.log(1 - unit())) * Math.cos(2 * Math.PI * unit());

const p = mesh.positions;
const lo = [Infinity, Infinity, Infinity];
const hi = [-Infinity, -Infinity, -Infinity];
for (let i = 0; i < p.length; i += 3)
  for (let a = 0; a < 3; ++a)
    ((lo[a] = Math.min(lo[a], p[i + a])), (hi[a] = Math.max(hi[a], p[i + a])));
const size = [0, 1, 2].map((a) => hi[a] - lo[a]);
const diag = Math.hypot(...size);
const centre = [0, 1, 2].map((a) => (lo[a] + hi[a]) / 2);
const rays = new Float32Array(6 * raysPerFrame * frames);
for (let r = 0; r < raysPerFrame * frames; ++r) {
  const g = [gauss(), gauss(), gauss()];
  const gl = Math.hypot(...g);
  const eye = [0, 1, 2].map((a) => centre[a] + (g[a] / gl) * diag);
  const target = [0, 1, 2].map((a) => lo[a] + unit() * size[a]);
  const d = [0, 1, 2].map((a) => target[a] - eye[a]);
  const dl = Math.hypot(...d);
  rays.set([...eye, ...d.map((x) => x / dl)], 6 * r);
}

// The first pick builds the tree.
let t0 = performance.now();
mesh.pick(centre, [0, 0, 1]);
const buildMs = performance.now() - t0;

const median = (xs) => [...xs].sort((a, b) => a - b)[xs.length >> 1];
const pickFrame = [];
const manyFrame = [];
let hits = 0;
const out = new Int32Array(raysPerFrame);
for (let f = -warmup; f < frames; ++f) {
  const frame = rays.subarray(
    6 * raysPerFrame * Math.max(f, 0),
    6 * raysPerFrame * (Math.max(f, 0) + 1),
  );
  t0 = performance.now();
  for (let r = 0; r < raysPerFrame; ++r) {
    const o = 6 * r;
    if (
      mesh.pick([frame[o], frame[o + 1], frame[o + 2]], [frame[o + 3], frame[o + 4], frame[o + 5]])
    )
      ++hits;
  }
  const pickMs = performance.now() - t0;
  t0 = performance.now();
  mesh.pickMany(frame, out);
  const manyMs = performance.now() - t0;
  if (f >= 0) (pickFrame.push(pickMs), manyFrame.push(manyMs));
  else hits = 0;
}

// The tree again, on a copy, now that the module's code is warm (V8 first runs wasm through its
// baseline compiler, and the first build also grows wasm memory).
const copy = mesh.clone();
t0 = performance.now();
copy.pick(centre, [0, 0, 1]);
const warmBuildMs = performance.now() - t0;
copy.dispose();

const name = path.split('/').pop() + (steps > 0 ? ` subdivided x${steps}` : '');
console.log(
  `mesh: ${name}, ${faces} triangles; ${frames} frames of ${raysPerFrame} rays, ` +
    `${((100 * hits) / (frames * raysPerFrame)).toFixed(0)}% hit`,
);
console.log(
  `BVH build (first pick): ${buildMs.toFixed(1)} ms cold, ${warmBuildMs.toFixed(1)} ms warm`,
);
const report = (label, xs) =>
  console.log(
    `${label} median ${median(xs).toFixed(2)} ms per ${raysPerFrame} rays ` +
      `(${((1000 * median(xs)) / raysPerFrame).toFixed(2)} us per ray; best frame ${Math.min(...xs).toFixed(2)} ms)`,
  );
report('pick():    ', pickFrame);
report('pickMany():', manyFrame);
console.log(
  `bar: 16.7 ms per frame (60 fps) -> ${median(pickFrame) < 16.7 ? 'met' : 'NOT met'} with pick()`,
);
mesh.dispose();
