// End-to-end tests of the playground in a real browser: Debian's chromium, headless, driven by
// playwright-core. Serves the page on 127.0.0.1 (a free port), runs each test on a fresh page,
// saves a screenshot per test and exits non-zero when any test fails.
//
//   node web/test/e2e.mjs [--only NAME]
//
// Environment: HEDGE_CLI (default build/release/tools/hedge/hedge, for `hedge info --json`),
// HEDGE_WASM_DIR (default build/wasm/dist), HEDGE_E2E_OUT (default build/output/web-e2e),
// CHROMIUM (default /usr/bin/chromium).
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { startServer } from '../serve.mjs';

const webDir = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const repoDir = resolve(webDir, '..');
const cli = process.env.HEDGE_CLI || join(repoDir, 'build', 'release', 'tools', 'hedge', 'hedge');
const wasmDir = process.env.HEDGE_WASM_DIR || join(repoDir, 'build', 'wasm', 'dist');
const outDir = process.env.HEDGE_E2E_OUT || join(repoDir, 'build', 'output', 'web-e2e');
const executablePath = process.env.CHROMIUM || '/usr/bin/chromium';
const only = process.argv.includes('--only')
  ? process.argv[process.argv.indexOf('--only') + 1]
  : null;

class Failure extends Error {}
function check(condition, message) {
  if (!condition) throw new Failure(message);
}
function checkEqual(actual, expected, what) {
  check(
    actual === expected,
    `${what}: expected ${JSON.stringify(expected)}, got ${JSON.stringify(actual)}`,
  );
}

// `hedge info --json FILE`: the counts the page must show for the same file.
function cliInfo(file) {
  check(existsSync(cli), `no hedge CLI at ${cli} (build the release preset)`);
  const out = execFileSync(cli, ['info', '--json', join(repoDir, 'data', file)], {
    encoding: 'utf8',
  });
  return JSON.parse(out);
}

// ---- page helpers -------------------------------------------------------------------------------

async function counts(page) {
  const text = await page.getAttribute('body', 'data-counts');
  const [vertices, edges, faces] = text.split(',').map(Number);
  return { vertices, edges, faces };
}

