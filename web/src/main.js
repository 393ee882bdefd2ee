// The playground: loads meshes with hedge (WebAssembly), draws them with three.js, shows the
// half-edge records under the cursor and edits the mesh, updating the GPU buffers range by range.
import { Viewer, COLORS } from './viewer.js';
import { loadHedge, PageMesh, SUBDIVISION_SCHEMES } from './page_mesh.js';
import { measurePicking } from './picking_bench.js';
import { BreakWorld, STEP, median, plateArrays } from './break_scene.js';

const $ = (id) => document.getElementById(id);
const fmt = (n) => n.toLocaleString('en-US');

const state = {
  hedge: null,
  current: null, // the PageMesh shown
  viewer: null,
  hover: null, // { kind: 'face' | 'edge' | 'vertex', face, halfedge, vertex, point }
  busy: false,
  lastUpload: null, // { bytes, full, ranges, gl: meter delta }
  mode: 'edit', // 'break' in a break scene: a click strikes
  world: null, // the BreakWorld (cannon-es) of the break scene
  thickness: 0, // of the shards in the break scene
  strikes: [], // {ms, wasmMs, shards} of each strike in the scene
  ticking: false, // the physics loop is running
};

// Mass per unit volume (kg/m^3) of each material, for the shards' mass properties.
const DENSITY = { glass: 2500, stone: 2600, wood: 600, ice: 917 };
// The speed (m/s) of the push a shard gets away from the impact.
const PUSH = 0.8;

// ---- errors -------------------------------------------------------------------------------------

function showError(message) {
  $('error-text').textContent = message;
  $('error').hidden = false;
  document.body.dataset.error = message;
}

function clearError() {
  $('error').hidden = true;
  delete document.body.dataset.error;
}

function messageOf(error) {
  if (error && typeof error.message === 'string') return error.message;
  return String(error);
}

// Runs an action so that a failure is reported on the page and leaves it usable.
async function guard(what, action) {
  if (state.busy) return undefined;
  state.busy = true;
  document.body.dataset.busy = '1';
  try {
    return await action();
  } catch (error) {
    showError(`${what}: ${messageOf(error)}`);
    return undefined;
  } finally {
    state.busy = false;
    delete document.body.dataset.busy;
  }
}

// ---- stats --------------------------------------------------------------------------------------

function showStats() {
  const s = state.current;
  if (!s) return;
  const c = s.counts();
  $('stat-v').textContent = fmt(c.vertices);
  $('stat-e').textContent = fmt(c.edges);
  $('stat-f').textContent = fmt(c.faces);
  const problems = s.problems();
  const valid = $('stat-valid');
  valid.textContent =
    problems.length === 0 ? 'valid' : `${problems.length} problem(s): ${problems[0]}`;
  valid.className = problems.length === 0 ? 'ok' : 'bad';
  document.body.dataset.counts = `${c.vertices},${c.edges},${c.faces}`;
  document.body.dataset.valid = problems.length === 0 ? '1' : '0';
}

const ms = (t) => `${t.toFixed(t < 10 ? 2 : 1)} ms`;

//! The last operation and its time; `syncMs`: the RenderSync sync and the buffer copies after it.
function showOperation(name, opMs, syncMs) {
  $('stat-op').textContent = name;
  $('stat-time').textContent =
    syncMs === undefined ? ms(opMs) : `${ms(opMs)} (then sync and upload ${ms(syncMs)})`;
}

function showUpload(upload) {
  const total = state.viewer.mesh.allocatedBytes;
  const gl = upload.gl;
  const sent = gl.subBytes + gl.fullBytes;
  const kind = upload.full ? 'full upload' : 'partial';
  $('stat-upload').textContent =
    `${fmt(sent)} B (${kind}: ${gl.subCalls} ranges, ${gl.fullCalls} whole buffers) of ${fmt(total)} B`;
  document.body.dataset.upload = JSON.stringify({
    ...gl,
    queued: upload.bytes,
    full: upload.full,
    total,
  });
}

// ---- loading ------------------------------------------------------------------------------------

