// The break scene: a plate, a sample or the loaded mesh above a ground plane; a click strikes the
// mesh and breaks it in wasm, the rest is synced to the GPU by dirty ranges and the broken parts
// fall in the physics world (break_scene.js). The plate breaks by surface fracture into shards; a 3D
// object (spot, the loaded mesh) by solid fracture into closed pieces whose caps are drawn in an
// inner colour, or by surface fracture when it is open (fractureSolid's kind 'auto'). Also times
// strikes, as the benchmark does.
import { PageMesh } from './page_mesh.js';
import { BreakWorld, STEP, median, plateArrays } from './break_scene.js';
import { $, fmt, ms, state, clearError, guard } from './page.js';
import { adopt, applyEdit, meshName } from './scene.js';

// Mass per unit volume (kg/m^3) of each material, for the shards' mass properties.
const DENSITY = { glass: 2500, stone: 2600, wood: 600, ice: 917 };
// The speed (m/s) of the push a shard gets away from the impact.
const PUSH = 0.8;

// The break scene's own state (the mode itself is state.mode).
const scene = {
  world: null, // the BreakWorld (cannon-es)
  thickness: 0, // of the shards
  size: {}, // the break radius ({units, radius}) of the scene's strikes; {}: the preset's
  solid: false, // strikes break by solid fracture (kind 'auto': surface fracture if refused)
  innerSubmesh: 1, // the caps' submesh, drawn in the inner colour
  strikes: [], // {ms, wasmMs, shards} of each strike in the scene
  ticking: false, // the physics loop is running
  lastTick: undefined,
  stepDebt: 0,
  strikeSnapshot: undefined, // the shards as the last strike made them, before any step
};

//! Makes the physics world in the viewer's scene; call once, before any break scene.
export function createBreakWorld(viewer) {
  scene.world = new BreakWorld(viewer.scene);
}

//! Leaves the break scene (if in one): back to edit mode, the shards gone, the viewer as it was.
export function leaveBreak() {
  state.mode = 'edit';
  scene.strikes = [];
  if (scene.world) scene.world.clear();
  if (state.viewer) {
    state.viewer.setSeeThrough(false);
    state.viewer.setInnerSubmesh(null);
    state.viewer.setWireframe($('show-wire').checked);
  }
  delete document.body.dataset.scene;
  delete document.body.dataset.fracture;
  $('stat-fracture').textContent = '-';
  $('stat-shards').textContent = '-';
}

//! Sets up a break scene: 'plate' (a plate of 224 x 224 squares, 100,352 triangles, made here),
//! 'spot' (a sample) or 'current' (a copy of the loaded mesh), above a ground plane.
async function setupBreak(name) {
  let bytes = null;
  if (name === 'spot') {
    const response = await fetch('/data/spot_triangulated.obj');
    if (!response.ok)
      throw new Error(`could not fetch spot_triangulated.obj (HTTP ${response.status})`);
    bytes = new Uint8Array(await response.arrayBuffer());
  }
  if (name === 'current' && !state.current) throw new Error('no mesh loaded');
  const label = {
    plate: 'plate, 224 x 224 squares',
    spot: 'spot_triangulated.obj',
    current: meshName(),
  }[name];
  // The copy is taken before leaving a break scene, so that 'current' in one breaks what is shown.
  const copy = name === 'current' ? state.current.mesh.clone() : null;
  leaveBreak();
  const t0 = performance.now();
  let next;
  if (name === 'plate') next = PageMesh.fromBuffers(state.hedge, plateArrays(224, 3, 1));
  else if (name === 'spot') next = PageMesh.load(state.hedge, bytes, label);
  else {
    try {
      next = new PageMesh(state.hedge, copy);
    } catch (error) {
      copy.dispose();
      throw error;
    }
  }
  next.buildPicking(); // strikes go through the picking tree, as in a game
  const loadMs = performance.now() - t0;
  clearError();
  adopt(next, label, loadMs, {
    operation: `set up the break scene: ${label}`,
    sameFile: name === 'current',
  });
  const box = next.boundingBox();
  const diagonal = Math.hypot(...[0, 1, 2].map((i) => box.max[i] - box.min[i]));
  // The plate lies at height 1 above the ground; the object stands just above it.
  const ground = name === 'plate' ? 0 : box.min[1] - 0.02 * diagonal;
  scene.world.setGround(ground, 3 * diagonal);
  // 1 cm for the 3 m plate (its squares are 1.3 cm wide); the object's in proportion.
  scene.thickness = name === 'plate' ? 0.01 : 0.004 * diagonal;
  // The plate breaks 25 cm around the impact, as a game gives a pane's break radius in metres (the
  // preset's fraction of the diagonal would take 0.55 m, some 12k of its 100k triangles a strike);
  // an object breaks the preset's fraction of its size.
  scene.size = name === 'plate' ? { units: 'model', radius: 0.25 } : {};
  scene.solid = name !== 'plate';
  scene.innerSubmesh = next.submeshCount();
  state.mode = 'break';
  if (scene.solid) state.viewer.setInnerSubmesh(scene.innerSubmesh);
  // The plate as glass, so the shards below show through; no wireframe over its 100k triangles.
  state.viewer.setSeeThrough(name === 'plate');
  state.viewer.setWireframe(name !== 'plate' && $('show-wire').checked);
  state.viewer.frame(
    { min: [box.min[0], ground, box.min[2]], max: box.max },
    name === 'plate' ? [-0.45, 0.9, -0.8] : undefined,
  );
  document.body.dataset.scene = name;
  $('stat-shards').textContent = 'click the mesh to strike it';
}

