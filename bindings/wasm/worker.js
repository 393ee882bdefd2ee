// The worker side of hedge's worker helper (worker_client.js is the page side): loads hedge with
// loadHedge() inside a module worker (a browser's, or node's worker_threads), keeps the meshes it
// makes by id, runs the calls the page requests, and posts the results back. Every typed array of a
// result is a fresh copy out of wasm memory whose buffer goes in the transfer list: the page
// receives it without a second copy, and the worker's copy is detached.
//
// Protocol (one message each way per call): the page posts {call, op, args}; the worker answers
// {call, value} or {call, error: {kind, message, refusal}}, the error of a HedgeError (or of kind
// 'internal' for any other exception). A module worker whose entry is this file serves its own
// port; serveHedge(port) serves any other port (a MessagePort of a MessageChannel).
import { HedgeError, loadHedge } from './hedge.js';
import { isNode } from './load.js';

const WORKER_THREADS = 'node:worker_threads';

/** The calls the worker runs: op -> (worker, ...args) => value. Mesh ids are whole numbers. */
const OPS = {
  version: (w) => w.hedge.version,

  /** A mesh read from a file's bytes: {id, counts, report (buildReport())}. */
  load(w, bytes, name) {
    return w.adopt(w.hedge.fromFile(bytes, name), { report: true });
  },

  /** A mesh from index buffers (Hedge.fromBuffers's options): {id, counts}. */
  fromBuffers(w, arrays) {
    return w.adopt(w.hedge.fromBuffers(arrays));
  },

  counts: (w, id) => w.mesh(id).counts(),
  validate: (w, id) => w.mesh(id).validate(),

  subdivide(w, id, scheme, steps) {
    const mesh = w.mesh(id);
    mesh.subdivide(scheme, steps);
    return mesh.counts();
  },

  smooth(w, id, options) {
    const mesh = w.mesh(id);
    mesh.smooth(options);
    return mesh.counts();
  },

  decimate: (w, id, options) => w.mesh(id).decimate(options),

  /** Builds the mesh's picking tree (a pick builds it when it is missing): {seconds}. */
  buildPickingTree(w, id) {
    const mesh = w.mesh(id);
    const t0 = performance.now();
    mesh.pick([0, 0, 0], [0, 0, 1]);
    return { seconds: (performance.now() - t0) / 1000 };
  },

  pick: (w, id, origin, direction) => w.mesh(id).pick(origin, direction),
  pickMany: (w, id, rays) => w.mesh(id).pickMany(rays),

  /** Mesh.fracture(); each shard's mesh stays in the worker under a new id: {shards: [{id, faces,
   *  centroid, ..., hull}], impactFace, impactPoint, seconds}. */
  fracture(w, id, point, options) {
    const result = w.mesh(id).fracture(point, options);
    result.shards = result.shards.map((shard) => {
      const { mesh, ...values } = shard;
      return { id: w.keep(mesh), ...values };
    });
    return result;
  },

  /** Mesh.fractureSolid(); each piece's (or, for kind 'auto' on an open or non-manifold mesh, each
   *  shard's, with the refusal and its refusalCode) mesh stays in the worker under a new id:
   *  {kind, pieces: [{id, volume, ..., hull}], bonds, ...}. */
  fractureSolid(w, id, point, options) {
    const result = w.mesh(id).fractureSolid(point, options);
    const keep = ({ mesh, ...values }) => ({ id: w.keep(mesh), ...values });
    if (result.kind === 'solid') result.pieces = result.pieces.map(keep);
    else result.shards = result.shards.map(keep);
    return result;
  },

  /** Mesh.solidFractureRefusal(): why a solid strike would be refused, or null. */
  solidFractureRefusal: (w, id, point, options) => w.mesh(id).solidFractureRefusal(point, options),
  /** Mesh.solidFractureRefusalCode(): 'none', 'open', 'non_manifold' (kind 'auto' breaks these by
   *  surface fracture), 'off_surface', ... */
  solidFractureRefusalCode: (w, id, point, options) =>
    w.mesh(id).solidFractureRefusalCode(point, options),

  /** Draw buffers: {positions, indices, normals} (Float32Array, Uint32Array, Float32Array; normals
   *  empty for normals: 'none'), from a RenderBuffers made for the call. options.normals as
   *  createRenderBuffers's ('auto' by default; 'auto' draws corner normals if computed). */
  buffers(w, id, { normals = 'auto' } = {}) {
    const render = w.mesh(id).createRenderBuffers({
      normals,
      interleaved: false,
      texcoords: false,
      colors: false,
    });
    try {
      render.sync();
      // Copied before the RenderBuffers is freed (the views show its memory).
      const positions = render.vertices.slice();
      const indices = render.indices.slice();
      return { positions, indices, normals: render.normals.slice() };
    } finally {
      render.dispose();
    }
  },

  computeCornerNormals(w, id, creaseDegrees) {
    w.mesh(id).computeCornerNormals(creaseDegrees);
  },
  toArrays: (w, id, options) => w.mesh(id).toArrays(options),
  toFile: (w, id, name) => w.mesh(id).toFile(name),

  /** Frees the mesh (idempotent: an unknown id does nothing). */
  dispose(w, id) {
    const mesh = w.meshes.get(id);
    if (mesh) mesh.dispose();
    w.meshes.delete(id);
  },
};

