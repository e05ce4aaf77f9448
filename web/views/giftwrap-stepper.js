// Gift wrapping, step by step: the seed's steps 1–4 replayed from the trace the C++ core records
// while it wraps (hullkit.giftwrapTrace, in the worker), not from a JavaScript re-implementation.
//
// The Hull view offers it for three-dimensional hulls of at most STEP_MAX points; the Delaunay
// view for the wrap of the lifted points (hullkit.delaunayGiftwrapTrace), drawn on the paraboloid
// and, projected, in the plane. The trace is a
// list of events (kind + three arguments); the picture at step k is the replay of events 0..k:
// the first point and first edge, the stack of open edges, the edge being wrapped, the candidate
// triangle with the point that just replaced it (the one-pass rule) or the literal restart, and
// the triangles accepted so far. Step back replays from the start (traces are small).
//
// Test hook: window[hook] (hullkitStepper, hullkitLiftStepper) = {step, events, accepted:
// [[a, b, c], ...], done, scan, oneShot} after every step shown (null when the stepper is closed).
import * as THREE from 'three';
import { discTexture, clearGroup } from '../app/stage.js';
import { fmtInt } from '../app/format.js';

export const STEP_MAX = 300;
const SPEEDS = [1, 2, 4, 8, 16, 32, 64, 256]; // steps per second
const COLORS = { point: 0x8a96ab, edge: 0xff4f8b, stack: 0xffb547, candidate: 0xff4f8b, done: 0x3fb8c9, replaced: 0xffffff, first: 0xffe066 };

/**
 * The replayed state after `count` events: {accepted, stack, edge, candidate, replaced, first,
 * firstEdge, restarts, last} (last: the last event applied, {kind, a, b, c}). Exported for tests.
 */
export function replay(trace, count) {
  const state = { accepted: [], stack: [], edge: null, candidate: null, replaced: null, first: null, firstEdge: null, restarts: 0, last: null, skipped: null };
  const names = trace.kindNames;
  for (let e = 0; e < count; e++) {
    const kind = names[trace.kinds[e]];
    const a = trace.args[3 * e], b = trace.args[3 * e + 1], c = trace.args[3 * e + 2];
    state.last = { kind, a, b, c };
    state.replaced = null;
    state.skipped = null;
    switch (kind) {
      case 'first_point': state.first = a; break;
      case 'first_edge': state.firstEdge = [a, b]; break;
      case 'push_edge': state.stack.push([a, b]); break;
      case 'pop_edge': {
        // The edge being wrapped: taken off the stack (the top, as the core pops it).
        const at = state.stack.findLastIndex(([p, q]) => p === a && q === b);
        if (at >= 0) state.stack.splice(at, 1);
        state.edge = [a, b];
        state.candidate = null;
        break;
      }
      case 'skip_edge': {
        const at = state.stack.findLastIndex(([p, q]) => p === a && q === b);
        if (at >= 0) state.stack.splice(at, 1);
        state.skipped = [a, b];
        state.edge = null;
        state.candidate = null;
        break;
      }
      case 'wrap_first': state.edge = [a, b]; state.candidate = null; break;
      case 'vertical_face': state.candidate = [a, b, c]; break;
      case 'coplanar': state.replaced = c; break;
      case 'candidate': state.candidate = [a, b, c]; break;
      case 'replace': state.candidate = [a, b, c]; state.replaced = c; break;
      case 'restart': state.restarts++; state.replaced = c; break;
      case 'accept': state.accepted.push([a, b, c]); state.candidate = null; state.edge = null; break;
      default: break; // 'done' and kinds this page does not draw
    }
  }
  return state;
}