function showFracture() {
  const strikes = scene.strikes;
  const last = strikes[strikes.length - 1];
  const m = median(strikes.map((x) => x.ms));
  const parts = last.kind === 'solid' ? 'closed pieces' : 'shards';
  $('stat-fracture').textContent =
    `${ms(last.ms)} (in the library ${ms(last.wasmMs)}), median ${ms(m)} over ${strikes.length} strike(s); ${last.shards} ${parts}`;
  // kind: 'solid' or 'surface'; closed: how many of the parts have no boundary.
  document.body.dataset.fracture = JSON.stringify({
    last: last.ms,
    wasm: last.wasmMs,
    median: m,
    strikes: strikes.length,
    shards: last.shards,
    kind: last.kind,
    closed: last.closed,
    bonds: last.bonds,
  });
}

function showShards() {
  const w = scene.world;
  const n = w.shards.length;
  const moving = w.moving;
  $('stat-shards').textContent =
    `${fmt(n)} shards: ${fmt(moving)} moving, ${fmt(n - moving)} at rest (${fmt(w.steps)} steps)`;
  document.body.dataset.shards = String(n);
  document.body.dataset.physicsSteps = String(w.steps);
}

//! Steps the physics at 60 Hz of simulated time (at most 4 steps a frame) while a shard moves.
function tick(now) {
  const w = scene.world;
  if (w.shards.length === 0 || w.moving === 0) {
    scene.ticking = false;
    showShards();
    state.viewer.requestRender();
    return;
  }
  const elapsed = scene.lastTick === undefined ? STEP : (now - scene.lastTick) / 1000;
  scene.lastTick = now;
  scene.stepDebt = Math.min(4 * STEP, (scene.stepDebt || 0) + elapsed);
  const steps = Math.max(1, Math.floor(scene.stepDebt / STEP));
  scene.stepDebt = Math.max(0, scene.stepDebt - steps * STEP);
  w.step(steps);
  state.viewer.render();
  showShards();
  requestAnimationFrame(tick);
}

function startPhysics() {
  if (scene.ticking) return;
  scene.ticking = true;
  scene.lastTick = undefined;
  requestAnimationFrame(tick);
}

function strikeOptions() {
  const material = $('break-material').value;
  const text = $('break-seed').value;
  const seed = Number(text);
  if (text.trim() === '' || !Number.isInteger(seed) || seed < 0)
    throw new Error(`the seed must be a whole number (0 or more), not '${text}'`);
  return { material, seed, thickness: scene.thickness, density: DENSITY[material], ...scene.size };
}

//! A strike of the scene's kind: solid fracture of a 3D object (surface fracture when it is open),
//! surface fracture of the plate.
function breakAt(s, point, options) {
  if (!scene.solid) return s.fracture(point, options);
  const { material, seed, density, thickness } = options;
  return s.fractureSolid(point, {
    kind: 'auto',
    material,
    seed,
    density,
    innerSubmesh: scene.innerSubmesh,
    surface: { thickness },
  });
}