// Replaces the current mesh by `next` (already loaded) and uploads it whole.
function adopt(next, name, loadMs) {
  const old = state.current;
  state.current = next;
  if (old) old.dispose();
  state.hover = null;
  state.viewer.clearOverlay();
  $('records').textContent = 'Hover the mesh.';
  $('mesh-name').textContent = name;
  $('mesh-notes').textContent = next.loadNotes();
  const before = state.viewer.meter.snapshot();
  const isEdge = next.edgeTest();
  const bytes = state.viewer.mesh.rebuild(next.buffers(), isEdge);
  state.viewer.frame(next.boundingBox());
  state.viewer.render();
  state.lastUpload = { bytes, full: true, ranges: 1, gl: state.viewer.meter.since(before) };
  showUpload(state.lastUpload);
  showOperation(`load ${name}`, loadMs);
  showStats();
  document.body.dataset.mesh = name;
}

async function loadBytes(bytes, name) {
  leaveBreak();
  const t0 = performance.now();
  const loaded = PageMesh.load(state.hedge, bytes, name);
  const loadMs = performance.now() - t0;
  clearError();
  adopt(loaded, name, loadMs);
}

async function loadSample(name) {
  const response = await fetch(`/data/${encodeURIComponent(name)}`);
  if (!response.ok) throw new Error(`could not fetch sample ${name} (HTTP ${response.status})`);
  await loadBytes(new Uint8Array(await response.arrayBuffer()), name);
}

async function loadFile(file) {
  const bytes = new Uint8Array(await file.arrayBuffer());
  await loadBytes(bytes, file.name);
}

// ---- inspect ------------------------------------------------------------------------------------

// Distance from p to segment ab, all [x, y, z].
function segmentDistance(p, a, b) {
  const ab = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
  const ap = [p[0] - a[0], p[1] - a[1], p[2] - a[2]];
  const len2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
  const t =
    len2 > 0 ? Math.min(1, Math.max(0, (ap[0] * ab[0] + ap[1] * ab[1] + ap[2] * ab[2]) / len2)) : 0;
  const d = [ap[0] - t * ab[0], ap[1] - t * ab[1], ap[2] - t * ab[2]];
  return Math.hypot(d[0], d[1], d[2]);
}

const VERTEX_PIXELS = 8;
const EDGE_PIXELS = 6;

//! What is under the pointer: the face hit, or its edge or corner when the hit is within a few
//! pixels of one. The reach shrinks on faces that look small, so that a face's middle always picks
//! the face and an edge's middle the edge. Null when the ray misses.
function elementAt(event) {
  const s = state.current;
  if (!s) return null;
  const ray = state.viewer.rayAt(event);
  const hit = s.pick(ray.origin, ray.direction);
  if (!hit) return null;
  const ppu = state.viewer.pixelsPerUnit(hit.point);
  const loop = s.faceHalfedges(hit.face).map((h) => {
    const r = s.record(h);
    return { h, r, a: s.position(r.origin), b: s.position(r.target) };
  });
  const centre = [0, 1, 2].map((i) => loop.reduce((sum, c) => sum + c.a[i], 0) / loop.length);
  const distance = (p, q) => Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
  let shortest = Infinity;
  for (const c of loop) shortest = Math.min(shortest, distance(c.a, c.b));
  const vertexReach = Math.min(VERTEX_PIXELS / ppu, 0.25 * shortest);
  let best = null;
  for (const c of loop) {
    const d = distance(c.a, hit.point);
    if (d < vertexReach && (!best || d < best.d)) best = { d, h: c.h, v: c.r.origin };
  }
  if (best)
    return { kind: 'vertex', face: hit.face, halfedge: best.h, vertex: best.v, point: hit.point };
  let bestEdge = null;
  for (const c of loop) {
    const d = segmentDistance(hit.point, c.a, c.b);
    const reach = Math.min(EDGE_PIXELS / ppu, 0.4 * segmentDistance(centre, c.a, c.b));
    if (d < reach && (!bestEdge || d < bestEdge.d)) bestEdge = { d, h: c.h };
  }
  if (bestEdge) return { kind: 'edge', face: hit.face, halfedge: bestEdge.h, point: hit.point };
  return { kind: 'face', face: hit.face, halfedge: loop[0].h, point: hit.point };
}

