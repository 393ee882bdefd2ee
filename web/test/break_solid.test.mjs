// Browser tests of the break scene's solid fracture: a strike on a closed 3D object breaks it into
// closed pieces, drawn with their caps in the inner colour, that fall and come to rest on the
// ground; an open mesh breaks by surface fracture instead; solid strikes timed on the page.
import { join } from 'node:path';
import {
  check,
  checkEqual,
  counts,
  edits,
  loadSample,
  outDir,
  playgroundSuite,
} from './playground.mjs';

// Sets up a break scene ('spot' or 'current') and waits for it.
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

// Clicks the largest visible face of the mesh and waits for the strike; returns its stats.
async function strikeLargestFace(page) {
  const centre = await page.evaluate(() => window.playground.visibleFaceCentre({ largest: true }));
  check(centre !== null, 'no visible face to strike');
  const before = await edits(page);
  await page.mouse.click(centre.x, centre.y);
  await page.waitForFunction(
    (n) => Number(document.body.dataset.edits || 0) > n || document.body.dataset.error,
    before,
    { timeout: 20000 },
  );
  check(
    await page.isHidden('#error'),
    `the strike failed: ${await page.textContent('#error-text')}`,
  );
  return JSON.parse(await page.getAttribute('body', 'data-fracture'));
}

// The shown mesh is a closed triangle mesh: every half-edge has a face.
const objectClosed = (page) =>
  page.evaluate(() => {
    const m = window.playground.state.current.mesh;
    const c = m.counts();
    return m.isTriangleMesh() && c.halfedges === 3 * c.faces;
  });

playgroundSuite('break solid', (test) => {
  test('break solid: spot breaks into closed pieces that fall and come to rest', async ({
    page,
    log,
  }) => {
    await setupBreak(page, 'spot');
    await page.selectOption('#break-material', 'stone');
    await page.fill('#break-seed', '3');
    check(await objectClosed(page), 'spot is closed before the strike');
    const stats = await strikeLargestFace(page);
    checkEqual(stats.kind, 'solid', 'the kind of fracture of a closed object');
    check(stats.shards >= 2, `${stats.shards} pieces`);
    checkEqual(stats.closed, stats.shards, 'closed pieces');
    check(stats.bonds >= stats.shards - 1, `${stats.bonds} bonds for ${stats.shards} pieces`);
    checkEqual(
      await page.getAttribute('body', 'data-valid'),
      '1',
      'spot after the strike is valid',
    );
    check(await objectClosed(page), 'the rest of spot is closed after the strike');
    checkEqual(
      Number(await page.getAttribute('body', 'data-shards')),
      stats.shards,
      'bodies in the physics',
    );
    const caps = await page.evaluate(() => window.playground.drawnCaps());
    checkEqual(caps.pieces, stats.shards, 'pieces drawn with their caps in the inner colour');
    check(caps.object, 'the remaining object draws its new caps in the inner colour');

    const { steps: startSteps, shards: start } = await page.evaluate(() =>
      window.playground.strikeSnapshot(),
    );
    await page.waitForFunction(
      (n) => Number(document.body.dataset.physicsSteps) >= n + 20,
      startSteps,
      { timeout: 30000 },
    );
    const moved = await page.evaluate(() => window.playground.shards());
    const falling = moved.filter((s, i) => s.position[1] < start[i].position[1] - 1e-3).length;
    checkEqual(falling, start.length, 'pieces lower after 20 steps');

    await page.waitForFunction(
      () =>
        window.playground
          .shards()
          .every((s) => s.asleep || (s.speed < 0.01 && s.angularSpeed < 0.05)),
      null,
      { timeout: 120000, polling: 500 },
    );
    const ground = await page.evaluate(() => window.playground.groundY());
    for (const [i, s] of (await page.evaluate(() => window.playground.shards())).entries()) {
      check(s.lowest > ground - 0.005, `piece ${i} sinks into the ground: ${s.lowest} < ${ground}`);
      check(s.lowest < ground + 0.005, `piece ${i} rests above the ground: ${s.lowest}`);
    }
    const steps = Number(await page.getAttribute('body', 'data-physics-steps'));
    log(
      `    ${stats.shards} pieces, ${stats.bonds} bonds, settled after ${steps} steps; strike ${stats.last.toFixed(2)} ms (${stats.wasm.toFixed(2)} ms in the library)`,
    );
    await page.screenshot({ path: join(outDir, 'break_solid_spot.png') });
  });

  test('break solid: an open loaded mesh breaks by surface fracture instead', async ({ page }) => {
    await loadSample(page, 'article_example.obj'); // a fan of six triangles: open
    await setupBreak(page, 'current');
    check(!(await objectClosed(page)), 'the fan is open');
    const before = await counts(page);
    const stats = await strikeLargestFace(page);
    checkEqual(stats.kind, 'surface', 'the kind of fracture of an open mesh');
    check(stats.shards >= 1, `${stats.shards} shards`);
    checkEqual(stats.closed, stats.shards, 'shards given a thickness are closed');
    check((await counts(page)).faces !== before.faces, 'the strike changed the mesh');
    checkEqual(await page.getAttribute('body', 'data-valid'), '1', 'the fan is valid');
  });

  test('break solid: 25 stone strikes on spot, timed', async ({ page, log }) => {
    await setupBreak(page, 'spot');
    await page.selectOption('#break-material', 'stone');
    await page.click('#break-bench');
    await page.waitForFunction(
      () => document.body.dataset.breakBench || document.body.dataset.error,
      null,
      { timeout: 180000 },
    );
    check(await page.isHidden('#error'), `timing failed: ${await page.textContent('#error-text')}`);
    const report = JSON.parse(await page.getAttribute('body', 'data-break-bench'));
    checkEqual(report.strikes, 25, 'strikes timed');
    check(report.meanShards >= 2, `${report.meanShards} pieces per stone strike`);
    check(
      report.medianMs > 0 &&
        report.medianInWasmMs <= report.medianMs &&
        report.medianMs <= report.p95Ms,
      `implausible: ${report.text}`,
    );
    log(`    ${report.text}`);
  });
});
