// Writes the benchmark inputs to bench/out/ (gitignored) as raw little-endian float64 files,
// x0 y0 z0 x1 y1 z1 ... with no header (point count = size / 24), plus bench/out/inputs.json
// describing them. Every input is generated from its own fixed seed, so the files are the same on
// every machine and run; a file that already exists with the right size is left alone.
//
//   node bench/make_inputs.mjs [--out DIR]
//
// Inputs:
//   cube-1e5, cube-1e6      uniform in the cube [-1, 1]^3
//   ball-1e5, ball-1e6      uniform in the unit ball (rejection sampling from the cube)
//   sphere-1e5, sphere-1e6  uniform on the unit sphere (Box-Muller normals, normalised): every
//                           point is a hull vertex up to rounding
//   bunny                   the vertices of the Stanford bunny from the npm package `bunny`
//   ball-1e3 ... ball-3e4   the gift wrapping scaling series (n = 1e3, 3e3, 1e4, 3e4; ball-1e5 above
//                           is its last member)
// The cube and sphere inputs are also written as text, NAME.txt, in qhull's rbox format ("3 rbox
// ...", the count, then "x y z" lines, each number JavaScript's shortest text that reads back to
// the same double), for the command-line rows (hullkit hull FILE vs qconvex o < FILE).
import { closeSync, existsSync, mkdirSync, openSync, readFileSync, statSync, writeFileSync, writeSync, renameSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const require = createRequire(import.meta.url);

const outArg = process.argv.indexOf('--out');
const outDir = outArg > 0 ? process.argv[outArg + 1] : join(here, 'out');

// mulberry32: a small 32-bit PRNG; two draws make one double with 53 random bits in [0, 1).
function mulberry32(seed) {
  let a = seed >>> 0;
  return function next32() {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return (t ^ (t >>> 14)) >>> 0;
  };
}

function uniform01(next32) {
  const high = next32() >>> 5; // 27 bits
  const low = next32() >>> 6; // 26 bits
  return (high * 67108864 + low) / 9007199254740992; // / 2^53
}

// A seed per input name (FNV-1a of the name), so one input never depends on another.
function seedOf(name) {
  let h = 0x811c9dc5;
  for (let i = 0; i < name.length; i++) {
    h ^= name.charCodeAt(i);
    h = Math.imul(h, 0x01000193) >>> 0;
  }
  return h;
}

function cube(n, rand) {
  const xyz = new Float64Array(3 * n);
  for (let i = 0; i < 3 * n; i++) xyz[i] = 2 * uniform01(rand) - 1;
  return xyz;
}

function ball(n, rand) {
  const xyz = new Float64Array(3 * n);
  for (let i = 0; i < n; ) {
    const x = 2 * uniform01(rand) - 1;
    const y = 2 * uniform01(rand) - 1;
    const z = 2 * uniform01(rand) - 1;
    if (x * x + y * y + z * z > 1) continue;
    xyz[3 * i] = x;
    xyz[3 * i + 1] = y;
    xyz[3 * i + 2] = z;
    i++;
  }
  return xyz;
}

function sphere(n, rand) {
  const xyz = new Float64Array(3 * n);
  const gaussian = () => {
    // Box-Muller; 1 - u keeps the logarithm's argument in (0, 1].
    const u = 1 - uniform01(rand);
    const v = uniform01(rand);
    return Math.sqrt(-2 * Math.log(u)) * Math.cos(2 * Math.PI * v);
  };
  for (let i = 0; i < n; ) {
    const x = gaussian();
    const y = gaussian();
    const z = gaussian();
    const r = Math.sqrt(x * x + y * y + z * z);
    if (!(r > 1e-12)) continue;
    xyz[3 * i] = x / r;
    xyz[3 * i + 1] = y / r;
    xyz[3 * i + 2] = z / r;
    i++;
  }
  return xyz;
}

function bunny() {
  const { positions } = require('bunny');
  const xyz = new Float64Array(3 * positions.length);
  positions.forEach((p, i) => xyz.set(p, 3 * i));
  return xyz;
}

const bunnyCount = require('bunny').positions.length;

const inputs = [
  ...[1e5, 1e6].flatMap((n) => [
    { kind: 'cube', n, make: cube },
    { kind: 'ball', n, make: ball },
    { kind: 'sphere', n, make: sphere },
  ]),
  { kind: 'bunny', name: 'bunny', n: bunnyCount, make: bunny },
  ...[1e3, 3e3, 1e4, 3e4].map((n) => ({ kind: 'ball', n, make: ball, series: 'giftwrap' })),
];

const sizeName = (n) => {
  const e = Math.floor(Math.log10(n));
  const m = n / 10 ** e;
  return Number.isInteger(m) && e >= 3 ? `${m}e${e}` : String(n);
};

function toLittleEndianBytes(xyz) {
  const bytes = new Uint8Array(xyz.byteLength);
  const view = new DataView(bytes.buffer);
  for (let i = 0; i < xyz.length; i++) view.setFloat64(8 * i, xyz[i], true);
  return bytes;
}

mkdirSync(outDir, { recursive: true });
const manifest = [];
for (const input of inputs) {
  const name = input.name ?? `${input.kind}-${sizeName(input.n)}`;
  const file = join(outDir, `${name}.bin`);
  const seed = input.kind === 'bunny' ? null : seedOf(name);
  const bytes = 24 * input.n;
  manifest.push({ name, kind: input.kind, n: input.n, seed, file: `${name}.bin` });
  if (existsSync(file) && statSync(file).size === bytes) continue;
  const started = performance.now();
  const xyz = input.make(input.n, seed === null ? null : mulberry32(seed));
  const temporary = `${file}.tmp`;
  writeFileSync(temporary, toLittleEndianBytes(xyz));
  renameSync(temporary, file);
  console.error(`make_inputs: wrote ${file} (${input.n} points, ${((performance.now() - started) / 1000).toFixed(1)} s)`);
}
// Text copies for the command-line rows, from the binary files (so the points are the same).
// A text file is rewritten only when missing or older than its binary.
function writeRboxText(binFile, textFile, name) {
  const bytes = readFileSync(binFile);
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const n = bytes.byteLength / 24;
  const temporary = `${textFile}.tmp`;
  const fd = openSync(temporary, 'w');
  let chunk = `3 rbox-style ${name} (hullkit bench/make_inputs.mjs)\n${n}\n`;
  for (let i = 0; i < n; i++) {
    chunk += `${view.getFloat64(24 * i, true)} ${view.getFloat64(24 * i + 8, true)} ${view.getFloat64(24 * i + 16, true)}\n`;
    if (chunk.length > 1 << 20) {
      writeSync(fd, chunk);
      chunk = '';
    }
  }
  writeSync(fd, chunk);
  closeSync(fd);
  renameSync(temporary, textFile);
}
for (const entry of manifest) {
  if (entry.kind !== 'cube' && entry.kind !== 'sphere') continue;
  const binFile = join(outDir, entry.file);
  const textFile = join(outDir, `${entry.name}.txt`);
  entry.text = `${entry.name}.txt`;
  if (existsSync(textFile) && statSync(textFile).mtimeMs >= statSync(binFile).mtimeMs) continue;
  writeRboxText(binFile, textFile, entry.name);
  console.error(`make_inputs: wrote ${textFile}`);
}
writeFileSync(join(outDir, 'inputs.json'), JSON.stringify(manifest, null, 2) + '\n');
