// The Delaunay view's panel: the page elements it uses, its inputs (point set, n, seed,
// algorithm, layout, Voronoi cells and the points clicked in) read and written, the options in
// the URL, and the listeners of the inputs.
import { fmtInt } from '../app/format.js';
import { writeUrl, validNumber, correctUrl } from '../app/url-state.js';
import { POINT_SETS, gridSide2 } from '../points2d.js';

const N_MIN = 3; // the fewest points with a triangle
const N_MAX = 50_000;
const SEED_MAX = 0xffffffff;
const DEFAULTS = { set: 'uniform', n: 300, seed: 1, layout: 'side', voronoi: false, algorithm: '' };
const FIGURE1_N = 1024;

/** The page elements of the Delaunay view. */
export function delaunayUi() {
  const $ = (id) => document.getElementById(id);
  return {
    form: $('dl-controls'), set: $('dl-set'), n: $('dl-n'), nHint: $('dl-n-hint'), seed: $('dl-seed'),
    algorithm: $('dl-algorithm'), algorithmField: $('dl-algorithm-field'), clear: $('dl-clear'),
    status: $('dl-status'), error: $('dl-error'), layout: $('dl-layout'),
    showLifted: $('dl-show-lifted'), showVoronoi: $('dl-show-voronoi'), showDrops: $('dl-show-drops'),
    stat: { n: $('dl-stat-n'), triangles: $('dl-stat-triangles'), hull: $('dl-stat-hull'), ms: $('dl-stat-ms'), rtt: $('dl-stat-rtt'), dup: $('dl-stat-dup') },
  };
}

// Out-of-range values become the nearest valid one (n = -5 → 3, a seed of -3 → 0).
const parseN = (text) => validNumber(text, { min: N_MIN, max: N_MAX, fallback: DEFAULTS.n });
const parseSeed = (text) => validNumber(text, { min: 0, max: SEED_MAX, round: Math.floor, fallback: DEFAULTS.seed });

function decodeAdded(text) {
  if (!text) return [];
  return text.split(';').map((s) => s.split(',').map(Number)).filter((p) => p.length === 2 && p.every(Number.isFinite)).slice(0, 10_000);
}

/**
 * The panel over the elements `ui`: it reads and writes `state.added` (and reads
 * `state.fileInput`, `state.active`), lays out and frames `scene`, redraws with `drawing` and
 * asks `compute` for a new triangulation. `viewUrlParams()`, when given, is what the view puts in
 * the URL (its constrained modes have their own parameters).
 */
export function createDelaunayPanel({ ui, state, scene, drawing, compute, viewUrlParams = null }) {
  const { layoutPanes, frame3d, requestRender } = scene;
  const { drawVoronoi, applyVisibility } = drawing;

  function readParams() {
    const set = POINT_SETS.includes(ui.set.value) || (ui.set.value === 'file' && state.fileInput) ? ui.set.value : DEFAULTS.set;
    return { set, n: parseN(ui.n.value), seed: parseSeed(ui.seed.value), layout: ui.layout.value, voronoi: ui.showVoronoi.checked, algorithm: ui.algorithm.value };
  }

  function writeParams(p) {
    ui.set.value = p.set;
    ui.n.value = String(p.n);
    ui.seed.value = String(p.seed);
    ui.layout.value = p.layout;
    ui.showVoronoi.checked = p.voronoi;
    if (p.algorithm && [...ui.algorithm.options].some((o) => o.value === p.algorithm)) ui.algorithm.value = p.algorithm;
    updateHint();
  }

  function updateHint() {
    const set = ui.set.value;
    const n = Number(ui.n.value) || 0;
    if (set === 'grid' || set === 'rotated-grid') {
      const k = gridSide2(n);
      ui.nHint.textContent = `n → ${k}×${k} = ${fmtInt(k * k)}`;
    } else {
      ui.nHint.textContent = 'n';
    }
  }

  const encodeAdded = () => state.added.map(([x, y]) => `${x},${y}`).join(';');

  function urlParams() {
    const p = readParams();
    if (p.set === 'file') return { set: DEFAULTS.set }; // a file's points cannot be put in a link
    return {
      set: p.set, n: p.n, seed: p.seed,
      layout: p.layout === 'side' ? undefined : p.layout,
      voronoi: p.voronoi ? 1 : undefined,
      algo: p.algorithm && p.algorithm !== ui.algorithm.options[0]?.value ? p.algorithm : undefined,
      add: state.added.length ? encodeAdded() : undefined,
    };
  }

  function applyUrl(q) {
    const n = parseN(q.get('n'));
    const seed = parseSeed(q.get('seed'));
    writeParams({
      set: POINT_SETS.includes(q.get('set')) ? q.get('set') : DEFAULTS.set,
      n, seed,
      layout: q.get('layout') === 'blend' ? 'blend' : 'side',
      voronoi: q.get('voronoi') === '1',
      algorithm: q.get('algo') ?? '',
    });
    correctUrl({ n, seed }); // out-of-range values, made valid
    state.added = decodeAdded(q.get('add'));
    layoutPanes();
    if (state.active) compute({ push: false });
  }

  function setAlgorithms(info) {
    const list = info?.delaunay?.algorithms ?? ['incremental'];
    const wanted = ui.algorithm.value;
    const labels = { incremental: 'incremental insertion', giftwrap: 'gift wrapping the lifted points' };
    ui.algorithm.replaceChildren(...list.map((name) => Object.assign(document.createElement('option'), { value: name, textContent: labels[name] ?? name })));
    ui.algorithm.value = list.includes(wanted) ? wanted : list[0];
    const q = new URLSearchParams(location.search);
    if (q.get('view') === 'delaunay' && list.includes(q.get('algo'))) ui.algorithm.value = q.get('algo');
  }

  /** Listens to the inputs. */
  function listen() {
    ui.set.addEventListener('change', () => {
      if (ui.set.value === 'figure1') ui.n.value = String(FIGURE1_N);
      state.added = [];
      updateHint();
      compute({ push: true });
    });
    ui.n.addEventListener('input', updateHint);
    ui.n.addEventListener('change', () => compute({ push: true }));
    ui.seed.addEventListener('change', () => compute({ push: true }));
    ui.algorithm.addEventListener('change', () => compute({ push: true }));
    ui.clear.addEventListener('click', () => {
      state.added = [];
      compute({ push: true });
    });
    ui.showVoronoi.addEventListener('change', () => {
      if (ui.showVoronoi.checked && !state.cells) compute({ push: true });
      else {
        drawVoronoi();
        writeUrl('delaunay', urlParams(), { push: true });
        requestRender();
      }
    });
    ui.layout.addEventListener('change', () => {
      layoutPanes();
      frame3d();
      applyVisibility();
      writeUrl('delaunay', (viewUrlParams ?? urlParams)(), { push: true });
      requestRender();
    });
    for (const box of [ui.showLifted, ui.showDrops]) box.addEventListener('change', () => { applyVisibility(); requestRender(); });
  }

  return { readParams, updateHint, encodeAdded, urlParams, applyUrl, setAlgorithms, listen };
}
