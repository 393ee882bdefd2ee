// hedge and three.js: BufferGeometry in and out, partial uploads after edits, and raycasting
// through hedge's picking tree. three.js is a peer dependency (imported as 'three', not bundled).
//
//   import { fromBufferGeometry, toBufferGeometry, syncBufferGeometry, hedgeRaycast } from 'hedge-wasm/three';
//   const mesh = fromBufferGeometry(hedge, loaded.geometry);         // groups, uvs, normals, colours kept
//   const render = mesh.createRenderBuffers();
//   const object = new THREE.Mesh(toBufferGeometry(mesh, { renderBuffers: render }), materials);
//   object.raycast = hedgeRaycast;                                   // or on THREE.Mesh.prototype
//   mesh.flip(edge);
//   syncBufferGeometry(object.geometry, render);                     // uploads only what changed
//
// A geometry made with a renderBuffers is live: its arrays are allocated at the RenderBuffers'
// capacities, syncBufferGeometry() copies the dirty ranges into them and marks just those ranges
// for upload (addUpdateRange), and hedgeRaycast finds its triangles through the mesh's picking tree.
// Each submesh ("f:submesh", a material) is one group of the index buffer, so an array of materials
// draws it. Free slots of the buffers are degenerate triangles, which draw and hit nothing.
import {
  BackSide,
  Box3,
  BufferAttribute,
  BufferGeometry,
  DynamicDrawUsage,
  FrontSide,
  InterleavedBuffer,
  InterleavedBufferAttribute,
  Matrix4,
  Mesh as ThreeMesh,
  Ray,
  Sphere,
  Triangle,
  Vector2,
  Vector3,
} from 'three';

import { HedgeError } from './hedge.js';

const invalid = (call, message) => new HedgeError('invalid-argument', `${call}: ${message}`);

const describe = (x) =>
  x === null || x === undefined
    ? String(x)
    : `a ${typeof x === 'object' ? (x.constructor?.name ?? 'object') : typeof x}`;

// ---- BufferGeometry -> Mesh ----------------------------------------------------------------------

// The `count` items of `width` floats of a three.js attribute (plain, interleaved or normalized)
// as one packed Float32Array; narrower items are padded with `pad` (a colour's alpha).
function packedFloats(call, name, attribute, width, pad = 1) {
  const size = attribute.itemSize;
  if (size > width || size < Math.min(width, 3))
    throw invalid(call, `attribute '${name}' has ${size} components, expected ${width}`);
  const n = attribute.count;
  const plain =
    !attribute.isInterleavedBufferAttribute &&
    !attribute.normalized &&
    attribute.array instanceof Float32Array;
  if (plain && size === width) return attribute.array.subarray(0, n * width);
  const out = new Float32Array(n * width);
  const get = ['getX', 'getY', 'getZ', 'getW'];
  for (let i = 0; i < n; ++i)
    for (let k = 0; k < width; ++k) out[i * width + k] = k < size ? attribute[get[k]](i) : pad;
  return out;
}

// One submesh id per triangle from the geometry's groups: a group's triangles take its
// materialIndex; a triangle in several groups takes the last one's, one in none takes 0.
function groupSubmeshes(call, geometry, triangles) {
  if (geometry.groups.length === 0) return undefined;
  const ids = new Int32Array(triangles);
  geometry.groups.forEach(({ start, count, materialIndex = 0 }, g) => {
    if (start % 3 !== 0 || (count !== Infinity && count % 3 !== 0))
      throw invalid(
        call,
        `group ${g} (start ${start}, count ${count}) does not hold whole triangles`,
      );
    if (!(Number.isInteger(materialIndex) && materialIndex >= 0 && materialIndex <= 65535))
      throw invalid(call, `group ${g}: materialIndex ${materialIndex} is not in [0, 65535]`);
    const first = start / 3;
    const end = Math.min(triangles, count === Infinity ? triangles : first + count / 3);
    for (let t = first; t < end; ++t) ids[t] = materialIndex;
  });
  return ids;
}

