// Checks a triangulation dumped by the native constrained benchmark (constrained_bench.cpp --dump
// PREFIX: PREFIX.tri uint32 triples, PREFIX.xy float64 x y) against its input, with the same check as
// the JavaScript rows (bench/constrained_common.mjs), and prints one JSON line:
// {"verdict": "ok"|"wrong", "reason"?, "triangles", "area_error", "t_junctions"?}.
//
//   node bench/constrained_check.mjs --input bench/out/constrained/NAME.json --dump PREFIX
import { readFileSync } from 'node:fs';
import { parseArgs } from 'node:util';

import { checkGraph, checkPolygon, readInput } from './constrained_common.mjs';

const { values } = parseArgs({ args: process.argv.slice(2), options: { input: { type: 'string' }, dump: { type: 'string' } } });
if (!values.input || !values.dump) {
  console.error('usage: node bench/constrained_check.mjs --input FILE.json --dump PREFIX');
  process.exit(2);
}
const input = readInput(values.input);
const bytes = (file) => {
  const b = readFileSync(file);
  return b.buffer.slice(b.byteOffset, b.byteOffset + b.byteLength);
};
let check;
try {
  const triangles = new Uint32Array(bytes(`${values.dump}.tri`));
  const coords = new Float64Array(bytes(`${values.dump}.xy`));
  check = input.kind === 'polygon' ? checkPolygon(input, triangles, coords) : checkGraph(input, triangles, coords);
} catch (error) {
  check = { verdict: 'wrong', reason: `unreadable dump: ${String(error?.message ?? error)}` };
}
console.log(JSON.stringify(check));
