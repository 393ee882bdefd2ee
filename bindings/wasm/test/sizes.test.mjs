// The sizes the READMEs state (bindings/wasm/README.md, README.md) are the built files' sizes, as
// sizes.mjs measures them, within 3% (or 1 KiB, for the small JS files): a row of its table, or a
// sentence "`file` is N B (M B gzipped)". After a change to a shipped file, paste sizes.mjs's table.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { measure } from '../sizes.mjs';

const root = new URL('../../../', import.meta.url);
const dist = process.env.HEDGE_WASM_DIST
  ? new URL(`file://${process.env.HEDGE_WASM_DIST.replace(/\/?$/, '/')}`)
  : new URL('build/wasm/dist/', root);

test('every file size the READMEs state is within 3% (or 1 KiB) of the built file', () => {
  const sizes = new Map(measure(dist).map((row) => [row.file, row]));
  const number = (s) => Number(s.replaceAll(',', ''));
  let checked = 0;
  for (const readme of ['bindings/wasm/README.md', 'README.md']) {
    const lines = readFileSync(new URL(readme, root), 'utf8').split('\n');
    lines.forEach((line, i) => {
      // A row of sizes.mjs's table, or a sentence: `file` is N B (M B gzipped).
      const row = /^\| `([\w.]+)` \| ([\d,]+) B \| ([\d,]+) B \|/.exec(line);
      const prose = [...line.matchAll(/`([\w.]+)` is ([\d,]+) B \(([\d,]+) B gzipped\)/g)];
      for (const [, file, bytes, gzipped] of row ? [row] : prose) {
        const where = `${readme}:${i + 1}: ${file}`;
        const actual = sizes.get(file);
        assert.ok(actual, `${where}: not a file of the package`);
        for (const [said, is] of [
          [number(bytes), actual.bytes],
          [number(gzipped), actual.gzipped],
        ])
          assert.ok(
            Math.abs(said - is) <= Math.max(0.03 * is, 1024),
            `${where}: says ${said} B, measured ${is} B (node bindings/wasm/sizes.mjs)`,
          );
        ++checked;
      }
    });
  }
  assert.ok(checked >= 6, `only ${checked} sizes found in the READMEs`);
});
