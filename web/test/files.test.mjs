// Browser tests of the playground: bad and truncated files, refusals and their way out shown where
// the user looks, hard edges of CAD models, and a page that follows the loaded mesh.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import {
  check,
  checkEqual,
  clickEdge,
  counts,
  dropFile,
  loadSample,
  outDir,
  repoDir,
  playgroundSuite,
} from './playground.mjs';

playgroundSuite('files, messages and warnings', (test) => {
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
    checkEqual(
      (await page.textContent('#stat-pick')).trim(),
      '-',
      'picking result after a new mesh',
    );
    check(!(await page.getAttribute('body', 'data-pick')), 'data-pick after a new mesh');
    const menu = await page.evaluate(() => {
      const s = document.getElementById('sample');
      return s.options[s.selectedIndex].textContent;
    });
    check(menu.includes('tet.off'), `the sample menu does not name the dropped file: ${menu}`);
    await loadSample(page, 'bob_small.ply');
    checkEqual(await page.inputValue('#sample'), 'bob_small.ply', 'sample menu after bob');
  });
});