function recordLines(s, h, label) {
  const r = s.record(h);
  return [
    `${label} h${h}  (edge e${r.edge})`,
    `  origin  v${r.origin}`,
    `  twin    h${r.twin}`,
    `  face    ${r.face < 0 ? 'boundary' : 'f' + r.face}`,
    `  next    h${r.next}`,
    `  prev    h${r.prev}`,
  ];
}

function describe(el) {
  const s = state.current;
  const lines = [];
  if (el.kind === 'face') {
    const loop = s.faceHalfedges(el.face);
    lines.push(
      `face f${el.face}: ${loop.length} corners, half-edges ${loop.map((h) => 'h' + h).join(' ')}`,
    );
    lines.push(...recordLines(s, el.halfedge, 'halfedge(f)'));
  } else if (el.kind === 'edge') {
    const r = s.record(el.halfedge);
    lines.push(`edge e${r.edge}: v${r.origin} - v${r.target}`);
    lines.push(...recordLines(s, el.halfedge, 'half-edge'));
    lines.push(...recordLines(s, r.twin, 'twin'));
  } else {
    const ring = s.oneRing(el.vertex);
    const p = s
      .position(el.vertex)
      .map((x) => x.toFixed(3))
      .join(', ');
    lines.push(`vertex v${el.vertex}: (${p}), valence ${ring.length}`);
    lines.push(
      `  one-ring ${ring
        .slice(0, 12)
        .map((v) => 'v' + v)
        .join(' ')}${ring.length > 12 ? ' ...' : ''}`,
    );
    lines.push(...recordLines(s, s.outgoing(el.vertex), 'outgoing'));
  }
  return lines.join('\n');
}

function faceCentre(s, f) {
  const loop = s.faceHalfedges(f);
  const c = [0, 0, 0];
  for (const h of loop) {
    const p = s.position(s.record(h).origin);
    for (let i = 0; i < 3; ++i) c[i] += p[i] / loop.length;
  }
  return c;
}

function drawArrow(s, h, color) {
  const r = s.record(h);
  if (r.face < 0) {
    // A boundary half-edge: bend it away from its twin's face.
    const inside = faceCentre(s, s.record(r.twin).face);
    const a = s.position(r.origin),
      b = s.position(r.target);
    const outside = [0, 1, 2].map((i) => a[i] + b[i] - inside[i]);
    state.viewer.addHalfedgeArrow(a, b, outside, color);
    return;
  }
  state.viewer.addHalfedgeArrow(
    s.position(r.origin),
    s.position(r.target),
    faceCentre(s, r.face),
    color,
  );
}

function drawHover() {
  const viewer = state.viewer;
  viewer.clearOverlay();
  const el = state.hover;
  const s = state.current;
  if (!el || !s) return;
  const loopPoints = (f) => s.faceHalfedges(f).map((h) => s.position(s.record(h).origin));
  // Overlay sizes follow the hovered face's edges, so they read the same at any zoom and density.
  const points = loopPoints(el.face);
  let unit = 0;
  for (let i = 0; i < points.length; ++i) {
    const a = points[i],
      b = points[(i + 1) % points.length];
    unit += Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]) / points.length;
  }
  if (el.kind === 'face') viewer.addPolygon(points, COLORS.face);
  if (el.kind === 'edge') {
    const r = s.record(el.halfedge);
    viewer.addSegment(s.position(r.origin), s.position(r.target), COLORS.edge, unit * 0.035);
  }
  const ringVertex = el.kind === 'vertex' ? el.vertex : s.record(el.halfedge).origin;
  if (el.kind === 'vertex') viewer.addPoint(s.position(el.vertex), COLORS.vertex, unit * 0.1);
  if ($('show-ring').checked) {
    const centre = s.position(ringVertex);
    viewer.addPoint(centre, COLORS.ring, unit * 0.08);
    for (const v of s.oneRing(ringVertex)) {
      viewer.addSegment(centre, s.position(v), COLORS.ring, unit * 0.02);
      viewer.addPoint(s.position(v), COLORS.ring, unit * 0.06);
    }
  }
  if ($('show-arrows').checked) {
    const h = el.kind === 'vertex' ? s.outgoing(el.vertex) : el.halfedge;
    const r = s.record(h);
    if (el.kind === 'face') {
      for (const g of s.faceHalfedges(el.face)) if (g !== h) drawArrow(s, g, COLORS.next);
    } else {
      if (r.face >= 0) {
        drawArrow(s, r.next, COLORS.next);
        drawArrow(s, r.prev, COLORS.prev);
      }
      drawArrow(s, r.twin, COLORS.twin);
    }
    drawArrow(s, h, COLORS.halfedge);
  }
  viewer.requestRender();
}

