// The Delaunay view's files in and out: a file opened (or dropped) is read with the C++ 2D point
// reader in the worker and its points triangulated; the export buttons write the last
// triangulation drawn as OFF (z = 0) or SVG (with the Voronoi cells when shown).
import { fmtInt } from '../app/format.js';
import { showError, readFileForView, chooseFileOption } from '../app/panel.js';
import { compact, offText, triangulationSvg, download } from '../app/export.js';

const FILE_MAX = 200_000; // points of an opened file the page draws (the CLI takes any number)

/**
 * Files in and out over the elements `ui`: openFile keeps the points in `state.fileInput`, clears
 * `state.added` and asks `compute`; the export buttons write `state.lastExport`.
 */
export function createDelaunayFiles({ ui, state, worker, setState, updateHint, compute }) {
  const exportButtons = [...document.querySelectorAll('[data-dl-export]')];
  for (const button of exportButtons) {
    button.addEventListener('click', () => {
      if (!state.lastExport) return;
      const { xy: pts, triangles, hull, cells: vcells, name } = state.lastExport;
      if (button.dataset.dlExport === 'off') {
        const mesh = compact(pts, triangles, 2);
        download(`${name}.off`, offText(mesh, `Delaunay triangulation by hullkit, z = 0, ${triangles.length / 3} triangles`), 'text/plain');
      } else {
        const svg = triangulationSvg({ xy: pts, triangles, hull, cells: vcells ? { offsets: vcells.cellOffsets, xy: vcells.cellXY } : null });
        download(`${name}.svg`, svg, 'image/svg+xml');
      }
    });
  }

  /** Reads `file` with the C++ 2D point reader (in the worker) and triangulates its points. */
  async function openFile(file) {
    const msg = await readFileForView(worker, file, 'points2d', { ui, onError: fileError });
    if (!msg) return;
    const count = msg.xy.length / 2;
    if (count > FILE_MAX) {
      fileError(`${file.name} has ${fmtInt(count)} points; this page draws at most ${fmtInt(FILE_MAX)} (the hullkit command and hullkit.delaunay take any number).`);
      return;
    }
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
