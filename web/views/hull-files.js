// The Hull view's files in and out: a file opened (or dropped) is read with the C++ point readers
// in the worker and its points hulled; the export buttons write the last hull drawn as OBJ, OFF,
// glTF (.glb) or binary STL.
import { readInWorker, chooseFileOption } from '../app/panel.js';
import { compact, objText, offText, stlBytes, glbBytes, download } from '../app/export.js';

/** The name (without extension) of the files exported for the hull of `params`. */
export function exportName(params) {
  if (params.distribution === 'file') return `${params.file.replace(/\.[^.]*$/, '')}-hull`;
  if (params.distribution === 'custom') return 'pasted-hull';
  return `hull-${params.distribution}-${params.n}-seed${params.seed}`;
}

/**
 * Files in and out over the elements `ui`: openFile keeps the points in `state.fileInput` (after
 * `cancelJob` when a run is going) and asks `requestCompute`; the export buttons write
 * `state.lastHull`.
 */
export function createHullFiles({ ui, state, worker, setState, hideWarning, hideError, updateSourceFields, cancelJob, requestCompute }) {
  /** Reads `file` with the C++ point readers (in the worker) and hulls its points. */
  async function openFile(file) {
    if (state.job) cancelJob();
    hideWarning();
    hideError();
    ui.status.textContent = `Reading ${file.name}…`;
    const msg = await readInWorker(worker, file, 'points');
    if (msg.cancelled) return;
    if (msg.error) {
      showFileError(msg.error);
      return;
    }
    state.fileInput = { name: file.name, xyz: msg.xyz };
    chooseFileOption(ui.distribution, file.name);
    updateSourceFields();
    requestCompute();
  }

  /** A file that cannot be read: say why; the drawing and the inputs stay as they were. */
  function showFileError(message) {
    ui.error.textContent = message;
    ui.error.hidden = false;
    ui.status.textContent = '';
    window.hullkitError = message;
    setState('error');
  }

  const exportButtons = [...document.querySelectorAll('[data-export]')];
  function setExportEnabled(on) {
    for (const b of exportButtons) b.disabled = !on;
  }
  for (const button of exportButtons) {
    button.addEventListener('click', () => {
      const { lastHull } = state;
      if (!lastHull) return;
      const mesh = compact(lastHull.xyz, lastHull.triangles, 3);
      const note = `convex hull by hullkit: ${mesh.positions.length / 3} vertices, ${mesh.triangles.length / 3} triangles, outward`;
      const format = button.dataset.export;
      if (format === 'obj') download(`${lastHull.name}.obj`, objText(mesh, note), 'model/obj');
      else if (format === 'off') download(`${lastHull.name}.off`, offText(mesh, note), 'text/plain');
      else if (format === 'glb') download(`${lastHull.name}.glb`, glbBytes(mesh), 'model/gltf-binary');
      else download(`${lastHull.name}.stl`, stlBytes(mesh, note), 'model/stl');
    });
  }

  return { openFile, setExportEnabled };
}