// A closed triangle mesh: every half-edge has a face (3 per triangle).
const isClosed = (mesh) => {
  const c = mesh.counts();
  return mesh.isTriangleMesh() && c.halfedges === 3 * c.faces;
};

//! Strikes the mesh at `point` (the ray travelling along `direction`): fracture in wasm, the
//! remaining mesh synced to the GPU by dirty ranges, the shards or pieces handed to the physics.
function strike(point, direction) {
  const options = strikeOptions();
  let result = null;
  let strikeMs = 0;
  applyEdit('strike', (s) => {
    const t0 = performance.now();
    result = breakAt(s, point, options);
    strikeMs = performance.now() - t0;
    const kind = result.kind === 'solid' ? 'solid' : 'surface';
    return `strike (${kind}, ${options.material}, seed ${options.seed})`;
  });
  const s = result.seconds;
  const solid = result.kind === 'solid';
  const parts = solid ? result.pieces : result.shards;
  scene.strikes.push({
    ms: strikeMs,
    wasmMs: 1000 * s.fracture,
    shards: parts.length,
    kind: solid ? 'solid' : 'surface',
    closed: parts.filter((p) => isClosed(p.mesh)).length,
    bonds: solid ? result.bonds.length : 0,
  });
  showFracture();
  const d = Math.hypot(...direction) || 1;
  try {
    for (const shard of parts) {
      // Away from the impact along the surface, and on along the strike.
      const out = [0, 1, 2].map((i) => shard.centreOfMass[i] - point[i]);
      const len = Math.hypot(...out) || 1;
      const away = [0, 1, 2].map((i) => out[i] / len + (0.5 * direction[i]) / d);
      const n = Math.hypot(...away) || 1;
      const unit = away.map((x) => x / n);
      if (solid) scene.world.addPiece(shard, unit, PUSH, scene.innerSubmesh);
      else scene.world.addShard(shard, unit, PUSH);
    }
  } finally {
    for (const shard of parts) shard.dispose();
  }
  // Where the new shards start, for the tests: the simulation moves them from the next frame on.
  scene.strikeSnapshot = { steps: scene.world.steps, shards: scene.world.report() };
  showShards();
  startPhysics();
}

export function strikeAt(event) {
  const s = state.current;
  if (!s) return;
  const ray = state.viewer.rayAt(event);
  const hit = s.pick(ray.origin, ray.direction);
  if (!hit) return;
  strike(hit.point, ray.direction);
}

//! Times `count` strikes of the chosen material on a copy of the scene's mesh, at points where
//! random rays hit it (after 5 that are not counted: the first calls run before the engine has
//! optimised the wasm code). As in the benchmark, the copy is made again (untimed) once a fifth of
//! its faces has broken off. Shards (in a 3D object's scene, solid pieces, as a click makes them) are
//! made (with their hulls) and freed, not simulated; the plate's break radius is its strikes'. A
//! point fracture refuses (a lone face left by earlier strikes) is skipped.
async function timeStrikes(count = 25) {
  const s = state.current;
  if (!s || state.mode !== 'break') throw new Error('set up a break scene first');
  const material = $('break-material').value;
  const fresh = () => {
    const copy = new PageMesh(state.hedge, s.mesh.clone(), { render: false });
    copy.buildPicking();
    return copy;
  };
  let copy = fresh();
  const triangles = copy.counts().faces;
  try {
    const box = copy.boundingBox();
    const centre = [0, 1, 2].map((i) => (box.min[i] + box.max[i]) / 2);
    const radius = Math.hypot(...[0, 1, 2].map((i) => box.max[i] - box.min[i]));
    let seed = 12345;
    const random = () => {
      seed = (seed * 1103515245 + 12345) % 2147483648;
      return seed / 2147483648;
    };
    const times = [],
      inWasm = [],
      shards = [],
      warmUp = [];
    let skipped = 0;
    const WARM_UP = 5;
    for (let attempt = 0; times.length < count && attempt < (count + WARM_UP) * 50; ++attempt) {
      if (copy.counts().faces < 0.8 * triangles) {
        copy.dispose();
        copy = fresh();
      }
      const z = 2 * random() - 1,
        a = 2 * Math.PI * random(),
        r = Math.sqrt(1 - z * z);
      const origin = [
        centre[0] + radius * r * Math.cos(a),
        centre[1] + radius * z,
        centre[2] + radius * r * Math.sin(a),
      ];
      const target = [0, 1, 2].map((i) => box.min[i] + random() * (box.max[i] - box.min[i]));
      const hit = copy.pick(
        origin,
        [0, 1, 2].map((i) => target[i] - origin[i]),
      );
      if (!hit) continue;
      let result;
      const t0 = performance.now();
      try {
        // Surface strikes as the benchmark times them (no thickness); solid ones as clicked.
        const extra = scene.solid
          ? { density: DENSITY[material], thickness: scene.thickness }
          : scene.size;
        result = breakAt(copy, hit.point, { material, seed: attempt, ...extra });
      } catch (error) {
        if (error.kind !== 'invalid-argument') throw error;
        ++skipped;
        continue;
      }
      const t = performance.now() - t0;
      const sec = result.seconds;
      const parts = result.kind === 'solid' ? result.pieces : result.shards;
      for (const part of parts) part.dispose();
      if (warmUp.length < WARM_UP) {
        warmUp.push(t);
        continue;
      }
      times.push(t);
      inWasm.push(1000 * sec.fracture);
      shards.push(parts.length);
      if (times.length % 5 === 0) await new Promise((resolve) => setTimeout(resolve, 0));
    }
    return { times, inWasm, shards, warmUp, skipped, material, triangles };
  } finally {
    copy.dispose();
  }
}

