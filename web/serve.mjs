// A small static file server for the playground, listening on 127.0.0.1 only.
//
//   node web/serve.mjs [--port N] [--wasm DIR]
//
// URL layout:
//   /                 web/ (index.html, src/)
//   /node_modules/... web/node_modules (three, cannon-es), reached through the page's import map
//   /data/...         the repository's sample meshes
//   /wasm/...         the WebAssembly build (hedge.mjs, hedge.wasm); DIR defaults to
//                     $HEDGE_WASM_DIR or build/wasm/dist
// --port 0 picks a free port. The first line printed is "serving http://127.0.0.1:PORT/". The
// browser tests (web/test/playground.mjs) call startServer({ port: 0 }) and get the URL back.
//
// Why a server of our own and not a maintained one (sirv 3, or vite's preview), checked against
// both: neither serves the playground by itself.
// - Four folders from three places, one chosen at run time (the wasm build, --wasm or
//   $HEDGE_WASM_DIR), each under its URL prefix. sirv (and sirv-cli) serves one folder; with it we
//   would still need this file's dispatch, its arguments and startServer(), and would save only the
//   MIME table and the path check (about 50 lines) for four more npm packages. vite's preview serves
//   one vite build's output, and the page is deliberately not bundled (an import map into
//   node_modules); vite's dev server would add a bundler's weight to the page's dependencies.
// - The files as they are now: a rebuilt hedge.wasm is served without a restart. sirv caches a
//   listing of its folder at start unless in its dev mode.
// - The types the page needs: application/wasm, JavaScript, and bytes for every mesh format (mrmime,
//   sirv's table, has no type for .off or .ply and sirv then sends an empty Content-Type).
// - Nothing out of the roots (.., encoded or not: the test 'the server serves its roots only'),
//   GET and HEAD only, 127.0.0.1 only.
// What it does not do, because the page needs none of it: range requests, ETags, compression, and
// cross-origin isolation headers (the module is built without threads, so no SharedArrayBuffer).
import { createServer } from 'node:http';
import { createReadStream, statSync } from 'node:fs';
import { dirname, extname, join, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';

const webDir = dirname(fileURLToPath(import.meta.url));
const repoDir = resolve(webDir, '..');

const MIME = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.wasm': 'application/wasm',
  '.png': 'image/png',
  '.svg': 'image/svg+xml',
  '.ico': 'image/x-icon',
  '.md': 'text/plain; charset=utf-8',
  // Meshes are fetched as bytes and parsed by hedge.
  '.obj': 'application/octet-stream',
  '.off': 'application/octet-stream',
  '.ply': 'application/octet-stream',
  '.stl': 'application/octet-stream',
  '.gltf': 'model/gltf+json',
  '.glb': 'model/gltf-binary',
};

function parseArgs(argv) {
  const options = {
    port: 8080,
    wasm: process.env.HEDGE_WASM_DIR || join(repoDir, 'build', 'wasm', 'dist'),
  };
  for (let i = 0; i < argv.length; ++i) {
    const arg = argv[i];
    const value = () => {
      if (i + 1 >= argv.length) throw new Error(`serve: ${arg} needs a value`);
      return argv[++i];
    };
    if (arg === '--port') options.port = Number(value());
    else if (arg === '--wasm') options.wasm = resolve(value());
    else if (arg === '--help' || arg === '-h') {
      console.log('usage: node web/serve.mjs [--port N] [--wasm DIR]');
      process.exit(0);
    } else throw new Error(`serve: unknown argument '${arg}'`);
  }
  if (!Number.isInteger(options.port) || options.port < 0 || options.port > 65535)
    throw new Error(`serve: bad port '${options.port}'`);
  return options;
}

// Maps a URL path to a file under one of the served roots, or null. Paths that climb out of their
// root (.., encoded or not) are refused.
function resolvePath(urlPath, roots) {
  let path;
  try {
    path = decodeURIComponent(urlPath);
  } catch {
    return null;
  }
  if (path.includes('\0')) return null;
  for (const [prefix, root] of roots) {
    if (!path.startsWith(prefix)) continue;
    const rest = path.slice(prefix.length);
    const file = resolve(root, '.' + sep + rest);
    if (file !== root && !file.startsWith(root + sep)) return null;
    return file;
  }
  return null;
}

export function startServer({ port = 0, wasm } = {}) {
  const roots = [
    ['/node_modules/', join(webDir, 'node_modules')],
    ['/data/', join(repoDir, 'data')],
    ['/wasm/', resolve(wasm)],
    ['/', webDir],
  ];
  const server = createServer((req, res) => {
    const url = new URL(req.url, 'http://127.0.0.1');
    if (req.method !== 'GET' && req.method !== 'HEAD') {
      res.writeHead(405, { Allow: 'GET, HEAD' }).end();
      return;
    }
    let file = resolvePath(url.pathname, roots);
    let stat = null;
    try {
      if (file) stat = statSync(file);
      if (stat && stat.isDirectory()) {
        file = join(file, 'index.html');
        stat = statSync(file);
      }
    } catch {
      stat = null;
    }
    if (!file || !stat || !stat.isFile()) {
      res
        .writeHead(404, { 'Content-Type': 'text/plain; charset=utf-8' })
        .end(`not found: ${url.pathname}\n`);
      return;
    }
    res.writeHead(200, {
      'Content-Type': MIME[extname(file).toLowerCase()] || 'application/octet-stream',
      'Content-Length': stat.size,
      'Cache-Control': 'no-cache',
    });
    if (req.method === 'HEAD') {
      res.end();
      return;
    }
    createReadStream(file).pipe(res);
  });
  return new Promise((resolveStart, rejectStart) => {
    server.once('error', rejectStart);
    server.listen(port, '127.0.0.1', () => {
      const url = `http://127.0.0.1:${server.address().port}/`;
      resolveStart({ server, url });
    });
  });
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  try {
    const options = parseArgs(process.argv.slice(2));
    const { url } = await startServer(options);
    console.log(`serving ${url}`);
    console.log(`  wasm build: ${options.wasm}`);
    console.log('  press Ctrl-C to stop');
  } catch (error) {
    console.error(error.message);
    process.exit(1);
  }
}
