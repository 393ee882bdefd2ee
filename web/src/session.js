// One loaded mesh as the page uses it: the hedge mesh in wasm, its RenderSync, and the queries and
// edits of the inspect and edit panels. Every failure is thrown as an Error whose message says what
// and where (hedge's own message, with the file and line for a bad file).
import createHedge from 'hedge';

export const SUBDIVISION_SCHEMES = [
  { id: 'loop', label: 'Loop' },
  { id: 'sqrt3', label: 'sqrt(3)' },
  { id: 'midpoint', label: 'Midpoint' },
  { id: 'catmull-clark', label: 'Catmull-Clark' },
  { id: 'split-faces', label: 'Split faces' },
];

//! Instantiates the WebAssembly module (fetches hedge.wasm next to hedge.mjs).
export async function loadHedge() {
  return createHedge();
}

// Runs a call into the module and turns a recorded C++ error into a thrown Error.
function checked(hedge, result) {
  const message = hedge.takeErrorMessage();
  if (message) throw new Error(message);
  return result;
}

export class Session {
  //! `render`: keep render buffers (RenderSync) for drawing; false for a mesh only measured.
  constructor(hedge, mesh, { render = true } = {}) {
    this.hedge = hedge;
    this.mesh = mesh;
    this.render = render ? checked(hedge, hedge.NativeRender.create(mesh, 'computed', true, false, false)) : null;
    this.pickFaces = null;
  }

  //! Reads a mesh file's bytes (a Uint8Array, passed to embind's std::string as they are) with the reader for `name`'s extension (OBJ, OFF, PLY, STL).
  static load(hedge, bytes, name, options = {}) {
    if (bytes.length === 0) throw new Error(`${name}: the file is empty`);
    const mesh = checked(hedge, hedge.NativeMesh.fromFile(bytes, name));
    try {
      return new Session(hedge, mesh, options);
    } catch (error) {
      mesh.delete();
      throw error;
    }
  }

  dispose() {
    if (this.render) this.render.delete();
    if (this.mesh) this.mesh.delete();
    this.render = null;
    this.mesh = null;
  }

  counts() {
    return checked(this.hedge, this.mesh.counts());
  }

  //! Triangles of the mesh (n - 2 for an n-gon). O(faces).
  triangleCount() {
    if (checked(this.hedge, this.mesh.isTriangleMesh())) return this.counts().faces;
    const { indices } = checked(this.hedge, this.mesh.toArrays(true));
    return indices.length / 3;
  }

  problems() {
    return checked(this.hedge, this.mesh.validate());
  }

  boundingBox() {
    const p = checked(this.hedge, this.mesh.positionsView());
    const min = [Infinity, Infinity, Infinity];
    const max = [-Infinity, -Infinity, -Infinity];
    for (let i = 0; i < p.length; i += 3) {
      for (let k = 0; k < 3; ++k) {
        const x = p[i + k];
        if (x < min[k]) min[k] = x;
        if (x > max[k]) max[k] = x;
      }
    }
    if (min[0] > max[0]) return { min: [-1, -1, -1], max: [1, 1, 1] };
    return { min, max };
  }

  //! Views of the render buffers in wasm memory; valid until the next call into the module.
  buffers() {
    const h = this.hedge;
    const layout = checked(h, this.render.layout());
    const sizes = checked(h, this.render.sizes());
    return {
      layout,
      vertices: checked(h, this.render.streamView(0)),
      indices: checked(h, this.render.indicesView()),
      vertexCapacity: sizes.vertexCapacity,
      indexCapacity: sizes.indexCapacity,
    };
  }

  //! Syncs the render buffers with the mesh: { vertexRanges, indexRanges: [{first, count}], resized, full }.
  sync() {
    const r = checked(this.hedge, this.render.sync());
    const ranges = (flat) => {
      const out = [];
      for (let i = 0; i < flat.length; i += 2) out.push({ first: flat[i], count: flat[i + 1] });
      return out;
    };
    return { ...r, vertexRanges: ranges(r.vertexRanges), indexRanges: ranges(r.indexRanges) };
  }

  //! The first face hit by a ray: { face, point } or null.
  pick(origin, direction) {
    const h = this.hedge;
    const face = checked(h, this.mesh.pick(...origin, ...direction));
    if (face < 0) return null;
    const scratch = new Float64Array(h.HEAPF64.buffer, h.pickScratchAddress(), 16);
    return { face, point: [scratch[2], scratch[3], scratch[4]] };
  }

  //! Builds (or updates) the picking BVH.
  buildPicking() {
    this.pick([0, 0, 0], [0, 0, 1]);
  }

  //! Casts rays (origins and directions, 3 floats each) in one call; returns the number of hits.
  castRays(origins, directions) {
    const n = origins.length / 3;
    if (!this.rays || this.rays.length !== n * 6) {
      this.rays = new Float32Array(n * 6);
      this.pickFaces = new Int32Array(n);
    }
    for (let i = 0; i < n; ++i) {
      this.rays.set(origins.subarray(i * 3, i * 3 + 3), i * 6);
      this.rays.set(directions.subarray(i * 3, i * 3 + 3), i * 6 + 3);
    }
    return checked(this.hedge, this.mesh.pickMany(this.rays, this.pickFaces));
  }

  isFaceLive(f) {
    try {
      this.faceHalfedges(f);
      return true;
    } catch {
      return false;
    }
  }

  faceHalfedges(f) {
    return checked(this.hedge, this.mesh.face(f)).halfedges;
  }

  //! { halfedge, origin, target, twin, face, next, prev, edge, boundary } of half-edge h.
  record(h) {
    return checked(this.hedge, this.mesh.halfedge(h));
  }

  position(v) {
    return checked(this.hedge, this.mesh.position(v));
  }

  outgoing(v) {
    return checked(this.hedge, this.mesh.vertex(v)).halfedge;
  }

  oneRing(v) {
    return checked(this.hedge, this.mesh.oneRing(v)).vertices;
  }

  splitEdge(e, point) {
    return checked(this.hedge, this.mesh.splitEdge(e, point));
  }

  flip(e) {
    return checked(this.hedge, this.mesh.flip(e));
  }

  collapse(h) {
    return checked(this.hedge, this.mesh.collapse(h, undefined));
  }

  splitFace(f, point) {
    return checked(this.hedge, this.mesh.splitFace(f, point));
  }

  subdivide(scheme) {
    return checked(this.hedge, this.mesh.subdivide(scheme, 1));
  }

  smooth() {
    return checked(this.hedge, this.mesh.smooth('taubin', 10, 0.5, -0.53, true));
  }

  decimate(targetFaces) {
    return checked(this.hedge, this.mesh.decimate(targetFaces, 0, -1));
  }
}
