"""scipy.spatial's ConvexHull and Delaunay on hullkit's exact core: switching is a change of
import.

    from hullkit.spatial import ConvexHull, Delaunay   # instead of: from scipy.spatial import ...

The attributes have scipy's names, shapes, dtypes and conventions. Where scipy raises
(QhullError on flat, collinear, repeated or too few points), hullkit answers, and ``dimension``
(an attribute scipy lacks) says what the points span:

* 3D points spanning a plane (``dimension`` 2): ``vertices`` the polygon's corners in order,
  ``simplices`` the triangles fanning it, ``equations`` their plane (one row each, the normal
  ``hullkit.hull`` reports), ``volume`` 0, ``area`` the polygon's area (one side).
* points on a line (``dimension`` 1): ``vertices`` the two ends; in 2D ``simplices`` the segment
  as a degenerate polygon (both directions), ``volume`` 0, ``area`` twice its length (the
  perimeter); in 3D no simplices, ``volume`` and ``area`` 0.
* one distinct point (``dimension`` 0) or none (-1): that point (or nothing) as ``vertices``, no
  simplices.

Delaunay (2D): ``simplices`` counter-clockwise, ``neighbors``, ``find_simplex`` (exact point
location; -1 outside), ``convex_hull``, ``vertex_neighbor_vertices``, ``transform``, ``coplanar``
(here: the exact duplicates, each with a simplex of the point that represents it and that
point), ``points``, ``npoints``, ``ndim``, ``nsimplex``, ``min_bound``, ``max_bound``;
and ``dimension``. Collinear points (``dimension`` 1) or one distinct point (0) give no
simplices; ``convex_hull`` is then the chain of edges along the line (or empty),
``vertex_neighbor_vertices`` links each point to its neighbours along it, and ``find_simplex``
answers -1.

Delaunay (3D, on ``hullkit.delaunay3``): ``simplices`` (m, 4) positively oriented, ``neighbors``,
``convex_hull`` (k, 3), ``vertex_neighbor_vertices``, ``vertex_to_simplex``, ``transform``,
``coplanar`` (the exact duplicates, as in 2D; empty otherwise: every distinct point is a vertex),
``points``, ``npoints``, ``ndim``, ``nsimplex``, ``min_bound``, ``max_bound``; and ``dimension``.
Cospherical points (grids) get tetrahedra that are never flat. Coplanar points (``dimension`` 2)
give no simplices and ``convex_hull`` their planar Delaunay triangles; collinear points or one
point no simplices and an empty ``convex_hull`` (``vertex_neighbor_vertices`` links the points
along the line). ``find_simplex`` is exact (hullkit.Delaunay3.locate): a point on a shared
face, edge or vertex gets the lowest-indexed simplex around it.

Only NaN or infinite coordinates and wrong shapes raise (HullkitError, a ValueError, naming the
point). Options scipy has and hullkit does not (qhull_options, incremental, furthest_site,
dimensions beyond 3) raise a clear "not supported".
"""
import numpy as _np

from . import HullkitError, _core, _translated, as_points, delaunay, delaunay3, hull

__all__ = ["ConvexHull", "Delaunay"]


def _bounds(array, ndim):
    """(min_bound, max_bound) of the points, column by column (numpy's min over axis 0 of an
    (n, 2) or (n, 3) array is many times slower); NaN without points."""
    if not len(array):
        return _np.full(ndim, _np.nan), _np.full(ndim, _np.nan)
    columns = [array[:, k] for k in range(ndim)]
    return _np.array([c.min() for c in columns]), _np.array([c.max() for c in columns])


def _not_supported(what, cls="ConvexHull"):
    raise HullkitError(f"{what} is not supported by hullkit.spatial.{cls} (hullkit is exact; it has no Qhull options)")


