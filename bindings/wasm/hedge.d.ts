// Types of the hedge JS API (hedge.js, and hedge.single.js: the same API). Element indices are
// numbers; -1 means "none". The node entry's types (node.d.ts) add loadHedgeNode.

/** The C ABI's status codes (hedge_status), one to one. */
export type ErrorKind =
  | 'invalid-argument'
  | 'bad-handle'
  | 'refused'
  | 'io'
  | 'topology'
  | 'out-of-memory'
  | 'buffer-too-small'
  | 'internal'
  | 'busy';

/** Every failure. A wrong argument (null, undefined, a wrong type, an array of the wrong length)
 *  throws one of kind 'invalid-argument' before the call runs, its message naming the call and the
 *  argument ("pick: origin must be [x, y, z] (...), got null"). */
export class HedgeError extends Error {
  readonly kind: ErrorKind;
  /** A refused edit's reason (the library's refusal); null for other errors. */
  readonly refusal: string | null;
}

export type SubdivisionScheme = 'loop' | 'midpoint' | 'catmull-clark' | 'sqrt3' | 'split-faces';
export type SmoothMethod = 'uniform' | 'taubin' | 'cotangent' | 'implicit';
export type Operation = 'splitEdge' | 'flip' | 'collapse' | 'splitFace' | 'cutFace' | 'fillHole';
export type Vec3 = [number, number, number] | Float32Array | Float64Array;

export const subdivisionSchemes: readonly SubdivisionScheme[];
export const smoothingMethods: readonly SmoothMethod[];
export type FracturePreset = 'glass' | 'stone' | 'wood' | 'ice';
export const fractureMaterials: readonly FracturePreset[];

export interface LoadOptions {
  /** The bytes of hedge.wasm, when they are at hand. */
  wasmBinary?: ArrayBuffer | Uint8Array;
  /** Where to fetch hedge.wasm from (a bundler's asset URL); under node, a path or a file: URL to
   *  read it from. Without it the wasm beside hedge.mjs is used. */
  locateFile?: (name: string, prefix: string) => string;
  [option: string]: unknown;
}

/** Loads the module: in node (ES module), a browser page, a module worker or a bundle; sets no
 *  globals. The same in the single-file variant (the package's "./single"), whose wasm is embedded. */
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
  /** Across each edge; -1 on the boundary. */
  faces: number[];
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

/** Why decimate() stopped. */
export type DecimateStop = 'target_reached' | 'error_bound' | 'no_legal_collapse';

export interface DecimateResult {
  vertices: number;
  faces: number;
  collapses: number;
  maxError: number;
  /** Why the run ended. */
  stop: DecimateStop;
  /** Collapse attempts each check refused (an edge retried in a later pass counts again). */
  refused: { topology: number; normal: number; shape: number };
}

export interface Arrays {
  positions: Float32Array;
  indices: Uint32Array;
  faceSizes: Uint32Array | null;
}

/** A material of one's own (docs/fracture.md): rings of break points around the impact. */
export interface FractureMaterial {
  name?: string;
  /** Innermost first, at most 1000 rings. points: a whole number in [0, 100000], at most 10000 in
   *  all rings; spacing > 0 from the previous ring, in proportion (the spacings are scaled so the
   *  outer ring lies at `radius`); jitter in [0, 1]. */
  rings: { points: number; spacing: number; jitter?: number }[];
  /** Grain direction (nonzero when grainStretch > 1). */
  grain?: Vec3;
  /** >= 1: cells this many times longer along the grain. Default 1. */
  grainStretch?: number;
  /** Longest edge left in the broken area (units as the spacing). Default 1.5. */
  refineEdge?: number;
  /** Units of radius. Default 'diagonal_fraction'. */
  units?: FractureUnits;
  /** The break radius (the outer ring's) in units, > 0. Default 0.1. */
  radius?: number;
}

/** Units of a break radius: a fraction of the mesh's bounding-box diagonal, model units, or mean
 *  edge lengths of the impact face. */
export type FractureUnits = 'diagonal_fraction' | 'model' | 'edge_lengths';

