// Types of the package's node entry (node.js): the JS API of hedge.js, and one name that exists only
// under node.
import type { Hedge, LoadOptions } from './hedge.js';

export * from './hedge.js';

/** @deprecated loadHedge() works under node; this alias of it goes in the next release. */
export function loadHedgeNode(options?: LoadOptions): Promise<Hedge>;
