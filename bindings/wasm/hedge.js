// hedge in JavaScript: the public API over the WebAssembly module (hedge.mjs + hedge.wasm).
//
//   import { loadHedge } from './hedge.js';
//   const hedge = await loadHedge();
//   const mesh = hedge.fromBuffers({ positions, indices });
//
// Elements are numbers: vertex, half-edge, edge and face indices; -1 means "none". Half-edge h
// belongs to edge h >> 1 and its twin is h ^ 1. Every failure throws a HedgeError whose message is
// hedge's own (the file and line of a malformed file, why an operation was refused). Wrong
// arguments (null, a wrong type, an array of the wrong length) throw one of kind 'invalid-argument'
// naming the call and the argument, before the call runs (arguments.js).
//
// Memory: a Mesh or RenderBuffers frees its wasm memory when it is garbage-collected, and dispose() frees
// it at once (calling it again does nothing; any other call on a disposed object throws). A
// RenderBuffers shares its mesh: the mesh's memory is freed when the mesh and every RenderBuffers
// made from it are disposed (or collected). Disposing a mesh first frees nothing yet; with
// hedge.warnings on (the default unless NODE_ENV is 'production') it logs a console warning then.
//
// Views: positions, render buffers and the like are typed arrays over wasm memory, not copies. A
// view stays valid until the next call that edits the mesh or syncs its RenderBuffers (which may move the
// buffer) or until wasm memory grows (any call that allocates may grow it; the old views then
// have length 0). Take views right before use; taking one costs no copy.
import createHedge from './hedge.mjs';

import { instantiate } from './load.js';
import { installArgumentChecks, point3, UNITS } from './arguments.js';
import { HedgeError, NativeOwner } from './native.js';
import { RenderBuffers } from './render_buffers.js';
import { fractureMaterials, materialArguments, Shard, unpackShards } from './fracture.js';
import { Piece, solidOptions, unpackSolidResult } from './fracture_solid.js';

export { fractureMaterials, HedgeError, Piece, RenderBuffers, Shard };

const SCHEMES = ['loop', 'midpoint', 'catmull-clark', 'sqrt3', 'split-faces'];
const METHODS = ['uniform', 'taubin', 'cotangent', 'implicit'];
/** Subdivision schemes and smoothing methods, for menus. */
export const subdivisionSchemes = Object.freeze([...SCHEMES]);
export const smoothingMethods = Object.freeze([...METHODS]);

/** Loads the module, in node, a browser page, a module worker or a bundle (load.js); sets no
 *  globals. options go to the emscripten factory: wasmBinary (the bytes of hedge.wasm) or
 *  locateFile(name) (where to fetch it from; under node, a path or a file: URL to read). */
export async function loadHedge(options = {}) {
  const module = await instantiate(createHedge, options);
  return new Hedge(module);
}

// Development builds: NODE_ENV is not 'production' (bundlers write it into the code; a page
// without a bundler has no process, and counts as development).
function developmentBuild() {
  try {
    // eslint-disable-next-line no-undef
    return process.env.NODE_ENV !== 'production';
  } catch {
    return true;
  }
}

/** The loaded module: makes meshes and reports memory. */
export class Hedge {
  /** @param module the emscripten module (from createHedge). */
  constructor(module) {
    this.module = module;
    /** Log console warnings of misuse that costs memory (a mesh disposed under a live
     *  RenderBuffers). On by default in development builds; set false to silence them. */
    this.warnings = developmentBuild();
    this._errorSlot = module.errorSlotAddress() >> 2;
    this._pick = module.pickScratchAddress() >> 3;
  }

  /** Throws the error the last native call recorded, deleting `result` if it is a native object. */
  _check(result) {
    const M = this.module;
    if (M.HEAP32[this._errorSlot] !== 0) {
      const kind = M.errorKind(M.HEAP32[this._errorSlot + 1]);
      const message = M.takeErrorMessage();
      const refusal = M.takeRefusal();
      if (result && typeof result.delete === 'function' && !result.isDeleted()) result.delete();
      throw new HedgeError(kind, message, refusal === '' ? null : refusal);
    }
    return result;
  }