export interface FractureOptions {
  /** Default 'glass'. */
  material?: FracturePreset | FractureMaterial;
  /** A whole number in [0, 2^53]. Default 0. */
  seed?: number;
  /** Units of `radius`, replacing the material's (the presets': 'diagonal_fraction'). */
  units?: FractureUnits;
  /** > 0: the break radius in `units`, replacing the material's (glass 0.13, stone 0.14, wood and
   *  ice 0.11 of the diagonal). Default 0 (the material's). */
  radius?: number;
  /** > 0: the break radius in model units (the material scaled to it), instead of units and
   *  radius. Default 0. */
  breakRadius?: number;
  /** > 0: each shard a closed solid this thick, with mass properties. Default 0 (open shards). */
  thickness?: number;
  /** Mass per unit volume. Default 1. */
  density?: number;
  /** Open shards weigh as a thin shell this thick (model units). Default 0: a twentieth of the
   *  break radius. */
  shellThickness?: number;
  /** Largest distance from the impact to the surface; 0: 1e-3 of the nearest face's longest edge. */
  tolerance?: number;
  /** Compute each shard's convex hull. Default true. */
  hulls?: boolean;
}

/** A piece broken off by Mesh.fracture(). */
export class Shard {
  /** Its faces, with their properties; a closed solid with a thickness. */
  readonly mesh: Mesh;
  readonly faces: number;
  /** Area-weighted centroid and area of the broken faces (the front). */
  readonly centroid: [number, number, number];
  readonly area: number;
  /** Of the closed solid; for an open shard (no thickness), of a thin shell shellThickness thick,
   *  as are mass and inertia (positive definite). */
  readonly volume: number;
  /** The thickness of the shell an open shard is weighed as (model units); 0 when closed. */
  readonly shellThickness: number;
  readonly closed: boolean;
  readonly mass: number;
  readonly centreOfMass: [number, number, number];
  /** About the centre of mass, row-major 3x3. */
  readonly inertia: Float64Array;
  /** Eigenvalues of inertia, ascending, and their unit axes (a right-handed frame). */
  readonly principalMoments: [number, number, number];
  readonly principalAxes: [
    [number, number, number],
    [number, number, number],
    [number, number, number],
  ];
  /** Convex hull of the shard's vertices, for a collider: outward triangles. dimension: 0 empty,
   *  1 point, 2 segment, 3 flat (thickened), 4 solid (HullDimension). */
  readonly hull: {
    positions: Float32Array;
    indices: Uint32Array;
    dimension: number;
    tolerance: number;
  };
  /** Frees the shard's mesh now. Idempotent. */
  dispose(): void;
}

export interface FractureResult {
  /** In the order of their break points (ring by ring, then by angle). */
  shards: Shard[];
  /** The face the impact was located on (it has broken off since). */
  impactFace: number;
  /** The impact moved onto the surface. */
  impactPoint: [number, number, number];
  /** The strike's break radius in model units. */
  breakRadius: number;
  /** Seconds, measured in wasm: per stage; `fracture`, the whole library call; `pack`, making
   *  the result for JS afterwards. */
  seconds: {
    locate: number;
    scatter: number;
    cut: number;
    detach: number;
    hulls: number;
    fracture: number;
    pack: number;
  };
}

export interface SolidFractureOptions {
  /** Default 'stone'. */
  material?: FracturePreset | FractureMaterial;
  /** 'solid' (default), or 'auto': an open or non-manifold mesh breaks by surface fracture. */
  kind?: 'solid' | 'auto';
  /** With kind 'auto': more options of the surface fracture it falls back to (e.g. thickness). */
  surface?: FractureOptions;
  /** A whole number in [0, 2^53]. Default 0. */
  seed?: number;
  /** The break radius in model units. Default 0: radiusFraction of the bounding-box diagonal. */
  radius?: number;
  /** In (0, 10]. Default 0.25. */
  radiusFraction?: number;
  /** The caps' "f:submesh"; -1 (default): one more than the largest. */
  innerSubmesh?: number;
  /** Mass per unit volume. Default 1. */
  density?: number;
  /** Largest distance from the impact to the surface; 0: 1e-3 of the nearest face's longest edge. */
  tolerance?: number;
  /** Compute each piece's convex hull. Default true. */
  hulls?: boolean;
}

/** A closed piece broken off by Mesh.fractureSolid(). */
export class Piece {
  /** Closed, outward; its caps are marked "f:inner" and carry the inner submesh. */
  readonly mesh: Mesh;
  readonly faces: number;
  /** Positive. */
  readonly volume: number;
  /** Area of the cap (inner) faces. */
  readonly capArea: number;
  readonly mass: number;
  readonly centroid: [number, number, number];
  readonly centreOfMass: [number, number, number];
  /** About the centre of mass, row-major 3x3. */
  readonly inertia: Float64Array;
  readonly principalMoments: [number, number, number];
  readonly principalAxes: [
    [number, number, number],
    [number, number, number],
    [number, number, number],
  ];
  /** As Shard's hull. */
  readonly hull: {
    positions: Float32Array;
    indices: Uint32Array;
    dimension: number;
    tolerance: number;
  };
  /** Frees the piece's mesh now. Idempotent. */
  dispose(): void;
}