function setHover(el) {
  const same = (a, b) =>
    a &&
    b &&
    a.kind === b.kind &&
    a.face === b.face &&
    a.halfedge === b.halfedge &&
    a.vertex === b.vertex;
  if (same(el, state.hover) || (!el && !state.hover)) return;
  state.hover = el;
  $('records').textContent = el ? describe(el) : 'Hover the mesh.';
  document.body.dataset.hover = el ? el.kind : '';
  drawHover();
}

// ---- edit ---------------------------------------------------------------------------------------

// Runs `edit` (which returns a short description, or throws), syncs RenderSync and uploads the
// rewritten ranges. The frame right after the edit is rendered here, with the overlays hidden, so
// that the upload meter counts this edit's buffers alone.
function applyEdit(name, edit) {
  const s = state.current;
  if (!s) throw new Error('no mesh loaded');
  const t0 = performance.now();
  const description = edit(s);
  const t1 = performance.now();
  const result = s.sync();
  const viewer = state.viewer;
  state.hover = null;
  viewer.clearOverlay();
  const before = viewer.meter.snapshot();
  const isEdge = s.edgeTest();
  const upload = viewer.mesh.update(s.buffers(), result, isEdge);
  viewer.render();
  const t2 = performance.now();
  state.lastUpload = { ...upload, gl: viewer.meter.since(before) };
  showUpload(state.lastUpload);
  showOperation(description || name, t1 - t0, t2 - t1);
  showStats();
  clearError();
  $('records').textContent = 'Hover the mesh.';
  document.body.dataset.edits = String(Number(document.body.dataset.edits || 0) + 1);
}

function edgeMode() {
  return document.querySelector('input[name="edge-mode"]:checked').value;
}

function clickEdit(el) {
  if (!el) return;
  if (el.kind === 'face') {
    applyEdit('split face', (s) => {
      s.splitFace(el.face, el.point);
      return `split face f${el.face}`;
    });
    return;
  }
  if (el.kind !== 'edge') return;
  const mode = edgeMode();
  const h = el.halfedge;
  applyEdit(`${mode} edge`, (s) => {
    const e = s.record(h).edge;
    if (mode === 'split') s.splitEdge(e, el.point);
    else if (mode === 'flip') s.flip(e);
    else s.collapse(h);
    return `${mode} edge e${e}`;
  });
}

// ---- break --------------------------------------------------------------------------------------

function leaveBreak() {
  state.mode = 'edit';
  state.strikes = [];
  if (state.world) state.world.clear();
  if (state.viewer) {
    state.viewer.setSeeThrough(false);
    state.viewer.setWireframe($('show-wire').checked);
  }
  delete document.body.dataset.scene;
  delete document.body.dataset.fracture;
  $('stat-fracture').textContent = '-';
  $('stat-shards').textContent = '-';
}

