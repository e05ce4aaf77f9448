// The benchmark report, from the JSON lines bench/run.sh collected:
//   node bench/report.mjs [--elapsed SECONDS] META.json RESULTS.jsonl
// writes bench/out/results.json ({meta, results}), bench/results.md and bench/results.svg (for a
// quick run, HULLKIT_BENCH_QUICK=1, the .md and .svg go to bench/out/ instead, so the committed
// report is never replaced by a smoke test) and prints the summary of targets to stdout.
//   node bench/report.mjs --meta QUICK
// prints the run's metadata (machine, versions, commit) as JSON, for run.sh to keep.
import { execFileSync } from 'node:child_process';
import { readFileSync, writeFileSync } from 'node:fs';
import { cpus, loadavg, totalmem } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const root = join(here, '..');

const sh = (cmd, args) => {
  try {
    return execFileSync(cmd, args, { cwd: root, encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] }).trim();
  } catch {
    return null;
  }
};

function meta(quick) {
  const dirty = sh('git', ['status', '--porcelain', '--', 'native', 'wasm', 'CMakeLists.txt']);
  const pkg = (name) => {
    try {
      return JSON.parse(readFileSync(join(root, 'node_modules', name, 'package.json'), 'utf8')).version;
    } catch {
      return null;
    }
  };
  return {
    date: new Date().toISOString(),
    quick: quick === '1',
    cpu: cpus()[0]?.model ?? 'unknown',
    cores: cpus().length,
    memory_gb: Math.round(totalmem() / 2 ** 30),
    load_at_start: loadavg().map((x) => Number(x.toFixed(2))),
    node: process.version,
    compiler: sh('c++', ['--version'])?.split('\n')[0] ?? null,
    commit: sh('git', ['rev-parse', '--short', 'HEAD']),
    core_modified: Boolean(dirty),
    qhull: sh('dpkg-query', ['-W', '-f=${Version}', 'libqhull-dev']),
    cgal: sh('dpkg-query', ['-W', '-f=${Version}', 'libcgal-dev']),
    quickhull3d: pkg('quickhull3d'),
    three: pkg('three'),
  };
}

if (process.argv[2] === '--meta') {
  console.log(JSON.stringify(meta(process.argv[3]), null, 2));
  process.exit(0);
}

// ------------------------------------------------------------------------------------ inputs
let argv = process.argv.slice(2);
let elapsed = null;
if (argv[0] === '--elapsed') {
  elapsed = Number(argv[1]);
  argv = argv.slice(2);
}
const [metaFile, resultsFile] = argv;
if (!metaFile || !resultsFile) {
  console.error('usage: node bench/report.mjs [--elapsed SECONDS] META.json RESULTS.jsonl');
  process.exit(2);
}
const info = JSON.parse(readFileSync(metaFile, 'utf8'));
if (elapsed !== null) {
  info.elapsed_seconds = elapsed;
  info.load_at_end = loadavg().map((x) => Number(x.toFixed(2)));
  writeFileSync(metaFile, JSON.stringify(info, null, 2) + '\n'); // so a later re-render keeps them
}
const results = readFileSync(resultsFile, 'utf8')
  .split('\n')
  .filter((line) => line.trim())
  .map((line) => JSON.parse(line));
writeFileSync(join(here, 'out', 'results.json'), JSON.stringify({ meta: info, results }, null, 2) + '\n');

const reportDir = info.quick ? join(here, 'out') : here;

const get = (kind, impl, input) => results.find((r) => r.kind === kind && r.impl === impl && r.input === input);
const ok = (r) => r && !r.error && (r.median != null || r.capped);
const timeOf = (r) => (ok(r) && r.median != null ? r.median : null);
/** The first run: the first call in a fresh process (null if not measured or stopped at the cap). */
const firstOf = (r) => (ok(r) && r.first != null ? r.first : null);
/** The median of the runs after the first (warm allocator, optimised JS). */
const warmOf = (r) => (ok(r) && r.warm_median != null ? r.warm_median : null);

// ---------------------------------------------------------------------------- formatting
const fmtS = (t) => {
  if (t == null) return '—';
  if (t >= 100) return t.toFixed(0);
  if (t >= 10) return t.toFixed(1);
  if (t >= 1) return t.toFixed(2);
  return t.toPrecision(3);
};
const fmtRatio = (x) => (x == null ? '—' : `${x < 0.1 ? x.toPrecision(2) : x.toFixed(2)}×`);
const fmtSpeedup = (x) => (x == null ? '—' : `${x >= 10 ? x.toFixed(0) : x.toFixed(1)}×`);
const fmtMb = (x) => (x == null ? '—' : x >= 100 ? x.toFixed(0) : x.toFixed(1));

const notes = new Map(); // footnote text -> number
function note(text) {
  if (!notes.has(text)) notes.set(text, notes.size + 1);
  return `[${notes.get(text)}]`;
}

