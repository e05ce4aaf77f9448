"""scipy.spatial's ConvexHull, Delaunay, Voronoi and tsearch on hullkit's exact core: switching
is a change of import.

    from hullkit.spatial import ConvexHull, Delaunay, Voronoi   # instead of: from scipy.spatial import ...

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

Voronoi (2D on ``hullkit.delaunay(merge_cocircular=True)``, 3D on ``hullkit.Delaunay3.voronoi``):
``vertices``, ``ridge_points``, ``ridge_vertices``, ``ridge_dict``, ``regions``,
``point_region``, ``furthest_site``, ``points``, ``npoints``, ``ndim``, ``min_bound``,
``max_bound``; and ``volumes`` (each point's cell area or volume, inf when unbounded) and
``dimension``. Which vertices, ridges and regions exist is exact: cocircular or cospherical points
share one vertex (a grid's are the cell centres, exactly); 3D faces with one finite vertex, which
Qhull leaves out, are listed. A repeated point shares the region of the first point equal to it;
collinear or coplanar points give the diagram without vertices (see Voronoi).
``tsearch(tri, xi)`` is ``tri.find_simplex(xi)``.

4 to 10 dimensions (ConvexHull; Delaunay and Voronoi up to 9), on the core's exact
``hull_nd`` and ``delaunay_nd`` (quickhull on simplicial facets; Delaunay as the lower facets of
the points lifted to the paraboloid, a point at infinity above them so that points all on one
sphere triangulate too): ``simplices``, ``neighbors``, ``equations``, ``vertices``, ``volume``,
``area`` for the hull (facets triangulated, as Qhull's Qt); ``simplices`` (positively oriented),
``neighbors``, ``convex_hull``, ``find_simplex`` (exact: the lowest-indexed simplex holding the
point), ``transform``, ``coplanar`` (repeated points), ``furthest_site`` for Delaunay; Voronoi's
``vertices`` (circumcentres; exactly cospherical simplices share one, as Qhull merges them: a
grid's cell centres), ``ridge_points``, ``ridge_vertices``, ``regions`` and ``volumes`` (made on
first use from the triangulation's faces, in floating point: about a second for 5 000 points in
4D). A ridge is a pair of cells sharing a face of full dimension, decided exactly: points whose
cells meet in less (a grid's diagonal neighbours), which Qhull lists, are not ridges here. Points
in a flat raise HullkitError saying how many dimensions they span (Qhull's QH6154), and so does
ConvexHull's QG, Qc or Qi. Unbounded ridges around a hull edge with one or two simplices, which
Qhull leaves out, are listed.

HalfspaceIntersection (2 to 10 dimensions; above 3 the dual hull's simplicial facets merged where
exactly coplanar, each corner solved from the planes of one of them): the intersection of halfspaces A x + b <= 0 through the exact
hull of their dual points, scipy's attributes; ``chebyshev_center`` finds an interior point.

Incremental mode (``incremental=True``, ``add_points``, ``add_halfspaces``, ``close``) builds
again from everything added so far: the result is exactly that of one call with all of it.
``qhull_options``: the options that steer Qhull's precision handling or speed (Qt, QJ, Qbb, QbB,
Qz, Qx, Q11, Q12, Qs, Qv, Pp, Po) change nothing, since every decision is exact; Qc is accepted
by Delaunay, Voronoi and HalfspaceIntersection (Delaunay always lists its repeated points in
``coplanar``), Fv by Voronoi; ConvexHull takes QGn and QG-n (``good``), Qc (``coplanar``: the
points exactly on the boundary that are not vertices) and Qi (the points inside). Any other option raises
HullkitError naming it; so do more than 10 dimensions (9 for Delaunay and Voronoi).
``furthest_site=True`` (Delaunay, Voronoi): the furthest-site triangulation of the hull's
extreme points (every circumcircle or circumsphere holds every point) and its diagram, exactly: in
2D by Lawson's flips with the exact in-circle test, in 3D by the core's tetrahedralization with
every in-sphere answer negated (the upper hull of the lifted points; ties by the same
perturbation, no flat tetrahedron).

Only NaN or infinite coordinates and wrong shapes raise (HullkitError, a ValueError, naming the
point; ``QhullError`` is the same class, so scipy code that catches it keeps working).
"""
import gc as _gc
import re as _re

import numpy as _np

from . import HullkitError, _core, _threads, _translated, as_points, delaunay, delaunay3, hull

__all__ = ["ConvexHull", "Delaunay", "Voronoi", "HalfspaceIntersection", "QhullError", "chebyshev_center", "tsearch",
           "delaunay_plot_2d", "convex_hull_plot_2d", "voronoi_plot_2d"]

#: scipy.spatial's QhullError is hullkit's HullkitError here: ``except QhullError`` keeps working.
QhullError = HullkitError


def _bounds(array, ndim):
    """(min_bound, max_bound) of the points, column by column (numpy's min over axis 0 of an
    (n, 2) or (n, 3) array is many times slower); NaN without points."""
    if not len(array):
        return _np.full(ndim, _np.nan), _np.full(ndim, _np.nan)
    columns = [array[:, k] for k in range(ndim)]
    return _np.array([c.min() for c in columns]), _np.array([c.max() for c in columns])


def _not_supported(what, cls="ConvexHull"):
    raise HullkitError(f"{what} is not supported by hullkit.spatial.{cls}")


# Qhull's options, as scipy passes them on, and what each means for hullkit's exact classes (the
# README's table says the same). Options that steer Qhull's floating-point handling or speed change
# nothing here: every decision is already exact, and the output is always simplicial.
_NO_EFFECT = {
    "Qt": "triangulated output: hullkit's facets and simplices are always simplices",
    "QJ": "joggled input: nothing to joggle when every decision is exact (repeated points stay "
          "repeated: Delaunay lists them in coplanar)",
    "Qbb": "scaled last coordinate", "QbB": "scaled to the unit cube", "Qz": "point at infinity",
    "Qx": "exact pre-merges", "Q11": "merging order", "Q12": "wide facet merges",
    "Qs": "search all points for the initial simplex", "Qv": "test vertex neighbours",
    "Pp": "no precision warnings", "Po": "forced output",
}
_PER_CLASS = {
    # Coplanar points: Delaunay lists its repeats always; ConvexHull fills `coplanar` with them.
    "Qc": ("ConvexHull", "Delaunay", "Voronoi", "HalfspaceIntersection"),
    "Fv": ("Voronoi",),  # Voronoi ridges: hullkit's ridges are always listed
    "Qi": ("ConvexHull",),  # interior points in `coplanar`, with their nearest facet
}
_GOOD = _re.compile(r"QG(-?)([0-9]+)")


def _parsed_options(qhull_options, cls):
    """The Qhull options of a ``cls`` checked one by one: returns the QGn option as (n, visible)
    (ConvexHull only) or None, and the set of options given (None when ``qhull_options`` is);
    an option hullkit does not have raises HullkitError naming it."""
    if qhull_options is None:
        return None, None
    if isinstance(qhull_options, bytes):
        qhull_options = qhull_options.decode("latin-1")
    if not isinstance(qhull_options, str):
        raise HullkitError(f"qhull_options must be a string, got {type(qhull_options).__name__}")
    good = None
    for option in qhull_options.split():
        if option in _NO_EFFECT or cls in _PER_CLASS.get(option, ()):
            continue
        match = _GOOD.fullmatch(option)
        if match and cls == "ConvexHull":
            good = (int(match.group(2)), match.group(1) != "-")
            continue
        _not_supported(f"the Qhull option {option!r} (in qhull_options={qhull_options!r}; see the README's "
                       f"table of the options hullkit accepts)", cls)
    return good, set(qhull_options.split())


def _float64(values, what):
    """``values`` as a C-ordered float64 array, or HullkitError saying what could not be converted."""
    try:
        return _np.ascontiguousarray(values, dtype=_np.float64)
    except (TypeError, ValueError) as error:
        raise HullkitError(f"{what} must be numbers convertible to float64: {error}") from None


# The most dimensions each class takes: hulls up to 10 (the core's hull_nd), triangulations and
# diagrams up to 9 (their lifted hulls have one more).
_MAX_DIMENSIONS = {"ConvexHull": 10, "Delaunay": 9, "Voronoi": 9}


def _checked_points(points, cls, many=None, what="points"):
    """The points of a ``cls`` (ConvexHull, Delaunay, Voronoi) as a C-ordered float64 (n, k)
    array, 2 <= k <= _MAX_DIMENSIONS[cls], or HullkitError (``many``: what the message calls the
    object in more dimensions, the class's name by default)."""
    array = _float64(points, what)
    most = _MAX_DIMENSIONS[cls]
    if array.ndim != 2 or not 2 <= array.shape[1] <= most:
        if array.ndim == 2 and array.shape[1] > most:
            _not_supported(f"{many or cls} in {array.shape[1]} dimensions (at most {most})", cls)
        raise HullkitError(f"{what} must have shape (n, k) with 2 <= k <= {most}, got {array.shape}")
    return array


def _cofactor_normals(rows):
    """The normal of each set of k - 1 rows in k dimensions ((m, k - 1, k) in, (m, k) out): the
    generalised cross product, (-1)^j det(rows without column j); unnormalised."""
    return _np.stack([(-1) ** j * _np.linalg.det(_np.delete(rows, j, axis=2)) for j in range(rows.shape[2])], axis=1)


def _faces_without_neighbour(simplices, neighbors):
    """The faces of (m, k + 1) simplices across which ``neighbors`` is -1 (the hull's), (f, k)."""
    simplex, corner = _np.nonzero(neighbors == -1)
    keep = _np.arange(simplices.shape[1])[None, :] != corner[:, None]
    return simplices[simplex][keep].reshape(-1, simplices.shape[1] - 1)


