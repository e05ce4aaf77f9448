// The Route view's files in and out: a mesh opened (or dropped) is read with the C++ mesh readers
// in the worker and becomes another obstacle or the traverse; the export buttons write the last
// report and the scene with the current route (waypoints with their rotations) as JSON.
import { readFileForView } from '../app/panel.js';
import { download } from '../app/export.js';
import { copyRoute } from '../route-poses.js';

/**
 * Wires the export buttons of `ui` to `state` (report, sceneJson, route, preset; `margin()` the
 * margin asked for) and returns openFile(file): `fail(message)` when it cannot be used, else the
 * scene changed (state.sceneJson, state.fileNote) and `sceneChanged()`.
 */
export function createRouteFiles({ ui, state, worker, margin, fail, sceneChanged }) {
  ui.exports.report.addEventListener('click', () => {
    if (state.report) download(`route-report-${state.preset}.json`, `${JSON.stringify(state.report, null, 2)}\n`, 'application/json');
  });
  ui.exports.scene.addEventListener('click', () => {
    const out = { ...state.sceneJson, route: copyRoute(state.route), margin: margin() };
    download(`route-scene-${state.preset}.json`, `${JSON.stringify(out)}\n`, 'application/json');
  });

  /** Reads a mesh file with the C++ mesh readers (in the worker): an obstacle or the traverse. */
  return async function openFile(file) {
    const msg = await readFileForView(worker, file, 'mesh', { ui, onError: (message) => fail(message, false) });
    if (!msg) return;
    const vertices = [];
    for (let i = 0; i < msg.vertices.length; i += 3) vertices.push([msg.vertices[i], msg.vertices[i + 1], msg.vertices[i + 2]]);
    const triangles = [];
    for (let t = 0; t < msg.triangles.length; t += 3) triangles.push([msg.triangles[t], msg.triangles[t + 1], msg.triangles[t + 2]]);
    if (!triangles.length) {
      fail(`Cannot use ${file.name}: it has no triangles (a traverse or an obstacle is a triangle mesh).`, false);
      return;
    }
    const part = { name: file.name, vertices, triangles };
    if (ui.fileRole.value === 'traverse') {
      // A new traverse turns about its own origin: the preset's pivot was for its parts.
      state.sceneJson = { ...state.sceneJson, traverse: { parts: [part] } };
      state.fileNote += `Traverse: ${file.name} (${triangles.length} triangles). `;
    } else {
      state.sceneJson = { ...state.sceneJson, obstacles: [...state.sceneJson.obstacles, part] };
      state.fileNote += `Obstacle added: ${file.name} (${triangles.length} triangles). `;
    }
    sceneChanged();
  };
}
