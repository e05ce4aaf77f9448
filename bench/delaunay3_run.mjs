// Runs every implementation x input of the 3D Delaunay benchmark, one process at a time (never two
// at once: the machine has 2 cores), and appends one JSON line per row to RESULTS.jsonl (the first
// line: the machine and versions). bench/delaunay3_run.sh builds, writes the inputs and calls this;
// see it and bench/README.md for what each row is.
//
//   node bench/delaunay3_run.mjs --native DIR --python PYTHON --quick 0|1 RESULTS.jsonl
//
// DIR holds hullkit_delaunay3_bench and the hullkit command; PYTHON the interpreter whose hullkit
// package is timed (without hullkit.delaunay3 its rows say why in "pending"). Environment:
//   HULLKIT_BENCH_QDELAUNAY_TIMEOUT  seconds before a qdelaunay run is stopped (default 300)
//   HULLKIT_BENCH_SCIPY_TIMEOUT      the same for a scipy process (default 900: the 1e6 grid takes long)
import { execFileSync, spawnSync } from 'node:child_process';
import { appendFileSync, closeSync, existsSync, openSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import { dirname, join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';

import { median } from './delaunay3_common.mjs';

const here = dirname(fileURLToPath(import.meta.url));
const root = join(here, '..');
const { values, positionals } = parseArgs({
  allowPositionals: true,
  options: { native: { type: 'string' }, python: { type: 'string' }, quick: { type: 'string', default: '0' } },
});
const quick = values.quick === '1';
const results = positionals[0];
const out = join(here, 'out', 'delaunay3');
const bench = join(values.native, 'hullkit_delaunay3_bench');
const hullkitCommand = join(values.native, 'hullkit');
const qdelaunayTimeout = Number(process.env.HULLKIT_BENCH_QDELAUNAY_TIMEOUT ?? 300);
const scipyTimeout = Number(process.env.HULLKIT_BENCH_SCIPY_TIMEOUT ?? 900);
const inputs = JSON.parse(readFileSync(join(out, 'inputs.json'), 'utf8'));

// ---- runs per row: quick mode 3 everywhere; full runs fewer the larger the input. qdelaunay and
// scipy are slow (10-30 s at 1e5, minutes at 1e6): one call from 5e4 points up, each a first call.
const runsFor = (n, what) => {
  if (what === 'slow' && n >= 5e4) return 1;
  if (quick) return 3;
  if (what === 'command') return n >= 1e6 ? 3 : n >= 1e5 ? 5 : 7;
  return n >= 1e6 ? 5 : n >= 1e5 ? 7 : 11;
};

/** Fresh processes timed per implementation for the headline of the native library calls and of the
 * Python calls on the target's input (see below); 1 in quick mode unless set. */
const FRESH_ROUNDS = process.env.HULLKIT_BENCH_FRESH_ROUNDS ? Number(process.env.HULLKIT_BENCH_FRESH_ROUNDS) : quick ? 1 : 3;
/** A row timed in fresh processes: its headline becomes the median of their first calls. */
const withMedianFirst = (row) => (row.first_each?.length > 1 ? { ...row, first: median(row.first_each) } : row);
const say = (text) => console.error(`delaunay3 bench: ${text}`);
const fileOf = (input, ext) => join(out, `${input.name}.${ext}`);

/** Appends a result line, tagged with its kind, and prints a progress line. */
function record(kind, line) {
  const r = { kind, ...line };
  appendFileSync(results, JSON.stringify(r) + '\n');
  const f = (s) => (s == null ? '-' : `${s.toPrecision(3)} s`);
  say(`${kind} ${r.impl} ${r.input}: ` + (r.error ? `error: ${r.error}` : r.pending ? `pending: ${r.pending}` : r.skipped ? `not run: ${r.skipped}` :
    `first ${f(r.first)}, warm ${f(r.warm)}, ${r.tetrahedra ?? '?'} tetrahedra${r.flat ? ` (${r.flat} flat)` : ''}, ` +
    `${r.peak_rss_mb?.toFixed(0)} MB`));
  return r;
}

/** Runs a program that prints one JSON line (stopped after `timeout` s); its line, or one with "error". */
function jsonLine(impl, input, command, args, timeout = 1800) {
  const run = spawnSync('timeout', [String(timeout), command, ...args], { cwd: join(root, 'build'), encoding: 'utf8', maxBuffer: 1 << 26 });
  const line = (run.stdout ?? '').split('\n').filter((l) => l.startsWith('{')).pop();
  if (line) return JSON.parse(line);
  if (run.status === 124) return { impl, input: input.name, error: `timed out after ${timeout} s`, timed_out: timeout };
  return { impl, input: input.name, error: `exit status ${run.status ?? run.signal}: ${(run.stderr ?? '').slice(-300).replace(/\s+/g, ' ')}` };
}

/** The counter's fields for tetrahedra another program wrote (tetrahedra, flat, fingerprint), the file removed. */
function count(input, file, format) {
  if (!existsSync(file)) return { error: `${relative(root, file)} was not written` };
  const line = jsonLine('count', input, bench, ['--count', file, '--format', format, '--input', fileOf(input, 'bin')]);
  rmSync(file, { force: true });
  const { tetrahedra, flat, flat_method, fingerprint, error } = line;
  return error ? { count_error: error } : { tetrahedra, flat, flat_method, fingerprint };
}

/**
 * Times a whole command `runs` times, each a fresh process, under /usr/bin/time (peak memory) and
 * `timeout`: wall seconds from spawn to exit. stdin/stdout: files or null. Stops at the first failure.
 */
function timeCommand(argv, { runs, stdin = null, stdout = null, timeout = 1800, beforeEach = () => {}, afterEach = () => {} }) {
  const seconds = [];
  let peak = 0;
  const timeFile = join(out, 'command.time');
  for (let k = 0; k < runs; k++) {
    const input = stdin ? openSync(stdin, 'r') : 'ignore';
    const output = stdout ? openSync(stdout, 'w') : 'ignore';
    beforeEach();
    const start = performance.now();
    const run = spawnSync('/usr/bin/time', ['-f', '%M', '-o', timeFile, 'timeout', String(timeout), ...argv],
      { stdio: [input, output, 'pipe'], encoding: 'utf8', maxBuffer: 1 << 26 });
    const wall = (performance.now() - start) / 1000;
    for (const fd of [input, output]) if (typeof fd === 'number') closeSync(fd);
    if (run.status !== 0) {
      const why = run.status === 124 ? `timed out after ${timeout} s` : `exit status ${run.status ?? run.signal}: ${run.stderr.slice(-300).replace(/\s+/g, ' ')}`;
      return { seconds, error: why, timed_out: run.status === 124 ? timeout : undefined };
    }
    peak = Math.max(peak, Number(readFileSync(timeFile, 'utf8').trim().split('\n').pop()) / 1024);
    seconds.push(wall);
    afterEach(run);
  }
  rmSync(timeFile, { force: true });
  // Every run is a fresh process, so each is a first call: the headline is their median.
  return { first: median(seconds), runs: seconds, warm: null, fresh_each: true, peak_rss_mb: peak };
}

/** Whether the hullkit command reads TetGen's .node (then the command rows give it the same file as TetGen). */
function hullkitReadsNode() {
  const node = join(out, 'probe.node');
  writeFileSync(node, '5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 2\n');
  const run = spawnSync(hullkitCommand, ['delaunay3', node, '-o', join(out, 'probe-out.json')], { encoding: 'utf8' });
  let ok = false;
  try {
    ok = run.status === 0 && JSON.parse(readFileSync(join(out, 'probe-out.json'), 'utf8')).tetrahedra.length === 2;
  } catch {}
  for (const f of ['probe.node', 'probe-out.json']) rmSync(join(out, f), { force: true });
  return ok;
}

/** The first line a command prints ('unknown' if it fails). */
function firstLine(command, ...args) {
  try {
    return execFileSync(command, args, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] }).trim().split('\n')[0];
  } catch {
    return 'unknown';
  }
}
const debianVersion = (name) => firstLine('dpkg-query', '-W', '-f', '${Version}', name);