/** A time cell: median seconds, "> 60 s" when stopped, the run count when fewer ran, or why not. */
function timeCell(r) {
  if (!r) return '—';
  if (r.error) return /unknown algorithm/.test(r.error) ? `unknown algorithm ${note(r.error)}` : `error ${note(r.error)}`;
  if (r.median == null && r.capped) return `> ${r.cap_seconds} s`;
  let cell = fmtS(r.median);
  const done = r.runs.filter((t) => t !== null).length;
  if (r.capped) cell += ` (${done} run${done === 1 ? '' : 's'}, then one > ${r.cap_seconds} s)`;
  else if (r.runs.length < Math.min(5, r.runs_requested)) cell += ` (${r.runs.length} run${r.runs.length === 1 ? '' : 's'})`;
  return cell;
}

const ratio = (a, b) => (a != null && b != null && b > 0 ? a / b : null);

/** Speed-up of hullkit over a peer; a peer stopped at the cap gives a lower bound. */
function speedup(hk, peer) {
  const t = timeOf(hk);
  if (t == null || !peer || peer.error) return null;
  if (peer.median == null && peer.capped) return { value: peer.cap_seconds / t, lowerBound: true };
  return { value: peer.median / t, lowerBound: false };
}
/** The same between first calls in fresh processes; a peer whose first call was stopped gives a lower bound. */
function firstSpeedup(hk, peer) {
  const t = firstOf(hk);
  if (t == null || !peer || peer.error) return null;
  if (peer.first == null && peer.capped) return { value: peer.cap_seconds / t, lowerBound: true };
  if (peer.first == null) return null;
  return { value: peer.first / t, lowerBound: false };
}
const fmtSpeedupCell = (s) => (s == null ? '—' : `${s.lowerBound ? '> ' : ''}${fmtSpeedup(s.value)}`);

function table(header, rows, align) {
  const lines = [`| ${header.join(' | ')} |`, `| ${header.map((_, i) => (align?.[i] === 'l' ? ':--' : '--:')).join(' | ')} |`];
  for (const row of rows) lines.push(`| ${row.join(' | ')} |`);
  return lines.join('\n');
}

// ---------------------------------------------------------------------------- the groups
const nativeInputs = ['cube-1e5', 'ball-1e5', 'sphere-1e5', 'cube-1e6', 'ball-1e6', 'sphere-1e6', 'bunny'].filter((input) =>
  results.some((r) => r.input === input),
);
const nOf = (input) => results.find((r) => r.input === input && r.n)?.n;
const fmtN = (n) => (n == null ? '—' : n.toLocaleString('en-US'));
const inputLabel = (input) => `${input} (n = ${fmtN(nOf(input))})`;

const md = [];
md.push('# hullkit benchmark results');
md.push('');
md.push(
  `Written by \`bench/run.sh\` (see [README.md](README.md)) on ${info.date.slice(0, 10)}` +
    `${info.elapsed_seconds != null ? ` in ${Math.round(info.elapsed_seconds / 60)} min` : ''}` +
    `${info.quick ? ' — **quick smoke run: 1 run each, no 1e6 inputs**' : ''}.`,
);
md.push('');
md.push(
  `Machine: ${info.cpu}, ${info.cores} cores, ${info.memory_gb} GB; a shared, noisy machine, so single numbers can be off ` +
    `by tens of percent${info.load_at_start ? ` (load average ${info.load_at_start[0]} at the start` +
      `${info.load_at_end ? `, ${info.load_at_end[0]} at the end, ${info.load_at_end[2]} over the last 15 min` : ''})` : ''}. Compiler: ${info.compiler}, Release (-O3 -DNDEBUG -ffp-contract=off). Node ${info.node}. ` +
    `Qhull ${info.qhull} (Debian libqhull-dev), CGAL ${info.cgal} (Debian libcgal-dev), quickhull3d ${info.quickhull3d}, ` +
    `three.js ${info.three}. hullkit at commit ${info.commit}${info.core_modified ? ' plus uncommitted changes to the core' : ''}.`,
);
md.push('');
md.push(
  'Times are medians in seconds of repeated runs (5 at 1,000,000 points, 7 at 100,000, 21 below; fewer where the runs would ' +
    'take over ~60 s, then the count is given). Each implementation × input runs in its own process, one at a time.',
);

