// What the playground's browser tests share: the server and the browser (one of each per test
// file), a fresh page per test, and the page actions and checks the tests are written in. The tests
// are node:test files next to this module, run by web/test/run:
//
//   web/test/run [--test-name-pattern REGEX] [FILE.test.mjs ...]
//
// Debian's chromium, headless, driven by playwright-core, on the page served on 127.0.0.1 (a free
// port). Each test saves a screenshot of its page at its end.
//
// Environment: HEDGE_CLI (default build/release/tools/hedge/hedge, for `hedge info --json`),
// HEDGE_WASM_DIR (default build/wasm/dist), HEDGE_E2E_OUT (default build/output/web-e2e),
// CHROMIUM (default /usr/bin/chromium).
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { after, before, describe, it } from 'node:test';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { startServer } from '../serve.mjs';

const webDir = resolve(dirname(fileURLToPath(import.meta.url)), '..');
export const repoDir = resolve(webDir, '..');
const cli = process.env.HEDGE_CLI || join(repoDir, 'build', 'release', 'tools', 'hedge', 'hedge');
export const wasmDir = process.env.HEDGE_WASM_DIR || join(repoDir, 'build', 'wasm', 'dist');
export const outDir = process.env.HEDGE_E2E_OUT || join(repoDir, 'build', 'output', 'web-e2e');
const executablePath = process.env.CHROMIUM || '/usr/bin/chromium';

export function check(condition, message) {
  if (!condition) assert.fail(message);
}
export function checkEqual(actual, expected, what) {
  check(
    actual === expected,
    `${what}: expected ${JSON.stringify(expected)}, got ${JSON.stringify(actual)}`,
  );
}

// `hedge info --json FILE`: the counts the page must show for the same file.
export function cliInfo(file) {
  check(existsSync(cli), `no hedge CLI at ${cli} (build the release preset)`);
  const out = execFileSync(cli, ['info', '--json', join(repoDir, 'data', file)], {
    encoding: 'utf8',
  });
  return JSON.parse(out);
}

// ---- the server, the browser and a page per test ------------------------------------------------

async function open() {
  check(
    existsSync(executablePath),
    `no browser at ${executablePath} (install chromium: scripts/deps.sh group web)`,
  );
  check(
    existsSync(join(wasmDir, 'hedge.mjs')),
    `no WebAssembly build in ${wasmDir} (run bindings/wasm/build)`,
  );
  mkdirSync(outDir, { recursive: true });
  const { server, url } = await startServer({ port: 0, wasm: wasmDir });
  const profile = mkdtempSync(join(tmpdir(), 'hedge-e2e-'));
  let context;
  try {
    context = await chromium.launchPersistentContext(profile, {
      executablePath,
      headless: true,
      viewport: { width: 1100, height: 700 },
      args: [
        '--no-sandbox',
        '--disable-gpu',
        '--disable-quic',
        '--no-first-run',
        '--disable-background-networking',
        '--disable-component-update',
        '--disable-sync',
        '--enable-unsafe-swiftshader',
      ],
    });
  } catch (error) {
    server.close();
    rmSync(profile, { recursive: true, force: true });
    throw error;
  }
  const close = async () => {
    await context.close();
    server.close();
    rmSync(profile, { recursive: true, force: true });
  };
  return { context, url, close };
}

// Runs `body` on a fresh page that has started (the sample loaded), then checks that the browser
// reported no error, and saves a screenshot whatever happened.
async function onPage({ context, url }, t, body) {
  const page = await context.newPage();
  const problems = [];
  page.on('console', (m) => {
    if (m.type() === 'error') problems.push(m.text());
  });
  page.on('pageerror', (e) => problems.push(`uncaught: ${e.message}`));
  page.on('requestfailed', (r) => problems.push(`request failed: ${r.url()}`));
  try {
    await page.goto(url);
    await page.waitForFunction(
      () => document.body.dataset.ready === '1' || document.body.dataset.error,
      null,
      { timeout: 30000 },
    );
    check(
      (await page.getAttribute('body', 'data-ready')) === '1',
      `the page did not start: ${await page.getAttribute('body', 'data-error')}`,
    );
    await body({ page, problems, url, log: (s) => t.diagnostic(s) });
    check(problems.length === 0, `browser errors: ${problems.join(' | ')}`);
  } finally {
    const file = join(outDir, `${t.name.replace(/[^a-z0-9]+/gi, '_').toLowerCase()}.png`);
    await page.screenshot({ path: file }).catch(() => {});
    await page.close();
  }
}

// A suite of browser tests: one server and one browser for all of them, a fresh page for each.
// `define` receives `test(name, body)`; body gets { page, problems, url, log }.
export function playgroundSuite(title, define) {
  describe(title, () => {
    let session = null;
    before(async () => {
      session = await open();
    });
    after(async () => {
      if (session) await session.close();
    });
    define((name, body) => it(name, (t) => onPage(session, t, body)));
  });
}

// ---- page actions ---------------------------------------------------------------------------------

export async function counts(page) {
  const text = await page.getAttribute('body', 'data-counts');
  const [vertices, edges, faces] = text.split(',').map(Number);
  return { vertices, edges, faces };
}

