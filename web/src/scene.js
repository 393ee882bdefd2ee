// The mesh on screen: adopting a loaded mesh, applying an edit and uploading the ranges it
// rewrote, and the stats panel (counts, validity, the last operation and upload), and what the
// file's reader warned about.
import { $, fmt, ms, state, clearError } from './page.js';

// The file the mesh on screen came from: {name, warnings, notes} (PageMesh.fileReport()).
const file = { name: '', warnings: [], notes: [] };

//! The name the mesh on screen was loaded under.
export function meshName() {
  return file.name;
}

function showStats() {
  const s = state.current;
  if (!s) return;
  const c = s.counts();
  $('stat-v').textContent = fmt(c.vertices);
  $('stat-e').textContent = fmt(c.edges);
  $('stat-f').textContent = fmt(c.faces);
  // validate() checks the half-edge structure, which loading makes consistent whatever the file
  // held: the file's warnings say what it had wrong, so a consistent structure built from a file
  // with warnings is not shown as plainly fine.
  const problems = s.problems();
  const valid = $('stat-valid');
  const warned = file.warnings.length > 0;
  if (problems.length > 0) {
    valid.textContent = `${problems.length} problem(s): ${problems[0]}`;
    valid.className = 'bad';
  } else {
    valid.textContent = warned
      ? 'half-edge structure valid; the file was not (see its warnings)'
      : 'half-edge structure valid';
    valid.className = warned ? 'warn' : 'ok';
  }
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

// The file's warnings next to its name, in the warning colour; its notes below in grey.
function showFileReport() {
  const list = $('mesh-warnings');
  list.replaceChildren(
    ...file.warnings.map((text) => {
      const item = document.createElement('li');
      item.textContent = text;
      return item;
    }),
  );
  list.hidden = file.warnings.length === 0;
  $('mesh-notes').textContent = file.notes.join('; ');
  document.body.dataset.fileWarnings = String(file.warnings.length);
}

// The sample menu shows what is loaded: its sample, else a disabled entry naming the mesh.
function showInSampleMenu(name) {
  const menu = $('sample');
  let fileEntry = menu.querySelector('option[data-file]');
  const sample = [...menu.options].find((o) => !o.dataset.file && o.value === name);
  if (sample) {
    if (fileEntry) fileEntry.remove();
    menu.value = sample.value;
    return;
  }
  if (!fileEntry) {
    fileEntry = document.createElement('option');
    fileEntry.dataset.file = '1';
    fileEntry.disabled = true;
    fileEntry.value = '';
    menu.prepend(fileEntry);
  }
  fileEntry.textContent = `loaded: ${name}`;
  menu.value = '';
}

// Replaces the current mesh by `next` (already loaded) and uploads it whole. `operation`: what made
// it, for the stats ('load NAME' by default); `sameFile`: it is a rebuild of the current mesh
// (triangulated), which keeps the file's name and warnings.
export function adopt(next, name, loadMs, { operation = `load ${name}`, sameFile = false } = {}) {
  const old = state.current;
  state.current = next;
  if (old) old.dispose();
  state.hover = null;
  state.viewer.clearOverlay();
  $('records').textContent = 'Hover the mesh.';
  if (!sameFile) Object.assign(file, { name, ...next.fileReport() });
  $('mesh-name').textContent = name;
  showFileReport();
  showInSampleMenu(name);
  // A picking measurement was of the mesh before.
  $('stat-pick').textContent = '-';
  delete document.body.dataset.pick;
  const before = state.viewer.meter.snapshot();
  const isEdge = next.edgeTest();
  const bytes = state.viewer.mesh.rebuild(next.mesh, next.render, isEdge);
  state.viewer.frame(next.boundingBox());
  state.viewer.render();
  state.lastUpload = { bytes, full: true, ranges: 1, gl: state.viewer.meter.since(before) };
  showUpload(state.lastUpload);
  showOperation(operation, loadMs);
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