// -------- targets (computed first, shown at the top)
const targets = [];
function target(name, value, text, met, why) {
  targets.push({ name, value, text, met, why });
}
{
  const hkCube = get('native', 'hullkit-quickhull', 'cube-1e6');
  const hkSphere = get('native', 'hullkit-quickhull', 'sphere-1e6');
  const whyMissing = (r, input) =>
    !r ? `no ${input} run` : r.error ? r.error : 'no time';
  for (const [input, peer, label, limit, first] of [
    ['cube-1e6', 'qhull', 'Qhull', 0.25, true],
    ['sphere-1e6', 'qhull', 'Qhull', 0.15, true],
    ['cube-1e6', 'cgal', 'CGAL', 0.1, false],
    ['sphere-1e6', 'cgal', 'CGAL', 0.1, false],
  ]) {
    const hk = input === 'cube-1e6' ? hkCube : hkSphere;
    const p = get('native', peer, input);
    // The Qhull targets compare first calls in fresh processes (what a user gets); CGAL medians.
    const pick = first ? firstOf : timeOf;
    const r = ratio(pick(hk), pick(p));
    target(
      `native quickhull ${input} ${first ? 'first call ' : ''}≤ ${limit}× ${label}${first ? "'s first call" : ''}`,
      r,
      r == null ? null : `${fmtRatio(r)} (${fmtS(pick(hk))} s vs ${fmtS(pick(p))} s)`,
      r == null ? null : r <= limit,
      r == null ? (timeOf(hk) == null ? `hullkit-quickhull: ${whyMissing(hk, input)}` : `${label}: ${whyMissing(p, input)}`) : null,
    );
  }
  // The first call's peak (a fresh process computing one hull: the headline); the process's peak
  // after all its runs beside it (glibc keeps some freed memory between runs).
  const mem = ok(hkSphere) ? hkSphere.first_peak_rss_mb ?? hkSphere.peak_rss_mb : null;
  target(
    'native quickhull peak memory sphere-1e6 ≤ 200 MB',
    mem,
    mem == null
      ? null
      : `${fmtMb(mem)} MB (whole process after the first call; ${fmtMb(mem - hkSphere.input_rss_mb)} MB above the ` +
        `${fmtMb(hkSphere.input_rss_mb)} MB it had with the input read; ${fmtMb(hkSphere.peak_rss_mb)} MB after all ${hkSphere.runs.length} runs)`,
    mem == null ? null : mem <= 200,
    mem == null ? `hullkit-quickhull: ${whyMissing(hkSphere, 'sphere-1e6')}` : null,
  );
  // The whole command, file in and OFF out, each run a fresh process.
  for (const [input, timeLimit, memoryLimit] of [
    ['cube-1e6', 0.25, 1.0],
    ['sphere-1e6', 0.2, 0.4],
  ]) {
    const hk = get('command', 'command-hullkit', input);
    const qh = get('command', 'command-qconvex', input);
    const why = !hk ? `no command-hullkit ${input} run` : hk.error ?? (!qh ? `no command-qconvex ${input} run` : qh.error);
    const r = ratio(timeOf(hk), timeOf(qh));
    target(
      `command hullkit hull ${input} ≤ ${timeLimit}× qconvex o`,
      r,
      r == null ? null : `${fmtRatio(r)} (${fmtS(timeOf(hk))} s vs ${fmtS(timeOf(qh))} s, wall, median of ${hk.runs.length})`,
      r == null ? null : r <= timeLimit,
      r == null ? why : null,
    );
    const m = ok(hk) && ok(qh) ? ratio(hk.peak_rss_mb, qh.peak_rss_mb) : null;
    target(
      `command hullkit hull ${input} peak memory ≤ ${memoryLimit}× qconvex o's`,
      m,
      m == null ? null : `${fmtRatio(m)} (${fmtMb(hk.peak_rss_mb)} MB vs ${fmtMb(qh.peak_rss_mb)} MB)`,
      m == null ? null : m <= memoryLimit,
      m == null ? why : null,
    );
  }
  for (const input of ['cube-1e5', 'sphere-1e5', 'cube-1e6', 'sphere-1e6']) {
    const hk = get('js', 'hullkit-quickhull', input);
    for (const [peer, label] of [
      ['quickhull3d', 'quickhull3d'],
      ['three', 'three.js'],
    ]) {
      const p = get('js', peer, input);
      const s = firstSpeedup(hk, p);
      target(
        `wasm quickhull ${input} first call ≥ 10× faster than ${label}'s first call`,
        s?.value ?? null,
        s == null ? null : `${fmtSpeedupCell(s)} (${fmtS(firstOf(hk))} s vs ${p.first == null ? `> ${p.cap_seconds}` : fmtS(p.first)} s)`,
        s == null ? null : s.value >= 10,
        s == null ? (firstOf(hk) == null ? `hullkit wasm quickhull: ${whyMissing(hk, input)}` : `${label}: ${whyMissing(p, input)}`) : null,
      );
    }
  }
  // Warm figures (the median of the runs after the first) must not get worse by more than 10%
  // against the run before issue 9's changes (commit d8971ad, bench/results.md of that commit:
  // all its runs were warm but the first). Absolute seconds: compare on a machine as quiet.
  for (const [kind, input, before] of [
    ['native', 'cube-1e5', 0.00359],
    ['native', 'sphere-1e5', 0.0691],
    ['native', 'cube-1e6', 0.0302],
    ['native', 'ball-1e6', 0.0671],
    ['native', 'sphere-1e6', 0.919],
    ['js', 'cube-1e5', 0.0114],
    ['js', 'sphere-1e5', 0.119],
    ['js', 'cube-1e6', 0.0632],
    ['js', 'sphere-1e6', 1.37],
  ]) {
    const hk = get(kind, 'hullkit-quickhull', input);
    const w = warmOf(hk);
    const r = ratio(w, before);
    target(
      `${kind === 'js' ? 'wasm' : 'native'} quickhull ${input} warm median ≤ 1.1× before (${fmtS(before)} s)`,
      r,
      r == null ? null : `${fmtRatio(r)} (${fmtS(w)} s)`,
      r == null ? null : r <= 1.1,
      r == null ? (hk ? hk.error ?? 'a single run: no warm runs' : `no ${input} run`) : null,
    );
  }
}

