// The Hull view's report of a run in the panel: the stats, the status line (what was drawn, the
// faces merged, degenerate inputs, what the seed's epsilon did), the table comparing the seed's
// epsilon with exact predicates, the error of a failed run, and the test hooks
// window.hullkitStats, window.hullkitEpsilon and window.hullkitError.
import { fmtInt, fmtReal, fmtMs } from '../app/format.js';
import { STEP_MAX } from './giftwrap-stepper.js';

const DIMENSION_NOTES = {
  2: (r) => `The points are coplanar: their hull is a flat convex polygon with ${fmtInt(r.vertices.length)} corners (volume 0).`,
  1: () => 'The points are collinear: their hull is a segment.',
  0: () => 'All points coincide: their hull is a single point.',
  [-1]: () => 'There are no points.',
};

const POLYGON_NAMES = { 3: 'triangle', 4: 'quadrilateral', 5: 'pentagon', 6: 'hexagon', 7: 'heptagon', 8: 'octagon' };

/** "6 quadrilaterals", "80 triangles, 3 quadrilaterals and 1 pentagon", … (largest groups first). */
function describeFaceSizes(sizes) {
  const groups = Object.entries(sizes).map(([k, count]) => [Number(k), count]).sort((a, b) => b[1] - a[1] || a[0] - b[0]);
  const parts = groups.slice(0, 4).map(([k, count]) => {
    const name = POLYGON_NAMES[k] ?? `${k}-gon`;
    return `${fmtInt(count)} ${name}${count === 1 ? '' : 's'}`;
  });
  if (groups.length > 4) parts.push(`${groups.length - 4} other sizes`);
  return parts.length > 1 ? `${parts.slice(0, -1).join(', ')} and ${parts.at(-1)}` : parts[0] ?? 'none';
}

/** A very thin 3D hull (near-coplanar points): its thickness, about 2 · volume / area. */
function slabNote(msg, radius) {
  if (msg.dimension !== 3 || !(msg.area > 0) || !(radius > 0)) return '';
  const thickness = (2 * msg.volume) / msg.area;
  if (thickness > 1e-6 * radius) return '';
  return ` The hull is a slab about ${thickness.toExponential(1)} thick: a polytope for exact predicates, drawn flat at this scale.`;
}

const EXACT_NAME = 'exact predicates';

const fmtEps = (c) => `ε = ${c.epsilon.toExponential(1)}`;
const hullSummary = (h) => `${fmtInt(h.vertices)} vertices, ${fmtInt(h.faces)} faces, volume ${fmtReal(h.volume)}`;

/** What the seed's epsilon did, as one or two sentences for the status line. */
function epsilonSentence(c, seed) {
  const exact = c.exact;
  if (!exact) return `Exact predicates could not be compared: ${c.exactError ?? 'unknown error'}.`;
  if (c.outcome === 'failed') {
    const exactHull = {
      3: () => `is a polytope with ${hullSummary(exact)}`,
      2: () => `is a flat polygon with ${fmtInt(exact.vertices)} corners`,
      1: () => 'is a segment',
      0: () => 'is a single point',
    }[exact.dimension]?.() ?? 'is empty';
    return `The seed's epsilon (${fmtEps(c)}) could not decide these points, so gift wrapping gave up; ` +
      `with ${EXACT_NAME} the hull ${exactHull}.`;
  }
  if (c.outcome === 'same') {
    return `The seed's epsilon (${fmtEps(c)}) made no difference here: ${EXACT_NAME} give the same ${fmtInt(exact.vertices)} vertices.`;
  }
  const parts = [];
  const dropped = c.dropped?.length ?? 0;
  if (dropped) parts.push(`left out ${fmtInt(dropped)} extreme point${dropped === 1 ? '' : 's'} (pink) that it took to lie on a face plane`);
  if (c.added) parts.push(`kept ${fmtInt(c.added)} point${c.added === 1 ? '' : 's'} that ${c.added === 1 ? 'is' : 'are'} not extreme`);
  if (!parts.length) parts.push('split the faces differently');
  return `The seed's epsilon (${fmtEps(c)}) changed the hull: it ${parts.join(' and ')}; ` +
    `${fmtInt(seed.vertices)} vertices instead of the exact ${fmtInt(exact.vertices)}.`;
}

