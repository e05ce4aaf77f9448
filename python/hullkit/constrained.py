"""Constrained Delaunay triangulation from Python: polygons with holes (earcut's arguments, as
``hullkit.triangulatePolygon`` in JS) and Triangle's dictionary and switches (``hullkit.triangulate``,
for users of the ``triangle`` package). Exact: see native/include/hullkit/constrained.hpp."""

import numpy as _np

from . import _core
from . import HullkitError, _translated, as_points

__all__ = ["triangulate", "triangulate_polygon"]

# Triangle's switches hullkit honours, and those it does not have yet (with what they are).
_SWITCHES = {"p": "segments", "c": "convex", "z": "zero-based", "n": "neighbors", "e": "edges", "Q": "quiet", "V": "verbose"}
_NOT_YET = {
    "q": "quality meshing (minimum angle)", "a": "maximum triangle area", "u": "user refinement test", "r": "refining a mesh",
    "D": "conforming Delaunay", "Y": "no Steiner points on the boundary", "S": "a Steiner point limit", "A": "regional attributes",
    "o": "second-order triangles", "i": "incremental insertion", "F": "Fortune's sweep", "l": "vertical cuts only", "s": "segment splitting",
    "C": "consistency checks", "j": "jettisoning vertices", "B": "no boundary markers", "P": "no .poly output", "N": "no .node output",
    "E": "no .ele output", "I": "no iteration numbers", "O": "ignoring holes", "X": "no exact arithmetic",
}
_KEYS = ("vertices", "segments", "holes")


def _run(points, segments, starts, fill, convex, holes):
    with _translated():
        return _core.constrained(points, segments, starts, fill, convex, holes)


def triangulate_polygon(coords, hole_indices=None, fill="evenodd"):
    """The triangles inside polygons with holes, earcut's way: ``coords`` the vertices (shape (n, 2),
    or flat x y x y ...), ``hole_indices`` the vertex index at which each hole (each ring after the
    first) starts. Rings open or closed, any orientation, nesting, touching or crossing; ``fill``
    'evenodd' (default) or 'nonzero'. A dict: ``coords`` (the input vertices then the crossing points
    added, (m, 2)), ``triangles`` ((t, 3), clockwise with y up as hullkit.delaunay's), ``halfedges``,
    ``constrained`` (per half-edge, 1 on a ring edge), ``representative``, ``crossing_count``."""
    array = _np.asarray(coords, dtype=_np.float64)
    if array.ndim == 1:
        if array.size % 2:
            raise HullkitError(f"flat coords must hold x y pairs, got {array.size} numbers")
        array = array.reshape(-1, 2)
    points = as_points(array, 2, "coords")
    starts = _np.ascontiguousarray([] if hole_indices is None else hole_indices, dtype=_np.int64).ravel()
    if starts.size and (starts.min() < 0 or starts.max() > len(points) or _np.any(_np.diff(starts) < 0)):
        raise HullkitError(f"hole_indices must be increasing vertex indices from 0 to {len(points)}, got {starts.tolist()}")
    if fill not in ("evenodd", "nonzero"):
        raise HullkitError(f"fill must be 'evenodd' or 'nonzero', got {fill!r}")
    coords_out, triangles, halfedges, constrained, representative, crossings = _run(
        points, _np.zeros(0, _np.uint32), starts.astype(_np.uint32), fill, False, _np.zeros((0, 2)))
    return {"coords": coords_out, "triangles": triangles, "halfedges": halfedges, "constrained": constrained,
            "representative": representative, "crossing_count": crossings}


def _switches(opts):
    if not isinstance(opts, str):
        raise HullkitError(f"opts must be a string of Triangle's switches, got {opts!r}")
    found = set()
    for i, c in enumerate(opts):
        if c in _SWITCHES:
            found.add(c)
        elif c in _NOT_YET:
            raise HullkitError(f"Triangle's switch '{c}' ({_NOT_YET[c]}) is not supported by hullkit yet")
        elif not (c.isdigit() or c == "."):
            raise HullkitError(f"unknown switch '{c}' at position {i} of opts {opts!r}")
        else:
            raise HullkitError(f"a number in opts {opts!r} belongs to a switch hullkit does not support yet")
    return found


def triangulate(tri, opts="", **options):
    """Triangle's ``triangulate(tri, opts)`` (the ``triangle`` package), exact. ``tri`` a dict with
    ``vertices`` (n, 2), optionally ``segments`` (m, 2) and ``holes`` (h, 2) (points inside holes).
    Switches: ``p`` triangulate the planar straight-line graph (segments kept as edges, split where
    a vertex lies on them or another segment crosses; the exterior and the hole regions removed),
    ``c`` keep the whole convex hull, ``n`` also ``neighbors``, ``e`` also ``edges``; ``z``, ``Q``,
    ``V`` are accepted (indices are always zero-based). Without ``p`` the vertices' Delaunay
    triangulation. The keyword ``convex=True`` is ``c``. Returns a dict: ``vertices`` (input
    vertices then the crossing points added), ``triangles`` (t, 3) counter-clockwise as Triangle's,
    ``segments`` (the edges on segments, each once), and ``neighbors``/``edges`` when asked."""
    if not isinstance(tri, dict):
        raise HullkitError(f"tri must be a dict with 'vertices' (and 'segments', 'holes'), got {type(tri).__name__}")
    unknown = sorted(set(tri) - set(_KEYS))
    if unknown:
        raise HullkitError(f"tri key(s) {unknown} are not supported by hullkit yet (it takes {list(_KEYS)})")
    if "vertices" not in tri:
        raise HullkitError("tri needs 'vertices', shape (n, 2)")
    extra = set(options) - {"convex"}
    if extra:
        raise HullkitError(f"unknown keyword(s) {sorted(extra)} (known: convex)")
    switches = _switches(opts)
    convex = bool(options.get("convex", False)) or "c" in switches
    points = as_points(tri["vertices"], 2, "tri['vertices']")
    segments = _np.zeros((0, 2), _np.int64)
    holes = _np.zeros((0, 2))
    if "p" in switches:
        if "segments" in tri:
            segments = _np.ascontiguousarray(tri["segments"], dtype=_np.int64).reshape(-1, 2)
            if segments.size and (segments.min() < 0 or segments.max() >= len(points)):
                raise HullkitError(f"tri['segments'] must index the {len(points)} vertices")
        if "holes" in tri:
            holes = as_points(tri["holes"], 2, "tri['holes']")
    else:
        convex = True  # Triangle without p: the Delaunay triangulation of the vertices
    vertices, triangles, halfedges, constrained, _, _ = _run(
        points, segments.astype(_np.uint32).ravel(), None, "evenodd", convex, holes)
    out = {"vertices": vertices, "triangles": _np.ascontiguousarray(triangles[:, [0, 2, 1]])}
    flat = triangles.ravel()
    following = _np.arange(len(flat)).reshape(-1, 3)[:, [1, 2, 0]].ravel()
    once = (halfedges < _np.arange(len(flat))) | (halfedges < 0)  # each edge once
    on_segment = once & (constrained == 1)
    out["segments"] = _np.stack([flat[on_segment], flat[following[on_segment]]], axis=1).astype(_np.int32)
    if "e" in switches:
        out["edges"] = _np.stack([flat[once], flat[following[once]]], axis=1).astype(_np.int32)
    if "n" in switches:
        across = _np.where(halfedges < 0, -1, halfedges // 3).reshape(-1, 3)
        out["neighbors"] = _np.ascontiguousarray(across[:, [1, 0, 2]]).astype(_np.int32)
    if "p" in switches and "holes" in tri:
        out["holes"] = holes
    return out
