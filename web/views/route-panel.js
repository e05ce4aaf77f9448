// The Route view's panel: the page elements it uses, the per-leg table (status — a graze the
// bounds could not resolve shown as "hit (graze)" —, fraction, obstacle, clearance, N-step
// sampling), the waypoints table with each waypoint's yaw (editable), and the route in the URL:
// "x,y,z" per waypoint, "x,y,z,yaw" for one turned about z, "x,y,z,yaw,pitch,roll" for any other
// turn (degrees), waypoints separated by ";".
import { positionOf, isTurned, quaternionOf, yawOf, yawPitchRoll, withYaw } from '../route-poses.js';

export const SAMPLES_MAX = 200;
const ROUTE_MAX = 200; // waypoints in a URL

/** The page elements of the Route view. */
export function routeUi() {
  const $ = (id) => document.getElementById(id);
  return {
    form: $('rt-controls'), preset: $('rt-preset'), margin: $('rt-margin'), samples: $('rt-samples'), fileRole: $('rt-file-role'),
    showSamples: $('rt-show-samples'), add: $('rt-add'), remove: $('rt-remove'), reset: $('rt-reset'),
    status: $('rt-status'), error: $('rt-error'), legs: $('rt-legs').querySelector('tbody'), waypoints: $('rt-waypoints').querySelector('tbody'),
    stat: { verdict: $('rt-stat-verdict'), clearance: $('rt-stat-clearance'), ms: $('rt-stat-ms') },
    exports: { report: document.querySelector('[data-rt-export="report"]'), scene: document.querySelector('[data-rt-export="scene"]') },
  };
}

export const fmtFraction = (f) => (Array.isArray(f) ? f[0] : f)?.toFixed(4) ?? '—';
export const fmtLength = (d) => (Number.isFinite(d) ? (Math.abs(d) >= 1e-3 || d === 0 ? d.toFixed(3) : d.toExponential(2)) : '—');
const fmtDegrees = (d) => `${Number(d.toFixed(1))}°`;

/** A leg's status as the table shows it: "hit (graze)" for a graze the bounds could not resolve. */
export const legStatusText = (leg) => (leg.status === 'hit' && leg.grazing ? 'hit (graze)' : leg.status);

/** The table rows of a report's legs; `turns[i]` is the angle leg i turns (degrees), `subintervals[i]` its sub-interval count. */
export function legRows(report, turns, subintervals) {
  return report.legs.map((leg, i) => {
    const tr = document.createElement('tr');
    tr.dataset.status = leg.status;
    if (leg.grazing) tr.dataset.grazing = 'true';
    const sampled = leg.sampled ? (leg.sampled.hit ? `hit ${leg.sampled.fraction.toFixed(2)}` : 'clear') : '—';
    const missed = leg.sampled && !leg.sampled.hit && leg.status !== 'clear';
    const cells = [
      String(i + 1), legStatusText(leg),
      leg.status === 'clear' ? (leg.fraction !== undefined ? fmtFraction(leg.fraction) : '—') : fmtFraction(leg.fraction),
      leg.obstacle ?? '—',
      leg.status === 'clear' ? fmtLength(leg.clearance) : '0',
      missed ? 'missed' : sampled,
    ];
    for (const [k, text] of cells.entries()) {
      const td = document.createElement('td');
      td.textContent = text;
      if (k === 1) td.className = `status-${leg.status}${leg.grazing ? ' grazing' : ''}`;
      if (k === 5 && missed) td.className = 'missed';
      tr.append(td);
    }
    const notes = [];
    if (turns[i] > 0) notes.push(`turns ${fmtDegrees(turns[i])}, drawn as ${subintervals[i]} sub-interval hulls`);
    if (leg.status !== 'clear' && Array.isArray(leg.fraction)) {
      notes.push(`first contact in [${leg.fraction[0]}, ${leg.fraction[1]}] with ${leg.obstacle}` +
        `${leg.triangle !== undefined ? ` (triangle ${leg.triangle})` : ''}${leg.part ? `, by ${leg.part}` : ''}`);
    }
    if (leg.grazing) notes.push('a tangential graze the bounds could not resolve: not certified clear, so counted as a hit');
    if (notes.length) tr.title = notes.join('; ');
    return tr;
  });
}

/**
 * Fills the waypoints table: position and an editable yaw per waypoint; `onYaw(i, degrees)` when
 * a yaw is typed, `onSelect(i)` when a row is clicked.
 */
export function showWaypoints(ui, route, selected, { onYaw, onSelect }) {
  const rows = route.map((w, i) => {
    const tr = document.createElement('tr');
    tr.dataset.yaw = String(yawOf(w));
    if (i === selected) tr.className = 'selected';
    const index = document.createElement('td');
    index.textContent = String(i + 1);
    const position = document.createElement('td');
    position.textContent = positionOf(w).map((x) => Number(x.toFixed(3))).join(', ');
    const yawCell = document.createElement('td');
    const input = Object.assign(document.createElement('input'), { type: 'number', step: '5', value: String(Number(yawOf(w).toFixed(2))), className: 'yaw' });
    input.setAttribute('aria-label', `yaw of waypoint ${i + 1} (degrees about z)`);
    if (isTurned(w) && !w.rotation.axis) yawCell.title = `also turned: pitch and roll ${yawPitchRoll(quaternionOf(w)).slice(1).map(fmtDegrees).join(', ')}`;
    input.addEventListener('change', () => {
      const v = Number(input.value);
      if (input.value.trim() !== '' && Number.isFinite(v)) onYaw(i, v);
    });
    yawCell.append(input);
    tr.append(index, position, yawCell);
    tr.addEventListener('click', (event) => { if (event.target !== input) onSelect(i); });
    return tr;
  });
  ui.waypoints.replaceChildren(...rows);
}

const trim = (x) => String(Number(x.toFixed(6)));

/** The route as the URL's `route` parameter. */
export function routeParam(route) {
  return route.map((w) => {
    const numbers = [...positionOf(w)];
    if (isTurned(w)) {
      const [yaw, pitch, roll] = yawPitchRoll(quaternionOf(w));
      const pure = Math.abs(pitch) < 1e-9 && Math.abs(roll) < 1e-9;
      numbers.push(...(pure ? [yawOf(w)] : [yaw, pitch, roll]));
    }
    return numbers.map(trim).join(',');
  }).join(';');
}

/** The route from the URL's `route` parameter (null when missing or malformed). */
export function parseRoute(text) {
  if (!text) return null;
  const pts = text.split(';').map((s) => s.split(',').map(Number));
  if (pts.length < 2 || pts.length > ROUTE_MAX || !pts.every((p) => [3, 4, 6].includes(p.length) && p.every(Number.isFinite))) return null;
  return pts.map((p) => {
    if (p.length === 3) return p;
    if (p.length === 4) return withYaw(p.slice(0, 3), p[3]);
    return { position: p.slice(0, 3), rotation: { yaw_pitch_roll_degrees: p.slice(3) } };
  });
}
