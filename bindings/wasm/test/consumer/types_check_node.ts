// Type-checked as node code (tsconfig.node.json: module "nodenext", with the "node" condition):
// hedge-mesh's types are then node.d.ts, hedge.d.ts and the deprecated loadHedgeNode.
import { loadHedge, loadHedgeNode, type Hedge } from 'hedge-mesh';

const hedge: Hedge = await loadHedge();
const old: Hedge = await loadHedgeNode();
export const versions: string[] = [hedge.version, old.version];