// -------- gift wrapping series (needed for a target, shown later)
const seriesInputs = ['ball-1e3', 'ball-3e3', 'ball-1e4', 'ball-3e4', 'ball-1e5'];
const series = seriesInputs.map((input) => {
  const r = get('native', 'hullkit-giftwrap', input);
  const t = timeOf(r);
  const fastest = t != null ? r.min : null;
  return {
    input,
    r,
    n: r?.n ?? nOf(input),
    h: ok(r) ? r.vertices : null,
    t,
    perNH: t != null ? t / (r.n * r.vertices) : null,
    fastestPerNH: fastest != null ? fastest / (r.n * r.vertices) : null,
  };
});
const perNH = series.filter((s) => s.perNH != null).map((s) => s.perNH);
const seriesRatio = perNH.length === seriesInputs.length ? Math.max(...perNH) / Math.min(...perNH) : null;
// The same from each size's fastest run: less exposed to other work on a shared machine.
const fastestPerNH = series.filter((s) => s.fastestPerNH != null).map((s) => s.fastestPerNH);
const fastestRatio = fastestPerNH.length === seriesInputs.length ? Math.max(...fastestPerNH) / Math.min(...fastestPerNH) : null;
target(
  'gift wrapping time/(n·h) within 2× across n = 1e3…1e5',
  seriesRatio,
  seriesRatio == null ? null : `max/min = ${seriesRatio.toFixed(2)} from medians (${fastestRatio.toFixed(2)} from each size's fastest run)`,
  seriesRatio == null ? null : seriesRatio <= 2,
  seriesRatio == null ? `only ${perNH.length} of ${seriesInputs.length} sizes measured` : null,
);

const statusOf = (t) => (t.met == null ? 'NOT MEASURED' : t.met ? 'MET' : 'NOT MET');
md.push('');
md.push('## Targets');
md.push('');
md.push(
  table(
    ['Target', 'Measured', 'Status'],
    targets.map((t) => [t.name, t.text ?? `— (${t.why})`, t.met == null ? 'not measured' : t.met ? '**met**' : '**not met**']),
    ['l', 'l', 'l'],
  ),
);

// -------- native times
md.push('');
md.push('## Native: hullkit vs Qhull vs CGAL');
md.push('');
md.push(
  'Median seconds of the hull computation alone, input already in memory in the form each library takes ' +
    '(hullkit and Qhull: the flat array of doubles; CGAL: a `std::vector<Point_3>` built beforehand). ' +
    'Qhull: `qh_new_qhull` with options `"qhull"` (3-d defaults: merged facets `C-0`, no `Qt`, no output), so its ' +
    'result is its own merged facet list, not triangles. CGAL: `CGAL::convex_hull_3` with ' +
    '`Exact_predicates_inexact_constructions_kernel` into a `Surface_mesh`. Ratios below 1 mean hullkit is faster. ' +
    'Gift wrapping is O(n·h) and is not run on the sphere inputs, where every point is a hull vertex. ' +
    '**First call** = the first run, in a fresh process: what a user running the command once gets ' +
    '(the headline); **warm** = the median of the later runs in the same process.',
);
md.push('');
const fmtFaults = (r) => (ok(r) && r.first_minor_faults != null ? r.first_minor_faults.toLocaleString('en-US') : '—');
md.push(
  table(
    ['Input', 'hullkit first call', 'Qhull first call', 'first ÷ Qhull', 'hullkit warm', 'Qhull warm', 'warm ÷ Qhull', 'CGAL', 'hullkit ÷ CGAL', 'hullkit first-call page faults', 'hullkit giftwrap'],
    nativeInputs.map((input) => {
      const hk = get('native', 'hullkit-quickhull', input);
      const qh = get('native', 'qhull', input);
      return [
        inputLabel(input),
        ok(hk) ? fmtS(firstOf(hk)) : timeCell(hk),
        ok(qh) ? fmtS(firstOf(qh)) : timeCell(qh),
        fmtRatio(ratio(firstOf(hk), firstOf(qh))),
        fmtS(warmOf(hk)),
        fmtS(warmOf(qh)),
        fmtRatio(ratio(warmOf(hk), warmOf(qh))),
        timeCell(get('native', 'cgal', input)),
        fmtRatio(ratio(timeOf(hk), timeOf(get('native', 'cgal', input)))),
        fmtFaults(hk),
        timeCell(get('native', 'hullkit-giftwrap', input)),
      ];
    }),
    ['l'],
  ),
);