//! Sets up a break scene: 'plate' (a plate of 224 x 224 squares, 100,352 triangles, made here) or
//! 'spot' (a sample), above a ground plane.
async function setupBreak(name) {
  let bytes = null;
  if (name === 'spot') {
    const response = await fetch('/data/spot_triangulated.obj');
    if (!response.ok)
      throw new Error(`could not fetch spot_triangulated.obj (HTTP ${response.status})`);
    bytes = new Uint8Array(await response.arrayBuffer());
  }
  leaveBreak();
  const t0 = performance.now();
  const next =
    name === 'plate'
      ? PageMesh.fromBuffers(state.hedge, plateArrays(224, 3, 1))
      : PageMesh.load(state.hedge, bytes, 'spot_triangulated.obj');
  next.buildPicking(); // strikes go through the picking tree, as in a game
  const loadMs = performance.now() - t0;
  clearError();
  adopt(next, name === 'plate' ? 'plate, 224 x 224 squares' : 'spot_triangulated.obj', loadMs);
  const box = next.boundingBox();
  const diagonal = Math.hypot(...[0, 1, 2].map((i) => box.max[i] - box.min[i]));
  // The plate lies at height 1 above the ground; the object stands just above it.
  const ground = name === 'plate' ? 0 : box.min[1] - 0.02 * diagonal;
  state.world.setGround(ground, 3 * diagonal);
  // 1 cm for the 3 m plate (its squares are 1.3 cm wide); the object's in proportion.
  state.thickness = name === 'plate' ? 0.01 : 0.004 * diagonal;
  state.mode = 'break';
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
  const strikes = state.strikes;
  const last = strikes[strikes.length - 1];
  const m = median(strikes.map((x) => x.ms));
  $('stat-fracture').textContent =
    `${ms(last.ms)} (in fracture() ${ms(last.wasmMs)}), median ${ms(m)} over ${strikes.length} strike(s); ${last.shards} shards`;
  document.body.dataset.fracture = JSON.stringify({
    last: last.ms,
    wasm: last.wasmMs,
    median: m,
    strikes: strikes.length,
    shards: last.shards,
  });
}

function showShards() {
  const w = state.world;
  const n = w.shards.length;
  const moving = w.moving;
  $('stat-shards').textContent =
    `${fmt(n)} shards: ${fmt(moving)} moving, ${fmt(n - moving)} at rest (${fmt(w.steps)} steps)`;
  document.body.dataset.shards = String(n);
  document.body.dataset.physicsSteps = String(w.steps);
}

//! Steps the physics at 60 Hz of simulated time (at most 4 steps a frame) while a shard moves.
function tick(now) {
  const w = state.world;
  if (w.shards.length === 0 || w.moving === 0) {
    state.ticking = false;
    showShards();
    state.viewer.requestRender();
    return;
  }
  const elapsed = state.lastTick === undefined ? STEP : (now - state.lastTick) / 1000;
  state.lastTick = now;
  state.stepDebt = Math.min(4 * STEP, (state.stepDebt || 0) + elapsed);
  const steps = Math.max(1, Math.floor(state.stepDebt / STEP));
  state.stepDebt = Math.max(0, state.stepDebt - steps * STEP);
  w.step(steps);
  state.viewer.render();
  showShards();
  requestAnimationFrame(tick);
}

function startPhysics() {
  if (state.ticking) return;
  state.ticking = true;
  state.lastTick = undefined;
  requestAnimationFrame(tick);
}

function strikeOptions() {
  const material = $('break-material').value;
  const text = $('break-seed').value;
  const seed = Number(text);
  if (text.trim() === '' || !Number.isInteger(seed) || seed < 0)
    throw new Error(`the seed must be a whole number (0 or more), not '${text}'`);
  return { material, seed, thickness: state.thickness, density: DENSITY[material] };
}

//! Strikes the mesh at `point` (the ray travelling along `direction`): fracture in wasm, the
//! remaining mesh synced to the GPU by dirty ranges, the shards handed to the physics.
function strike(point, direction) {
  const options = strikeOptions();
  let result = null;
  let strikeMs = 0;
  applyEdit('strike', (s) => {
    const t0 = performance.now();
    result = s.fracture(point, options);
    strikeMs = performance.now() - t0;
    return `strike (${options.material}, seed ${options.seed})`;
  });
  const s = result.seconds;
  state.strikes.push({ ms: strikeMs, wasmMs: 1000 * s.fracture, shards: result.shards.length });
  showFracture();
  const d = Math.hypot(...direction) || 1;
  try {
    for (const shard of result.shards) {
      // Away from the impact along the surface, and on along the strike.
      const out = [0, 1, 2].map((i) => shard.centreOfMass[i] - point[i]);
      const len = Math.hypot(...out) || 1;
      const away = [0, 1, 2].map((i) => out[i] / len + (0.5 * direction[i]) / d);
      const n = Math.hypot(...away) || 1;
      state.world.addShard(
        shard,
        away.map((x) => x / n),
        PUSH,
      );
    }
  } finally {
    for (const shard of result.shards) shard.dispose();
  }
  // Where the new shards start, for the tests: the simulation moves them from the next frame on.
  state.strikeSnapshot = { steps: state.world.steps, shards: state.world.report() };
  showShards();
  startPhysics();
}

