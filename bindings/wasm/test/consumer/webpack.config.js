// Two pages bundled by webpack 5 into dist/webpack/, after vite has written dist/: the first
// (main.js: loadHedge()) and the worker helper's (remote_page.js: hedge-mesh/worker). webpack emits
// hedge.wasm as an asset through the module's new URL('hedge.wasm', import.meta.url), and
// worker.js as a worker chunk of its own through the package's new Worker(new URL('./worker.js',
// import.meta.url), {type: 'module'}). package_test.sh fails on any warning.
import { fileURLToPath } from 'node:url';

export default {
  mode: 'production',
  target: 'web',
  entry: { main: './main.js', remote_page: './remote_page.js' },
  output: {
    path: fileURLToPath(new URL('dist/webpack/', import.meta.url)),
    filename: '[name].js',
    module: true,
  },
  experiments: { outputModule: true },
  // The wasm is 1.3 MB; that is known, not a finding.
  performance: { hints: false },
};
