// Loading hedge under node: the emscripten ES module (built for web and node) expects the CommonJS
// globals require and __dirname under node, and reads hedge.wasm from disk itself only through
// them; this supplies both and passes the wasm bytes directly. Browsers and bundlers use hedge.js.
import { createRequire } from 'node:module';
import { readFileSync } from 'node:fs';
import { dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadHedge } from './hedge.js';

export * from './hedge.js';

/** loadHedge() for node: options as for loadHedge. */
export async function loadHedgeNode(options = {}) {
  globalThis.require ??= createRequire(import.meta.url);
  globalThis.__dirname ??= dirname(fileURLToPath(import.meta.url));
  const wasmBinary = readFileSync(new URL('./hedge.wasm', import.meta.url));
  return loadHedge({ wasmBinary, ...options });
}