/** Builds a hedge Mesh from a THREE.BufferGeometry (indexed or not) with hedge.fromEngineStreams:
 *  positions are welded into vertices (options.weld: 'exact' by default, 'epsilon', 'none') while
 *  the attributes stay per corner, so seams and hard edges survive. Kept, each unless its option is
 *  false: normals ('normal'), uvs ('uv'), colors ('color', 3 or 4 components; alpha 1 when 3), and
 *  groups (each triangle's group materialIndex as its submesh, "f:submesh"). options.policy:
 *  'repair' (default) or 'strict'. The whole index is read (the draw range is not applied); morph
 *  targets and skinning are not. A geometry without positions, an attribute of the wrong width, an
 *  index count not a multiple of 3 or a bad group throws a HedgeError of kind 'invalid-argument'
 *  naming it; the library checks the rest (non-finite values, indices out of range). */
export function fromBufferGeometry(hedge, geometry, options = {}) {
  const call = 'fromBufferGeometry';
  if (typeof hedge?.fromEngineStreams !== 'function')
    throw invalid(call, `hedge must be the loaded module (loadHedge()), got ${describe(hedge)}`);
  if (!geometry?.isBufferGeometry)
    throw invalid(call, `geometry must be a THREE.BufferGeometry, got ${describe(geometry)}`);
  if (options === null || typeof options !== 'object')
    throw invalid(call, `options must be an object, got ${describe(options)}`);
  const { normals = true, uvs = true, colors = true, groups = true } = options;
  const position = geometry.getAttribute('position');
  if (!position) throw invalid(call, "the geometry has no 'position' attribute");
  const positions = packedFloats(call, 'position', position, 3);
  let indices;
  if (geometry.index) {
    const index = geometry.index;
    indices =
      index.array instanceof Uint32Array
        ? index.array.subarray(0, index.count)
        : Uint32Array.from(index.array.subarray(0, index.count));
  } else {
    indices = new Uint32Array(position.count);
    for (let i = 0; i < indices.length; ++i) indices[i] = i;
  }
  if (indices.length % 3 !== 0)
    throw invalid(call, `${indices.length} indices is not 3 per triangle`);
  const attribute = (name, width, wanted) => {
    const a = wanted ? geometry.getAttribute(name) : undefined;
    if (!a) return undefined;
    if (a.count !== position.count)
      throw invalid(
        call,
        `attribute '${name}' has ${a.count} items for ${position.count} vertices`,
      );
    return packedFloats(call, name, a, width);
  };
  return hedge.fromEngineStreams({
    positions,
    indices,
    normals: attribute('normal', 3, normals),
    texcoords: attribute('uv', 2, uvs),
    colors: attribute('color', 4, colors),
    submeshes: groups ? groupSubmeshes(call, geometry, indices.length / 3) : undefined,
    policy: options.policy,
    weld: options.weld,
  });
}

// ---- Mesh -> BufferGeometry, and syncing ------------------------------------------------------

// What a live geometry mirrors: its RenderBuffers and mesh, and the layout its arrays were made for.
const links = new WeakMap();

// The three.js attributes of RenderBuffers' streams: [name, layout field, item size, stream getter].
const STREAMS = [
  ['position', 'position', 3, 'vertices'],
  ['normal', 'normal', 3, 'normals'],
  ['uv', 'texcoord', 2, 'texcoords'],
  ['color', 'color', 4, 'colors'],
];

