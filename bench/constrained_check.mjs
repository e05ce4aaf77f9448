// Checks a triangulation dumped by the native constrained benchmark (constrained_bench.cpp --dump
// PREFIX: PREFIX.tri uint32 triples, PREFIX.xy float64 x y) against its input, with the same check as
// the JavaScript rows (bench/constrained_common.mjs), and prints one JSON line:
// {"verdict": "ok"|"wrong", "reason"?, "triangles", "area_error", "t_junctions"?}.
// With --mesh DEGREES the dump is a quality mesh of a polygon (hullkit-mesh: points added inside and on
// the rings) and gets checkMesh instead (clockwise, boundary on the rings, area and perimeter, every
// angle at least DEGREES but where small input angles excuse it); its line adds "length_error",
// "min_angle_deg", "below_bound", "excused_input_angle" and "excused_shells".
//
//   node bench/constrained_check.mjs --input bench/out/constrained/NAME.json --dump PREFIX [--mesh DEGREES]
import { readFileSync } from 'node:fs';
import { parseArgs } from 'node:util';

import { checkGraph, checkMesh, checkPolygon, readInput } from './constrained_common.mjs';

const { values } = parseArgs({ args: process.argv.slice(2), options: { input: { type: 'string' }, dump: { type: 'string' }, mesh: { type: 'string' } } });
const minAngle = values.mesh == null ? null : Number(values.mesh);
if (!values.input || !values.dump || (minAngle != null && !(minAngle >= 0 && minAngle < 60))) {
  console.error('usage: node bench/constrained_check.mjs --input FILE.json --dump PREFIX [--mesh MIN_ANGLE_DEGREES]');
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
  if (minAngle != null) {
    check = input.kind === 'polygon' ? checkMesh(input, triangles, coords, { minAngle }) : { verdict: 'wrong', reason: '--mesh checks polygons only' };
  } else {
    check = input.kind === 'polygon' ? checkPolygon(input, triangles, coords) : checkGraph(input, triangles, coords);
  }
} catch (error) {
  check = { verdict: 'wrong', reason: `unreadable dump: ${String(error?.message ?? error)}` };
}
console.log(JSON.stringify(check));
