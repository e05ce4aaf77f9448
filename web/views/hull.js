// The Hull view: points in 3D (generated or pasted), their convex hull computed in the shared
// worker, drawn translucent with its edges and vertices; gift wrapping's seed epsilon compared
// with exact predicates.
//
// This module runs the jobs (request, progress, cancel, answer) and wires the view's parts: the
// panel's inputs and URL state (hull-panel.js), the cost estimate (hull-cost.js), the three.js
// scene (hull-scene.js), the report of a run (hull-report.js), files in and out (hull-files.js)
// and gift wrapping step by step (giftwrap-stepper.js).
//
// Test hooks: document.body.dataset.state is 'loading' | 'computing' | 'ready' | 'error' |
// 'cancelled' while this view is shown, window.hullkitStats describes the last hull drawn,
// window.hullkitError holds the message of the last failed run (else null) and
// window.hullkitEpsilon compares the last run with the seed's epsilon to exact predicates:
// {outcome: 'same' | 'different' | 'failed', epsilon, seed, exact} (null after an exact run).
import { fmtDuration } from '../app/format.js';
import { correctUrl } from '../app/url-state.js';
import { createGiftwrapStepper } from './giftwrap-stepper.js';
import { hullUi, createHullPanel, nToSlider, urlParamsOf, paramsKey, CUSTOM_SAMPLE } from './hull-panel.js';
import { SPHERE_WARN_N, needsConfirmation, createCostModel } from './hull-cost.js';
import { createHullScene } from './hull-scene.js';
import { centredPositions } from '../positions.js';
import { createHullReport } from './hull-report.js';
import { createHullFiles, exportName } from './hull-files.js';

/**
 * Creates the view over the shared `stage` (renderer) and `worker` (WorkerClient); `setState`
 * publishes its state on <body data-state> while it is the view shown.
 */
