// Times one JavaScript-side convex hull implementation on one input file in Node and prints one
// JSON line, like build/bench/hullkit_bench does for the native side.
//
//   node bench/wasm_bench.mjs --impl IMPL --input FILE.bin [--runs 5] [--budget 60] [--cap 60]
//                             [--name NAME]
//
// IMPL is one of
//   hullkit-ALGO  hullkit's WebAssembly build through its public JS API (wasm/hullkit.js):
//                 hull(xyz: Float64Array, {algorithm: ALGO}). The time is the whole public call:
//                 copying the points into wasm memory, the hull, copying triangles and vertices out.
//                 An algorithm the loaded module does not list gives an "unknown algorithm" row.
//   quickhull3d   the npm package quickhull3d (2.1.0, CommonJS): qh(points) with points an array of
//                 [x, y, z] arrays; it returns triangles as index triples.
//   three         three.js's ConvexHull (three/examples/jsm/math/ConvexHull.js):
//                 new ConvexHull().setFromPoints(points) with points an array of THREE.Vector3.
// The two peers do not take a flat Float64Array, so their times include building their input
// format from it (reported separately as convert_median as well); hullkit's does not need that.
// Module loading (createHullkit, imports) and reading the file are not timed.
// The first run is the first call in a fresh Node process, right after createHullkit() (or the
// peer's import): what a page or script calling hull() once gets, before V8 has optimised
// anything for this input. It is reported as "first", beside "warm_median" (the later runs).
//
// Input file: raw little-endian float64 x0 y0 z0 x1 y1 z1 ... (see bench/make_inputs.mjs).
//
// The work runs in a child Node process (so a run can be stopped, and peak memory is that run's):
//  - runs: up to --runs timed runs, with a full garbage collection between runs (not timed);
//  - budget: no further run starts when the runs so far plus one more of the same length would
//    exceed --budget seconds (at least one run; the JSON line says how many ran);
//  - cap: a run still going after --cap seconds is killed and recorded as null with
//    "capped": true; the median then reads "> cap" unless most runs finished.
import { spawn } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { basename } from 'node:path';
import { fileURLToPath } from 'node:url';

const thisFile = fileURLToPath(import.meta.url);

function parseArgs(argv) {
  const args = { runs: 5, budget: 60, cap: 60, child: false };
  for (let i = 0; i < argv.length; i++) {
    const key = argv[i];
    const value = () => {
      if (i + 1 >= argv.length) usage(`${key} needs a value`);
      return argv[++i];
    };
    if (key === '--impl') args.impl = value();
    else if (key === '--input') args.input = value();
    else if (key === '--name') args.name = value();
    else if (key === '--runs') args.runs = Number(value());
    else if (key === '--budget') args.budget = Number(value());
    else if (key === '--cap') args.cap = Number(value());
    else if (key === '--child') args.child = true;
    else usage(`unknown argument ${key}`);
  }
  if (!args.impl || !args.input) usage('--impl and --input are required');
  if (!(args.runs >= 1)) usage('--runs must be at least 1');
  args.name ??= basename(args.input).replace(/\.bin$/, '');
  return args;
}

function usage(message) {
  console.error(`wasm_bench: ${message}`);
  console.error('usage: node bench/wasm_bench.mjs --impl hullkit-ALGO|quickhull3d|three --input FILE.bin [--runs 5] [--budget 60] [--cap 60]');
  process.exit(2);
}

function readPoints(file) {
  const bytes = readFileSync(file);
  if (bytes.byteLength % 24 !== 0) throw new Error(`${file}: ${bytes.byteLength} bytes is not a whole number of 3D points`);
  const xyz = new Float64Array(bytes.byteLength / 8);
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  for (let i = 0; i < xyz.length; i++) xyz[i] = view.getFloat64(8 * i, true);
  return xyz;
}

const median = (values) => {
  const s = [...values].sort((a, b) => a - b);
  const m = s.length;
  return m % 2 ? s[(m - 1) / 2] : (s[m / 2 - 1] + s[m / 2]) / 2;
};

// ---------------------------------------------------------------- child: does the timed work

// Each maker returns { detail, run() -> {seconds, convertSeconds, result} , count(result) -> {vertices, faces} }.
async function makeRunner(impl, xyz) {
  const n = xyz.length / 3;
  if (impl.startsWith('hullkit-')) {
    const algorithm = impl.slice('hullkit-'.length);
    const { default: createHullkit } = await import('../wasm/hullkit.js');
    const hullkit = await createHullkit();
    if (!hullkit.algorithms.includes(algorithm)) {
      return { error: `unknown algorithm "${algorithm}": the wasm module lists ${JSON.stringify(hullkit.algorithms)}` };
    }
    return {
      detail: `hullkit wasm hull(Float64Array, {algorithm: "${algorithm}"}), copies in and out included`,
      run() {
        const start = performance.now();
        const result = hullkit.hull(xyz, { algorithm });
        return { seconds: (performance.now() - start) / 1000, convertSeconds: null, result };
      },
      count: (result) => ({ vertices: result.vertices.length, faces: result.triangles.length / 3 }),
    };
  }
  if (impl === 'quickhull3d') {
    const require = createRequire(import.meta.url);
    const qh = require('quickhull3d').default;
    const version = require('quickhull3d/package.json').version;
    return {
      detail: `quickhull3d ${version} qh(Array<[x, y, z]>), conversion from Float64Array included`,
      run() {
        const start = performance.now();
        const points = new Array(n);
        for (let i = 0; i < n; i++) points[i] = [xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]];
        const converted = performance.now();
        const result = qh(points);
        const end = performance.now();
        return { seconds: (end - start) / 1000, convertSeconds: (converted - start) / 1000, result };
      },
      count(faces) {
        const used = new Set();
        for (const face of faces) for (const index of face) used.add(index);
        return { vertices: used.size, faces: faces.length };
      },
    };
  }
  if (impl === 'three') {
    const { Vector3, REVISION } = await import('three');
    const { ConvexHull } = await import('three/examples/jsm/math/ConvexHull.js');
    return {
      detail: `three.js r${REVISION} ConvexHull.setFromPoints(Array<Vector3>), conversion from Float64Array included`,
      run() {
        const start = performance.now();
        const points = new Array(n);
        for (let i = 0; i < n; i++) points[i] = new Vector3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
        const converted = performance.now();
        const result = new ConvexHull().setFromPoints(points);
        const end = performance.now();
        return { seconds: (end - start) / 1000, convertSeconds: (converted - start) / 1000, result };
      },
      count(hull) {
        const used = new Set();
        for (const face of hull.faces) {
          let edge = face.edge;
          do {
            used.add(edge.vertex);
            edge = edge.next;
          } while (edge !== face.edge);
        }
        return { vertices: used.size, faces: hull.faces.length };
      },
    };
  }
  return { error: `unknown implementation "${impl}" (known: hullkit-ALGO, quickhull3d, three)` };
}

