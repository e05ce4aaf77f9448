// The Delaunay 3D view's panel: the page elements it uses, its inputs (the Hull view's point sets:
// distribution, n, seed, pasted points; shrink and the cutting plane) read and written, the options
// in the URL (every number made valid as the other views do), and the listeners of the inputs.
import { DISTRIBUTIONS, gridSide } from '../distributions.js';
import { fmtInt } from '../app/format.js';
import { writeUrl, validNumber, correctUrl } from '../app/url-state.js';
import { CUSTOM_SAMPLE } from './hull-panel.js';
import { CUT_MODES } from './delaunay3-scene.js';

const N_MAX = 200_000; // 100 000 points stay interactive: ~670 000 tetrahedra drawn
const SEED_MAX = 0xffffffff;
const SOURCES = [...Object.keys(DISTRIBUTIONS), 'custom', 'file'];
const GRIDS = ['grid', 'rotated-grid'];
export const DEFAULTS = Object.freeze({
  distribution: 'ball', n: 1000, seed: 1, sites: 'nearest', shrink: 0.75, cut: 'whole', offset: 0.1, azimuth: 0, elevation: 15,
});
const SITES = ['nearest', 'furthest'];

// Out-of-range values become the nearest valid one (n = -5 → 1, a shrink of 3 → 1, a tilt of 200° → 90°).
const RANGES = {
  n: { min: 1, max: N_MAX, fallback: DEFAULTS.n },
  seed: { min: 0, max: SEED_MAX, round: Math.floor, fallback: DEFAULTS.seed },
  shrink: { min: 0.1, max: 1, round: (v) => Math.round(100 * v) / 100, fallback: DEFAULTS.shrink },
  offset: { min: -1, max: 1, round: (v) => Math.round(100 * v) / 100, fallback: DEFAULTS.offset },
  azimuth: { min: -180, max: 180, fallback: DEFAULTS.azimuth },
  elevation: { min: -90, max: 90, fallback: DEFAULTS.elevation },
};
const valid = (key, text) => validNumber(text, RANGES[key]);
// The URL's names of the numeric options.
const URL_KEYS = { n: 'n', seed: 'seed', shrink: 'shrink', offset: 'offset', azimuth: 'az', elevation: 'el' };

/** The page elements of the Delaunay 3D view. */
export function delaunay3Ui() {
  const $ = (id) => document.getElementById(id);
  return {
    form: $('d3-controls'), distribution: $('d3-distribution'), generatedFields: $('d3-generated-fields'),
    n: $('d3-n'), nHint: $('d3-n-hint'), seed: $('d3-seed'), sites: $('d3-sites'), customField: $('d3-custom-field'), customPoints: $('d3-custom-points'),
    compute: $('d3-compute'), cancel: $('d3-cancel'), status: $('d3-status'), error: $('d3-error'),
    shrink: $('d3-shrink'), shrinkValue: $('d3-shrink-value'), cut: $('d3-cut'),
    offset: $('d3-offset'), offsetValue: $('d3-offset-value'), azimuth: $('d3-azimuth'), azimuthValue: $('d3-azimuth-value'),
    elevation: $('d3-elevation'), elevationValue: $('d3-elevation-value'),
    hover: $('d3-hover'), cell: $('d3-cell'), showPoints: $('d3-show-points'), showPlane: $('d3-show-plane'), resetView: $('d3-reset-view'),
    stat: {
      n: $('d3-stat-n'), tetrahedra: $('d3-stat-tetrahedra'), hull: $('d3-stat-hull'), ms: $('d3-stat-ms'),
      voronoi: $('d3-stat-voronoi'), rtt: $('d3-stat-rtt'), dup: $('d3-stat-dup'), draw: $('d3-stat-draw'),
    },
  };
}

/** The unit normal of the cutting plane from its azimuth (about z) and elevation, in degrees. */
export function planeNormal(azimuth, elevation) {
  const a = (azimuth * Math.PI) / 180, e = (elevation * Math.PI) / 180;
  return { x: Math.cos(e) * Math.cos(a), y: Math.cos(e) * Math.sin(a), z: Math.sin(e) };
}

const signed = (v) => (v < 0 ? `−${-v}` : String(v));

/**
 * The panel over the elements `ui`; `state.fileInput` holds the points of the last file opened.
 * `compute({push})` is asked for a new tetrahedralization, `applyDisplay()` when shrink or the cut
 * changed.
 */
