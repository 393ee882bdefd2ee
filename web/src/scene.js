// The mesh on screen: adopting a loaded mesh, applying an edit and uploading the ranges it
// rewrote, and the stats panel (counts, validity, the last operation and upload).
import { $, fmt, ms, state, clearError } from './page.js';

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

//! The last operation and its time; `syncMs`: the RenderBuffers sync and the buffer copies after it.
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

// Replaces the current mesh by `next` (already loaded) and uploads it whole.
export function adopt(next, name, loadMs) {
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
  const bytes = state.viewer.mesh.rebuild(next.mesh, next.render, isEdge);
  state.viewer.frame(next.boundingBox());
  state.viewer.render();
  state.lastUpload = { bytes, full: true, ranges: 1, gl: state.viewer.meter.since(before) };
  showUpload(state.lastUpload);
  showOperation(`load ${name}`, loadMs);
  showStats();
  document.body.dataset.mesh = name;
}

// Runs `edit` (which returns a short description, or throws), syncs RenderBuffers and uploads the
// rewritten ranges. The frame right after the edit is rendered here, with the overlays hidden, so
// that the upload meter counts this edit's buffers alone.
export function applyEdit(name, edit) {
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
  const upload = viewer.mesh.update(s.render, result, isEdge);
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
