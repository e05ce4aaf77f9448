"""hullkit: exact convex hulls in 3D, Delaunay triangulations in 2D and 3D and route checks with
swept traverses, from hullkit's C++ core.

Every decision is made by exact predicates, so flat, collinear, repeated and nearly degenerate
inputs get an answer rather than an error. ``hullkit.spatial`` offers scipy.spatial's
``ConvexHull``, ``Delaunay``, ``Voronoi`` and ``HalfspaceIntersection`` on the same core,
``hullkit.interpolate`` scipy.interpolate's triangulation interpolators and ``griddata``;
``hullkit.dask`` spreads hulls, route checks and interpolation over a Dask cluster.
"""
import json as _json
import os as _os
import re as _re
import uuid as _uuid

import numpy as _np

from . import _core

__all__ = [
    "HullkitError", "Hull", "hull", "verify", "HullBuilder", "Delaunay", "delaunay", "verify_delaunay",
    "Delaunay3", "delaunay3", "verify_delaunay3", "check_route", "RouteChecker", "read_points", "read_mesh",
    "triangulate", "triangulate_polygon",
]
__version__ = "0.1.0"


class HullkitError(ValueError):
    """A problem with the input, as the C++ core words it. ``point`` is the index of the point to
    blame, or None."""

    def __init__(self, message, point=None):
        super().__init__(message)
        self.point = point


class _translated:
    """Turns the core's errors into HullkitError (argument errors from the binding too)."""

    def __enter__(self):
        return self

    def __exit__(self, kind, error, trace):
        if kind is None:
            return False
        if issubclass(kind, _core.CoreError):
            message, point = error.args
            raise HullkitError(message, None if point < 0 else int(point)) from None
        if issubclass(kind, (ValueError, TypeError)) and not issubclass(kind, HullkitError):
            raise HullkitError(str(error)) from None
        return False


def as_points(points, dims, what="points"):
    """The points as a C-ordered float64 array of shape (n, dims): converted once (anything numpy
    converts; Fortran order and other dtypes are copied), or HullkitError naming the problem."""
    try:
        array = _np.ascontiguousarray(points, dtype=_np.float64)
    except (TypeError, ValueError) as error:
        raise HullkitError(f"{what} must be numbers convertible to float64: {error}") from None
    if array.ndim != 2 or array.shape[1] != dims:
        raise HullkitError(f"{what} must have shape (n, {dims}), got {array.shape}")
    return array


def _threads(threads):
    if isinstance(threads, bool) or not isinstance(threads, (int, _np.integer)) or threads < 0:
        raise HullkitError(f"threads must be a non-negative integer, got {threads!r}")
    return int(threads)


def _read_only(array):
    array.flags.writeable = False
    return array


# ---- hulls ---------------------------------------------------------------------------------------

class Hull:
    """The convex hull of points in 3D, as the C++ core gives it.

    ``dimension``: the affine dimension of the points (3 a polytope, 2 a polygon, 1 a segment,
    0 one point, -1 none). ``triangles`` (m, 3) uint32, counter-clockwise seen from outside;
    ``vertices`` uint32 (ascending for a polytope, in order around a polygon); ``volume`` and
    ``area`` (a polygon: volume 0, area its area); ``normal`` for a polygon; with
    ``merge_coplanar`` the planar faces as ``faces`` (a list of uint32 arrays), else None."""

    def __init__(self, result, points):
        self._result = result
        self.points = points
        self.dimension = int(result["dimension"])
        self.triangles = result["triangles"].reshape(-1, 3)
        self.vertices = result["vertices"]
        self.volume = float(result["volume"])
        self.area = float(result["area"])
        self.normal = _np.array(result["normal"], dtype=_np.float64)
        offsets, corners = result["face_offsets"], result["face_vertices"]
        self.faces = [corners[offsets[k]: offsets[k + 1]] for k in range(len(offsets) - 1)] if len(offsets) else None

    def __repr__(self):
        return (f"hullkit.Hull(dimension={self.dimension}, vertices={len(self.vertices)}, "
                f"triangles={len(self.triangles)}, volume={self.volume!r}, area={self.area!r})")


