// Turns the JSON lines of bench/delaunay_run.sh into bench/results-delaunay.md (a table of first-call
// and warm times with ratios against the peers) and prints the targets summary.
//
//   node bench/delaunay_report.mjs [--quick 0|1] [--elapsed SECONDS] RESULTS.jsonl
//
// The headline of every figure is the first call in a fresh process (what a user meets); the warm
// median of the later calls stands beside it. Targets (issue 6), each a ratio from the same run:
//   native, 1e6 uniform: hullkit at most 1.0x CGAL's time
//   wasm in Node, 1e6 uniform, copies in and out included: at most 0.7x delaunator's time
//   1e5 points on a circle: at most 2x the time of 1e5 uniform points (native and wasm)
//   peak memory, native 1e6 uniform: at most 250 MB
// In quick mode every input has 1e4 points and stands in for both sizes; the report says so.
import { readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import os from 'node:os';

const here = dirname(fileURLToPath(import.meta.url));
const argv = process.argv.slice(2);
const option = (name, fallback) => {
  const i = argv.indexOf(name);
  if (i < 0) return fallback;
  const [value] = argv.splice(i, 2).slice(1);
  return value;
};
const quick = option('--quick', '0') === '1';
const elapsed = option('--elapsed', null);
const file = argv[0] ?? join(here, 'out', 'delaunay', 'results.jsonl');
const results = readFileSync(file, 'utf8').split('\n').filter(Boolean).map((line) => JSON.parse(line));

const find = (kind, impl, input) => results.find((r) => r.kind === kind && r.impl === impl && r.input === input);
const big = quick ? '1e4' : '1e6';
const small = quick ? '1e4' : '1e5';

const seconds = (s) => (s == null ? '–' : s < 0.1 ? `${(s * 1000).toPrecision(3)} ms` : `${s.toPrecision(3)} s`);
const time = (r) => (!r ? 'not run' : r.error ? `error: ${r.error.slice(0, 60)}` : `${seconds(r.first)} (${seconds(r.warm)})`);
const ratio = (a, b) => (a && b && !a.error && !b.error && a.first > 0 && b.first > 0 ? a.first / b.first : null);
const ratioText = (value) => (value == null ? '–' : `${value.toFixed(2)}×`);

const inputs = [...new Set(results.map((r) => r.input))];
const rows = inputs.map((input) => {
  const native = find('native', 'hullkit-incremental', input);
  const cgal = find('native', 'cgal', input);
  const single = find('native-1thread', 'hullkit-incremental', input);
  const qhull = find('native', 'qdelaunay', input);
  const wasm = find('js', 'hullkit-incremental', input);
  const delaunator = find('js', 'delaunator', input);
  // Every triangulation of the same distinct points has the same number of triangles.
  const counts = [native, single, cgal, qhull, wasm, delaunator].filter((r) => r && !r.error).map((r) => r.triangles);
  const agree = counts.every((c) => c === counts[0]);
  return `| ${input} | ${native?.n ?? '–'} | ${time(native)} | ${time(cgal)} | ${ratioText(ratio(native, cgal))} | ` +
    `${time(single)} | ${ratioText(ratio(single, cgal))} | ${time(qhull)} | ` +
    `${time(wasm)} | ${time(delaunator)} | ${ratioText(ratio(wasm, delaunator))} | ${agree ? counts[0] ?? '–' : `differ: ${counts.join(' / ')}`} |`;
});

const targets = [];
function target(label, value, limit, unit, how) {
  const met = value != null && value <= limit;
  targets.push({ label, value, limit, met, text: `${label}: ${value == null ? 'not measured' : `${value.toFixed(2)}${unit}`} (target ≤ ${limit}${unit}) ${value == null ? '–' : met ? 'met' : 'NOT met'} — ${how}` });
}
const uniformBig = `uniform-${big}`;
target(`native ${big} uniform, hullkit / CGAL`, ratio(find('native', 'hullkit-incremental', uniformBig), find('native', 'cgal', uniformBig)), 1.0, '×',
  'first call in a fresh process each');
target(`wasm ${big} uniform, hullkit / delaunator`, ratio(find('js', 'hullkit-incremental', uniformBig), find('js', 'delaunator', uniformBig)), 0.7, '×',
  'first call after loading, copies in and out included');
target(`native ${small} circle / ${small} uniform`, ratio(find('native', 'hullkit-incremental', `circle-${small}`), find('native', 'hullkit-incremental', `uniform-${small}`)), 2.0, '×',
  'hullkit native, first calls');
target(`wasm ${small} circle / ${small} uniform`, ratio(find('js', 'hullkit-incremental', `circle-${small}`), find('js', 'hullkit-incremental', `uniform-${small}`)), 2.0, '×',
  'hullkit wasm, first calls (delaunator: ' +
  ratioText(ratio(find('js', 'delaunator', `circle-${small}`), find('js', 'delaunator', `uniform-${small}`))) + ')');
const singleRatio = ratio(find('native-1thread', 'hullkit-incremental', uniformBig), find('native', 'cgal', uniformBig));
const memory = find('native', 'hullkit-incremental', uniformBig);
target(`peak memory, native ${big} uniform`, memory && !memory.error ? memory.peak_rss_mb : null, 250, ' MB',
  `whole process (input included; CGAL ${find('native', 'cgal', uniformBig)?.peak_rss_mb?.toFixed(0) ?? '–'} MB, ` +
  `qdelaunay ${find('native', 'qdelaunay', uniformBig)?.peak_rss_mb?.toFixed(0) ?? '–'} MB)`);

const cpu = os.cpus()[0]?.model ?? 'unknown CPU';
const lines = [
  '# Delaunay benchmark',
  '',
  `Written by \`bench/delaunay_report.mjs\` from \`bench/delaunay_run.sh\`${quick ? ' in QUICK mode (1e4 points standing in for every size: not the real figures)' : ''}` +
    `${elapsed ? `, ${elapsed} s in all` : ''}; ${cpu}, ${os.cpus().length} cores, Node ${process.version}.`,
  '',
  'Each cell: the first call in a fresh process (the headline), and in parentheses the median of the later',
  'calls in the same process (warm). Native: the triangulation alone on an in-memory array (CGAL: the range',
  'insert into `Delaunay_triangulation_2` with the exact-predicates kernel); qdelaunay: the whole `qdelaunay Qt i`',
  'command reading the same points as text. JS: Node, hullkit\'s wasm `delaunay()` with copies in and out,',
  'delaunator on the same `Float64Array`. Ratios compare first calls. hullkit native uses a second thread for',
  'its output stage on large inputs by default (`DelaunayOptions::threads`); "1 thread" is the same call with',
  '`threads = 1`. CGAL\'s insert and the wasm build are single-threaded.',
  '',
  '| input | points | hullkit native | CGAL | hullkit / CGAL | hullkit native, 1 thread | 1 thread / CGAL | qdelaunay | hullkit wasm | delaunator | wasm / delaunator | triangles |',
  '|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|',
  ...rows,
  '',
  '## Targets',
  '',
  ...targets.map((t) => `- ${t.text}`),
  `- for reference, not a target: native ${big} uniform with one thread (\`threads = 1\`), hullkit / CGAL: ${ratioText(singleRatio)}`,
  '',
];
writeFileSync(join(here, 'results-delaunay.md'), lines.join('\n'));
console.log(`delaunay bench targets${quick ? ' (QUICK mode: 1e4 points only)' : ''}:`);
for (const t of targets) console.log(`  ${t.text}`);
console.log(`(${targets.filter((t) => t.met).length} of ${targets.length} met; table in bench/results-delaunay.md)`);
console.log(`  for reference: native ${big} uniform with one thread, hullkit / CGAL: ${ratioText(singleRatio)}`);