// Allocates the geometry's arrays (at `capacity` sizes) and copies the buffers whole; sets the
// groups and draw range. Returns the bytes copied.
function fill(geometry, render, dynamic) {
  const layout = render.layout;
  const sizes = render.sizes();
  const vertexCount = dynamic ? Math.max(sizes.vertexCapacity, 1) : sizes.vertexSlots;
  const indexCount = dynamic ? Math.max(sizes.indexCapacity, 3) : sizes.indexCount;
  const usage = (a) => (dynamic ? a.setUsage(DynamicDrawUsage) : a);
  for (const [name] of STREAMS) geometry.deleteAttribute(name);
  let bytes = 0;
  if (layout.interleaved) {
    const array = new Float32Array(vertexCount * layout.stride);
    array.set(render.vertices);
    bytes += render.vertices.byteLength;
    const buffer = usage(new InterleavedBuffer(array, layout.stride));
    for (const [name, field, size] of STREAMS)
      if (layout[field] >= 0)
        geometry.setAttribute(name, new InterleavedBufferAttribute(buffer, size, layout[field]));
  } else {
    for (const [name, field, size, stream] of STREAMS) {
      if (layout[field] < 0) continue;
      const view = render[stream];
      const array = new Float32Array(vertexCount * size);
      array.set(view);
      bytes += view.byteLength;
      geometry.setAttribute(name, usage(new BufferAttribute(array, size)));
    }
  }
  const index = new Uint32Array(indexCount);
  index.set(render.indices);
  bytes += sizes.indexCount * 4;
  geometry.setIndex(usage(new BufferAttribute(index, 1)));
  setGroups(geometry, render, sizes.indexCount);
  geometry.boundingBox = new Box3();
  geometry.boundingSphere = new Sphere();
  growBounds(geometry, 0, sizes.vertexSlots, true);
  return { bytes, layout, vertexCount, indexCount };
}

const _p = new Vector3();

// Grows the geometry's bounds by render vertices [first, first + count). The arrays hold more
// vertices than are in use (their capacity, zero-filled beyond), which three.js's own
// computeBoundingBox would count in, so the bounds are kept here: made exact by a full fill
// (fresh: the sphere then centred on the box), grown by each sync's rewritten vertices (they
// only grow, so they stay bounds after vertices move inward).
function growBounds(geometry, first, count, fresh = false) {
  const position = geometry.getAttribute('position');
  const box = geometry.boundingBox;
  const sphere = geometry.boundingSphere;
  for (let i = first; i < first + count; ++i)
    box.expandByPoint(_p.fromBufferAttribute(position, i));
  if (fresh) {
    if (box.isEmpty()) return sphere.makeEmpty();
    box.getCenter(sphere.center);
    let r2 = 0;
    for (let i = first; i < first + count; ++i)
      r2 = Math.max(r2, sphere.center.distanceToSquared(_p.fromBufferAttribute(position, i)));
    sphere.radius = Math.sqrt(r2);
  } else {
    for (let i = first; i < first + count; ++i)
      sphere.expandByPoint(_p.fromBufferAttribute(position, i));
  }
}

// One group per submesh that has triangles, and the draw range over the buffers in use.
function setGroups(geometry, render, indexCount) {
  geometry.clearGroups();
  render.submeshes().forEach(({ indexStart, indexCount: count, empty }, i) => {
    if (count > 0 && !empty) geometry.addGroup(indexStart, count, i);
  });
  geometry.setDrawRange(0, indexCount);
}

/** The mesh as a THREE.BufferGeometry: position, normal, uv and color (4 components) attributes as
 *  RenderBuffers writes them (one vertex per distinct set of corner attributes), an index, and one
 *  group per submesh (materialIndex: the submesh id). With options.renderBuffers (the mesh's own,
 *  from mesh.createRenderBuffers()) the geometry is live: it follows that RenderBuffers' layout,
 *  its arrays are allocated at its capacities (dynamic draw usage; the draw range covers the
 *  buffers in use), syncBufferGeometry() keeps it in step with edits, and hedgeRaycast picks on it.
 *  Without, it is a copy, made through a RenderBuffers of options {normals ('auto'), texcoords,
 *  colors (true), interleaved (false)} that is freed at once. */