md.push('');
md.push('### Native peak memory (MB)');
md.push('');
md.push(
  'Peak resident set of the whole benchmark process (`getrusage` `ru_maxrss`), input included, right after the ' +
    'first call and, in parentheses, after all the runs: the points take ' +
    '2.4 MB at 100,000 points and 24 MB at 1,000,000, and CGAL\'s process holds a second copy as `Point_3`s.',
);
md.push('');
md.push(
  table(
    ['Input', 'hullkit quickhull', 'Qhull', 'CGAL', 'hullkit giftwrap'],
    nativeInputs.map((input) => [
      inputLabel(input),
      ...['hullkit-quickhull', 'qhull', 'cgal', 'hullkit-giftwrap'].map((impl) => {
        const r = get('native', impl, input);
        if (!ok(r)) return '—';
        return r.first_peak_rss_mb == null ? fmtMb(r.peak_rss_mb) : `${fmtMb(r.first_peak_rss_mb)} (${fmtMb(r.peak_rss_mb)})`;
      }),
    ]),
    ['l'],
  ),
);

// -------- vertex counts
const vertexImpls = [
  ['native', 'hullkit-quickhull', 'hullkit quickhull'],
  ['native', 'qhull', 'Qhull'],
  ['native', 'cgal', 'CGAL'],
  ['native', 'hullkit-giftwrap', 'hullkit giftwrap'],
  ['js', 'hullkit-quickhull', 'wasm quickhull'],
  ['js', 'quickhull3d', 'quickhull3d'],
  ['js', 'three', 'three.js'],
];
md.push('');
md.push('### Hull vertex counts');
md.push('');
md.push(
  'As each implementation reports them (hullkit: `Hull::vertices`; Qhull: its vertex list after merging; CGAL: the ' +
    'mesh\'s vertices; quickhull3d and three.js: the distinct points used by their faces). Points of the sphere inputs ' +
    'lie on the sphere only up to rounding, so implementations may legitimately disagree about nearly coplanar ones.',
);
md.push('');
md.push(
  table(
    ['Input', ...vertexImpls.map(([, , label]) => label), 'Agree?'],
    nativeInputs.map((input) => {
      const counts = vertexImpls.map(([kind, impl]) => {
        const r = get(kind, impl, input);
        return ok(r) && r.vertices != null ? r.vertices : null;
      });
      const known = counts.filter((c) => c != null);
      const agree = known.length < 2 ? '—' : known.every((c) => c === known[0]) ? 'yes' : '**no**';
      return [inputLabel(input), ...counts.map((c) => (c == null ? '—' : c.toLocaleString('en-US'))), agree];
    }),
    ['l'],
  ),
);

// -------- the whole command
const commandInputs = ['cube-1e5', 'sphere-1e5', 'cube-1e6', 'sphere-1e6'].filter((input) =>
  results.some((r) => r.kind === 'command' && r.input === input),
);
if (commandInputs.length) {
  md.push('');
  md.push('## The whole command: `hullkit hull FILE -o OUT.off` vs `qconvex o < FILE > OUT.off`');
  md.push('');
  md.push(
    'What a user of the command line waits for: one fresh process per run (median of the runs), reading the ' +
      'same rbox-format text file (`bench/out/NAME.txt`, the points of `NAME.bin`) and writing OFF. Wall time from ' +
      "fork to exit; peak memory and minor page faults are the child process's own (`wait4`). `qconvex o` lists " +
      "every input point in its OFF file and Qhull's merged facets; hullkit lists the hull vertices and triangles.",
  );
  md.push('');
  md.push(
    table(
      ['Input', 'hullkit', 'qconvex o', 'ratio', 'hullkit peak MB', 'qconvex peak MB', 'memory ratio', 'hullkit page faults', 'qconvex page faults'],
      commandInputs.map((input) => {
        const hk = get('command', 'command-hullkit', input);
        const qh = get('command', 'command-qconvex', input);
        return [
          inputLabel(input),
          timeCell(hk),
          timeCell(qh),
          fmtRatio(ratio(timeOf(hk), timeOf(qh))),
          ok(hk) ? fmtMb(hk.peak_rss_mb) : '—',
          ok(qh) ? fmtMb(qh.peak_rss_mb) : '—',
          ok(hk) && ok(qh) ? fmtRatio(ratio(hk.peak_rss_mb, qh.peak_rss_mb)) : '—',
          fmtFaults(hk),
          fmtFaults(qh),
        ];
      }),
      ['l'],
    ),
  );
}

