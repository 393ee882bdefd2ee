// The vite build (dist/) and the webpack build (dist/webpack/) in headless chromium: serves them
// with vite's preview server, opens the seven pages and compares what each computed; the
// single-file page must fetch no .wasm, the others must.
// playwright-core comes from the playground's packages: HEDGE_REPO/web/node_modules. CHROMIUM
// (default /usr/bin/chromium) is the browser.
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { preview } from 'vite';

const repo = process.env.HEDGE_REPO;
assert.ok(repo, 'HEDGE_REPO must name the hedge checkout');
const expected = JSON.parse(process.argv[2]);
// three.html: a 4 x 4 x 4 segment box (192 triangles) hit 4.5 in front of its +z face; one face
// split in three; uploaded as a few ranges, not whole; drawn without a WebGL error.
const expectedThree = {
  hitDistance: 4.5,
  faces: 194,
  problems: [],
  partialUpload: true,
  glError: 0,
};
// remote.html: the square loaded, picked and drawn in hedge's worker (hedge-mesh/worker), a bad
// scheme refused there as a HedgeError.
const expectedRemote = {
  version: expected.version,
  faces: 2,
  hitFace: 0,
  drawn: [12, 6],
  problems: [],
  error: 'HedgeError: invalid-argument',
};
const { chromium } = await import(
  pathToFileURL(join(repo, 'web/node_modules/playwright-core/index.mjs')).href
);

const server = await preview({ logLevel: 'warn', preview: { port: 0, host: '127.0.0.1' } });
const base = server.resolvedUrls.local[0];
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  headless: true,
  // SwiftShader draws three.html's WebGL without a GPU.
  args: [
    '--no-sandbox',
    '--disable-gpu',
    '--no-first-run',
    '--disable-background-networking',
    '--enable-unsafe-swiftshader',
  ],
});
try {
  for (const [page_, wantsWasm] of [
    ['index.html', true],
    ['single.html', false],
    ['worker.html', true],
    ['webpack/index.html', true],
    ['webpack/remote.html', true],
    ['three.html', true],
    ['remote.html', true],
  ]) {
    const page = await browser.newPage();
    const problems = [];
    const wasm = [];
    page.on('console', (m) => m.type() === 'error' && problems.push(m.text()));
    page.on('pageerror', (e) => problems.push(`uncaught: ${e.message}`));
    page.on('requestfailed', (r) => problems.push(`request failed: ${r.url()}`));
    page.on('request', (r) => r.url().endsWith('.wasm') && wasm.push(r.url()));
    page.on('response', (r) => r.status() >= 400 && problems.push(`${r.status()}: ${r.url()}`));
    await page.goto(new URL(page_, base).href);
    const text = await page.waitForFunction(
      () => document.querySelector('#result').textContent || null,
      null,
      { timeout: 30000 },
    );
    const result = JSON.parse(await text.jsonValue());
    assert.deepEqual(problems, [], `${page_}: console errors`);
    if (page_ === 'three.html') {
      const { uploadedBytes, ...rest } = result;
      assert.deepEqual(rest, expectedThree, `${page_}: what the page computed`);
      assert.ok(uploadedBytes > 0 && uploadedBytes < 4096, `${page_}: ${uploadedBytes} B uploaded`);
    } else if (page_.endsWith('remote.html')) {
      assert.deepEqual(result, expectedRemote, `${page_}: what the page computed`);
    } else assert.deepEqual(result, expected, `${page_}: what the page computed`);
    assert.equal(wasm.length > 0, wantsWasm, `${page_}: .wasm requests: ${wasm.join(', ')}`);
    console.log(`chromium: ${page_}: ${JSON.stringify(result)}; wasm fetched: ${wasm.length}`);
    await page.close();
  }
} finally {
  await browser.close();
  await server.close();
}