  /** Builds a mesh from index buffers.
   *  positions: Float32Array, 3 per vertex. indices: Uint32Array, the corners of all faces.
   *  faceSizes: Uint32Array of corners per face, or omitted for triangles.
   *  policy: 'repair' (default: split non-manifold input, drop degenerate faces) or 'strict'
   *  (throw). weld: 'none' (default), 'exact' or 'epsilon'. */
  fromBuffers({ positions, indices, faceSizes, policy = 'repair', weld = 'none' }) {
    const p = { strict: 0, repair: 1 }[policy];
    const w = { none: 0, exact: 1, epsilon: 2 }[weld];
    if (p === undefined)
      throw new HedgeError('invalid-argument', `unknown policy '${policy}' (strict, repair)`);
    if (w === undefined)
      throw new HedgeError('invalid-argument', `unknown weld '${weld}' (none, exact, epsilon)`);
    const native = this._check(
      this.module.NativeMesh.fromBuffers(positions, indices, faceSizes, p, w),
    );
    return new Mesh(this, native);
  }

  /** Builds a mesh from an engine's arrays, one attribute set per vertex (a three.js
   *  BufferGeometry, a glTF primitive): positions are welded into topological vertices (weld:
   *  'exact' by default, 'epsilon' or 'none') while normals, texcoords and colours stay per corner,
   *  so seams and hard edges survive, and the RenderBuffers of the mesh gives them back.
   *  positions: Float32Array, 3 per vertex. indices: Uint32Array, 3 per triangle. Optional, one
   *  entry per vertex: normals (3 floats), texcoords (2), colors (4: r, g, b, a). submeshes:
   *  optional, one id in [0, 65535] per triangle (a material; the face property "f:submesh", which
   *  edits keep and RenderBuffers groups the index buffer by). policy as for fromBuffers. A bad
   *  stream (wrong length, a non-finite value, an index out of range, a submesh id out of range)
   *  throws a HedgeError naming the stream and the entry; no mesh is made then. */
  fromEngineStreams({
    positions,
    indices,
    normals,
    texcoords,
    colors,
    submeshes,
    policy = 'repair',
    weld = 'exact',
  }) {
    const p = { strict: 0, repair: 1 }[policy];
    const w = { none: 0, exact: 1, epsilon: 2 }[weld];
    if (p === undefined)
      throw new HedgeError(
        'invalid-argument',
        `fromEngineStreams: unknown policy '${policy}' (strict, repair)`,
      );
    if (w === undefined)
      throw new HedgeError(
        'invalid-argument',
        `fromEngineStreams: unknown weld '${weld}' (none, exact, epsilon)`,
      );
    const native = this._check(
      this.module.meshFromEngineStreams(
        positions,
        indices,
        normals,
        texcoords,
        colors,
        submeshes,
        p,
        w,
      ),
    );
    return new Mesh(this, native);
  }

  /** Builds a mesh from a file's bytes (Uint8Array or ArrayBuffer), read by hedge's reader for the
   *  format of name's extension (.obj, .off, .ply, .stl, and the others the library reads), with
   *  the file defaults: repair policy, exact welding for STL. A malformed file throws a
   *  HedgeError of kind 'io' naming the file and the line (or byte offset). */
  fromFile(bytes, name) {
    const data = bytes instanceof ArrayBuffer ? new Uint8Array(bytes) : bytes;
    const native = this._check(this.module.NativeMesh.fromFile(data, name));
    return new Mesh(this, native);
  }

  /** The library's thread setting (hedge::set_max_threads). The WebAssembly module is built
   *  without threads: every call runs on the calling thread, whatever is set. setMaxThreads accepts
   *  any whole number >= 0 (0: every core) and maxThreads() reports 1. */
  // n is checked by the argument check (ARGUMENTS below); there is nothing else to do.
  // eslint-disable-next-line no-unused-vars
  setMaxThreads(n) {}

