// Turns the JSON lines of bench/delaunay3_run.sh into bench/results-delaunay3.md (quick mode:
// bench/out/delaunay3/results-delaunay3.md, never over the committed figures) and prints the
// targets summary.
//
//   node bench/delaunay3_report.mjs [--elapsed SECONDS] [RESULTS.jsonl]
//
// The headline of every time is the first call in a fresh process (what a user meets), the warm
// median of the later calls beside it; whole commands are a fresh process every run, so their
// headline is the median of the runs. Targets (issue 29), each a ratio from the same run, on the
// 1e6 uniform points unless said:
//   hullkit on one thread <= 0.5x CGAL's time; on two threads <= 0.6x its one-thread time
//   the whole command (text in, .ele out) <= 0.5x `tetgen -NEFQ` on the same points
//   peak memory <= 0.5x CGAL's process; 1e7 points in <= 3 GB (hullkit's process)
//   Python: hullkit.delaunay3 <= 0.03x scipy.spatial.Delaunay (first calls)
//   wasm: first call on 1e5 points <= 2x the native one-thread first call
//   no flat tetrahedron from hullkit, anywhere
// In quick mode uniform-1e5 stands in for uniform-1e6 and uniform-1e6 for uniform-1e7 (its memory
// limit scaled to 0.3 GB); the report says so.
import { readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';

import { markdownTable, megabytes, ratioOf, ratioText, seconds } from './delaunay3_common.mjs';

const here = dirname(fileURLToPath(import.meta.url));
const { values, positionals } = parseArgs({ allowPositionals: true, options: { elapsed: { type: 'string' } } });
const file = positionals[0] ?? join(here, 'out', 'delaunay3', 'results.jsonl');
const lines = readFileSync(file, 'utf8').split('\n').filter(Boolean).map((line) => JSON.parse(line));
const meta = lines.find((r) => r.kind === 'meta') ?? {};
const results = lines.filter((r) => r.kind !== 'meta');
const quick = Boolean(meta.quick);

const get = (impl, input) => results.find((r) => r.impl === impl && r.input === input);
const usable = (r) => r && !r.error && !r.pending && r.first > 0;
const inputs = meta.inputs ?? [...new Set(results.map((r) => r.input))].map((name) => ({ name, n: get('hullkit-t1', name)?.n, role: 'compare' }));
const compared = inputs.filter((i) => i.role !== 'memory');
const memoryInput = inputs.find((i) => i.role === 'memory')?.name;
const big = quick ? 'uniform-1e5' : 'uniform-1e6';
const small = 'uniform-1e5';

/** A time cell: first (warm), or what happened instead. */
function time(r) {
  if (!r) return 'not run';
  if (r.pending) return 'pending';
  if (r.skipped) return `not run: ${r.skipped}`;
  if (r.timed_out) return `timed out after ${r.timed_out} s`;
  if (r.error) return `error: ${r.error.slice(0, 80)}`;
  if (r.fresh_each) return `${seconds(r.first)}${r.runs.length > 1 ? ` (median of ${r.runs.length})` : ''}`;
  const processes = r.first_each?.length > 1 ? `median of ${r.first_each.length} processes` : '';
  const warm = r.runs.length > 1 ? `warm ${seconds(r.warm)}` : processes ? '' : '1 call';
  return `${seconds(r.first)} (${[processes, warm].filter(Boolean).join('; ')})`;
}
const pendingReasons = [...new Set(results.filter((r) => r.pending).map((r) => `${r.impl}: ${r.pending}`))];
const ratio = (a, b) => (usable(a) && usable(b) ? ratioOf(a.first, b.first) : null);
const memory = (r) => (r && !r.error && !r.pending ? megabytes(r.peak_rss_mb) : '–');
const peakOf = (...rows) => Math.max(...rows.map((r) => (r && !r.error ? r.peak_rss_mb ?? 0 : 0))) || null;

// ---- tables
const nativeTable = markdownTable(
  [['input', 'l'], ['points', 'r'], ['hullkit, 1 thread', 'r'], ['hullkit, 2 threads', 'r'], ['2 / 1 thread', 'r'], ['CGAL', 'r'],
    ['1 thread / CGAL', 'r'], ['peak memory: hullkit 1 / 2 threads, CGAL', 'r'], ['hullkit / CGAL memory', 'r']],
  inputs.map(({ name, n }) => {
    const [one, two, cgal] = ['hullkit-t1', 'hullkit-t2', 'cgal'].map((impl) => get(impl, name));
    return [name, n ?? '–', time(one), time(two), ratioText(ratio(two, one)), time(cgal), ratioText(ratio(one, cgal)),
      `${memory(one)} / ${memory(two)}, ${memory(cgal)}`, ratioText(ratioOf(peakOf(one, two), peakOf(cgal)))];
  }),
);

const commandTable = markdownTable(
  [['input', 'l'], ['hullkit command', 'r'], ['its tetrahedralization (--stats)', 'r'], ['tetgen -NEFQ', 'r'], ['hullkit / tetgen -NEFQ', 'r'],
    ['tetgen -NFQ (writes .ele)', 'r'], ['qdelaunay Qt i', 'r'], ['peak memory: hullkit, tetgen, qdelaunay', 'r']],
  compared.map(({ name }) => {
    const [command, tetgen, tetgenEle, qdelaunay] = ['hullkit-command', 'tetgen-NEFQ', 'tetgen-NFQ', 'qdelaunay'].map((impl) => get(impl, name));
    return [name, time(command), seconds(command?.core_seconds), time(tetgen), ratioText(ratio(command, tetgen)), time(tetgenEle), time(qdelaunay),
      `${memory(command)}, ${memory(tetgen)}, ${memory(qdelaunay)}`];
  }),
);

const bindingTable = markdownTable(
  [['input', 'l'], ['scipy.spatial.Delaunay', 'r'], ['hullkit.delaunay3 (Python)', 'r'], ['Python: hullkit / scipy', 'r'],
    ['hullkit wasm delaunay3', 'r'], ['wasm / native 1 thread', 'r'], ['peak memory: scipy, hullkit Python, Node', 'r']],
  compared.map(({ name }) => {
    const [scipy, python, wasm, one] = ['scipy', 'hullkit-python', 'hullkit-wasm', 'hullkit-t1'].map((impl) => get(impl, name));
    return [name, time(scipy), time(python), ratioText(ratio(python, scipy), 3), time(wasm), ratioText(ratio(wasm, one)),
      `${memory(scipy)}, ${memory(python)}, ${memory(wasm)}`];
  }),
);

// Furthest-site (the upper 4D hull): scipy's Delaunay(furthest_site=True) and hullkit's, on the inputs
// that have the rows; the same set of tetrahedra where the answer is unique (points in general position).
const furthestInputs = compared.filter(({ name }) => get('hullkit-python-furthest', name) || get('scipy-furthest', name));
const furthestTable = markdownTable(
  [['input', 'l'], ['scipy furthest_site=True', 'r'], ['hullkit furthest_site=True', 'r'], ['hullkit / scipy', 'r'],
    ['tetrahedra: scipy, hullkit', 'r'], ['same set', 'l'], ['peak memory: scipy, hullkit', 'r']],
  furthestInputs.map(({ name }) => {
    const [scipy, python] = ['scipy-furthest', 'hullkit-python-furthest'].map((impl) => get(impl, name));
    const same = scipy?.fingerprint && python?.fingerprint ? (scipy.fingerprint === python.fingerprint ? 'yes' : 'no') : '–';
    return [name, time(scipy), time(python), ratioText(ratio(python, scipy), 3), `${scipy?.tetrahedra ?? '–'}, ${python?.tetrahedra ?? '–'}`, same,
      `${memory(scipy)}, ${memory(python)}`];
  }),
);

// Tetrahedra: counts, flat ones, and whether the set is hullkit's (same fingerprint as hullkit on one thread).
const peers = [['hullkit-t1', 'hullkit'], ['hullkit-t2', 'hullkit 2 threads'], ['cgal', 'CGAL'], ['tetgen-NFQ', 'TetGen'], ['qdelaunay', 'qdelaunay'],
  ['scipy', 'scipy'], ['hullkit-command', 'hullkit command'], ['hullkit-python', 'hullkit Python'], ['hullkit-wasm', 'hullkit wasm']];
const agreement = compared.map(({ name }) => {
  const reference = get('hullkit-t1', name);
  const cells = peers.map(([impl]) => {
    const r = get(impl, name);
    if (!r || r.tetrahedra == null) return { text: r?.pending ? 'pending' : r?.timed_out ? 'timed out' : '–' };
    const same = r.fingerprint && reference?.fingerprint ? r.fingerprint === reference.fingerprint : null;
    const flat = r.flat == null ? '' : `, ${r.flat} flat`;
    return { r, same, text: `${r.tetrahedra}${flat}${impl === 'hullkit-t1' || same == null ? '' : same ? ', =' : ', ≠'}` };
  });
  const counted = cells.filter((c) => c.r);
  return { name, cells, countsAgree: counted.every((c) => c.r.tetrahedra === counted[0].r.tetrahedra), counted };
});
const countTable = markdownTable([['input', 'l'], ...peers.map(([, title]) => [title, 'r'])], agreement.map(({ name, cells }) => [name, ...cells.map((c) => c.text)]));

// ---- targets
const targets = [];
function target(label, value, limit, unit, how, pending) {
  const met = value != null && value <= limit;
  const shown = value == null ? (pending ? `PENDING (${pending})` : 'NOT MEASURED') : `${unit === '×' ? value.toFixed(3) : value.toFixed(2)}${unit} (target ≤ ${limit}${unit}) ${met ? 'MET' : 'NOT MET'}`;
  targets.push({ met, text: `${label}: ${shown} — ${how}` });
}
const at = (impl, input = big) => get(impl, input);
target(`${big}, hullkit 1 thread / CGAL`, ratio(at('hullkit-t1'), at('cgal')), 0.5, '×', 'first call in a fresh process each');
target(`${big}, hullkit 2 threads / 1 thread`, ratio(at('hullkit-t2'), at('hullkit-t1')), 0.6, '×', 'first calls');
target(`${big}, whole command / tetgen -NEFQ`, ratio(at('hullkit-command'), at('tetgen-NEFQ')), 0.5, '×',
  `medians of fresh processes; hullkit reads ${meta.hullkit_reads_node ? 'the same .node' : 'the same values as x y z text (it does not read .node)'} and writes .ele + .node, TetGen writes nothing`);
target(`${big}, peak memory hullkit / CGAL`, ratioOf(peakOf(at('hullkit-t1'), at('hullkit-t2')), peakOf(at('cgal'))), 0.5, '×',
  `whole processes, input included (hullkit ${megabytes(peakOf(at('hullkit-t1'), at('hullkit-t2')))}, the larger of 1 and 2 threads; CGAL ${megabytes(peakOf(at('cgal')))})`);
const memoryLimit = quick ? 0.3 : 3;
const memoryPeak = peakOf(at('hullkit-t1', memoryInput), at('hullkit-t2', memoryInput));
target(`${memoryInput ?? 'memory input'}, hullkit peak memory`, memoryPeak == null ? null : memoryPeak / 1024, memoryLimit, ' GB',
  `${quick ? 'QUICK: 1e6 standing in for 1e7, limit scaled; ' : ''}whole process, the larger of 1 and 2 threads (CGAL ${megabytes(peakOf(at('cgal', memoryInput)))})`);
const python = at('hullkit-python');
target(`${big}, Python hullkit.delaunay3 / scipy`, ratio(python, at('scipy')), 0.03, '×', 'first call in a fresh process each', python?.pending);
const wasm = at('hullkit-wasm', small);
target(`${small}, wasm first call / native 1 thread`, ratio(wasm, at('hullkit-t1', small)), 2, '×', 'first call after createHullkit(), copies included', wasm?.pending);
const hullkitFlat = results.filter((r) => r.impl.startsWith('hullkit') && r.flat != null);
const flatTotal = hullkitFlat.reduce((sum, r) => sum + r.flat, 0);
targets.push({
  met: hullkitFlat.length > 0 && flatTotal === 0,
  text: `no flat tetrahedron from hullkit: ${hullkitFlat.length === 0 ? 'NOT MEASURED' : `${flatTotal} in ${hullkitFlat.length} results ${flatTotal === 0 ? 'MET' : 'NOT MET'}`}` +
    ` — peers on the grids: ${agreement.filter((a) => a.name.startsWith('grid')).map((a) => `${a.name} ` +
      peers.slice(2, 6).map(([impl, title]) => `${title} ${get(impl, a.name)?.flat ?? '–'}`).join(', ')).join('; ')}`,
});

const cgalSame = agreement.map((a) => a.cells[2].same);
const facts = [
  `CGAL's tetrahedra are hullkit's (same set): ${cgalSame.every((s) => s === true) ? 'yes, on every input' : agreement.map((a, i) => `${a.name} ${cgalSame[i] ?? '–'}`).join(', ')}`,
  `tetrahedron counts agree across peers: ${agreement.map((a) => `${a.name} ${a.countsAgree ? 'yes' : 'no'}`).join(', ')}`,
];

// ---- the file
const header = [
  '# 3D Delaunay benchmark (issue 29)',
  '',
  `Written by \`bench/delaunay3_report.mjs\` from \`bash bench/delaunay3_run.sh\`${quick ? ' in QUICK mode (1e5 points standing in for 1e6, 1e6 for 1e7: not the real figures)' : ''}` +
    `${values.elapsed ? `, ${values.elapsed} s in all` : ''}; ${meta.date ?? ''} at ${meta.commit ?? '?'}${meta.uncommitted ? ` (with ${meta.uncommitted} uncommitted files in native/, python/, wasm/)` : ''}; ${meta.cpu ?? '?'}, ${meta.cores ?? '?'} cores, ` +
    `load average ${meta.load_average?.map((l) => l.toFixed(1)).join(' ') ?? '?'} at the start. Peers: CGAL ${meta.cgal}, TetGen ${meta.tetgen}, ` +
    `Qhull ${meta.qhull}, scipy ${meta.scipy} (Debian's), Node ${meta.node}.`,
  '',
  ...(meta.load_average?.[0] > 0.5 * meta.cores
    ? [`**The machine was busy** (load average ${meta.load_average[0].toFixed(1)} on ${meta.cores} cores when the run started): other work shared`,
      'the cores, so times and ratios are rough; rerun on a quiet machine before drawing conclusions.', '']
    : []),
  'Each time: the first call in a fresh process (the headline; for the native library calls, and for the Python',
  `calls on ${big}, the median of the first calls of three fresh processes, the implementations taking turns, since`,
  'this machine\'s speed drifts within minutes), in parentheses the median of the later calls in the same process',
  '(warm). Ratios compare headlines.',
  'Commands run as a fresh process every time, so their figure is the median of those runs (wall time from spawn to',
  'exit). Peak memory: the maximum resident set of the whole process (input included); for the library calls, as',
  'the first call left it (the first call\'s peak, in the first of the fresh processes).',
  '',
];
const body = [
  '## The library call, native',
  '',
  'hullkit: `hullkit::delaunay3(PointSpan, {threads})` on the flat array. CGAL: `Delaunay_triangulation_3<Epick>`',
  'constructed from the vector of `Point_3` (its range insert sorts them spatially first), single-threaded.',
  '',
  ...nativeTable,
  '',
  '## Whole commands',
  '',
  `\`hullkit delaunay3 FILE -o OUT.ele --stats\` reads the points as ${meta.hullkit_reads_node ? 'the `.node` file TetGen reads' : '`x y z` text (the same values as TetGen\'s `.node`: hullkit does not read `.node`)'}`,
  'and writes `OUT.ele` and `OUT.node` (new files each run: the last run\'s are removed before the clock starts); `tetgen -NEFQ FILE.node` reads the same points and writes nothing (-N, -E, -F:',
  'no .node, .ele, .face), `tetgen -NFQ` (one run) writes the `.ele` that is counted below. `qdelaunay Qt i < FILE`',
  `(Qhull's command, triangulated output, indices written to a file), stopped after ${meta.qdelaunay_timeout ?? '?'} s.`,
  '"its tetrahedralization" is the hullkit command\'s own `--stats` seconds (median).',
  '',
  ...commandTable,
  '',
  '## Python and WebAssembly',
  '',
  '`scipy.spatial.Delaunay(points)` with Debian\'s `/usr/bin/python3` (one call from 5e4 points up: a minute or two',
  `and 2-3 GB at 1e6, far longer on the grid; stopped after ${meta.scipy_timeout ?? 1800} s), \`hullkit.delaunay3(points, threads=0)\`, and in Node the public \`delaunay3(Float64Array)\` of`,
  '`wasm/hullkit.js` (first call after `createHullkit()`, copies in and out included). "pending" means the binding',
  'does not exist yet; the run script picks it up once it does.',
  '',
  ...bindingTable,
  '',
  ...pendingReasons.map((reason) => `- pending, ${reason}`),
  ...(pendingReasons.length ? [''] : []),
  ...(furthestInputs.length ? [
    '### Furthest-site',
    '',
    '`scipy.spatial.Delaunay(points, furthest_site=True)` against `hullkit.delaunay3(points, furthest_site=True)` (the',
    'upper hull of the lifted points: every circumsphere holds every point), first calls in fresh processes. "same set":',
    'the same tetrahedra (order-free hash); points on a sphere have many furthest-site tetrahedralizations, so there',
    'the sets and counts may differ. No target names furthest-site; the rows show what a switching user meets.',
    '',
    ...furthestTable,
    '',
  ] : []),
  '## Tetrahedra',
  '',
  'Each cell: the number of tetrahedra, how many have zero volume (exactly: an int64 determinant on the integer',
  'grids, CGAL\'s exact orientation predicate otherwise), and `=` / `≠`: the same set of tetrahedra as hullkit\'s',
  'or not (an order-free hash of the sorted index quadruples). Cospherical points (the grids) have many',
  'Delaunay tetrahedralizations, so there the sets and even the counts may differ.',
  '',
  ...countTable,
  '',
  ...facts.map((f) => `- ${f}`),
  '',
  '## Targets',
  '',
  ...targets.map((t) => `- ${t.text}`),
  '',
];
const report = quick ? join(here, 'out', 'delaunay3', 'results-delaunay3.md') : join(here, 'results-delaunay3.md');
writeFileSync(report, [...header, ...body].join('\n'));
console.log(`delaunay3 bench targets${quick ? ' (QUICK mode: 1e5 points for 1e6, 1e6 for 1e7)' : ''}:`);
for (const t of targets) console.log(`  ${t.text}`);
for (const f of facts) console.log(`  ${f}`);
console.log(`(${targets.filter((t) => t.met).length} of ${targets.length} met; tables in ${report.replace(`${here}/`, 'bench/')})`);