def hull(points, algorithm="quickhull", merge_coplanar=False, threads=0):
    """The exact convex hull of ``points`` (array-like, shape (n, 3)).

    ``algorithm``: "quickhull" (default) or "giftwrap" (the seed's gift wrapping, O(n h)).
    ``threads``: 0 every core, 1 the calling thread only; the result is the same bits for any
    value. Raises HullkitError on NaN or infinite coordinates (naming the point), a wrong shape
    or an unknown option."""
    array = as_points(points, 3)
    with _translated():
        result = _core.hull(array, str(algorithm), bool(merge_coplanar), _threads(threads))
    return Hull(result, array)


def verify(points, hull_or_triangles):
    """An exact check that a hull (a Hull, or triangles (m, 3) of a hull with volume) is the
    convex hull of ``points``. Returns a dict: ok, problems (one line each), problem_count, notes,
    checked_points, triangle_count, vertex_count, face_count, dimension."""
    array = as_points(points, 3)
    with _translated():
        if isinstance(hull_or_triangles, Hull):
            return _core.verify_hull(array, hull_or_triangles._result)
        triangles = _np.ascontiguousarray(hull_or_triangles, dtype=_np.uint32)
        return _core.verify_triangles(array, triangles)


class HullBuilder:
    """The hull of a cloud given in pieces (hullkit::HullBuilder): ``add(points, first_index)``
    or ``add_indexed(points, indices)`` any number of times, then ``finish()``. Holds only the
    running hull's vertices between calls. Indices are 64-bit. ``finish()`` returns a dict:
    ``hull`` (a Hull over ``points``, the kept points), ``points`` (k, 3), ``index`` (k,) uint64
    (the caller's index of each kept point), ``point_count``; the hull of the whole cloud has
    triangle corners ``index[hull.triangles]``, the same arrays as hull() of the whole."""

    def __init__(self, algorithm="quickhull", threads=0):
        with _translated():
            self._builder = _core.HullBuilder(str(algorithm), _threads(threads))

    def add(self, points, first_index=0):
        if isinstance(first_index, bool) or not isinstance(first_index, (int, _np.integer)) or first_index < 0:
            raise HullkitError(f"first_index must be a non-negative integer, got {first_index!r}")
        with _translated():
            self._builder.add(as_points(points, 3), int(first_index))

    def add_indexed(self, points, indices):
        array = as_points(points, 3)
        index = _np.ascontiguousarray(indices, dtype=_np.uint64)
        if index.shape != (len(array),):
            raise HullkitError(f"indices must have shape ({len(array)},), got {index.shape}")
        with _translated():
            self._builder.add_indexed(array, index)

    def finish(self):
        with _translated():
            out = self._builder.finish()
        out["hull"] = Hull(out["hull"], out["points"])
        return out

    @property
    def points_added(self):
        return self._builder.points_added


# ---- Delaunay ------------------------------------------------------------------------------------

def _located(core, queries, dims, simplex, barycentric, nearest, threads):
    """The core's locate on (q, dims) ``queries`` as the dict Delaunay.locate and Delaunay3.locate
    return: ``simplex`` (the key of the holding simplex), and what was asked for."""
    array = as_points(queries, dims, "queries")
    with _translated():
        found, weights, near = core.locate(array, bool(barycentric), bool(nearest), _threads(threads))
    out = {simplex: found}
    if barycentric:
        out["barycentric"] = weights
    if nearest:
        out["nearest"] = near
    return out


class _CoreViews:
    """A result that views a core object's arrays (kept alive by them): ``points``,
    ``dimension``, ``duplicate_count``, and each name in ``_arrays`` as a read-only view of the
    core's array of that name."""

    _arrays = ()

    def __init__(self, core, points):
        self._core = core
        self.points = points
        self.dimension = core.dimension
        self.duplicate_count = core.duplicate_count
        for name in self._arrays:
            setattr(self, name, _read_only(getattr(core, name)))