  maxThreads() {
    return 1;
  }

  /** Bytes of wasm heap in use by the allocator (what a leak makes grow). */
  heapBytesInUse() {
    return this.module.heapBytesInUse();
  }

  /** Size of wasm memory in bytes (it grows, never shrinks). */
  get memoryBytes() {
    return this.module.HEAP8.length;
  }

  get version() {
    return this.module.version();
  }
}

/** A half-edge mesh in wasm memory. dispose() frees it now, unless a RenderBuffers made from it is
 *  live: that one shares the mesh and keeps working, and the mesh's memory is freed with the last
 *  of them (hedge.warnings: a console warning says so). */
export class Mesh extends NativeOwner {
  constructor(hedge, native) {
    super(hedge, native, 'mesh');
    // The RenderBuffers made from this mesh, held weakly: they may be collected before it.
    this._renders = [];
  }

  /** Frees the mesh now; while a RenderBuffers made from it is live, only this handle (the memory
   *  goes with the last RenderBuffers). Idempotent. */
  dispose() {
    if (!this.disposed && this.hedge.warnings) {
      const live = this._renders.filter((ref) => {
        const render = ref.deref();
        return render !== undefined && !render.disposed;
      }).length;
      if (live > 0)
        console.warn(
          `hedge: Mesh.dispose() with ${live} live RenderBuffers made from it frees none of the ` +
            "mesh's memory: the RenderBuffers share the mesh, which is freed with the last of " +
            'them. Dispose the RenderBuffers too (first, or together with the mesh).',
        );
    }
    this._renders = [];
    super.dispose();
  }

  /** An independent copy. */
  clone() {
    return new Mesh(this.hedge, this._call('clone'));
  }

  /** What building repaired: {repairs, weldedVertices, degenerateFaces, ..., warnings}. */
  buildReport() {
    return this._call('buildReport');
  }

  // ---- Queries ----

  /** {vertices, edges, halfedges, faces} (live elements) and the slot counts
   *  {vertexSlots, halfedgeSlots, edgeSlots, faceSlots} (indices run below them). */
  counts() {
    return this._call('counts');
  }

  /** Every broken invariant, one message each; [] for a valid mesh. */
  validate() {
    return this._call('validate');
  }

  isValid() {
    return this.validate().length === 0;
  }

  isTriangleMesh() {
    return this._call('isTriangleMesh');
  }

  /** Float32Array view of the positions, 3 per vertex slot (deleted slots included). No copy; see
   *  the note on views at the top of this file. */
  get positions() {
    return this._call('positionsView');
  }

  /** [x, y, z] of vertex v. */
  position(v) {
    return this._call('position', v);
  }

  setPosition(v, point) {
    this._call('setPosition', v, point3(point));
  }

  /** The records of half-edge h: {halfedge, origin, target, twin, face, next, prev, edge, boundary}
   *  (face -1 on a boundary half-edge). */
  halfedge(h) {
    return this._call('halfedge', h);
  }

  /** {vertex, halfedge (outgoing), position, valence, boundary, isolated}. */
  vertex(v) {
    return this._call('vertex', v);
  }

  /** {edge, halfedges: [h0, h1], vertices: [a, b], faces: [f0, f1] (-1 on the boundary side), boundary}. */
  edge(e) {
    return this._call('edge', e);
  }

  /** The half-edges of face f in order, with their target vertices, edges and the faces across:
   *  {face, halfedge, halfedges, vertices, edges, faces (-1 on the boundary), boundary}. */
  face(f) {
    return this._call('face', f);
  }

  /** The one-ring of v, clockwise: {vertex, halfedges (outgoing), vertices, edges, faces (-1 across a
   *  boundary gap)}. */
  oneRing(v) {
    return this._call('oneRing', v);
  }

