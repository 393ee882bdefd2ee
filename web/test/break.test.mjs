// Browser tests of the playground: the break scene, strikes on the plate, on spot and on the loaded
// mesh, shards that fall and settle on the ground, and the timed strikes.
import { join } from 'node:path';
import {
  check,
  checkEqual,
  checkGpuCopy,
  checkPartialUpload,
  counts,
  edits,
  lastUpload,
  loadSample,
  outDir,
  playgroundSuite,
} from './playground.mjs';

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
playgroundSuite('break', (test) => {
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
        Math.hypot(s.position[0] - start[i].position[0], s.position[2] - start[i].position[2]) >
        1e-3,
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
    const centre = await page.evaluate(() =>
      window.playground.visibleFaceCentre({ largest: true }),
    );
    check(centre !== null, 'no visible face of spot');
    const stats = await strikeAtPixel(page, centre.x, centre.y);
    check(stats.shards >= 2, `${stats.shards} shards`);
    checkEqual(
      await page.getAttribute('body', 'data-valid'),
      '1',
      'spot after the strike is valid',
    );
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
    const centre = await page.evaluate(() =>
      window.playground.visibleFaceCentre({ largest: true }),
    );
    check(centre !== null, 'no visible face of bob');
    const stats = await strikeAtPixel(page, centre.x, centre.y);
    check(stats.shards >= 2, `${stats.shards} shards`);
    // bob is closed: it breaks into closed pieces, and its caps close the rest (more faces or fewer).
    checkEqual(stats.kind, 'solid', 'the kind of fracture of a closed mesh');
    checkEqual(stats.closed, stats.shards, 'closed pieces');
    check((await counts(page)).faces !== before.faces, 'the strike left the mesh as it was');
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
});
