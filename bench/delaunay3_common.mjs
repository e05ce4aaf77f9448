// Helpers shared by the 3D Delaunay benchmark's scripts (bench/delaunay3_run.mjs, _wasm_bench.mjs,
// _report.mjs): run statistics, the binary formats of bench/out/delaunay3/, and Markdown tables.
import { readFileSync, writeFileSync } from 'node:fs';

/** The median of a list of numbers (null for none). */
export function median(values) {
  if (values.length === 0) return null;
  const sorted = [...values].sort((a, b) => a - b);
  const m = sorted.length;
  return m % 2 ? sorted[(m - 1) / 2] : (sorted[m / 2 - 1] + sorted[m / 2]) / 2;
}

/** A process's run times as a result line has them: the first call, all of them, the median of the rest. */
export const summarizeRuns = (runs) => ({ first: runs[0], runs, warm: median(runs.slice(1)) });

/**
 * Calls `call` up to `runs` times (at least once, no new call once the calls so far add up to
 * `budget` seconds), `between()` before every call but the first; returns the seconds of each call
 * and the last call's result.
 */
export function timeCalls(call, { runs, budget, between = () => {} }) {
  const seconds = [];
  let result;
  while (seconds.length < runs && (seconds.length === 0 || seconds.reduce((a, b) => a + b, 0) < budget)) {
    if (seconds.length > 0) between();
    result = undefined;
    const start = performance.now();
    result = call();
    seconds.push((performance.now() - start) / 1000);
  }
  return { seconds, result };
}

/** The points of a NAME.bin input (raw little-endian float64 x y z triples). */
export function readXyz(file) {
  const bytes = readFileSync(file);
  if (bytes.byteLength % 24 !== 0) throw new Error(`${file}: not a whole number of 3D points`);
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  return Float64Array.from({ length: bytes.byteLength / 8 }, (_, i) => view.getFloat64(8 * i, true));
}

/** Writes tetrahedra (flat, 4 indices each from 0) as raw little-endian uint32 for the counter. */
export function writeU32(file, indices) {
  const bytes = new Uint8Array(4 * indices.length);
  const view = new DataView(bytes.buffer);
  for (let i = 0; i < indices.length; i++) view.setUint32(4 * i, indices[i], true);
  writeFileSync(file, bytes);
}

// ---- report formatting

/** Seconds as text: milliseconds below 0.1 s, three significant digits; '–' for none. */
export const seconds = (s) => (s == null ? '–' : s < 0.1 ? `${(s * 1000).toPrecision(3)} ms` : `${s.toPrecision(3)} s`);
/** A ratio as text ('–' for none). */
export const ratioText = (value, digits = 2) => (value == null ? '–' : `${value.toFixed(digits)}×`);
/** a / b when both are positive numbers, else null. */
export const ratioOf = (a, b) => (a > 0 && b > 0 ? a / b : null);
/** Megabytes as text. */
export const megabytes = (mb) => (mb == null ? '–' : mb >= 1024 ? `${(mb / 1024).toFixed(2)} GB` : `${mb.toFixed(0)} MB`);

/** A Markdown table: `columns` as [title, 'l'|'r'], rows as arrays of cells. */
export function markdownTable(columns, rows) {
  return [
    `| ${columns.map(([title]) => title).join(' | ')} |`,
    `|${columns.map(([, align]) => (align === 'r' ? '---:' : ':---')).join('|')}|`,
    ...rows.map((cells) => `| ${cells.join(' | ')} |`),
  ];
}