/** The current step in words (the seed's step numbers in brackets). */
function describe(state, step, total, lifted) {
  const last = state.last;
  if (lifted && last) {
    const p = (i) => `p${i}`;
    switch (last.kind) {
      case 'first_point': return `Step 1: ${p(last.a)}, the lowest point in (x, y) order, is a hull vertex of the lifted points.`;
      case 'replace': return `${p(last.c)} lies strictly inside the candidate's circle — its lift is below the lifted plane — so it replaces the third corner.`;
      case 'coplanar': return `${p(last.c)} lies exactly on the candidate's circle (an exact in-circle test): it joins the face if the candidate stands.`;
      case 'accept': return `No point inside the circle of ${p(last.a)} ${p(last.b)} ${p(last.c)}: a lower face of the lifted hull, projected, a Delaunay triangle (${fmtInt(state.accepted.length)} so far).`;
      case 'pop_edge': return `Wrap edge ${p(last.a)}–${p(last.b)}: find the point whose circle with it holds no other point.`;
      default: break;
    }
  }
  if (!last) return 'Press Step or Play: gift wrapping starts from the lowest point.';
  const p = (i) => `p${i}`;
  switch (last.kind) {
    case 'first_point': return `Step 1: ${p(last.a)} has the largest x (ties broken by y, then z), so it is surely a hull vertex.`;
    case 'first_edge': return `Step 2: the first edge ${p(last.a)}–${p(last.b)}: every other point lies on one side of a plane through it, so it is a hull edge.`;
    case 'push_edge': return `Edge ${p(last.a)}–${p(last.b)} goes on the stack: the face on its other side is still to be found (${state.stack.length} open).`;
    case 'pop_edge': return `Step 3: wrap edge ${p(last.a)}–${p(last.b)}: look for the point whose triangle with it has every other point on its inner side.`;
    case 'wrap_first': return `The first face: a plane through ${p(last.a)}–${p(last.b)} is turned until it rests on a third point.`;
    case 'vertical_face': return `The vertical plane through ${p(last.a)}, ${p(last.b)} and ${p(last.c)} already has every point on one side: the first face lies in it.`;
    case 'coplanar': return `${p(last.c)} lies exactly on the candidate's plane (an exact test): it joins the face if the candidate stands.`;
    case 'skip_edge': return `Edge ${p(last.a)}–${p(last.b)} already has both its faces: nothing to wrap.`;
    case 'candidate': return `Candidate triangle ${p(last.a)} ${p(last.b)} ${p(last.c)}: now test every other point against its plane.`;
    case 'replace': return `Step 4: ${p(last.c)} lies above the candidate's plane, so it replaces the third corner (one pass: keep scanning with the new candidate).`;
    case 'restart': return `Step 4, literally: ${p(last.c)} lies above the candidate's plane, so it becomes the new candidate and the scan restarts from the first point.`;
    case 'accept': return `No point lies above ${p(last.a)} ${p(last.b)} ${p(last.c)}: it is a hull face (${fmtInt(state.accepted.length)} so far); its new edges go on the stack.`;
    case 'done': return `Done: the stack is empty and the hull is closed, ${fmtInt(state.accepted.length)} triangles.`;
    default: return `${last.kind} (${step} of ${total})`;
  }
}

/**
 * `prefix` names the elements (PREFIX-start, PREFIX-play, ...); `targets(coords)` gives the
 * scenes to draw in with the points' positions there ([{scene, positions: Float32Array}]);
 * `request(coords, scan)` the worker message; `hideResult(hidden)` hides the one-shot drawing.
 */
/** Adds the playback controls, the step text and the legend to the stepper's section. */
function addControls(section, prefix) {
  const id = (name) => `${prefix}-${name}`;
  const button = (name, text, title = '', cls = 'ghost small') => `<button id="${id(name)}" type="button" class="${cls}"${title ? ` title="${title}"` : ''}>${text}</button>`;
  section.insertAdjacentHTML('beforeend', `
    <div id="${id('controls')}" hidden>
      <div class="step-buttons">
        ${button('back', '◀ Back', 'Step back (←)')} ${button('play', 'Play', '', 'small')}
        ${button('next', 'Step ▶', 'Step (→)')} ${button('end', 'End')} ${button('exit', 'Close')}
      </div>
      <div class="step-sliders">
        <label for="${id('speed')}">speed</label>
        <input id="${id('speed')}" type="range" min="0" max="7" step="1" value="4" aria-label="Speed in steps per second">
        <label for="${id('pos')}">position</label>
        <input id="${id('pos')}" type="range" min="0" max="0" step="1" value="0" aria-label="Position in the recorded gift wrap">
      </div>
      <p id="${id('count')}" class="step-count"></p>
      <ul class="step-legend">
        <li><span class="swatch wrap-edge"></span>edge being wrapped</li>
        <li><span class="swatch wrap-stack"></span>open edges (stack)</li>
        <li><span class="swatch wrap-candidate"></span>candidate</li>
        <li><span class="swatch wrap-replaced"></span>point that replaced it</li>
        <li><span class="swatch wrap-done"></span>accepted faces</li>
      </ul>
    </div>
    <p id="${id('text')}" class="step-text" aria-live="polite"></p>
    <p id="${id('error')}" class="error" hidden role="alert"></p>`);
}