export function toBufferGeometry(mesh, options = {}) {
  const call = 'toBufferGeometry';
  if (typeof mesh?.createRenderBuffers !== 'function')
    throw invalid(call, `mesh must be a hedge Mesh, got ${describe(mesh)}`);
  if (options === null || typeof options !== 'object')
    throw invalid(call, `options must be an object, got ${describe(options)}`);
  const { renderBuffers, normals = 'auto', texcoords = true, colors = true } = options;
  const { interleaved = false } = options;
  if (renderBuffers !== undefined && typeof renderBuffers?.sync !== 'function')
    throw invalid(
      call,
      `options.renderBuffers must be a RenderBuffers, got ${describe(renderBuffers)}`,
    );
  const geometry = new BufferGeometry();
  if (renderBuffers) {
    renderBuffers.sync();
    const made = fill(geometry, renderBuffers, true);
    links.set(geometry, { mesh, render: renderBuffers, ...made });
    return geometry;
  }
  const render = mesh.createRenderBuffers({ normals, texcoords, colors, interleaved });
  try {
    fill(geometry, render, false);
  } finally {
    render.dispose();
  }
  return geometry;
}

// Copies `count` items of `width` floats from `from` into `to` at item `first`.
function copyRange(to, from, first, count, width) {
  to.set(from.subarray(first * width, (first + count) * width), first * width);
}

/** Brings a live geometry (toBufferGeometry with a renderBuffers) in step with its mesh's edits:
 *  syncs the RenderBuffers (or takes `result`, the result of a sync already done), copies the
 *  rewritten ranges into the geometry's arrays and marks only those for upload
 *  (addUpdateRange), so three.js sends just them to the GPU (bufferSubData). When the sync was full
 *  or resized the buffers (or its layout changed), the geometry is disposed (freeing its GPU
 *  buffers) and refilled whole at the new capacities; attributes are then new objects. Updates the
 *  groups, the draw range and the bounds (boundingBox, boundingSphere: grown by the rewritten
 *  vertices, so they still bound the mesh, perhaps loosely, after vertices move inward; call
 *  geometry.computeBoundingBox() for exact ones, which counts the unused capacity in as zeros). Returns {result, full, bytes (copied for upload), ranges}. */
export function syncBufferGeometry(geometry, renderBuffers, result) {
  const call = 'syncBufferGeometry';
  const link = geometry?.isBufferGeometry ? links.get(geometry) : undefined;
  if (!link)
    throw invalid(call, 'geometry must be made by toBufferGeometry(mesh, {renderBuffers})');
  const render = renderBuffers ?? link.render;
  if (render !== link.render)
    throw invalid(call, 'renderBuffers is not the one the geometry was made with');
  const r = result ?? render.sync();
  const layout = render.layout;
  const sizes = render.sizes();
  const stride = layout.interleaved ? layout.stride : 0;
  const outgrown =
    sizes.vertexSlots > link.vertexCount ||
    sizes.indexCount > link.indexCount ||
    stride !== (link.layout.interleaved ? link.layout.stride : 0) ||
    STREAMS.some(([, field]) => layout[field] >= 0 !== link.layout[field] >= 0);
  if (r.resized || r.full || outgrown) {
    geometry.dispose();
    Object.assign(link, fill(geometry, render, true));
    return { result: r, full: true, bytes: link.bytes, ranges: 1 };
  }
  let bytes = 0;
  const vertexRanges = r.vertexRanges;
  const attributes = STREAMS.filter(([, field]) => layout[field] >= 0);
  for (let k = 0; k < vertexRanges.length; k += 2) {
    const first = vertexRanges[k];
    const count = vertexRanges[k + 1];
    if (count === 0) continue;
    if (layout.interleaved) {
      const buffer = geometry.getAttribute('position').data;
      copyRange(buffer.array, render.vertices, first, count, stride);
      buffer.addUpdateRange(first * stride, count * stride);
      bytes += count * stride * 4;
    } else {
      for (const [name, , size, stream] of attributes) {
        const attribute = geometry.getAttribute(name);
        copyRange(attribute.array, render[stream], first, count, size);
        attribute.addUpdateRange(first * size, count * size);
        bytes += count * size * 4;
      }
    }
  }
  const indexRanges = r.indexRanges;
  const index = geometry.getIndex();
  for (let k = 0; k < indexRanges.length; k += 2) {
    const first = indexRanges[k];
    const count = indexRanges[k + 1];
    if (count === 0) continue;
    copyRange(index.array, render.indices, first, count, 1);
    index.addUpdateRange(first, count);
    bytes += count * 4;
  }
  if (vertexRanges.length) {
    if (layout.interleaved) geometry.getAttribute('position').data.needsUpdate = true;
    else for (const [name] of attributes) geometry.getAttribute(name).needsUpdate = true;
    for (let k = 0; k < vertexRanges.length; k += 2)
      growBounds(geometry, vertexRanges[k], vertexRanges[k + 1]);
  }
  if (indexRanges.length) index.needsUpdate = true;
  setGroups(geometry, render, sizes.indexCount);
  return { result: r, full: false, bytes, ranges: (vertexRanges.length + indexRanges.length) / 2 };
}