export async function loadSample(page, name) {
  await page.selectOption('#sample', name);
  await page.click('#load-sample');
  await page.waitForFunction(
    (n) =>
      !document.body.dataset.busy &&
      (document.body.dataset.mesh === n || (document.body.dataset.error || '').includes(n)),
    name,
  );
  check(
    await page.isHidden('#error'),
    `loading ${name} failed: ${await page.textContent('#error-text')}`,
  );
}

export async function edits(page) {
  return Number((await page.getAttribute('body', 'data-edits')) || 0);
}

export async function lastUpload(page) {
  return JSON.parse(await page.getAttribute('body', 'data-upload'));
}

// Pixels of the WebGL canvas that differ from the background: the mesh was drawn.
export async function drawnPixels(page) {
  return page.evaluate(() => {
    const canvas = document.getElementById('canvas');
    const copy = document.createElement('canvas');
    copy.width = canvas.width;
    copy.height = canvas.height;
    const ctx = copy.getContext('2d');
    ctx.drawImage(canvas, 0, 0);
    const data = ctx.getImageData(0, 0, copy.width, copy.height).data;
    let n = 0;
    for (let i = 0; i < data.length; i += 4) {
      if (
        Math.abs(data[i] - 0xf4) + Math.abs(data[i + 1] - 0xf4) + Math.abs(data[i + 2] - 0xf2) >
        24
      )
        ++n;
    }
    return n;
  });
}

// Moves the pointer onto a visible interior edge until the page highlights it; returns it.
// `central`: the edges nearest the middle of the view first.
export async function hoverEdge(page, { central = false } = {}) {
  const candidates = await page.evaluate(
    (n) => window.playground.visibleEdges(n),
    central ? 200 : 20,
  );
  if (central) {
    const box = await page.locator('#canvas').boundingBox();
    const cx = box.x + box.width / 2,
      cy = box.y + box.height / 2;
    const score = (e) => Math.hypot(e.x - cx, e.y - cy) - 2 * e.length;
    candidates.sort((a, b) => score(a) - score(b));
  }
  check(candidates.length > 0, 'no visible edge found to click');
  for (const c of candidates) {
    await page.mouse.move(c.x + 40, c.y + 40);
    await page.mouse.move(c.x, c.y);
    try {
      await page.waitForFunction(() => document.body.dataset.hover === 'edge', null, {
        timeout: 2000,
      });
      return c;
    } catch {
      // The highlight landed on a neighbour (a vertex within a few pixels): try the next edge.
    }
  }
  assert.fail('hovering the visible edges never highlighted an edge');
}

// Clicks the edge under the pointer in `mode` and waits for the edit to land.
export async function clickEdge(page, mode) {
  await page.check(`input[name="edge-mode"][value="${mode}"]`);
  const c = await hoverEdge(page);
  const before = await edits(page);
  await page.mouse.click(c.x, c.y);
  await page.waitForFunction((n) => Number(document.body.dataset.edits || 0) > n, before, {
    timeout: 5000,
  });
  return c;
}

export async function dropFile(page, name, text) {
  const transfer = await page.evaluateHandle(
    ({ name, text }) => {
      const dt = new DataTransfer();
      dt.items.add(new File([text], name, { type: 'application/octet-stream' }));
      return dt;
    },
    { name, text },
  );
  await page.dispatchEvent('#view', 'dragover', { dataTransfer: transfer });
  await page.dispatchEvent('#view', 'drop', { dataTransfer: transfer });
}

// The page's copies of the buffers (what three.js uploads) against RenderBuffers' buffers in wasm:
// after partial updates they must be equal, element for element.
export async function checkGpuCopy(page, what) {
  const mismatch = await page.evaluate(() => {
    const { current, viewer } = window.playground.state;
    const b = current.buffers();
    const gpu = viewer.mesh;
    for (let i = 0; i < b.vertices.length; ++i)
      if (gpu.vertexArray[i] !== b.vertices[i])
        return `vertex float ${i}: ${gpu.vertexArray[i]} != ${b.vertices[i]}`;
    for (let i = 0; i < b.indices.length; ++i)
      if (gpu.indexArray[i] !== b.indices[i])
        return `index ${i}: ${gpu.indexArray[i]} != ${b.indices[i]}`;
    if (gpu.indexCount !== b.indices.length)
      return `draw range ${gpu.indexCount} != ${b.indices.length}`;
    return null;
  });
  check(
    mismatch === null,
    `${what}: the GPU copy differs from RenderBuffers' buffers: ${mismatch}`,
  );
}

// The partial-upload check shared by the edit tests: some bytes went up through bufferSubData, no
// buffer was reallocated, and far less than the whole buffers was sent.
export function checkPartialUpload(upload, what) {
  check(
    upload.full === false,
    `${what}: the edit re-uploaded the buffers whole: ${JSON.stringify(upload)}`,
  );
  checkEqual(upload.fullCalls, 0, `${what}: whole-buffer uploads (bufferData)`);
  check(
    upload.subCalls > 0 && upload.subBytes > 0,
    `${what}: nothing was uploaded: ${JSON.stringify(upload)}`,
  );
  check(
    upload.subBytes * 20 < upload.total,
    `${what}: ${upload.subBytes} B uploaded is not small against the ${upload.total} B buffers`,
  );
}
