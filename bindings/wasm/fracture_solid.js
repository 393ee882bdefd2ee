// Solid fracture in the JS API: the options of Mesh.fractureSolid() and Mesh.solidFractureRefusal()
// as the module takes them, and the pieces unpacked from its result (hedge.js calls these). A
// piece is a closed Mesh with its volume, cap area, mass properties and convex hull; the bonds say
// which pieces touch (docs/fracture.md).

/** The options of a solid fracture with their defaults filled in, typed for the module (the
 *  argument check has made sure each given one is a number or a boolean). */
export function solidOptions({
  radius = 0,
  radiusFraction = 0.25,
  seed = 0,
  innerSubmesh = -1,
  density = 1,
  tolerance = 0,
  hulls = true,
} = {}) {
  return { radius, radiusFraction, seed, innerSubmesh, density, tolerance, hulls: Boolean(hulls) };
}

/** A closed piece broken off by Mesh.fractureSolid(). `mesh` is its own Mesh (dispose() frees it):
 *  its outer faces keep the struck mesh's properties, its cap faces are marked inner and carry the
 *  inner submesh (a RenderBuffers groups them apart, so they can be drawn with an inner material).
 *  The rest are plain values: volume (positive), capArea (the area of its cap faces), mass,
 *  centroid (= centreOfMass), inertia (about the centre of mass, row-major 3x3 Float64Array),
 *  principalMoments (ascending), principalAxes (unit vectors, a right-handed frame), and its convex
 *  hull for a collider as hull.positions (Float32Array, 3 per vertex) and hull.indices
 *  (Uint32Array, 3 per outward triangle). */
export class Piece {
  constructor(mesh, s) {
    this.mesh = mesh;
    this.faces = s.faces;
    this.volume = s.volume;
    this.capArea = s.capArea;
    this.mass = s.mass;
    this.centroid = s.centroid;
    this.centreOfMass = s.centreOfMass;
    this.inertia = s.inertia;
    this.principalMoments = s.principalMoments;
    this.principalAxes = s.principalAxes;
    this.hull = s.hull;
  }

  /** Frees the piece's mesh now. Idempotent. */
  dispose() {
    this.mesh.dispose();
  }
}

// Numbers per piece in the module's packed result (WasmMesh::fracture_solid).
const SCALARS = 33;

/** The module's packed result made into {pieces: [Piece], bonds: [{a, b, area}], ...}: b is null
 *  when piece a touches the remaining object. makeMesh wraps a native mesh into a Mesh. */
export function unpackSolidResult(result, makeMesh) {
  const p = result.pieces;
  const s = p.scalars;
  const v3 = (k) => [s[k], s[k + 1], s[k + 2]];
  const pieces = [];
  for (let i = 0; i < p.count; ++i) {
    const k = i * SCALARS;
    const hv = [p.hullVertexOffsets[i], p.hullVertexOffsets[i + 1]];
    const hi = [p.hullIndexOffsets[i], p.hullIndexOffsets[i + 1]];
    pieces.push(
      new Piece(makeMesh(p.meshes[i]), {
        faces: s[k],
        volume: s[k + 1],
        capArea: s[k + 2],
        mass: s[k + 3],
        centroid: v3(k + 6),
        centreOfMass: v3(k + 9),
        principalMoments: v3(k + 12),
        principalAxes: [v3(k + 15), v3(k + 18), v3(k + 21)],
        inertia: s.slice(k + 24, k + 33),
        hull: {
          positions: p.hullPositions.subarray(hv[0] * 3, hv[1] * 3),
          indices: p.hullIndices.subarray(hi[0], hi[1]),
          dimension: s[k + 4],
          tolerance: s[k + 5],
        },
      }),
    );
  }
  const bonds = [];
  for (let k = 0; k < result.bonds.length; k += 3) {
    const b = result.bonds[k + 1];
    bonds.push({ a: result.bonds[k], b: b < 0 ? null : b, area: result.bonds[k + 2] });
  }
  return {
    kind: 'solid',
    pieces,
    bonds,
    impactFace: result.impactFace,
    impactPoint: result.impactPoint,
    radius: result.radius,
    seconds: result.seconds,
  };
}
