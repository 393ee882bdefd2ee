// Types of hedge's worker helper (worker_client.js, the page side, imported as 'hedge-mesh/worker';
// worker.js is the worker side). Meshes live in the worker, named by id; every method returns a
// promise, and every typed array of a result was transferred from the worker, not copied. A
// failure rejects with a HedgeError of the same kind and message as the call on the page throws.
import type {
  Arrays,
  BuildReport,
  Counts,
  DecimateResult,
  FractureOptions,
  FractureResult,
  Pick,
  Piece,
  SolidFractureOptions,
  SolidFractureResult,
  SolidRefusal,
  Shard,
  SmoothMethod,
  SubdivisionScheme,
  Vec3,
} from './hedge.js';

export interface Loaded {
  /** The mesh's id in the worker. */
  id: number;
  counts: Counts;
}

/** A shard as the worker sends it: its mesh stays in the worker under id. */
export type RemoteShard = Omit<Shard, 'mesh' | 'dispose'> & { id: number };

export interface RemoteFractureResult extends Omit<FractureResult, 'shards'> {
  shards: RemoteShard[];
}

export type RemotePiece = Omit<Piece, 'mesh' | 'dispose'> & { id: number };

export interface RemoteSolidFractureResult extends Omit<SolidFractureResult, 'pieces'> {
  pieces: RemotePiece[];
}

/** What fractureSolid() with kind 'auto' resolves to for a mesh solid fracture refuses for its
 *  shape: the shards of fracture(), with the refusal and its code. */
export interface RemoteSurfaceFallbackResult extends RemoteFractureResult {
  kind: 'surface';
  /** Why solid fracture was refused. */
  refusal: string;
  /** The refusal's code: 'open' or 'non_manifold'. */
  refusalCode: 'open' | 'non_manifold';
}

export interface DrawBuffers {
  /** 3 per render vertex. */
  positions: Float32Array;
  /** 3 per triangle slot. */
  indices: Uint32Array;
  /** 3 per render vertex; empty for normals: 'none'. */
  normals: Float32Array;
}

export interface HedgeWorker {
  /** The worker: a Worker (browser), a worker_threads Worker (node) or a MessagePort. */
  readonly port: unknown;
  version(): Promise<string>;
  /** Reads a mesh from a file's bytes (hedge.fromFile). transfer: true hands the bytes' buffer to
   *  the worker instead of copying it (it is detached on the page). */
  load(
    bytes: Uint8Array | ArrayBuffer,
    name: string,
    options?: { transfer?: boolean },
  ): Promise<Loaded & { report: BuildReport }>;
  fromBuffers(arrays: {
    positions: Float32Array;
    indices: Uint32Array;
    faceSizes?: Uint32Array;
    policy?: 'repair' | 'strict';
    weld?: 'none' | 'exact' | 'epsilon';
  }): Promise<Loaded>;
  counts(id: number): Promise<Counts>;
  validate(id: number): Promise<string[]>;
  /** Resolves to the counts after subdividing. */
  subdivide(id: number, scheme?: SubdivisionScheme, steps?: number): Promise<Counts>;
  smooth(
    id: number,
    options?: {
      method?: SmoothMethod;
      iterations?: number;
      lambda?: number;
      mu?: number;
      fixBoundary?: boolean;
    },
  ): Promise<Counts>;
  decimate(
    id: number,
    options: { ratio?: number; targetFaces?: number; targetVertices?: number; maxError?: number },
  ): Promise<DecimateResult>;
  /** Builds the mesh's picking tree now (the first pick would), off the page: {seconds}. */
  buildPickingTree(id: number): Promise<{ seconds: number }>;
  pick(id: number, origin: Vec3, direction: Vec3): Promise<Pick | null>;
  pickMany(id: number, rays: Float32Array): Promise<Int32Array>;
  /** Mesh.fracture(); each shard's mesh stays in the worker (dispose(shard.id) frees it). */
  fracture(id: number, impact: Vec3, options?: FractureOptions): Promise<RemoteFractureResult>;
  /** Mesh.fractureSolid(); each piece's mesh stays in the worker (dispose(piece.id) frees it). */
  fractureSolid(
    id: number,
    impact: Vec3,
    options?: SolidFractureOptions,
  ): Promise<RemoteSolidFractureResult | RemoteSurfaceFallbackResult>;
  /** Mesh.solidFractureRefusal(): why fractureSolid() would be refused, or null. */
  solidFractureRefusal(
    id: number,
    impact: Vec3,
    options?: Omit<SolidFractureOptions, 'kind'>,
  ): Promise<string | null>;
  /** Mesh.solidFractureRefusalCode(): the refusal as a code ('none' when the strike can be made;
   *  'open' and 'non_manifold' are what fractureSolid() with kind 'auto' breaks by surface
   *  fracture, any other code rejects with either kind). */
  solidFractureRefusalCode(
    id: number,
    impact: Vec3,
    options?: Omit<SolidFractureOptions, 'kind' | 'surface'>,
  ): Promise<SolidRefusal>;
  /** Draw buffers of the mesh as a RenderBuffers (not interleaved) makes them. normals as
   *  createRenderBuffers's; default 'auto'. */
  buffers(
    id: number,
    options?: { normals?: 'auto' | 'computed' | 'attribute' | 'none' },
  ): Promise<DrawBuffers>;
  computeCornerNormals(id: number, creaseDegrees?: number): Promise<void>;
  toArrays(id: number, options?: { triangulate?: boolean }): Promise<Arrays>;
  toFile(id: number, name: string): Promise<Uint8Array>;
  /** Frees the mesh in the worker (an unknown id does nothing). */
  dispose(id: number): Promise<void>;
  /** Runs a call of worker.js by name; transfer lists buffers of args to hand over. */
  call(op: string, args?: unknown[], transfer?: ArrayBuffer[]): Promise<unknown>;
  /** Stops the worker; calls still waiting reject with a HedgeError of kind 'bad-handle'. */
  terminate(): void;
}

export declare const HedgeWorker: {
  /** port: a Worker or MessagePort serving worker.js (see createHedgeWorker). */
  new (port: unknown): HedgeWorker;
};

/** Starts worker.js in a module worker and resolves once hedge is loaded there. options.worker:
 *  a Worker (or MessagePort) you started on worker.js yourself. */
export function createHedgeWorker(options?: { worker?: unknown }): Promise<HedgeWorker>;