export function createHullView({ stage, worker, setState }) {
  const ui = hullUi();

  // What the view's parts share.
  const state = {
    active: false, // the view is shown
    job: null, // { params, t0, estMs, timer, freshWorker }
    runCount: 0,
    lastFailed: false, // the last run failed (its URL is still worth a history entry)
    pendingConfirmKey: null,
    preferredAlgorithm: null, // from the URL, applied once the worker lists the algorithms
    fileInput: null, // {name, xyz}: the points of the last file opened
    lastHull: null, // {xyz, triangles, dimension, name}: what the export buttons write
  };
  let started = false; // the first computation has been requested

  const panel = createHullPanel({ ui, state });
  const { readParams, writeParams, updateEpsilonField, paramsFromUrl, paramsToUrl, describeInput, setAlgorithms, showWarning, hideWarning, hideError } = panel;
  const { estimateMs, calibrate } = createCostModel();
  const scene = createHullScene({ stage, ui, state });
  const { requestRender, render, resize, controls } = scene;

  // ---------------------------------------------------------------- worker

  function startJob(params, estMs) {
    hideWarning();
    hideError();
    ui.compare.hidden = true;
    const current = { params, t0: performance.now(), estMs, timer: 0, freshWorker: !worker.warm };
    state.job = current;
    setState('computing');
    ui.compute.disabled = true;
    ui.cancel.disabled = false;
    updateProgress();
    state.job.timer = setInterval(updateProgress, 200);
    paramsToUrl(params);
    const request = { type: 'compute', ...params };
    if (params.distribution === 'file') request.xyz = state.fileInput.xyz.slice();
    worker.request(request).then(
      (msg) => { if (state.job === current) onAnswer(msg); },
      (err) => {
        if (state.job !== current || err.cancelled) return; // cancelJob has said so already
        finishJob();
        report.showFailure(err.message, null);
      },
    );
  }

  function updateProgress() {
    const { job } = state;
    if (!job) return;
    const elapsed = performance.now() - job.t0;
    let text = `Computing the hull of ${describeInput(job.params)}… ${(elapsed / 1000).toFixed(1)} s`;
    if (job.estMs > 2000) text += ` (estimate ≈ ${fmtDuration(job.estMs)})`;
    ui.status.textContent = text;
  }

  function finishJob() {
    if (!state.job) return null;
    clearInterval(state.job.timer);
    const done = state.job;
    state.job = null;
    ui.compute.disabled = false;
    ui.cancel.disabled = true;
    return done;
  }

  function onAnswer(msg) {
    const done = finishJob();
    const roundTripMs = performance.now() - done.t0;
    if (msg.type === 'result') {
      try {
        report.showResult(msg, done.params, roundTripMs, done.freshWorker);
      } catch (err) {
        const message = `Drawing the hull failed: ${err.message}`;
        console.error(`[hullkit] ${message}`, err);
        report.showFailure(message, null);
      }
    } else if (msg.type === 'error') {
      const prefix = msg.kind === 'input' ? 'Cannot compute the hull' : 'Hull computation failed';
      const message = `${prefix}: ${String(msg.message).replace(/^hull:\s*/, '')}`;
      if (msg.kind !== 'input') console.error(`[hullkit] ${message}`);
      report.showFailure(message, msg, done.params);
    }
  }

  /** The first hull, once the view is shown and the module has loaded (or failed to). */
  function startOnce() {
    if (started || !state.active) return;
    if (worker.loadError) {
      started = true;
      const message = `Hull computation failed: ${worker.loadError}`;
      console.error(`[hullkit] ${message}`);
      report.showFailure(message, null);
      return;
    }
    if (!worker.ready) return;
    started = true;
    requestCompute();
  }

  // ---------------------------------------------------------------- actions

  function requestCompute({ force = false } = {}) {
    if (state.job) return;
    const params = readParams();
    if (params.distribution !== 'custom') writeParams(params); // normalise what the user typed
    const estMs = estimateMs(params);
    if (!force && state.pendingConfirmKey !== paramsKey(params) && needsConfirmation(params, estMs)) {
      showWarning(params, estMs);
      return;
    }
    startJob(params, estMs);
  }

  function cancelJob() {
    if (!state.job) return;
    worker.restart(); // the wasm call cannot be interrupted: drop the whole worker
    const done = finishJob();
    ui.status.textContent = `Cancelled after ${((performance.now() - done.t0) / 1000).toFixed(1)} s; worker restarted.`;
    setState('cancelled');
  }

  ui.form.addEventListener('submit', (event) => {
    event.preventDefault();
    requestCompute();
  });
  ui.useCap.addEventListener('click', () => {
    ui.n.value = String(SPHERE_WARN_N);
    ui.nSlider.value = String(nToSlider(SPHERE_WARN_N));
    requestCompute({ force: true });
  });
  ui.useQuickhull.addEventListener('click', () => {
    ui.algorithm.value = 'quickhull';
    updateEpsilonField();
    requestCompute({ force: true });
  });
  ui.cancel.addEventListener('click', cancelJob);

  // ---------------------------------------------------------------- files in and out

  const files = createHullFiles({
    ui, state, worker, setState, hideWarning, hideError, updateSourceFields: panel.updateSourceFields, cancelJob, requestCompute,
  });

  // ---------------------------------------------------------------- gift wrapping, step by step

  const stepper = createGiftwrapStepper({
    worker, requestRender,
    targets: (xyz) => [{ scene: scene.scene, positions: centredPositions(xyz).positions }],
    request: (xyz, scan) => ({ type: 'trace', xyz, scan }),
    hideResult: (hidden) => { scene.content.visible = !hidden; requestRender(); },
  });

  // ---------------------------------------------------------------- the report of a run

  const report = createHullReport({
    ui, state, scene, setState, calibrate, describeInput, exportName, setExportEnabled: files.setExportEnabled, stepper,
  });

  panel.listen({ requestCompute, scene });

  // ---------------------------------------------------------------- start

  ui.customPoints.value = CUSTOM_SAMPLE;
  writeParams(paramsFromUrl(new URLSearchParams(location.search)));
  updateEpsilonField();
  worker.on('ready', (info) => { setAlgorithms(info.algorithms); startOnce(); });
  worker.on('load-error', () => startOnce());
  if (worker.info) setAlgorithms(worker.info.algorithms);
  scene.warmUpShaders();

  return {
    name: 'hull',
    render,
    resize,
    /** Shown: take the controls and draw; the first hull starts here. */
    activate() {
      state.active = true;
      controls.enabled = true;
      startOnce();
      requestRender();
    },
    deactivate() {
      state.active = false;
      controls.enabled = false;
    },
    /** The URL changed (back/forward): show its parameters and recompute when they differ. */
    applyUrl(q) {
      const before = paramsKey(readParams());
      const fromUrl = paramsFromUrl(q);
      writeParams(fromUrl);
      correctUrl({ n: fromUrl.n, seed: fromUrl.seed }); // out-of-range values, made valid
      updateEpsilonField();
      if (state.preferredAlgorithm && [...ui.algorithm.options].some((o) => o.value === state.preferredAlgorithm)) {
        ui.algorithm.value = state.preferredAlgorithm;
        updateEpsilonField();
      }
      if (started && paramsKey(readParams()) !== before && !state.job) startJob(readParams(), 0);
    },
    /** The view's options for the URL when it is switched to. */
    urlParams() {
      return urlParamsOf(readParams());
    },
    openFile: files.openFile,
    fileHint: 'points from OBJ, OFF, PLY, STL, glTF or x y z text',
    busyLabel: () => (state.job ? `Computing the hull of ${describeInput(state.job.params)}` : 'Working'),
    cancel() {
      if (state.job) cancelJob();
      else stepper.cancel();
    },
  };
}