  /** The face, edge and vertex under a ray: null if it misses, else {face, t, point,
   *  halfedge (of the face, nearest the hit point), edge, vertex (nearest corner), edgeDistance,
   *  vertexDistance, corners (of the fan triangle hit), barycentric}. A bounding volume hierarchy
   *  is built on the first call and kept up to date with edits. */
  pick(origin, direction) {
    // The hot path of hovering: no argument arrays are made (a NaN coordinate finds nothing).
    const native = this._n();
    const face = native.pick(
      +origin[0],
      +origin[1],
      +origin[2],
      +direction[0],
      +direction[1],
      +direction[2],
    );
    this.hedge._check(face);
    if (face < 0) return null;
    const f = this.hedge.module.HEAPF64;
    const k = this.hedge._pick;
    return {
      face: f[k],
      t: f[k + 1],
      point: [f[k + 2], f[k + 3], f[k + 4]],
      halfedge: f[k + 5],
      edge: f[k + 6],
      vertex: f[k + 7],
      edgeDistance: f[k + 8],
      vertexDistance: f[k + 9],
      corners: [f[k + 10], f[k + 11], f[k + 12]],
      barycentric: [f[k + 13], f[k + 14], f[k + 15]],
    };
  }

  /** Casts many rays at once. rays: Float32Array of 6 per ray (origin, direction). Returns an
   *  Int32Array of the face hit by each ray, -1 for a miss (written into `out` if given). */
  pickMany(rays, out = new Int32Array(rays.length / 6)) {
    this._call('pickMany', rays, out);
    return out;
  }

  // ---- Local operations. Each checks its elements (a HedgeError of kind 'bad-handle' for one out
  // of range or deleted), then the library's refusal: a refused edit throws a HedgeError of kind
  // 'refused' whose refusal says why, and leaves the mesh unchanged. lastRefusal keeps that reason
  // until the next edit is done. ----

  /** Why the last refused edit on this mesh was refused (the library's reason, as HedgeError's
   *  refusal), or after a predicate (canFlip, ...) that answered false, why its edit would be; null
   *  after an edit that was done or a predicate that answered true, or before any. */
  lastRefusal = null;

  /** null if edit ('splitEdge', 'flip', 'collapse', 'splitFace' (one element each), 'cutFace' (two
   *  half-edges), 'fillHole' (a half-edge)) is allowed on the elements, else the library's refusal
   *  in words ("the edge is on the boundary (...)", "the edge is not live", ...). */
  refusal(edit, ...elements) {
    const reason = this._call('refusal', edit, elements);
    return reason === '' ? null : reason;
  }

  /** @deprecated since 0.2: use refusal(op, element), which it calls; kept for one release. */
  whyNot(op, element) {
    return this.refusal(op, element);
  }

  // The predicates (canFlip, ...): true if the edit is allowed; each also sets lastRefusal, to why
  // that edit would be refused or null, so the reason read after a predicate is always its own (as
  // C's hedge_last_refusal() and C#'s LastRefusal after a predicate).
  canSplitEdge(e) {
    return this._allowed('splitEdge', e);
  }
  canFlip(e) {
    return this._allowed('flip', e);
  }
  canCollapse(h) {
    return this._allowed('collapse', h);
  }
  canSplitFace(f) {
    return this._allowed('splitFace', f);
  }
  canCutFace(h0, h1) {
    return this._allowed('cutFace', h0, h1);
  }
  canFillHole(h) {
    return this._allowed('fillHole', h);
  }

  _allowed(edit, ...elements) {
    this.lastRefusal = this.refusal(edit, ...elements);
    return this.lastRefusal === null;
  }

  /** Runs an edit, keeping lastRefusal. */
  _edit(name, ...args) {
    try {
      const result = this._call(name, ...args);
      this.lastRefusal = null;
      return result;
    } catch (e) {
      if (e instanceof HedgeError && e.kind === 'refused') this.lastRefusal = e.refusal;
      throw e;
    }
  }

  /** Inserts a vertex on edge e at point (default: the midpoint); triangles beside it are split in
   *  two. Returns the new vertex. */
  splitEdge(e, point) {
    return this._edit('splitEdge', e, point === undefined ? undefined : point3(point));
  }

