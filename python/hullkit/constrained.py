"""Constrained Delaunay triangulation from Python: polygons with holes (earcut's arguments, as
``hullkit.triangulatePolygon`` in JS) and Triangle's dictionary and switches (``hullkit.triangulate``,
for users of the ``triangle`` package). Exact: see native/include/hullkit/constrained.hpp."""

import numpy as _np

from . import _core
from . import HullkitError, _translated, as_points

__all__ = ["triangulate", "triangulate_polygon"]

# Triangle's switches hullkit honours, and those it does not have yet (with what they are).
_SWITCHES = {"p": "segments", "c": "convex", "z": "zero-based", "n": "neighbors", "e": "edges", "Q": "quiet", "V": "verbose",
             "q": "minimum angle", "a": "maximum area", "D": "conforming Delaunay", "S": "Steiner point limit",
             "A": "regional attributes", "Y": "no Steiner points on the boundary (YY: on any segment)",
             "u": "user refinement test (the unsuitable= function)", "r": "refine tri['triangles']"}
_NUMBERED = ("q", "a", "S")  # switches that may carry a number
_NOT_YET = {
    "o": "second-order triangles", "i": "incremental insertion", "F": "Fortune's sweep", "l": "vertical cuts only", "s": "segment splitting",
    "C": "consistency checks", "j": "jettisoning vertices", "B": "no boundary markers", "P": "no .poly output", "N": "no .node output",
    "E": "no .ele output", "I": "no iteration numbers", "O": "ignoring holes", "X": "no exact arithmetic",
}
_KEYS = ("vertices", "segments", "holes", "regions", "triangles", "triangle_max_area")
_OUTPUT_KEYS = ("edges", "neighbors", "triangle_attributes")  # an earlier output's: ignored
_NO_POINTS = _np.zeros((0, 2))


def _quality(min_angle, max_area, conforming, max_steiner_points, keep_segments=0):
    """The refinement keywords checked (the core checks the ranges again)."""
    try:
        min_angle, max_area = float(min_angle), float(max_area)
    except (TypeError, ValueError):
        raise HullkitError(f"min_angle and max_area must be numbers, got {min_angle!r} and {max_area!r}") from None
    if not 0 <= min_angle <= 34:
        raise HullkitError(f"min_angle must be from 0 to 34 degrees, got {min_angle}")
    if not (0 <= max_area < _np.inf):
        raise HullkitError(f"max_area must be a positive number (0: none), got {max_area}")
    if isinstance(max_steiner_points, bool) or not isinstance(max_steiner_points, (int, _np.integer)) or max_steiner_points < 0:
        raise HullkitError(f"max_steiner_points must be a whole number (0: no cap), got {max_steiner_points!r}")
    if keep_segments not in (0, 1, 2) or isinstance(keep_segments, bool):
        raise HullkitError(f"keep_segments must be 0 (none), 1 (the boundary's) or 2 (every segment), got {keep_segments!r}")
    return min_angle, max_area, bool(conforming), int(max_steiner_points), int(keep_segments)


def _run(points, segments, starts, fill, convex, holes, regions=None, quality=(0.0, 0.0, False, 0, 0), unsuitable=None,
         mesh=None, mesh_areas=None):
    if unsuitable is not None and not callable(unsuitable):
        raise HullkitError(f"unsuitable must be a function (a, b, c, area) -> bool, got {unsuitable!r}")
    with _translated():
        return _core.constrained(points, segments, starts, fill, convex, holes,
                                 _np.zeros((0, 3)) if regions is None else regions, *quality, unsuitable, mesh, mesh_areas)


