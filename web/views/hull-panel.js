// The Hull view's panel: the page elements it uses, its inputs (point source, n, seed,
// algorithm, the seed's epsilon, merging) read and written, the options in the URL, the
// confirmation asked before an expensive gift wrapping run, and the listeners of the inputs.
import { gridSide } from '../distributions.js';
import { fmtInt, fmtDuration } from '../app/format.js';
import { writeUrl, validNumber } from '../app/url-state.js';
import { SPHERE_WARN_N } from './hull-cost.js';

const N_MIN = 4; // the slider's left end
const N_FEWEST = 1; // typed or in the URL: fewer than 4 points are passed on, and the library says
// what their hull is (a point, a segment, a triangle); no points at all make no hull
const N_MAX = 1_000_000;
const SEED_MAX = 0xffffffff;
const N_DEFAULT = 2000;
const SEED_DEFAULT = 1;
const DIST_DEFAULT = 'ball';
const DEFAULT_ALGORITHM = 'quickhull'; // the library's default (it lists it first)
const DISTRIBUTIONS = ['cube', 'ball', 'sphere', 'plane', 'near-coplanar', 'grid', 'rotated-grid', 'custom', 'file'];
const GRIDS = ['grid', 'rotated-grid'];
export const CUSTOM_SAMPLE = `# x y z per point; '#' comments
# unit cube + centre
0 0 0
1 0 0
0 1 0
1 1 0
0 0 1
1 0 1
0 1 1
1 1 1
0.5 0.5 0.5
`;

/** The page elements of the Hull view. */
export function hullUi() {
  const $ = (id) => document.getElementById(id);
  return {
    form: $('controls'),
    distribution: $('distribution'),
    algorithmField: $('algorithm-field'),
    algorithm: $('algorithm'),
    epsilonField: $('epsilon-field'),
    epsilon: $('epsilon'),
    epsilonNote: $('epsilon-note'),
    merge: $('merge'),
    nHint: $('n-hint'),
    generatedFields: $('generated-fields'),
    customField: $('custom-field'),
    customPoints: $('custom-points'),
    nSlider: $('n-slider'),
    n: $('n'),
    seed: $('seed'),
    reseed: $('reseed'),
    compute: $('compute'),
    cancel: $('cancel'),
    status: $('status'),
    error: $('error'),
    warning: $('warning'),
    warningText: $('warning-text'),
    useCap: $('use-cap'),
    useQuickhull: $('use-quickhull'),
    compare: $('compare'),
    compareText: $('compare-text'),
    compareSeed: $('compare-seed'),
    compareExact: $('compare-exact'),
    facesLabel: $('stat-faces-label'),
    legendDropped: $('legend-dropped'),
    showFaces: $('show-faces'),
    showEdges: $('show-edges'),
    showPoints: $('show-points'),
    resetView: $('reset-view'),
    viewport: $('viewport'),
    canvas: $('canvas'),
    stat: {
      n: $('stat-n'),
      vertices: $('stat-vertices'),
      faces: $('stat-faces'),
      edges: $('stat-edges'),
      volume: $('stat-volume'),
      area: $('stat-area'),
      ms: $('stat-ms'),
      rtt: $('stat-rtt'),
      draw: $('stat-draw'),
    },
  };
}

// ---------------------------------------------------------------- inputs

const LOG_RANGE = Math.log(N_MAX / N_MIN);
const sliderToN = (s) => Math.round(N_MIN * Math.exp((s / 1000) * LOG_RANGE));
export const nToSlider = (n) => Math.round((1000 * Math.log(Math.max(N_MIN, Math.min(N_MAX, n)) / N_MIN)) / LOG_RANGE);

// Out-of-range values become the nearest valid one (n = -5 → 1, a seed of -3 → 0).
const parseN = (text) => validNumber(text, { min: N_FEWEST, max: N_MAX, fallback: N_DEFAULT });
const parseSeed = (text) => validNumber(text, { min: 0, max: SEED_MAX, round: Math.floor, fallback: SEED_DEFAULT });