export function createDelaunay3Panel({ ui, state }) {
  // The Hull view's point sets, by the labels of its generators.
  ui.distribution.replaceChildren(...SOURCES.map((name) => Object.assign(document.createElement('option'), {
    value: name,
    textContent: DISTRIBUTIONS[name]?.label ?? (name === 'custom' ? 'custom (paste coordinates)' : 'from a file'),
    hidden: name === 'file',
  })));
  ui.customPoints.value = CUSTOM_SAMPLE;

  function readParams() {
    let distribution = SOURCES.includes(ui.distribution.value) ? ui.distribution.value : DEFAULTS.distribution;
    if (distribution === 'file' && !state.fileInput) distribution = DEFAULTS.distribution;
    const sites = SITES.includes(ui.sites.value) ? ui.sites.value : DEFAULTS.sites;
    const p = { distribution, n: valid('n', ui.n.value), seed: valid('seed', ui.seed.value), sites };
    if (distribution === 'custom') p.text = ui.customPoints.value;
    if (distribution === 'file') Object.assign(p, { n: state.fileInput.xyz.length / 3, file: state.fileInput.name });
    return p;
  }

  function readDisplay() {
    return {
      shrink: valid('shrink', ui.shrink.value),
      cut: CUT_MODES.includes(ui.cut.value) ? ui.cut.value : DEFAULTS.cut,
      offset: valid('offset', ui.offset.value),
      azimuth: valid('azimuth', ui.azimuth.value),
      elevation: valid('elevation', ui.elevation.value),
    };
  }

  function writeParams(p) {
    ui.distribution.value = p.distribution;
    ui.n.value = String(p.n);
    ui.seed.value = String(p.seed);
    ui.sites.value = p.sites ?? DEFAULTS.sites;
    updateSourceFields();
  }

  function writeDisplay(d) {
    ui.shrink.value = String(d.shrink);
    ui.cut.value = d.cut;
    ui.offset.value = String(d.offset);
    ui.azimuth.value = String(d.azimuth);
    ui.elevation.value = String(d.elevation);
    showDisplayValues();
  }

  function showDisplayValues() {
    const d = readDisplay();
    ui.shrinkValue.textContent = d.shrink.toFixed(2);
    ui.offsetValue.textContent = signed(d.offset);
    ui.azimuthValue.textContent = `${signed(d.azimuth)}°`;
    ui.elevationValue.textContent = `${signed(d.elevation)}°`;
    for (const el of [ui.offset, ui.azimuth, ui.elevation]) el.disabled = d.cut === 'off';
  }

  function updateSourceFields() {
    const source = ui.distribution.value;
    ui.customField.hidden = source !== 'custom';
    ui.generatedFields.hidden = source === 'custom' || source === 'file';
    if (GRIDS.includes(source)) {
      const k = gridSide(valid('n', ui.n.value));
      ui.nHint.textContent = `n → ${k}×${k}×${k} = ${fmtInt(k ** 3)}`;
    } else {
      ui.nHint.textContent = 'n';
    }
  }

  /** The URL parameters that reproduce the view (display options only where not the default). */
  function urlParams() {
    const p = readParams();
    const q = { dist: p.distribution === 'file' ? DEFAULTS.distribution : p.distribution };
    if (!['custom', 'file'].includes(p.distribution)) Object.assign(q, { n: p.n, seed: p.seed });
    if (p.sites !== DEFAULTS.sites) q.sites = p.sites;
    const d = readDisplay();
    for (const key of ['shrink', 'offset', 'azimuth', 'elevation']) if (d[key] !== DEFAULTS[key]) q[URL_KEYS[key]] = d[key];
    if (d.cut !== DEFAULTS.cut) q.cut = d.cut;
    return q;
  }

  /** The URL's options shown in the panel; numbers out of range made valid, in the URL too. */
  function applyUrl(q) {
    const dist = q.get('dist');
    const p = {
      distribution: SOURCES.includes(dist) && dist !== 'file' ? dist : DEFAULTS.distribution,
      n: valid('n', q.get('n')), seed: valid('seed', q.get('seed')),
      sites: SITES.includes(q.get('sites')) ? q.get('sites') : DEFAULTS.sites,
    };
    const d = {
      cut: CUT_MODES.includes(q.get('cut')) ? q.get('cut') : DEFAULTS.cut,
      ...Object.fromEntries(['shrink', 'offset', 'azimuth', 'elevation'].map((key) => [key, valid(key, q.get(URL_KEYS[key]))])),
    };
    writeParams(p);
    writeDisplay(d);
    correctUrl({ ...Object.fromEntries(Object.entries(URL_KEYS).map(([key, name]) => [name, key in p ? p[key] : d[key]])), sites: p.sites });
  }

  /** Listens to the inputs: `compute` for new points, `applyDisplay` for shrink and the cut. */
  function listen({ compute, applyDisplay, scene }) {
    ui.distribution.addEventListener('change', () => {
      updateSourceFields();
      if (ui.distribution.value !== 'custom') compute({ push: true });
    });
    ui.n.addEventListener('input', updateSourceFields);
    for (const el of [ui.n, ui.seed, ui.sites]) el.addEventListener('change', () => compute({ push: true }));
    ui.customPoints.addEventListener('keydown', (event) => {
      if (event.key === 'Enter' && (event.ctrlKey || event.metaKey)) {
        event.preventDefault();
        compute({ push: true, force: true });
      }
    });
    // While a slider moves the drawing follows; the URL is written when it is let go.
    for (const el of [ui.shrink, ui.offset, ui.azimuth, ui.elevation]) {
      el.addEventListener('input', () => { showDisplayValues(); applyDisplay(); });
      el.addEventListener('change', () => writeUrl('delaunay3', urlParams()));
    }
    ui.cut.addEventListener('change', () => {
      showDisplayValues();
      applyDisplay();
      writeUrl('delaunay3', urlParams(), { push: true });
    });
    ui.showPoints.addEventListener('change', () => scene.setVisible({ points: ui.showPoints.checked }));
    ui.showPlane.addEventListener('change', () => scene.setVisible({ plane: ui.showPlane.checked }));
    ui.resetView.addEventListener('click', () => { scene.frameView(); scene.requestRender(); });
  }

  /** Sets the plane's offset (from a drag of its handle) in the slider. */
  function setOffset(offset) {
    ui.offset.value = String(valid('offset', offset));
    showDisplayValues();
  }

  return { readParams, readDisplay, writeParams, writeDisplay, updateSourceFields, urlParams, applyUrl, listen, setOffset };
}
