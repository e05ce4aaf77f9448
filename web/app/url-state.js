// The URL holds the view shown and that view's options (?view=delaunay&set=grid&n=400...), so a
// copied link reproduces the view and back/forward move between states.

export const VIEWS = ['hull', 'delaunay', 'delaunay3', 'route'];

/** The view the URL names (hull when none or unknown). */
export function viewFromUrl() {
  const view = new URLSearchParams(location.search).get('view');
  return VIEWS.includes(view) ? view : 'hull';
}

/** The URL's parameters. */
export function queryFromUrl() {
  return new URLSearchParams(location.search);
}

/**
 * Puts `view` and its `params` (an object of strings/numbers; undefined/null/'' left out) in the
 * URL: a new history entry when `push`, else in place. Nothing happens when the URL already says so.
 */
export function writeUrl(view, params, { push = false } = {}) {
  const q = new URLSearchParams({ view });
  for (const [key, value] of Object.entries(params)) {
    if (value !== undefined && value !== null && value !== '') q.set(key, String(value));
  }
  const search = `?${q}`;
  if (location.search === search) return;
  if (push) history.pushState(null, '', search);
  else history.replaceState(null, '', search);
}

/**
 * A number from the URL (or typed in a field) made valid: out of [min, max] it becomes the nearest
 * bound (±Infinity included), `round` (Math.round, Math.floor; null keeps fractions) makes it a
 * whole number, and text that is no number at all (or is missing) gives `fallback`. The views read
 * every numeric option through this, and put the value they use back in the URL.
 */
export function validNumber(text, { min = -Infinity, max = Infinity, round = Math.round, fallback }) {
  if (text === null || text === undefined || String(text).trim() === '') return fallback;
  const v = Number(text);
  if (Number.isNaN(v)) return fallback;
  let valid = Math.max(min, Math.min(max, v));
  if (round) valid = round(valid); // the bounds are whole numbers where `round` is given
  return Number.isFinite(valid) ? valid + 0 : fallback; // + 0: no -0
}

/**
 * Corrects the URL in place: each key of `values` that the URL has gets the value given (the one
 * the view uses, see validNumber); the other parameters stay as they are. No history entry.
 */
export function correctUrl(values) {
  const q = new URLSearchParams(location.search);
  let changed = false;
  for (const [key, value] of Object.entries(values)) {
    if (q.has(key) && q.get(key) !== String(value)) {
      q.set(key, String(value));
      changed = true;
    }
  }
  if (changed) history.replaceState(null, '', `?${q}`);
}
