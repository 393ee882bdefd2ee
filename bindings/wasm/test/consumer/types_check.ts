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
