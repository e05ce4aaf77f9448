// Writes the Delaunay benchmark inputs to bench/out/delaunay/ (gitignored with bench/out): each as
// raw little-endian float64 x0 y0 x1 y1 ... (NAME.bin, point count = size / 16) for hullkit, CGAL
// and the JS runs, and as qhull text (NAME.txt: "2", the count, "x y" lines with 17 significant
// digits, so qdelaunay reads exactly the same doubles). Every input comes from its own fixed seed
// (the page's mulberry32); a file that already exists with the right size is left alone.
//
//   node bench/delaunay_inputs.mjs [--quick] [--out DIR]
//
// Inputs (n = 1e5 and 1e6; with --quick n = 1e4 only):
//   uniform-N    uniform in the square [-1, 1]^2
//   gaussian-N   standard normal in x and y (Box-Muller)
//   grid-N       the integer grid k x k with k = round(sqrt(N)): cocircular everywhere
//   circle-N     (1e5, or 1e4 quick) uniform angles on the unit circle: every point on the hull up
//                to rounding, the case where delaunator degrades
import { existsSync, mkdirSync, statSync, writeFileSync, renameSync, createWriteStream } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { once } from 'node:events';

import { mulberry32 } from '../web/distributions.js';

const here = dirname(fileURLToPath(import.meta.url));
const args = process.argv.slice(2);
const quick = args.includes('--quick');
const outArg = args.indexOf('--out');
const outDir = outArg >= 0 ? args[outArg + 1] : join(here, 'out', 'delaunay');

/** Uniform doubles in [0, 1) with 53 random bits from two 32-bit draws. */
function uniform53(rand) {
  const high = Math.floor(rand() * 2 ** 27);
  const low = Math.floor(rand() * 2 ** 26);
  return (high * 2 ** 26 + low) / 2 ** 53;
}

const makers = {
  uniform(n, rand) {
    return Float64Array.from({ length: 2 * n }, () => 2 * uniform53(rand) - 1);
  },
  gaussian(n, rand) {
    const xy = new Float64Array(2 * n);
    for (let i = 0; i < 2 * n; i += 2) {
      const r = Math.sqrt(-2 * Math.log(1 - uniform53(rand)));
      const a = 2 * Math.PI * uniform53(rand);
      xy[i] = r * Math.cos(a);
      xy[i + 1] = r * Math.sin(a);
    }
    return xy;
  },
  grid(n) {
    const k = Math.round(Math.sqrt(n));
    const xy = new Float64Array(2 * k * k);
    for (let i = 0; i < k; i++) for (let j = 0; j < k; j++) xy.set([j, i], 2 * (i * k + j));
    return xy;
  },
  circle(n, rand) {
    const xy = new Float64Array(2 * n);
    for (let i = 0; i < n; i++) {
      const a = 2 * Math.PI * uniform53(rand);
      xy[2 * i] = Math.cos(a);
      xy[2 * i + 1] = Math.sin(a);
    }
    return xy;
  },
};

const sizeName = (n) => `${n / 10 ** Math.floor(Math.log10(n))}e${Math.floor(Math.log10(n))}`;

const inputs = quick
  ? ['uniform', 'gaussian', 'grid', 'circle'].map((kind) => ({ kind, n: 1e4 }))
  : [
      ...[1e5, 1e6].flatMap((n) => ['uniform', 'gaussian', 'grid'].map((kind) => ({ kind, n }))),
      { kind: 'circle', n: 1e5 },
    ];

async function writeQhullText(file, xy) {
  const temporary = `${file}.tmp`;
  const stream = createWriteStream(temporary);
  stream.write(`2\n${xy.length / 2}\n`);
  let chunk = '';
  for (let i = 0; i < xy.length; i += 2) {
    // toPrecision(17) reads back to the same double, like hullkit's own writers.
    chunk += `${xy[i].toPrecision(17)} ${xy[i + 1].toPrecision(17)}\n`;
    if (chunk.length > 1 << 16) {
      if (!stream.write(chunk)) await once(stream, 'drain');
      chunk = '';
    }
  }
  stream.end(chunk);
  await once(stream, 'finish');
  renameSync(temporary, file);
}

mkdirSync(outDir, { recursive: true });
const manifest = [];
for (const { kind, n } of inputs) {
  const name = `${kind}-${sizeName(n)}`;
  const bin = join(outDir, `${name}.bin`);
  const text = join(outDir, `${name}.txt`);
  // A fixed seed per input, so that one input never depends on another.
  const seed = 1000003 * (Object.keys(makers).indexOf(kind) + 1) + n;
  const xy = makers[kind](n, mulberry32(seed));
  manifest.push({ name, kind, n: xy.length / 2 });
  if (!(existsSync(bin) && statSync(bin).size === 8 * xy.length)) {
    const bytes = new Uint8Array(xy.byteLength);
    const view = new DataView(bytes.buffer);
    for (let i = 0; i < xy.length; i++) view.setFloat64(8 * i, xy[i], true);
    writeFileSync(`${bin}.tmp`, bytes);
    renameSync(`${bin}.tmp`, bin);
    console.error(`delaunay_inputs: wrote ${bin} (${xy.length / 2} points)`);
  }
  if (!existsSync(text) || statSync(text).mtimeMs < statSync(bin).mtimeMs) await writeQhullText(text, xy);
}
writeFileSync(join(outDir, 'inputs.json'), JSON.stringify(manifest, null, 2) + '\n');