function strikeAt(event) {
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
//! its faces has broken off. Shards are made (with their hulls) and freed, not simulated. A point
//! fracture refuses (a lone face left by earlier strikes) is skipped.
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
        result = copy.fracture(hit.point, { material, seed: attempt });
      } catch (error) {
        if (error.kind !== 'invalid-argument') throw error;
        ++skipped;
        continue;
      }
      const t = performance.now() - t0;
      const sec = result.seconds;
      for (const shard of result.shards) shard.dispose();
      if (warmUp.length < WARM_UP) {
        warmUp.push(t);
        continue;
      }
      times.push(t);
      inWasm.push(1000 * sec.fracture);
      shards.push(result.shards.length);
      if (times.length % 5 === 0) await new Promise((resolve) => setTimeout(resolve, 0));
    }
    return { times, inWasm, shards, warmUp, skipped, material, triangles };
  } finally {
    copy.dispose();
  }
}

// ---- wiring -------------------------------------------------------------------------------------

function wireInput() {
  const viewer = state.viewer;
  const canvas = viewer.canvas;
  let down = null;
  let moveQueued = null;
  canvas.addEventListener('pointermove', (event) => {
    if (event.buttons) return;
    const queued = moveQueued;
    moveQueued = event;
    if (queued) return;
    requestAnimationFrame(() => {
      const e = moveQueued;
      moveQueued = null;
      if (state.busy || !state.current) return;
      try {
        setHover(elementAt(e));
      } catch (error) {
        showError(`inspect: ${messageOf(error)}`);
      }
    });
  });
  canvas.addEventListener('pointerleave', () => setHover(null));
  canvas.addEventListener('pointerdown', (event) => {
    down = { x: event.clientX, y: event.clientY };
  });
  canvas.addEventListener('pointerup', (event) => {
    if (!down || event.button !== 0) return;
    const moved = Math.hypot(event.clientX - down.x, event.clientY - down.y);
    down = null;
    if (moved > 4) return; // an orbit, not a click
    if (state.mode === 'break') guard('strike', () => strikeAt(event));
    else guard('edit', () => clickEdit(elementAt(event)));
  });

  const view = $('view');
  view.addEventListener('dragover', (event) => {
    event.preventDefault();
    $('drop-hint').hidden = false;
  });
  view.addEventListener('dragleave', () => {
    $('drop-hint').hidden = true;
  });
  view.addEventListener('drop', (event) => {
    event.preventDefault();
    $('drop-hint').hidden = true;
    const file = event.dataTransfer && event.dataTransfer.files[0];
    if (!file) return;
    guard(`loading ${file.name}`, () => loadFile(file));
  });

  $('file').addEventListener('change', (event) => {
    const file = event.target.files[0];
    if (!file) return;
    guard(`loading ${file.name}`, () => loadFile(file)).finally(() => {
      event.target.value = '';
    });
  });
  $('error-close').addEventListener('click', clearError);
  $('load-sample').addEventListener('click', () => {
    const name = $('sample').value;
    guard(`loading ${name}`, () => loadSample(name));
  });
  $('show-wire').addEventListener('change', (e) => viewer.setWireframe(e.target.checked));
  $('show-ring').addEventListener('change', drawHover);
  $('show-arrows').addEventListener('change', drawHover);

  const buttons = $('subdivide-buttons');
  for (const { id, label } of SUBDIVISION_SCHEMES) {
    const button = document.createElement('button');
    button.type = 'button';
    button.id = `subdivide-${id}`;
    button.textContent = label;
    button.addEventListener('click', () =>
      guard(label, () =>
        applyEdit(label, (s) => {
          s.subdivide(id);
          return label;
        }),
      ),
    );
    buttons.appendChild(button);
  }
  $('smooth').addEventListener('click', () =>
    guard('smooth', () =>
      applyEdit('smooth', (s) => {
        s.smooth();
        return 'smooth (Taubin, 10 steps)';
      }),
    ),
  );
  const ratio = $('decimate-ratio');
  const ratioLabel = () => {
    $('decimate-label').textContent = `${ratio.value}% of faces`;
  };
  ratio.addEventListener('input', ratioLabel);
  ratioLabel();
  $('decimate').addEventListener('click', () =>
    guard('decimate', () =>
      applyEdit('decimate', (s) => {
        const before = s.counts().faces;
        const target = Math.max(4, Math.round((before * Number(ratio.value)) / 100));
        s.decimate(target);
        return `decimate to ${fmt(target)} faces`;
      }),
    ),
  );
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
  $('pick-bench').addEventListener('click', () =>
    guard('picking benchmark', async () => {
      $('stat-pick').textContent = 'measuring...';
      const report = await measurePicking(state.hedge, state.current, Number($('pick-size').value));
      $('stat-pick').textContent = report.text;
      document.body.dataset.pick = JSON.stringify(report);
    }),
  );
}

