// Instantiating the emscripten module wherever the JS API runs (node, browsers, module workers,
// bundles), setting no globals.
//
// hedge.mjs is built for the web and workers only (ENVIRONMENT=web,worker in CMakeLists.txt): its
// node code reads the CommonJS globals require and __dirname, which an ES module under node does not
// have. In browsers and workers the module fetches hedge.wasm itself, from new URL('hedge.wasm',
// import.meta.url): the form vite and webpack recognise and emit as an asset (esbuild leaves it
// as it is). Under node, which cannot fetch a file: URL, the bytes are read here with node:fs and
// passed as wasmBinary.
// node:fs is imported dynamically through a name held in a variable, with the comments that tell
// webpack and vite to leave the import alone, so a browser bundle never tries to include it.

const FS_MODULE = 'node:fs/promises';
const WASM_FILE = 'hedge.wasm';

/** True under node (and runtimes that mimic it, such as Deno and Bun), outside a browser page or
 *  a web worker. */
export function isNode() {
  return (
    typeof process === 'object' &&
    typeof process.versions === 'object' &&
    typeof process.versions.node === 'string' &&
    typeof window === 'undefined' &&
    typeof importScripts === 'undefined'
  );
}

/** Runs the emscripten factory with options. Under node, unless the options already say how to get
 *  the wasm (wasmBinary, instantiateWasm) or the module embeds it (hedge.single.mjs), reads
 *  hedge.wasm from beside this file, or from options.locateFile('hedge.wasm', '') (a path or a
 *  file: URL), and passes its bytes. */
export async function instantiate(factory, options = {}) {
  if (!isNode() || factory.wasmEmbedded || options.wasmBinary || options.instantiateWasm)
    return factory(options);
  const located = options.locateFile ? options.locateFile(WASM_FILE, '') : WASM_FILE;
  // webpackIgnore: webpack would otherwise bundle every file of this folder for this URL.
  const url = new URL(/* webpackIgnore: true */ located, import.meta.url);
  const { readFile } = await import(/* webpackIgnore: true */ /* @vite-ignore */ FS_MODULE);
  let wasmBinary;
  try {
    wasmBinary = await readFile(url);
  } catch (e) {
    throw new Error(`loadHedge: cannot read the WebAssembly module ${url.href}: ${e.message}`);
  }
  return factory({ ...options, wasmBinary });
}
