// Types of hedge's three.js adapter (three.js). three.js is a peer dependency.
import type { BufferGeometry, Intersection, Mesh as ThreeMesh, Raycaster } from 'three';
import type { Hedge, Mesh, RenderBuffers, SyncResult } from './hedge.js';

export interface FromBufferGeometryOptions {
  /** Keep the 'normal' attribute per corner. Default true. */
  normals?: boolean;
  /** Keep the 'uv' attribute per corner. Default true. */
  uvs?: boolean;
  /** Keep the 'color' attribute (3 or 4 components; alpha 1 when 3) per corner. Default true. */
  colors?: boolean;
  /** Keep the groups: each triangle's group materialIndex (in [0, 65535]) as its submesh. A
   *  triangle in several groups takes the last one's; one in none takes 0. Default true. */
  groups?: boolean;
  /** How positions are welded into vertices. Default 'exact'. */
  weld?: 'none' | 'exact' | 'epsilon';
  policy?: 'repair' | 'strict';
}

/** A hedge Mesh from a BufferGeometry (indexed or not; the whole index, not the draw range). A bad
 *  geometry throws a HedgeError of kind 'invalid-argument' naming what is wrong. */
export function fromBufferGeometry(
  hedge: Hedge,
  geometry: BufferGeometry,
  options?: FromBufferGeometryOptions,
): Mesh;

export interface ToBufferGeometryOptions {
  /** The mesh's own RenderBuffers: the geometry is then live (syncBufferGeometry, hedgeRaycast)
   *  and follows its layout. Without, the geometry is a copy made with the options below. */
  renderBuffers?: RenderBuffers;
  normals?: 'auto' | 'computed' | 'attribute' | 'none';
  texcoords?: boolean;
  colors?: boolean;
  /** One interleaved vertex buffer. Default false (one attribute per stream). */
  interleaved?: boolean;
}

/** The mesh as a BufferGeometry: position, normal, uv, color (4 components), an index, and one
 *  group per submesh (materialIndex: the submesh id). */
export function toBufferGeometry(mesh: Mesh, options?: ToBufferGeometryOptions): BufferGeometry;

export interface GeometrySync {
  /** The RenderBuffers' sync result the geometry was updated from. */
  result: SyncResult;
  /** The geometry was refilled whole (a full or resized sync); its attributes are new objects. */
  full: boolean;
  /** Bytes copied and marked for upload. */
  bytes: number;
  /** Ranges marked for upload (addUpdateRange), vertex and index ranges. */
  ranges: number;
}

/** Brings a live geometry in step with its mesh: syncs renderBuffers (or takes `result`, a sync
 *  already done) and marks only the rewritten ranges for upload. renderBuffers defaults to the one
 *  the geometry was made with. */
export function syncBufferGeometry(
  geometry: BufferGeometry,
  renderBuffers?: RenderBuffers,
  result?: SyncResult,
): GeometrySync;

/** THREE.Mesh's raycast through hedge's picking tree, for a live geometry (any other falls back to
 *  three.js's): the nearest hit, with the fields three.js gives. Assign it to a mesh's raycast or to
 *  THREE.Mesh.prototype.raycast. */
export function hedgeRaycast(
  this: ThreeMesh,
  raycaster: Raycaster,
  intersects: Intersection[],
): void;

/** Whether hedgeRaycast picks on the geometry through hedge. */
export function isHedgeGeometry(geometry: BufferGeometry): boolean;
