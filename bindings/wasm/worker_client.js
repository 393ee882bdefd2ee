// The page side of hedge's worker helper (worker.js is the worker side): runs hedge's heavy calls
// (loading a file, subdividing, decimating, building the picking tree, fracturing) in a module
// worker, so the page keeps answering while they run.
//
//   import { createHedgeWorker } from 'hedge-mesh/worker';
//   const remote = await createHedgeWorker();
//   const { id } = await remote.load(bytes, 'bunny.obj');
//   await remote.subdivide(id, 'loop', 2);
//   const { positions, indices, normals } = await remote.buffers(id);   // transferred, not copied
//
// Meshes stay in the worker, named by id; each method returns a promise of the call's result, in
// which every typed array was transferred from the worker (no copy on the way back). A failure
// rejects with a HedgeError of the worker's kind and message, as the same call on the page throws.
import { HedgeError } from './hedge.js';
import { isNode } from './load.js';

const WORKER_THREADS = 'node:worker_threads';
const WORKER_FILE = './worker.js';

// The calls of worker.js (its OPS), each a method of HedgeWorker taking the same arguments.
const CALLS = [
  'version',
  'load',
  'fromBuffers',
  'counts',
  'validate',
  'subdivide',
  'smooth',
  'decimate',
  'buildPickingTree',
  'pick',
  'pickMany',
  'fracture',
  'fractureSolid',
  'solidFractureRefusal',
  'solidFractureRefusalCode',
  'buffers',
  'computeCornerNormals',
  'toArrays',
  'toFile',
  'dispose',
];

/** Starts worker.js in a module worker (a browser's Worker, or node's worker_threads) and resolves
 *  once hedge is loaded in it. options.worker: a worker (or MessagePort) already started on
 *  worker.js, for bundlers that need to see `new Worker(new URL(...), {type: 'module'})` in your
 *  own code. A module that fails to load rejects with its error. */
export async function createHedgeWorker({ worker } = {}) {
  const port = worker ?? (await startWorker());
  const remote = new HedgeWorker(port);
  try {
    await remote.version();
  } catch (e) {
    remote.terminate();
    throw e;
  }
  return remote;
}

// In a browser, the literal `new Worker(new URL('./worker.js', import.meta.url), ...)` is the form
// that vite (and, by its documentation, webpack 5) recognises: worker.js is bundled with hedge as a
// worker of its own. Under
// node the file's name is held in a variable, so that bundlers do not copy it a second time.
async function startWorker() {
  if (!isNode()) return new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
  const threads = await import(/* webpackIgnore: true */ /* @vite-ignore */ WORKER_THREADS);
  return new threads.Worker(new URL(/* webpackIgnore: true */ WORKER_FILE, import.meta.url));
}

/** hedge in a worker: one promise-returning method per call of worker.js. */
export class HedgeWorker {
  /** @param port a Worker or MessagePort serving worker.js's protocol. */
  constructor(port) {
    this.port = port;
    this._pending = new Map();
    this._next = 1;
    this._terminated = false;
    const receive = (data) => {
      const pending = this._pending.get(data.call);
      if (!pending) return;
      this._pending.delete(data.call);
      if (data.error) {
        const { kind, message, refusal = null } = data.error;
        pending.reject(new HedgeError(kind, message, refusal));
      } else {
        pending.resolve(data.value);
      }
    };
    const fail = (error) => {
      const e = new HedgeError('internal', `hedge worker: ${error?.message ?? 'failed'}`);
      for (const pending of this._pending.values()) pending.reject(e);
      this._pending.clear();
    };
    if (typeof port.addEventListener === 'function') {
      port.addEventListener('message', (event) => receive(event.data));
      port.addEventListener('error', (event) => fail(event.error ?? event));
      if (typeof port.start === 'function') port.start();
    } else {
      // node's worker_threads Worker: an EventEmitter.
      port.on('message', receive);
      port.on('error', fail);
      port.on('exit', (code) => fail(new Error(`the worker exited (code ${code})`)));
    }
  }

  /** Runs op(...args) in the worker. args and the result are structured-cloned; typed arrays of
   *  args are copied, unless their buffers are listed in transfer (they are then detached here). */
  call(op, args = [], transfer = []) {
    if (this._terminated)
      return Promise.reject(new HedgeError('bad-handle', `${op}: the hedge worker was terminated`));
    const call = this._next++;
    return new Promise((resolve, reject) => {
      this._pending.set(call, { resolve, reject });
      try {
        this.port.postMessage({ call, op, args }, transfer);
      } catch (e) {
        this._pending.delete(call);
        reject(new HedgeError('invalid-argument', `${op}: ${e.message}`));
      }
    });
  }

  /** Reads a mesh from a file's bytes (Uint8Array or ArrayBuffer) in the worker: {id, counts,
   *  report}. transfer: true hands the bytes' buffer over instead of copying it (it is detached). */
  load(bytes, name, { transfer = false } = {}) {
    const buffer = bytes instanceof ArrayBuffer ? bytes : bytes?.buffer;
    return this.call('load', [bytes, name], transfer && buffer ? [buffer] : []);
  }

  /** Stops the worker; calls still waiting reject. */
  terminate() {
    this._terminated = true;
    for (const pending of this._pending.values())
      pending.reject(new HedgeError('bad-handle', 'hedge worker: terminated'));
    this._pending.clear();
    if (typeof this.port.terminate === 'function') this.port.terminate();
    else if (typeof this.port.close === 'function') this.port.close();
  }
}

for (const op of CALLS) {
  if (op in HedgeWorker.prototype) continue;
  HedgeWorker.prototype[op] = function (...args) {
    return this.call(op, args);
  };
}
