// RenderBuffers in the JS API: engine-ready vertex and index buffers kept in step with a Mesh
// (Mesh.createRenderBuffers() makes them), updated by dirty ranges.
import { NativeOwner } from './native.js';

/** Vertex and index buffers for a GPU, updated by dirty ranges (RenderBuffers). */
export class RenderBuffers extends NativeOwner {
  constructor(hedge, native) {
    super(hedge, native, 'render object');
  }

  /** Floats per vertex and the offset of each attribute (-1: absent):
   *  {stride, position, normal, texcoord, color, interleaved}. */
  get layout() {
    return this._call('layout');
  }

  /** {vertexSlots, triangleSlots, indexCount, vertices, triangles, vertexCapacity, indexCapacity,
   *  freeTriangleSlots, bufferBytes}. Allocate GPU buffers at the capacities. */
  sizes() {
    return this._call('sizes');
  }

  /** Float32Array views (no copy): the whole interleaved vertex buffer (or the positions), and the
   *  separate streams (empty when interleaved or absent). Valid until the next sync or memory growth. */
  get vertices() {
    return this._call('streamView', 0);
  }
  get normals() {
    return this._call('streamView', 1);
  }
  get texcoords() {
    return this._call('streamView', 2);
  }
  get colors() {
    return this._call('streamView', 3);
  }

  /** Uint32Array view of the index buffer (3 per triangle slot; a free slot is degenerate). */
  get indices() {
    return this._call('indicesView');
  }

  /** Uint32Array view: render vertex -> mesh vertex (0xFFFFFFFF for a free slot). */
  get vertexSource() {
    return this._call('vertexSourceView');
  }

  /** [first triangle slot, count] of face f. */
  faceTriangles(f) {
    return this._call('faceTriangles', f);
  }

  /** The first face along a ray (through the mesh's picking tree, as Mesh.pick) and the triangle
   *  slots it owns in these buffers as of the last sync: null if the ray misses, else {face, t,
   *  point, first, count} (triangles [first, first + count) of the index buffer; count 0 for a face
   *  made since the last sync). One call per ray: what a raycast against the uploaded triangles
   *  needs (the three.js adapter's hedgeRaycast). */
  pickTriangles(origin, direction) {
    const face = this._n().pickTriangles(
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
      face,
      t: f[k + 1],
      point: [f[k + 2], f[k + 3], f[k + 4]],
      first: f[k + 5],
      count: f[k + 6],
    };
  }

  /** Each submesh's (material's) part of the buffers as of the last sync, in submesh order:
   *  [{indexStart, indexCount, firstVertex, vertexCount, empty}]. A submesh's triangles lie in
   *  index entries [indexStart, indexStart + indexCount) (spare slots included, kept degenerate):
   *  one draw call or three.js group each; their render vertices in [firstVertex, firstVertex +
   *  vertexCount). empty: no live triangle since the last full build (or only triangles whose
   *  corners are all at the origin, which draw nothing), e.g. the ids between used ones. A mesh
   *  without submeshes has one, the whole buffer. */
  submeshes() {
    return this._call('submeshes');
  }

  /** Brings the buffers in step with the mesh's edits since the last sync and says what was
   *  rewritten: {vertexRanges, indexRanges (Uint32Array pairs [first, count] in vertices and in
   *  indices), vertexBytes, indexBytes, facesSynced, verticesSynced, resized (reallocate the GPU
   *  buffers and upload all), full (everything was rewritten)}. Upload only the ranges: for
   *  interleaved vertices the floats [first * stride, (first + count) * stride). Take the views
   *  again after a sync. */
  sync() {
    return this._call('sync');
  }

  /** The dirty ranges of a sync result as views into the buffers (no copy):
   *  {vertices: Float32Array[], indices: Uint32Array[]}. */
  dirtyViews(result) {
    const stride = this.layout.interleaved ? this.layout.stride : 3;
    const vertices = this.vertices;
    const indices = this.indices;
    const v = [];
    const i = [];
    for (let k = 0; k < result.vertexRanges.length; k += 2) {
      const first = result.vertexRanges[k];
      const count = result.vertexRanges[k + 1];
      v.push(vertices.subarray(first * stride, (first + count) * stride));
    }
    for (let k = 0; k < result.indexRanges.length; k += 2) {
      const first = result.indexRanges[k];
      i.push(indices.subarray(first, first + result.indexRanges[k + 1]));
    }
    return { vertices: v, indices: i };
  }

  /** Rebuilds everything (a full export); returns the result as sync() does. */
  rebuild() {
    return this._call('rebuild');
  }

  /** Packs the buffers, removing free slots; the next sync reports everything. */
  compact() {
    this._call('compact');
  }

  /** begin() ... edits ... commit(): one sync for many edits. */
  begin() {
    this._call('begin');
  }
  commit() {
    return this._call('commit');
  }
}