  /** Turns edge e between its two triangles. Returns e. */
  flip(e) {
    return this._edit('flip', e);
  }

  /** Merges the origin of half-edge h into its target, which survives and moves to point if given
   *  (e.g. the midpoint). Returns the surviving vertex. */
  collapse(h, point) {
    return this._edit('collapse', h, point === undefined ? undefined : point3(point));
  }

  /** Inserts a vertex into face f at point (default: its centroid), fanning the face into
   *  triangles. Returns the new vertex. */
  splitFace(f, point) {
    return this._edit('splitFace', f, point === undefined ? undefined : point3(point));
  }

  /** Cuts the face of half-edges h0 and h1 in two along a new edge from the target of h0 to the
   *  target of h1. Returns the new half-edge (from the target of h0). */
  cutFace(h0, h1) {
    return this._edit('cutFace', h0, h1);
  }

  /** Fills the hole whose boundary loop holds half-edge h (a boundary half-edge) with triangles.
   *  Returns the new faces. */
  fillHole(h) {
    return this._edit('fillHole', h);
  }

  /** Removes deleted elements, renumbering every element. */
  garbageCollection() {
    this._call('garbageCollection');
  }

  // ---- Algorithms ----

  /** scheme: 'loop', 'midpoint', 'catmull-clark', 'sqrt3' or 'split-faces'. Renumbers elements. */
  subdivide(scheme = 'loop', steps = 1) {
    this._call('subdivide', scheme, steps);
  }

  /** method: 'uniform', 'taubin', 'cotangent' or 'implicit'. */
  smooth({
    method = 'uniform',
    iterations = 10,
    lambda = 0.5,
    mu = -0.53,
    fixBoundary = true,
  } = {}) {
    this._call('smooth', method, iterations, lambda, mu, fixBoundary);
  }

  /** Corner normals (the half-edge property "h:normal"): smooth across edges where the faces meet
   *  at less than creaseDegrees (0..180; 0 flat, 180 smooth), hard edges elsewhere, as CAD models
   *  need. A RenderBuffers made afterwards with normals 'auto' draws them and keeps them up around
   *  each edit (an existing one shows them after rebuild()). */
  computeCornerNormals(creaseDegrees = 45) {
    this._call('computeCornerNormals', creaseDegrees);
  }

  /** Quadric edge-collapse decimation of a triangle mesh. ratio: the fraction of faces to keep
   *  (or targetFaces / targetVertices as counts); maxError: stop before a collapse moving the
   *  surface further than this; relaxNormalChange (true): should the 60-degree normal limit alone
   *  stop the run short of its target, raise it to 90 for the rest (false: it holds to the end).
   *  Renumbers elements. Returns {vertices, faces, collapses, maxError, stop, refused}: stop says
   *  why the run ended ('target_reached', 'error_bound' or 'no_legal_collapse'), refused counts
   *  the collapse attempts each check refused ({topology, normal, shape}; an edge retried in a
   *  later pass counts again). */
  decimate({
    ratio,
    targetFaces = 0,
    targetVertices = 0,
    maxError = -1,
    relaxNormalChange = true,
  } = {}) {
    if (ratio !== undefined) {
      if (!(ratio > 0 && ratio <= 1))
        throw new HedgeError('invalid-argument', `decimate: ratio ${ratio} is not in (0, 1]`);
      targetFaces = Math.max(1, Math.round(ratio * this.counts().faces));
    }
    return this._call(
      'decimate',
      targetFaces,
      targetVertices,
      maxError,
      Boolean(relaxNormalChange),
    );
  }

  // ---- Fracture ----

