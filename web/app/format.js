// Number formatting shared by the views' stats panels.

const intFmt = new Intl.NumberFormat('en-US');

/** 12,345 */
export const fmtInt = (v) => intFmt.format(v);

/** A real in a stats cell: six significant digits, or three in exponent form when large/small. */
export function fmtReal(v) {
  if (!Number.isFinite(v)) return String(v);
  if (v === 0) return '0';
  return Math.abs(v) >= 1e5 || Math.abs(v) < 1e-3 ? v.toExponential(2) : String(Number(v.toPrecision(6)));
}

/** 3.21 ms, 45.6 ms, 1.23 s */
export function fmtMs(ms) {
  if (ms < 10) return `${ms.toFixed(2)} ms`;
  if (ms < 1000) return `${ms.toFixed(1)} ms`;
  return `${(ms / 1000).toFixed(2)} s`;
}

/** A rough duration for estimates: "< 1 s", "40 s", "3 min 5 s", "1.2 h". */
export function fmtDuration(ms) {
  const s = ms / 1000;
  if (s < 1) return '< 1 s';
  if (s < 90) return `${Math.round(s)} s`;
  if (s < 3600) {
    const m = Math.floor(s / 60);
    const r = Math.round(s - 60 * m);
    return r ? `${m} min ${r} s` : `${m} min`;
  }
  return `${(s / 3600).toFixed(1)} h`;
}
