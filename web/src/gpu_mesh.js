// The three.js side of RenderBuffers: the mesh's geometry made and kept in step by hedge's three.js
// adapter (toBufferGeometry, syncBufferGeometry: only the ranges an edit rewrote are uploaded), and
// the wireframe drawn over it.
//
// The wireframe shares the surface's vertex buffer and draws a line index buffer derived from the
// triangle indices (triangle t's three sides sit at line indices [6t, 6t + 6)), so it follows the
// same dirty ranges. A polygon's triangles have sides that are no edges of the mesh (its
// diagonals); an `isEdge(a, b)` test on render vertices, when given, leaves those out of the
// wireframe (a degenerate line instead).
import * as THREE from 'three';
import { syncBufferGeometry, toBufferGeometry } from 'hedge/three';

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
    this.lineArray = null;
  }

  //! The geometry's copies of the vertex and index buffers (what three.js uploads).
  get vertexArray() {
    const position = this.geometry.getAttribute('position');
    return position
      ? (position.isInterleavedBufferAttribute ? position.data : position).array
      : null;
  }
  get indexArray() {
    return this.geometry.getIndex()?.array ?? null;
  }
  //! Index-buffer entries in use (the draw range).
  get indexCount() {
    return this.geometry.drawRange.count;
  }

  //! Bytes of the GPU buffers as allocated (vertices, triangle indices and line indices).
  get allocatedBytes() {
    if (!this.lineArray) return 0;
    return this.vertexArray.byteLength + this.indexArray.byteLength + this.lineArray.byteLength;
  }

  //! Makes the geometry of `mesh` from its RenderBuffers `render` and uploads it whole; returns the
  //! bytes allocated. isEdge: null (every side is an edge: a triangle mesh) or (a, b) => whether
  //! render vertices a and b are joined by an edge of the mesh.
  rebuild(mesh, render, isEdge = null) {
    this.geometry.dispose();
    this.geometry = toBufferGeometry(mesh, { renderBuffers: render });
    this.surface.geometry = this.geometry;
    this.rebuildLines(isEdge);
    return this.allocatedBytes;
  }

  //! Uploads what the sync `result` of `render` rewrote (a whole upload when it was full or
  //! resized). Returns {bytes (queued), full, ranges}.
  update(render, result, isEdge = null) {
    const upload = syncBufferGeometry(this.geometry, render, result);
    if (upload.full) {
      this.rebuildLines(isEdge);
      return { bytes: this.allocatedBytes, full: true, ranges: 1 };
    }
    const lines = this.lineGeometry.getIndex();
    const ranges = result.indexRanges;
    // Index ranges cover whole triangles, so they map onto whole line triples.
    for (let k = 0; k < ranges.length; k += 2) {
      if (ranges[k + 1] === 0) continue;
      this.writeLines(ranges[k], ranges[k + 1], isEdge);
      lines.addUpdateRange(ranges[k] * 2, ranges[k + 1] * 2);
    }
    if (ranges.length) lines.needsUpdate = true;
    this.lineGeometry.setDrawRange(0, this.indexCount * 2);
    return {
      bytes: upload.bytes + upload.result.indexBytes * 2,
      full: false,
      ranges: upload.ranges,
    };
  }

  // A new line geometry over the surface's vertex buffer, its indices written whole.
  rebuildLines(isEdge) {
    this.lineArray = new Uint32Array(this.indexArray.length * 2);
    this.writeLines(0, this.indexCount, isEdge);
    this.lineGeometry.dispose();
    this.lineGeometry = new THREE.BufferGeometry();
    this.lineGeometry.setAttribute('position', this.geometry.getAttribute('position'));
    const lines = new THREE.BufferAttribute(this.lineArray, 1).setUsage(THREE.DynamicDrawUsage);
    this.lineGeometry.setIndex(lines);
    this.lineGeometry.setDrawRange(0, this.indexCount * 2);
    this.wireframe.geometry = this.lineGeometry;
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
