// Browser tests of the playground: hovering shows the half-edge records; clicks split, flip and
// collapse with partial uploads; refusals change nothing; subdivide, smooth and decimate.
import { join } from 'node:path';
import {
  check,
  checkEqual,
  checkGpuCopy,
  checkPartialUpload,
  clickEdge,
  counts,
  edits,
  hoverEdge,
  lastUpload,
  loadSample,
  outDir,
  playgroundSuite,
} from './playground.mjs';

playgroundSuite('inspecting and editing', (test) => {
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
    const overlay = await page.evaluate(
      () => window.playground.state.viewer.overlay.children.length,
    );
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
    await page.waitForFunction(() => document.body.dataset.hover === 'face', null, {
      timeout: 2000,
    });
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
    await page.waitForFunction(() => document.body.dataset.hover === 'face', null, {
      timeout: 2000,
    });
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
    check(
      !/^(\w+): \1:/.test(refusal.trim()),
      `the decimate refusal repeats its prefix: ${refusal}`,
    );
  });
});