// ---- the machine and versions
const readsNode = hullkitReadsNode();
writeFileSync(results, JSON.stringify({
  kind: 'meta',
  quick,
  date: new Date().toISOString(),
  commit: firstLine('git', '-C', root, 'rev-parse', '--short', 'HEAD'),
  // Files of the library and its bindings changed since that commit (the binaries were built with them).
  uncommitted: execFileSync('git', ['-C', root, 'status', '--porcelain', '--', 'native', 'python', 'wasm'], { encoding: 'utf8' })
    .split('\n').filter(Boolean).length,
  cpu: os.cpus()[0]?.model ?? 'unknown CPU',
  cores: os.cpus().length,
  memory_gb: os.totalmem() / 2 ** 30,
  load_average: os.loadavg(),
  node: process.version,
  cgal: debianVersion('libcgal-dev'),
  tetgen: debianVersion('tetgen'),
  qhull: debianVersion('qhull-bin'),
  scipy: firstLine('/usr/bin/python3', '-c', 'import scipy; print(scipy.__version__)'),
  inputs: inputs.map(({ name, n, role }) => ({ name, n, role })),
  hullkit_reads_node: readsNode,
  qdelaunay_timeout: qdelaunayTimeout,
  scipy_timeout: scipyTimeout,
}) + '\n');