// ---- Raycasting ----------------------------------------------------------------------------------

const threeRaycast = ThreeMesh.prototype.raycast;
const _inverse = new Matrix4();
const _ray = new Ray();
const _a = new Vector3();
const _b = new Vector3();
const _c = new Vector3();
const _point = new Vector3();
const _best = new Vector3();
const _world = new Vector3();
const _origin = [0, 0, 0];
const _direction = [0, 0, 0];

// The material drawing triangle slot t (an array of materials is indexed by t's group).
function materialOf(object, geometry, t) {
  const material = object.material;
  if (!Array.isArray(material)) return { material, materialIndex: 0 };
  for (const group of geometry.groups)
    if (t * 3 >= group.start && t * 3 < group.start + group.count)
      return { material: material[group.materialIndex], materialIndex: group.materialIndex };
  return { material: undefined, materialIndex: 0 };
}

// The nearest hit of the local ray on triangle slots [first, first + count) of the geometry, as
// three.js's own raycast computes it (its culling by the material's side included):
// {t, distance, materialIndex} with the point in _best, or null.
function hitSlots(object, geometry, first, count, raycaster) {
  const index = geometry.index.array;
  const position = geometry.getAttribute('position');
  let best = null;
  for (let t = first; t < first + count; ++t) {
    const { material, materialIndex } = materialOf(object, geometry, t);
    if (!material) continue;
    _a.fromBufferAttribute(position, index[3 * t]);
    _b.fromBufferAttribute(position, index[3 * t + 1]);
    _c.fromBufferAttribute(position, index[3 * t + 2]);
    const hit =
      material.side === BackSide
        ? _ray.intersectTriangle(_c, _b, _a, true, _point)
        : _ray.intersectTriangle(_a, _b, _c, material.side === FrontSide, _point);
    if (hit === null) continue;
    _world.copy(_point).applyMatrix4(object.matrixWorld);
    const distance = raycaster.ray.origin.distanceTo(_world);
    if (distance < raycaster.near || distance > raycaster.far) continue;
    if (best === null || distance < best.distance) {
      best = { t, distance, materialIndex };
      _best.copy(_point);
    }
  }
  return best;
}

// The nearest hit (as hitSlots) on the faces around the corner and across the edge nearest to
// where the picking tree hit face `face`: a ray through an edge or a corner may pass three.js's
// test on a neighbour of the face hedge found, not on that face.
function hitNeighbours(object, geometry, link, face, raycaster) {
  const hit = link.mesh.pick(_origin, _direction);
  if (hit === null || hit.face !== face) return null;
  const faces = new Set([
    ...link.mesh.oneRing(hit.vertex).faces,
    ...link.mesh.edge(hit.edge).faces,
  ]);
  faces.delete(face);
  faces.delete(-1);
  let best = null;
  let point = null;
  for (const f of faces) {
    const [first, count] = link.render.faceTriangles(f);
    const h = hitSlots(object, geometry, first, count, raycaster);
    if (h !== null && (best === null || h.distance < best.distance)) {
      best = h;
      point = _best.clone();
    }
  }
  if (point) _best.copy(point);
  return best;
}

