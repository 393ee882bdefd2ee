// hedge-mesh under node, as installed from the tarball: the package's node entry and its
// single-file variant, each through loadHedge(), with no globals set.
import assert from 'node:assert/strict';
import * as main from 'hedge-mesh';
import * as single from 'hedge-mesh/single';
import { scenario } from './scenario.js';

const expected = JSON.parse(process.argv[2]);
for (const [name, api] of [
  ['hedge-mesh', main],
  ['hedge-mesh/single', single],
]) {
  const result = await scenario(api.loadHedge);
  assert.deepEqual(result, expected, `${name} under node`);
  console.log(`node: ${name}: ${JSON.stringify(result)}`);
}
assert.equal(typeof main.loadHedgeNode, 'function', 'the node entry keeps loadHedgeNode');