// -------- wasm vs JS
const jsInputs = nativeInputs.filter((input) => results.some((r) => r.kind === 'js' && r.input === input));
md.push('');
md.push('## WebAssembly in Node: hullkit vs quickhull3d vs three.js');
md.push('');
md.push(
  `Median seconds in Node ${info.node}. hullkit: the public call \`hull(Float64Array, {algorithm})\` of ` +
    '`wasm/hullkit.js`, copying the points into wasm memory and the triangles and vertices out included. ' +
    `quickhull3d ${info.quickhull3d} takes an array of \`[x, y, z]\` arrays and three.js ${info.three} ` +
    '`ConvexHull.setFromPoints` an array of `Vector3`: **their times include building that input from the ' +
    'Float64Array** (the conversion alone is listed below), hullkit\'s needs none. A garbage collection runs ' +
    'between runs, outside the timing. A run still going after 60 s is stopped and shown as "> 60 s"; a speed-up ' +
    'against it is then a lower bound. Speed-up = peer time ÷ hullkit time.',
);
md.push('');
md.push(
  'First call = the first run in a fresh Node process, right after `createHullkit()` (hullkit) or the import ' +
    '(peers): the headline, what a page calling `hull()` once gets. The medians in the second table include it.',
);
md.push('');
const firstCell = (r) => (!ok(r) ? timeCell(r) : r.first == null ? `> ${r.cap_seconds} s` : fmtS(r.first));
md.push(
  table(
    ['Input', 'hullkit first call', 'quickhull3d first call', 'three.js first call', 'first-call speed-up vs quickhull3d', 'vs three.js'],
    jsInputs.map((input) => {
      const hk = get('js', 'hullkit-quickhull', input);
      return [
        inputLabel(input),
        firstCell(hk),
        firstCell(get('js', 'quickhull3d', input)),
        firstCell(get('js', 'three', input)),
        fmtSpeedupCell(firstSpeedup(hk, get('js', 'quickhull3d', input))),
        fmtSpeedupCell(firstSpeedup(hk, get('js', 'three', input))),
      ];
    }),
    ['l'],
  ),
);
md.push('');
md.push(
  table(
    ['Input', 'hullkit wasm quickhull median', 'hullkit warm', 'quickhull3d', 'three.js', 'speed-up vs quickhull3d', 'speed-up vs three.js', 'hullkit wasm giftwrap'],
    jsInputs.map((input) => {
      const hk = get('js', 'hullkit-quickhull', input);
      return [
        inputLabel(input),
        timeCell(hk),
        fmtS(warmOf(hk)),
        timeCell(get('js', 'quickhull3d', input)),
        timeCell(get('js', 'three', input)),
        fmtSpeedupCell(speedup(hk, get('js', 'quickhull3d', input))),
        fmtSpeedupCell(speedup(hk, get('js', 'three', input))),
        timeCell(get('js', 'hullkit-giftwrap', input)),
      ];
    }),
    ['l'],
  ),
);
md.push('');
md.push('Input conversion alone (median seconds, included in the peers\' times above) and peak memory of each Node process (MB, Node itself is ~50 MB):');
md.push('');
md.push(
  table(
    ['Input', 'quickhull3d conversion', 'three.js conversion', 'hullkit wasm MB', 'quickhull3d MB', 'three.js MB'],
    jsInputs.map((input) => {
      const conv = (impl) => {
        const r = get('js', impl, input);
        return ok(r) && r.convert_median != null ? fmtS(r.convert_median) : '—';
      };
      const mem = (impl) => {
        const r = get('js', impl, input);
        return ok(r) && r.peak_rss_mb != null ? fmtMb(r.peak_rss_mb) : '—';
      };
      return [inputLabel(input), conv('quickhull3d'), conv('three'), mem('hullkit-quickhull'), mem('quickhull3d'), mem('three')];
    }),
    ['l'],
  ),
);

