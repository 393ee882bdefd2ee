// Solid fracture in WebAssembly under node, beside the native library: strikes on a closed mesh at
// the points where random rays meet it (data/spot_triangulated.obj, or data/icosahedron_binary.stl
// after six Loop steps: 81,920 triangles, with --mesh ico6), each on a fresh copy whose picking tree
// is built before the strike, as a page keeps it. Reports the median of fractureSolid() (the call)
// and of the library's part of it (seconds.fracture), after 5 strikes not counted (the engine
// optimises the wasm code meanwhile), and writes the strikes (point, seed) to --out, which
// bench/python/fracture_solid_native.py replays natively for the ratio (the bar: within 3x).
//
//   bindings/wasm/build && node bench/wasm_fracture_solid.mjs [--mesh spot|ico6] [--material stone]
//     [--radius R] [--strikes 40] [--out build/output/solid_strikes.json]
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname } from 'node:path';
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

const meshName = option('--mesh', 'spot');
const material = option('--material', 'stone');
const radius = Number(option('--radius', 0));
const count = Number(option('--strikes', 40));
const out = option('--out', fileURLToPath(new URL('build/output/solid_strikes.json', root)));
const file = meshName === 'ico6' ? 'icosahedron_binary.stl' : 'spot_triangulated.obj';
const base = hedge.fromFile(new Uint8Array(readFileSync(new URL(`data/${file}`, root))), file);
if (meshName === 'ico6') base.subdivide('loop', 6);

// Rays from a sphere about the origin (both meshes lie about it) toward the origin.
let state = 12345;
const random = () => {
  state = (state * 1103515245 + 12345) % 2147483648;
  return state / 2147483648;
};
const box = base.toArrays().positions.reduce((m, x) => Math.max(m, Math.abs(x)), 0);
const strikes = [];
const call = [];
const library = [];
const pieces = [];
for (let attempt = 0; strikes.length < count + 5 && attempt < 100 * count; ++attempt) {
  const z = 2 * random() - 1;
  const a = 2 * Math.PI * random();
  const r = Math.sqrt(1 - z * z);
  const origin = [3 * box * r * Math.cos(a), 3 * box * z, 3 * box * r * Math.sin(a)];
  const copy = base.clone();
  const hit = copy.pick(
    origin,
    origin.map((x) => -x),
  ); // builds the picking tree
  if (!hit) {
    copy.dispose();
    continue;
  }
  let result;
  const t0 = performance.now();
  try {
    result = copy.fractureSolid(hit.point, { material, seed: attempt, radius });
  } catch (error) {
    copy.dispose();
    if (error.kind !== 'invalid-argument') throw error;
    continue; // a refused strike is skipped, natively as well
  }
  const t = performance.now() - t0;
  result.pieces.forEach((p) => p.dispose());
  copy.dispose();
  strikes.push({ point: hit.point, seed: attempt });
  if (strikes.length <= 5) continue;
  call.push(t);
  library.push(1000 * result.seconds.fracture);
  pieces.push(result.pieces.length);
}
const median = (v) => [...v].sort((x, y) => x - y)[v.length >> 1];
mkdirSync(dirname(out), { recursive: true });
writeFileSync(out, JSON.stringify({ mesh: meshName, material, radius, strikes: strikes.slice(5) }));
console.log(
  `${meshName}, ${material}, radius ${radius || 'default'}: ${call.length} strikes, ` +
    `${(pieces.reduce((x, y) => x + y, 0) / pieces.length).toFixed(1)} pieces; median ` +
    `fractureSolid() ${median(call).toFixed(1)} ms, in the library ${median(library).toFixed(1)} ms ` +
    `(strikes in ${out})`,
);