  /** Breaks the mesh at `impact` ([x, y, z], within the tolerance of the surface) into shards; the
   *  mesh is edited in place (the broken faces leave it) and its RenderBuffers syncs the change as a few
   *  ranges. material: 'glass', 'stone', 'wood', 'ice' or {name, rings: [{points, spacing,
   *  jitter}], grain, grainStretch, refineEdge, units, radius} (docs/fracture.md). seed: a whole
   *  number (the same seed, mesh and impact give the same shards). The break radius (the outer
   *  ring's) is the material's radius in its units: for the presets a fraction of the mesh's
   *  bounding-box diagonal (glass 0.13, stone 0.14, wood and ice 0.11), so the same share of an
   *  object breaks at any resolution. units ('diagonal_fraction', 'model', 'edge_lengths') and
   *  radius > 0 replace the material's; breakRadius > 0 sets it in model units instead (0: as
   *  above). thickness > 0 makes each shard a closed solid, with mass properties at `density`;
   *  open shards weigh as a thin shell shellThickness thick (model units; 0: a twentieth of the
   *  break radius). Uses the picking tree (built if missing), so an impact costs what the broken
   *  area does. Returns {shards: [Shard], impactFace, impactPoint, breakRadius (model units),
   *  seconds: {locate, scatter, cut, detach, hulls, fracture (the whole library call), pack (making
   *  the result for JS)}}. A bad impact (NaN, off the surface) or option
   *  throws a HedgeError, the mesh unchanged. */
  fracture(
    impact,
    {
      material = 'glass',
      seed = 0,
      breakRadius = 0,
      units = '',
      radius = 0,
      thickness = 0,
      density = 1,
      shellThickness = 0,
      tolerance = 0,
      hulls = true,
    } = {},
  ) {
    const at = point3(impact);
    const [preset, custom] = materialArguments('fracture', material);
    if (units !== '' && !UNITS.includes(units))
      throw new HedgeError(
        'invalid-argument',
        `fracture: units must be one of ${UNITS.join(', ')}, got '${units}'`,
      );
    const result = this._call(
      'fracture',
      at,
      preset,
      custom,
      seed,
      breakRadius,
      units,
      radius,
      thickness,
      density,
      shellThickness,
      tolerance,
      Boolean(hulls),
    );
    return unpackShards(result, (native) => new Mesh(this.hedge, native));
  }

  /** Breaks the closed mesh at `impact` ([x, y, z], within the tolerance of the surface) into
   *  closed pieces with capped inner faces (docs/fracture.md); the mesh, edited in place, becomes
   *  the remaining object, closed too. material: a preset ('stone' by default) or an object as for
   *  fracture(). radius: the break radius in model units (0: radiusFraction times the diagonal of
   *  the mesh's bounding box). seed: a whole number (the same seed, mesh and impact give the same
   *  pieces). innerSubmesh: the caps' submesh (-1: one more than the largest). density: for the
   *  pieces' mass. hulls: compute each piece's convex hull. kind: 'solid', or 'auto' to break an
   *  open or non-manifold mesh by surface fracture instead (solidFractureRefusalCode() 'open' or
   *  'non_manifold'; the result then is fracture()'s, with kind 'surface', the refusal that sent it
   *  there and its refusalCode; `surface`: more options for that fracture, e.g. {thickness}; any
   *  other refusal, a bad option or impact, throws as with 'solid'). Uses the picking tree, so a strike costs
   *  the broken region. Returns {kind: 'solid', pieces: [Piece], bonds: [{a, b, area}] (pieces a
   *  and b share `area` of cap; b null: the remaining object), impactFace, impactPoint, radius,
   *  seconds: {locate, cells, clip, cap, assemble, perPiece, fracture, pack}}. A refused strike (an
   *  open mesh with kind 'solid', a bad impact or option) throws a HedgeError of kind
   *  'invalid-argument', the mesh unchanged. */
  fractureSolid(impact, { material = 'stone', kind = 'solid', surface = {}, ...options } = {}) {
    if (kind !== 'solid' && kind !== 'auto')
      throw new HedgeError(
        'invalid-argument',
        `fractureSolid: unknown kind '${kind}' (solid, auto)`,
      );
    const at = point3(impact);
    const [preset, custom] = materialArguments('fractureSolid', material);
    const o = solidOptions(options);
    if (kind === 'auto') {
      // Only the input's shape (open or non-manifold) goes to surface fracture, the rule of every
      // binding (solid_refusal_falls_back()); any other refusal throws below, as with kind 'solid'.
      const { code, message: refusal } = this._call('solidFractureCheck', at, preset, custom, o);
      if (code === 'open' || code === 'non_manifold') {
        const { seed, radius, density, tolerance, hulls } = o;
        const shards = this.fracture(impact, {
          material,
          seed,
          breakRadius: radius,
          density,
          tolerance,
          hulls,
          ...surface,
        });
        return { kind: 'surface', refusal, refusalCode: code, ...shards };
      }
    }
    const result = this._call('fractureSolid', at, preset, custom, o);
    return unpackSolidResult(result, (native) => new Mesh(this.hedge, native));
  }