class Delaunay(_CoreViews):
    """A Delaunay triangulation in delaunator's layout (as hullkit's JS ``delaunay``): flat
    ``triangles`` (uint32, 3 per triangle, clockwise with y up), ``halfedges`` (int32, -1 on the
    hull), ``hull`` (uint32 cycle), ``representative`` (uint32: each point's lowest identical
    point), ``dimension`` (2, 1 collinear, 0 one point, -1 none). Arrays are read-only views."""

    _arrays = ("triangles", "halfedges", "hull", "representative")

    def __init__(self, core, points):
        super().__init__(core, points)
        offsets, corners = core.polygon_offsets, core.polygon_vertices
        self.polygons = [corners[offsets[k]: offsets[k + 1]] for k in range(len(offsets) - 1)] if len(offsets) else None

    def find(self, x, y=None, start=-1):
        """The index of the input point nearest to (x, y), exactly (ties: the lowest index); -1
        without points. ``x`` may also be an (n, 2) array of queries: then an int64 array."""
        if y is None:
            queries = as_points(x, 2, "queries")
            with _translated():
                return self._core.find(queries, int(start))
        with _translated():
            return int(self._core.find(as_points([[x, y]], 2, "query"), int(start))[0])

    def locate(self, queries, barycentric=False, nearest=False, threads=0):
        """Exact point location of ``queries`` (array-like, shape (q, 2)). A dict:

        * ``triangle`` (q,) int32: the triangle holding each query (an index into ``triangles``
          taken three at a time), -1 outside the hull (and for every query when ``dimension`` is
          below 2); a query on an edge or vertex gets the lowest-indexed triangle around it, so
          the answer depends only on the point;
        * with ``barycentric``: ``barycentric`` (q, 3), the weights of that triangle's corners (in
          its corner order) that give the query; exactly 0 on the edge opposite a corner and 1 at
          a corner, NaN outside the hull;
        * with ``nearest``: ``nearest`` (q,) int32, the nearest input point (exact distances;
          ties: the lowest index), also for collinear points.

        Queries are sorted along a Hilbert curve and spread over ``threads`` (0: every core); the
        answers are the same for any value. Raises HullkitError for a NaN or infinite query
        coordinate, or one too far from the points' scale to be decided exactly (``error.point``
        names the query).

        Examples
        --------
        >>> import hullkit
        >>> d = hullkit.delaunay([[0, 0], [1, 0], [0, 1], [1, 1]])
        >>> found = d.locate([[0.25, 0.5], [2, 0], [1, 1]], barycentric=True, nearest=True)
        >>> found["triangle"].tolist(), found["nearest"].tolist()
        ([0, -1, 0], [0, 1, 3])
        >>> t, w = found["triangle"][0], found["barycentric"][0]
        >>> (w @ d.points[d.triangles[3 * t: 3 * t + 3]]).tolist()
        [0.25, 0.5]
        """
        return _located(self._core, queries, 2, "triangle", barycentric, nearest, threads)

    def voronoi(self, bounds=None):
        """Voronoi cells clipped to ``bounds`` (xmin, ymin, xmax, ymax; default the points'
        bounding box): a list, per input point, of its cell's corners as an (k, 2) array,
        counter-clockwise (empty for duplicates and cells outside the box)."""
        if bounds is None:
            if len(self.points) == 0:
                return []
            lo, hi = self.points.min(axis=0), self.points.max(axis=0)
            pad = _np.where(hi > lo, 0.0, 1.0)
            bounds = (lo[0] - pad[0], lo[1] - pad[1], hi[0] + pad[0], hi[1] + pad[1])
        with _translated():
            offsets, xy = self._core.voronoi(*map(float, bounds))
        return [xy[offsets[i]: offsets[i + 1]] for i in range(len(offsets) - 1)]

    def __repr__(self):
        return f"hullkit.Delaunay(points={len(self.points)}, triangles={len(self.triangles) // 3}, dimension={self.dimension})"


