// The playground: loads meshes with hedge (WebAssembly), draws them with three.js, shows the
// half-edge records under the cursor and edits the mesh, updating the GPU buffers range by range.
import { Viewer, COLORS } from './viewer.js';
import { loadHedge, PageMesh, SUBDIVISION_SCHEMES } from './page_mesh.js';
import { measurePicking } from './picking_bench.js';

const $ = (id) => document.getElementById(id);
const fmt = (n) => n.toLocaleString('en-US');

const state = {
  hedge: null,
  current: null,     // the PageMesh shown
  viewer: null,
  hover: null,      // { kind: 'face' | 'edge' | 'vertex', face, halfedge, vertex, point }
  busy: false,
  lastUpload: null, // { bytes, full, ranges, gl: meter delta }
};

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
  valid.textContent = problems.length === 0 ? 'valid' : `${problems.length} problem(s): ${problems[0]}`;
  valid.className = problems.length === 0 ? 'ok' : 'bad';
  document.body.dataset.counts = `${c.vertices},${c.edges},${c.faces}`;
  document.body.dataset.valid = problems.length === 0 ? '1' : '0';
}

const ms = (t) => `${t.toFixed(t < 10 ? 2 : 1)} ms`;

//! The last operation and its time; `syncMs`: the RenderSync sync and the buffer copies after it.
function showOperation(name, opMs, syncMs) {
  $('stat-op').textContent = name;
  $('stat-time').textContent = syncMs === undefined ? ms(opMs) : `${ms(opMs)} (then sync and upload ${ms(syncMs)})`;
}

function showUpload(upload) {
  const total = state.viewer.mesh.allocatedBytes;
  const gl = upload.gl;
  const sent = gl.subBytes + gl.fullBytes;
  const kind = upload.full ? 'full upload' : 'partial';
  $('stat-upload').textContent =
    `${fmt(sent)} B (${kind}: ${gl.subCalls} ranges, ${gl.fullCalls} whole buffers) of ${fmt(total)} B`;
  document.body.dataset.upload = JSON.stringify({ ...gl, queued: upload.bytes, full: upload.full, total });
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
  const t = len2 > 0 ? Math.min(1, Math.max(0, (ap[0] * ab[0] + ap[1] * ab[1] + ap[2] * ab[2]) / len2)) : 0;
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
  if (best) return { kind: 'vertex', face: hit.face, halfedge: best.h, vertex: best.v, point: hit.point };
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
    lines.push(`face f${el.face}: ${loop.length} corners, half-edges ${loop.map((h) => 'h' + h).join(' ')}`);
    lines.push(...recordLines(s, el.halfedge, 'halfedge(f)'));
  } else if (el.kind === 'edge') {
    const r = s.record(el.halfedge);
    lines.push(`edge e${r.edge}: v${r.origin} - v${r.target}`);
    lines.push(...recordLines(s, el.halfedge, 'half-edge'));
    lines.push(...recordLines(s, r.twin, 'twin'));
  } else {
    const ring = s.oneRing(el.vertex);
    const p = s.position(el.vertex).map((x) => x.toFixed(3)).join(', ');
    lines.push(`vertex v${el.vertex}: (${p}), valence ${ring.length}`);
    lines.push(`  one-ring ${ring.slice(0, 12).map((v) => 'v' + v).join(' ')}${ring.length > 12 ? ' ...' : ''}`);
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
    const a = s.position(r.origin), b = s.position(r.target);
    const outside = [0, 1, 2].map((i) => a[i] + b[i] - inside[i]);
    state.viewer.addHalfedgeArrow(a, b, outside, color);
    return;
  }
  state.viewer.addHalfedgeArrow(s.position(r.origin), s.position(r.target), faceCentre(s, r.face), color);
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
    const a = points[i], b = points[(i + 1) % points.length];
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
  const same = (a, b) => a && b && a.kind === b.kind && a.face === b.face && a.halfedge === b.halfedge && a.vertex === b.vertex;
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
    if (moved > 4) return;  // an orbit, not a click
    guard('edit', () => clickEdit(elementAt(event)));
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
    button.addEventListener('click', () => guard(label, () => applyEdit(label, (s) => {
      s.subdivide(id);
      return label;
    })));
    buttons.appendChild(button);
  }
  $('smooth').addEventListener('click', () => guard('smooth', () => applyEdit('smooth', (s) => {
    s.smooth();
    return 'smooth (Taubin, 10 steps)';
  })));
  const ratio = $('decimate-ratio');
  const ratioLabel = () => {
    $('decimate-label').textContent = `${ratio.value}% of faces`;
  };
  ratio.addEventListener('input', ratioLabel);
  ratioLabel();
  $('decimate').addEventListener('click', () => guard('decimate', () => applyEdit('decimate', (s) => {
    const before = s.counts().faces;
    const target = Math.max(4, Math.round(before * Number(ratio.value) / 100));
    s.decimate(target);
    return `decimate to ${fmt(target)} faces`;
  })));
  $('pick-bench').addEventListener('click', () => guard('picking benchmark', async () => {
    $('stat-pick').textContent = 'measuring...';
    const report = await measurePicking(state.hedge, state.current, Number($('pick-size').value));
    $('stat-pick').textContent = report.text;
    document.body.dataset.pick = JSON.stringify(report);
  }));
}

async function main() {
  try {
    state.viewer = new Viewer($('canvas'));
  } catch (error) {
    showError(`WebGL is not available: ${messageOf(error)}`);
    return;
  }
  wireInput();
  try {
    state.hedge = await loadHedge();
  } catch (error) {
    showError(`The hedge WebAssembly module did not load (build it with bindings/wasm/build): ${messageOf(error)}`);
    return;
  }
  await guard('loading spot_triangulated.obj', () => loadSample('spot_triangulated.obj'));
  document.body.dataset.ready = '1';
}

// Read-only hooks for the end-to-end tests: where things are on screen, nothing that edits.
window.playground = {
  state,
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
      const a = s.position(r.origin), b = s.position(r.target);
      const mid = [0, 1, 2].map((i) => (a[i] + b[i]) / 2);
      const { x, y } = state.viewer.project(mid);
      const pa = state.viewer.project(a), pb = state.viewer.project(b);
      const length = Math.hypot(pa.x - pb.x, pa.y - pb.y);
      const el = elementAt({ clientX: x, clientY: y });
      if (el && el.kind === 'edge' && s.record(el.halfedge).edge === r.edge) out.push({ edge: r.edge, halfedge: h, x, y, length });
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
      const corners = s.faceHalfedges(f).map((h) => state.viewer.project(s.position(s.record(h).origin)));
      let area = 0;
      for (let i = 0; i < corners.length; ++i) {
        const p = corners[i], q = corners[(i + 1) % corners.length];
        area += (p.x * q.y - q.x * p.y) / 2;
      }
      if (!best || Math.abs(area) > best.area) best = { face: f, x, y, area: Math.abs(area) };
    }
    return best;
  },
};

main();
