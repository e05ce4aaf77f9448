// The Delaunay view's files in and out: a file opened (or dropped) is read with the C++ 2D point
// reader in the worker and its points triangulated, or, for a GeoJSON or Triangle .poly file, read
// as a polygon (polygons.js, in the worker) and handed to the constrained modes; the export
// buttons write the last triangulation drawn as OFF (z = 0) or SVG (with the Voronoi cells when shown).
import { fmtInt } from '../app/format.js';
import { showError, readFileForView, chooseFileOption } from '../app/panel.js';
import { compact, offText, triangulationSvg, download } from '../app/export.js';

const FILE_MAX = 200_000; // points of an opened file the page draws (the CLI takes any number)

/** Files the constrained modes take: GeoJSON polygons and Triangle's planar graphs. */
export const isPolygonFile = (name) => /\.(geojson|json|poly)$/i.test(name);

/**
 * Files in and out over the elements `ui`: openFile keeps the points in `state.fileInput`, clears
 * `state.added` and asks `compute` (after `beforePoints()`, which leaves a constrained mode), or
 * hands a polygon file's polygon to `onPolygon(name, polygon)`; the export buttons write
 * `state.lastExport`.
 */
export function createDelaunayFiles({ ui, state, worker, setState, updateHint, compute, onPolygon, beforePoints }) {
  const exportButtons = [...document.querySelectorAll('[data-dl-export]')];
  for (const button of exportButtons) {
    button.addEventListener('click', () => {
      if (!state.lastExport) return;
      const { xy: pts, triangles, hull, cells: vcells, name, title = 'Delaunay triangulation' } = state.lastExport;
      if (button.dataset.dlExport === 'off') {
        const mesh = compact(pts, triangles, 2);
        download(`${name}.off`, offText(mesh, `${title} by hullkit, z = 0, ${triangles.length / 3} triangles`), 'text/plain');
      } else {
        const svg = triangulationSvg({ xy: pts, triangles, hull, title, cells: vcells ? { offsets: vcells.cellOffsets, xy: vcells.cellXY } : null });
        download(`${name}.svg`, svg, 'image/svg+xml');
      }
    });
  }

  /** Reads `file` with the C++ 2D point reader (in the worker) and triangulates its points. */
  async function openFile(file) {
    if (isPolygonFile(file.name) && onPolygon) {
      const read = await readFileForView(worker, file, 'polygon', { ui, onError: fileError });
      if (read) onPolygon(file.name, read.polygon);
      return;
    }
    const msg = await readFileForView(worker, file, 'points2d', { ui, onError: fileError });
    if (!msg) return;
    const count = msg.xy.length / 2;
    if (count > FILE_MAX) {
      fileError(`${file.name} has ${fmtInt(count)} points; this page draws at most ${fmtInt(FILE_MAX)} (the hullkit command and hullkit.delaunay take any number).`);
      return;
    }
    beforePoints?.();
    state.fileInput = { name: file.name, xy: msg.xy };
    chooseFileOption(ui.set, file.name);
    ui.n.value = String(count);
    state.added = [];
    updateHint();
    state.framed = false;
    compute({ force: true });
  }

  /** A file that cannot be read: say why; the drawing stays as it was. */
  function fileError(message) {
    showError(ui.error, message, false);
    ui.status.textContent = '';
    setState('error');
  }

  return { exportButtons, openFile };
}
