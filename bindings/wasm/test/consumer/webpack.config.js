// The first page (main.js) bundled by webpack 5 into dist/webpack/, after vite has written dist/:
// webpack emits hedge.wasm as an asset through the module's new URL('hedge.wasm',
// import.meta.url). package_test.sh fails on any warning.
import { fileURLToPath } from 'node:url';

export default {
  mode: 'production',
  target: 'web',
  entry: './main.js',
  output: {
    path: fileURLToPath(new URL('dist/webpack/', import.meta.url)),
    filename: 'main.js',
    module: true,
  },
  experiments: { outputModule: true },
  // The wasm is 1.3 MB; that is known, not a finding.
  performance: { hints: false },
};