export function createGiftwrapStepper({ worker, requestRender, targets, request, hideResult, prefix = 'step', hook = 'hullkitStepper', lifted = false, limit = STEP_MAX }) {
  const $ = (id) => document.getElementById(`${prefix}-${id}`);
  addControls(document.getElementById(prefix === 'step' ? 'stepper' : `${prefix}per`), prefix);
  const ui = {
    section: document.getElementById(prefix === 'step' ? 'stepper' : `${prefix}per`),
    start: $('start'),
    scan: $('scan'),
    controls: $('controls'),
    back: $('back'),
    play: $('play'),
    next: $('next'),
    end: $('end'),
    exit: $('exit'),
    speed: $('speed'),
    pos: $('pos'),
    text: $('text'),
    count: $('count'),
    error: $('error'),
  };

  let drawIn = []; // [{group, positions}]
  const disc = discTexture();
  const mat = {
    point: new THREE.PointsMaterial({ color: COLORS.point, size: 5, sizeAttenuation: false, map: disc, alphaTest: 0.5 }),
    first: new THREE.PointsMaterial({ color: COLORS.first, size: 12, sizeAttenuation: false, map: disc, alphaTest: 0.5, depthTest: false }),
    replaced: new THREE.PointsMaterial({ color: COLORS.replaced, size: 11, sizeAttenuation: false, map: disc, alphaTest: 0.5, depthTest: false }),
    done: new THREE.MeshStandardMaterial({ color: COLORS.done, transparent: true, opacity: 0.45, side: THREE.DoubleSide, flatShading: true, depthWrite: false }),
    doneEdge: new THREE.LineBasicMaterial({ color: 0xa6eef8, transparent: true, opacity: 0.8 }),
    candidate: new THREE.MeshBasicMaterial({ color: COLORS.candidate, transparent: true, opacity: 0.35, side: THREE.DoubleSide, depthWrite: false }),
    stack: new THREE.LineBasicMaterial({ color: COLORS.stack, depthTest: false }),
    edge: new THREE.LineBasicMaterial({ color: COLORS.edge, depthTest: false }),
  };

  let offered = null; // {coords, n}: the points of the last result, when small enough
  let trace = null; // {kinds, args, kindNames, triangles}
  let step = 0;
  let timer = 0;
  let pending = 0; // request sequence
  let open = false;

  function setButtons() {
    const total = trace ? trace.kinds.length : 0;
    ui.back.disabled = step <= 0;
    ui.next.disabled = step >= total;
    ui.end.disabled = step >= total;
    ui.play.textContent = timer ? 'Pause' : 'Play';
    ui.play.disabled = step >= total && !timer;
  }

  /**
   * The view drew a new result: offer stepping through it when `coords` (flat coordinates of `n`
   * points) is small enough and `eligible`; `why` says otherwise.
   */
  function offer({ coords = null, n = 0, eligible = false, why = '' } = {}) {
    close();
    offered = eligible && coords && n <= limit ? { coords: coords.slice(), n } : null;
    ui.section.hidden = false;
    ui.start.disabled = !offered;
    if (ui.scan) ui.scan.disabled = !offered;
    ui.text.textContent = offered
      ? `Replay how gift wrapping finds ${lifted ? 'the lifted points\' lower hull' : 'these points\' hull'} (${fmtInt(offered.n)} points), one event at a time.`
      : why || `Available for at most ${limit} points.`;
    ui.count.textContent = '';
  }

  async function start() {
    if (!offered) return;
    const id = ++pending;
    ui.error.hidden = true;
    ui.start.disabled = true;
    ui.text.textContent = 'Recording the gift wrap…';
    let msg;
    try {
      msg = await worker.request(request(offered.coords.slice(), ui.scan?.value));
    } catch (err) {
      if (id === pending && !err.cancelled) fail(err.message);
      return;
    } finally {
      ui.start.disabled = !offered;
    }
    if (id !== pending) return;
    if (msg.type !== 'result') {
      fail(msg.message);
      return;
    }
    trace = msg;
    drawIn = targets(offered.coords).map(({ scene, positions }) => {
      const group = new THREE.Group();
      scene.add(group);
      return { group, positions };
    });
    open = true;
    ui.controls.hidden = false;
    ui.pos.max = String(trace.kinds.length);
    hideResult(true);
    show(0);
    play();
  }

  function fail(message) {
    ui.error.textContent = `Cannot step through gift wrapping: ${message}`;
    ui.error.hidden = false;
    ui.text.textContent = '';
  }

  function close() {
    pause();
    pending++;
    if (open) hideResult(false);
    open = false;
    trace = null;
    for (const { group } of drawIn) {
      clearGroup(group);
      group.removeFromParent();
    }
    drawIn = [];
    ui.controls.hidden = true;
    window[hook] = null;
    requestRender();
  }

  function cancel() {
    if (pending && !trace) {
      worker.restart();
      pending++;
      ui.text.textContent = 'Cancelled.';
    }
  }

  let positions = null; // the target being drawn
  function lineGeometry(pairs) {
    const pos = new Float32Array(6 * pairs.length);
    pairs.forEach(([a, b], i) => {
      pos.set(positions.subarray(3 * a, 3 * a + 3), 6 * i);
      pos.set(positions.subarray(3 * b, 3 * b + 3), 6 * i + 3);
    });
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(pos, 3));
    return g;
  }

  function pointGeometry(indices) {
    const pos = new Float32Array(3 * indices.length);
    indices.forEach((i, k) => pos.set(positions.subarray(3 * i, 3 * i + 3), 3 * k));
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(pos, 3));
    return g;
  }

  function triangleGeometry(tris) {
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    g.setIndex(tris.flat());
    return g;
  }

  let group = null; // the target's group being drawn
  function add(obj, order) {
    obj.renderOrder = order;
    obj.frustumCulled = false;
    group.add(obj);
  }

  function show(k) {
    const total = trace.kinds.length;
    step = Math.max(0, Math.min(total, k));
    const state = replay(trace, step);
    for (const target of drawIn) {
      group = target.group;
      positions = target.positions;
      drawState(state);
    }
    ui.text.textContent = describe(state, step, total, lifted);
    ui.count.textContent = `event ${fmtInt(step)} of ${fmtInt(total)} · ${fmtInt(state.accepted.length)} triangles · ${fmtInt(state.stack.length)} open edges` +
      (state.restarts ? ` · ${fmtInt(state.restarts)} restarts` : '');
    ui.pos.value = String(step);
    setButtons();
    window[hook] = {
      step, events: total, accepted: state.accepted.map((t) => [...t]), done: step >= total,
      scan: ui.scan?.value ?? null, oneShot: Array.from(trace.triangles),
    };
    requestRender();
  }

  function drawState(state) {
    clearGroup(group);
    const all = new THREE.BufferGeometry();
    all.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    add(new THREE.Points(all, mat.point), 0);
    if (state.accepted.length) {
      const g = triangleGeometry(state.accepted);
      add(new THREE.Mesh(g, mat.done), 1);
      add(new THREE.LineSegments(lineGeometry(state.accepted.flatMap(([a, b, c]) => [[a, b], [b, c], [c, a]])), mat.doneEdge), 2);
    }
    if (state.candidate) add(new THREE.Mesh(triangleGeometry([state.candidate]), mat.candidate), 3);
    if (state.stack.length) add(new THREE.LineSegments(lineGeometry(state.stack), mat.stack), 4);
    const current = state.edge ?? (state.accepted.length === 0 ? state.firstEdge : null);
    if (current) add(new THREE.LineSegments(lineGeometry([current]), mat.edge), 5);
    if (state.first !== null) add(new THREE.Points(pointGeometry([state.first]), mat.first), 6);
    if (state.replaced !== null) add(new THREE.Points(pointGeometry([state.replaced]), mat.replaced), 7);
  }

  function play() {
    if (timer || !trace) return;
    if (step >= trace.kinds.length) show(0);
    const tick = () => {
      if (!trace || step >= trace.kinds.length) {
        pause();
        return;
      }
      show(step + 1);
    };
    timer = setInterval(tick, 1000 / SPEEDS[Number(ui.speed.value)]);
    setButtons();
  }

  function pause() {
    clearInterval(timer);
    timer = 0;
    if (trace) setButtons();
  }

  ui.start.addEventListener('click', start);
  ui.play.addEventListener('click', () => (timer ? pause() : play()));
  ui.next.addEventListener('click', () => { pause(); show(step + 1); });
  ui.back.addEventListener('click', () => { pause(); show(step - 1); });
  ui.end.addEventListener('click', () => { pause(); show(trace.kinds.length); });
  ui.exit.addEventListener('click', () => {
    const again = offered;
    close();
    offer(again ? { coords: again.coords, n: again.n, eligible: true } : {});
  });
  ui.pos.addEventListener('input', () => { pause(); show(Number(ui.pos.value)); });
  ui.speed.addEventListener('input', () => {
    if (timer) { pause(); play(); }
  });
  // The candidate rule's short label, and its whole description as the select's tooltip.
  if (ui.scan) {
    const describeRule = () => { ui.scan.title = ui.scan.selectedOptions[0]?.title ?? ''; };
    describeRule();
    ui.scan.addEventListener('change', describeRule);
  }
  // Arrow keys step while the stepper's controls have focus.
  ui.controls.addEventListener('keydown', (event) => {
    if (!trace || event.target === ui.pos) return;
    if (event.key === 'ArrowRight') { pause(); show(step + 1); event.preventDefault(); }
    if (event.key === 'ArrowLeft') { pause(); show(step - 1); event.preventDefault(); }
  });

  return { offer, cancel, close };
}
