// The Delaunay view's panel in the constrained modes: its elements, which of the view's elements
// each mode shows ([data-dl-only="unconstrained constrained quality"]), the quality options read
// from the inputs, and the rings drawn, as they go in the URL.
import { validNumber } from '../../app/url-state.js';

export const MODES = ['unconstrained', 'constrained', 'quality'];
export const ANGLE_MAX = 34;
export const ANGLE_DEFAULT = 20;

/** The page elements of the constrained modes. */
export function polygonUi() {
  const $ = (id) => document.getElementById(id);
  return {
    mode: $('dl-mode'), closeRing: $('dl-close-ring'), undoVertex: $('dl-undo-vertex'), clearRings: $('dl-clear-rings'),
    sample: $('dl-sample'), minAngle: $('dl-min-angle'), minAngleValue: $('dl-min-angle-value'), maxArea: $('dl-max-area'),
    conforming: $('dl-conforming'), keep: $('dl-keep'), note: $('dl-cdt-note'), stepper: $('dl-stepper'),
  };
}

/** Which segments refinement leaves whole (keepSegments): 'none' (the default), 'boundary' or 'all'. */
export const KEEP_SEGMENTS = ['none', 'boundary', 'all'];
export const parseKeep = (text) => (KEEP_SEGMENTS.includes(text) ? text : 'none');

/** The minimum angle, whole or half degrees in [0, 34] (20 for anything else). */
export const parseAngle = (text) => validNumber(text, { min: 0, max: ANGLE_MAX, round: (v) => Math.round(2 * v) / 2, fallback: ANGLE_DEFAULT });

/** The maximum area: a positive finite number, or null for none (empty, 0, negative, not a number). */
export function parseArea(text) {
  if (text === null || text === undefined || String(text).trim() === '') return null;
  const v = Number(text);
  return Number.isFinite(v) && v > 0 ? v : null;
}

/** Shows the elements of `mode` and hides the others'; the stats take the mode's names. */
export function showModeElements(mode, stat) {
  for (const el of document.querySelectorAll('[data-dl-only]')) el.hidden = !el.dataset.dlOnly.split(' ').includes(mode);
  const points = mode === 'unconstrained';
  const label = (dd, text) => { dd.previousElementSibling.textContent = text; };
  label(stat.hull, points ? 'hull' : 'constrained');
  label(stat.dup, points ? 'duplicates' : 'added');
  label(stat.ms, points ? 'delaunay call' : mode === 'quality' ? 'mesh call' : 'CDT call');
  stat.hull.title = points ? '' : 'constrained edges: the rings\' edges and segments, split where points lie on them or they cross';
  stat.dup.title = points ? '' : 'points hullkit added: crossings of constraints and, in a quality mesh, Steiner points';
}

// Rings in the URL: rings=x,y;x,y;x,y|x,y;... (closed rings), open=x,y;... (the one being drawn);
// rings=none for none at all.

const encodeRing = (points, ring) => ring.map((i) => `${points[i][0]},${points[i][1]}`).join(';');

/** {rings, open} URL parameters of a drawn model (points in rings and the open ring only). */
export function encodeRings(model) {
  const rings = model.rings.map((ring) => encodeRing(model.points, ring)).join('|');
  return { rings: rings || 'none', open: model.open.length ? encodeRing(model.points, model.open) : undefined };
}

/** A drawn model from the URL's rings and open parameters, or null when it has no rings parameter. */
export function decodeRings(ringsText, openText) {
  if (ringsText === null || ringsText === undefined) return null;
  const points = [];
  const parse = (text) => (text ? text.split(';') : []).map((s) => s.split(',').map(Number))
    .filter((p) => p.length === 2 && p.every(Number.isFinite)).slice(0, 5000)
    .map((p) => points.push(p) - 1);
  const rings = ringsText === 'none' ? [] : ringsText.split('|').slice(0, 200).map(parse).filter((ring) => ring.length >= 3);
  const open = parse(openText ?? '');
  const used = new Set([...rings.flat(), ...open]);
  // Points of rings too short to keep are dropped, and the others renumbered.
  const renumber = new Map();
  const kept = [];
  points.forEach((p, i) => {
    if (used.has(i)) renumber.set(i, kept.push(p) - 1);
  });
  return { points: kept, rings: rings.map((ring) => ring.map((i) => renumber.get(i))), open: open.map((i) => renumber.get(i)) };
}
