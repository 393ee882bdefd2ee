// The three.js side of RenderBuffers: GPU buffers that mirror hedge's render buffers and are updated
// range by range after an edit.
//
// The vertex buffer is one interleaved buffer (position, normal, ...) shared by the surface and by
// the wireframe; the surface draws the triangle index buffer, the wireframe draws a line index
// buffer derived from it (triangle t's three sides sit at line indices [6t, 6t + 6)), so both follow
// the same dirty ranges. A polygon's triangles have sides that are no edges of the mesh (its
// diagonals); an `isEdge(a, b)` test on render vertices, when given, leaves those out of the
// wireframe (a degenerate line instead). The buffers are allocated at RenderBuffers' capacity, and only a sync that
// reports `resized` or `full` reallocates and uploads them whole.
import * as THREE from 'three';

// Copies [first, first + count) elements of `width` numbers each from `from` into `to`.
function copyRange(to, from, first, count, width) {
  const begin = first * width;
  const end = (first + count) * width;
  to.set(from.subarray(begin, end), begin);
}

export class GpuMesh {
  //! `material` draws the surface and `lineMaterial` the wireframe.
  constructor(material, lineMaterial) {
    this.geometry = new THREE.BufferGeometry();
    this.lineGeometry = new THREE.BufferGeometry();
    this.surface = new THREE.Mesh(this.geometry, material);
    this.wireframe = new THREE.LineSegments(this.lineGeometry, lineMaterial);
    this.surface.frustumCulled = false;
    this.wireframe.frustumCulled = false;
    this.group = new THREE.Group();
    this.group.add(this.surface, this.wireframe);
    this.vertexArray = null;
    this.indexArray = null;
    this.lineArray = null;
    this.stride = 0;
  }

  //! Bytes of the GPU buffers as allocated (vertices, triangle indices and line indices).
  get allocatedBytes() {
    if (!this.vertexArray) return 0;
    return this.vertexArray.byteLength + this.indexArray.byteLength + this.lineArray.byteLength;
  }

  //! Reallocates every buffer from `buffers` and uploads it whole.
  //! buffers: { vertices: Float32Array, indices: Uint32Array, layout: {stride, position, normal},
  //!            vertexCapacity, indexCapacity } (capacities in render vertices and in indices).
  //! isEdge: null (every side is an edge: a triangle mesh) or (a, b) => whether render vertices a
  //! and b are joined by an edge of the mesh.
  rebuild(buffers, isEdge = null) {
    const { layout } = buffers;
    const vertexCapacity = Math.max(
      buffers.vertexCapacity,
      buffers.vertices.length / layout.stride,
      1,
    );
    const indexCapacity = Math.max(buffers.indexCapacity, buffers.indices.length, 3);
    this.stride = layout.stride;
    this.vertexArray = new Float32Array(vertexCapacity * layout.stride);
    this.vertexArray.set(buffers.vertices);
    this.indexArray = new Uint32Array(indexCapacity);
    this.indexArray.set(buffers.indices);
    this.lineArray = new Uint32Array(indexCapacity * 2);
    const indexCount = buffers.indices.length;
    // The views into wasm memory are used up: isEdge may call into the module and move them.
    this.writeLines(0, indexCount, isEdge);

    const interleaved = new THREE.InterleavedBuffer(this.vertexArray, layout.stride);
    interleaved.setUsage(THREE.DynamicDrawUsage);
    const position = new THREE.InterleavedBufferAttribute(interleaved, 3, layout.position);
    const index = new THREE.BufferAttribute(this.indexArray, 1).setUsage(THREE.DynamicDrawUsage);
    const lines = new THREE.BufferAttribute(this.lineArray, 1).setUsage(THREE.DynamicDrawUsage);

    // New geometries, so three.js allocates new GPU buffers of the new size.
    this.geometry.dispose();
    this.lineGeometry.dispose();
    this.geometry = new THREE.BufferGeometry();
    this.lineGeometry = new THREE.BufferGeometry();
    this.geometry.setAttribute('position', position);
    if (layout.normal >= 0)
      this.geometry.setAttribute(
        'normal',
        new THREE.InterleavedBufferAttribute(interleaved, 3, layout.normal),
      );
    this.geometry.setIndex(index);
    this.lineGeometry.setAttribute('position', position);
    this.lineGeometry.setIndex(lines);
    this.surface.geometry = this.geometry;
    this.wireframe.geometry = this.lineGeometry;
    this.indexCount = indexCount;
    this.geometry.setDrawRange(0, this.indexCount);
    this.lineGeometry.setDrawRange(0, this.indexCount * 2);
    this.geometry.computeBoundingSphere();
    return this.allocatedBytes;
  }