function publicComparison(c, seed) {
  return {
    outcome: c.outcome, epsilon: c.epsilon, seed, exact: c.exact,
    dropped: c.dropped ? c.dropped.length : 0, added: c.added ?? 0,
  };
}

/**
 * The report over the elements `ui`: showResult and showFailure draw on `scene`, write the shared
 * `state` (runCount, lastFailed, lastHull), calibrate the cost model, offer the `stepper` and
 * enable the export buttons (`setExportEnabled`, the file names from `exportName`).
 */
export function createHullReport({ ui, state, scene, setState, calibrate, describeInput, exportName, setExportEnabled, stepper }) {
  function showResult(msg, params, roundTripMs, freshWorker) {
    const merged = Boolean(params.mergeCoplanar) && msg.dimension >= 2;
    const faces = msg.faces ?? msg.triangles.length / 3;
    const vertices = msg.vertices.length;
    const edges = msg.edges.length / 2;
    const comparison = msg.comparison ?? null;
    const d0 = performance.now();
    scene.drawScene({ ...msg, dropped: comparison?.dropped ?? null });
    const drawMs = performance.now() - d0;

    state.runCount++;
    if (msg.dimension === 3) calibrate(params.algorithm, msg.n, vertices, msg.hullMs);

    setStats({
      n: fmtInt(msg.n), vertices: fmtInt(vertices), faces: fmtInt(faces), edges: fmtInt(edges),
      volume: fmtReal(msg.volume), area: fmtReal(msg.area), ms: fmtMs(msg.hullMs), rtt: fmtMs(roundTripMs),
      draw: fmtMs(drawMs),
    });
    ui.facesLabel.textContent = merged ? 'polygons' : 'triangles';
    ui.stat.faces.title = merged
      ? `${fmtInt(faces)} planar faces (${describeFaceSizes(msg.faceSizes ?? {})}), drawn as ${fmtInt(msg.triangles.length / 3)} triangles`
      : 'triangles of the hull surface';
    ui.stat.edges.title = merged ? 'sides of the polygon faces (no triangulation diagonals)' : 'edges of the triangles';
    ui.stat.volume.title = String(msg.volume);
    ui.stat.area.title = String(msg.area);
    ui.stat.ms.title = `hullkit.hull() inside the worker; points generated in ${fmtMs(msg.genMs)}, worker total ${fmtMs(msg.workerMs)}`;
    ui.stat.rtt.title = 'from posting the request to receiving the result (generation, hull, edges, transfer)';
    ui.stat.draw.title = 'building the three.js geometry and the first render on the main thread';
    const seedNote = ['custom', 'grid', 'file'].includes(params.distribution) ? '' : ` (seed ${params.seed})`;
    const fromFile = params.distribution === 'file';
    let status = `Hull of ${params.distribution === 'custom' ? `${fmtInt(msg.n)} pasted points` : describeInput(params)}${fromFile ? '' : seedNote}.`;
    if (scene.interiorStride > 1) status += ` Drawing every ${fmtInt(scene.interiorStride)}th of the ${fmtInt(scene.interiorTotal)} interior points.`;
    if (scene.dense) status += ' So many faces: drawn without the wireframe and back faces, so that orbiting stays smooth.';
    if (DIMENSION_NOTES[msg.dimension]) status += ` ${DIMENSION_NOTES[msg.dimension](msg)}`;
    if (merged && msg.dimension === 3) {
      const sizes = msg.faceSizes ?? {};
      status += Object.keys(sizes).every((k) => k === '3')
        ? ` No coplanar triangles to merge: ${fmtInt(faces)} triangular faces.`
        : ` Coplanar triangles merged into ${fmtInt(faces)} faces: ${describeFaceSizes(sizes)}.`;
    }
    status += slabNote(msg, scene.viewRadius);
    if (comparison) status += ` ${epsilonSentence(comparison, { vertices, faces, volume: msg.volume })}`;
    if (freshWorker) status += ' The round trip includes starting the worker and loading the WebAssembly module.';
    ui.status.textContent = status;
    showComparison(comparison, { vertices, faces, volume: msg.volume }, merged);

    state.lastHull = { xyz: msg.xyz, triangles: msg.triangles, dimension: msg.dimension, name: exportName(params) };
    setExportEnabled(msg.triangles.length > 0);
    stepper.offer({
      coords: msg.xyz, n: msg.n, eligible: msg.dimension === 3,
      why: msg.dimension === 3 ? `Available for at most ${STEP_MAX} points (set n to ${STEP_MAX} or fewer).` : 'Available for three-dimensional hulls.',
    });
    window.hullkitStats = {
      n: msg.n, vertices, faces, edges, triangles: msg.triangles.length / 3, merged,
      interiorStride: scene.interiorStride,
      volume: msg.volume, area: msg.area, dimension: msg.dimension,
      ms: msg.hullMs, roundTripMs, drawMs, answeredAt: d0, distribution: params.distribution, seed: params.seed,
      algorithm: params.algorithm ?? null, epsilon: params.epsilon ?? 'exact', run: state.runCount,
    };
    // The triangles too, on demand (non-enumerable: JSON of the hook stays short).
    const drawnTriangles = msg.triangles;
    Object.defineProperty(window.hullkitStats, 'triangleList', { get: () => Array.from(drawnTriangles) });
    window.hullkitEpsilon = comparison ? publicComparison(comparison, { vertices, faces, volume: msg.volume }) : null;
    window.hullkitError = null;
    state.lastFailed = false;
    setState('ready');
  }

  function showComparison(c, seed, merged) {
    if (!c) {
      ui.compare.hidden = true;
      return;
    }
    const cells = (row, values) => row.querySelectorAll('td').forEach((td, i) => { td.textContent = values[i] ?? ''; });
    const facesWord = merged ? 'polygons' : 'triangles';
    ui.compare.dataset.outcome = c.outcome;
    ui.compareText.textContent = `The seed's ${fmtEps(c)} ` + {
      same: 'gives the exact hull',
      different: `gives a different hull from ${EXACT_NAME}`,
      failed: `fails; ${EXACT_NAME} succeed`,
    }[c.outcome];
    if (seed) cells(ui.compareSeed, [fmtInt(seed.vertices), fmtInt(seed.faces), fmtReal(seed.volume)]);
    else cells(ui.compareSeed, ['error', '—', '—']);
    if (c.exact) cells(ui.compareExact, [fmtInt(c.exact.vertices), fmtInt(c.exact.faces), fmtReal(c.exact.volume)]);
    else cells(ui.compareExact, ['error', '—', '—']);
    ui.compare.querySelector('thead th:nth-child(3)').textContent = facesWord;
    ui.compare.hidden = false;
  }

  function showFailure(message, msg, params = null) {
    const comparison = msg?.comparison ?? null;
    state.lastHull = null;
    setExportEnabled(false);
    stepper.offer({ why: 'Compute a hull first.' });
    if (msg && msg.xyz && msg.xyz.length % 3 === 0) {
      scene.drawScene({ xyz: msg.xyz }); // show the offending input
      setStats({ n: fmtInt(msg.n) });
    } else {
      scene.clearContent();
      scene.requestRender();
      setStats({});
    }
    ui.facesLabel.textContent = 'faces';
    ui.error.textContent = message;
    ui.error.hidden = false;
    ui.status.textContent = comparison ? epsilonSentence(comparison, null) : '';
    showComparison(comparison, null, Boolean(params?.mergeCoplanar));
    window.hullkitError = message;
    state.lastFailed = true;
    window.hullkitEpsilon = comparison ? publicComparison(comparison, null) : null;
    setState('error');
  }

  function setStats(values) {
    for (const [key, el] of Object.entries(ui.stat)) {
      el.textContent = values[key] ?? '—';
      el.title = '';
    }
  }

  return { showResult, showFailure };
}