def delaunay(points, algorithm="incremental", merge_cocircular=False, threads=0):
    """The exact Delaunay triangulation of ``points`` (array-like, shape (n, 2)); see Delaunay.
    ``algorithm``: "incremental" (default) or "giftwrap" (the seed's, on the lifted points)."""
    array = as_points(points, 2)
    with _translated():
        core = _core.Triangulation(array, str(algorithm), bool(merge_cocircular), _threads(threads))
    return Delaunay(core, array)


def verify_delaunay(points, triangles):
    """An exact check that flat ``triangles`` are a Delaunay triangulation of the distinct points
    (empty circles by the exact in-circle test). A dict: ok, problems, problem_count,
    distinct_points, hull_points."""
    array = as_points(points, 2)
    flat = _np.ascontiguousarray(triangles, dtype=_np.uint32).ravel()
    with _translated():
        return _core.verify_delaunay(array, flat)


class Delaunay3(_CoreViews):
    """A Delaunay tetrahedralization of points in 3D, as the C++ core gives it (see delaunay3).

    What is filled depends on ``dimension``, the dimension the points span:

    * 3: ``tetrahedra`` (m, 4) uint32, positively oriented (the fourth corner on the side the
      normal (t1 - t0) x (t2 - t0) points to); ``neighbors`` (m, 4) int32, ``neighbors[t, k]`` the
      tetrahedron across the face opposite corner k, -1 on the hull (scipy's convention);
      ``hull`` (k, 3) uint32, the convex hull's triangles, counter-clockwise seen from outside.
    * 2 (coplanar points): ``triangles`` (t, 3) uint32, their Delaunay triangulation in the plane,
      counter-clockwise seen from the side ``normal`` points to; ``neighbors`` (t, 3) int32, across
      the edge opposite corner k, -1 on the boundary.
    * 1 (collinear points): ``vertices`` the distinct points in order along the line; 0 (one
      distinct point): ``vertices`` holds it; -1: no points.

    Always: ``representative`` (n,) uint32, each point's lowest-indexed identical point (itself if
    it has none; duplicates are merged, never dropped silently), ``duplicate_count`` and
    ``points``. Unused arrays are empty with the shapes above. The arrays are read-only views of
    the core's result (no copy), which they keep alive. Ties (five or more cospherical points, as
    on a grid) are broken by a symbolic perturbation: one answer that depends only on the points,
    never a flat tetrahedron, the same for any ``threads``."""

    _arrays = ("tetrahedra", "neighbors", "hull", "triangles", "vertices", "representative")

    def __init__(self, core, points):
        super().__init__(core, points)
        self.normal = _read_only(_np.array(core.normal, dtype=_np.float64))

    def locate(self, queries, barycentric=False, nearest=False, threads=0):
        """Exact point location of ``queries`` (array-like, shape (q, 3)). A dict:

        * ``tetrahedron`` (q,) int32: the tetrahedron holding each query, -1 outside the hull (and
          for every query when ``dimension`` is below 3); a query on a face, edge or vertex gets
          the lowest-indexed tetrahedron around it, so the answer depends only on the point;
        * with ``barycentric``: ``barycentric`` (q, 4), the weights of that tetrahedron's corners
          (in its corner order) that give the query; exactly 0 on the face opposite a corner and
          1 at a corner, NaN outside the hull;
        * with ``nearest``: ``nearest`` (q,) int32, the nearest input point (exact distances; ties:
          the lowest index).

        Queries are sorted along a Hilbert curve and spread over ``threads`` (0: every core); the
        answers are the same for any value. Raises HullkitError for a NaN or infinite query
        coordinate, or one too far from the points' scale to be decided exactly (``error.point``
        names the query).

        Examples
        --------
        >>> import hullkit
        >>> cube = [[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)]
        >>> d = hullkit.delaunay3(cube)
        >>> found = d.locate([[0.25, 0.25, 0.25], [2, 0, 0]], barycentric=True, nearest=True)
        >>> int(found["tetrahedron"][1]), found["nearest"].tolist()
        (-1, [0, 4])
        >>> t = found["tetrahedron"][0]
        >>> w = found["barycentric"][0]
        >>> [round(float(c), 12) for c in w @ d.points[d.tetrahedra[t]]]
        [0.25, 0.25, 0.25]
        """
        return _located(self._core, queries, 3, "tetrahedron", barycentric, nearest, threads)

    def voronoi(self):
        """The Voronoi diagram, dual to this tetrahedralization. A dict of arrays (numbers are
        indices into the others):

        * ``vertices`` (v, 3): the circumcentres of the Delaunay cells (tetrahedra whose
          circumspheres coincide exactly, as a grid's, share one); ``tetrahedron_vertex`` (m,):
          each tetrahedron's vertex;
        * ``face_points`` (f, 2): the two points p < q each face separates; its corners are
          ``face_vertices[face_offsets[k]:face_offsets[k + 1]]``, counter-clockwise seen from q's
          side; ``face_bounded`` (f,) 1 or 0 (an unbounded face lists the chain between its rays);
        * ``cell_faces[cell_offsets[i]:cell_offsets[i + 1]]``: point i's faces; ``volume`` (n,):
          its cell's volume, inf when unbounded (a hull point), NaN for a duplicate point.

        Which vertices and faces exist is decided exactly; coordinates and volumes are rounded.
        Below dimension 3 every cell is unbounded (no vertices or faces).

        Examples
        --------
        >>> import numpy as np
        >>> import hullkit
        >>> grid = np.array([[x, y, z] for x in range(3) for y in range(3) for z in range(3)], dtype=float)
        >>> v = hullkit.delaunay3(grid).voronoi()
        >>> float(v["volume"][13]), int(np.isinf(v["volume"]).sum())  # the centre's cell: a unit cube
        (1.0, 26)
        """
        with _translated():
            arrays = self._core.voronoi()
        names = ("vertices", "tetrahedron_vertex", "face_points", "face_offsets", "face_vertices",
                 "face_bounded", "cell_offsets", "cell_faces", "volume")
        return dict(zip(names, arrays))

    def __repr__(self):
        return (f"hullkit.Delaunay3(points={len(self.points)}, tetrahedra={len(self.tetrahedra)}, "
                f"dimension={self.dimension})")


