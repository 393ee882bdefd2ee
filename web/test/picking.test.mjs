// Browser tests of the playground: the picking measurement, on the page and, for 1.5M triangles, in
// a worker while the page keeps drawing and answering.
import { check, checkEqual, playgroundSuite } from './playground.mjs';

playgroundSuite('picking', (test) => {
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
        if (!document.body.dataset.pick && !document.body.dataset.error)
          requestAnimationFrame(tick);
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
    check(
      await page.isHidden('#error'),
      `picking failed: ${await page.textContent('#error-text')}`,
    );
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
});