def _edges_of_cells(points, simplices, vertex_of, cell_count, edge_keys, edge, cell, hull_faces):
    """Which edges of a triangulation of cospherical groups are edges of the Delaunay cells (the
    groups' polytopes), exactly: per edge a bool. Lifted to the paraboloid, with the hull's flat
    pieces joined to a point at infinity, the cells are the facets of one convex polytope, and a
    face of a polytope is the intersection of the facets holding it: an edge i-j of the
    triangulation is an edge of a cell when the corners common to every facet holding both i and
    j are i and j alone (a diagonal shares the whole face it crosses). The facets holding i and j
    are the groups around the edge (``edge``, ``cell``: sorted pairs) and, on the hull, the flat
    pieces of the hull around it; those pieces are the hull's faces joined across shared ridges
    where exactly coplanar (orient_nd)."""
    n = len(points)
    k = points.shape[1]
    e_count = len(edge_keys)
    # Each cell's corners: (cell, point) pairs.
    cell_points = _np.unique(_np.repeat(vertex_of, k + 1) * n + simplices.ravel())
    members = [(edge, cell, cell_points // n, cell_points % n, cell_count)]
    if len(hull_faces):
        # The hull's flat pieces: faces sharing a ridge (all corners but one) joined when coplanar.
        f = len(hull_faces)
        faces = _np.sort(hull_faces, axis=1)
        ridges = _np.concatenate([_np.delete(faces, drop, axis=1) for drop in range(k)])
        face_of = _np.tile(_np.arange(f), k)
        dropped = _np.concatenate([faces[:, drop] for drop in range(k)])
        order = _np.lexsort(ridges.T[::-1])
        ridges, face_of, dropped = ridges[order], face_of[order], dropped[order]
        same = _np.all(ridges[1:] == ridges[:-1], axis=1)
        parent = list(range(f))

        def find(x):
            while parent[x] != x:
                parent[x] = parent[parent[x]]
                x = parent[x]
            return x

        for at in _np.flatnonzero(same):
            a, b = int(face_of[at]), int(face_of[at + 1])
            ra, rb = find(a), find(b)
            if ra == rb:
                continue
            rows = _np.vstack([points[faces[a]], points[int(dropped[at + 1])]])
            if _core.orient_nd(_np.ascontiguousarray(rows, dtype=_np.float64)) == 0:
                parent[max(ra, rb)] = min(ra, rb)
        piece = _np.array([find(x) for x in range(f)], dtype=_np.int64)
        piece_points = _np.unique(_np.repeat(piece, k) * n + faces.ravel())
        # The pieces around each hull edge: its faces' pieces.
        face_pairs = [(i, j) for i in range(k) for j in range(i + 1, k)]
        keys = _np.concatenate([faces[:, i] * _np.int64(n) + faces[:, j] for i, j in face_pairs])
        owners = _np.tile(piece, len(face_pairs))
        at_edge = _np.searchsorted(edge_keys, keys)
        around = _np.unique(at_edge * _np.int64(f) + owners)
        members.append((around // f, around % f, piece_points // n, piece_points % n, f))
    # For each edge, how many of the facets holding it hold each point; the points held by all.
    facets_per_edge = _np.zeros(e_count, dtype=_np.int64)
    counted = []
    for edges_of, facet_of, owner_of, point_of, facet_count in members:
        _np.add.at(facets_per_edge, edges_of, 1)
        starts = _np.searchsorted(owner_of, _np.arange(facet_count + 1))
        sizes = starts[facet_of + 1] - starts[facet_of]
        rows = _np.repeat(_np.arange(len(facet_of)), sizes)
        position = _np.arange(len(rows)) - _np.repeat(_np.cumsum(sizes) - sizes, sizes)
        counted.append(edges_of[rows] * _np.int64(n) + point_of[starts[facet_of][rows] + position])
    keys, times = _np.unique(_np.concatenate(counted), return_counts=True)
    common = _np.bincount(keys[times == facets_per_edge[keys // n]] // n, minlength=e_count)
    return common == 2


def _nd_facet_planes(points, facets):
    """Unit normals and offsets [n, c] of hull_nd's facets (m, k): outward (hull_nd's corners are
    ordered so that det[[c_0, 1], ..., [c_k-1, 1], [q, 1]] > 0 beyond; that determinant is
    (-1)^k n . (q - c_0) for the cofactor normal n of the edges c_i - c_0)."""
    k = points.shape[1]
    corners = points[facets]
    first = corners[:, 0]
    edges = corners[:, 1:] - first[:, None]  # (m, k - 1, k)
    normal = -_cofactor_normals(edges)
    with _np.errstate(all="ignore"):
        normal /= _np.linalg.norm(normal, axis=1)[:, None]
    offset = -_np.einsum("mi,mi->m", normal, first)
    return _np.concatenate([normal, offset[:, None]], axis=1) if len(facets) else _np.zeros((0, k + 1))


class _Incremental:
    """scipy's incremental mode for a class that computes everything from all its points in
    ``_build(points)``: ``add_points`` builds again from all the points so far, so the result is
    exactly the one a single call with all of them gives (``restart`` changes nothing: each build
    starts afresh). Each addition costs a whole build."""

    def _start(self, incremental):
        self._incremental, self._closed = bool(incremental), False

    def add_points(self, points, restart=False):
        """Adds ``points`` (k, ndim) (needs ``incremental=True``; not after ``close()``)."""
        cls = type(self).__name__
        if not self._incremental:
            raise HullkitError(f"add_points needs {cls}(..., incremental=True)")
        if self._closed:
            raise HullkitError(f"add_points after close(): this {cls} takes no more points")
        array = _checked_points(points, cls)
        if array.shape[1] != self.ndim:
            raise HullkitError(f"points must have shape (k, {self.ndim}) like the first ones, got {array.shape}")
        self._build(_np.concatenate([self.points, array]))

    def close(self):
        """Ends the incremental mode: add_points raises from now on."""
        self._closed = True


class ConvexHull(_Incremental):
    """The convex hull of points in 2 to 10 dimensions (see the module's documentation).

    Attributes (scipy's): points, vertices, simplices, neighbors, equations, coplanar (with the
    option Qc: the points exactly on the boundary that are not vertices, each with a facet whose
    line or plane holds it and that facet's nearest corner; with Qi the points strictly inside,
    each with its nearest facet; empty without either), good (with the option
    QGn: None without), volume, area,
    npoints, ndim, min_bound, max_bound; and dimension. Methods: add_points, close
    (``incremental=True``).

    ``qhull_options="QGn"`` leaves point n out of the hull and sets ``good``: for each facet,
    whether point n is strictly beyond it (exactly: a point on a facet's line or plane does not see
    it); ``"QG-n"`` the opposite. Options that only steer Qhull's precision (Qt, Qbb, Qz, ...)
    change nothing; others raise HullkitError naming the option.

    Examples
    --------
    >>> from hullkit.spatial import ConvexHull
    >>> square = [[0.2, 0.2], [0.2, 0.4], [0.4, 0.4], [0.4, 0.2], [0.3, 0.6]]
    >>> hull = ConvexHull(square, qhull_options="QG4")
    >>> hull.simplices[hull.good].tolist()  # the square's side that (0.3, 0.6) sees
    [[2, 1]]
    >>> grown = ConvexHull(square[:4], incremental=True)
    >>> grown.add_points([[0.3, 0.6]])
    >>> sorted(grown.vertices.tolist())
    [0, 1, 2, 3, 4]
    """

    def __init__(self, points, incremental=False, qhull_options=None):
        self._good_option, options = _parsed_options(qhull_options, "ConvexHull")
        self._keep_coplanar = options is not None and "Qc" in options
        self._keep_interior = options is not None and "Qi" in options
        self._start(incremental)
        self._build(_checked_points(points, "ConvexHull", "a hull"))

    def _build(self, array):
        self.points = array
        self.npoints, self.ndim = array.shape
        self.min_bound, self.max_bound = _bounds(array, self.ndim)
        self.coplanar = _np.zeros((0, 3), dtype=_np.int32)
        self.good = None
        kept = array
        if self._good_option is not None:
            seen_from, visible = self._good_option
            if seen_from >= self.npoints:
                raise HullkitError(f"QG{'' if visible else '-'}{seen_from}: there is no point {seen_from} "
                                   f"({self.npoints} points)")
            kept = _np.delete(array, seen_from, axis=0)
        if self.ndim > 3 and (self._good_option is not None or self._keep_coplanar or self._keep_interior):
            _not_supported(f"the options QG, Qc and Qi in {self.ndim} dimensions")
        if self.ndim > 3:
            self._from_nd(kept)
        elif self.ndim == 3:
            self._from_3d(hull(as_points(kept, 3)), kept)
        else:
            self._from_2d(kept)
        if self._good_option is not None:
            # Point n left out: indices at and after it move up by one.
            for name in ("vertices", "simplices"):
                indices = getattr(self, name)
                setattr(self, name, indices + (indices >= seen_from).astype(_np.int32))
            with _translated():
                sides = _core.facet_sides(array, _np.ascontiguousarray(self.simplices, dtype=_np.uint32),
                                          array[seen_from: seen_from + 1])[0]
            self.good = sides > 0 if visible else sides <= 0
        if self._keep_coplanar or self._keep_interior:
            self.coplanar = self._boundary_points()

    def _boundary_points(self):
        """Qc: the points on the hull's boundary that are not vertices, exactly (each against every
        facet's line or plane: _core.facet_holding), as rows (point, a facet whose line or plane
        holds it, that facet's nearest corner). Qi: the points strictly inside, with the facet whose
        plane is nearest (the largest signed distance, in floating point: a choice of facet, not a
        decision about the hull) and its nearest corner. Rows in point order."""
        candidates = _np.ones(self.npoints, dtype=bool)
        candidates[self.vertices] = False
        if self._good_option is not None:
            candidates[self._good_option[0]] = False  # QGn's point is no part of the hull
        candidates = _np.flatnonzero(candidates)
        if not len(candidates) or not len(self.simplices):
            return _np.zeros((0, 3), dtype=_np.int32)
        with _translated():
            facet = _core.facet_holding(self.points, _np.ascontiguousarray(self.simplices, dtype=_np.uint32),
                                        self.points[candidates])
        on = facet >= 0
        if self._keep_interior:  # the interior points' nearest facet
            inside = _np.flatnonzero(~on)
            normals, offsets = self.equations[:, :-1], self.equations[:, -1]
            for start in range(0, len(inside), 8192):
                rows = inside[start: start + 8192]
                facet[rows] = (self.points[candidates[rows]] @ normals.T + offsets).argmax(axis=1)
            keep = _np.ones_like(on) if self._keep_coplanar else ~on
        else:
            keep = on
        points, facet = candidates[keep], facet[keep]
        corners = self.simplices[facet]  # (k, ndim)
        distance = _np.linalg.norm(self.points[corners] - self.points[points][:, None, :], axis=2)
        nearest = corners[_np.arange(len(points)), distance.argmin(axis=1)]
        return _np.stack([points, facet, nearest], axis=1).astype(_np.int32)

    # -- 4D and up -----------------------------------------------------------------------------
    def _from_nd(self, points):
        """The core's exact hull in k dimensions (hullkit::hull_nd): simplicial facets, each with its
        neighbours (across from each corner); vertices ascending; volume and area from the facets."""
        with _translated():
            self.simplices, self.neighbors, self.vertices, self._groups = _core.hull_nd(points)
        self.dimension = k = self.ndim
        self.equations = _nd_facet_planes(points, self.simplices)
        corners = points[self.simplices]
        inside = points[self.vertices].mean(axis=0)
        factorial_k = float(_np.prod(_np.arange(1, k + 1)))
        self.volume = float(_np.abs(_np.linalg.det(corners - inside)).sum() / factorial_k)
        edges = corners[:, 1:] - corners[:, :1]
        gram = _np.einsum("mik,mjk->mij", edges, edges)
        self.area = float(_np.sqrt(_np.clip(_np.linalg.det(gram), 0, None)).sum() * k / factorial_k)

    # -- 3D ------------------------------------------------------------------------------------
    def _from_3d(self, h, xyz):
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
            offset = -float(normal @ xyz[self.vertices[0]])
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


class Delaunay(_Incremental):
    """The Delaunay triangulation of points in 2D, tetrahedralization in 3D or triangulation in 4 to 9
    dimensions, exact (see the module's documentation).

    Attributes (scipy's): points, simplices, neighbors, equations, paraboloid_scale,
    paraboloid_shift, convex_hull, vertex_neighbor_vertices, vertex_to_simplex, transform,
    coplanar, npoints, ndim, nsimplex, min_bound, max_bound; and dimension. Methods:
    find_simplex, lift_points, plane_distance, add_points and close (``incremental=True``).

    ``furthest_site=True``: the triangulation (2D) or tetrahedralization (3D) of the hull's extreme
    points whose circumcircles or circumspheres hold every point (the upper hull of the lifted
    points), exact; ``equations`` then point up, and points inside the hull (or inside a hull face
    or edge) are in no simplex (``coplanar`` is empty, as scipy's). Coplanar 3D points: no
    simplices, ``convex_hull`` the furthest-site triangles of the polygon's corners.

    ``equations`` are the planes of the simplices lifted onto the paraboloid
    z = paraboloid_scale * |x|^2 + paraboloid_shift (scale 1, shift 0: hullkit does not rescale),
    unit normals pointing down, as scipy's; they are computed on first use (the triangulation
    itself never uses them: its decisions are exact).

    Examples
    --------
    >>> import numpy as np
    >>> from hullkit.spatial import Delaunay
    >>> cube = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)
    >>> d = Delaunay(cube)
    >>> d.ndim, d.nsimplex, d.simplices.dtype, d.convex_hull.shape, d.coplanar.shape
    (3, 6, dtype('int32'), (12, 3), (0, 3))
    >>> tri = Delaunay([[0, 0], [1, 0], [0, 1]])
    >>> tri.simplices.tolist(), tri.lift_points([1, 2]).tolist()
    ([[0, 1, 2]], [1.0, 2.0, 5.0])
    >>> float(tri.plane_distance([0.25, 0.25])[0]) > 0  # below the lifted triangle: inside its circle
    True
    """

    paraboloid_scale = 1.0
    paraboloid_shift = 0.0

    def __init__(self, points, furthest_site=False, incremental=False, qhull_options=None):
        _parsed_options(qhull_options, "Delaunay")
        self._furthest = bool(furthest_site)
        self._start(incremental)
        self._build(_checked_points(points, "Delaunay"))

    def _build(self, array):
        self.points = array
        self.npoints, self.ndim = array.shape
        self.min_bound, self.max_bound = _bounds(array, self.ndim)
        self._equations = None
        if self.ndim > 3:
            self._from_nd(array)
        elif self.ndim == 3:
            self._from_3d(array)
        else:
            self._from_2d(array)
            if self._furthest and self.dimension == 2:
                self._furthest_2d(array)
        self.nsimplex = len(self.simplices)
        self.coplanar = _np.zeros((0, 3), dtype=_np.int32)
        if self._duplicate_count and not self._furthest:
            representative = _np.asarray(self._representative, dtype=_np.int64)
            repeats = _np.flatnonzero(representative != _np.arange(self.npoints))
            simplex_of = self._corner_simplex()
            self.coplanar = _np.stack([repeats, simplex_of[representative[repeats]], representative[repeats]],
                                      axis=1).astype(_np.int32)

    @property
    def vertices(self):
        """The old name of ``simplices`` (scipy's, deprecated there: a DeprecationWarning)."""
        import warnings
        warnings.warn("Delaunay attribute 'vertices' is deprecated in favour of 'simplices' and will be removed "
                      "in Scipy 1.11.0. (hullkit keeps it for code written against scipy; use 'simplices'.)",
                      DeprecationWarning, stacklevel=2)
        return self.simplices

    def lift_points(self, x):
        """``x`` (..., ndim) lifted onto the paraboloid: (..., ndim + 1), the last coordinate
        paraboloid_scale * |x|^2 + paraboloid_shift."""
        array = _np.asarray(x, dtype=_np.float64)
        if array.shape[-1:] != (self.ndim,):
            raise HullkitError(f"x must have shape (..., {self.ndim}), got {array.shape}")
        lifted = _np.empty(array.shape[:-1] + (self.ndim + 1,))
        lifted[..., :-1] = array
        lifted[..., -1] = (array * array).sum(axis=-1) * self.paraboloid_scale + self.paraboloid_shift
        return lifted

    @property
    def equations(self):
        """(nsimplex, ndim + 2): each simplex's lifted plane [unit normal, offset], the normal's
        last component negative; a lifted point x has distance normal . x + offset (positive
        below the plane: inside the simplex's circumcircle or sphere)."""
        if self._equations is None:
            k = self.ndim
            corners = self.points[self.simplices]
            first = corners[:, 0]
            edges = corners[:, 1:] - first[:, None]  # (m, k, k)
            # Lifted edge heights |v|^2 - |a|^2 as (v - a) . (v + a): no cancellation of the squares.
            heights = _np.einsum("mij,mij->mi", edges, corners[:, 1:] + first[:, None]) * self.paraboloid_scale
            rows = _np.concatenate([edges, heights[:, :, None]], axis=2)  # (m, k, k + 1)
            # The normal of the k rows in k + 1 dimensions: its cofactors (the generalised cross product).
            normal = _cofactor_normals(rows)
            with _np.errstate(all="ignore"):  # a flat simplex (none here) would give NaN, not a warning
                normal /= _np.linalg.norm(normal, axis=1)[:, None]
            normal *= _np.sign(normal[:, -1:]) * (1 if self._furthest else -1)  # up for the upper hull
            lifted_first = self.lift_points(first)
            offset = -_np.einsum("mi,mi->m", normal, lifted_first)
            self._equations = _np.concatenate([normal, offset[:, None]], axis=1) if len(corners) else _np.zeros((0, k + 2))
        return self._equations

    def plane_distance(self, xi):
        """The distance of each point of ``xi`` (..., ndim), lifted, to every simplex's lifted plane:
        (..., nsimplex), positive below the plane (see ``equations``)."""
        lifted = self.lift_points(xi)
        eq = self.equations
        return lifted @ eq[:, :-1].T + eq[:, -1]

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

    def _furthest_2d(self, xy):
        """furthest_site=True (2D): the triangulation of the hull's corners whose circumcircles hold
        every point (exactly: _core.furthest_delaunay, Lawson's flips with the exact in-circle
        test); its hull the corners' cycle. Points inside the hull are in no simplex."""
        with _translated():
            self.simplices, self.neighbors, self._groups, self._centres, corners = _core.furthest_delaunay(
                xy, _np.ascontiguousarray(self._triangulation.hull, dtype=_np.uint32))
        self.convex_hull = _np.stack([corners, _np.roll(corners, -1)], axis=1).astype(_np.int32)
        self._chain = self.convex_hull

    # -- 4D and up -----------------------------------------------------------------------------
    def _from_nd(self, points):
        """The core's exact triangulation in k dimensions (hullkit::delaunay_nd: the lower, or with
        furthest_site the upper, facets of the lifted hull); the hull's faces are the simplices'
        faces without a neighbour."""
        with _translated():
            self._triangulation_nd = t = _core.TriangulationNd(points, self._furthest)
        self.dimension = self.ndim
        self._representative, self._duplicate_count = t.representative, t.duplicate_count
        self.simplices, self.neighbors = t.simplices, t.neighbors
        self.convex_hull = _faces_without_neighbour(self.simplices, self.neighbors).astype(_np.int32)
        self._chain = self.convex_hull

    # -- 3D ------------------------------------------------------------------------------------
    def _from_3d(self, xyz):
        # furthest_site=True: the core's furthest-site tetrahedralization (its corners the hull's
        # extreme points; coplanar points: the furthest-site triangles of the polygon's corners).
        self._tetrahedralization = d = delaunay3(xyz, furthest_site=self._furthest)
        self.dimension = d.dimension
        self._representative, self._duplicate_count = d.representative, d.duplicate_count
        # The core's uint32 indices are below 2**31 (it refuses more points): as int32 they are the
        # same bits. Copies, writable as scipy's are (the core's arrays stay read-only: its
        # point location reads them).
        self.simplices = d.tetrahedra.astype(_np.int32)
        self.neighbors = d.neighbors.copy() if d.dimension == 3 else _np.zeros((0, 4), dtype=_np.int32)
        if d.dimension == 3:
            self.convex_hull = d.hull.astype(_np.int32)
        elif d.dimension == 2:  # flat: the planar triangles are the (two-sided) hull's faces
            self.convex_hull = d.triangles.astype(_np.int32)
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
        if dims > 3:
            with _translated():
                return self._triangulation_nd.locate(flat).reshape(array.shape[:-1])
        if self._furthest and dims == 2:
            return self._furthest_find(flat).reshape(array.shape[:-1])
        if dims == 3:
            found = self._tetrahedralization.locate(flat)["tetrahedron"]
            return found.reshape(array.shape[:-1])
        return self._triangulation.locate(flat)["triangle"].reshape(array.shape[:-1])

    def _furthest_find(self, flat):
        """find_simplex in the furthest-site triangulation: each query against every triangle's
        edges (exactly, _core.facet_sides); the lowest-indexed triangle holding it, -1 outside."""
        found = _np.full(len(flat), -1, dtype=_np.int32)
        if not self.nsimplex:
            return found
        edges = _np.ascontiguousarray(self.simplices[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2), dtype=_np.uint32)
        for start in range(0, len(flat), 4096):  # (queries, simplices) sides a block at a time
            with _translated():
                sides = _core.facet_sides(self.points, edges, flat[start: start + 4096])
            inside = (sides.reshape(len(sides), -1, 3) <= 0).all(axis=2)
            hit = inside.any(axis=1)
            found[start: start + len(sides)][hit] = inside[hit].argmax(axis=1)
        return found

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
        scipy's. As scipy's too, a simplex so flat that its inverse cannot be trusted in floating
        point (reciprocal condition number below 1000 eps) gets NaN in T^-1 (the exact
        triangulation keeps such slivers where the points make them; find_simplex is exact)."""
        k = self.ndim
        if self.nsimplex == 0:
            return _np.zeros((0, k + 1, k))
        corners = self.points[self.simplices]
        r = corners[:, k]
        t = (corners[:, :k] - r[:, None]).transpose(0, 2, 1)  # columns: v_j - r
        with _np.errstate(all="ignore"):
            singular = ~(_np.abs(_np.linalg.det(t)) > 0)
            inverse = _np.linalg.inv(_np.where(singular[:, None, None], _np.eye(k), t))
            # 1-norm condition: the largest column sum of |T| times that of |T^-1|.
            condition = _np.abs(t).sum(axis=1).max(axis=1) * _np.abs(inverse).sum(axis=1).max(axis=1)
            untrusted = singular | ~(1.0 / condition >= 1000 * _np.finfo(float).eps)
        inverse[untrusted] = _np.nan
        out = _np.empty((self.nsimplex, k + 1, k))
        out[:, :k] = inverse
        out[:, k] = r
        return out

    def __repr__(self):
        return (f"hullkit.spatial.Delaunay(npoints={self.npoints}, nsimplex={self.nsimplex}, "
                f"dimension={self.dimension})")


def tsearch(tri, xi):
    """The simplex of ``tri`` (a hullkit.spatial.Delaunay) holding each point of ``xi``: the same
    as ``tri.find_simplex(xi)``, as scipy.spatial.tsearch (-1 outside; exact).

    Examples
    --------
    >>> from hullkit.spatial import Delaunay, tsearch
    >>> tsearch(Delaunay([[0, 0], [1, 0], [0, 1]]), [[0.25, 0.25], [1, 1]]).tolist()
    [0, -1]
    """
    if not hasattr(tri, "find_simplex"):
        raise HullkitError(f"tsearch needs a Delaunay triangulation, got {type(tri).__name__}")
    return tri.find_simplex(xi)


# -- Voronoi ---------------------------------------------------------------------------------------

class _no_collection:
    """Python's cyclic garbage collector paused while millions of lists are made (it would walk
    them over and over: twice the time), and restored as it was."""

    def __enter__(self):
        self._was = _gc.isenabled()
        _gc.disable()

    def __exit__(self, *exc):
        if self._was:
            _gc.enable()
        return False


def _grouped(flat, offsets, rows=None, leading_empty=False):
    """Python lists flat[offsets[r]:offsets[r + 1]] of ints for each r in ``rows`` (all when
    None), after an empty one with ``leading_empty`` (made in the core: _core.nested_lists)."""
    rows = _np.zeros(0, dtype=_np.int64) if rows is None else _np.ascontiguousarray(rows, dtype=_np.int64)
    with _no_collection(), _translated():
        return _core.nested_lists(_np.ascontiguousarray(flat, dtype=_np.int64),
                                  _np.ascontiguousarray(offsets, dtype=_np.int64), rows, bool(leading_empty))


def _offsets(sizes):
    return _np.concatenate([[0], _np.cumsum(sizes)]).astype(_np.int64)


class Voronoi(_Incremental):
    """The Voronoi diagram of points in 2 to 9 dimensions, with scipy.spatial.Voronoi's attributes, on
    hullkit's exact Delaunay (which vertices, ridges and regions exist is decided exactly; the
    coordinates are rounded).

    Attributes (scipy's): ``points``, ``npoints``, ``ndim``, ``min_bound``, ``max_bound``,
    ``vertices`` (nv, ndim) float64, ``ridge_points`` (nr, 2) int32 (p < q), ``ridge_vertices``
    (a list per ridge; -1 is the vertex at infinity), ``ridge_dict`` ({(p, q): ridge vertices}),
    ``regions`` (lists of vertex indices, -1 in an unbounded one), ``point_region`` (intp, each
    point's index into ``regions``), ``furthest_site``. And two scipy lacks: ``volumes``
    (per point, its cell's area in 2D or volume in 3D; inf when unbounded) and ``dimension``
    (what the points span: 2 or 3, less for degenerate input).

    * Cocircular (2D) or cospherical (3D and up) points share one vertex, as Qhull merges them (a
      grid has one vertex per square or cube, exactly at its centre). Above 3D a ridge is a pair
      of cells sharing a face of full dimension (decided exactly); Qhull also lists pairs of a
      grid's diagonal neighbours, whose cells meet in a smaller face.
    * 2D: ``regions`` are counter-clockwise, a bounded one from its lowest vertex, an unbounded
      one with -1 last (between its last and first vertex); a ridge is ``[a, b]``, or
      ``[-1, a]`` for a ray. 2D vertices are numbered along a space-filling curve (nearby
      vertices are near each other in the array; Qhull's order is its own). 3D: a region lists its
      vertices ascending (-1 first if unbounded; scipy's order is Qhull's); a ridge lists its
      face's vertices in order around it, an unbounded face ``[-1, a, ..., b]`` (the chain between
      its two rays). Unlike Qhull, every face is listed, also an unbounded one with a single
      finite vertex (Qhull's option Fv leaves out ridges that need two rays).
    * ``regions[0]`` is empty, as scipy's (the region of Qhull's point at infinity), and there is
      one more region for each distinct point: ``len(regions)`` is the number of distinct points
      plus one. With ``qhull_options`` that leave out Qz (scipy's default has it) there is no
      empty region, as in scipy: ``len(regions)`` is the number of distinct points.
    * Repeated points: the lowest index of each set of equal points has the cell; the others share
      its ``point_region`` and ``volumes`` entry and have no ridges of their own.
    * Where scipy raises QhullError, hullkit gives the diagram that exists: collinear 2D points
      have no vertices, and parallel lines between consecutive points along the line as ridges
      (``[-1, -1]``: both ends at infinity); in 3D, coplanar points have no vertices and a ridge
      ``[-1]`` between each pair of points whose cells share a face (the planar Voronoi edge swept
      along the normal), collinear points a plane ``[-1]`` between consecutive points. One point
      has the whole space as its cell (region ``[-1]``). Every cell is then unbounded.
    * ``furthest_site=True``: each extreme point's furthest-site cell (unbounded; in 2D
      counter-clockwise with -1 last, in 3D ascending with -1 first), the other points' cells empty
      (volume 0; in 2D they share region 0, in 3D each has its own empty region, as scipy's). Coplanar or
      collinear points in 3D, and collinear ones in 2D, raise "not supported" (scipy raises too).
      ``qhull_options`` as the module says;
      NaN or infinite coordinates and wrong shapes raise HullkitError (a ValueError).

    Examples
    --------
    >>> import numpy as np
    >>> from hullkit.spatial import Voronoi
    >>> points = np.array([[x, y] for x in range(3) for y in range(3)], dtype=float)
    >>> vor = Voronoi(points)
    >>> vor.vertices.tolist()
    [[0.5, 0.5], [1.5, 0.5], [1.5, 1.5], [0.5, 1.5]]
    >>> vor.regions[vor.point_region[4]]  # the centre's cell, counter-clockwise
    [0, 1, 2, 3]
    >>> vor.regions[vor.point_region[1]]  # (0, 1)'s: unbounded, -1 last
    [0, 3, -1]
    >>> vor.ridge_dict[(1, 4)], vor.ridge_dict[(0, 1)]
    ([3, 0], [-1, 0])
    >>> vor.volumes.tolist()[:5]
    [inf, inf, inf, inf, 1.0]
    >>> cube = np.array([[x, y, z] for x in range(3) for y in range(3) for z in range(3)], dtype=float)
    >>> vor3 = Voronoi(cube)
    >>> len(vor3.vertices), float(vor3.volumes[13]), sorted(vor3.regions[vor3.point_region[13]])
    (8, 1.0, [0, 1, 2, 3, 4, 5, 6, 7])
    """

    def __init__(self, points, furthest_site=False, incremental=False, qhull_options=None):
        self._furthest = bool(furthest_site)
        # scipy's regions[0] is empty: the region of the point at infinity that Qhull's option Qz
        # (in scipy's default options) adds. Options given without Qz: no such region, as scipy's.
        options = _parsed_options(qhull_options, "Voronoi")[1]
        self._infinity_region = options is None or "Qz" in options
        self._start(incremental)
        self._build(_checked_points(points, "Voronoi"))

    def _build(self, array):
        self.points = array
        self.npoints, self.ndim = array.shape
        self.min_bound, self.max_bound = _bounds(array, self.ndim)
        self.furthest_site = self._furthest
        self._ridge_dict = self._ridge_vertices = self._regions = None
        self._volumes = self._volume_parts = None
        if self.ndim > 3:
            parts = self._from_nd(array)
        elif self._furthest and self.ndim == 2:
            parts = self._furthest_2d(array)
        else:
            parts = self._from_3d(array) if self.ndim == 3 else self._from_2d(array)
        if parts is None:  # the core made every array (2D)
            return
        representative, cells, offsets, volumes = parts
        # One region per distinct point (ascending), after scipy's empty one.
        representative = _np.asarray(representative, dtype=_np.intp)
        distinct = _np.flatnonzero(representative == _np.arange(self.npoints))
        region = _np.zeros(self.npoints, dtype=_np.intp)
        first = 1 if self._infinity_region else 0
        region[distinct] = _np.arange(first, len(distinct) + first)
        self.point_region = region[representative]
        self._region_lists = (cells, offsets, distinct)
        if volumes is None:  # 4D and up: computed on first use from _volume_parts (see volumes)
            self._volumes = None
        else:
            self.volumes = volumes[representative]

    @property
    def volumes(self):
        """Each point's cell area (2D) or volume, inf when unbounded (a repeated point: its
        representative's). Above 3 dimensions made on first use, in floating point, from the
        Delaunay triangulation's faces and their circumcentres (hullkit::voronoi_nd_volumes: each
        cell a signed sum of orthoschemes, every face visited once)."""
        if self._volumes is None and self._volume_parts is not None:
            triangulation, representative = self._volume_parts
            with _translated():
                volumes = triangulation.cell_volumes()
            self._volumes = volumes[_np.asarray(representative, dtype=_np.intp)]
        return self._volumes

    @volumes.setter
    def volumes(self, value):
        self._volumes = value

    # The lists are made on first use, from flat arrays (millions of small Python lists cost more
    # time and memory than the diagram; a user who reads only the vertices, ridge_points,
    # point_region or volumes never pays for them).
    @property
    def regions(self):
        """scipy's regions: a list of vertex indices per region (made on first use)."""
        if self._regions is None:
            self._regions = _grouped(*self._region_lists, leading_empty=self._infinity_region)
        return self._regions

    @property
    def ridge_vertices(self):
        """scipy's ridge_vertices: a list of vertex indices per ridge, -1 at infinity (made on
        first use)."""
        if self._ridge_vertices is None:
            self._ridge_vertices = _grouped(*self._ridge_lists)
        return self._ridge_vertices

    @property
    def ridge_dict(self):
        """{(p, q): ridge vertices} for each ridge (scipy's; built once, on first use)."""
        if self._ridge_dict is None:
            self._ridge_dict = dict(zip(map(tuple, self.ridge_points.tolist()), self.ridge_vertices))
        return self._ridge_dict

    def _without_vertices(self, representative):
        """No vertices: every distinct point's cell unbounded (region [-1], volume inf)."""
        self.vertices = _np.zeros((0, self.ndim))
        distinct = _np.asarray(representative) == _np.arange(self.npoints)
        return (representative, _np.full(int(distinct.sum()), -1, dtype=_np.int64), _offsets(distinct),
                _np.where(distinct, _np.inf, _np.nan))

    def _along_line(self, representative, chain, ridge):
        """Points on a line (or one point): ridges between the points of ``chain`` consecutive in
        it (``ridge``: each one's vertex list), no vertices."""
        chain = _np.asarray(chain, dtype=_np.int64)
        count = max(len(chain) - 1, 0)
        self._set_ridges(_np.stack([chain[:-1], chain[1:]], axis=1) if count else _np.zeros((0, 2)),
                         _np.tile(_np.asarray(ridge, dtype=_np.int64), count), _offsets(_np.full(count, len(ridge))))
        return self._without_vertices(representative)

    def _set_ridges(self, pairs, flat, offsets):
        """ridge_points from the pairs (each sorted); ridge k's vertices flat[offsets[k]:offsets[k + 1]]."""
        self.ridge_points = _np.sort(_np.asarray(pairs, dtype=_np.int64).reshape(-1, 2), axis=1).astype(_np.int32)
        self._ridge_lists = (flat, offsets)

    # -- 2D ------------------------------------------------------------------------------------
    def _from_2d(self, xy):
        """The diagram made in the core (hullkit::delaunay_voronoi_diagram, through
        Triangulation.scipy_voronoi: one vertex per Delaunay polygon, exactly cocircular triangles
        merged; a ridge per Delaunay edge; each point's cell counter-clockwise); None when done."""
        with _translated():
            core = _core.Triangulation(xy, "incremental", False, 0)
        self.dimension = core.dimension
        if core.dimension < 2:  # collinear: the points in order along the line (or one point)
            return self._along_line(core.representative, core.hull, (-1, -1))
        with _translated():
            (self.vertices, self.ridge_points, ridge_vertices, cells, offsets, self.point_region,
             self.volumes) = core.scipy_voronoi(self._infinity_region)
        self._ridge_lists = (ridge_vertices.ravel(), _np.arange(0, 2 * len(ridge_vertices) + 1, 2, dtype=_np.int64))
        self._region_lists = (cells, offsets, None)
        return None

    def _furthest_2d(self, xy):
        """furthest_site=True (2D): the diagram of the points' furthest-site cells, dual to the
        furthest-site Delaunay triangulation (Delaunay(furthest_site=True)): a vertex per group of
        exactly cocircular triangles, a ridge per edge between two groups or on the hull (a ray),
        a cell (unbounded: -1 last) for each hull corner, counter-clockwise; the other points'
        cells are empty (region 0, volume 0)."""
        tri = Delaunay(xy, furthest_site=True)
        self.dimension = tri.dimension
        if tri.nsimplex == 0:
            _not_supported("furthest_site=True for collinear points or fewer than three distinct points", "Voronoi")
        self._infinity_region = True  # the points that are no corner share the empty region 0
        simplices, neighbors, groups = tri.simplices, tri.neighbors, tri._groups
        self.vertices = tri._centres
        pairs, ridges = [], []
        for q in range(tri.nsimplex):
            for k in range(3):
                other = int(neighbors[q, k])
                edge = (int(simplices[q, (k + 1) % 3]), int(simplices[q, (k + 2) % 3]))
                if other < 0:
                    pairs.append(edge), ridges.append((-1, int(groups[q])))
                elif other > q and groups[other] != groups[q]:
                    pairs.append(edge), ridges.append((int(groups[other]), int(groups[q])))
        self._set_ridges(pairs, _np.asarray(ridges, dtype=_np.int64).reshape(-1), _np.arange(0, 2 * len(ridges) + 1, 2))
        # Each corner's triangles, counter-clockwise around it: from the one whose edge to the next
        # corner is on the hull, across the edge to the previous corner, to the hull again.
        at = {}
        for q in range(tri.nsimplex):
            for k in range(3):
                at.setdefault(int(simplices[q, k]), []).append((q, k))
        corners = sorted(at)
        cells, sizes = [], []
        for p in corners:
            place = dict(at[p])
            q = next(t for t, k in at[p] if neighbors[t, (k + 2) % 3] < 0)
            chain = []
            while q >= 0:
                if not chain or chain[-1] != groups[q]:
                    chain.append(int(groups[q]))
                q = int(neighbors[q, (place[q] + 1) % 3])
            cells += chain + [-1]
            sizes.append(len(chain) + 1)
        region = _np.zeros(self.npoints, dtype=_np.intp)
        region[corners] = _np.arange(1, len(corners) + 1)
        self.point_region = region
        self._region_lists = (_np.asarray(cells, dtype=_np.int64), _offsets(sizes), None)
        self.volumes = _np.where(region > 0, _np.inf, 0.0)
        return None

    # -- 3D ------------------------------------------------------------------------------------
    def _from_3d(self, xyz):
        d = delaunay3(xyz, furthest_site=self._furthest)
        self.dimension = d.dimension
        if self._furthest and d.dimension < 3:
            _not_supported("furthest_site=True for coplanar or collinear 3D points", "Voronoi")
        if d.dimension == 3:
            # Furthest-site: the diagram dual to the furthest-site tetrahedralization (each extreme
            # point's cell unbounded; a point in no tetrahedron has an empty cell, volume 0).
            v = d.voronoi()
            self.vertices = v["vertices"]
            cells, offsets = self._faces_3d(v, len(xyz))
            volume = v["volume"]
            if self._furthest:
                volume = _np.where((_np.diff(offsets) == 0) & ~_np.isnan(volume), 0.0, volume)
            return (d.representative, cells, offsets, volume)
        if d.dimension == 2:
            return self._coplanar_3d(xyz, d)
        return self._along_line(d.representative, d.vertices, (-1,))

    def _from_nd(self, points):
        """k dimensions from the core's triangulation (hullkit::delaunay_nd): a vertex per group of
        simplices with one circumsphere (its circumcentre: one simplex per group in general
        position; a grid's cells, as Qhull merges them), a ridge per Delaunay edge (its vertices:
        the groups around the edge, after a -1 when the edge lies on the hull), each point's cell
        the groups around it (after a -1 when the point is on the hull). With cospherical points an
        edge of the triangulation may be a diagonal of a group (two points whose cells meet in less
        than a ridge): see _edges_of_cells."""
        if self._furthest:
            _not_supported(f"furthest_site=True in {self.ndim} dimensions", "Voronoi")
        k = self.ndim
        with _translated():
            t = _core.TriangulationNd(points)
        self.dimension = k
        self._volume_parts = (t, t.representative)  # the volumes, on first use
        simplices = t.simplices.astype(_np.int64)
        m, n = len(simplices), len(points)
        # One vertex per group, numbered in the order of the groups' lowest simplices.
        group = t.group.astype(_np.int64)
        cospherical = bool((group != _np.arange(m)).any())
        if cospherical:
            roots, vertex_of = _np.unique(group, return_inverse=True)
            vertex_of = vertex_of.reshape(-1)
        else:
            roots = vertex_of = _np.arange(m, dtype=_np.int64)
        corners = points[simplices[roots] if cospherical else simplices]
        first = corners[:, 0]
        edges = corners[:, 1:] - first[:, None]
        rhs = 0.5 * _np.einsum("mij,mij->mi", edges, corners[:, 1:] + first[:, None])
        self.vertices = _np.linalg.solve(edges, rhs[..., None])[..., 0] if m else _np.zeros((0, k))
        on_hull = _np.zeros(n, dtype=bool)
        hull_faces = _faces_without_neighbour(simplices, t.neighbors)
        on_hull[hull_faces.ravel()] = True
        # Cells: (point, vertex) pairs sorted, -1 first for a point on the hull.
        size = len(roots) + 1
        pairs = _np.concatenate([simplices.ravel() * size + _np.repeat(vertex_of, k + 1) + 1,
                                 _np.flatnonzero(on_hull) * size])
        pairs = _np.unique(pairs)
        cells = pairs % size - 1
        offsets = _offsets(_np.bincount(pairs // size, minlength=n))
        # Ridges: each Delaunay edge with the vertices around it, -1 first when on the hull.
        count = _np.int64(n)
        corner_pairs = [(i, j) for i in range(k + 1) for j in range(i + 1, k + 1)]
        lower = _np.concatenate([_np.minimum(simplices[:, i], simplices[:, j]) for i, j in corner_pairs])
        higher = _np.concatenate([_np.maximum(simplices[:, i], simplices[:, j]) for i, j in corner_pairs])
        owner = _np.tile(_np.arange(m), len(corner_pairs))
        key = lower * count + higher
        face_pairs = [(i, j) for i in range(k) for j in range(i + 1, k)]
        hull_keys = _np.unique(_np.concatenate(
            [_np.minimum(hull_faces[:, i], hull_faces[:, j]) * count + _np.maximum(hull_faces[:, i], hull_faces[:, j])
             for i, j in face_pairs])) if len(hull_faces) else _np.zeros(0, dtype=_np.int64)
        edge_keys, inverse = _np.unique(key, return_inverse=True)
        inverse = inverse.reshape(-1)
        unbounded = _np.isin(edge_keys, hull_keys)
        if cospherical:
            around = _np.unique(inverse * size + vertex_of[owner] + 1)  # (edge, vertex) pairs
            ridge = _edges_of_cells(points, simplices, vertex_of, len(roots), edge_keys, around // size,
                                    around % size - 1, hull_faces)
            renumber = _np.cumsum(ridge) - 1
            around = around[ridge[around // size]]
            around = renumber[around // size] * size + around % size
            edge_keys, unbounded = edge_keys[ridge], unbounded[ridge]
            entries = _np.sort(_np.concatenate([around, _np.flatnonzero(unbounded) * size]))
        else:  # a vertex per simplex: every triangulation edge is a ridge
            entries = _np.unique(_np.concatenate([inverse * size + owner + 1, _np.flatnonzero(unbounded) * size]))
        flat = entries % size - 1
        ridge_offsets = _offsets(_np.bincount(entries // size, minlength=len(edge_keys)))
        self._set_ridges(_np.stack([edge_keys // count, edge_keys % count], axis=1), flat, ridge_offsets)
        return (t.representative, cells, offsets, None)  # volumes on first use

    def _faces_3d(self, v, n):
        """Ridges from the core's faces; each point's cell vertices."""
        face_points = v["face_points"].astype(_np.int64)
        offsets = v["face_offsets"].astype(_np.int64)
        corners = v["face_vertices"].astype(_np.int64)
        unbounded = v["face_bounded"] == 0
        sizes = _np.diff(offsets)
        face = _np.repeat(_np.arange(len(sizes)), sizes)
        # Ridge vertices: the face's, after a -1 where it is unbounded.
        ridge_offsets = _offsets(sizes + unbounded)
        flat = _np.full(ridge_offsets[-1], -1, dtype=_np.int64)
        position = _np.arange(len(corners)) - offsets[face]
        flat[ridge_offsets[face] + unbounded[face] + position] = corners
        self._set_ridges(face_points, flat, ridge_offsets)
        # Cells: each point's vertices over its faces (ascending), -1 (first) when one is unbounded.
        count = len(self.vertices) + 1
        pairs = _np.concatenate([face_points[face, 0] * count + corners + 1, face_points[face, 1] * count + corners + 1,
                                 face_points[unbounded, 0] * count, face_points[unbounded, 1] * count])
        pairs = _np.unique(pairs)
        cells = pairs % count - 1
        return cells, _offsets(_np.bincount(pairs // count, minlength=n))

    def _coplanar_3d(self, xyz, d):
        """Coplanar points: cells are prisms over the planar cells, unbounded, without vertices. Which
        cells share a face is the planar Voronoi diagram's adjacency, read exactly off the
        tetrahedralization of the points and one apex off their plane (each planar Delaunay triangle
        and the apex make a tetrahedron; cocircular triangles share a circumcentre)."""
        n = len(xyz)
        low, high = self.min_bound, self.max_bound
        # Off the plane by at least the cloud's size and a quarter of its largest coordinate: far
        # beyond what rounding the apex's coordinates can take back.
        # Along the plane's normal, or (when that rounded to nothing, as for coordinates near
        # 1e300) along the first axis that leaves the plane: exactly decided by delaunay3.
        reach = max(float((high / 2 - low / 2).max()) * 2, float(_np.abs([low, high]).max()) / 4)
        for direction in (_np.asarray(d.normal), *_np.eye(3)):
            lifted = _np.vstack([xyz, low / 2 + high / 2 + reach * direction])
            pyramid = delaunay3(lifted)
            if pyramid.dimension == 3:
                break
        v = pyramid.voronoi()
        real = v["face_points"][:, 1] < n  # not the apex's faces
        pairs = v["face_points"][real]
        self._set_ridges(pairs, _np.full(len(pairs), -1, dtype=_np.int64), _np.arange(len(pairs) + 1, dtype=_np.int64))
        return self._without_vertices(d.representative)

    def _box(self, lower, upper):
        """The box [lower, upper] (default: the points' bounding box, widened where flat) as two
        float64 arrays of ndim coordinates, or HullkitError."""
        if lower is None or upper is None:
            low, high = self.min_bound, self.max_bound
            pad = _np.where(high > low, 0.0, 1.0)  # a flat box would have no area
            lower = low - pad if lower is None else lower
            upper = high + pad if upper is None else upper
        low, high = (_np.asarray(v, dtype=_np.float64).reshape(-1) for v in (lower, upper))
        k = self.ndim
        if low.shape != (k,) or high.shape != (k,) or not (_np.isfinite(low).all() and _np.isfinite(high).all()) \
                or not (low < high).all():
            raise HullkitError(f"the box needs finite lower < upper, each of {k} coordinates; got {low.tolist()}, {high.tolist()}")
        return low, high

    def clipped_cells(self, lower=None, upper=None):
        """2D: each point's cell clipped to the box [lower, upper] (default: the points' bounding
        box): a list, per point, of its corners as a (k, 2) array, counter-clockwise (empty when the
        cell misses the box; a repeated point gets the cell of the first point equal to it).
        Unbounded cells end on the box's sides. The corners are rounded; which Delaunay neighbours
        bound each cell is exact (hullkit.Delaunay.voronoi)."""
        if self.ndim != 2:
            _not_supported("clipped_cells in 3D (clipped_volumes has the volumes)", "Voronoi")
        if not self.npoints:
            return []
        low, high = self._box(lower, upper)
        triangulation = delaunay(self.points)
        cells = triangulation.voronoi((low[0], low[1], high[0], high[1]))
        representative = _np.asarray(triangulation.representative)
        return [cells[r] for r in representative.tolist()]

    def clipped_volumes(self, lower=None, upper=None, threads=0):
        """(n,) float64: the area (2D) or volume (3D) of each point's cell inside the box [lower,
        upper] (default: the points' bounding box): finite for every cell; a repeated point gets its
        first's. 2D: from clipped_cells (0 for a cell that misses the box). 3D: every point must lie
        in the box (sides included); each cell is the box's halfspaces and the bisectors with its
        Delaunay neighbours, intersected through the exact hull of their dual points (as
        HalfspaceIntersection), on ``threads`` threads (0: every core; the same bits for any)."""
        if self.ndim == 2:
            areas = _np.zeros(self.npoints)
            for i, corners in enumerate(self.clipped_cells(lower, upper)):
                if len(corners) >= 3:
                    x, y = corners[:, 0] - corners[0, 0], corners[:, 1] - corners[0, 1]
                    areas[i] = 0.5 * float((x[:-1] * y[1:] - x[1:] * y[:-1]).sum())
            return areas
        if self.dimension != 3:
            _not_supported("clipped_volumes of points that do not span space", "Voronoi")
        low, high = self._box(lower, upper)
        with _translated():
            return delaunay3(self.points)._core.clipped_volumes(low, high, _threads(threads))

    def __repr__(self):
        return (f"hullkit.spatial.Voronoi(npoints={self.npoints}, ndim={self.ndim}, dimension={self.dimension}, "
                f"vertices={len(self.vertices)}, ridges={len(self.ridge_points)})")



# -- Halfspace intersection ------------------------------------------------------------------------

def _checked_halfspaces(halfspaces, what="halfspaces"):
    array = _float64(halfspaces, what)
    if array.ndim != 2 or not 3 <= array.shape[1] <= 11:
        if array.ndim == 2 and array.shape[1] > 11:
            _not_supported(f"halfspaces in {array.shape[1] - 1} dimensions (at most 10)", "HalfspaceIntersection")
        raise HullkitError(f"{what} must have shape (n, k + 1) with 2 <= k <= 10 ([A; b] for A x + b <= 0 in k "
                           f"dimensions), got {array.shape}")
    bad = _np.flatnonzero(~_np.isfinite(array).all(axis=1))
    if len(bad):
        raise HullkitError(f"halfspace {bad[0]} has a non-finite coefficient: {array[bad[0]].tolist()}", int(bad[0]))
    return array


def _exact_signs(a, b, x):
    """The exact sign of a[i] . x + b[i] for each row, and its value in float64: from the
    floating-point sum where its error bound leaves no doubt, in rational arithmetic where it does."""
    from fractions import Fraction

    terms = a * x
    with _np.errstate(all="ignore"):
        value = terms.sum(axis=1) + b
        magnitude = _np.abs(terms).sum(axis=1) + _np.abs(b)
        # Each product and sum rounds by at most one unit in the last place of the magnitude (and a
        # product below the normal range by 2^-1074): a generous bound on the total error.
        bound = (a.shape[1] + 3) * 2.0 ** -52 * magnitude + (a.shape[1] + 1) * 2.0 ** -1070
        unsure = ~(_np.abs(value) > bound) | ~_np.isfinite(value)
    signs = _np.sign(value)
    for i in _np.flatnonzero(unsure).tolist():
        exact = sum((Fraction(float(p)) * Fraction(float(q)) for p, q in zip(a[i], x)), Fraction(float(b[i])))
        signs[i] = (exact > 0) - (exact < 0)
        value[i] = float(exact)
    return signs, value


class HalfspaceIntersection:
    """The intersection of halfspaces A x + b <= 0 in 2 to 10 dimensions (scipy.spatial's class): the
    polar dual of the halfspaces about ``interior_point`` is hulled exactly, and each facet of that
    hull is one corner of the intersection.

    ``halfspaces`` (n, ndim + 1) holds the rows [A_i, b_i]. ``interior_point`` (ndim,) must lie
    strictly inside every halfspace: that is checked exactly, and a point that is not gets
    HullkitError (also ``QhullError``) naming the first halfspace it violates.
    ``chebyshev_center(halfspaces)`` finds one.

    Attributes (scipy's): ``halfspaces``, ``interior_point``, ``ndim``, ``nineq``,
    ``dual_points`` (A_i / -(A_i . p + b_i)), ``dual_vertices`` (the halfspaces that bound the
    intersection: counter-clockwise in 2D, ascending in 3D), ``dual_facets`` (each facet's
    halfspaces: the facets are merged, so a corner where more than three planes meet is one
    facet and one intersection), ``dual_equations`` (unit normal and offset of each facet),
    ``dual_area``, ``dual_volume`` and ``intersections`` (one corner per facet, solved from its
    halfspaces; in 2D in counter-clockwise order). Methods: ``add_halfspaces`` and ``close`` (``incremental=True``).

    Which halfspaces bound the intersection and which meet at each corner is decided exactly for
    the dual points as computed (their coordinates are rounded, as Qhull's are). An unbounded
    intersection raises HullkitError (its corners are not all finite). ``qhull_options`` as the
    module says (Qt has no effect: the facets are always merged).

    Examples
    --------
    >>> import numpy as np
    >>> from hullkit.spatial import HalfspaceIntersection
    >>> square = np.array([[-1, 0, 0], [0, -1, 0], [1, 0, -2], [0, 1, -2]], dtype=float)  # 0 <= x, y <= 2
    >>> hs = HalfspaceIntersection(square, np.array([1.0, 1.0]))
    >>> hs.intersections.tolist()  # counter-clockwise
    [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]
    >>> hs.dual_vertices.tolist(), hs.dual_facets
    ([0, 1, 2, 3], [[0, 1], [1, 2], [2, 3], [3, 0]])
    """

    def __init__(self, halfspaces, interior_point, incremental=False, qhull_options=None):
        _parsed_options(qhull_options, "HalfspaceIntersection")
        array = _checked_halfspaces(halfspaces)
        self.ndim = array.shape[1] - 1
        point = _float64(interior_point, "interior_point")
        if point.shape != (self.ndim,):
            raise HullkitError(f"interior_point must have shape ({self.ndim},) for halfspaces of shape "
                               f"{array.shape}, got {point.shape}")
        if not _np.isfinite(point).all():
            raise HullkitError(f"interior_point must be finite, got {point.tolist()}")
        self.interior_point = point.copy()
        self._incremental, self._closed = bool(incremental), False
        self._build(array)

    def add_halfspaces(self, halfspaces, restart=False):
        """Adds halfspaces (k, ndim + 1) (needs ``incremental=True``; not after ``close()``); the
        result is that of one call with all of them (``restart`` changes nothing)."""
        if not self._incremental:
            raise HullkitError("add_halfspaces needs HalfspaceIntersection(..., incremental=True)")
        if self._closed:
            raise HullkitError("add_halfspaces after close(): this HalfspaceIntersection takes no more halfspaces")
        array = _checked_halfspaces(halfspaces)
        if array.shape[1] != self.ndim + 1:
            raise HullkitError(f"halfspaces must have shape (k, {self.ndim + 1}) like the first ones, got {array.shape}")
        self._build(_np.concatenate([self.halfspaces, array]))

    def close(self):
        """Ends the incremental mode: add_halfspaces raises from now on."""
        self._closed = True

    def _build(self, array):
        k = self.ndim
        self.halfspaces, self.nineq = array, len(array)
        a, b = array[:, :k], array[:, k]
        signs, value = _exact_signs(a, b, self.interior_point)
        outside = _np.flatnonzero(signs >= 0)
        if len(outside):
            i = int(outside[0])
            raise HullkitError(f"interior_point {self.interior_point.tolist()} is not strictly inside halfspace {i} "
                               f"{array[i].tolist()}: A x + b = {value[i]!r} there, and must be < 0", i)
        with _np.errstate(all="ignore"):
            self.dual_points = a / -value[:, None]
        far = _np.flatnonzero(~_np.isfinite(self.dual_points).all(axis=1))
        if len(far):
            i = int(far[0])
            raise HullkitError(f"interior_point is too close to the boundary of halfspace {i} for its dual point "
                               f"(A x + b = {value[i]!r} there): choose one further inside", i)
        if self.nineq <= k:
            raise HullkitError(f"{self.nineq} halfspaces cannot bound a region in {k}D: the intersection is unbounded")
        if k > 3:
            self._build_nd(a, b)
            return
        if k == 2:
            dual = ConvexHull(self.dual_points)
            self.dual_vertices, self.dual_volume, self.dual_area = dual.vertices, dual.volume, dual.area
            bounded = dual.dimension == 2
            flat = dual.simplices.ravel().astype(_np.int64)
            offsets = _np.arange(0, len(flat) + 1, 2, dtype=_np.int64)
            self.dual_equations = dual.equations
            triangles = dual.simplices
        else:
            with _translated():  # the core's result as it is (hullkit.Hull would list the faces)
                h = _core.hull(_np.ascontiguousarray(self.dual_points), "quickhull", True, 0)
            bounded = int(h["dimension"]) == 3
            self.dual_vertices = h["vertices"].astype(_np.int32)
            self.dual_volume, self.dual_area = float(h["volume"]), float(h["area"])
            flat = h["face_vertices"].astype(_np.int64) if bounded else _np.zeros(0, dtype=_np.int64)
            offsets = h["face_offsets"].astype(_np.int64) if bounded else _np.zeros(1, dtype=_np.int64)
            self.dual_equations = self._face_planes(flat, offsets)
            triangles = h["triangles"].reshape(-1, 3)
        self.dual_facets = _grouped(flat, offsets)
        if bounded:  # the origin (the interior point) strictly inside the dual hull: exactly
            with _translated():
                sides = _core.facet_sides(_np.ascontiguousarray(self.dual_points),
                                          _np.ascontiguousarray(triangles, dtype=_np.uint32), _np.zeros((1, k)))
            bounded = bool((sides < 0).all())
        if not bounded:
            raise HullkitError("the intersection of the halfspaces is unbounded: their normals do not surround the "
                               "interior point (its dual hull does not contain it strictly)")
        self.intersections = self._corners(a, b, flat, offsets)

    def _build_nd(self, a, b):
        """4 to 10 dimensions: the dual points' exact hull (hull_nd), its simplicial facets merged
        into the flat pieces of its boundary (exactly coplanar neighbours), one corner each."""
        k = self.ndim
        try:
            dual = ConvexHull(self.dual_points)
        except HullkitError as error:
            if "flat" not in str(error):
                raise
            raise HullkitError("the intersection of the halfspaces is unbounded: their normals span fewer than "
                               f"{k} dimensions ({error})") from None
        self.dual_vertices, self.dual_volume, self.dual_area = dual.vertices, dual.volume, dual.area
        # The origin (the interior point) strictly inside the dual hull, exactly: against every facet.
        origin = _np.zeros((1, k))
        for facet in dual.simplices:
            with _translated():
                side = _core.orient_nd(_np.concatenate([self.dual_points[facet], origin]))
            if side >= 0:
                raise HullkitError("the intersection of the halfspaces is unbounded: their normals do not surround "
                                   "the interior point (its dual hull does not contain it strictly)")
        groups = dual._groups
        pieces = _np.unique(groups)
        sizes, flat = [], []
        for piece in pieces.tolist():
            corners = _np.unique(dual.simplices[groups == piece])
            sizes.append(len(corners))
            flat.append(corners)
        flat = _np.concatenate(flat).astype(_np.int64)
        offsets = _offsets(sizes)
        self.dual_facets = _grouped(flat, offsets)
        self.dual_equations = dual.equations[pieces]
        # Each corner from k of its planes: those of the piece's first simplicial facet, whose dual
        # points are affinely independent off the origin, so their normals are independent.
        rows = dual.simplices[pieces]
        self.intersections = _np.linalg.solve(a[rows], -b[rows][:, :, None])[:, :, 0] + 0.0

    def _corners(self, a, b, flat, offsets):
        """Each facet's corner: where its halfspaces' planes meet, solved from the halfspaces
        themselves (A_F x = -b_F, least squares where more than ndim planes meet), which is more
        accurate than the dual facet's rounded plane (a corner at 0 comes out as 0)."""
        k = self.ndim
        sizes = _np.diff(offsets)
        corners = _np.empty((len(sizes), k))
        simple = _np.flatnonzero(sizes == k)
        if len(simple):
            rows = flat[offsets[simple][:, None] + _np.arange(k)]
            corners[simple] = _np.linalg.solve(a[rows], -b[rows][:, :, None])[:, :, 0]
        for f in _np.flatnonzero(sizes != k).tolist():
            rows = flat[offsets[f]: offsets[f + 1]]
            corners[f] = _np.linalg.lstsq(a[rows], -b[rows], rcond=None)[0]
        return corners + 0.0  # -0.0 (from -b where b is 0) as 0.0

    def _face_planes(self, flat, offsets):
        """Each polygonal face's plane [unit outward normal, offset]: Newell's normal (the sum of
        the cross products of consecutive corners, which are counter-clockwise seen from outside)
        and the plane through the corners' centroid."""
        if len(offsets) < 2:
            return _np.zeros((0, 4))
        sizes = _np.diff(offsets)
        following = _np.arange(1, len(flat) + 1)
        following[offsets[1:] - 1] = offsets[:-1]
        corner = self.dual_points[flat]
        normal = _np.add.reduceat(_np.cross(corner, corner[following]), offsets[:-1], axis=0)
        normal /= _np.linalg.norm(normal, axis=1)[:, None]
        centroid = _np.add.reduceat(corner, offsets[:-1], axis=0) / sizes[:, None]
        return _np.column_stack([normal, -_np.einsum("ij,ij->i", normal, centroid)])

    def __repr__(self):
        return (f"hullkit.spatial.HalfspaceIntersection(nineq={self.nineq}, ndim={self.ndim}, "
                f"intersections={len(self.intersections)})")


def chebyshev_center(halfspaces):
    """The centre and radius of the largest ball inside the halfspaces A x + b <= 0 (n, ndim + 1):
    an interior point for HalfspaceIntersection, as scipy's documentation computes it (a linear
    program, solved by scipy.optimize.linprog, which needs scipy). HullkitError when the
    intersection is empty, has no interior (radius 0) or is unbounded.

    Examples
    --------
    >>> from hullkit.spatial import chebyshev_center
    >>> centre, radius = chebyshev_center([[-1, 0, 0], [0, -1, 0], [1, 0, -2], [0, 1, -2]])
    >>> centre.tolist(), radius
    ([1.0, 1.0], 1.0)
    """
    array = _checked_halfspaces(halfspaces)
    try:
        from scipy.optimize import linprog
    except ImportError:  # pragma: no cover - scipy is installed wherever its tests run
        raise HullkitError("chebyshev_center needs scipy (scipy.optimize.linprog)") from None
    k = array.shape[1] - 1
    norms = _np.linalg.norm(array[:, :k], axis=1)
    objective = _np.zeros(k + 1)
    objective[-1] = -1.0  # maximise the radius
    result = linprog(objective, A_ub=_np.column_stack([array[:, :k], norms]), b_ub=-array[:, k],
                     bounds=[(None, None)] * k + [(0, None)], method="highs")
    if result.status == 2:
        raise HullkitError("the halfspaces have an empty intersection (the linear program is infeasible)")
    if result.status == 3:
        raise HullkitError("the intersection of the halfspaces is unbounded: it holds balls of any radius")
    if result.status != 0:
        raise HullkitError(f"the linear program for the Chebyshev centre failed: {result.message}")
    radius = float(result.x[-1])
    if not radius > 0:
        raise HullkitError("the intersection of the halfspaces has no interior (its largest ball has radius 0)")
    return result.x[:k].copy(), radius


# -- Plots (matplotlib, as scipy.spatial's) ------------------------------------------------------

def _plot_axes(ax, thing, what):
    """The axes to draw on (a new figure's when None), after checking ``thing`` is 2D."""
    points = getattr(thing, "points", None)
    if points is None or _np.ndim(points) != 2 or _np.shape(points)[1] != 2:
        raise HullkitError(f"{what} draws 2D diagrams; got {type(thing).__name__}"
                           + (f" of points with shape {_np.shape(points)}" if points is not None else ""))
    if ax is None:
        import matplotlib.pyplot as plt
        ax = plt.figure().gca()
    return ax


def _fit_view(ax, points):
    """The view around the points with a tenth of their extent to spare on each side."""
    if len(points):
        spare = 0.1 * _np.ptp(points, axis=0)
        low, high = points.min(axis=0) - spare, points.max(axis=0) + spare
        if high[0] > low[0]:
            ax.set_xlim(low[0], high[0])
        if high[1] > low[1]:
            ax.set_ylim(low[1], high[1])


def delaunay_plot_2d(tri, ax=None):
    """Draws a 2D Delaunay triangulation (its points and triangles) on ``ax`` (a new figure's
    axes when None), as scipy.spatial.delaunay_plot_2d; returns the figure. Needs matplotlib."""
    ax = _plot_axes(ax, tri, "delaunay_plot_2d")
    x, y = tri.points[:, 0], tri.points[:, 1]
    ax.plot(x, y, "o")
    if len(tri.simplices):
        ax.triplot(x, y, _np.array(tri.simplices))
    _fit_view(ax, tri.points)
    return ax.figure


def convex_hull_plot_2d(hull, ax=None):
    """Draws a 2D convex hull (the points and the hull's edges) on ``ax``, as
    scipy.spatial.convex_hull_plot_2d; returns the figure. Needs matplotlib."""
    from matplotlib.collections import LineCollection

    ax = _plot_axes(ax, hull, "convex_hull_plot_2d")
    ax.plot(hull.points[:, 0], hull.points[:, 1], "o")
    ax.add_collection(LineCollection(hull.points[hull.simplices], colors="k", linestyle="solid"))
    _fit_view(ax, hull.points)
    return ax.figure


def voronoi_plot_2d(vor, ax=None, **kw):
    """Draws a 2D Voronoi diagram on ``ax``, as scipy.spatial.voronoi_plot_2d, with its keywords:
    show_points, show_vertices (True), line_colors ("k"), line_width (1.0), line_alpha (1.0),
    point_size (None). Finite ridges are solid; a ray (a ridge to infinity) is dashed, from its
    vertex away from the points across the hull edge it bisects, as long as the points' extent; a
    line between two collinear points (no vertex) is drawn whole, dashed. Returns the figure.
    Needs matplotlib."""
    from matplotlib.collections import LineCollection

    known = {"show_points", "show_vertices", "line_colors", "line_width", "line_alpha", "point_size"}
    unknown = sorted(set(kw) - known)
    if unknown:
        raise HullkitError(f"voronoi_plot_2d: unknown keywords {unknown}; it takes {sorted(known)}")
    ax = _plot_axes(ax, vor, "voronoi_plot_2d")
    points, vertices = vor.points, vor.vertices
    if kw.get("show_points", True):
        ax.plot(points[:, 0], points[:, 1], ".", markersize=kw.get("point_size"))
    if kw.get("show_vertices", True) and len(vertices):
        ax.plot(vertices[:, 0], vertices[:, 1], "o")
    centre = points.mean(axis=0)
    reach = float(_np.ptp(points, axis=0).max()) if len(points) else 1.0
    finite, rays = [], []
    for (p, q), ridge in zip(vor.ridge_points.tolist(), vor.ridge_vertices):
        ends = [v for v in ridge if v >= 0]
        if len(ends) == len(ridge):
            finite.append(vertices[ridge])
            continue
        # Perpendicular to p-q, away from the points: the centroid lies strictly inside their hull,
        # so strictly on the inner side of the hull edge p-q that the ray crosses.
        tangent = points[q] - points[p]
        normal = _np.array([-tangent[1], tangent[0]]) / _np.hypot(tangent[0], tangent[1])
        middle = (points[p] + points[q]) / 2
        if not ends:  # collinear points: the whole bisector line
            rays.append([middle - normal * reach, middle + normal * reach])
            continue
        direction = -normal if float((centre - middle) @ normal) > 0 else normal
        rays.append([vertices[ends[0]], vertices[ends[0]] + direction * reach])
    style = {"colors": kw.get("line_colors", "k"), "lw": kw.get("line_width", 1.0), "alpha": kw.get("line_alpha", 1.0)}
    ax.add_collection(LineCollection(finite, linestyle="solid", **style))
    ax.add_collection(LineCollection(rays, linestyle="dashed", **style))
    _fit_view(ax, points)
    return ax.figure
