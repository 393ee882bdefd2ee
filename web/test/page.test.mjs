// Browser tests of the playground: it starts clean, shows what `hedge info` says of each sample, and
// its server serves its roots only.
import {
  check,
  checkEqual,
  cliInfo,
  counts,
  drawnPixels,
  loadSample,
  playgroundSuite,
} from './playground.mjs';

playgroundSuite('the page and its server', (test) => {
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
      checkEqual(
        statText.replace(/,/g, ''),
        String(info.faces),
        `${name}: faces in the stats panel`,
      );
    }
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
});