async function loadSample(page, name) {
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

async function edits(page) {
  return Number((await page.getAttribute('body', 'data-edits')) || 0);
}

async function lastUpload(page) {
  return JSON.parse(await page.getAttribute('body', 'data-upload'));
}

// Pixels of the WebGL canvas that differ from the background: the mesh was drawn.
async function drawnPixels(page) {
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
async function hoverEdge(page, { central = false } = {}) {
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
  throw new Failure('hovering the visible edges never highlighted an edge');
}

// Clicks the edge under the pointer in `mode` and waits for the edit to land.
async function clickEdge(page, mode) {
  await page.check(`input[name="edge-mode"][value="${mode}"]`);
  const c = await hoverEdge(page);
  const before = await edits(page);
  await page.mouse.click(c.x, c.y);
  await page.waitForFunction((n) => Number(document.body.dataset.edits || 0) > n, before, {
    timeout: 5000,
  });
  return c;
}

async function dropFile(page, name, text) {
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
async function checkGpuCopy(page, what) {
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
function checkPartialUpload(upload, what) {
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

// ---- tests --------------------------------------------------------------------------------------

const tests = [];
const test = (name, body) => tests.push({ name, body });

test('page loads without console errors', async ({ page, problems }) => {
  checkEqual(
    await page.getAttribute('body', 'data-mesh'),
    'spot_triangulated.obj',
    'mesh loaded at start',
  );
  check(
    await page.isHidden('#error'),
    `the page shows an error: ${await page.textContent('#error-text')}`,
  );
  const drawn = await drawnPixels(page);
  check(drawn > 5000, `the canvas shows almost nothing (${drawn} drawn pixels)`);
  checkEqual(await page.getAttribute('body', 'data-valid'), '1', 'validity shown');
  check(problems.length === 0, `console errors: ${problems.join(' | ')}`);
});

test('samples match hedge info', async ({ page }) => {
  for (const name of ['spot_triangulated.obj', 'bob_small.ply', 'anchor.off']) {
    await loadSample(page, name);
    const info = cliInfo(name);
    const shown = await counts(page);
    checkEqual(shown.vertices, info.vertices, `${name}: vertices`);
    checkEqual(shown.edges, info.edges, `${name}: edges`);
    checkEqual(shown.faces, info.faces, `${name}: faces`);
    checkEqual(
      await page.getAttribute('body', 'data-valid'),
      info.valid ? '1' : '0',
      `${name}: validity`,
    );
    const statText = await page.textContent('#stat-f');
    checkEqual(statText.replace(/,/g, ''), String(info.faces), `${name}: faces in the stats panel`);
  }
});

test('hovering an edge shows its half-edge records, one-ring and arrows', async ({ page }) => {
  await loadSample(page, 'spot_control_mesh.obj');
  await page.check('#show-ring');
  await page.check('#show-arrows');
  const c = await hoverEdge(page, { central: true });
  const text = await page.textContent('#records');
  const h = Number(/half-edge h(\d+)/.exec(text)?.[1]);
  check(Number.isInteger(h), `no half-edge in the records panel: ${text}`);
  // The panel's records against hedge's own (read through the page's current) and the pairing rule.
  const record = await page.evaluate((k) => window.playground.state.current.record(k), h);
  checkEqual(record.twin, h ^ 1, 'twin of the hovered half-edge');
  for (const key of ['origin', 'twin', 'next', 'prev']) {
    const prefix = key === 'origin' ? 'v' : 'h';
    check(
      new RegExp(`${key}\\s+${prefix}${record[key]}\\b`).test(text),
      `records panel lacks ${key} ${prefix}${record[key]}: ${text}`,
    );
  }
  check(
    text.includes(`edge e${record.edge}: v${record.origin} - v${record.target}`),
    `edge line missing: ${text}`,
  );
  // Highlight, one-ring spokes and four arrows (the half-edge, next, prev and twin) are drawn.
  const overlay = await page.evaluate(() => window.playground.state.viewer.overlay.children.length);
  const ring = await page.evaluate(
    (v) => window.playground.state.current.oneRing(v).length,
    record.origin,
  );
  check(
    overlay >= 2 + 2 * ring + 4,
    `${overlay} overlay objects for an edge with a ${ring}-vertex ring and 4 arrows`,
  );
  await page.screenshot({ path: join(outDir, 'inspect_edge.png') });

  // A face: the panel lists its loop, the arrows go round it (the picture in the README).
  const face = await page.evaluate(() => window.playground.visibleFaceCentre({ largest: true }));
  check(face, 'no visible face found to hover');
  await page.mouse.move(face.x, face.y);
  await page.waitForFunction(() => document.body.dataset.hover === 'face', null, { timeout: 2000 });
  const loop = await page.evaluate(
    (f) => window.playground.state.current.faceHalfedges(f),
    face.face,
  );
  const faceText = await page.textContent('#records');
  check(
    faceText.includes(
      `face f${face.face}: ${loop.length} corners, half-edges ${loop.map((g) => 'h' + g).join(' ')}`,
    ),
    `face records: ${faceText}`,
  );
  await page.screenshot({ path: join(outDir, 'inspect_face.png') });
});

test('click on an edge splits it with a partial upload', async ({ page, log }) => {
  const before = await counts(page);
  await clickEdge(page, 'split');
  const after = await counts(page);
  // An interior edge between two triangles: one new vertex, three new edges, two new faces.
  checkEqual(after.faces - before.faces, 2, 'faces added by the split');
  checkEqual(after.edges - before.edges, 3, 'edges added by the split');
  checkEqual(after.vertices - before.vertices, 1, 'vertices added by the split');
  checkEqual(await page.getAttribute('body', 'data-valid'), '1', 'validity after the split');
  checkPartialUpload(await lastUpload(page), 'split');
  await checkGpuCopy(page, 'split');
  const line = await page.textContent('#stat-upload');
  check(line.includes('partial'), 'the upload line says partial');
  log(`    split: ${line}`);
});

test('flip and collapse an edge, split a face', async ({ page, log }) => {
  let before = await counts(page);
  await clickEdge(page, 'flip');
  let after = await counts(page);
  checkEqual(JSON.stringify(after), JSON.stringify(before), 'counts after a flip');
  checkPartialUpload(await lastUpload(page), 'flip');
  await checkGpuCopy(page, 'flip');
  log(`    flip: ${await page.textContent('#stat-upload')}`);

  before = after;
  await clickEdge(page, 'collapse');
  after = await counts(page);
  // An interior edge between two triangles: one vertex, three edges and two faces go.
  checkEqual(before.faces - after.faces, 2, 'faces removed by the collapse');
  checkEqual(before.edges - after.edges, 3, 'edges removed by the collapse');
  checkEqual(before.vertices - after.vertices, 1, 'vertices removed by the collapse');
  checkPartialUpload(await lastUpload(page), 'collapse');
  await checkGpuCopy(page, 'collapse');
  log(`    collapse: ${await page.textContent('#stat-upload')}`);

  // A face: zoom in (mouse wheel), hover a face's centre until the page highlights the face, click.
  before = after;
  await page.mouse.move(700, 350);
  for (let i = 0; i < 5; ++i) await page.mouse.wheel(0, -200);
  const centre = await page.evaluate(() => window.playground.visibleFaceCentre());
  check(centre, 'no visible face found to click');
  await page.mouse.move(centre.x, centre.y);
  await page.waitForFunction(() => document.body.dataset.hover === 'face', null, { timeout: 2000 });
  const n = await edits(page);
  await page.mouse.click(centre.x, centre.y);
  await page.waitForFunction((k) => Number(document.body.dataset.edits || 0) > k, n, {
    timeout: 5000,
  });
  after = await counts(page);
  checkEqual(after.faces - before.faces, 2, 'faces added by splitting a triangle');
  checkEqual(after.vertices - before.vertices, 1, 'vertices added by splitting a triangle');
  checkPartialUpload(await lastUpload(page), 'face split');
  await checkGpuCopy(page, 'face split');
  log(`    face split: ${await page.textContent('#stat-upload')}`);
  checkEqual(await page.getAttribute('body', 'data-valid'), '1', 'validity after the edits');
});

test('a refused collapse says why and changes nothing', async ({ page }) => {
  // Every edge collapse of a tetrahedron is refused (it would leave valence-2 vertices).
  await loadSample(page, 'tet.obj');
  const before = await counts(page);
  await page.check('input[name="edge-mode"][value="collapse"]');
  const c = await hoverEdge(page);
  await page.mouse.click(c.x, c.y);
  await page.waitForSelector('#error', { state: 'visible', timeout: 5000 });
  const message = await page.textContent('#error-text');
  check(
    /collapse of halfedge \d+ refused: \S/.test(message),
    `the refusal does not say why: ${message}`,
  );
  checkEqual(
    JSON.stringify(await counts(page)),
    JSON.stringify(before),
    'counts after a refused collapse',
  );
  checkEqual(
    await page.getAttribute('body', 'data-valid'),
    '1',
    'validity after a refused collapse',
  );
  // And the page still edits: a split of the same edge.
  await clickEdge(page, 'split');
  checkEqual(
    (await counts(page)).faces - before.faces,
    2,
    'faces added by a split after the refusal',
  );
});

test('subdivide, smooth and decimate', async ({ page }) => {
  await loadSample(page, 'anchor.off');
  const start = await counts(page);
  await page.click('#subdivide-loop');
  await page.waitForFunction(() => Number(document.body.dataset.edits || 0) >= 1);
  const loop = await counts(page);
  // Loop subdivision of a closed triangle mesh: 4 faces per face, a vertex per edge.
  checkEqual(loop.faces, start.faces * 4, 'faces after Loop subdivision');
  checkEqual(loop.vertices, start.vertices + start.edges, 'vertices after Loop subdivision');
  await page.click('#smooth');
  await page.waitForFunction(() => Number(document.body.dataset.edits || 0) >= 2);
  checkEqual(
    JSON.stringify(await counts(page)),
    JSON.stringify(loop),
    'smoothing keeps the counts',
  );
  await page.fill('#decimate-ratio', '25');
  await page.click('#decimate');
  await page.waitForFunction(() => Number(document.body.dataset.edits || 0) >= 3);
  const decimated = await counts(page);
  check(
    decimated.faces <= Math.round(loop.faces * 0.25) + 2 && decimated.faces > 0,
    `decimation to 25% left ${decimated.faces} of ${loop.faces} faces`,
  );
  checkEqual(await page.getAttribute('body', 'data-valid'), '1', 'validity after decimation');
  check(
    await page.isHidden('#error'),
    `the page shows an error: ${await page.textContent('#error-text')}`,
  );

  // Catmull-Clark of the (closed, mostly quad) control mesh: a quad per corner, so twice the edges,
  // and a vertex per vertex, edge and face.
  await loadSample(page, 'spot_control_mesh.obj');
  const quads = await counts(page);
  await page.click('#subdivide-catmull-clark');
  await page.waitForFunction(() => Number(document.body.dataset.edits || 0) >= 4);
  const cc = await counts(page);
  checkEqual(cc.faces, 2 * quads.edges, 'faces after Catmull-Clark of a closed mesh');
  checkEqual(
    cc.vertices,
    quads.vertices + quads.edges + quads.faces,
    'vertices after Catmull-Clark',
  );
  checkEqual(await page.getAttribute('body', 'data-valid'), '1', 'validity after Catmull-Clark');

  // Decimating the quads is refused, and the refusal names its call once.
  await page.click('#decimate');
  await page.waitForSelector('#error', { state: 'visible', timeout: 5000 });
  const refusal = await page.textContent('#error-text');
  check(refusal.includes('triangulate first'), `the decimate refusal says why: ${refusal}`);
  check(!/^(\w+): \1:/.test(refusal.trim()), `the decimate refusal repeats its prefix: ${refusal}`);
});

test('a malformed file shows an error and the page keeps working', async ({ page }) => {
  const before = await counts(page);
  await dropFile(page, 'broken.obj', 'v 0 0 0\nv 1 0 0\nv 0 1 zero\nf 1 2 3\n');
  await page.waitForSelector('#error', { state: 'visible', timeout: 5000 });
  const message = await page.textContent('#error-text');
  check(
    /broken\.obj\b.*\b3\b/.test(message),
    `the error does not name the file and line 3: ${message}`,
  );
  checkEqual(
    JSON.stringify(await counts(page)),
    JSON.stringify(before),
    'the loaded mesh after a bad file',
  );
  checkEqual(await page.getAttribute('body', 'data-mesh'), 'spot_triangulated.obj', 'mesh kept');

  await dropFile(page, 'empty.stl', '');
  await page.waitForFunction(
    () => (document.body.dataset.error || '').includes('empty.stl'),
    null,
    { timeout: 5000 },
  );
  await page.screenshot({ path: join(outDir, 'malformed_file_error.png') });

  // A truncated face is dropped with a warning naming the line; the rest of the file loads.
  await dropFile(page, 'short.obj', 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2\n');
  await page.waitForFunction(() => document.body.dataset.mesh === 'short.obj', null, {
    timeout: 5000,
  });
  checkEqual((await counts(page)).faces, 1, 'faces of short.obj');
  const notes = await page.textContent('#mesh-warnings');
  check(notes.includes('short.obj:6'), `the warning does not name line 6: ${notes}`);
  await loadSample(page, 'spot_triangulated.obj');

  // Still working: an edit, then a good file by drop, which also clears the message.
  await clickEdge(page, 'split');
  checkEqual(
    (await counts(page)).faces - before.faces,
    2,
    'faces added by a split after the errors',
  );
  await dropFile(
    page,
    'tet.off',
    'OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n',
  );
  await page.waitForFunction(() => document.body.dataset.mesh === 'tet.off', null, {
    timeout: 5000,
  });
  checkEqual(
    JSON.stringify(await counts(page)),
    JSON.stringify({ vertices: 4, edges: 6, faces: 4 }),
    'tetrahedron dropped',
  );
  check(await page.isHidden('#error'), 'the error stays after a good file');
});

// A refusal of a control below the fold is shown where the user looks, and offers the way out.
test('a refusal below the fold shows in view and offers to triangulate', async ({ page }) => {
  await page.setViewportSize({ width: 1280, height: 800 });
  await loadSample(page, 'spot_control_mesh.obj');
  const polygons = await counts(page);
  // Down to the Break and Picking controls, as a user does, then Loop (still in sight).
  await page.locator('#pick-bench').scrollIntoViewIfNeeded();
  const scrolled = await page.evaluate(() => document.getElementById('panel').scrollTop);
  check(scrolled > 200, `the panel did not scroll at 1280x800 (scrollTop ${scrolled})`);
  await page.click('#subdivide-loop');
  await page.waitForSelector('#error', { state: 'visible', timeout: 5000 });
  const refusal = await page.textContent('#error-text');
  check(refusal.includes('triangulate first'), `the Loop refusal says why: ${refusal}`);
  const box = await page.locator('#error').boundingBox();
  check(
    box.y >= 0 && box.y + box.height <= 800 && box.x >= 0 && box.x + box.width <= 1280,
    `the refusal is outside the 1280x800 viewport: ${JSON.stringify(box)}`,
  );
  await page.screenshot({ path: join(outDir, 'refusal_in_view.png') });
  const offer = page.locator('#error-action');
  check(await offer.isVisible(), 'the refusal offers no way out');
  checkEqual((await offer.textContent()).trim(), 'Triangulate', 'the way out offered');
  await offer.click();
  await page.waitForFunction(() => Number(document.body.dataset.edits || 0) >= 1);
  check(await page.isHidden('#error'), 'the refusal stays after triangulating');
  const triangles = await counts(page);
  checkEqual(triangles.vertices, polygons.vertices, 'triangulating keeps the vertices');
  check(
    await page.evaluate(() => window.playground.state.current.mesh.isTriangleMesh()),
    'the mesh is not a triangle mesh after triangulating',
  );
  checkEqual(triangles.faces, 2 * triangles.vertices - 4, 'triangles of a closed genus-0 mesh');
  checkEqual(await page.getAttribute('body', 'data-valid'), '1', 'validity after triangulating');
  await page.click('#subdivide-loop');
  await page.waitForFunction(() => Number(document.body.dataset.edits || 0) >= 2);
  check(
    await page.isHidden('#error'),
    `Loop after triangulating: ${await page.textContent('#error-text')}`,
  );
  checkEqual((await counts(page)).faces, 4 * triangles.faces, 'faces after Loop');
  checkEqual(await page.getAttribute('body', 'data-valid'), '1', 'validity after Loop');
});

test('a CAD model is drawn with hard edges: corner normals with a crease angle', async ({
  page,
}) => {
  await loadSample(page, 'fandisk_quads.off');
  const { vertices, renderVertices } = await page.evaluate(() => {
    const s = window.playground.state.current;
    return { vertices: s.counts().vertices, renderVertices: s.render.sizes().vertices };
  });
  // Smooth vertex normals would give one render vertex per vertex; a crease splits its vertices.
  check(
    renderVertices > vertices * 1.1,
    `${renderVertices} render vertices for ${vertices} vertices: no hard edges`,
  );
  await page.screenshot({ path: join(outDir, 'fandisk_corner_normals.png') });
});

// A file cut short loads what it holds, and the page says the file was not fine.
test('a truncated file shows its warnings as warnings', async ({ page }) => {
  checkEqual(
    (await page.textContent('#stat-valid')).trim(),
    'half-edge structure valid',
    'a clean sample',
  );
  checkEqual(await page.getAttribute('#stat-valid', 'class'), 'ok', 'class of a clean sample');
  check(await page.isHidden('#mesh-warnings'), 'a clean sample shows warnings');
  const text = readFileSync(join(repoDir, 'data', 'spot_triangulated.obj'), 'utf8');
  await dropFile(page, 'spot_cut.obj', text.slice(0, Math.floor(text.length * 0.6)));
  await page.waitForFunction(() => document.body.dataset.mesh === 'spot_cut.obj', null, {
    timeout: 5000,
  });
  const warnings = page.locator('#mesh-warnings');
  check(await warnings.isVisible(), 'the truncated file shows no warnings');
  const shown = await warnings.textContent();
  check(/may be truncated/.test(shown), `the warnings do not say truncated: ${shown}`);
  check(
    /non-manifold vertices split/.test(shown),
    `the warnings omit the split vertices: ${shown}`,
  );
  const colour = await warnings.evaluate((e) => getComputedStyle(e).backgroundColor);
  checkEqual(colour, 'rgb(255, 244, 214)', 'background of the warnings');
  const validity = (await page.textContent('#stat-valid')).trim();
  check(
    validity.startsWith('half-edge structure valid') && validity !== 'half-edge structure valid',
    `the structure line does not say the file was not valid: ${validity}`,
  );
  checkEqual(
    await page.getAttribute('#stat-valid', 'class'),
    'warn',
    'class of the structure line',
  );
  await page.screenshot({ path: join(outDir, 'truncated_file_warnings.png') });
  await loadSample(page, 'anchor.off');
  check(await page.isHidden('#mesh-warnings'), 'the warnings stay after a clean sample');
  checkEqual(await page.getAttribute('#stat-valid', 'class'), 'ok', 'class after a clean sample');
});

test('the page follows the loaded mesh: sample menu, picking result, drop hint', async ({
  page,
}) => {
  check(/glTF/.test(await page.textContent('#panel')), 'the drop hint omits glTF');
  await loadSample(page, 'anchor.off');
  checkEqual(await page.inputValue('#sample'), 'anchor.off', 'sample menu after loading anchor');
  await page.selectOption('#pick-size', '0');
  await page.click('#pick-bench');
  await page.waitForFunction(() => document.body.dataset.pick, null, { timeout: 60000 });
  check((await page.textContent('#stat-pick')).trim() !== '-', 'no picking result shown');
  await dropFile(
    page,
    'tet.off',
    'OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n',
  );
  await page.waitForFunction(() => document.body.dataset.mesh === 'tet.off', null, {
    timeout: 5000,
  });
  checkEqual((await page.textContent('#stat-pick')).trim(), '-', 'picking result after a new mesh');
  check(!(await page.getAttribute('body', 'data-pick')), 'data-pick after a new mesh');
  const menu = await page.evaluate(() => {
    const s = document.getElementById('sample');
    return s.options[s.selectedIndex].textContent;
  });
  check(menu.includes('tet.off'), `the sample menu does not name the dropped file: ${menu}`);
  await loadSample(page, 'bob_small.ply');
  checkEqual(await page.inputValue('#sample'), 'bob_small.ply', 'sample menu after bob');
});

test('picking: 500 rays per frame on 93,696 triangles', async ({ page, log }) => {
  await page.selectOption('#pick-size', '2');
  await page.click('#pick-bench');
  await page.waitForFunction(() => document.body.dataset.pick, null, { timeout: 120000 });
  const report = JSON.parse(await page.getAttribute('body', 'data-pick'));
  checkEqual(report.triangles, 93696, 'triangles of spot after 2 Loop steps');
  check(report.triangles >= 80000, `the picking mesh has ${report.triangles} triangles`);
  check(report.hits > report.rays / 4, `only ${report.hits} of ${report.rays} rays hit the mesh`);
  checkEqual(report.frames, 60, 'frames measured');
  check(report.fps > 0 && report.medianMs <= report.p95Ms, `implausible timing: ${report.text}`);
  log(`    ${report.text}`);
});

test('picking on 1.5M triangles runs in a worker: the page keeps drawing and answering', async ({
  page,
  log,
}) => {
  // Every animation frame until the measurement ends: the longest gap between two.
  await page.evaluate(() => {
    const frames = { count: 0, longest: 0 };
    window.frameGaps = frames;
    let last = performance.now();
    const tick = (now) => {
      frames.longest = Math.max(frames.longest, now - last);
      last = now;
      ++frames.count;
      if (!document.body.dataset.pick && !document.body.dataset.error) requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  });
  await page.selectOption('#pick-size', '4');
  await page.click('#pick-bench');
  // A click while the worker subdivides is handled at once: the time from the click's event to its
  // handler (the page's input delay).
  await page.evaluate(() => {
    document.getElementById('show-wire').addEventListener(
      'click',
      (event) => {
        window.clickDelay = performance.now() - event.timeStamp;
      },
      { once: true },
    );
  });
  await page.waitForTimeout(400);
  const wire = await page.isChecked('#show-wire');
  await page.click('#show-wire');
  const answered = await page.evaluate(() => ({
    busy: document.body.dataset.busy === '1' && !document.body.dataset.pick,
    delay: window.clickDelay,
    checked: document.getElementById('show-wire').checked,
  }));
  checkEqual(answered.checked, !wire, 'the wireframe box after a click');
  check(answered.busy, 'the click came after the picking measurement');
  await page.waitForFunction(
    () => document.body.dataset.pick || document.body.dataset.error,
    null,
    {
      timeout: 180000,
    },
  );
  check(await page.isHidden('#error'), `picking failed: ${await page.textContent('#error-text')}`);
  const report = JSON.parse(await page.getAttribute('body', 'data-pick'));
  checkEqual(report.triangles, 1499136, 'triangles of spot after 4 Loop steps');
  check(answered.delay < 300, `the click waited ${answered.delay.toFixed(0)} ms for the page`);
  const frames = await page.evaluate(() => window.frameGaps);
  check(
    frames.longest < 400,
    `the page stopped drawing for ${frames.longest.toFixed(0)} ms (tree built in ${report.buildMs.toFixed(0)} ms)`,
  );
  check(report.worker, 'the measurement did not run in the worker');
  check(report.hits > report.rays / 4, `only ${report.hits} of ${report.rays} rays hit the mesh`);
  log(
    `    ${report.text}; ${frames.count} frames drawn, longest gap ${frames.longest.toFixed(0)} ms, a click answered in ${answered.delay.toFixed(0)} ms`,
  );
});

// Sets up a break scene ('plate' or 'spot') and waits for it.
async function setupBreak(page, scene) {
  await page.selectOption('#break-scene', scene);
  await page.click('#break-setup');
  await page.waitForFunction(
    (s) => document.body.dataset.scene === s && !document.body.dataset.busy,
    scene,
    { timeout: 30000 },
  );
  check(
    await page.isHidden('#error'),
    `setting up ${scene} failed: ${await page.textContent('#error-text')}`,
  );
}

// Clicks the mesh at world point p and waits for the strike to land; returns the strike's stats.
async function strikeAt(page, p) {
  const { x, y } = await page.evaluate((q) => window.playground.project(q), p);
  return strikeAtPixel(page, x, y);
}

// Clicks the canvas at pixel (x, y) and waits for the strike to land; returns the strike's stats.
async function strikeAtPixel(page, x, y) {
  const before = await edits(page);
  await page.mouse.click(x, y);
  await page.waitForFunction(
    (n) => Number(document.body.dataset.edits || 0) > n || document.body.dataset.error,
    before,
    { timeout: 10000 },
  );
  check(
    await page.isHidden('#error'),
    `the strike failed: ${await page.textContent('#error-text')}`,
  );
  return JSON.parse(await page.getAttribute('body', 'data-fracture'));
}

const shardReport = (page) => page.evaluate(() => window.playground.shards());
const steps = async (page) => Number(await page.getAttribute('body', 'data-physics-steps'));

// Waits until every shard is still (slower than 1 cm/s and 0.05 rad/s), at most `seconds`.
async function waitForRest(page, seconds) {
  await page.waitForFunction(
    () =>
      window.playground
        .shards()
        .every((s) => s.asleep || (s.speed < 0.01 && s.angularSpeed < 0.05)),
    null,
    { timeout: seconds * 1000, polling: 500 },
  );
}

test('break: a strike on the plate makes shards that fall and settle on the ground', async ({
  page,
  log,
}) => {
  await setupBreak(page, 'plate');
  checkEqual((await counts(page)).faces, 100352, 'faces of the plate');
  await page.selectOption('#break-material', 'glass');
  await page.fill('#break-seed', '7');
  const facesBefore = (await counts(page)).faces;
  const stats = await strikeAt(page, [0.11, 1, 0.07]);
  check(stats.shards >= 20 && stats.shards <= 40, `${stats.shards} shards from a glass strike`);
  checkEqual(stats.strikes, 1, 'strikes counted');
  check(
    stats.last > 0 && stats.wasm > 0 && stats.wasm <= stats.last,
    `implausible times: ${JSON.stringify(stats)}`,
  );
  const after = await counts(page);
  check(after.faces < facesBefore, `the plate still has ${after.faces} faces`);
  checkEqual(
    await page.getAttribute('body', 'data-valid'),
    '1',
    'the plate after the strike is valid',
  );
  checkEqual(
    await page.textContent('#stat-valid'),
    'half-edge structure valid',
    'the stats panel after the strike',
  );
  checkPartialUpload(await lastUpload(page), 'strike');
  await checkGpuCopy(page, 'strike');
  checkEqual(
    Number(await page.getAttribute('body', 'data-shards')),
    stats.shards,
    'bodies in the physics',
  );

  // All bodies of the strike, from where it made them (before any step) to a later frame.
  const { steps: startSteps, shards: start } = await page.evaluate(() =>
    window.playground.strikeSnapshot(),
  );
  checkEqual(start.length, stats.shards, 'bodies made by the strike');
  const startY = start.map((s) => s.position[1]);
  check(
    startY.every((y) => y > 0.98 && y < 1),
    `the shards start in the plate (y = 1, 1 cm thick): ${startY.join(' ')}`,
  );
  await page.waitForFunction(
    (n) => Number(document.body.dataset.physicsSteps) >= n + 20,
    startSteps,
    { timeout: 30000 },
  );
  const moved = await shardReport(page);
  checkEqual(moved.length, start.length, 'bodies after 20 steps');
  const falling = moved.filter((s, i) => s.position[1] < start[i].position[1] - 1e-3).length;
  checkEqual(falling, start.length, 'shards lower after 20 steps');
  const shifted = moved.filter(
    (s, i) =>
      Math.hypot(s.position[0] - start[i].position[0], s.position[2] - start[i].position[2]) > 1e-3,
  ).length;
  check(
    shifted > start.length / 2,
    `only ${shifted} of ${start.length} shards moved sideways (away from the impact)`,
  );

  await waitForRest(page, 120);
  const rest = await shardReport(page);
  const ground = await page.evaluate(() => window.playground.groundY());
  checkEqual(ground, 0, 'ground height');
  for (const [i, s] of rest.entries()) {
    check(
      s.lowest > ground - 0.005,
      `shard ${i} sinks into the ground: its lowest point is at ${s.lowest}`,
    );
    check(
      s.position[1] < 0.1,
      `shard ${i} did not fall to the ground: its centre is at y = ${s.position[1]}`,
    );
    check(s.speed < 0.01, `shard ${i} still moves at ${s.speed} m/s`);
  }
  const settledSteps = await steps(page);
  check(/at rest/.test(await page.textContent('#stat-shards')), 'the shard count is shown');
  log(
    `    ${stats.shards} shards, settled after ${settledSteps} steps (${(settledSteps / 60).toFixed(1)} s simulated); strike ${stats.last.toFixed(2)} ms`,
  );
  await page.screenshot({ path: join(outDir, 'break_plate.png') });

  // A second strike elsewhere, another material; and a bad seed is refused without harm.
  await page.selectOption('#break-material', 'stone');
  const second = await strikeAt(page, [-0.6, 1, -0.4]);
  check(second.shards >= 3 && second.shards <= 7, `${second.shards} shards from a stone strike`);
  checkEqual(second.strikes, 2, 'strikes counted');
  checkEqual(
    await page.getAttribute('body', 'data-valid'),
    '1',
    'the plate after two strikes is valid',
  );
  const faces = (await counts(page)).faces;
  await page.fill('#break-seed', '-3');
  const { x, y } = await page.evaluate(() => window.playground.project([0.5, 1, 0.5]));
  await page.mouse.click(x, y);
  await page.waitForSelector('#error', { state: 'visible', timeout: 5000 });
  check(/seed/.test(await page.textContent('#error-text')), 'the error names the seed');
  checkEqual((await counts(page)).faces, faces, 'faces after a refused strike');
});

test('break: a strike on a 3D object', async ({ page }) => {
  await setupBreak(page, 'spot');
  await page.selectOption('#break-material', 'wood');
  const centre = await page.evaluate(() => window.playground.visibleFaceCentre({ largest: true }));
  check(centre !== null, 'no visible face of spot');
  const stats = await strikeAtPixel(page, centre.x, centre.y);
  check(stats.shards >= 2, `${stats.shards} shards`);
  checkEqual(await page.getAttribute('body', 'data-valid'), '1', 'spot after the strike is valid');
  await waitForRest(page, 120);
  const ground = await page.evaluate(() => window.playground.groundY());
  for (const s of await shardReport(page)) {
    check(s.lowest > ground - 0.005, `a shard sinks into the ground: ${s.lowest} < ${ground}`);
    check(s.lowest < ground + 0.005, `a shard rests above the ground: ${s.lowest} > ${ground}`);
  }
});

test('break: a strike on the loaded mesh', async ({ page }) => {
  await loadSample(page, 'bob_small.ply');
  const before = await counts(page);
  await setupBreak(page, 'current');
  checkEqual(await page.getAttribute('body', 'data-mesh'), 'bob_small.ply', 'the mesh broken');
  checkEqual(JSON.stringify(await counts(page)), JSON.stringify(before), 'the copy set up');
  const centre = await page.evaluate(() => window.playground.visibleFaceCentre({ largest: true }));
  check(centre !== null, 'no visible face of bob');
  const stats = await strikeAtPixel(page, centre.x, centre.y);
  check(stats.shards >= 2, `${stats.shards} shards`);
  check((await counts(page)).faces < before.faces, 'the strike broke no face off');
  checkEqual(await page.getAttribute('body', 'data-valid'), '1', 'bob after the strike is valid');
});

test('break: 25 glass strikes on the 100k-triangle plate, timed', async ({ page, log }) => {
  await setupBreak(page, 'plate');
  await page.selectOption('#break-material', 'glass');
  await page.click('#break-bench');
  await page.waitForFunction(
    () => document.body.dataset.breakBench || document.body.dataset.error,
    null,
    { timeout: 120000 },
  );
  check(await page.isHidden('#error'), `timing failed: ${await page.textContent('#error-text')}`);
  const report = JSON.parse(await page.getAttribute('body', 'data-break-bench'));
  checkEqual(report.triangles, 100352, 'triangles of the plate');
  checkEqual(report.strikes, 25, 'strikes timed');
  check(report.meanShards > 30, `${report.meanShards} shards per glass strike`);
  check(
    report.medianMs > 0 &&
      report.medianInWasmMs <= report.medianMs &&
      report.medianMs <= report.p95Ms,
    `implausible: ${report.text}`,
  );
  checkEqual(await page.getAttribute('body', 'data-valid'), '1', 'the plate is left valid');
  log(`    ${report.text}`);
});

test('the server serves its roots only, with the right types', async ({ url }) => {
  const get = async (path) => {
    // node's http keeps the path as written (fetch would resolve the dots first).
    const { request } = await import('node:http');
    return new Promise((resolveGet, rejectGet) => {
      const req = request(new URL(path, url), { method: 'GET', path }, (res) => {
        res.resume();
        res.on('end', () =>
          resolveGet({ status: res.statusCode, type: res.headers['content-type'] }),
        );
      });
      req.on('error', rejectGet);
      req.end();
    });
  };
  checkEqual((await get('/wasm/hedge.wasm')).type, 'application/wasm', 'type of hedge.wasm');
  checkEqual(
    (await get('/wasm/hedge.mjs')).type,
    'text/javascript; charset=utf-8',
    'type of hedge.mjs',
  );
  checkEqual((await get('/data/anchor.off')).status, 200, 'a sample');
  // Each of these would reach the repository's README.md if the dots were followed.
  for (const path of [
    '/../README.md',
    '/data/..%2fREADME.md',
    '/data/%2e%2e%2fREADME.md',
    '/%2e%2e/README.md',
    '/wasm/..%2f..%2f..%2fREADME.md',
    '/node_modules/..%2f..%2fREADME.md',
  ])
    checkEqual((await get(path)).status, 404, `GET ${path}`);
});

// ---- runner -------------------------------------------------------------------------------------

async function run() {
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
  const context = await chromium.launchPersistentContext(profile, {
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
  let failed = 0;
  let ran = 0;
  const started = Date.now();
  try {
    for (const t of tests) {
      if (only && !t.name.includes(only)) continue;
      ++ran;
      const page = await context.newPage();
      const problems = [];
      page.on('console', (m) => {
        if (m.type() === 'error') problems.push(m.text());
      });
      page.on('pageerror', (e) => problems.push(`uncaught: ${e.message}`));
      page.on('requestfailed', (r) => problems.push(`request failed: ${r.url()}`));
      const t0 = Date.now();
      const lines = [];
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
        await t.body({ page, problems, url, log: (s) => lines.push(s) });
        check(problems.length === 0, `browser errors: ${problems.join(' | ')}`);
        console.log(`PASS ${t.name} (${Date.now() - t0} ms)`);
      } catch (error) {
        ++failed;
        console.log(
          `FAIL ${t.name} (${Date.now() - t0} ms)\n    ${error instanceof Failure ? error.message : error.stack}`,
        );
      } finally {
        for (const s of lines) console.log(s);
        const file = join(outDir, `${t.name.replace(/[^a-z0-9]+/gi, '_').toLowerCase()}.png`);
        await page.screenshot({ path: file }).catch(() => {});
        await page.close();
      }
    }
  } finally {
    await context.close();
    server.close();
    rmSync(profile, { recursive: true, force: true });
  }
  console.log(
    `${ran - failed} of ${ran} browser tests passed in ${((Date.now() - started) / 1000).toFixed(1)} s;` +
      ` screenshots in ${outDir}`,
  );
  return failed === 0;
}

run().then(
  (ok) => process.exit(ok ? 0 : 1),
  (error) => {
    console.error(error instanceof Failure ? `e2e: ${error.message}` : error);
    process.exit(1);
  },
);
