// The heavy calls the page hands to hedge's worker helper (hedge/worker), so that it keeps drawing
// and answering while they run: reading a large file, and decimating a large mesh. The mesh the
// page shows and edits stays on the page (its edits, partial uploads and hover read it there), so
// the worker's result comes back as arrays, transferred, and is rebuilt on the page with
// fromBuffers, which costs a small part of the call it replaces. Measured under node on spot after
// 3 Loop steps (374,784 triangles): reading its 26 MB OBJ takes 1.6-1.8 s, rebuilding it from
// arrays 75-80 ms (its 7 MB binary PLY: 165-390 ms against 50 ms); decimating it to a quarter
// 876 ms, rebuilding the result 26 ms. Subdivision stays on the page: its result is four times the
// mesh, and rebuilding that (354 ms) costs more than subdividing on the page (250 ms).
// Small files and meshes stay on the page too, where they take less than a round trip's worth.
import { createHedgeWorker } from 'hedge/worker';
import { PageMesh } from './page_mesh.js';

//! Files of at least this many bytes are read in the worker (a 1 MB OBJ takes about 65 ms).
export const LOAD_IN_WORKER_BYTES = 1 << 20;
//! Triangle meshes of at least this many faces are decimated in the worker (about 70 ms).
export const DECIMATE_IN_WORKER_FACES = 20000;

// The worker, started on first use (again after a failed start).
let remote = null;
export function worker() {
  if (!remote)
    remote = createHedgeWorker().catch((error) => {
      remote = null;
      throw error;
    });
  return remote;
}

// Runs `work(w, id)` on mesh `id` of the worker, then brings the mesh back as arrays (transferred)
// and frees it there, whatever happened.
async function takeBack(w, id, work) {
  try {
    const value = await work();
    const arrays = await w.toArrays(id);
    return { value, arrays };
  } finally {
    w.dispose(id).catch(() => {});
  }
}

//! Reads a file's bytes in the worker and rebuilds the mesh on the page, keeping the reader's
//! report (warnings, repairs). The bytes are handed over (their buffer is detached). A malformed
//! file rejects with hedge's message, as PageMesh.load() throws it.
export async function loadInWorker(hedge, bytes, name) {
  if (bytes.length === 0) throw new Error(`${name}: the file is empty`);
  const w = await worker();
  const { id, report } = await w.load(bytes, name, { transfer: true });
  const { arrays } = await takeBack(w, id, async () => null);
  return PageMesh.fromBuffers(hedge, { ...arrays, weld: 'none' }, { report });
}

//! Decimates a copy of the page's mesh `s` in the worker to `targetFaces` and returns the result
//! rebuilt on the page (a new PageMesh; `s` is left as it was).
export async function decimateInWorker(s, targetFaces) {
  const w = await worker();
  const { positions, indices, faceSizes } = s.mesh.toArrays();
  const sent = { positions, indices, weld: 'none' };
  if (faceSizes) sent.faceSizes = faceSizes;
  const transfer = [positions.buffer, indices.buffer, ...(faceSizes ? [faceSizes.buffer] : [])];
  const { id } = await w.call('fromBuffers', [sent], transfer);
  const { arrays } = await takeBack(w, id, () => w.decimate(id, { targetFaces }));
  return PageMesh.fromBuffers(s.hedge, { ...arrays, weld: 'none' });
}