// -------- gift wrapping series
const minPerNH = perNH.length ? Math.min(...perNH) : null;
md.push('');
md.push('## Gift wrapping scaling: time / (n·h)');
md.push('');
md.push(
  'Native `hullkit::hull` with the giftwrap algorithm on n points uniform in a ball (h = hull vertices). ' +
    'O(n·h) means the last column stays flat.',
);
md.push('');
md.push(
  table(
    ['n', 'h', 'median (s)', 'time / (n·h) (ns)', 'relative to the smallest', 'fastest run (s)', 'fastest / (n·h) (ns)'],
    series.map((s) => [
      fmtN(s.n),
      s.h == null ? '—' : s.h.toLocaleString('en-US'),
      timeCell(s.r),
      s.perNH == null ? '—' : (s.perNH * 1e9).toFixed(2),
      s.perNH == null ? '—' : `${(s.perNH / minPerNH).toFixed(2)}×`,
      s.fastestPerNH == null ? '—' : fmtS(s.r.min),
      s.fastestPerNH == null ? '—' : (s.fastestPerNH * 1e9).toFixed(2),
    ]),
  ),
);
md.push('');
md.push(
  `max/min of time/(n·h): ${
    seriesRatio == null
      ? '— (incomplete series)'
      : `**${seriesRatio.toFixed(2)}** from the medians (target ≤ 2); ${fastestRatio.toFixed(2)} from each size's fastest run, ` +
        'which other work on the machine disturbs least'
  }.`,
);

if (notes.size) {
  md.push('');
  md.push('## Notes');
  md.push('');
  for (const [text, k] of notes) md.push(`${k}. ${text.replace(/\|/g, '\\|')}`);
}
md.push('');
md.push('![hullkit benchmark ratios](results.svg)');
md.push('');
writeFileSync(join(reportDir, 'results.md'), md.join('\n'));

// ---------------------------------------------------------------------------------- SVG
// Horizontal bars on a log scale, three panels: native time ratios (lower is better), wasm
// speed-ups (higher is better), gift wrapping time/(n·h) relative to its minimum (flat is better).
// Its own card background (light, or dark under prefers-color-scheme: dark) keeps it readable on
// any page.
function svgChart() {
  const W = 860;
  const labelW = 200;
  const plotX = labelW + 10;
  const plotW = 470;
  const barH = 14;
  const rowH = 20;
  const esc = (s) => String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
  const parts = [];
  let y = 16;

  const panel = (title, subtitle, rows, scale, marks) => {
    // rows: {label, series: [{name, cls, value, text, target?, lowerBound?}]} ; value null = missing
    y += 20;
    parts.push(`<text class="title" x="16" y="${y}">${esc(title)}</text>`);
    y += 16;
    parts.push(`<text class="sub" x="16" y="${y}">${esc(subtitle)}</text>`);
    y += 12;
    const x = scale.linear
      ? (v) => plotX + (plotW * (v - scale.min)) / (scale.max - scale.min)
      : (v) => plotX + (plotW * (Math.log10(v) - Math.log10(scale.min))) / (Math.log10(scale.max) - Math.log10(scale.min));
    const clampX = (v) => Math.min(plotX + plotW, Math.max(plotX, x(v)));
    const top = y;
    const height = rows.reduce((sum, row) => sum + row.series.length * rowH + 8, 0);
    // grid
    for (const tick of scale.ticks) {
      parts.push(`<line class="${tick === scale.parity ? 'parity' : 'grid'}" x1="${x(tick).toFixed(1)}" y1="${top}" x2="${x(tick).toFixed(1)}" y2="${top + height}"/>`);
      parts.push(`<text class="tick" x="${x(tick).toFixed(1)}" y="${top + height + 12}" text-anchor="middle">${tick}×</text>`);
    }
    for (const mark of marks) {
      parts.push(`<line class="target" x1="${x(mark.value).toFixed(1)}" y1="${top - 4}" x2="${x(mark.value).toFixed(1)}" y2="${top + height}"/>`);
      parts.push(`<text class="targetlabel" x="${(x(mark.value) + 3).toFixed(1)}" y="${top + 4}">${esc(mark.label)}</text>`);
    }
    let ry = top + 6;
    for (const row of rows) {
      parts.push(`<text class="label" x="${labelW}" y="${ry + barH - 3}" text-anchor="end">${esc(row.label)}</text>`);
      for (const s of row.series) {
        if (s.value == null) {
          parts.push(`<rect class="missing" x="${plotX}" y="${ry}" width="${plotW * 0.3}" height="${barH}" rx="2"/>`);
          parts.push(`<text class="value" x="${plotX + plotW * 0.3 + 6}" y="${ry + barH - 3}">${esc(s.name)}: ${esc(s.text)}</text>`);
        } else {
          const x1 = clampX(s.value);
          parts.push(`<rect class="${s.cls}" x="${plotX}" y="${ry}" width="${Math.max(1, x1 - plotX).toFixed(1)}" height="${barH}" rx="2"/>`);
          let textX = x1 + 6;
          if (s.target != null) {
            const tx = clampX(s.target);
            parts.push(`<line class="target" x1="${tx.toFixed(1)}" y1="${ry - 2}" x2="${tx.toFixed(1)}" y2="${ry + barH + 2}"/>`);
            textX = Math.max(textX, tx + 6);
          }
          const status = s.met == null ? '' : s.met ? ' ✓' : ' ✗';
          parts.push(`<text class="value" x="${textX.toFixed(1)}" y="${ry + barH - 3}">${esc(s.name)} ${esc(s.text)}${status}</text>`);
        }
        ry += rowH;
      }
      ry += 8;
    }
    y = top + height + 18;
  };

  // Panel 1: native ratios.
  const nativeRows = ['cube-1e6', 'ball-1e6', 'sphere-1e6', 'cube-1e5', 'ball-1e5', 'sphere-1e5']
    .filter((input) => nativeInputs.includes(input))
    .map((input) => {
      const hk = get('native', 'hullkit-quickhull', input);
      const series = [
        ['qhull', 'vs Qhull', 'qhull', input === 'cube-1e6' ? 0.25 : input === 'sphere-1e6' ? 0.15 : null],
        ['cgal', 'vs CGAL', 'cgal', input.endsWith('1e6') && input !== 'ball-1e6' ? 0.1 : null],
      ].map(([impl, name, cls, limit]) => {
        const r = ratio(timeOf(hk), timeOf(get('native', impl, input)));
        return {
          name,
          cls,
          value: r,
          text: r == null ? (hk?.error ? 'hullkit quickhull not measured (unknown algorithm)' : 'not measured') : fmtRatio(r),
          target: limit,
          met: r == null || limit == null ? null : r <= limit,
        };
      });
      return { label: input, series };
    });
  panel(
    'Native: hullkit quickhull time ÷ peer time',
    'lower is better; the small upright marks are the targets (1e6: cube ≤ 0.25× Qhull, sphere ≤ 0.15× Qhull, both ≤ 0.1× CGAL)',
    nativeRows,
    { min: 0.01, max: 10, ticks: [0.01, 0.1, 1, 10], parity: 1 },
    [],
  );

  // Panel 2: wasm speed-ups.
  const wasmRows = ['cube-1e6', 'sphere-1e6', 'cube-1e5', 'sphere-1e5']
    .filter((input) => jsInputs.includes(input))
    .map((input) => {
      const hk = get('js', 'hullkit-quickhull', input);
      const series = [
        ['quickhull3d', 'vs quickhull3d', 'qh3d'],
        ['three', 'vs three.js', 'three'],
      ].map(([impl, name, cls]) => {
        const s = speedup(hk, get('js', impl, input));
        return {
          name,
          cls,
          value: s?.value ?? null,
          text: s == null ? (hk?.error ? 'hullkit wasm quickhull not measured (unknown algorithm)' : 'not measured') : fmtSpeedupCell(s),
          met: s == null ? null : s.value >= 10,
        };
      });
      return { label: input, series };
    });
  panel(
    'WebAssembly in Node: speed-up of hullkit over peer',
    'higher is better (peer time ÷ hullkit time; peers\' input conversion included); target ≥ 10×',
    wasmRows,
    { min: 0.1, max: 1000, ticks: [0.1, 1, 10, 100, 1000], parity: 1 },
    [{ value: 10, label: 'target 10×' }],
  );

  // Panel 3: gift wrapping series, on a linear scale from 0.
  const seriesMax = Math.max(3, Math.ceil(seriesRatio ?? 0));
  const seriesRows = series.map((s) => ({
    label: `giftwrap n = ${fmtN(s.n)}`,
    series: [
      {
        name: '',
        cls: 'giftwrap',
        value: s.perNH == null ? null : s.perNH / minPerNH,
        text: s.perNH == null ? 'not measured' : `${(s.perNH * 1e9).toFixed(2)} ns = ${(s.perNH / minPerNH).toFixed(2)}× min`,
      },
    ],
  }));
  panel(
    'Gift wrapping: time / (n·h), relative to the smallest',
    `flat means O(n·h); target: max/min ≤ 2${seriesRatio == null ? '' : ` (measured ${seriesRatio.toFixed(2)})`}`,
    seriesRows,
    { linear: true, min: 0, max: seriesMax, ticks: Array.from({ length: seriesMax + 1 }, (_, k) => k) },
    [{ value: 2, label: 'target 2×' }],
  );

  const H = y + 10;
  const style = `
    .card { fill: #ffffff; stroke: #d0d7de; }
    text { font-family: system-ui, -apple-system, "Segoe UI", Helvetica, Arial, sans-serif; fill: #1f2328; }
    .title { font-size: 15px; font-weight: 600; }
    .sub, .tick { font-size: 11px; fill: #57606a; }
    .label, .value { font-size: 12px; }
    .targetlabel { font-size: 11px; fill: #cf222e; }
    .value, .label, .targetlabel { paint-order: stroke; stroke: #ffffff; stroke-width: 4px; stroke-linejoin: round; }
    .grid { stroke: #d0d7de; stroke-width: 1; }
    .parity { stroke: #8c959f; stroke-width: 1.5; }
    .target { stroke: #cf222e; stroke-width: 2; }
    .qhull { fill: #4e79a7; } .cgal { fill: #e8833a; }
    .qh3d { fill: #59a14f; } .three { fill: #9c6ade; } .giftwrap { fill: #2a9d8f; }
    .missing { fill: none; stroke: #8c959f; stroke-dasharray: 4 3; }
    @media (prefers-color-scheme: dark) {
      .card { fill: #0d1117; stroke: #30363d; }
      text { fill: #e6edf3; }
      .sub, .tick { fill: #9198a1; }
      .value, .label, .targetlabel { stroke: #0d1117; }
      .grid { stroke: #30363d; }
      .parity { stroke: #6e7681; }
      .target { stroke: #ff7b72; } .targetlabel { fill: #ff7b72; }
      .missing { stroke: #6e7681; }
    }`;
  return [
    `<svg xmlns="http://www.w3.org/2000/svg" width="${W}" height="${H}" viewBox="0 0 ${W} ${H}" role="img" aria-label="hullkit benchmark ratios">`,
    `<style>${style}\n</style>`,
    `<rect class="card" x="0.5" y="0.5" width="${W - 1}" height="${H - 1}" rx="8"/>`,
    ...parts,
    '</svg>',
    '',
  ].join('\n');
}
writeFileSync(join(reportDir, 'results.svg'), svgChart());

// ------------------------------------------------------------------------------- stdout
const lines = [];
lines.push(`hullkit bench summary${info.quick ? ' (QUICK smoke run: not the real numbers)' : ''}:`);
const width = Math.max(...targets.map((t) => t.name.length));
for (const t of targets) {
  lines.push(`  ${statusOf(t).padEnd(12)} ${t.name.padEnd(width)}  ${t.text ?? `(${t.why})`}`);
}
const met = targets.filter((t) => t.met === true).length;
const notMet = targets.filter((t) => t.met === false).length;
const unmeasured = targets.filter((t) => t.met == null).length;
lines.push(`  ${met} met, ${notMet} not met, ${unmeasured} not measured of ${targets.length} targets`);
lines.push(`  report: ${join(reportDir, 'results.md')}, ${join(reportDir, 'results.svg')}; raw: bench/out/results.json`);
console.log(lines.join('\n'));