async function child(args) {
  const send = (message) => process.stdout.write(JSON.stringify(message) + '\n');
  const xyz = readPoints(args.input);
  const n = xyz.length / 3;
  const runner = await makeRunner(args.impl, xyz);
  if (runner.error) {
    send({ type: 'error', n, error: runner.error });
    return;
  }
  send({ type: 'ready', n, detail: runner.detail });
  let total = 0;
  let last = 0;
  for (let k = 0; k < args.runs; k++) {
    if (k > 0 && total + last > args.budget) break;
    globalThis.gc?.();
    let timed;
    try {
      timed = runner.run();
    } catch (error) {
      send({ type: 'error', n, error: `${args.impl} threw: ${error?.message ?? error}` });
      return;
    }
    const counts = runner.count(timed.result);
    send({ type: 'run', seconds: timed.seconds, convertSeconds: timed.convertSeconds, ...counts });
    total += timed.seconds;
    last = timed.seconds;
  }
  send({ type: 'done', peakRssMb: process.resourceUsage().maxRSS / 1024 });
}

// ---------------------------------------------------------------- parent: supervises the child

function supervise(args) {
  return new Promise((resolve) => {
    const out = { impl: args.impl, input: args.name, file: args.input };
    const runs = [];
    const converts = [];
    let capped = false;
    let finished = false;
    let timer = null;
    const proc = spawn(
      process.execPath,
      ['--expose-gc', '--max-old-space-size=12288', thisFile, '--child', '--impl', args.impl, '--input', args.input,
        '--runs', String(args.runs), '--budget', String(args.budget)],
      { stdio: ['ignore', 'pipe', 'inherit'] },
    );
    const arm = (seconds) => {
      clearTimeout(timer);
      timer = setTimeout(() => {
        capped = true;
        proc.kill('SIGKILL');
      }, seconds * 1000);
    };
    arm(Math.max(args.cap, 120)); // loading the module and the file, generously
    let buffered = '';
    proc.stdout.setEncoding('utf8');
    proc.stdout.on('data', (chunk) => {
      buffered += chunk;
      let newline;
      while ((newline = buffered.indexOf('\n')) >= 0) {
        const line = buffered.slice(0, newline);
        buffered = buffered.slice(newline + 1);
        if (!line.trim()) continue;
        const message = JSON.parse(line);
        if (message.type === 'ready') {
          out.n = message.n;
          out.detail = message.detail;
          arm(args.cap);
        } else if (message.type === 'run') {
          runs.push(message.seconds);
          if (message.convertSeconds != null) converts.push(message.convertSeconds);
          out.vertices = message.vertices;
          out.faces = message.faces;
          arm(args.cap);
        } else if (message.type === 'error') {
          out.n = message.n;
          out.error = message.error;
        } else if (message.type === 'done') {
          out.peak_rss_mb = message.peakRssMb;
          finished = true;
        }
      }
    });
    proc.on('exit', (code, signal) => {
      clearTimeout(timer);
      if (capped) {
        out.capped = true;
        out.cap_seconds = args.cap;
        runs.push(null); // the run that was stopped
      } else if (!finished && !out.error) {
        out.error = `child exited with ${signal ?? `code ${code}`} (out of memory?)`;
      }
      if (!out.error) {
        out.runs = runs;
        out.runs_requested = args.runs;
        // A stopped run counts as longer than anything else.
        const m = median(runs.map((t) => (t === null ? Infinity : t)));
        out.median = Number.isFinite(m) ? m : null;
        const done = runs.filter((t) => t !== null);
        out.min = done.length ? Math.min(...done) : null;
        if (converts.length) out.convert_median = median(converts);
        out.first = runs[0] ?? null; // null: the first run itself was stopped at the cap
        out.first_capped = runs[0] === null;
        const warm = runs.slice(1).filter((t) => t !== null);
        out.warm_median = warm.length ? median(warm) : null;
      }
      resolve(out);
    });
  });
}

const args = parseArgs(process.argv.slice(2));
if (args.child) {
  await child(args);
} else {
  const result = await supervise(args);
  process.stdout.write(JSON.stringify(result) + '\n');
}
