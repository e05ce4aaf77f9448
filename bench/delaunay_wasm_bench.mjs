// Times one JavaScript Delaunay implementation on one 2D input file in a fresh Node process and
// prints one JSON line, like build/bench/hullkit_delaunay_bench does natively.
//
//   node bench/delaunay_wasm_bench.mjs --impl IMPL --input FILE.bin [--runs 5] [--budget 60]
//
// IMPL is one of
//   hullkit-ALGO  hullkit's WebAssembly build through its public API (wasm/hullkit.js):
//                 delaunay(xy: Float64Array, {algorithm: ALGO}); the time is the whole public call,
//                 copying the points into wasm memory and the four result arrays out included.
//   delaunator    the npm package delaunator: new Delaunator(xy) on the same Float64Array.
// Loading (createHullkit, imports) and reading the file are not timed. The first call after loading
// is reported on its own as "first" (the headline: what a user meets), the median of the later calls
// as "warm"; a full garbage collection runs between calls when Node was started with --expose-gc.
// Output: {"impl", "input", "n", "first", "runs", "warm", "triangles", "peak_rss_mb", "detail"}.
import { readFileSync } from 'node:fs';
import { basename } from 'node:path';
import { createRequire } from 'node:module';
import { parseArgs } from 'node:util';

function usage(message) {
  console.error(`delaunay_wasm_bench: ${message}`);
  console.error('usage: node bench/delaunay_wasm_bench.mjs --impl hullkit-ALGO|delaunator --input FILE.bin [--runs 5] [--budget 60]');
  process.exit(2);
}

function parseArguments(argv) {
  let values;
  try {
    ({ values } = parseArgs({
      args: argv,
      options: { impl: { type: 'string' }, input: { type: 'string' }, runs: { type: 'string', default: '5' }, budget: { type: 'string', default: '60' } },
    }));
  } catch (error) {
    usage(error.message);
  }
  const args = { impl: values.impl, input: values.input, runs: Number(values.runs), budget: Number(values.budget) };
  if (!args.impl || !args.input) usage('--impl and --input are required');
  if (!(args.runs >= 1)) usage('--runs must be at least 1');
  return args;
}

const args = parseArguments(process.argv.slice(2));
const name = basename(args.input).replace(/\.bin$/, '');
const bytes = readFileSync(args.input);
if (bytes.byteLength % 16 !== 0) usage(`${args.input}: not a whole number of 2D points`);
const xy = new Float64Array(bytes.byteLength / 8);
const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
for (let i = 0; i < xy.length; i++) xy[i] = view.getFloat64(8 * i, true);

let run;
let detail;
if (args.impl.startsWith('hullkit-')) {
  const algorithm = args.impl.slice('hullkit-'.length);
  const { default: createHullkit } = await import('../wasm/hullkit.js');
  const hullkit = await createHullkit();
  if (!hullkit.delaunayAlgorithms.includes(algorithm)) {
    console.log(JSON.stringify({ impl: args.impl, input: name, error: `unknown algorithm "${algorithm}"` }));
    process.exit(0);
  }
  detail = `hullkit wasm delaunay(Float64Array, {algorithm: "${algorithm}"}), copies in and out included`;
  run = () => hullkit.delaunay(xy, { algorithm }).triangles.length / 3;
} else if (args.impl === 'delaunator') {
  const { default: Delaunator } = await import('delaunator');
  const version = createRequire(import.meta.url)('delaunator/package.json').version;
  detail = `delaunator ${version} new Delaunator(Float64Array)`;
  run = () => new Delaunator(xy).triangles.length / 3;
} else {
  usage(`unknown implementation ${args.impl} (known: hullkit-ALGO, delaunator)`);
}

const runs = [];
let triangles = 0;
let total = 0;
try {
  for (let k = 0; k < args.runs && (k === 0 || total < args.budget); k++) {
    if (k > 0 && globalThis.gc) globalThis.gc();
    const start = performance.now();
    triangles = run();
    const seconds = (performance.now() - start) / 1000;
    runs.push(seconds);
    total += seconds;
  }
} catch (error) {
  console.log(JSON.stringify({ impl: args.impl, input: name, error: String(error.message ?? error) }));
  process.exit(0);
}
const later = runs.slice(1).sort((a, b) => a - b);
const m = later.length;
const warm = m === 0 ? null : m % 2 ? later[(m - 1) / 2] : (later[m / 2 - 1] + later[m / 2]) / 2;
console.log(JSON.stringify({
  impl: args.impl,
  input: name,
  n: xy.length / 2,
  first: runs[0],
  runs,
  warm,
  triangles,
  peak_rss_mb: process.resourceUsage().maxRSS / 1024,
  detail,
}));
