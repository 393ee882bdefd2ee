// Browser tests of the playground: the heavy buttons run in hedge's worker helper (web/src/heavy.js)
// while the page keeps drawing and answering. A 26 MB OBJ (spot after 3 Loop steps, 374,784
// triangles, made here with the node build) is read in the worker, then decimated there.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import {
  check,
  checkEqual,
  counts,
  edits,
  playgroundSuite,
  repoDir,
  wasmDir,
} from './playground.mjs';

// Spot after `steps` Loop steps, as the bytes of an OBJ file.
async function largeObj(steps) {
  const { loadHedge } = await import(pathToFileURL(join(wasmDir, 'node.js')).href);
  const hedge = await loadHedge();
  const bytes = readFileSync(join(repoDir, 'data', 'spot_triangulated.obj'));
  const mesh = hedge.fromFile(new Uint8Array(bytes), 'spot_triangulated.obj');
  try {
    mesh.subdivide('loop', steps);
    return { bytes: Buffer.from(mesh.toFile('spot_large.obj')), faces: mesh.counts().faces };
  } finally {
    mesh.dispose();
  }
}

// Counts animation frames from now on, and the longest gap between two, in window.frameGaps.
async function watchFrames(page) {
  await page.evaluate(() => {
    const frames = { count: 0, longest: 0 };
    window.frameGaps = frames;
    let last = performance.now();
    const tick = (now) => {
      frames.longest = Math.max(frames.longest, now - last);
      last = now;
      ++frames.count;
      requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  });
}

// While the page is busy with `what` (data-busy set, and `done`, a JS expression, not yet true),
// clicks the mesh's name, which has no action of its own: the click must be handled while the call
// runs, at once, and frames must have been drawn since the call began. Returns {delay, frames}.
async function answersWhileBusy(page, what, done) {
  try {
    await page.waitForFunction(() => document.body.dataset.busy === '1', null, { timeout: 10000 });
  } catch {
    assert.fail(`the page never drew a frame while ${what} ran (it was blocked until the end)`);
  }
  // The gaps from here on: the call's, not those of handing the file to the page.
  const framesBefore = await page.evaluate(() => {
    window.frameGaps.longest = 0;
    return window.frameGaps.count;
  });
  await page.evaluate((doneSource) => {
    const isDone = new Function(`return ${doneSource}`);
    window.clicked = null;
    document.getElementById('mesh-name').addEventListener(
      'click',
      (event) => {
        window.clicked = {
          delay: performance.now() - event.timeStamp,
          busy: document.body.dataset.busy === '1' && !isDone(),
          frames: window.frameGaps.count,
        };
      },
      { once: true },
    );
  }, done);
  await page.waitForTimeout(300);
  await page.click('#mesh-name');
  const clicked = await page.evaluate(() => window.clicked);
  check(clicked, `the click during ${what} was not handled`);
  check(clicked.busy, `the click came after ${what}: the page did not answer while it ran`);
  check(clicked.delay < 300, `the click waited ${clicked.delay.toFixed(0)} ms during ${what}`);
  const drawn = clicked.frames - framesBefore;
  check(drawn >= 10, `${drawn} frames drawn during ${what}`);
  return { delay: clicked.delay, frames: drawn };
}

playgroundSuite('the heavy buttons in a worker', (test) => {
  test('a large file is read, and decimated, in a worker: the page keeps drawing and answering', async ({
    page,
    log,
  }) => {
    const { bytes, faces } = await largeObj(3);
    checkEqual(faces, 374784, 'triangles of spot after 3 Loop steps');
    // SwiftShader, the software renderer of the tests, draws 374,784 triangles in a second or more
    // (their wireframe in seconds): the gaps it makes are logged, not checked.
    await page.uncheck('#show-wire');
    await watchFrames(page);
    await page.setInputFiles('#file', {
      name: 'spot_large.obj',
      mimeType: 'application/octet-stream',
      buffer: bytes,
    });
    const read = await answersWhileBusy(
      page,
      'reading the file',
      "document.body.dataset.mesh === 'spot_large.obj'",
    );
    await page.waitForFunction(
      () => document.body.dataset.mesh === 'spot_large.obj' || document.body.dataset.error,
      null,
      { timeout: 60000 },
    );
    check(
      await page.isHidden('#error'),
      `loading failed: ${await page.textContent('#error-text')}`,
    );
    const loaded = await counts(page);
    checkEqual(loaded.faces, faces, 'faces shown');
    checkEqual(loaded.vertices, faces / 2 + 2, 'vertices of a closed genus-0 triangle mesh');
    checkEqual(await page.getAttribute('body', 'data-valid'), '1', 'validity after the load');
    const loadOp = await page.textContent('#stat-op');
    check(/read in a worker/.test(loadOp), `the file was not read in the worker: ${loadOp}`);
    const loadTime = await page.textContent('#stat-time');
    const loadGap = await page.evaluate(() => window.frameGaps.longest);
    log(
      `    load ${(bytes.length / 1e6).toFixed(1)} MB: ${loadTime}; ${read.frames} frames drawn while the worker read, a click answered in ${read.delay.toFixed(0)} ms; longest frame gap ${loadGap.toFixed(0)} ms (the rebuild on the page and its first draw)`,
    );

    // Decimate to a quarter: in the worker, then the result replaces the mesh on screen.
    await watchFrames(page);
    const n = await edits(page);
    await page.fill('#decimate-ratio', '25');
    await page.click('#decimate');
    const decimating = await answersWhileBusy(
      page,
      'decimating',
      `Number(document.body.dataset.edits || 0) > ${n}`,
    );
    await page.waitForFunction(
      (k) => Number(document.body.dataset.edits || 0) > k || document.body.dataset.error,
      n,
      { timeout: 60000 },
    );
    check(
      await page.isHidden('#error'),
      `decimating failed: ${await page.textContent('#error-text')}`,
    );
    const decimated = await counts(page);
    check(
      decimated.faces <= Math.round(faces * 0.25) + 2 && decimated.faces > faces * 0.2,
      `decimation to 25% left ${decimated.faces} of ${faces} faces`,
    );
    checkEqual(await page.getAttribute('body', 'data-valid'), '1', 'validity after decimating');
    const op = await page.textContent('#stat-op');
    check(/in a worker/.test(op), `the mesh was not decimated in the worker: ${op}`);
    checkEqual(await page.getAttribute('body', 'data-mesh'), 'spot_large.obj', 'the mesh kept');
    const gap = await page.evaluate(() => window.frameGaps.longest);
    log(
      `    ${op}: ${await page.textContent('#stat-time')}; ${decimating.frames} frames drawn meanwhile, a click answered in ${decimating.delay.toFixed(0)} ms; longest frame gap ${gap.toFixed(0)} ms`,
    );
  });
});