class ConvexHull:
    """The convex hull of points in 2 or 3 dimensions (see the module's documentation).

    Attributes (scipy's): points, vertices, simplices, neighbors, equations, volume, area,
    npoints, ndim, min_bound, max_bound; and dimension."""

    def __init__(self, points, incremental=False, qhull_options=None):
        if incremental:
            _not_supported("incremental=True")
        if qhull_options is not None:
            _not_supported(f"qhull_options={qhull_options!r}")
        try:
            array = _np.ascontiguousarray(points, dtype=_np.float64)
        except (TypeError, ValueError) as error:
            raise HullkitError(f"points must be numbers convertible to float64: {error}") from None
        if array.ndim != 2 or array.shape[1] not in (2, 3):
            if array.ndim == 2 and array.shape[1] > 3:
                _not_supported(f"a hull in {array.shape[1]} dimensions")
            raise HullkitError(f"points must have shape (n, 2) or (n, 3), got {array.shape}")
        self.points = array
        self.npoints, self.ndim = array.shape
        self.min_bound, self.max_bound = _bounds(array, self.ndim)
        if self.ndim == 3:
            self._from_3d(hull(as_points(array, 3)))
        else:
            self._from_2d(array)

    # -- 3D ------------------------------------------------------------------------------------
    def _from_3d(self, h):
        self.dimension = h.dimension
        # scipy: vertices "in input order" for 3D; a polygon's come in order around it.
        self.vertices = h.vertices.astype(_np.int32)
        self.simplices = h.triangles.astype(_np.int32)
        self.volume, self.area = h.volume, h.area
        with _translated():
            neighbors, equations = _core.surface_extras(h.points, _np.ascontiguousarray(h.triangles))
        self.neighbors = neighbors
        if h.dimension == 2:
            normal = h.normal
            offset = -float(normal @ self.points[self.vertices[0]])
            self.equations = _np.tile(_np.append(normal, offset), (len(self.simplices), 1))
        else:
            self.equations = equations

    # -- 2D ------------------------------------------------------------------------------------
    def _from_2d(self, xy):
        lifted = _np.zeros((len(xy), 3))
        lifted[:, :2] = xy
        # A polygon in z = 0 comes counter-clockwise seen from +z (hullkit.Hull's rule: seen from
        # the side of the normal's largest component), which is scipy's counter-clockwise in 2D.
        h = hull(lifted)
        self.dimension = h.dimension
        self.vertices = h.vertices.astype(_np.int32)
        m = len(self.vertices)
        if h.dimension >= 1:
            following = _np.roll(self.vertices, -1)
            self.simplices = _np.stack([self.vertices, following], axis=1).astype(_np.int32)
            edges = xy[following] - xy[self.vertices]
            lengths = _np.hypot(edges[:, 0], edges[:, 1])
            normals = _np.stack([edges[:, 1], -edges[:, 0]], axis=1) / lengths[:, None]
            offsets = -_np.einsum("ij,ij->i", normals, xy[self.vertices])
            self.equations = _np.concatenate([normals, offsets[:, None]], axis=1)
            self.area = float(lengths.sum())
            self.volume = float(h.area) if h.dimension == 2 else 0.0
            # Edge k joins vertex k and k + 1: opposite its vertex 0 lies edge k + 1, opposite
            # its vertex 1 edge k - 1.
            k = _np.arange(m, dtype=_np.int32)
            self.neighbors = _np.stack([(k + 1) % m, (k - 1) % m], axis=1).astype(_np.int32)
        else:
            self.simplices = _np.zeros((0, 2), dtype=_np.int32)
            self.equations = _np.zeros((0, 3))
            self.neighbors = _np.zeros((0, 2), dtype=_np.int32)
            self.area = self.volume = 0.0

    def __repr__(self):
        return (f"hullkit.spatial.ConvexHull(npoints={self.npoints}, ndim={self.ndim}, dimension={self.dimension}, "
                f"vertices={len(self.vertices)}, simplices={len(self.simplices)})")