def delaunay3(points, threads=0, furthest_site=False):
    """The exact Delaunay tetrahedralization of ``points`` (array-like, shape (n, 3)); see Delaunay3.

    ``furthest_site=True``: the furthest-site tetrahedralization instead (scipy's and Qhull's
    furthest_site: the upper hull of the lifted points), whose tetrahedra's circumspheres hold every
    point; only the hull's extreme points are corners (a point inside the hull, or inside one of its
    faces or edges, is in no tetrahedron); coplanar points: the furthest-site triangulation of the
    polygon's corners; collinear: the two end points.

    Anything numpy converts to float64 is accepted (float32, Fortran order, lists: converted once;
    a C-ordered float64 array is used as it is). ``threads``: 0 every core, 1 the calling thread
    only; the arrays are the same bits for any value. The GIL is released while the core works.
    Raises HullkitError on a wrong shape or a NaN or infinite coordinate (naming the point, also
    as ``error.point``).

    Examples
    --------
    >>> import numpy as np
    >>> import hullkit
    >>> cube = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)
    >>> d = hullkit.delaunay3(cube)
    >>> d.dimension, d.tetrahedra.shape, d.neighbors.shape, d.hull.shape
    (3, (6, 4), (6, 4), (12, 3))
    >>> a, b, c, e = (cube[d.tetrahedra[:, k]] for k in range(4))
    >>> float(np.linalg.det(np.stack([b - a, c - a, e - a], axis=1)).sum() / 6)  # the cube's volume
    1.0
    >>> hullkit.verify_delaunay3(cube, d.tetrahedra)["ok"]
    True
    >>> square = hullkit.delaunay3([[0, 0, 1], [1, 0, 1], [0, 1, 1], [1, 1, 1]])
    >>> square.dimension, square.triangles.shape, square.normal.tolist()
    (2, (2, 3), [0.0, 0.0, 1.0])
    """
    array = as_points(points, 3)
    with _translated():
        core = _core.Tetrahedralization(array, _threads(threads), bool(furthest_site))
    return Delaunay3(core, array)