// Cheap count of the coordinates in the pasted text (for the cost estimate only).
function roughCustomCount(text) {
  const tokens = text.replace(/#.*$/gm, '').split(/[\s,;]+/).filter(Boolean).length;
  return Math.floor(tokens / 3);
}

/** The URL parameters that reproduce `params`. */
export function urlParamsOf({ distribution, n, seed, algorithm, epsilon, mergeCoplanar }) {
  const q = { dist: distribution };
  if (distribution === 'file') return { dist: DIST_DEFAULT }; // not reproducible by a link
  if (distribution !== 'custom') {
    q.n = n;
    q.seed = seed;
  }
  if (algorithm) q.algo = algorithm;
  if (epsilon === 'seed') q.eps = 'seed';
  if (mergeCoplanar) q.merge = 1;
  return q;
}

export const paramsKey = (p) => `${p.distribution}|${p.n}|${p.seed}|${p.algorithm}|${p.epsilon}|${p.mergeCoplanar}|${p.text ?? ''}|${p.file ?? ''}`;

const ALGORITHM_LABELS = { giftwrap: 'gift wrapping · O(n·h)', quickhull: 'quickhull · O(n log n)' };

/**
 * The panel over the elements `ui`; `state` is the view's shared state (it reads active,
 * job, runCount, lastFailed, fileInput; keeps preferredAlgorithm and pendingConfirmKey).
 */
export function createHullPanel({ ui, state }) {
  /** The algorithm that will run: the selected one, else the library's default. */
  const chosenAlgorithm = () => ui.algorithm.value || DEFAULT_ALGORITHM;
  /** The seed's epsilon exists for gift wrapping only; quickhull always decides exactly. */
  const epsilonApplies = () => chosenAlgorithm() === 'giftwrap';

  function readParams() {
    const distribution = DISTRIBUTIONS.includes(ui.distribution.value) ? ui.distribution.value : DIST_DEFAULT;
    const algorithm = ui.algorithm.value || undefined;
    const epsilon = epsilonApplies() && ui.epsilon.value === 'seed' ? 'seed' : 'exact';
    const mergeCoplanar = ui.merge.checked;
    if (distribution === 'file' && state.fileInput) {
      return { distribution, n: state.fileInput.xyz.length / 3, seed: 0, algorithm, epsilon, mergeCoplanar, file: state.fileInput.name };
    }
    if (distribution === 'custom') {
      const text = ui.customPoints.value;
      return { distribution, n: roughCustomCount(text), seed: 0, algorithm, epsilon, mergeCoplanar, text };
    }
    return { distribution, n: parseN(ui.n.value), seed: parseSeed(ui.seed.value), algorithm, epsilon, mergeCoplanar };
  }

  function writeParams({ distribution, n, seed }) {
    ui.distribution.value = distribution === 'file' && !state.fileInput ? DIST_DEFAULT : distribution;
    if (distribution !== 'custom' && distribution !== 'file') {
      ui.n.value = String(n);
      ui.nSlider.value = String(nToSlider(n));
      ui.seed.value = String(seed);
    }
    updateSourceFields();
  }

  function updateSourceFields() {
    const custom = ui.distribution.value === 'custom';
    ui.customField.hidden = !custom;
    ui.generatedFields.hidden = custom || ui.distribution.value === 'file';
    updateNHint();
  }

  /** Grids round n to a cube number: say which. */
  function updateNHint() {
    const distribution = ui.distribution.value;
    if (GRIDS.includes(distribution)) {
      const k = gridSide(parseN(ui.n.value));
      ui.nHint.textContent = `n → ${k}×${k}×${k} = ${fmtInt(k ** 3)}`;
    } else {
      ui.nHint.textContent = 'n';
    }
  }

  function updateEpsilonField() {
    const applies = epsilonApplies();
    ui.epsilon.disabled = !applies;
    ui.epsilonField.classList.toggle('inactive', !applies);
    ui.epsilonNote.textContent = applies
      ? (ui.epsilon.value === 'seed'
        ? 'Within ε = DBL_EPSILON × (x + y + z extent) of a plane counts as on it; each run is compared with exact predicates.'
        : 'Every side test is exact. Pick the seed\'s epsilon to compare (try “near-coplanar”).')
      : 'Quickhull is always exact; the seed\'s epsilon is a gift wrapping option.';
  }

  function paramsFromUrl(q) {
    // A file's points cannot be put in a link: such URLs show the default points.
    const distribution = DISTRIBUTIONS.includes(q.get('dist')) && q.get('dist') !== 'file' ? q.get('dist') : DIST_DEFAULT;
    const n = q.has('n') ? parseN(q.get('n')) : N_DEFAULT;
    const seed = q.has('seed') ? parseSeed(q.get('seed')) : SEED_DEFAULT;
    state.preferredAlgorithm = q.get('algo');
    ui.epsilon.value = q.get('eps') === 'seed' ? 'seed' : 'exact';
    ui.merge.checked = q.get('merge') === '1';
    return { distribution, n, seed };
  }

  /** A new history entry for each run after the first (back/forward step through them). */
  function paramsToUrl(params) {
    if (params.distribution === 'file') return; // the URL keeps the last reproducible state
    if (state.active) writeUrl('hull', urlParamsOf(params), { push: state.runCount > 0 || state.lastFailed });
  }

  function describeInput({ distribution, n, file }) {
    if (distribution === 'custom') return 'the pasted points';
    if (distribution === 'file') return `${fmtInt(n)} points from ${file}`;
    if (GRIDS.includes(distribution)) {
      const k = gridSide(n);
      return `${fmtInt(k ** 3)} points: ${labelOf(distribution)} ${k}×${k}×${k}`;
    }
    return `${fmtInt(n)} ${n === 1 ? 'point' : 'points'} ${labelOf(distribution)}`;
  }

  function labelOf(distribution) {
    return ui.distribution.querySelector(`option[value="${distribution}"]`)?.textContent ?? distribution;
  }

  function setAlgorithms(algorithms) {
    if (!Array.isArray(algorithms) || algorithms.length === 0) return;
    const current = ui.algorithm.value || state.preferredAlgorithm;
    ui.algorithm.replaceChildren(...algorithms.map((name) => {
      const option = document.createElement('option');
      option.value = name;
      option.textContent = ALGORITHM_LABELS[name] ?? name;
      return option;
    }));
    // The library lists its default first.
    ui.algorithm.value = algorithms.includes(current) ? current : algorithms[0];
    ui.algorithmField.hidden = false;
    ui.epsilonField.hidden = !algorithms.includes('giftwrap');
    updateEpsilonField();
  }

  function showWarning(params, estMs) {
    state.pendingConfirmKey = paramsKey(params);
    // Only gift wrapping asks (see needsConfirmation).
    const why = params.distribution === 'sphere'
      ? `All ${fmtInt(params.n)} points on a sphere are hull vertices, and gift wrapping costs O(n·h) = O(n²) here.`
      : `Gift wrapping costs O(n·h) for ${describeInput(params)}.`;
    ui.warningText.textContent = `${why} Estimated time ≈ ${fmtDuration(estMs)}. ` +
      'Click “Run anyway” to start; the page stays responsive and the run can be cancelled. ' +
      'Quickhull computes the same hull in well under a second.';
    ui.useCap.hidden = params.distribution === 'custom' || params.n <= SPHERE_WARN_N;
    ui.useQuickhull.hidden = ![...ui.algorithm.options].some((o) => o.value === 'quickhull');
    ui.warning.hidden = false;
    ui.compute.textContent = 'Run anyway';
    ui.compute.classList.add('warn');
    ui.status.textContent = 'Expensive run: confirm or reduce n.';
  }

  function hideWarning() {
    state.pendingConfirmKey = null;
    ui.warning.hidden = true;
    ui.compute.textContent = 'Compute';
    ui.compute.classList.remove('warn');
  }

  function hideError() {
    ui.error.hidden = true;
    ui.error.textContent = '';
  }

  /**
   * Listens to the inputs (`requestCompute` on Ctrl/Cmd+Enter in the pasted points) and to the
   * display options of `scene`.
   */
  function listen({ requestCompute, scene }) {
    ui.nSlider.addEventListener('input', () => {
      ui.n.value = String(sliderToN(Number(ui.nSlider.value)));
      onParamsEdited();
    });
    ui.n.addEventListener('input', () => {
      const v = Number(ui.n.value);
      if (Number.isFinite(v)) ui.nSlider.value = String(nToSlider(v));
      onParamsEdited();
    });
    ui.seed.addEventListener('input', onParamsEdited);
    ui.customPoints.addEventListener('input', onParamsEdited);
    ui.algorithm.addEventListener('change', () => {
      updateEpsilonField();
      onParamsEdited();
    });
    ui.epsilon.addEventListener('change', () => {
      updateEpsilonField();
      onParamsEdited();
    });
    ui.merge.addEventListener('change', onParamsEdited);
    ui.distribution.addEventListener('change', () => {
      updateSourceFields();
      onParamsEdited();
    });
    ui.reseed.addEventListener('click', () => {
      ui.seed.value = String((Math.random() * 0x100000000) >>> 0);
      onParamsEdited();
    });
    function onParamsEdited() {
      updateNHint();
      if (state.pendingConfirmKey !== null && state.pendingConfirmKey !== paramsKey(readParams())) {
        hideWarning();
        if (!state.job) ui.status.textContent = '';
      }
    }
    // Ctrl/Cmd+Enter in the text area computes (Enter alone inserts a line).
    ui.customPoints.addEventListener('keydown', (event) => {
      if (event.key === 'Enter' && (event.ctrlKey || event.metaKey)) {
        event.preventDefault();
        requestCompute();
      }
    });

    for (const box of [ui.showFaces, ui.showEdges, ui.showPoints]) {
      box.addEventListener('change', () => { scene.applyVisibility(); scene.requestRender(); });
    }
    ui.resetView.addEventListener('click', () => { scene.frameView(false); scene.requestRender(); });
  }

  return {
    readParams, writeParams, updateSourceFields, updateEpsilonField, paramsFromUrl, paramsToUrl,
    describeInput, setAlgorithms, showWarning, hideWarning, hideError, listen,
  };
}