/** Pieces a and b share `area` of cap; b null: a touches the remaining object. a < b. */
export interface SolidBond {
  a: number;
  b: number | null;
  area: number;
}

export interface SolidFractureResult {
  kind: 'solid';
  /** In the order of their break points; empty cells make none. */
  pieces: Piece[];
  /** Sorted by (a, b). */
  bonds: SolidBond[];
  impactFace: number;
  impactPoint: [number, number, number];
  /** The break radius used, in model units. */
  radius: number;
  /** Seconds, measured in wasm: per stage; `fracture`, the whole library call; `pack`, making the
   *  result for JS afterwards. */
  seconds: {
    locate: number;
    cells: number;
    clip: number;
    cap: number;
    assemble: number;
    perPiece: number;
    fracture: number;
    pack: number;
  };
}

/** Why a strike cannot be a solid fracture (solidFractureRefusalCode()): 'open' and 'non_manifold'
 *  are the input's shape, which fractureSolid() with kind 'auto' breaks by surface fracture; the
 *  others are errors with either kind. */
export type SolidRefusal =
  | 'none'
  | 'open'
  | 'non_manifold'
  | 'bad_option'
  | 'bad_impact'
  | 'off_surface'
  | 'no_face'
  | 'bad_radius';

/** What fractureSolid() with kind 'auto' returns for a mesh solid fracture refuses for its shape. */
export interface SurfaceFallbackResult extends FractureResult {
  kind: 'surface';
  /** Why solid fracture was refused. */
  refusal: string;
  /** The refusal's code: 'open' or 'non_manifold'. */
  refusalCode: 'open' | 'non_manifold';
}

export class Hedge {
  readonly module: unknown;
  /** Log console warnings of misuse that costs memory (Mesh.dispose() under a live RenderBuffers).
   *  Default: on unless process.env.NODE_ENV is 'production' (a bundler's production build). */
  warnings: boolean;
  fromBuffers(input: {
    positions: Float32Array | number[];
    indices: Uint32Array | number[];
    faceSizes?: Uint32Array | number[];
    policy?: 'repair' | 'strict';
    weld?: 'none' | 'exact' | 'epsilon';
  }): Mesh;
  /** An engine's arrays (a three.js BufferGeometry's): positions welded into vertices, the other
   *  streams kept per corner, one submesh id in [0, 65535] per triangle ("f:submesh"). */
  fromEngineStreams(streams: {
    /** 3 floats a vertex. */
    positions: Float32Array | number[];
    /** 3 a triangle. */
    indices: Uint32Array | number[];
    /** 3 floats a vertex. */
    normals?: Float32Array | number[] | null;
    /** 2 floats a vertex. */
    texcoords?: Float32Array | number[] | null;
    /** 4 floats a vertex: r, g, b, a. */
    colors?: Float32Array | number[] | null;
    /** One per triangle. */
    submeshes?: Int32Array | Uint32Array | number[] | null;
    policy?: 'repair' | 'strict';
    /** Default 'exact'. */
    weld?: 'none' | 'exact' | 'epsilon';
  }): Mesh;
  fromFile(bytes: Uint8Array | ArrayBuffer, name: string): Mesh;
  /** The thread setting; the module is single-threaded, so it changes nothing (n: integer >= 0). */
  setMaxThreads(n: number): void;
  /** Always 1: the module runs every call on the calling thread. */
  maxThreads(): number;
  heapBytesInUse(): number;
  readonly memoryBytes: number;
  readonly version: string;
}

