// Shared by the node tests: the module, the sample meshes and small mesh generators.
import { existsSync, readFileSync, symlinkSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

const root = new URL('../../../', import.meta.url);
const dist = process.env.HEDGE_WASM_DIST
  ? new URL(`file://${process.env.HEDGE_WASM_DIST.replace(/\/?$/, '/')}`)
  : new URL('build/wasm/dist/', root);

/** The folder of the built package (HEDGE_WASM_DIST, or build/wasm/dist). */
export { dist };
const api = await import(new URL('node.js', dist).href);
export const { HedgeError, loadHedge } = api;
export const hedge = await loadHedge();

/** hedge's three.js adapter (three.js of the build) and three.js itself, from the playground's npm
 *  packages (web/node_modules, installed by `npm ci` in web/): {THREE, adapter}, or null when three
 *  is not installed. The adapter imports 'three' as a peer dependency, which node looks for in a
 *  node_modules folder above the build's: a link to web/node_modules is made beside it. */
export async function threeAdapter() {
  const modules = new URL('web/node_modules/', root);
  if (!existsSync(new URL('three/package.json', modules))) return null;
  const link = new URL('../node_modules', dist);
  try {
    symlinkSync(fileURLToPath(modules), fileURLToPath(link));
  } catch (e) {
    if (e.code !== 'EEXIST') throw e;
  }
  const THREE = await import(new URL('three/build/three.module.js', modules).href);
  const adapter = await import(new URL('three.js', dist).href);
  return { THREE, adapter };
}

/** The bytes of a file of data/. */
export function sample(name) {
  return new Uint8Array(readFileSync(fileURLToPath(new URL(`data/${name}`, root))));
}

/** An n x n grid of unit squares in the z = 0 plane, each cut into two triangles. */
export function gridArrays(n) {
  const positions = [];
  for (let j = 0; j <= n; ++j) for (let i = 0; i <= n; ++i) positions.push(i, j, 0);
  const indices = [];
  const at = (i, j) => j * (n + 1) + i;
  for (let j = 0; j < n; ++j)
    for (let i = 0; i < n; ++i)
      indices.push(
        at(i, j),
        at(i + 1, j),
        at(i + 1, j + 1),
        at(i, j),
        at(i + 1, j + 1),
        at(i, j + 1),
      );
  return { positions: new Float32Array(positions), indices: new Uint32Array(indices) };
}

export function grid(n) {
  return hedge.fromBuffers(gridArrays(n));
}

/** A regular octahedron (closed, 6 vertices of valence 4). */
export function octahedron() {
  return hedge.fromBuffers({
    positions: new Float32Array([1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1]),
    indices: new Uint32Array([
      0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5,
    ]),
  });
}

/** A tetrahedron (closed, every vertex of valence 3). */
export function tetrahedron() {
  return hedge.fromBuffers({
    positions: new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]),
    indices: new Uint32Array([0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]),
  });
}

/** A closed cube of six quads. */
export function cube() {
  return hedge.fromBuffers({
    positions: new Float32Array([
      0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1,
    ]),
    indices: new Uint32Array([
      0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7,
    ]),
    faceSizes: new Uint32Array([4, 4, 4, 4, 4, 4]),
  });
}
