// Surface fracture in the JS API: the material presets and the material argument as the module
// takes it, and the shards unpacked from its result (hedge.js calls these). A shard is a Mesh with
// what the library reports of it (docs/fracture.md).
import { customMaterial } from './arguments.js';
import { HedgeError } from './native.js';

const MATERIALS = ['glass', 'stone', 'wood', 'ice'];
/** The fracture presets, for menus. */
export const fractureMaterials = Object.freeze([...MATERIALS]);

// A fracture material as the module takes it: [preset name, ''] or ['', the custom material].
export function materialArguments(call, material) {
  if (typeof material !== 'string') return ['', customMaterial(material, call)];
  if (!MATERIALS.includes(material))
    throw new HedgeError(
      'invalid-argument',
      `${call}: unknown material '${material}' (${MATERIALS.join(', ')}, or an object)`,
    );
  return [material, null];
}

/** A piece broken off by Mesh.fracture(). `mesh` is its own Mesh (dispose() frees it); the rest
 *  are plain values: centroid and area of its broken faces, and its volume, mass, centreOfMass,
 *  inertia (about the centre of mass, row-major 3x3 Float64Array), principalMoments (ascending)
 *  and principalAxes (unit vectors, a right-handed frame): of the solid when it is closed
 *  (thickness > 0), else of a thin shell shellThickness thick (0 when closed); its convex hull for a collider as hull.positions (Float32Array, 3 per vertex) and
 *  hull.indices (Uint32Array, 3 per outward triangle). */
export class Shard {
  constructor(mesh, s) {
    this.mesh = mesh;
    this.faces = s.faces;
    this.centroid = s.centroid;
    this.area = s.area;
    this.volume = s.volume;
    this.closed = s.closed;
    this.mass = s.mass;
    this.centreOfMass = s.centreOfMass;
    this.inertia = s.inertia;
    this.principalMoments = s.principalMoments;
    this.principalAxes = s.principalAxes;
    this.shellThickness = s.shellThickness;
    this.hull = s.hull;
  }

  /** Frees the shard's mesh now. Idempotent. */
  dispose() {
    this.mesh.dispose();
  }
}

// Numbers per shard in the module's packed result (WasmMesh::fracture).
const SCALARS = 35;

/** The module's packed result with its shards made into [Shard] (hulls concatenated in the
 *  result, each shard's a view). makeMesh wraps a native mesh into a Mesh. */
export function unpackShards(result, makeMesh) {
  const p = result.shards;
  const shards = [];
  const v3 = (k) => [p.scalars[k], p.scalars[k + 1], p.scalars[k + 2]];
  for (let i = 0; i < p.count; ++i) {
    const k = i * SCALARS;
    const hv = [p.hullVertexOffsets[i], p.hullVertexOffsets[i + 1]];
    const hi = [p.hullIndexOffsets[i], p.hullIndexOffsets[i + 1]];
    shards.push(
      new Shard(makeMesh(p.meshes[i]), {
        faces: p.scalars[k],
        area: p.scalars[k + 1],
        volume: p.scalars[k + 2],
        closed: p.scalars[k + 3] === 1,
        mass: p.scalars[k + 4],
        centroid: v3(k + 7),
        centreOfMass: v3(k + 10),
        principalMoments: v3(k + 13),
        principalAxes: [v3(k + 16), v3(k + 19), v3(k + 22)],
        inertia: p.scalars.slice(k + 25, k + 34),
        shellThickness: p.scalars[k + 34],
        hull: {
          positions: p.hullPositions.subarray(hv[0] * 3, hv[1] * 3),
          indices: p.hullIndices.subarray(hi[0], hi[1]),
          dimension: p.scalars[k + 5],
          tolerance: p.scalars[k + 6],
        },
      }),
    );
  }
  result.shards = shards;
  return result;
}