def triangulate_polygon(coords, hole_indices=None, fill="evenodd", *, min_angle=0, max_area=0, conforming=False,
                        max_steiner_points=0, keep_segments=0, unsuitable=None):
    """The triangles inside polygons with holes, earcut's way: ``coords`` the vertices (shape (n, 2),
    or flat x y x y ...), ``hole_indices`` the vertex index at which each hole (each ring after the
    first) starts. Rings open or closed, any orientation, nesting, touching or crossing; ``fill``
    'evenodd' (default) or 'nonzero'. A dict: ``coords`` (the input vertices then the crossing points
    added, (m, 2)), ``triangles`` ((t, 3), clockwise with y up as hullkit.delaunay's), ``halfedges``,
    ``constrained`` (per half-edge, 1 on a ring edge), ``representative``, ``crossing_count``.

    A quality mesh of the inside (Delaunay refinement, as Triangle's -q, -a and -D): ``min_angle``
    degrees (0 to 34; up to 28.6 refinement always finishes), ``max_area`` (largest triangle),
    ``conforming`` (every triangle Delaunay), ``max_steiner_points`` (an error past this many added
    points; 0 no cap), ``keep_segments`` (1 or 2: no point added on the rings, as Triangle's -Y;
    see ``triangulate``), ``unsuitable`` (Triangle's -u: see ``triangulate``). The points added follow the crossings in ``coords`` (``steiner_count``);
    ``unrefined_count`` triangles were left below the bound at input angles smaller than it."""
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
    quality = _quality(min_angle, max_area, conforming, max_steiner_points, keep_segments)
    coords_out, triangles, halfedges, constrained, representative, crossings, steiner, unrefined, _ = _run(
        points, _np.zeros(0, _np.uint32), starts.astype(_np.uint32), fill, False, _NO_POINTS, None, quality, unsuitable)
    return {"coords": coords_out, "triangles": triangles, "halfedges": halfedges, "constrained": constrained,
            "representative": representative, "crossing_count": crossings, "steiner_count": steiner,
            "unrefined_count": unrefined}


def _switches(opts):
    """Triangle's switches as {switch: number or None}; q, a and S may carry a number ("pq30a0.5");
    'a' may appear twice, bare (regional areas) and with a number (global): kept as 'a' and 'a#'."""
    if not isinstance(opts, str):
        raise HullkitError(f"opts must be a string of Triangle's switches, got {opts!r}")
    found = {}
    i = 0
    while i < len(opts):
        c = opts[i]
        j = i + 1
        while j < len(opts) and (opts[j].isdigit() or opts[j] == "."):
            j += 1
        number = opts[i + 1:j]
        if c == "Y" and not number:  # 'Y' once: the boundary's segments; 'YY': every segment
            found["Y"] = min(found.get("Y", 0) + 1, 2)
        elif c in _SWITCHES:
            if number and c not in _NUMBERED:
                raise HullkitError(f"switch '{c}' takes no number, got '{c}{number}' in opts {opts!r}")
            value = None
            if number:
                try:
                    value = float(number)
                except ValueError:
                    raise HullkitError(f"'{number}' after switch '{c}' in opts {opts!r} is not a number") from None
            found["a#" if c == "a" and value is not None else c] = value
        elif c in _NOT_YET:
            raise HullkitError(f"Triangle's switch '{c}' ({_NOT_YET[c]}) is not supported by hullkit yet")
        elif c.isdigit() or c == ".":
            raise HullkitError(f"the number at position {i} of opts {opts!r} follows no switch that takes one (q, a, S)")
        else:
            raise HullkitError(f"unknown switch '{c}' at position {i} of opts {opts!r}")
        i = j
    return found