async function main() {
  try {
    state.viewer = new Viewer($('canvas'));
  } catch (error) {
    showError(`WebGL is not available: ${messageOf(error)}`);
    return;
  }
  state.world = new BreakWorld(state.viewer.scene);
  wireInput();
  try {
    state.hedge = await loadHedge();
  } catch (error) {
    showError(
      `The hedge WebAssembly module did not load (build it with bindings/wasm/build): ${messageOf(error)}`,
    );
    return;
  }
  await guard('loading spot_triangulated.obj', () => loadSample('spot_triangulated.obj'));
  document.body.dataset.ready = '1';
}

// Read-only hooks for the end-to-end tests: where things are on screen, nothing that edits.
window.playground = {
  state,
  //! The shards of the break scene: [{position, lowest, speed, angularSpeed, asleep}].
  shards() {
    return state.world ? state.world.report() : [];
  },
  //! The shards as the last strike made them, before any step: {steps, shards}.
  strikeSnapshot() {
    return state.strikeSnapshot;
  },
  groundY() {
    return state.world ? state.world.groundY : NaN;
  },
  //! Screen position (client pixels) of world point p.
  project(p) {
    return state.viewer.project(p);
  },
  //! Edges whose midpoint is visible and picks back as that edge: [{edge, halfedge, x, y, length}]
  //! (screen pixels).
  visibleEdges(limit = 20) {
    const s = state.current;
    const out = [];
    const faces = s.counts().faces;
    for (let f = 0; f < faces && out.length < limit; f += Math.max(1, Math.floor(faces / 400))) {
      if (!s.isFaceLive(f)) continue;
      const h = s.faceHalfedges(f)[0];
      const r = s.record(h);
      if (s.record(r.twin).face < 0) continue;
      const a = s.position(r.origin),
        b = s.position(r.target);
      const mid = [0, 1, 2].map((i) => (a[i] + b[i]) / 2);
      const { x, y } = state.viewer.project(mid);
      const pa = state.viewer.project(a),
        pb = state.viewer.project(b);
      const length = Math.hypot(pa.x - pb.x, pa.y - pb.y);
      const el = elementAt({ clientX: x, clientY: y });
      if (el && el.kind === 'edge' && s.record(el.halfedge).edge === r.edge)
        out.push({ edge: r.edge, halfedge: h, x, y, length });
    }
    return out;
  },
  //! Screen position of the centroid of a visible face that picks back as that face, or null;
  //! `largest`: of the face that looks largest on screen (its screen-space area) instead of the first.
  visibleFaceCentre({ largest = false } = {}) {
    const s = state.current;
    const faces = s.counts().faces;
    let best = null;
    for (let f = 0; f < faces; ++f) {
      if (!s.isFaceLive(f)) continue;
      const { x, y } = state.viewer.project(faceCentre(s, f));
      const el = elementAt({ clientX: x, clientY: y });
      if (!el || el.kind !== 'face' || el.face !== f) continue;
      if (!largest) return { face: f, x, y };
      const corners = s
        .faceHalfedges(f)
        .map((h) => state.viewer.project(s.position(s.record(h).origin)));
      let area = 0;
      for (let i = 0; i < corners.length; ++i) {
        const p = corners[i],
          q = corners[(i + 1) % corners.length];
        area += (p.x * q.y - q.x * p.y) / 2;
      }
      if (!best || Math.abs(area) > best.area) best = { face: f, x, y, area: Math.abs(area) };
    }
    return best;
  },
};

main();
