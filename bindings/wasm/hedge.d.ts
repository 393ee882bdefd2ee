// Types of the hedge JS API (hedge.js). Element indices are numbers; -1 means "none".

export type ErrorKind = 'invalid-argument' | 'io' | 'topology' | 'refused' | 'out-of-memory' | 'internal' | 'disposed';

export class HedgeError extends Error {
  readonly kind: ErrorKind;
}

export type SubdivisionScheme = 'loop' | 'midpoint' | 'catmull-clark' | 'sqrt3' | 'split-faces';
export type SmoothMethod = 'uniform' | 'taubin' | 'cotangent' | 'implicit';
export type Operation = 'splitEdge' | 'flip' | 'collapse' | 'splitFace';
export type Vec3 = [number, number, number] | Float32Array | Float64Array;

export const subdivisionSchemes: readonly SubdivisionScheme[];
export const smoothingMethods: readonly SmoothMethod[];

export interface LoadOptions {
  /** The bytes of hedge.wasm, when they are at hand (node, tests). */
  wasmBinary?: ArrayBuffer | Uint8Array;
  /** Where to fetch hedge.wasm from (a bundler's asset URL). */
  locateFile?: (name: string, prefix: string) => string;
  [option: string]: unknown;
}

export function loadHedge(options?: LoadOptions): Promise<Hedge>;

export interface BuildReport {
  weldedVertices: number;
  degenerateFaces: number;
  repeatedCorners: number;
  reorientedFaces: number;
  nonManifoldEdges: number;
  nonManifoldVertices: number;
  duplicatedVertices: number;
  isolatedVertices: number;
  repairs: number;
  warnings: string[];
}

export interface Counts {
  vertices: number;
  edges: number;
  halfedges: number;
  faces: number;
  vertexSlots: number;
  halfedgeSlots: number;
  edgeSlots: number;
  faceSlots: number;
}

export interface HalfedgeRecord {
  halfedge: number;
  origin: number;
  target: number;
  twin: number;
  face: number;
  next: number;
  prev: number;
  edge: number;
  boundary: boolean;
}

export interface VertexRecord {
  vertex: number;
  halfedge: number;
  position: [number, number, number];
  valence: number;
  boundary: boolean;
  isolated: boolean;
}

export interface EdgeRecord {
  edge: number;
  halfedges: [number, number];
  vertices: [number, number];
  faces: [number, number];
  boundary: boolean;
}

export interface FaceRecord {
  face: number;
  halfedge: number;
  halfedges: number[];
  vertices: number[];
  edges: number[];
  boundary: boolean;
}

export interface OneRing {
  vertex: number;
  halfedges: number[];
  vertices: number[];
  edges: number[];
  faces: number[];
}

export interface Pick {
  face: number;
  t: number;
  point: [number, number, number];
  halfedge: number;
  edge: number;
  vertex: number;
  edgeDistance: number;
  vertexDistance: number;
  corners: [number, number, number];
  barycentric: [number, number, number];
}

export interface DecimateResult {
  vertices: number;
  faces: number;
  collapses: number;
  maxError: number;
}

export interface Arrays {
  positions: Float32Array;
  indices: Uint32Array;
  faceSizes: Uint32Array | null;
}

export class Hedge {
  readonly module: unknown;
  fromBuffers(input: {
    positions: Float32Array | number[];
    indices: Uint32Array | number[];
    faceSizes?: Uint32Array | number[];
    policy?: 'repair' | 'strict';
    weld?: 'none' | 'exact' | 'epsilon';
  }): Mesh;
  fromFile(bytes: Uint8Array | ArrayBuffer, name: string): Mesh;
  heapBytesInUse(): number;
  readonly memoryBytes: number;
  readonly version: string;
}

export class Mesh {
  readonly hedge: Hedge;
  dispose(): void;
  readonly disposed: boolean;
  clone(): Mesh;
  buildReport(): BuildReport;
  counts(): Counts;
  validate(): string[];
  isValid(): boolean;
  isTriangleMesh(): boolean;
  readonly positions: Float32Array;
  position(v: number): [number, number, number];
  setPosition(v: number, point: Vec3): void;
  halfedge(h: number): HalfedgeRecord;
  vertex(v: number): VertexRecord;
  edge(e: number): EdgeRecord;
  face(f: number): FaceRecord;
  oneRing(v: number): OneRing;
  pick(origin: Vec3, direction: Vec3): Pick | null;
  pickMany(rays: Float32Array, out?: Int32Array): Int32Array;
  whyNot(op: Operation, element: number): string | null;
  canSplitEdge(e: number): boolean;
  canFlip(e: number): boolean;
  canCollapse(h: number): boolean;
  canSplitFace(f: number): boolean;
  splitEdge(e: number, point?: Vec3): number;
  flip(e: number): number;
  collapse(h: number, point?: Vec3): number;
  splitFace(f: number, point?: Vec3): number;
  garbageCollection(): void;
  subdivide(scheme?: SubdivisionScheme, steps?: number): void;
  smooth(options?: { method?: SmoothMethod; iterations?: number; lambda?: number; mu?: number; fixBoundary?: boolean }): void;
  decimate(options: { ratio?: number; targetFaces?: number; targetVertices?: number; maxError?: number }): DecimateResult;
  toArrays(options?: { triangulate?: boolean }): Arrays;
  toFile(name: string): Uint8Array;
  memoryBytes(): number;
  createRender(options?: {
    normals?: 'auto' | 'computed' | 'attribute' | 'none';
    interleaved?: boolean;
    texcoords?: boolean;
    colors?: boolean;
  }): Render;
}

export interface Layout {
  stride: number;
  position: number;
  normal: number;
  texcoord: number;
  color: number;
  interleaved: boolean;
}

export interface RenderSizes {
  vertexSlots: number;
  triangleSlots: number;
  indexCount: number;
  vertices: number;
  triangles: number;
  vertexCapacity: number;
  indexCapacity: number;
  freeTriangleSlots: number;
  bufferBytes: number;
}

export interface SyncResult {
  /** Pairs [first, count] of render vertices. */
  vertexRanges: Uint32Array;
  /** Pairs [first, count] of index-buffer entries. */
  indexRanges: Uint32Array;
  vertexBytes: number;
  indexBytes: number;
  facesSynced: number;
  verticesSynced: number;
  resized: boolean;
  full: boolean;
}

export class Render {
  readonly hedge: Hedge;
  dispose(): void;
  readonly disposed: boolean;
  readonly layout: Layout;
  sizes(): RenderSizes;
  readonly vertices: Float32Array;
  readonly normals: Float32Array;
  readonly texcoords: Float32Array;
  readonly colors: Float32Array;
  readonly indices: Uint32Array;
  readonly vertexSource: Uint32Array;
  faceTriangles(f: number): [number, number];
  sync(): SyncResult;
  dirtyViews(result: SyncResult): { vertices: Float32Array[]; indices: Uint32Array[] };
  rebuild(): SyncResult;
  compact(): void;
  begin(): void;
  commit(): SyncResult;
}

/** node only (node.js): loadHedge with the wasm read from disk. */
export function loadHedgeNode(options?: LoadOptions): Promise<Hedge>;
