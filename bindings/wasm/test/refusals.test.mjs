// The shared table of refused edits and bad handles (tests/cases/refusals.txt, which says its
// format) run through the JS API: each case must give the table's status and text, as the C ABI's
// and the C# binding's tests of the same table must.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { hedge, HedgeError } from './support.mjs';

const table = readFileSync(
  fileURLToPath(new URL('../../../tests/cases/refusals.txt', import.meta.url)),
  'utf8',
);

const meshes = new Map();
const cases = [];
for (const raw of table.split('\n')) {
  const line = raw.trim();
  if (line.startsWith('mesh ')) {
    const at = line.indexOf('=');
    meshes.set(
      line.slice(5, at).trim(),
      line
        .slice(at + 1)
        .trim()
        .replaceAll(';', '\n'),
    );
  } else if (line.startsWith('case ')) {
    cases.push(
      line
        .slice(5)
        .split('|')
        .map((f) => f.trim()),
    );
  }
}

/** An element: e:A-B, h:A>B, or e:N, h:N, f:N. */
function element(mesh, token) {
  const pair = /^([eh]):(\d+)[->](\d+)$/.exec(token);
  if (pair) {
    const [a, b] = [Number(pair[2]), Number(pair[3])];
    const h = mesh.oneRing(a).halfedges.find((x) => mesh.halfedge(x).target === b);
    assert.notEqual(h, undefined, `${token}: no such half-edge`);
    return pair[1] === 'e' ? h >> 1 : h;
  }
  return Number(token.slice(2));
}

const parse = (mesh, text) => {
  const [name, ...elements] = text.split(/\s+/);
  return { name, elements: elements.map((t) => element(mesh, t)) };
};

function run(mesh, { name, elements: [a, b] }) {
  switch (name) {
    case 'flip':
      return mesh.flip(a);
    case 'collapse':
      return mesh.collapse(a);
    case 'split_edge':
      return mesh.splitEdge(a, [0, 0, 0]);
    case 'split_face':
      return mesh.splitFace(a, [0, 0, 0]);
    case 'cut_face':
      return mesh.cutFace(a, b);
    case 'fill_hole':
      return mesh.fillHole(a);
    default:
      throw new Error(`unknown edit ${name}`);
  }
}

/** The C ABI's status name of a HedgeError kind: 'bad-handle' -> 'HEDGE_ERROR_BAD_HANDLE'. */
const statusName = (kind) => `HEDGE_ERROR_${kind.toUpperCase().replaceAll('-', '_')}`;

test('the shared table of refusals and error kinds', () => {
  assert.ok(cases.length >= 10);
  for (const [meshName, first, edit, status, text] of cases) {
    const where = `case ${meshName} | ${first} | ${edit}`;
    const mesh = hedge.fromFile(new TextEncoder().encode(meshes.get(meshName)), `${meshName}.obj`);
    const checked = parse(mesh, edit); // before the edits done first
    if (first !== '-') for (const e of first.split(';')) run(mesh, parse(mesh, e.trim()));
    assert.throws(
      () => run(mesh, checked),
      (e) => {
        assert.ok(e instanceof HedgeError, where);
        assert.equal(statusName(e.kind), status, where);
        assert.equal(e.kind === 'refused' ? e.refusal : e.message, text, where);
        if (e.kind === 'refused') assert.equal(mesh.lastRefusal, text, where);
        return true;
      },
    );
    assert.deepEqual(mesh.validate(), [], where);
    mesh.dispose();
  }
});

test('lastRefusal is cleared by an edit that is done', () => {
  const square = hedge.fromFile(new TextEncoder().encode(meshes.get('square')), 'square.obj');
  assert.equal(square.lastRefusal, null);
  assert.throws(
    () => square.fillHole(element(square, 'h:0>1')),
    (e) => e.kind === 'refused',
  );
  assert.equal(square.lastRefusal, 'the half-edge is not on a boundary (it has a face)');
  square.splitEdge(0);
  assert.equal(square.lastRefusal, null);
  assert.deepEqual(square.validate(), []);
  square.dispose();
});

test('a predicate sets lastRefusal to the reason of its own edit', () => {
  const square = hedge.fromFile(new TextEncoder().encode(meshes.get('square')), 'square.obj');
  const inner = element(square, 'h:0>1');
  assert.throws(
    () => square.fillHole(inner),
    (e) => e.kind === 'refused',
  );
  assert.equal(square.canFlip(square.halfedge(inner).edge), false);
  assert.equal(square.lastRefusal, square.refusal('flip', square.halfedge(inner).edge));
  assert.notEqual(square.lastRefusal, 'the half-edge is not on a boundary (it has a face)');
  assert.equal(square.canSplitEdge(0), true);
  assert.equal(square.lastRefusal, null);
  assert.equal(square.canFillHole(inner), false);
  assert.equal(square.lastRefusal, 'the half-edge is not on a boundary (it has a face)');
  assert.deepEqual(square.validate(), []);
  square.dispose();
});