const qdelaunayTimedOut = new Map();  // point count -> the input it timed out on
// Not run on points on a sphere (all cospherical up to rounding): scipy had not finished 1e5 of them
// after 16 minutes (5 Dec 2026), and qdelaunay is the same Qhull.
const SLOW_PEERS_SKIPPED = 'Qhull on points on a sphere: scipy had not finished 1e5 of them after 16 min (one-off, 5 Dec 2026)';
for (const input of inputs) {
  const bin = fileOf(input, 'bin');
  const memoryOnly = input.role === 'memory';
  const runs = memoryOnly ? 1 : runsFor(input.n);
  // -- native: the library call alone (first call in a fresh process, warm median beside it).
  // The first call is a single sample a process, and this machine's speed drifts by a third within
  // minutes: so each implementation's first call is timed in FRESH_ROUNDS fresh processes, taken in
  // turns (hullkit 1 thread, 2 threads, CGAL, then again), and the headline is their median. The
  // first round's process also times the warm calls and examines the output (flat count,
  // fingerprint); the later ones only time their first call.
  const nativeArgs = ['--input', bin, '--runs', String(runs), '--budget', '40', ...(memoryOnly ? ['--no-examine'] : [])];
  const natives = [['hullkit-t1', ['--impl', 'hullkit', '--threads', '1']], ['hullkit-t2', ['--impl', 'hullkit', '--threads', '2']], ['cgal', ['--impl', 'cgal']]];
  const rounds = memoryOnly ? 1 : FRESH_ROUNDS;
  const nativeRows = new Map();
  for (let round = 0; round < rounds; round++) {
    for (const [impl, extra] of natives) {
      const args = round === 0 ? [...extra, ...nativeArgs] : [...extra, '--input', bin, '--runs', '1', '--no-examine'];
      const line = jsonLine(impl, input, bench, args);
      if (round === 0) nativeRows.set(impl, { ...line, impl, first_each: [] });
      const row = nativeRows.get(impl);
      if (!row.error && !line.error) row.first_each.push(line.first);
    }
  }
  for (const row of nativeRows.values()) record('native', withMedianFirst(row));
  if (memoryOnly) continue;

  // -- whole commands, text in: hullkit (.ele and .node out) vs TetGen (-NEFQ: nothing written;
  // -NFQ: the .ele written, one run, counted) vs qdelaunay (indices out)
  const eleOut = join(out, `cmd-${input.name}.ele`);
  const stats = [];
  const hullkitRow = timeCommand([hullkitCommand, 'delaunay3', fileOf(input, readsNode ? 'node' : 'xyz'), '-o', eleOut, '--stats', '--quiet'], {
    runs: runsFor(input.n, 'command'),
    // every run writes new files, as the first does: replacing the last run's 240 MB .ele made the
    // file system free it inside the timed command (0.1-0.2 s at 1e6 points)
    beforeEach: () => { for (const f of [eleOut, eleOut.replace(/\.ele$/, '.node')]) rmSync(f, { force: true }); },
    afterEach: (run) => stats.push(JSON.parse(run.stderr.split('\n').filter((l) => l.startsWith('{')).pop() ?? '{}').seconds ?? null),
  });
  record('command', { impl: 'hullkit-command', input: input.name, n: input.n, ...hullkitRow, core_seconds: median(stats.filter((s) => s != null)),
    input_file: readsNode ? 'node' : 'xyz', ...count(input, eleOut, 'ele') });
  rmSync(eleOut.replace(/\.ele$/, '.node'), { force: true });

  record('command', { impl: 'tetgen-NEFQ', input: input.name, n: input.n, ...timeCommand(['tetgen', '-NEFQ', fileOf(input, 'node')], { runs: runsFor(input.n, 'command') }) });
  const tetgenEle = fileOf(input, '1.ele');
  record('command', { impl: 'tetgen-NFQ', input: input.name, n: input.n, ...timeCommand(['tetgen', '-NFQ', fileOf(input, 'node')], { runs: 1 }), ...count(input, tetgenEle, 'ele') });

  // qdelaunay is not run again at a size where it has timed out once (minutes each at 1e6).
  const qhullOut = join(out, `qdelaunay-${input.name}.out`);
  const timedOut = qdelaunayTimedOut.get(input.n);
  if (input.kind === 'sphere') {
    record('command', { impl: 'qdelaunay', input: input.name, n: input.n, skipped: SLOW_PEERS_SKIPPED });
  } else if (timedOut) {
    record('command', { impl: 'qdelaunay', input: input.name, n: input.n, skipped: `timed out after ${qdelaunayTimeout} s on ${timedOut}` });
  } else {
    const qdelaunay = timeCommand(['qdelaunay', 'Qt', 'i'], { runs: runsFor(input.n, 'slow'), stdin: fileOf(input, 'txt'), stdout: qhullOut, timeout: qdelaunayTimeout });
    if (qdelaunay.timed_out) qdelaunayTimedOut.set(input.n, input.name);
    record('command', { impl: 'qdelaunay', input: input.name, n: input.n, ...qdelaunay, ...(qdelaunay.error ? {} : count(input, qhullOut, 'qhull')) });
  }
  rmSync(qhullOut, { force: true });

  // -- Python (first call in a fresh process): scipy through Debian's interpreter, hullkit's binding
  const tets = join(out, `tets-${input.name}.u32`);
  const pythonLine = (impl, interpreter, lib, args) =>
    jsonLine(impl, input, interpreter, [join(here, 'delaunay3_python.py'), '--lib', lib, '--input', bin, ...args], lib === 'scipy' ? scipyTimeout : undefined);
  // (recorded at once unless `recorded` is false: then the row is returned to be recorded later)
  const pythonRow = (impl, interpreter, lib, pythonRuns, extra = [], recorded = true) => {
    const line = pythonLine(impl, interpreter, lib, ['--runs', String(pythonRuns), '--budget', '45', '--tets', tets, ...extra]);
    const row = { ...line, impl, ...(line.error || line.pending ? {} : count(input, tets, 'u32')) };
    return recorded ? record('python', row) : row;
  };
  if (input.kind === 'sphere') {
    record('python', { impl: 'scipy', input: input.name, n: input.n, skipped: SLOW_PEERS_SKIPPED });
    pythonRow('hullkit-python', values.python, 'hullkit', runsFor(input.n));
  } else if (input.name !== (quick ? 'uniform-1e5' : 'uniform-1e6')) {
    pythonRow('scipy', '/usr/bin/python3', 'scipy', runsFor(input.n, 'slow'));
    pythonRow('hullkit-python', values.python, 'hullkit', runsFor(input.n));
  } else {
    // The input of the Python target: scipy and hullkit in FRESH_ROUNDS fresh processes each,
    // taking turns, the headlines their medians (as the native calls above). The first round's
    // processes also time the warm calls and write the tetrahedra that are counted.
    const rows = [pythonRow('scipy', '/usr/bin/python3', 'scipy', runsFor(input.n, 'slow'), [], false),
      pythonRow('hullkit-python', values.python, 'hullkit', runsFor(input.n), [], false)];
    for (const row of rows) row.first_each = row.error || row.pending ? [] : [row.first];
    for (let round = 1; round < FRESH_ROUNDS; round++) {
      for (const [row, interpreter, lib] of [[rows[0], '/usr/bin/python3', 'scipy'], [rows[1], values.python, 'hullkit']]) {
        if (row.error || row.pending) continue;
        const line = pythonLine(row.impl, interpreter, lib, ['--runs', '1']);
        if (!line.error) row.first_each.push(line.first);
      }
    }
    for (const row of rows) record('python', withMedianFirst(row));
  }
  // Furthest-site (Delaunay(points, furthest_site=True)) on the uniform and sphere inputs: Qhull's
  // upper hull finishes on the sphere where its lower hull does not (3.7 s at 1e5 points, one-off).
  if (input.kind === 'uniform' || input.kind === 'sphere') {
    pythonRow('scipy-furthest', '/usr/bin/python3', 'scipy', runsFor(input.n, 'slow'), ['--furthest']);
    pythonRow('hullkit-python-furthest', values.python, 'hullkit', runsFor(input.n), ['--furthest']);
  }

  // -- wasm in Node: the public delaunay3() of wasm/hullkit.js
  const wasm = jsonLine('hullkit-wasm', input, process.execPath, ['--expose-gc', join(here, 'delaunay3_wasm_bench.mjs'), '--input', bin, '--runs', String(runsFor(input.n)), '--tets', tets]);
  record('wasm', { ...wasm, ...(wasm.error || wasm.pending ? {} : count(input, tets, 'u32')) });
  rmSync(tets, { force: true });
}