class Delaunay:
    """The Delaunay triangulation of points in 2D or tetrahedralization in 3D, exact (see the
    module's documentation).

    Attributes (scipy's): points, simplices, neighbors, convex_hull, vertex_neighbor_vertices,
    vertex_to_simplex, transform, coplanar, npoints, ndim, nsimplex, min_bound, max_bound; and
    dimension. Method: find_simplex.

    Examples
    --------
    >>> import numpy as np
    >>> from hullkit.spatial import Delaunay
    >>> cube = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)
    >>> d = Delaunay(cube)
    >>> d.ndim, d.nsimplex, d.simplices.dtype, d.convex_hull.shape, d.coplanar.shape
    (3, 6, dtype('int32'), (12, 3), (0, 3))
    >>> Delaunay([[0, 0], [1, 0], [0, 1]]).simplices.tolist()
    [[0, 1, 2]]
    """

    def __init__(self, points, furthest_site=False, incremental=False, qhull_options=None):
        for flag, what in ((furthest_site, "furthest_site=True"), (incremental, "incremental=True")):
            if flag:
                _not_supported(what, "Delaunay")
        if qhull_options is not None:
            _not_supported(f"qhull_options={qhull_options!r}", "Delaunay")
        try:
            array = _np.ascontiguousarray(points, dtype=_np.float64)
        except (TypeError, ValueError) as error:
            raise HullkitError(f"points must be numbers convertible to float64: {error}") from None
        if array.ndim != 2 or array.shape[1] not in (2, 3):
            if array.ndim == 2 and array.shape[1] > 3:
                _not_supported(f"Delaunay in {array.shape[1]} dimensions", "Delaunay")
            raise HullkitError(f"points must have shape (n, 2) or (n, 3), got {array.shape}")
        self.points = array
        self.npoints, self.ndim = array.shape
        self.min_bound, self.max_bound = _bounds(array, self.ndim)
        if self.ndim == 3:
            self._from_3d(array)
        else:
            self._from_2d(array)
        self.nsimplex = len(self.simplices)
        self.coplanar = _np.zeros((0, 3), dtype=_np.int32)
        if self._duplicate_count:
            representative = _np.asarray(self._representative, dtype=_np.int64)
            repeats = _np.flatnonzero(representative != _np.arange(self.npoints))
            simplex_of = self._corner_simplex()
            self.coplanar = _np.stack([repeats, simplex_of[representative[repeats]], representative[repeats]],
                                      axis=1).astype(_np.int32)

    # -- 2D ------------------------------------------------------------------------------------
    def _from_2d(self, xy):
        self._triangulation = d = delaunay(xy)
        self.dimension = d.dimension
        self._representative, self._duplicate_count = d.representative, d.duplicate_count
        # hullkit's triangles are clockwise with y up (delaunator's); scipy's counter-clockwise.
        # The corners reordered and the neighbours from the half-edges, in one pass in the core.
        with _translated():
            self.simplices, self.neighbors = d._core.scipy_arrays()
        hull_cycle = _np.asarray(d.hull, dtype=_np.int32)
        if d.dimension == 2:
            self.convex_hull = _np.stack([hull_cycle, _np.roll(hull_cycle, -1)], axis=1)
        elif d.dimension == 1:  # the points in order along the line: the chain of edges
            self.convex_hull = _np.stack([hull_cycle[:-1], hull_cycle[1:]], axis=1)
        else:
            self.convex_hull = _np.zeros((0, 2), dtype=_np.int32)
        self._chain = self.convex_hull

    # -- 3D ------------------------------------------------------------------------------------
    def _from_3d(self, xyz):
        self._tetrahedralization = d = delaunay3(xyz)
        self.dimension = d.dimension
        self._representative, self._duplicate_count = d.representative, d.duplicate_count
        # The core's uint32 indices are below 2**31 (it refuses more points): as int32 they are the
        # same bits, so scipy's dtype without a copy (read-only views of the core's arrays).
        self.simplices = d.tetrahedra.view(_np.int32)
        self.neighbors = d.neighbors if d.dimension == 3 else _np.zeros((0, 4), dtype=_np.int32)
        if d.dimension == 3:
            self.convex_hull = d.hull.view(_np.int32)
        elif d.dimension == 2:  # flat: the planar triangles are the (two-sided) hull's faces
            self.convex_hull = d.triangles.view(_np.int32)
        else:
            self.convex_hull = _np.zeros((0, 3), dtype=_np.int32)
        vertices = _np.asarray(d.vertices, dtype=_np.int32)  # collinear: in order along the line
        self._chain = _np.stack([vertices[:-1], vertices[1:]], axis=1) if d.dimension == 1 else self.convex_hull

    def find_simplex(self, xi, bruteforce=False, tol=None):
        """The simplex containing each point of ``xi`` (shape (..., ndim)), -1 outside the hull;
        exact. A point on an edge, face or vertex gets the lowest-indexed simplex around it
        (hullkit.Delaunay.locate, hullkit.Delaunay3.locate), and without simplices (flat input)
        every point gets -1. ``bruteforce`` and ``tol`` are
        accepted for scipy's signature and change nothing: the location is exact."""
        dims = self.ndim
        array = _np.asarray(xi, dtype=_np.float64)
        if array.shape[-1:] != (dims,):
            raise HullkitError(f"xi must have shape (..., {dims}), got {array.shape}")
        flat = as_points(array.reshape(-1, dims), dims, "xi")
        if dims == 3:
            found = self._tetrahedralization.locate(flat)["tetrahedron"]
            return found.reshape(array.shape[:-1])
        return self._triangulation.locate(flat)["triangle"].reshape(array.shape[:-1])

    @property
    def vertex_neighbor_vertices(self):
        """(indptr, indices): the neighbours of point k are indices[indptr[k]:indptr[k+1]],
        ascending. Without simplices, the neighbours along the line (or on the plane's triangles)."""
        cells = self.simplices if self.nsimplex else self._chain
        corners = cells.shape[1]
        if len(cells) == 0 or corners < 2:
            return _np.zeros(self.npoints + 1, dtype=_np.int32), _np.zeros(0, dtype=_np.int32)
        n = _np.int64(max(self.npoints, 1))
        cells = cells.astype(_np.int64)
        # Each edge once as the key lower * n + higher (one 1-D unique: sorting rows is far
        # slower), then both directions sorted by their first point.
        pairs = [(i, j) for i in range(corners) for j in range(i + 1, corners)]
        lower = _np.concatenate([_np.minimum(cells[:, i], cells[:, j]) for i, j in pairs])
        higher = _np.concatenate([_np.maximum(cells[:, i], cells[:, j]) for i, j in pairs])
        edges = _np.unique(lower * n + higher)
        lower, higher = edges // n, edges % n
        keys = _np.sort(_np.concatenate([edges, higher * n + lower]))
        indptr = _np.searchsorted(keys, _np.arange(self.npoints + 1, dtype=_np.int64) * n).astype(_np.int32)
        return indptr, (keys % n).astype(_np.int32)

    def _corner_simplex(self):
        """(npoints,) int32: the first simplex each point is a corner of, -1 for none."""
        simplex_of = _np.full(self.npoints, -1, dtype=_np.int32)
        if self.nsimplex:
            corners = self.simplices.shape[1]
            # Written from the last simplex to the first, so that the first one's write stays.
            order = _np.arange(self.nsimplex - 1, -1, -1, dtype=_np.int32)
            simplex_of[self.simplices[::-1].ravel()] = _np.repeat(order, corners)
        return simplex_of

    @property
    def vertex_to_simplex(self):
        """(npoints,) int32: a simplex each point is a corner of (as scipy's: the first), a
        duplicate its representative's (its ``coplanar`` row's), -1 when there are no simplices."""
        simplex_of = self._corner_simplex()
        simplex_of[self.coplanar[:, 0]] = self.coplanar[:, 1]
        return simplex_of

    @property
    def transform(self):
        """Barycentric transforms (nsimplex, ndim + 1, ndim): c = T^-1 (x - r) with
        T^-1 = transform[i, :ndim] and r = transform[i, ndim] (the simplex's last corner), as
        scipy's."""
        k = self.ndim
        if self.nsimplex == 0:
            return _np.zeros((0, k + 1, k))
        corners = self.points[self.simplices]
        r = corners[:, k]
        t = (corners[:, :k] - r[:, None]).transpose(0, 2, 1)  # columns: v_j - r
        out = _np.empty((self.nsimplex, k + 1, k))
        out[:, :k] = _np.linalg.inv(t)
        out[:, k] = r
        return out

    def __repr__(self):
        return (f"hullkit.spatial.Delaunay(npoints={self.npoints}, nsimplex={self.nsimplex}, "
                f"dimension={self.dimension})")
