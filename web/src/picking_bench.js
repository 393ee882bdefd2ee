// The picking measurement: 500 rays per animation frame, cast through hedge's BVH in wasm, against
// the current mesh or a large one made by Loop subdivision of the spot sample (5,856 triangles:
// 2 steps give 93,696, 4 steps 1,499,136). Reports the time of
// the 500 rays per frame (median and 95th percentile over the frames) and the frame rate reached.
import { PageMesh } from './page_mesh.js';

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

//! Measures picking against `current` (loopSteps 0) or the spot sample after `loopSteps` Loop
//! subdivisions (a separate mesh, freed afterwards). The rays go in one pickMany call per frame.
//! Returns { triangles, rays, frames, medianMs, p95Ms, fps, hits, buildMs, text }.
export async function measurePicking(hedge, current, loopSteps) {
  let mesh = current;
  let owned = null;
  let subdivideMs = 0;
  if (loopSteps > 0) {
    const response = await fetch('/data/spot_triangulated.obj');
    if (!response.ok) throw new Error(`could not fetch the spot sample (HTTP ${response.status})`);
    owned = PageMesh.load(
      hedge,
      new Uint8Array(await response.arrayBuffer()),
      'spot_triangulated.obj',
      { render: false },
    );
    mesh = owned;
    const t0 = performance.now();
    for (let i = 0; i < loopSteps; ++i) mesh.subdivide('loop');
    subdivideMs = performance.now() - t0;
  }
  if (!mesh) throw new Error('no mesh loaded');
  try {
    const triangles = mesh.triangleCount();
    const t0 = performance.now();
    mesh.buildPicking();
    const buildMs = performance.now() - t0;
    const rays = makeRays(mesh.boundingBox(), RAYS_PER_FRAME, 12345);
    const times = [];
    let hits = 0;
    await nextFrame();
    const start = performance.now();
    for (let frame = 0; frame < FRAMES; ++frame) {
      const f0 = performance.now();
      hits = mesh.castRays(rays.origins, rays.directions);
      times.push(performance.now() - f0);
      await nextFrame();
    }
    const fps = FRAMES / ((performance.now() - start) / 1000);
    times.sort((a, b) => a - b);
    const medianMs = percentile(times, 0.5);
    const p95Ms = percentile(times, 0.95);
    const text =
      `${RAYS_PER_FRAME} rays/frame on ${triangles.toLocaleString('en-US')} triangles: ` +
      `${medianMs.toFixed(2)} ms median, ${p95Ms.toFixed(2)} ms p95 (${hits} hits), ${fps.toFixed(0)} fps` +
      ` over ${FRAMES} frames; BVH built in ${buildMs.toFixed(0)} ms` +
      (owned ? `, mesh subdivided in ${subdivideMs.toFixed(0)} ms` : '');
    return {
      triangles,
      rays: RAYS_PER_FRAME,
      frames: FRAMES,
      medianMs,
      p95Ms,
      fps,
      hits,
      buildMs,
      text,
    };
  } finally {
    if (owned) owned.dispose();
  }
}
