// Numbers in files: the module's readers and writers give the same floats as the native ones
// (emscripten's C++ library lacks the floating-point std::from_chars and std::to_chars, for which
// the io layer then falls back on strtof and printf under the same contract).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { hedge, sample } from './support.mjs';

const text = (s) => new TextEncoder().encode(s);

test('coordinates parse to the nearest float, with the grammar of from_chars', () => {
  const mesh = hedge.fromFile(
    text('v 0.1 -2.5e-3 +7\nv 1e-50 3.4028235e38 -0\nv 1.17549435e-38 16777217 .5\nf 1 2 3\n'),
    'numbers.obj',
  );
  const p = Array.from(mesh.positions);
  const expected = [
    0.1, -2.5e-3, 7, 0, 3.4028234663852886e38, -0, 1.17549435e-38, 16777217, 0.5,
  ].map(Math.fround);
  assert.deepEqual(p, expected);
  assert.ok(Object.is(p[5], -0), '-0 keeps its sign');
  mesh.dispose();
});

test('numbers out of float range or in other notations are errors naming the line', () => {
  for (const bad of [
    'v 1e39 0 0',
    'v 0x10 0 0',
    'v nan 0 0',
    'v inf 0 0',
    'v 1.5.5 0 0',
    'v e5 0 0',
  ]) {
    assert.throws(
      () => hedge.fromFile(text(`v 0 0 0\n${bad}\nv 0 1 0\nf 1 2 3\n`), 'bad.obj'),
      (e) => e.kind === 'io' && /bad\.obj:2/.test(e.message),
      bad,
    );
  }
});

test('written files read back to the same floats, bit for bit', () => {
  const mesh = hedge.fromFile(sample('spot_triangulated.obj'), 'spot.obj');
  const original = new Float32Array(mesh.positions);
  mesh.smooth({ method: 'taubin', iterations: 3 }); // floats with long expansions
  const smoothed = new Float32Array(mesh.positions);
  assert.notDeepEqual(smoothed, original);
  for (const name of ['out.obj', 'out.off', 'out.ply', 'out.stl']) {
    const bytes = mesh.toFile(name);
    assert.ok(bytes instanceof Uint8Array && bytes.length > 1000, name);
    const back = hedge.fromFile(bytes, name);
    assert.equal(back.counts().faces, mesh.counts().faces, name);
    if (name !== 'out.stl') assert.deepEqual(new Float32Array(back.positions), smoothed, name);
    assert.deepEqual(back.validate(), [], name);
    back.dispose();
  }
  // Text is the shortest that reads back: 0.1 is written as 0.1, not 0.100000001.
  const tiny = hedge.fromFile(text('v 0.1 0.2 0.3\nv 1 0 0\nv 0 1 0\nf 1 2 3\n'), 'tiny.obj');
  assert.match(new TextDecoder().decode(tiny.toFile('tiny.obj')), /^v 0\.1 0\.2 0\.3$/m);
  tiny.dispose();
  mesh.dispose();
});