export class Mesh {
  readonly hedge: Hedge;
  /** Frees the mesh's wasm memory now (else the garbage collector does). Lifetime rule: a
   *  RenderBuffers made from the mesh shares it, so while one is live dispose() frees nothing
   *  (the memory goes with the last RenderBuffers), and with hedge.warnings on a console warning
   *  says so. Dispose the RenderBuffers first, or together with the mesh. Idempotent. */
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
  /** Why the last refused edit was refused, or why the edit of the last predicate (canFlip, ...)
   *  that answered false would be; null after an edit that was done or a predicate that answered true. */
  readonly lastRefusal: string | null;
  refusal(op: Operation, ...elements: number[]): string | null;
  /** @deprecated use refusal(op, element). */
  whyNot(op: Operation, element: number): string | null;
  canSplitEdge(e: number): boolean;
  canFlip(e: number): boolean;
  canCollapse(h: number): boolean;
  canSplitFace(f: number): boolean;
  canCutFace(h0: number, h1: number): boolean;
  canFillHole(h: number): boolean;
  splitEdge(e: number, point?: Vec3): number;
  flip(e: number): number;
  collapse(h: number, point?: Vec3): number;
  splitFace(f: number, point?: Vec3): number;
  cutFace(h0: number, h1: number): number;
  fillHole(h: number): number[];
  garbageCollection(): void;
  subdivide(scheme?: SubdivisionScheme, steps?: number): void;
  smooth(options?: {
    method?: SmoothMethod;
    iterations?: number;
    lambda?: number;
    mu?: number;
    fixBoundary?: boolean;
  }): void;
  decimate(options: {
    ratio?: number;
    targetFaces?: number;
    targetVertices?: number;
    maxError?: number;
    /** true (the default): should the normal limit alone stop the run short of its target, it is
     *  raised from 60 to 90 degrees for the rest; false: it holds to the end. */
    relaxNormalChange?: boolean;
  }): DecimateResult;
  /** Corner normals ("h:normal"), hard where faces meet at more than creaseDegrees (0..180,
   *  default 45), smooth elsewhere. A RenderBuffers made afterwards with normals 'auto' draws them
   *  and keeps them up around edits; an existing one shows them after rebuild(). */
  computeCornerNormals(creaseDegrees?: number): void;
  /** Breaks the mesh at impact; the broken faces leave it as shards (see FractureOptions). */
  fracture(impact: Vec3, options?: FractureOptions): FractureResult;
  /** Breaks the closed mesh at impact into closed pieces; the mesh becomes the remaining object. */
  fractureSolid(
    impact: Vec3,
    options?: SolidFractureOptions & { kind?: 'solid' },
  ): SolidFractureResult;
  fractureSolid(
    impact: Vec3,
    options: SolidFractureOptions & { kind: 'auto' },
  ): SolidFractureResult | SurfaceFallbackResult;
  /** Why fractureSolid() would be refused, or null. */
  solidFractureRefusal(impact: Vec3, options?: Omit<SolidFractureOptions, 'kind'>): string | null;
  /** solidFractureRefusal()'s answer as a code ('none' when the strike can be made). */
  solidFractureRefusalCode(
    impact: Vec3,
    options?: Omit<SolidFractureOptions, 'kind' | 'surface'>,
  ): SolidRefusal;
  toArrays(options?: { triangulate?: boolean }): Arrays;
  toFile(name: string): Uint8Array;
  memoryBytes(): number;
  /** Buffers kept in step with the mesh. They share the mesh: its memory stays until the mesh and
   *  every RenderBuffers made from it are disposed (see dispose()). */
  createRenderBuffers(options?: {
    normals?: 'auto' | 'computed' | 'attribute' | 'none';
    interleaved?: boolean;
    texcoords?: boolean;
    colors?: boolean;
  }): RenderBuffers;
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

/** One submesh's (material's) part of the render buffers. */
export interface SubmeshRange {
  /** Its index entries [indexStart, indexStart + indexCount), spare (degenerate) slots included. */
  indexStart: number;
  indexCount: number;
  /** The render vertices its entries refer to. */
  firstVertex: number;
  vertexCount: number;
  /** No live triangle since the last full build (or only ones with every corner at the origin). */
  empty: boolean;
}

export class RenderBuffers {
  readonly hedge: Hedge;
  /** Frees the buffers, and the mesh's memory too if the mesh was disposed already and no other
   *  RenderBuffers of it is live. Idempotent. */
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
  /** As of the last sync, in submesh order. */
  submeshes(): SubmeshRange[];
  /** The first face along a ray and its triangle slots [first, first + count) as of the last sync;
   *  null for a miss. */
  pickTriangles(
    origin: Vec3,
    direction: Vec3,
  ): {
    face: number;
    t: number;
    point: [number, number, number];
    first: number;
    count: number;
  } | null;
  sync(): SyncResult;
  dirtyViews(result: SyncResult): { vertices: Float32Array[]; indices: Uint32Array[] };
  rebuild(): SyncResult;
  compact(): void;
  begin(): void;
  commit(): SyncResult;
}

// ---- Deprecated names (kept for one release) ----------------------------------------------------
// The names of the previous release; the next release removes them.

/** @deprecated Use RenderBuffers. */
export declare const Render: typeof RenderBuffers;
/** @deprecated Use RenderBuffers. */
export type Render = RenderBuffers;

export interface Mesh {
  /** @deprecated Use createRenderBuffers(options). */
  createRender(options?: Parameters<Mesh['createRenderBuffers']>[0]): RenderBuffers;
}
// ---- End of deprecated names --------------------------------------------------------------------