def verify_delaunay3(points, tetrahedra, perturbed=True):
    """An exact check that ``tetrahedra`` (shape (m, 4), or a Delaunay3) is the Delaunay
    tetrahedralization of the distinct points of ``points``: indices in range, every tetrahedron
    positively oriented (none flat), faces shared by at most two tetrahedra with opposite
    orientations, the boundary a triangulation of the convex hull, every distinct point a vertex,
    the volume the hull's, every interior face locally Delaunay by the exact in-sphere test. With
    ``perturbed`` (the default) cospherical ties must also go delaunay3's way (which makes the
    answer unique); without, either way passes. A dict: ok, problems (one line each),
    problem_count, distinct_points, hull_triangles.

    Examples
    --------
    >>> import numpy as np
    >>> import hullkit
    >>> points = np.random.default_rng(1).random((100, 3))
    >>> tetrahedra = hullkit.delaunay3(points).tetrahedra
    >>> hullkit.verify_delaunay3(points, tetrahedra)["ok"]
    True
    >>> report = hullkit.verify_delaunay3(points, tetrahedra[1:])  # one tetrahedron missing
    >>> report["ok"], report["problem_count"] > 0
    (False, True)
    """
    array = as_points(points, 3)
    if isinstance(tetrahedra, Delaunay3):
        tetrahedra = tetrahedra.tetrahedra
    corners = _np.ascontiguousarray(tetrahedra, dtype=_np.uint32)
    if corners.ndim != 2 or corners.shape[1] != 4:
        raise HullkitError(f"tetrahedra must have shape (m, 4), got {corners.shape}")
    with _translated():
        return _core.verify_delaunay3(array, corners, bool(perturbed))


# ---- route checking ------------------------------------------------------------------------------

def _json_rows(array):
    """json.dumps(array.tolist()) for a 2-D array of finite floats or of integers, byte for byte
    but written by the core; None for any other array (json.dumps writes it)."""
    if array.ndim != 2 or array.size == 0:
        return None
    if array.dtype.kind == "f" and array.dtype.itemsize <= 8:  # long double: left to json.dumps
        values = _np.ascontiguousarray(array, dtype=_np.float64)
        return _core.json_rows_float64(values) if _np.isfinite(values).all() else None
    if array.dtype.kind == "i" or (array.dtype.kind == "u" and array.dtype.itemsize < 8):
        return _core.json_rows_int64(_np.ascontiguousarray(array, dtype=_np.int64))
    return None


