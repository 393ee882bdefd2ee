#!/usr/bin/env node
// Measures the npm package: every file it ships (package.json's "files" found in the folder), raw
// and gzipped (zlib at level 9, as `gzip -9`), and the packed tarball when one is given. Every size
// that the READMEs state comes from this script (test/package.test.mjs compares them).
//   node bindings/wasm/sizes.mjs [DIST] [--json]     DIST defaults to build/wasm/dist
// Prints a Markdown table (the one in bindings/wasm/README.md), or JSON with --json.
import { existsSync, readFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

/** [{file, bytes, gzipped}] for every shipped file present in dist (a directory URL or path). */
export function measure(dist) {
  const dir = typeof dist === 'string' ? pathToFileURL(`${resolve(dist)}/`) : dist;
  const pkg = JSON.parse(readFileSync(new URL('package.json', dir), 'utf8'));
  const files = [...pkg.files, 'package.json'];
  return files
    .filter((file) => existsSync(new URL(file, dir)))
    .map((file) => {
      const bytes = readFileSync(new URL(file, dir));
      return { file, bytes: bytes.length, gzipped: gzipSync(bytes, { level: 9 }).length };
    });
}

/** 1390686 -> '1,390,686'. */
export function grouped(n) {
  return String(n).replace(/\B(?=(\d{3})+(?!\d))/g, ',');
}

/** The rows as the README's table. */
export function markdown(rows) {
  const lines = ['| file | bytes | gzipped |', '| --- | --- | --- |'];
  for (const { file, bytes, gzipped } of rows)
    lines.push(`| \`${file}\` | ${grouped(bytes)} B | ${grouped(gzipped)} B |`);
  return lines.join('\n');
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) {
  const args = process.argv.slice(2);
  const json = args.includes('--json');
  const given = args.find((a) => !a.startsWith('--'));
  const dist = given ?? fileURLToPath(new URL('../../build/wasm/dist/', import.meta.url));
  if (!existsSync(`${dist}/package.json`)) {
    console.error(`sizes: no package in ${dist} (build it first: bindings/wasm/build)`);
    process.exit(1);
  }
  const rows = measure(dist);
  console.log(json ? JSON.stringify(rows, null, 2) : markdown(rows));
}
