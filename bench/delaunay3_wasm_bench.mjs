// Times hullkit's WebAssembly delaunay3 on one input file in a fresh Node process and prints one JSON
// line, like build/bench/hullkit_delaunay3_bench does natively.
//
//   node --expose-gc bench/delaunay3_wasm_bench.mjs --input FILE.bin [--runs 3] [--budget 60] [--tets OUT.u32]
//
// The call is the public one of wasm/hullkit.js: createHullkit() (untimed, as are the imports and
// reading the file), then delaunay3(xyz: Float64Array), copies into wasm memory and out included.
// While the module has no delaunay3 the line says {"pending": "no JS binding ..."}. The first call is
// the headline ("first"), the median of the later calls "warm"; a full garbage collection runs
// between calls when Node was started with --expose-gc. --tets writes the last call's tetrahedra as
// raw uint32 for the counter (hullkit_delaunay3_bench --count OUT.u32 --format u32).
import { basename } from 'node:path';
import { parseArgs } from 'node:util';

import { readXyz, summarizeRuns, timeCalls, writeU32 } from './delaunay3_common.mjs';

const { values } = parseArgs({
  options: {
    input: { type: 'string' },
    runs: { type: 'string', default: '3' },
    budget: { type: 'string', default: '60' },
    tets: { type: 'string' },
  },
});
if (!values.input) {
  console.error('usage: node bench/delaunay3_wasm_bench.mjs --input FILE.bin [--runs 3] [--budget 60] [--tets OUT.u32]');
  process.exit(2);
}
const line = { impl: 'hullkit-wasm', input: basename(values.input).replace(/\.bin$/, '') };
const say = (fields) => console.log(JSON.stringify({ ...line, ...fields }));

const xyz = readXyz(values.input);
let hullkit;
try {
  const { default: createHullkit } = await import('../wasm/hullkit.js');
  hullkit = await createHullkit();
} catch (error) {
  say({ error: `loading wasm/hullkit.js: ${error.message ?? error}` });
  process.exit(0);
}
if (typeof hullkit.delaunay3 !== 'function') {
  say({ pending: 'no JS binding: createHullkit() has no delaunay3' });
  process.exit(0);
}

// The tetrahedra as one flat list of indices, whether the binding returns them flat or as quadruples.
const flatTetrahedra = (result) => {
  const t = result.tetrahedra;
  return ArrayBuffer.isView(t) ? t : t.flat();
};
try {
  const { seconds, result } = timeCalls(() => hullkit.delaunay3(xyz), {
    runs: Number(values.runs),
    budget: Number(values.budget),
    between: () => globalThis.gc?.(),
  });
  const tetrahedra = flatTetrahedra(result);
  if (values.tets) writeU32(values.tets, tetrahedra);
  say({ n: xyz.length / 3, threads: 1, ...summarizeRuns(seconds), tetrahedra: tetrahedra.length / 4, peak_rss_mb: process.resourceUsage().maxRSS / 1024 });
} catch (error) {
  say({ error: String(error.message ?? error) });
}