/** The names of the calls, for the page side. */
export const workerCalls = Object.freeze(Object.keys(OPS));

/** The meshes of one served port, and the module. */
class Served {
  constructor(hedge) {
    this.hedge = hedge;
    this.meshes = new Map();
    this.nextId = 1;
  }

  keep(mesh) {
    const id = this.nextId++;
    this.meshes.set(id, mesh);
    return id;
  }

  adopt(mesh, { report = false } = {}) {
    const out = { id: this.keep(mesh), counts: mesh.counts() };
    if (report) out.report = mesh.buildReport();
    return out;
  }

  mesh(id) {
    const mesh = this.meshes.get(id);
    if (!mesh)
      throw new HedgeError('bad-handle', `worker: no mesh ${id} (disposed, or never made)`);
    return mesh;
  }
}

/** Copies every typed array of value that views wasm memory (which cannot be transferred, and
 *  which the next call may overwrite) and collects the buffers of all of them: [value, transfer]. */
export function detach(value, heap) {
  const transfer = new Set();
  const walk = (v) => {
    if (ArrayBuffer.isView(v)) {
      const own = v.buffer === heap ? v.slice() : v;
      transfer.add(own.buffer);
      return own;
    }
    if (Array.isArray(v)) return v.map(walk);
    if (v && typeof v === 'object') {
      for (const key of Object.keys(v)) v[key] = walk(v[key]);
    }
    return v;
  };
  const out = walk(value);
  return [out, [...transfer]];
}

function errorOf(e) {
  if (e instanceof HedgeError) return { kind: e.kind, message: e.message, refusal: e.refusal };
  return { kind: 'internal', message: `worker: ${e && e.message ? e.message : String(e)}` };
}

/** Serves hedge's calls on port (a worker's global scope, node's parentPort or a MessagePort):
 *  loads the module (loadHedge(options)) and answers each request. Returns the port's state, whose
 *  meshes map holds the live meshes by id. */
export function serveHedge(port, options = {}) {
  const loading = loadHedge(options).then((hedge) => new Served(hedge));
  const answer = async ({ call, op, args }) => {
    let reply;
    let transfer = [];
    try {
      const served = await loading;
      if (!Object.hasOwn(OPS, op))
        throw new HedgeError('invalid-argument', `worker: unknown call '${op}'`);
      const value = OPS[op](served, ...(Array.isArray(args) ? args : []));
      [reply, transfer] = detach({ call, value }, served.hedge.module.HEAPU8.buffer);
    } catch (e) {
      reply = { call, error: errorOf(e) };
    }
    try {
      port.postMessage(reply, transfer);
    } catch (e) {
      port.postMessage({ call, error: errorOf(e) });
    }
  };
  const listener = (event) => answer(event.data);
  port.addEventListener('message', listener);
  if (typeof port.start === 'function') port.start();
  return { loading, close: () => port.removeEventListener('message', listener) };
}

// The worker's own port: self in a browser's module worker (served at once, before any message can
// arrive), parentPort in a node worker (whose port holds messages until served). No top-level
// await: bundlers' default targets refuse it.
if (typeof WorkerGlobalScope !== 'undefined' && globalThis instanceof WorkerGlobalScope) {
  serveHedge(globalThis);
} else if (isNode()) {
  import(/* webpackIgnore: true */ /* @vite-ignore */ WORKER_THREADS).then((threads) => {
    if (!threads.isMainThread && threads.parentPort) serveHedge(threads.parentPort);
  });
}