  /** Why fractureSolid(impact, options) would be refused (the mesh open, naming an edge, or
   *  non-manifold near the impact; the impact off the surface; an illegal option), or null if it
   *  would not. Whether the mesh is closed is kept by the picking tree until the mesh changes. */
  solidFractureRefusal(impact, { material = 'stone', ...options } = {}) {
    const [preset, custom] = materialArguments('solidFractureRefusal', material);
    const { message } = this._call(
      'solidFractureCheck',
      point3(impact),
      preset,
      custom,
      solidOptions(options),
    );
    return message === '' ? null : message;
  }

  /** solidFractureRefusal()'s answer as a code, the same in every binding: 'none' (no refusal),
   *  'open' or 'non_manifold' (the input's shape: fractureSolid() with kind 'auto' breaks these by
   *  surface fracture), or 'bad_option', 'bad_impact', 'off_surface', 'no_face', 'bad_radius'
   *  (errors with either kind). */
  solidFractureRefusalCode(impact, { material = 'stone', ...options } = {}) {
    const [preset, custom] = materialArguments('solidFractureRefusalCode', material);
    return this._call('solidFractureCheck', point3(impact), preset, custom, solidOptions(options))
      .code;
  }

  /** The mesh as index buffers (copies): {positions, indices, faceSizes (null for triangles)};
   *  triangulate: true fans polygons into triangles (ear clipping). */
  toArrays({ triangulate = false } = {}) {
    return this._call('toArrays', triangulate);
  }

  /** The mesh as the bytes of a file in the format of name's extension (.obj, .off, .ply, .stl),
   *  as hedge writes files: PLY and STL binary, STL fanned into triangles. A Uint8Array copy. */
  toFile(name) {
    return this._call('toFile', name);
  }

  /** Heap bytes held by the mesh and its picking tree. */
  memoryBytes() {
    return this._call('memoryBytes');
  }

  /** Engine-ready buffers kept in step with this mesh (RenderBuffers). options: normals ('auto',
   *  'computed', 'attribute', 'none'), interleaved (true), texcoords (true), colors (true). The
   *  RenderBuffers shares the mesh: the mesh's memory stays until both are disposed. */
  createRenderBuffers({
    normals = 'auto',
    interleaved = true,
    texcoords = true,
    colors = true,
  } = {}) {
    const native = this.hedge._check(
      this.hedge.module.NativeRenderBuffers.create(
        this._n(),
        normals,
        interleaved,
        texcoords,
        colors,
      ),
    );
    const render = new RenderBuffers(this.hedge, native);
    this._renders = this._renders.filter((ref) => ref.deref() !== undefined);
    this._renders.push(new WeakRef(render));
    return render;
  }
}

installArgumentChecks({ Hedge, Mesh, RenderBuffers });

// ---- Deprecated names (kept for one release) ----------------------------------------------------
// The names of the previous release; the next release removes them.

/** @deprecated Use RenderBuffers. */
export const Render = RenderBuffers;

/** @deprecated Use mesh.createRenderBuffers(options). */
Mesh.prototype.createRender = function createRender(options) {
  return this.createRenderBuffers(options);
};
// ---- End of deprecated names --------------------------------------------------------------------