  //! Copies the rewritten ranges of `result` from `buffers` and asks three.js to upload only them.
  //! Falls back to rebuild() when the sync resized or rebuilt the buffers, or they outgrew ours.
  //! Returns the bytes queued for upload.
  update(buffers, result, isEdge = null) {
    const stride = buffers.layout.stride;
    if (
      result.resized ||
      result.full ||
      !this.vertexArray ||
      stride !== this.stride ||
      buffers.vertices.length > this.vertexArray.length ||
      buffers.indices.length > this.indexArray.length
    )
      return { bytes: this.rebuild(buffers, isEdge), full: true, ranges: 1 };
    const indexCount = buffers.indices.length;

    const position = this.geometry.getAttribute('position');
    const interleaved = position.data;
    const index = this.geometry.getIndex();
    const lines = this.lineGeometry.getIndex();
    let bytes = 0;
    for (const { first, count } of result.vertexRanges) {
      if (count === 0) continue;
      copyRange(this.vertexArray, buffers.vertices, first, count, stride);
      interleaved.addUpdateRange(first * stride, count * stride);
      bytes += count * stride * 4;
    }
    for (const { first, count } of result.indexRanges) {
      if (count === 0) continue;
      copyRange(this.indexArray, buffers.indices, first, count, 1);
      index.addUpdateRange(first, count);
      lines.addUpdateRange(first * 2, count * 2);
      bytes += count * 4 * 3;
    }
    // After every copy: isEdge may call into the module, which can move the views.
    // Index ranges cover whole triangles, so they map onto whole line triples.
    for (const { first, count } of result.indexRanges) this.writeLines(first, count, isEdge);
    if (result.vertexRanges.length) interleaved.needsUpdate = true;
    if (result.indexRanges.length) {
      index.needsUpdate = true;
      lines.needsUpdate = true;
    }
    this.indexCount = indexCount;
    this.geometry.setDrawRange(0, this.indexCount);
    this.lineGeometry.setDrawRange(0, this.indexCount * 2);
    return { bytes, full: false, ranges: result.vertexRanges.length + result.indexRanges.length };
  }

  // Line indices for index-buffer entries [first, first + count), whole triangles; a side that
  // isEdge rejects becomes a zero-length line.
  writeLines(first, count, isEdge) {
    const tri = this.indexArray;
    const out = this.lineArray;
    for (let i = first; i < first + count; i += 3) {
      const corners = [tri[i], tri[i + 1], tri[i + 2]];
      for (let k = 0; k < 3; ++k) {
        const a = corners[k],
          b = corners[(k + 1) % 3];
        const o = i * 2 + k * 2;
        const keep = a !== b && (!isEdge || isEdge(a, b));
        out[o] = a;
        out[o + 1] = keep ? b : a;
      }
    }
  }

  dispose() {
    this.geometry.dispose();
    this.lineGeometry.dispose();
  }
}

//! Counts the bytes a WebGL context is given by bufferData and bufferSubData, so the page reports
//! what really went to the GPU and not what it meant to send.
export class UploadMeter {
  constructor(gl) {
    this.subBytes = 0;
    this.subCalls = 0;
    this.fullBytes = 0;
    this.fullCalls = 0;
    const meter = this;
    const bufferData = gl.bufferData.bind(gl);
    const bufferSubData = gl.bufferSubData.bind(gl);
    const sizeOf = (data, srcOffset, length) => {
      if (typeof data === 'number') return data;
      if (!data || data.byteLength === undefined) return 0;
      if (ArrayBuffer.isView(data) && srcOffset !== undefined) {
        const elements = length ? length : data.length - srcOffset;
        return elements * (data.BYTES_PER_ELEMENT || 1);
      }
      return data.byteLength;
    };
    gl.bufferData = function (target, data, usage, srcOffset, length) {
      meter.fullBytes += sizeOf(data, srcOffset, length);
      meter.fullCalls += 1;
      return bufferData(...arguments);
    };
    gl.bufferSubData = function (target, dstOffset, data, srcOffset, length) {
      meter.subBytes += sizeOf(data, srcOffset, length);
      meter.subCalls += 1;
      return bufferSubData(...arguments);
    };
  }

  snapshot() {
    return {
      subBytes: this.subBytes,
      subCalls: this.subCalls,
      fullBytes: this.fullBytes,
      fullCalls: this.fullCalls,
    };
  }

  since(before) {
    return {
      subBytes: this.subBytes - before.subBytes,
      subCalls: this.subCalls - before.subCalls,
      fullBytes: this.fullBytes - before.fullBytes,
      fullCalls: this.fullCalls - before.fullCalls,
    };
  }
}
