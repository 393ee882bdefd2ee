// One loaded mesh as the page uses it: the hedge mesh in wasm, its RenderBuffers, and the queries and
// edits of the inspect and edit panels. Every failure is thrown as an Error whose message says what
// and where (hedge's own message, with the file and line for a bad file).
import { loadHedge as load } from 'hedge';

export const SUBDIVISION_SCHEMES = [
  { id: 'loop', label: 'Loop' },
  { id: 'sqrt3', label: 'sqrt(3)' },
  { id: 'midpoint', label: 'Midpoint' },
  { id: 'catmull-clark', label: 'Catmull-Clark' },
  { id: 'split-faces', label: 'Split faces' },
];

//! The angle (degrees) between faces above which their shared edge is drawn hard.
export const CREASE_DEGREES = 40;

//! Instantiates the WebAssembly module (hedge.wasm is fetched next to hedge.mjs).
export async function loadHedge() {
  return load();
}

export class PageMesh {
  //! `render`: keep render buffers (RenderBuffers) for drawing; false for a mesh only measured.
  //! `report`: the buildReport() of the file the mesh was read from, when it was read elsewhere (in
  //! the worker) and rebuilt here from arrays; by default the mesh's own.
  constructor(hedge, mesh, { render = true, report = null } = {}) {
    this.hedge = hedge;
    this.mesh = mesh;
    this.report = report;
    // Corner normals, the same for every file: smooth where faces meet at less than CREASE_DEGREES,
    // hard edges elsewhere (smooth vertex normals streak the flat sides of CAD models); 'auto'
    // keeps them up around each edit, creases included.
    if (render) mesh.computeCornerNormals(CREASE_DEGREES);
    this.render = render
      ? mesh.createRenderBuffers({ normals: 'auto', texcoords: false, colors: false })
      : null;
    this.rays = null;
    this.pickFaces = null;
    this.rebuildNext = false; // the next sync() rebuilds the render buffers (see fractureSolid)
  }

  //! Reads a mesh file's bytes (a Uint8Array) with the reader for `name`'s extension. A malformed
  //! file throws hedge's message, which names the file and the line or byte.
  static load(hedge, bytes, name, options = {}) {
    if (bytes.length === 0) throw new Error(`${name}: the file is empty`);
    const mesh = hedge.fromFile(bytes, name);
    try {
      return new PageMesh(hedge, mesh, options);
    } catch (error) {
      mesh.dispose();
      throw error;
    }
  }

  //! A mesh from typed arrays ({positions, indices}, triangles), as hedge.fromBuffers takes them.
  static fromBuffers(hedge, arrays, options = {}) {
    const mesh = hedge.fromBuffers(arrays);
    try {
      return new PageMesh(hedge, mesh, options);
    } catch (error) {
      mesh.dispose();
      throw error;
    }
  }

  dispose() {
    if (this.render) this.render.dispose();
    if (this.mesh) this.mesh.dispose();
    this.render = null;
    this.mesh = null;
  }

  //! What loading found wrong with the file and what it only noted: {warnings, notes}, lists of
  //! lines. Warnings: the reader's own (a face dropped, the file may be truncated, ...) and the
  //! repairs that mean the file was not a clean surface (faces dropped or reoriented, vertices and
  //! edges split). Notes: welding and isolated vertices, which well-formed files have too (an STL
  //! file's corners are welded into vertices).
  fileReport() {
    const report = this.report ?? this.mesh.buildReport();
    const warningLabels = {
      degenerateFaces: 'degenerate faces dropped',
      repeatedCorners: 'repeated corners removed',
      reorientedFaces: 'faces reoriented',
      nonManifoldEdges: 'non-manifold edges split',
      nonManifoldVertices: 'non-manifold vertices split',
      duplicatedVertices: 'vertices duplicated',
    };
    const noteLabels = { weldedVertices: 'welded vertices', isolatedVertices: 'isolated vertices' };
    const listed = (labels) =>
      Object.entries(labels)
        .filter(([key]) => report[key])
        .map(([key, label]) => `${report[key].toLocaleString('en-US')} ${label}`);
    const repairs = listed(warningLabels);
    const warnings = [...(report.warnings || [])];
    if (warnings.length > 3) warnings.splice(3, warnings.length, `and ${warnings.length - 3} more`);
    if (repairs.length) warnings.push(`repaired: ${repairs.join(', ')}`);
    const notes = listed(noteLabels);
    return { warnings, notes: notes.length ? [`repairs: ${notes.join(', ')}`] : [] };
  }

  //! A triangle mesh of the same vertices: each polygon cut along its diagonals (ear clipping, so
  //! concave faces stay inside their outline), built anew. For the edits that need triangles
  //! (Loop, sqrt(3), decimate). The caller disposes this one.
  triangulated() {
    const { positions, indices } = this.mesh.toArrays({ triangulate: true });
    return PageMesh.fromBuffers(this.hedge, { positions, indices, weld: 'none' });
  }

  counts() {
    return this.mesh.counts();
  }