def _scene_json(scene):
    """(json text, source name, directory for mesh files) of a scene given as a dict (numpy
    arrays allowed) or a path to a JSON file."""
    if isinstance(scene, (str, _os.PathLike)):
        path = _os.fspath(scene)
        try:
            with open(path, "rb") as file:
                text = file.read().decode("utf-8")
        except OSError as error:
            raise HullkitError(f"{path}: cannot open: {error.strerror}") from None
        except UnicodeDecodeError:
            raise HullkitError(f"{path}: not UTF-8 text") from None
        return text, path, _os.path.dirname(path) or "."
    if isinstance(scene, dict):
        # 2-D numeric arrays (meshes) are written by the core, into the places of unique strings:
        # the same text as json.dumps of their lists, so the same scene and the same messages.
        marker, rows = f"hullkit-rows-{_uuid.uuid4().hex}-", []

        def plain(value):
            if isinstance(value, _np.ndarray):
                text = _json_rows(value)
                if text is None:
                    return value.tolist()
                rows.append(text)
                return f"{marker}{len(rows) - 1}"
            if isinstance(value, (_np.integer, _np.floating)):
                return value.item()
            raise TypeError(f"{type(value).__name__} is not JSON")
        try:
            text = _json.dumps(scene, default=plain, allow_nan=True)
        except (TypeError, ValueError) as error:
            raise HullkitError(f"scene: {error}") from None
        if rows:
            text = _re.sub(f'"{marker}([0-9]+)"', lambda m: rows[int(m.group(1))], text)
        return text, "scene", "."
    raise HullkitError(f"a scene is a dict or the path of a JSON file, got {type(scene).__name__}")


class RouteChecker:
    """A scene prepared once (hulls, bounding-volume hierarchy) for many route checks, as the
    page's dragging does. ``scene``: a dict in ``hullkit route``'s JSON format (meshes inline as
    "vertices"/"triangles", numpy arrays allowed, or "mesh" files relative to the current
    directory) or the path of a scene file (mesh files relative to it)."""

    def __init__(self, scene):
        text, source, directory = _scene_json(scene)
        with _translated():
            self._core = _core.RouteChecker(text, source, directory)

    def check(self, route=None, clearance=True, samples=0, threads=0, rotations=None):
        """The report of ``route`` (waypoints, shape (k, 3); default the scene's own) as a dict in
        ``hullkit route``'s JSON format: clear, min_clearance, legs (each with status "clear",
        "hit" or "start-overlap" and its details), build_seconds, seconds. ``rotations``: the
        traverse's orientation at each waypoint, shape (k, 4), unit quaternions w x y z (legs
        between different orientations turn; see docs/route-checking.md)."""
        waypoints = _np.zeros((0, 3)) if route is None else as_points(route, 3, "route")
        if route is not None and len(waypoints) < 2:
            raise HullkitError(f"a route needs at least 2 waypoints, got {len(waypoints)}")
        if rotations is not None and route is None:
            raise HullkitError("rotations need a route: pass both to check()")
        turns = _np.zeros((0, 4)) if rotations is None else as_points(rotations, 4, "rotations")
        if route is None and self._core.scene_waypoints == 0:
            raise HullkitError("the scene has no route: pass one to check()")
        if isinstance(samples, bool) or not isinstance(samples, (int, _np.integer)) or samples < 0:
            raise HullkitError(f"samples must be a non-negative integer, got {samples!r}")
        with _translated():
            text = self._core.check(waypoints, turns, bool(clearance), int(samples), _threads(threads))
        return _json.loads(text)

    @property
    def build_seconds(self):
        return self._core.build_seconds


def check_route(scene, clearance=True, samples=0, threads=0):
    """One check of a scene's own route: RouteChecker(scene).check(...)."""
    return RouteChecker(scene).check(None, clearance=clearance, samples=samples, threads=threads)


# ---- readers -------------------------------------------------------------------------------------

def read_points(path, threads=0):
    """Every point of a point file (xyz text, rbox, OBJ, OFF, PLY, STL) as an (n, 3) float64
    array; text is parsed on ``threads`` threads (0: every core). Errors name file and line."""
    with _translated():
        return _core.read_points(_os.fspath(path), _threads(threads))


def read_mesh(path):
    """A triangle mesh file (OBJ, OFF, PLY, STL): (vertices (n, 3) float64, triangles (m, 3)
    uint32). Errors name file and line."""
    path = _os.fspath(path)
    try:
        with open(path, "rb") as file:
            data = file.read()
    except OSError as error:
        raise HullkitError(f"{path}: cannot open: {error.strerror}") from None
    with _translated():
        return _core.read_mesh(data, path)


from .constrained import triangulate, triangulate_polygon  # noqa: E402  (needs the names above)