def triangulate(tri, opts="", **options):  # noqa: C901 - one switch after the other
    """Triangle's ``triangulate(tri, opts)`` (the ``triangle`` package), exact. ``tri`` a dict with
    ``vertices`` (n, 2), optionally ``segments`` (m, 2) and ``holes`` (h, 2) (points inside holes).
    Switches: ``p`` triangulate the planar straight-line graph (segments kept as edges, split where
    a vertex lies on them or another segment crosses; the exterior and the hole regions removed),
    ``c`` keep the whole convex hull, ``n`` also ``neighbors``, ``e`` also ``edges``; ``z``, ``Q``,
    ``V`` are accepted (indices are always zero-based). Without ``p`` the vertices' Delaunay
    triangulation. Quality meshes: ``q`` (a minimum angle, default 20 degrees: ``q30``), ``a0.5``
    (a maximum area), bare ``a`` (each region's area from ``tri['regions']``, rows x y attribute
    max_area), ``D`` (conforming Delaunay), ``S100`` (at most 100 added points, else an error), ``A``
    (``triangle_attributes`` (t, 1): the attribute of the region holding each triangle, the last
    region given where several seeds share one, 0 outside every region), ``Y`` (no point added on
    the boundary's segments; ``YY`` on any segment: where a circumcentre lies beyond such a segment a
    triangle too large gets its centroid, one with only a small angle is left, counted as
    unrefined), ``u`` with ``unsuitable=f``: Triangle's triunsuitable, ``f((ax, ay), (bx, by), (cx,
    cy), area)`` returning True for a triangle to refine (a function of the triangle alone; whether
    refinement ends is up to it: unless ``S`` is given a cap of 16 points per vertex plus 10^6
    applies). The keywords ``convex``, ``min_angle``, ``max_area``, ``conforming``,
    ``max_steiner_points``, ``keep_segments`` (0, 1 = Y, 2 = YY), ``unsuitable`` (with or without
    ``u``) do the same. ``r`` refines a mesh, ``tri['triangles']`` (t, 3) (an earlier output, say): the
    domain is their union, its boundary kept (with ``p`` ``tri['segments']`` too), the inside
    triangulated anew and refined as asked; vertices no triangle or segment uses stay in
    ``vertices`` in no triangle; with bare ``a`` each triangle's own bound from
    ``tri['triangle_max_area']`` (t,) (0 or negative: none; every edge of the mesh is then kept).
    ``holes`` and ``regions`` do not apply with ``r`` (an earlier output's keys are ignored, as its
    ``edges``, ``neighbors`` and ``triangle_attributes``). Returns a dict: ``vertices`` (input vertices then the crossing and refinement points),
    ``triangles`` (t, 3) counter-clockwise as Triangle's, ``segments`` (the edges on segments, each
    once), and ``neighbors``/``edges`` when asked."""
    if not isinstance(tri, dict):
        raise HullkitError(f"tri must be a dict with 'vertices' (and 'segments', 'holes'), got {type(tri).__name__}")
    unknown = sorted(set(tri) - set(_KEYS) - set(_OUTPUT_KEYS))
    if unknown:
        raise HullkitError(f"tri key(s) {unknown} are not supported by hullkit yet (it takes {list(_KEYS)})")
    if "vertices" not in tri:
        raise HullkitError("tri needs 'vertices', shape (n, 2)")
    known = {"convex", "min_angle", "max_area", "conforming", "max_steiner_points", "keep_segments", "unsuitable"}
    extra = set(options) - known
    if extra:
        raise HullkitError(f"unknown keyword(s) {sorted(extra)} (known: {', '.join(sorted(known))})")
    switches = _switches(opts)
    convex = bool(options.get("convex", False)) or "c" in switches
    min_angle = options.get("min_angle")
    if min_angle is None:
        min_angle = (20.0 if switches["q"] is None else switches["q"]) if "q" in switches else 0.0
    max_area = options.get("max_area")
    if max_area is None:
        max_area = switches.get("a#") or 0.0
    steiner = options.get("max_steiner_points", 0)
    if "S" in switches:
        steiner = int(switches["S"] or 0)
    keep = options.get("keep_segments", switches.get("Y", 0))
    quality = _quality(min_angle, max_area, bool(options.get("conforming", False)) or "D" in switches, steiner, keep)
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
    if "r" in switches:
        return _refine(tri, switches, points, segments, quality, options.get("unsuitable"))
    if "triangles" in tri or "triangle_max_area" in tri:
        raise HullkitError("tri['triangles'] and tri['triangle_max_area'] are a mesh to refine: add switch 'r'")
    regions = None
    rows = _np.zeros((0, 4))
    if "A" in switches and "p" not in switches:
        raise HullkitError("switch 'A' (regional attributes) needs 'p': the regions are bounded by tri['segments']")
    if "regions" in tri and "p" in switches:
        rows = _np.ascontiguousarray(tri["regions"], dtype=_np.float64)
        if rows.ndim != 2 or rows.shape[1] != 4:
            raise HullkitError(f"tri['regions'] must have shape (k, 4): x, y, attribute, max_area; got {rows.shape}")
        if not _np.isfinite(rows[:, 2]).all():
            raise HullkitError(f"tri['regions'] row {int(_np.flatnonzero(~_np.isfinite(rows[:, 2]))[0])}: the attribute is not finite")
        # Without a bare 'a' the regions' areas are not bounds (as Triangle reads them).
        regions = _np.ascontiguousarray(rows[:, [0, 1, 3]] if "a" in switches else _np.c_[rows[:, :2], _np.zeros(len(rows))])
    unsuitable = options.get("unsuitable")
    if "u" in switches and unsuitable is None:
        raise HullkitError("switch 'u' (Triangle's triunsuitable) needs the test as unsuitable=function(a, b, c, area) -> bool")
    result = _run(points, segments.astype(_np.uint32).ravel(), None, "evenodd", convex, holes, regions, quality, unsuitable)
    out = _triangle_dict(result, switches)
    if "p" in switches and "holes" in tri:
        out["holes"] = holes
    if "p" in switches and "regions" in tri:
        out["regions"] = _np.asarray(tri["regions"], dtype=_np.float64)
    if "A" in switches:  # each triangle's region's attribute, 0 outside every region (Triangle's)
        region = result[8]
        attributes = _np.zeros(len(out["triangles"]))
        if len(region):
            inside = region >= 0
            attributes[inside] = rows[region[inside], 2]
        out["triangle_attributes"] = attributes.reshape(-1, 1)
    return out


