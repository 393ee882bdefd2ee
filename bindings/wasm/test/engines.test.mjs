// Node 18 (Debian 12's nodejs, 18.20.4) must run the build, the node tests and the browser tests:
// every npm package of the lock files (web/'s, and the package test's consumer project) and the
// package itself must admit it in its "engines" field. A field this reader cannot parse fails too.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';

const root = new URL('../../../', import.meta.url);
const DEBIAN_NODE = '18.20.4';

const parse = (v) => v.split('.').map((part) => (/^[x*]$/i.test(part) ? NaN : Number(part)));
const compare = (a, b) => {
  for (let i = 0; i < 3; ++i) if ((a[i] ?? 0) !== (b[i] ?? 0)) return (a[i] ?? 0) - (b[i] ?? 0);
  return 0;
};

/** Whether version (x.y.z) satisfies one comparator: >=1.2.3, <2, ^1.2, ~1.2.3, 1.x, 18, *. */
function satisfiesComparator(version, comparator) {
  const m = /^(>=|<=|>|<|=|\^|~)?\s*v?(\d+|[x*])(?:\.(\d+|[x*]))?(?:\.(\d+|[x*]))?$/i.exec(
    comparator,
  );
  if (!m) throw new Error(`cannot read the version comparator '${comparator}'`);
  const [, op = '', ...parts] = m;
  const given = parts.filter((p) => p !== undefined);
  const bound = parse(given.join('.'));
  const v = parse(version);
  const wild = bound.findIndex((n) => Number.isNaN(n));
  const precise = wild === -1 ? given.length : wild; // numbers given before any wildcard
  const low = bound.slice(0, precise);
  const nextUp = (k) => [...low.slice(0, k - 1), (low[k - 1] ?? 0) + 1];
  switch (op) {
    case '>=':
      return compare(v, low) >= 0;
    case '>':
      return precise < 3 ? compare(v, nextUp(precise)) >= 0 : compare(v, low) > 0;
    case '<=':
      return precise < 3 ? compare(v, nextUp(precise)) < 0 : compare(v, low) <= 0;
    case '<':
      return compare(v, low) < 0;
    case '^': {
      const k = low.findIndex((n) => n !== 0);
      const upper = nextUp(k === -1 ? precise : Math.min(k + 1, precise));
      return compare(v, low) >= 0 && compare(v, upper) < 0;
    }
    case '~':
      return compare(v, low) >= 0 && compare(v, nextUp(Math.min(precise, 2) || 1)) < 0;
    default:
      if (precise === 0) return true;
      return (
        compare(v, low) >= 0 &&
        (precise === 3 ? compare(v, low) === 0 : compare(v, nextUp(precise)) < 0)
      );
  }
}

/** Whether version satisfies an npm range: alternatives joined by ||, each a list of comparators
 *  (or a hyphen range a - b). */
export function satisfies(version, range) {
  return range.split('||').some((alternative) => {
    const text = alternative.trim();
    if (text === '' || text === '*') return true;
    const hyphen = /^(\S+)\s+-\s+(\S+)$/.exec(text);
    const comparators = hyphen
      ? [`>=${hyphen[1]}`, `<=${hyphen[2]}`]
      : text.replace(/(>=|<=|>|<|=|\^|~)\s+/g, '$1').split(/\s+/);
    return comparators.every((c) => satisfiesComparator(version, c));
  });
}

test('the range reader reads npm ranges as npm does', () => {
  const cases = [
    ['>=18', true],
    ['>=20', false],
    ['>= 18.0.0', true],
    ['^18.0.0 || ^20.0.0 || >=22.0.0', true],
    ['^20.19.0 || >=22.12.0', false],
    ['^14.18.0 || >=16.0.0', true],
    ['^10 || ^12 || ^13.7 || ^14 || >=15.0.1', true],
    ['18 || 20', true],
    ['18.x', true],
    ['>=18.20.5', false],
    ['~18.20.0', true],
    ['~18.19', false],
    ['>=12 <18', false],
    ['16 - 18', true],
    ['<=18', true],
    ['>18', false],
    ['*', true],
  ];
  for (const [range, admits] of cases) assert.equal(satisfies('18.20.4', range), admits, range);
  assert.throws(
    () => satisfies('18.20.4', 'latest'),
    /cannot read the version comparator 'latest'/,
  );
});

function lockEngines(path) {
  const lock = JSON.parse(readFileSync(new URL(path, root), 'utf8'));
  return Object.entries(lock.packages)
    .filter(([, info]) => info.engines?.node)
    .map(([name, info]) => [
      `${path}: ${name || '(the project)'} ${info.version}`,
      info.engines.node,
    ]);
}

test(`every npm package the project installs, and the package, admit node ${DEBIAN_NODE}`, () => {
  const pkg = JSON.parse(readFileSync(new URL('bindings/wasm/package.json', root), 'utf8'));
  const entries = [
    ['bindings/wasm/package.json', pkg.engines.node],
    ...lockEngines('web/package-lock.json'),
  ];
  const consumer = 'bindings/wasm/test/consumer/package-lock.json';
  if (existsSync(new URL(consumer, root))) entries.push(...lockEngines(consumer));
  const refused = entries.filter(([, range]) => !satisfies(DEBIAN_NODE, range));
  assert.deepEqual(
    refused.map(([what, range]) => `${what} wants node ${range}`),
    [],
    `packages that refuse node ${DEBIAN_NODE}`,
  );
  assert.ok(entries.length >= 3, 'too few engines fields found');
});