  //! Triangles of the mesh (n - 2 for an n-gon). O(faces).
  triangleCount() {
    if (this.mesh.isTriangleMesh()) return this.counts().faces;
    return this.mesh.toArrays({ triangulate: true }).indices.length / 3;
  }

  problems() {
    return this.mesh.validate();
  }

  boundingBox() {
    const p = this.mesh.positions;
    const min = [Infinity, Infinity, Infinity];
    const max = [-Infinity, -Infinity, -Infinity];
    for (let i = 0; i < p.length; i += 3) {
      for (let k = 0; k < 3; ++k) {
        const x = p[i + k];
        if (x < min[k]) min[k] = x;
        if (x > max[k]) max[k] = x;
      }
    }
    if (!(min[0] <= max[0])) return { min: [-1, -1, -1], max: [1, 1, 1] };
    return { min, max };
  }

  //! Views of the render buffers in wasm memory; valid until the next call into the module.
  buffers() {
    const sizes = this.render.sizes();
    return {
      layout: this.render.layout,
      vertices: this.render.vertices,
      indices: this.render.indices,
      vertexCapacity: sizes.vertexCapacity,
      indexCapacity: sizes.indexCapacity,
    };
  }

  //! Null for a triangle mesh (every side of a render triangle is an edge); else a test whether
  //! render vertices a and b are joined by an edge, for drawing polygons without their diagonals.
  //! Valid until the next edit.
  edgeTest() {
    if (this.mesh.isTriangleMesh()) return null;
    const source = this.render.vertexSource.slice(); // a copy: the test calls into the module
    const rings = new Map();
    return (a, b) => {
      const va = source[a],
        vb = source[b];
      let ring = rings.get(va);
      if (!ring) {
        ring = new Set(this.mesh.oneRing(va).vertices);
        rings.set(va, ring);
      }
      return ring.has(vb);
    };
  }

  //! Syncs the render buffers with the mesh: RenderBuffers.sync()'s result ({vertexRanges,
  //! indexRanges: Uint32Array pairs [first, count], resized, full, ...}).
  sync() {
    if (this.rebuildNext) {
      this.rebuildNext = false;
      return this.render.rebuild();
    }
    return this.render.sync();
  }

  //! The first face hit by a ray: { face, point, ... } or null.
  pick(origin, direction) {
    return this.mesh.pick(origin, direction);
  }

  //! Builds (or updates) the picking BVH.
  buildPicking() {
    this.mesh.pick([0, 0, 0], [0, 0, 1]);
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
    const faces = this.mesh.pickMany(this.rays, this.pickFaces);
    let hits = 0;
    for (let i = 0; i < n; ++i) hits += faces[i] >= 0 ? 1 : 0;
    return hits;
  }

  isFaceLive(f) {
    try {
      this.mesh.face(f);
      return true;
    } catch {
      return false;
    }
  }

  faceHalfedges(f) {
    return this.mesh.face(f).halfedges;
  }

  //! { halfedge, origin, target, twin, face, next, prev, edge, boundary } of half-edge h.
  record(h) {
    return this.mesh.halfedge(h);
  }

  position(v) {
    return this.mesh.position(v);
  }

  outgoing(v) {
    return this.mesh.vertex(v).halfedge;
  }

  oneRing(v) {
    return this.mesh.oneRing(v).vertices;
  }

  splitEdge(e, point) {
    return this.mesh.splitEdge(e, point);
  }

  flip(e) {
    return this.mesh.flip(e);
  }

  collapse(h) {
    return this.mesh.collapse(h);
  }

  splitFace(f, point) {
    return this.mesh.splitFace(f, point);
  }

  subdivide(scheme) {
    return this.mesh.subdivide(scheme, 1);
  }

  smooth() {
    return this.mesh.smooth({ method: 'taubin', iterations: 10 });
  }

  //! Breaks the mesh at `point` (Mesh.fracture); the shards come back with their own meshes, which
  //! the caller disposes.
  fracture(point, options) {
    return this.mesh.fracture(point, options);
  }

  //! Breaks the closed mesh at `point` into closed pieces (Mesh.fractureSolid; with kind 'auto', an
  //! open mesh by surface fracture); the pieces (or shards) come back with their own meshes, which
  //! the caller disposes.
  //! The corner normals are computed again with the page's crease angle (the caps' corners carry
  //! their plane's normal, the outer faces' are interpolated), and the next sync uploads everything.
  fractureSolid(point, options) {
    const result = this.mesh.fractureSolid(point, options);
    if (result.kind === 'solid' && this.render) {
      this.mesh.computeCornerNormals(CREASE_DEGREES);
      this.rebuildNext = true;
    }
    return result;
  }

  //! How many submesh ids the drawn mesh has (one more than the largest; 1 without submeshes): the
  //! id a solid fracture's caps get by default.
  submeshCount() {
    return this.render ? this.render.submeshes().length : 1;
  }

  decimate(targetFaces) {
    return this.mesh.decimate({ targetFaces });
  }
}
