// The URL holds the view shown and that view's options (?view=delaunay&set=grid&n=400...), so a
// copied link reproduces the view and back/forward move between states.

export const VIEWS = ['hull', 'delaunay', 'route'];

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