def _triangle_dict(result, switches):
    """Triangle's output dict from the core's arrays: counter-clockwise triangles, the segments'
    edges, and the edges and neighbours when asked ('e', 'n')."""
    vertices, triangles, halfedges, constrained = result[:4]
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
    return out


def _refine(tri, switches, points, segments, quality, unsuitable):
    """Triangle's -r: the mesh tri['triangles'] refined (hullkit::refine_mesh)."""
    if "triangles" not in tri:
        raise HullkitError("switch 'r' refines a mesh: tri needs 'triangles', shape (t, 3)")
    if "A" in switches:
        raise HullkitError("switch 'A' (regional attributes) does not apply with 'r': the mesh has no regions")
    triangles = _np.asarray(tri["triangles"])
    if triangles.ndim != 2 or triangles.shape[1] != 3 or not (_np.issubdtype(triangles.dtype, _np.integer) or triangles.size == 0):
        raise HullkitError(f"tri['triangles'] must be whole numbers of shape (t, 3), got {triangles.dtype} {triangles.shape}")
    if triangles.size and (triangles.min() < 0 or triangles.max() >= len(points)):
        raise HullkitError(f"tri['triangles'] must index the {len(points)} vertices")
    areas = None
    if "a" in switches:
        if "triangle_max_area" not in tri:
            raise HullkitError("bare switch 'a' with 'r' reads each triangle's bound from tri['triangle_max_area'], shape (t,)")
        areas = _np.ascontiguousarray(tri["triangle_max_area"], dtype=_np.float64).ravel()
        if len(areas) != len(triangles):
            raise HullkitError(f"tri['triangle_max_area'] holds {len(areas)} numbers for {len(triangles)} triangles")
    mesh = _np.ascontiguousarray(triangles, dtype=_np.uint32)
    result = _run(points, segments.astype(_np.uint32).ravel(), None, "evenodd", False, _NO_POINTS, None, quality, unsuitable,
                  mesh, areas)
    return _triangle_dict(result, switches)
