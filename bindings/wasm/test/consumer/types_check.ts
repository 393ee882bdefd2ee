// Type-checked as a browser build (tsconfig.bundler.json: moduleResolution "bundler", without the
// "node" condition): hedge-mesh's types are then hedge.d.ts, which has no loadHedgeNode.
import { loadHedge, type Hedge } from 'hedge-mesh';
import * as single from 'hedge-mesh/single';
// @ts-expect-error loadHedgeNode exists only under node (node.d.ts)
import { loadHedgeNode } from 'hedge-mesh';

const hedge: Hedge = await loadHedge();
const fromSingle: Hedge = await single.loadHedge({ locateFile: (name: string) => name });
const mesh = hedge.fromBuffers({
  positions: new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0]),
  indices: new Uint32Array([0, 1, 2]),
});
export const faces: number = mesh.counts().faces;
export const versions: string[] = [hedge.version, fromSingle.version];
export const unused = loadHedgeNode;

// The worker helper: meshes in a module worker, named by id; results with typed arrays.
import { createHedgeWorker, type HedgeWorker } from 'hedge-mesh/worker';
const remote: HedgeWorker = await createHedgeWorker();
const loaded = await remote.load(new Uint8Array(0), 'empty.obj', { transfer: true });
const drawn: Float32Array = (await remote.buffers(loaded.id, { normals: 'computed' })).positions;
const broken = await remote.fracture(loaded.id, [0, 0, 0], { material: 'glass' });
export const remoteIds: number[] = [loaded.id, ...broken.shards.map((s) => s.id), drawn.length];

// Solid fracture: pieces and bonds; with kind 'auto', surface fracture's result when refused.
import type { Piece, SolidBond } from 'hedge-mesh';
const solid = mesh.fractureSolid([0, 0, 0], { material: 'stone', radius: 0.5, seed: 1 });
const pieces: Piece[] = solid.pieces;
const bonds: SolidBond[] = solid.bonds;
const auto = mesh.fractureSolid([0, 0, 0], { kind: 'auto', surface: { thickness: 0.01 } });
export const solidParts: number =
  pieces.length + bonds.length + (auto.kind === 'solid' ? auto.pieces.length : auto.shards.length);
export const solidRefusal: string | null = mesh.solidFractureRefusal([0, 0, 0]);
const remoteSolid = await remote.fractureSolid(loaded.id, [0, 0, 0], { kind: 'auto' });
export const remotePieceIds: number[] =
  remoteSolid.kind === 'solid'
    ? remoteSolid.pieces.map((p) => p.id)
    : remoteSolid.shards.map((s) => s.id);
// The refusal in the worker, as a code: the same names as on the page.
import type { SolidRefusal } from 'hedge-mesh';
const remoteCode: SolidRefusal = await remote.solidFractureRefusalCode(loaded.id, [0, 0, 0]);
export const remoteRefusal: (string | null)[] = [
  await remote.solidFractureRefusal(loaded.id, [0, 0, 0], { material: 'stone' }),
  remoteSolid.kind === 'surface' ? remoteSolid.refusalCode : remoteCode,
];