//! Wires the break scene's buttons: set up a scene, time strikes.
export function wireBreakInput() {
  $('break-setup').addEventListener('click', () => {
    const name = $('break-scene').value;
    guard(`setting up the ${name} scene`, () => setupBreak(name));
  });
  $('break-bench').addEventListener('click', () =>
    guard('timing strikes', async () => {
      $('stat-fracture').textContent = 'timing 25 strikes...';
      const r = await timeStrikes(25);
      const sorted = [...r.times].sort((a, b) => a - b);
      const report = {
        material: r.material,
        triangles: r.triangles,
        strikes: r.times.length,
        medianMs: median(r.times),
        p95Ms: sorted[Math.floor(0.95 * (sorted.length - 1))],
        medianInWasmMs: median(r.inWasm),
        meanShards: r.shards.reduce((a, b) => a + b, 0) / r.shards.length,
        warmUpMs: r.warmUp,
        skipped: r.skipped,
      };
      report.text =
        `${r.material} on ${fmt(r.triangles)} triangles: median ${ms(report.medianMs)} per strike ` +
        `(in fracture() ${ms(report.medianInWasmMs)}), p95 ${ms(report.p95Ms)}, ${report.meanShards.toFixed(1)} shards, ` +
        `over ${report.strikes} strikes (first of 5 warm-up: ${ms(r.warmUp[0])})` +
        (r.skipped ? `; ${r.skipped} points refused (a lone face)` : '');
      clearError();
      $('stat-fracture').textContent = report.text;
      document.body.dataset.breakBench = JSON.stringify(report);
    }),
  );
}

//! Read-only views of the break scene for the end-to-end tests.
export const breakHooks = {
  //! The shards: [{position, lowest, speed, angularSpeed, asleep}].
  shards() {
    return scene.world ? scene.world.report() : [];
  },
  //! The shards as the last strike made them, before any step: {steps, shards}.
  strikeSnapshot() {
    return scene.strikeSnapshot;
  },
  groundY() {
    return scene.world ? scene.world.groundY : NaN;
  },
  //! How the caps of a solid fracture are drawn: {innerSubmesh, pieces (bodies drawn with a
  //! non-empty group of the inner material), object (the remaining object's geometry has such a
  //! group)}.
  drawnCaps() {
    const inner = scene.innerSubmesh;
    const capped = (mesh) =>
      Array.isArray(mesh.material) &&
      mesh.material[inner] !== mesh.material[0] &&
      mesh.geometry.groups.some((g) => g.materialIndex === inner && g.count > 0);
    return {
      innerSubmesh: inner,
      pieces: scene.world ? scene.world.shards.filter(({ mesh }) => capped(mesh)).length : 0,
      object: state.viewer ? capped(state.viewer.mesh.surface) : false,
    };
  },
};
