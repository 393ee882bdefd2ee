// The picking measurement: 500 rays per animation frame, cast through hedge's BVH in wasm, against
// the current mesh or a large one made by Loop subdivision of the spot sample (5,856 triangles:
// 2 steps give 93,696, 4 steps 1,499,136). Reports the time of
// the 500 rays per frame (median and 95th percentile over the frames) and the frame rate reached.
// The large mesh is made, given its picking tree and cast at in a worker (hedge/worker), so the
// page keeps drawing and answering while it is subdivided and its tree is built (seconds for 1.5M
// triangles); its ray times are then round trips to the worker.
import { worker } from './heavy.js';

const RAYS_PER_FRAME = 500;
const FRAMES = 60;

// A small seeded generator (xorshift32), so every run casts the same rays.
function random(seed) {
  let x = seed >>> 0 || 1;
  return () => {
    x ^= x << 13;
    x >>>= 0;
    x ^= x >>> 17;
    x ^= x << 5;
    x >>>= 0;
    return x / 4294967296;
  };
}

// Rays from a sphere around the box towards random points inside it (most of them hit).
function makeRays(box, count, seed) {
  const next = random(seed);
  const centre = [0, 1, 2].map((i) => (box.min[i] + box.max[i]) / 2);
  const radius = Math.hypot(...[0, 1, 2].map((i) => box.max[i] - box.min[i])) || 1;
  const origins = new Float32Array(count * 3);
  const directions = new Float32Array(count * 3);
  for (let r = 0; r < count; ++r) {
    const z = next() * 2 - 1;
    const phi = next() * 2 * Math.PI;
    const s = Math.sqrt(1 - z * z);
    const o = [
      centre[0] + radius * s * Math.cos(phi),
      centre[1] + radius * s * Math.sin(phi),
      centre[2] + radius * z,
    ];
    const t = [0, 1, 2].map((i) => box.min[i] + next() * (box.max[i] - box.min[i]));
    const d = [t[0] - o[0], t[1] - o[1], t[2] - o[2]];
    const len = Math.hypot(d[0], d[1], d[2]) || 1;
    for (let i = 0; i < 3; ++i) {
      origins[r * 3 + i] = o[i];
      directions[r * 3 + i] = d[i] / len;
    }
  }
  return { origins, directions };
}

const nextFrame = () => new Promise((resolve) => requestAnimationFrame(resolve));

function percentile(sorted, p) {
  return sorted[Math.min(sorted.length - 1, Math.floor(p * sorted.length))];
}

function boxOf(positions) {
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i += 3)
    for (let k = 0; k < 3; ++k) {
      min[k] = Math.min(min[k], positions[i + k]);
      max[k] = Math.max(max[k], positions[i + k]);
    }
  return { min, max };
}

// Casts the rays once per animation frame: {times (ms per frame), hits, fps}.
async function castFrames(cast) {
  const times = [];
  let hits = 0;
  await nextFrame();
  const start = performance.now();
  for (let frame = 0; frame < FRAMES; ++frame) {
    const f0 = performance.now();
    hits = await cast();
    times.push(performance.now() - f0);
    await nextFrame();
  }
  return { times, hits, fps: FRAMES / ((performance.now() - start) / 1000) };
}

// The spot sample after loopSteps Loop steps, in the worker: its picking tree built there and the
// rays cast there. {triangles, buildMs, subdivideMs, frames}.
async function measureInWorker(loopSteps) {
  const response = await fetch('/data/spot_triangulated.obj');
  if (!response.ok) throw new Error(`could not fetch the spot sample (HTTP ${response.status})`);
  const bytes = new Uint8Array(await response.arrayBuffer());
  const hedge = await worker();
  const { id } = await hedge.load(bytes, 'spot_triangulated.obj', { transfer: true });
  try {
    const t0 = performance.now();
    const counts = await hedge.subdivide(id, 'loop', loopSteps);
    const subdivideMs = performance.now() - t0;
    const { seconds } = await hedge.buildPickingTree(id);
    const { positions } = await hedge.toArrays(id);
    const { origins, directions } = makeRays(boxOf(positions), RAYS_PER_FRAME, 12345);
    const rays = new Float32Array(RAYS_PER_FRAME * 6);
    for (let i = 0; i < RAYS_PER_FRAME; ++i) {
      rays.set(origins.subarray(i * 3, i * 3 + 3), i * 6);
      rays.set(directions.subarray(i * 3, i * 3 + 3), i * 6 + 3);
    }
    const frames = await castFrames(async () => {
      const faces = await hedge.pickMany(id, rays);
      return faces.reduce((n, f) => n + (f >= 0 ? 1 : 0), 0);
    });
    return { triangles: counts.faces, buildMs: seconds * 1000, subdivideMs, frames };
  } finally {
    await hedge.dispose(id);
  }
}

//! Measures picking against `current` (loopSteps 0, on the page) or the spot sample after
//! `loopSteps` Loop subdivisions (in the worker, freed afterwards). The rays go in one pickMany call
//! per frame. Returns { triangles, rays, frames, medianMs, p95Ms, fps, hits, buildMs, worker, text }.
export async function measurePicking(current, loopSteps) {
  let run;
  if (loopSteps > 0) {
    run = await measureInWorker(loopSteps);
  } else {
    if (!current) throw new Error('no mesh loaded');
    const t0 = performance.now();
    current.buildPicking();
    const buildMs = performance.now() - t0;
    const rays = makeRays(current.boundingBox(), RAYS_PER_FRAME, 12345);
    const frames = await castFrames(async () => current.castRays(rays.origins, rays.directions));
    run = { triangles: current.triangleCount(), buildMs, frames };
  }
  const { times, hits, fps } = run.frames;
  times.sort((a, b) => a - b);
  const medianMs = percentile(times, 0.5);
  const p95Ms = percentile(times, 0.95);
  const triangles = run.triangles;
  const inWorker = loopSteps > 0;
  const text =
    `${RAYS_PER_FRAME} rays/frame on ${triangles.toLocaleString('en-US')} triangles: ` +
    `${medianMs.toFixed(2)} ms median, ${p95Ms.toFixed(2)} ms p95 (${hits} hits), ${fps.toFixed(0)} fps` +
    ` over ${FRAMES} frames; BVH built in ${run.buildMs.toFixed(0)} ms` +
    (inWorker
      ? `, mesh subdivided in ${run.subdivideMs.toFixed(0)} ms, in a worker (ray times: round trips)`
      : '');
  return {
    triangles,
    rays: RAYS_PER_FRAME,
    frames: FRAMES,
    medianMs,
    p95Ms,
    fps,
    hits,
    buildMs: run.buildMs,
    worker: inWorker,
    text,
  };
}