// The intersection record three.js makes for a hit at _best on triangle slot t.
function intersection(object, geometry, { t, distance, materialIndex }) {
  const index = geometry.index.array;
  const [a, b, c] = [index[3 * t], index[3 * t + 1], index[3 * t + 2]];
  const position = geometry.getAttribute('position');
  _a.fromBufferAttribute(position, a);
  _b.fromBufferAttribute(position, b);
  _c.fromBufferAttribute(position, c);
  const barycoord = new Vector3();
  Triangle.getBarycoord(_best, _a, _b, _c, barycoord);
  const face = { a, b, c, normal: new Vector3(), materialIndex };
  Triangle.getNormal(_a, _b, _c, face.normal);
  const out = {
    distance,
    point: _best.clone().applyMatrix4(object.matrixWorld),
    object,
    face,
    faceIndex: t,
    barycoord,
  };
  const uv = geometry.getAttribute('uv');
  if (uv) out.uv = Triangle.getInterpolatedAttribute(uv, a, b, c, barycoord, new Vector2());
  const normal = geometry.getAttribute('normal');
  if (normal) {
    out.normal = Triangle.getInterpolatedAttribute(normal, a, b, c, barycoord, new Vector3());
    if (out.normal.dot(_ray.direction) > 0) out.normal.multiplyScalar(-1);
  }
  return out;
}

/** A raycast for THREE.Mesh through hedge's picking tree (a bounding volume hierarchy kept up to
 *  date with edits), in the manner of three-mesh-bvh's acceleratedRaycast: assign it to one mesh
 *  (object.raycast = hedgeRaycast) or to THREE.Mesh.prototype.raycast. On a live geometry
 *  (toBufferGeometry with a renderBuffers, synced after the last edit) it adds the nearest hit to
 *  `intersects` with the fields three.js gives (distance, point, object, face {a, b, c, normal,
 *  materialIndex}, faceIndex (the triangle's index, its slot in the index buffer), barycoord, uv
 *  and normal when the geometry has them), computed by three.js's own triangle test, so they equal
 *  three's; the material's side, near and far are honoured. It reports only the nearest hit (as
 *  three-mesh-bvh with firstHitOnly). Any other mesh falls back to three.js's raycast. */
export function hedgeRaycast(raycaster, intersects) {
  const geometry = this.geometry;
  const link = geometry ? links.get(geometry) : undefined;
  if (!link || link.mesh.disposed || link.render.disposed || geometry.morphAttributes.position)
    return threeRaycast.call(this, raycaster, intersects);
  if (this.material === undefined) return;
  _inverse.copy(this.matrixWorld).invert();
  _ray.copy(raycaster.ray).applyMatrix4(_inverse);
  _ray.origin.toArray(_origin);
  _ray.direction.toArray(_direction);
  // The picking tree gives the first face along the ray; when the material culls it (its back
  // side) or it lies before `near`, the ray goes on from just past it.
  const scale = Math.max(geometry.boundingSphere?.radius ?? 1, 1e-30);
  for (let step = 0; step < 64; ++step) {
    const hit = link.render.pickTriangles(_origin, _direction);
    if (hit === null) return;
    let best = hitSlots(this, geometry, hit.first, hit.count, raycaster);
    if (best === null) best = hitNeighbours(this, geometry, link, hit.face, raycaster);
    if (best !== null) {
      intersects.push(intersection(this, geometry, best));
      return;
    }
    for (let k = 0; k < 3; ++k) _origin[k] = hit.point[k] + _direction[k] * scale * 1e-6;
  }
}

/** Whether hedgeRaycast picks on `geometry` through hedge (a live geometry of a live mesh). */
export function isHedgeGeometry(geometry) {
  const link = links.get(geometry);
  return Boolean(link && !link.mesh.disposed && !link.render.disposed);
}
