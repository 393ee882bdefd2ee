// Five pages: index.html imports hedge-mesh (the module and its wasm as two files), single.html
// imports hedge-mesh/single (one file), worker.html runs hedge-mesh in a module worker, three.html
// draws, raycasts and edits a mesh through hedge-mesh/three, remote.html uses hedge's worker helper
// (hedge-mesh/worker), whose worker vite finds in the package's `new Worker(new URL(...))`. The dev server must not pre-bundle the
// package, which would separate hedge.mjs from hedge.wasm; the build needs nothing.
import { defineConfig } from 'vite';

export default defineConfig({
  optimizeDeps: { exclude: ['hedge-mesh'] },
  worker: { format: 'es' },
  build: {
    rollupOptions: {
      input: ['index.html', 'single.html', 'worker.html', 'three.html', 'remote.html'],
    },
    // The single-file module is 2 MB: the wasm is in it. Say so only above that.
    chunkSizeWarningLimit: 2500,
  },
});
