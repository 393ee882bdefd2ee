// The playground: loads meshes with hedge (WebAssembly), draws them with three.js, shows the
// half-edge records under the cursor and edits the mesh, updating the GPU buffers range by range.
// This file loads meshes and wires the page; showing a mesh and applying an edit are in scene.js,
// the hover and its overlays in inspect.js, the break scene in break_mode.js.
import { Viewer } from './viewer.js';
import { loadHedge, PageMesh, SUBDIVISION_SCHEMES } from './page_mesh.js';
import { measurePicking } from './picking_bench.js';
import {
  DECIMATE_IN_WORKER_FACES,
  LOAD_IN_WORKER_BYTES,
  decimateInWorker,
  loadInWorker,
} from './heavy.js';
import { $, fmt, state, showError, clearError, messageOf, guard, offerRemedy } from './page.js';
import { adopt, applyEdit, meshName } from './scene.js';
import { elementAt, faceCentre, drawHover, setHover } from './inspect.js';
import {
  createBreakWorld,
  leaveBreak,
  strikeAt,
  wireBreakInput,
  breakHooks,
} from './break_mode.js';

// ---- loading ------------------------------------------------------------------------------------

// A large file is read in the worker (heavy.js), so the page keeps drawing meanwhile.
async function loadBytes(bytes, name) {
  leaveBreak();
  const inWorker = bytes.length >= LOAD_IN_WORKER_BYTES;
  const t0 = performance.now();
  const loaded = inWorker
    ? await loadInWorker(state.hedge, bytes, name)
    : PageMesh.load(state.hedge, bytes, name);
  const loadMs = performance.now() - t0;
  clearError();
  adopt(loaded, name, loadMs, {
    operation: `load ${name}${inWorker ? ' (read in a worker)' : ''}`,
  });
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

// ---- edit ---------------------------------------------------------------------------------------

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

// Replaces a polygon mesh by its triangulation (PageMesh.triangulated()): the way out of the
// refusals of Loop, sqrt(3) and decimate, which need triangles.
function triangulate() {
  const s = state.current;
  if (!s) throw new Error('no mesh loaded');
  const name = meshName();
  if (s.mesh.isTriangleMesh()) {
    $('stat-op').textContent = 'triangulate: the mesh has triangles only already';
    return;
  }
  leaveBreak();
  const before = s.counts().faces;
  const t0 = performance.now();
  const next = s.triangulated();
  const opMs = performance.now() - t0;
  clearError();
  const after = next.counts().faces;
  adopt(next, name, opMs, {
    operation: `triangulate: ${fmt(before)} faces into ${fmt(after)} triangles`,
    sameFile: true,
  });
  document.body.dataset.edits = String(Number(document.body.dataset.edits || 0) + 1);
}

// Decimates to `percent` of the faces: a large triangle mesh in the worker (heavy.js), whose result
// replaces the mesh on screen; else on the page, as an edit with a partial upload.
async function decimate(percent) {
  const s = state.current;
  if (!s) throw new Error('no mesh loaded');
  const before = s.counts().faces;
  const target = Math.max(4, Math.round((before * percent) / 100));
  const operation = `decimate to ${fmt(target)} faces`;
  if (before < DECIMATE_IN_WORKER_FACES || !s.mesh.isTriangleMesh()) {
    applyEdit('decimate', (m) => {
      m.decimate(target);
      return operation;
    });
    return;
  }
  const t0 = performance.now();
  const next = await decimateInWorker(s, target);
  const opMs = performance.now() - t0;
  leaveBreak();
  clearError();
  adopt(next, meshName(), opMs, { operation: `${operation} (in a worker)`, sameFile: true });
  document.body.dataset.edits = String(Number(document.body.dataset.edits || 0) + 1);
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
    if (!name) return; // the entry naming a loaded file
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
  $('triangulate').addEventListener('click', () => guard('triangulate', triangulate));
  offerRemedy((message) =>
    /triangulate first/.test(message) && state.current && !state.current.mesh.isTriangleMesh()
      ? { label: 'Triangulate', run: () => guard('triangulate', triangulate) }
      : null,
  );
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
    guard('decimate', () => decimate(Number(ratio.value))),
  );
  wireBreakInput();
  $('pick-bench').addEventListener('click', () =>
    guard('picking benchmark', async () => {
      $('stat-pick').textContent = 'measuring...';
      const report = await measurePicking(state.current, Number($('pick-size').value));
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
  createBreakWorld(state.viewer);
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
  ...breakHooks,
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
