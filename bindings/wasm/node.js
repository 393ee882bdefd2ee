// The package's entry under node (the "node" condition of package.json's exports): the JS API of
// hedge.js, whose loadHedge() works under node as it does in a browser (load.js), and the name the
// previous release had for it.
import { loadHedge } from './hedge.js';

export * from './hedge.js';

/** @deprecated loadHedge() works under node; this alias of it goes in the next release. */
export function loadHedgeNode(options = {}) {
  return loadHedge(options);
}
