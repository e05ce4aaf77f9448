// Writes the 3D Delaunay benchmark inputs to bench/out/delaunay3/ (gitignored with bench/out), each
// from its own fixed seed (so they are the same on every machine), and bench/out/delaunay3/inputs.json
// listing them. A file that already exists (a binary of the right size, a text copy no older than its
// binary) is kept.
//
//   node bench/delaunay3_inputs.mjs [--quick] [--out DIR]
//
// Files per input:
//   NAME.bin   raw little-endian float64 x0 y0 z0 x1 ... (point count = size / 24): the harnesses
//              (hullkit, CGAL, scipy, wasm) read it;
//   NAME.xyz   "x y z" lines: the hullkit command's input;
//   NAME.node  TetGen's: "N 3 0 0", then "i x y z" lines numbered from 1;
//   NAME.txt   qhull's: "3", N, then "x y z" lines (qdelaunay's standard input).
// Every number in the text copies is JavaScript's shortest text that reads back to the same double,
// so all programs see exactly the points of NAME.bin. The memory input (the last one) has no text
// copies: only hullkit and CGAL run on it.
//
// Inputs (full run; --quick: the 1e5 versions, grid-1e3, and uniform-1e6 for the memory test):
//   uniform-N    uniform in the cube [-1, 1]^3 (the page's generator: web/distributions.js "cube")
//   gaussian-N   100 Gaussian clusters (sigma 0.02) around centres uniform in [-1, 1]^3, each point
//                in a cluster drawn at random
//   grid-N       the integer grid {0, ..., k-1}^3 with k = round(cbrt(N)) (100^3 = 1e6, 46^3 for 1e5,
//                10^3): cospherical everywhere, the case where flat tetrahedra can appear
//   sphere-N     uniform on the unit sphere (the page's generator "sphere"): every five points
//                cospherical up to the rounding of their coordinates (scipy and qdelaunay are not
//                run on it: scipy had not finished 1e5 such points after 16 minutes)
//   uniform-1e7  (uniform-1e6 in quick mode) the memory test
import { createWriteStream, existsSync, mkdirSync, renameSync, statSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { Readable } from 'node:stream';
import { pipeline } from 'node:stream/promises';
import { fileURLToPath } from 'node:url';

import { generatePoints, mulberry32 } from '../web/distributions.js';

const here = dirname(fileURLToPath(import.meta.url));
const args = process.argv.slice(2);
const quick = args.includes('--quick');
const outArg = args.indexOf('--out');
const outDir = outArg >= 0 ? args[outArg + 1] : join(here, 'out', 'delaunay3');

const CLUSTERS = 100;
const SIGMA = 0.02;

function gaussianClusters(n, seed) {
  const rand = mulberry32(seed);
  const centres = generatePoints('cube', CLUSTERS, seed + 1);
  const normal = () => Math.sqrt(-2 * Math.log(1 - rand())) * Math.cos(2 * Math.PI * rand());
  const xyz = new Float64Array(3 * n);
  for (let i = 0; i < n; i++) {
    const c = Math.floor(rand() * CLUSTERS);
    for (let k = 0; k < 3; k++) xyz[3 * i + k] = centres[3 * c + k] + SIGMA * normal();
  }
  return xyz;
}

const makers = {
  uniform: (n, seed) => generatePoints('cube', n, seed),
  gaussian: gaussianClusters,
  grid: (n) => generatePoints('grid', n, 0),
  sphere: (n, seed) => generatePoints('sphere', n, seed),
};

const sizeName = (n) => `1e${Math.round(Math.log10(n))}`;
const pointCount = (kind, n) => (kind === 'grid' ? Math.round(Math.cbrt(n)) ** 3 : n);

const INPUTS = {
  full: [
    ['uniform', 1e5], ['uniform', 1e6], ['gaussian', 1e6], ['grid', 1e6], ['grid', 1e3], ['sphere', 1e6], ['uniform', 1e7, 'memory'],
  ],
  quick: [
    ['uniform', 1e5], ['gaussian', 1e5], ['grid', 1e5], ['grid', 1e3], ['sphere', 1e5], ['uniform', 1e6, 'memory'],
  ],
};

/** Writes `xyz` as text through a temporary file: `header`, then `${prefix(i)}x y z` lines. */
async function writeText(file, header, xyz, prefix) {
  function* text() {
    yield header;
    for (let start = 0; start < xyz.length / 3; start += 10000) {
      let lines = '';
      for (let i = start; i < Math.min(start + 10000, xyz.length / 3); i++) lines += `${prefix(i)}${xyz[3 * i]} ${xyz[3 * i + 1]} ${xyz[3 * i + 2]}\n`;
      yield lines;
    }
  }
  await pipeline(Readable.from(text()), createWriteStream(`${file}.tmp`));
  renameSync(`${file}.tmp`, file);
}

const fresh = (file, than) => existsSync(file) && statSync(file).mtimeMs >= statSync(than).mtimeMs;

mkdirSync(outDir, { recursive: true });
const manifest = [];
for (const [kind, size, role] of INPUTS[quick ? 'quick' : 'full']) {
  const name = `${kind}-${sizeName(size)}`;
  const n = pointCount(kind, size);
  const seed = 7919 * (Object.keys(makers).indexOf(kind) + 1) + size;
  const bin = join(outDir, `${name}.bin`);
  const texts = role === 'memory' ? [] : ['xyz', 'node', 'txt'];
  manifest.push({ name, kind, n, seed, role: role ?? 'compare', files: ['bin', ...texts].map((ext) => `${name}.${ext}`) });
  const binKept = existsSync(bin) && statSync(bin).size === 24 * n;
  if (binKept && texts.every((ext) => fresh(join(outDir, `${name}.${ext}`), bin))) continue;

  const started = performance.now();
  const xyz = makers[kind](n, seed);
  if (!binKept) {
    const bytes = new Uint8Array(xyz.byteLength);
    const view = new DataView(bytes.buffer);
    xyz.forEach((v, i) => view.setFloat64(8 * i, v, true));
    writeFileSync(`${bin}.tmp`, bytes);
    renameSync(`${bin}.tmp`, bin);
  }
  const headers = { xyz: '', node: `${n} 3 0 0\n`, txt: `3\n${n}\n` };
  for (const ext of texts) {
    const file = join(outDir, `${name}.${ext}`);
    if (!fresh(file, bin)) await writeText(file, headers[ext], xyz, ext === 'node' ? (i) => `${i + 1} ` : () => '');
  }
  console.error(`delaunay3_inputs: wrote ${name} (${n} points, ${((performance.now() - started) / 1000).toFixed(1)} s)`);
}
writeFileSync(join(outDir, 'inputs.json'), JSON.stringify(manifest, null, 2) + '\n');
