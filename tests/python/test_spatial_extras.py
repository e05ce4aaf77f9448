"""hullkit.spatial's scipy extras: ConvexHull's `good` (QGn), the incremental mode of every class,
Qhull options, Delaunay's lifted planes (equations, plane_distance, lift_points), barycentric
transforms of slivers, and HalfspaceIntersection; each against an independent check (rational
arithmetic, brute force) or scipy (Qhull) on inputs in general position."""
import doctest
from fractions import Fraction

import numpy as np
import pytest
import scipy.spatial

from hullkit import HullkitError
from hullkit.spatial import ConvexHull, Delaunay, HalfspaceIntersection, QhullError, Voronoi, chebyshev_center


def test_docstring_examples_run():
    for function in (ConvexHull, Delaunay, HalfspaceIntersection, chebyshev_center):
        finder = doctest.DocTestFinder(recurse=False)
        runner = doctest.DocTestRunner()
        for test in finder.find(function, function.__name__, globs={}):
            runner.run(test)
        assert runner.failures == 0 and runner.tries > 0, function.__name__


def exact_side(corners, q):
    """The exact sign of orient(corners..., q) in hullkit's convention for hull facets: > 0 when q
    is strictly beyond the facet (2D: right of a -> b; 3D: on the side the normal (b-a)x(c-a) points to)."""
    f = [[Fraction(float(v)) for v in row] for row in corners]
    q = [Fraction(float(v)) for v in q]
    if len(q) == 2:
        (ax, ay), (bx, by) = f
        value = -((bx - ax) * (q[1] - ay) - (by - ay) * (q[0] - ax))
    else:
        a, b, c = f
        u = [b[i] - a[i] for i in range(3)]
        v = [c[i] - a[i] for i in range(3)]
        w = [q[i] - a[i] for i in range(3)]
        value = (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
                 + u[2] * (v[0] * w[1] - v[1] * w[0]))
    return (value > 0) - (value < 0)


@pytest.mark.parametrize("ndim", [2, 3])
def test_good_marks_the_facets_point_n_sees(ndim):
    rng = np.random.default_rng(ndim)
    points = rng.random((60, ndim))
    points[7] = 0.5 + 0.8 * (points[7] - 0.5) / np.linalg.norm(points[7] - 0.5)  # near the hull, outside it
    for option, visible in (("QG7", True), ("QG-7", False), ("Qt QG7 Qbb", True)):
        hull = ConvexHull(points, qhull_options=option)
        assert 7 not in hull.vertices and hull.good.dtype == bool and hull.good.shape == (len(hull.simplices),)
        alone = ConvexHull(np.delete(points, 7, axis=0))
        assert len(alone.simplices) == len(hull.simplices) and len(alone.vertices) == len(hull.vertices)
        sees = np.array([exact_side(points[f], points[7]) > 0 for f in hull.simplices])
        assert np.array_equal(hull.good, sees if visible else ~sees) and sees.any() and not sees.all()
    assert ConvexHull(points).good is None
    with pytest.raises(HullkitError, match="QG60: there is no point 60"):
        ConvexHull(points, qhull_options="QG60")


def test_good_of_a_point_on_a_facet_line_is_false():
    square = np.array([[0, 0], [2, 0], [2, 2], [0, 2], [1, 0]], dtype=float)  # point 4 on the bottom edge
    hull = ConvexHull(square, qhull_options="QG4")
    assert not hull.good.any()
    hull = ConvexHull(np.vstack([square[:4], [[1, -1e-100]]]), qhull_options="QG4")  # just below it
    assert hull.good.sum() == 1 and sorted(hull.simplices[hull.good][0].tolist()) == [0, 1]


@pytest.mark.parametrize("cls,ndim", [(ConvexHull, 2), (ConvexHull, 3), (Delaunay, 2), (Delaunay, 3),
                                      (Voronoi, 2), (Voronoi, 3)])
def test_incremental_equals_one_build(cls, ndim):
    rng = np.random.default_rng(10 + ndim)
    chunks = [rng.random((8, ndim)), rng.random((1, ndim)), rng.random((30, ndim)), np.zeros((0, ndim))]
    grown = cls(chunks[0], incremental=True)
    restarted = cls(chunks[0], incremental=True)
    for chunk in chunks[1:]:
        grown.add_points(chunk)
    restarted.add_points(np.concatenate(chunks[1:]), restart=True)
    whole = cls(np.concatenate(chunks))
    for result in (grown, restarted):
        assert result.npoints == whole.npoints == 39
        for name, value in vars(whole).items():
            if isinstance(value, np.ndarray):
                assert np.array_equal(getattr(result, name), value), name
        if cls is Voronoi:
            assert result.regions == whole.regions and result.ridge_vertices == whole.ridge_vertices
    grown.close()
    with pytest.raises(HullkitError, match="after close"):
        grown.add_points(chunks[1])
    with pytest.raises(HullkitError, match="incremental=True"):
        whole.add_points(chunks[1])
    with pytest.raises(HullkitError, match=rf"shape \(k, {ndim}\)"):
        restarted.add_points(np.zeros((2, 5 - ndim)))


def test_precision_options_change_nothing():
    rng = np.random.default_rng(4)
    for ndim in (2, 3):
        points = rng.random((200, ndim))
        for cls, options in ((ConvexHull, "Qt Qbb Qz Qx Q12 QJ Pp Qs"), (Delaunay, "Qbb Qc Qz Q12 QJ Qt"),
                             (Voronoi, "Qbb Qc Qz Fv")):
            plain, optioned = cls(points), cls(points, qhull_options=options)
            for name, value in vars(plain).items():
                if isinstance(value, np.ndarray):
                    assert np.array_equal(getattr(optioned, name), value), (cls, name)
        # bytes, as scipy accepts
        assert np.array_equal(Delaunay(points, qhull_options=b"Qbb Qc").simplices, Delaunay(points).simplices)


def test_voronoi_without_qz_has_no_empty_region():
    points = np.random.default_rng(5).random((40, 2))
    with_qz, without = Voronoi(points), Voronoi(points, qhull_options="Qbb Qc")
    assert with_qz.regions[0] == [] and without.regions == with_qz.regions[1:]
    assert np.array_equal(without.point_region, with_qz.point_region - 1)


@pytest.mark.parametrize("ndim", [2, 3])
def test_lifted_planes_agree_with_exact_in_circle_tests(ndim):
    rng = np.random.default_rng(20 + ndim)
    points = rng.random((40, ndim))
    tri = Delaunay(points)
    eq = tri.equations
    assert eq.shape == (tri.nsimplex, ndim + 2)
    assert np.allclose(np.linalg.norm(eq[:, :-1], axis=1), 1) and (eq[:, -2] < 0).all()
    lifted = tri.lift_points(points)
    assert lifted.shape == (40, ndim + 1) and np.array_equal(lifted[:, -1], (points ** 2).sum(axis=1))
    corner_distance = np.einsum("mkd,md->mk", lifted[tri.simplices], eq[:, :-1]) + eq[:, -1:]
    assert np.abs(corner_distance).max() < 1e-12
    queries = rng.random((25, ndim))
    distance = tri.plane_distance(queries)
    assert distance.shape == (25, tri.nsimplex)
    assert tri.plane_distance(queries[0]).shape == (tri.nsimplex,)
    # Positive exactly when the query is inside the simplex's circumsphere (rational arithmetic).
    for q in range(25):
        for s in range(0, tri.nsimplex, 7):
            corners = [[Fraction(float(v)) for v in points[i]] for i in tri.simplices[s]]
            x = [Fraction(float(v)) for v in queries[q]]
            rows = [[c[k] - x[k] for k in range(ndim)] + [sum((c[k] - x[k]) ** 2 for k in range(ndim))]
                    for c in corners]
            orientation = np.sign(np.linalg.det(np.array([[float(c[k] - corners[-1][k]) for k in range(ndim)]
                                                          for c in corners[:-1]])))
            inside = Fraction_det(rows) * int(orientation)
            if abs(distance[q, s]) > 1e-12:
                assert (distance[q, s] > 0) == (inside > 0), (q, s)


def Fraction_det(rows):
    """Determinant of a square matrix of Fractions (Laplace expansion: 3x3 and 4x4 here)."""
    if len(rows) == 1:
        return rows[0][0]
    return sum((-1) ** j * rows[0][j] * Fraction_det([row[:j] + row[j + 1:] for row in rows[1:]])
               for j in range(len(rows)))


def test_transform_is_nan_only_for_untrustworthy_slivers():
    rng = np.random.default_rng(6)
    points = np.vstack([rng.random((50, 2)), [[0, 2], [1, 2], [2, 2 + 1e-15]]])
    tri = Delaunay(points)
    t = tri.transform
    bad = np.isnan(t[:, 0, 0])
    assert bad.any() and bad.sum() < 5
    corners = points[tri.simplices[~bad]]
    centroids = corners.mean(axis=1)
    c = np.einsum("ijk,ik->ij", t[~bad, :2], centroids - t[~bad, 2])
    assert np.allclose(c, 1 / 3, rtol=1e-6)


def test_vertices_alias_warns_and_3d_arrays_are_writable():
    tri = Delaunay([[0, 0], [0, 1], [1, 0]])
    with pytest.warns(DeprecationWarning, match="'vertices' is deprecated in favour of 'simplices'"):
        assert tri.vertices is tri.simplices
    tri3 = Delaunay(np.random.default_rng(7).random((30, 3)))
    before = tri3.find_simplex(tri3.points[:5].mean(axis=0))
    for name in ("simplices", "neighbors", "convex_hull"):
        getattr(tri3, name).sort(axis=1)  # scipy's are writable; the core's own arrays stay untouched
    assert tri3.find_simplex(tri3.points[:5].mean(axis=0)) == before


# -- HalfspaceIntersection ---------------------------------------------------------------------

def tangent_halfspaces(rng, n, ndim):
    normals = rng.normal(size=(n, ndim))
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    return np.column_stack([normals, -np.ones(n) - rng.random(n)])  # n . x <= 1 + r


@pytest.mark.parametrize("ndim", [2, 3])
def test_halfspaces_match_scipy_in_general_position(ndim):
    rng = np.random.default_rng(30 + ndim)
    halfspaces = tangent_halfspaces(rng, 60, ndim)
    halfspaces[5, -1] = -50.0  # far away: redundant
    point = rng.random(ndim) * 0.1
    ours, theirs = HalfspaceIntersection(halfspaces, point), scipy.spatial.HalfspaceIntersection(halfspaces, point)
    assert np.allclose(ours.dual_points, theirs.dual_points, rtol=1e-15)
    assert sorted(ours.dual_vertices.tolist()) == sorted(theirs.dual_vertices.tolist()) and 5 not in ours.dual_vertices
    assert sorted(map(sorted, ours.dual_facets)) == sorted(map(sorted, theirs.dual_facets))
    assert len(ours.intersections) == len(theirs.intersections) == len(ours.dual_facets)
    tree = scipy.spatial.cKDTree(theirs.intersections)
    assert tree.query(ours.intersections)[0].max() < 1e-12
    assert ours.dual_volume == pytest.approx(theirs.dual_volume, rel=1e-12)
    assert ours.dual_area == pytest.approx(theirs.dual_area, rel=1e-12)
    # Each corner lies on its facet's planes and inside all the others.
    for corner, facet in zip(ours.intersections, ours.dual_facets):
        values = halfspaces[:, :-1] @ corner + halfspaces[:, -1]
        assert np.abs(values[facet]).max() < 1e-12 and values.max() < 1e-12
    if ndim == 2:  # counter-clockwise corners
        x, y = (ours.intersections - ours.intersections.mean(axis=0)).T
        assert (np.diff(np.unwrap(np.arctan2(y, x))) > 0).all()
    assert ours.ndim == ndim and ours.nineq == 60 and np.array_equal(ours.halfspaces, halfspaces)


def test_halfspace_corners_where_more_planes_meet_are_one_facet():
    cube = np.array([[-1, 0, 0, 0], [1, 0, 0, -1], [0, -1, 0, 0], [0, 1, 0, -1], [0, 0, -1, 0], [0, 0, 1, -1]],
                    dtype=float)
    hs = HalfspaceIntersection(cube, [0.5, 0.5, 0.5])
    assert len(hs.intersections) == 8 and all(len(f) == 3 for f in hs.dual_facets)
    assert sorted(map(tuple, hs.intersections.round(12).tolist())) == [
        (x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
    # A square pyramid: four planes meet at its apex (1, 1, 1) (from the interior point, exactly:
    # the dual points are coplanar), which is one corner with four halfspaces.
    pyramid = np.array([[0, 0, -1, 0], [1, 0, 1, -2], [-1, 0, 1, 0], [0, 1, 1, -2], [0, -1, 1, 0]], dtype=float)
    hs = HalfspaceIntersection(pyramid, [1.0, 1.0, 0.25])
    sizes = sorted(len(f) for f in hs.dual_facets)
    assert sizes == [3, 3, 3, 3, 4] and len(hs.intersections) == 5
    apex = hs.intersections[[len(f) == 4 for f in hs.dual_facets]][0]
    assert np.allclose(apex, [1, 1, 1], atol=1e-14)


def test_halfspace_errors_name_the_problem():
    square = np.array([[-1, 0, 0], [0, -1, 0], [1, 0, -1], [0, 1, -1]], dtype=float)
    with pytest.raises(QhullError, match="not strictly inside halfspace 0") as caught:
        HalfspaceIntersection(square, [0.0, 0.5])  # on the boundary x = 0: exactly, not inside
    assert caught.value.point == 0 and QhullError is HullkitError
    with pytest.raises(HullkitError, match="not strictly inside halfspace 2"):
        HalfspaceIntersection(square, [1 + 2 ** -52, 0.5])
    tiny = 1e-300  # exact even where the floating-point sum would underflow
    with pytest.raises(HullkitError, match="not strictly inside halfspace 0"):
        HalfspaceIntersection(np.array([[tiny, tiny, 0], [-1, 0, -1], [0, -1, -1], [1, 1, -5]]), [0.0, 0.0])
    with pytest.raises(HullkitError, match="unbounded"):
        HalfspaceIntersection(square[:3], [0.5, 0.5])
    with pytest.raises(HullkitError, match="unbounded"):
        HalfspaceIntersection(np.array([[-1, 0, 0], [0, -1, 0], [1, 0, -1], [-1, 0, -3]], dtype=float), [0.5, 0.5])
    for point in ([0.5, 0.5, 0.5], [[0.5], [0.5]], [[0.5, 0.5]]):
        with pytest.raises(ValueError, match="interior_point must have shape"):
            HalfspaceIntersection(square, np.array(point))
    with pytest.raises(HullkitError, match="halfspace 1 has a non-finite"):
        HalfspaceIntersection(np.vstack([square[:1], [[np.nan, 0, 0]], square[1:]]), [0.5, 0.5])
    with pytest.raises(HullkitError, match=r"halfspaces in 11 dimensions \(at most 10\) is not supported"):
        HalfspaceIntersection(np.zeros((13, 12)), np.zeros(11))
    with pytest.raises(HullkitError, match="Qhull option 'QG0'"):
        HalfspaceIntersection(square, [0.5, 0.5], qhull_options="QG0")


def test_halfspace_incremental_and_chebyshev_center():
    rng = np.random.default_rng(40)
    halfspaces = tangent_halfspaces(rng, 30, 3)
    centre, radius = chebyshev_center(halfspaces)
    assert (halfspaces[:, :-1] @ centre + halfspaces[:, -1] <= -radius * (1 - 1e-9)).all() and radius >= 1
    grown = HalfspaceIntersection(halfspaces[:10], centre, incremental=True)
    for row in halfspaces[10:]:
        grown.add_halfspaces(row[None, :])
    whole = HalfspaceIntersection(halfspaces, centre)
    assert np.array_equal(grown.intersections, whole.intersections) and grown.dual_facets == whole.dual_facets
    grown.close()
    with pytest.raises(HullkitError, match="after close"):
        grown.add_halfspaces(halfspaces[:1])
    with pytest.raises(HullkitError, match="incremental=True"):
        whole.add_halfspaces(halfspaces[:1])
    with pytest.raises(HullkitError, match="empty intersection"):
        chebyshev_center([[1, 0, 0], [-1, 0, 1], [0, 1, 0], [0, -1, 0]])  # x <= 0 and x >= 1
    with pytest.raises(HullkitError, match="unbounded"):
        chebyshev_center([[1, 0, -1], [0, 1, -1]])
    with pytest.raises(HullkitError, match="no interior"):
        chebyshev_center([[1, 0, 0], [-1, 0, 0], [0, 1, -1], [0, -1, -1]])  # x = 0 exactly


# -- plots ---------------------------------------------------------------------------------------

def segments_of(ax, style):
    """The line segments of the axes' LineCollections drawn in ``style`` ("solid" or "dashed")."""
    from matplotlib.collections import LineCollection
    out = []
    for collection in ax.collections:
        if isinstance(collection, LineCollection) and collection.get_segments():
            dashed = collection.get_linestyle()[0][1] is not None
            if dashed == (style == "dashed"):
                out += [np.asarray(s) for s in collection.get_segments()]
    return out


def test_plots_draw_the_diagrams():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from hullkit.spatial import convex_hull_plot_2d, delaunay_plot_2d, voronoi_plot_2d

    rng = np.random.default_rng(70)
    points = rng.random((40, 2))
    vor = Voronoi(points)
    figure = voronoi_plot_2d(vor, line_colors="orange", line_width=2, point_size=3)
    ax = figure.axes[0]
    solid, dashed = segments_of(ax, "solid"), segments_of(ax, "dashed")
    finite = [r for r in vor.ridge_vertices if -1 not in r]
    assert len(solid) == len(finite) and len(dashed) == len(vor.ridge_vertices) - len(finite)
    for segment, ridge in zip(solid, finite):
        assert np.array_equal(segment, vor.vertices[ridge])
    hull = ConvexHull(points)
    outside = lambda x: (hull.equations[:, :2] @ x + hull.equations[:, 2]).max()
    for segment in dashed:  # each ray leaves the hull: its far end is outside, beyond its start
        assert outside(segment[1]) > max(outside(segment[0]), 0)
    plt.close(figure)

    figure = delaunay_plot_2d(Delaunay(points))
    assert len(figure.axes[0].lines) >= 2  # the points and the triangles' edges
    plt.close(figure)
    figure, ax = plt.subplots()
    assert convex_hull_plot_2d(hull, ax=ax) is figure
    assert sorted(map(lambda s: tuple(sorted(map(tuple, s.tolist()))), segments_of(ax, "solid"))) == sorted(
        tuple(sorted(map(tuple, points[s].tolist()))) for s in hull.simplices)
    plt.close(figure)
    # Collinear points: each bisector line drawn whole.
    line = Voronoi(np.c_[np.arange(4.0), np.zeros(4)])
    figure = voronoi_plot_2d(line)
    assert len(segments_of(figure.axes[0], "dashed")) == 3
    plt.close(figure)
    with pytest.raises(HullkitError, match="draws 2D diagrams"):
        voronoi_plot_2d(Voronoi(rng.random((20, 3))))
    with pytest.raises(HullkitError, match="unknown keywords"):
        voronoi_plot_2d(vor, colour="red")


# -- furthest site -------------------------------------------------------------------------------

def incircle_sign(a, b, c, d):
    """Exact sign of the in-circle determinant (positive: d inside the circle of counter-clockwise a, b, c)."""
    rows = [[Fraction(float(p[0])) - Fraction(float(d[0])), Fraction(float(p[1])) - Fraction(float(d[1]))] for p in (a, b, c)]
    rows = [r + [r[0] ** 2 + r[1] ** 2] for r in rows]
    value = Fraction_det(rows)
    return (value > 0) - (value < 0)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_furthest_site_delaunay_and_voronoi_match_scipy(seed):
    rng = np.random.default_rng(90 + seed)
    points = rng.random((60, 2))
    ours, theirs = Delaunay(points, furthest_site=True), scipy.spatial.Delaunay(points, furthest_site=True)
    assert sorted(map(sorted, ours.simplices.tolist())) == sorted(map(sorted, theirs.simplices.tolist()))
    hull_corners = set(ConvexHull(points).vertices.tolist())
    assert set(ours.simplices.ravel().tolist()) == hull_corners and len(ours.coplanar) == 0
    # Every circumcircle holds every point (exactly), and the triangles are counter-clockwise.
    for a, b, c in ours.simplices:
        assert exact_side(points[[b, a]], points[c]) > 0  # c left of a -> b
        assert all(incircle_sign(points[a], points[b], points[c], q) >= 0 for q in points)
    # Neighbours across each corner, the hull as the corners' cycle, equations pointing up.
    for t, row in enumerate(ours.neighbors):
        for k, u in enumerate(row):
            shared = set(ours.simplices[t].tolist()) - {int(ours.simplices[t, k])}
            if u >= 0:
                assert shared <= set(ours.simplices[u].tolist()) and t in ours.neighbors[u]
            else:
                assert tuple(sorted(shared)) in {tuple(sorted(e)) for e in ours.convex_hull.tolist()}
    assert (ours.equations[:, -2] > 0).all()
    queries = rng.random((200, 2))
    found = ours.find_simplex(queries)
    assert np.array_equal(found >= 0, theirs.find_simplex(queries) >= 0)
    for q, t in zip(queries, found):
        if t >= 0:
            assert all(exact_side(points[ours.simplices[t][[i, (i + 1) % 3]]], q) <= 0 for i in range(3))
    # Voronoi: the same vertices, ridges and regions as scipy's, as sets.
    vor, svor = Voronoi(points, furthest_site=True), scipy.spatial.Voronoi(points, furthest_site=True)
    assert vor.furthest_site is True
    tree = scipy.spatial.cKDTree(svor.vertices)
    distance, index = tree.query(vor.vertices)
    assert distance.max() < 1e-9 and len(set(index.tolist())) == len(index) == len(svor.vertices)
    mapping = {**dict(enumerate(index.tolist())), -1: -1}
    ours_ridges = {tuple(p): frozenset(mapping[v] for v in r) for p, r in zip(vor.ridge_points.tolist(), vor.ridge_vertices)}
    their_ridges = {tuple(sorted(p)): frozenset(r) for p, r in zip(svor.ridge_points.tolist(), svor.ridge_vertices)}
    assert ours_ridges == their_ridges
    for i in range(len(points)):
        assert {mapping[v] for v in vor.regions[vor.point_region[i]]} == set(svor.regions[svor.point_region[i]])
        assert vor.volumes[i] == (np.inf if i in hull_corners else 0.0)


def test_furthest_site_on_cocircular_corners_and_refusals():
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0.5], [0.5, 0]], dtype=float)  # centre, edge midpoint
    tri = Delaunay(square, furthest_site=True)
    assert tri.nsimplex == 2 and set(tri.simplices.ravel().tolist()) == {0, 1, 2, 3}
    vor = Voronoi(square, furthest_site=True)
    assert vor.vertices.tolist() == [[0.5, 0.5]]  # the four corners' one circle: one vertex
    assert all(vor.regions[vor.point_region[i]] == [0, -1] for i in range(4))
    assert vor.point_region[4] == vor.point_region[5] == 0 and vor.regions[0] == []
    with pytest.raises(HullkitError, match="furthest_site=True for collinear points"):
        Voronoi(np.c_[np.arange(4.0), np.zeros(4)], furthest_site=True)
    line = Delaunay(np.c_[np.arange(4.0), np.zeros(4)], furthest_site=True)
    assert line.nsimplex == 0 and line.find_simplex([[1.0, 0.0]]).tolist() == [-1]


def insphere_sign(a, b, c, d, e):
    """Exact sign of e against the sphere through a, b, c, d (positively oriented): > 0 inside."""
    rows = [[Fraction(float(p[k])) - Fraction(float(e[k])) for k in range(3)] for p in (a, b, c, d)]
    rows = [r + [r[0] ** 2 + r[1] ** 2 + r[2] ** 2] for r in rows]
    value = -Fraction_det(rows)  # the determinant is negative for e inside
    return (value > 0) - (value < 0)


def six_volume(points, tetrahedra):
    """6 x the tetrahedra's total signed volume, exactly."""
    total = Fraction(0)
    for a, b, c, d in tetrahedra:
        rows = [[Fraction(float(points[v][k])) - Fraction(float(points[a][k])) for k in range(3)] for v in (b, c, d)]
        total += Fraction_det(rows)
    return total


@pytest.mark.parametrize("seed", [1, 2])
def test_furthest_site_3d_delaunay_and_voronoi_match_scipy(seed):
    """3D furthest-site: scipy's tetrahedra on random points; exactly, every circumsphere holds every
    point, the tetrahedra are positive and fill the hull (the ordinary tetrahedralization's volume),
    the corners are the hull's vertices; find_simplex agrees with scipy; the Voronoi diagram has
    scipy's vertices and ridges (plus the faces with one finite vertex Qhull leaves out)."""
    rng = np.random.default_rng(110 + seed)
    points = rng.random((40, 3))
    ours, theirs = Delaunay(points, furthest_site=True), scipy.spatial.Delaunay(points, furthest_site=True)
    assert sorted(map(sorted, ours.simplices.tolist())) == sorted(map(sorted, theirs.simplices.tolist()))
    assert set(ours.simplices.ravel().tolist()) == set(ConvexHull(points).vertices.tolist()) and len(ours.coplanar) == 0
    for a, b, c, d in ours.simplices:
        assert exact_side(points[[a, b, c]], points[d]) > 0
        assert all(insphere_sign(points[a], points[b], points[c], points[d], q) >= 0 for q in points)
    assert six_volume(points, ours.simplices) == six_volume(points, Delaunay(points).simplices)
    assert (ours.equations[:, -2] > 0).all()  # the lifted facets face up
    queries = rng.random((300, 3)) * 1.2 - 0.1
    found = ours.find_simplex(queries)
    expected = theirs.find_simplex(queries)
    assert np.array_equal(found >= 0, expected >= 0)
    assert all(set(ours.simplices[t]) == set(theirs.simplices[u]) for t, u in zip(found, expected) if t >= 0)
    bary = np.einsum("nij,nj->ni", ours.transform[found[found >= 0], :3], queries[found >= 0] - ours.transform[found[found >= 0], 3])
    assert (bary > -1e-12).all() and (bary.sum(axis=1) < 1 + 1e-12).all()
    vor, svor = Voronoi(points, furthest_site=True), scipy.spatial.Voronoi(points, furthest_site=True)
    tree = scipy.spatial.cKDTree(svor.vertices)
    distance, index = tree.query(vor.vertices)
    assert distance.max() < 1e-9 and len(set(index.tolist())) == len(index) == len(svor.vertices)
    mapping = {**dict(enumerate(index.tolist())), -1: -1}
    ours_ridges = {tuple(p): frozenset(mapping[v] for v in r) for p, r in zip(vor.ridge_points.tolist(), vor.ridge_vertices)}
    for p, r in zip(svor.ridge_points.tolist(), svor.ridge_vertices):
        assert ours_ridges[tuple(sorted(p))] == frozenset(r)
    assert all(sum(v >= 0 for v in r) == 1 for p, r in ours_ridges.items() if p not in {tuple(sorted(q)) for q in svor.ridge_points.tolist()})
    corners = set(ours.simplices.ravel().tolist())
    for i in range(len(points)):
        assert {mapping[v] for v in vor.regions[vor.point_region[i]]} == set(svor.regions[svor.point_region[i]])
        assert vor.volumes[i] == (np.inf if i in corners else 0.0)


def test_furthest_site_3d_on_a_grid_and_lower_dimensions():
    """A 3 x 3 x 3 grid: only the 8 corners, which are cospherical (ties: never flat), the same
    tetrahedra in any input order; coplanar 3D points: the polygon's furthest-site triangles;
    Voronoi refuses coplanar points, as scipy does."""
    grid = np.array(np.meshgrid(*[np.arange(3.0)] * 3, indexing="ij")).reshape(3, -1).T
    tri = Delaunay(grid, furthest_site=True)
    assert set(tri.simplices.ravel().tolist()) == {0, 2, 6, 8, 18, 20, 24, 26}
    assert all(exact_side(grid[[a, b, c]], grid[d]) > 0 for a, b, c, d in tri.simplices)
    assert six_volume(grid, tri.simplices) == 6 * 8
    order = np.random.default_rng(5).permutation(len(grid))
    moved = Delaunay(grid[order], furthest_site=True)
    assert sorted(map(sorted, order[moved.simplices].tolist())) == sorted(map(sorted, tri.simplices.tolist()))
    assert tri.find_simplex([[1.0, 1.0, 1.0], [3.0, 0.0, 0.0]]).tolist()[1] == -1
    plane = np.c_[np.random.default_rng(6).random((30, 2)), np.full(30, 2.0)]
    flat = Delaunay(plane, furthest_site=True)
    assert flat.dimension == 2 and flat.nsimplex == 0
    corners2d = set(ConvexHull(plane[:, :2]).vertices.tolist())
    assert set(flat.convex_hull.ravel().tolist()) == corners2d and len(flat.convex_hull) == len(corners2d) - 2
    with pytest.raises(HullkitError, match="furthest_site=True for coplanar or collinear 3D points"):
        Voronoi(plane, furthest_site=True)


@pytest.mark.parametrize("ndim", [2, 3])
def test_qc_lists_the_boundary_points_that_are_not_vertices(ndim):
    grid = np.array(np.meshgrid(*[np.arange(4.0)] * ndim, indexing="ij")).reshape(ndim, -1).T  # 4^ndim grid
    rng = np.random.default_rng(100 + ndim)
    points = np.vstack([grid, rng.random((30, ndim)) * 3, grid[:2]])  # inner points, two repeated corners
    hull = ConvexHull(points, qhull_options="Qc")
    plain = ConvexHull(points)
    assert np.array_equal(hull.simplices, plain.simplices) and len(plain.coplanar) == 0
    on_boundary = ((points == 0) | (points == 3)).any(axis=1)  # exactly, for this grid
    expected = set(np.flatnonzero(on_boundary).tolist()) - set(hull.vertices.tolist())
    assert set(hull.coplanar[:, 0].tolist()) == expected and len(expected) > 4
    for point, facet, nearest in hull.coplanar:
        assert exact_side(points[hull.simplices[facet]], points[point]) == 0
        assert nearest in hull.simplices[facet]
    # The repeated corners are on the boundary and their nearest corner is the point they repeat.
    rows = {int(p): int(v) for p, _, v in hull.coplanar}
    assert np.array_equal(points[rows[len(points) - 2]], points[len(points) - 2])
    # Qi: the points strictly inside, each with its nearest facet (largest signed distance); Qc Qi: both.
    interior = ConvexHull(points, qhull_options="Qi")
    inner = set(np.flatnonzero(~on_boundary).tolist())
    assert set(interior.coplanar[:, 0].tolist()) == inner
    for point, facet, nearest in interior.coplanar:
        distances = hull.equations[:, :-1] @ points[point] + hull.equations[:, -1]
        assert distances[facet] == distances.max() < 0 and nearest in hull.simplices[facet]
    both = ConvexHull(points, qhull_options="Qc Qi")
    assert set(both.coplanar[:, 0].tolist()) == inner | expected
    assert np.array_equal(both.coplanar[:, 0], np.sort(both.coplanar[:, 0]))


@pytest.mark.parametrize("seed", range(6))
def test_furthest_site_on_degenerate_integer_clouds(seed):
    """Small integer clouds (many cocircular, collinear and repeated points): the furthest-site
    triangles tile the hull, every circumcircle holds every point (exact), and every hull corner is
    used; cocircular neighbours share one Voronoi vertex."""
    rng = np.random.default_rng(200 + seed)
    points = rng.integers(-3, 4, size=(rng.integers(4, 40), 2)).astype(float)
    hull = ConvexHull(points)
    if hull.dimension < 2:
        return
    tri = Delaunay(points, furthest_site=True)
    corners = set(hull.vertices.tolist())
    assert set(tri.simplices.ravel().tolist()) == corners
    area = sum(0.5 * float(np.cross(points[b] - points[a], points[c] - points[a])) for a, b, c in tri.simplices)
    assert area == pytest.approx(hull.volume, abs=1e-12)
    for a, b, c in tri.simplices:
        assert exact_side(points[[b, a]], points[c]) > 0
        assert all(incircle_sign(points[a], points[b], points[c], q) >= 0 for q in points)
    vor = Voronoi(points, furthest_site=True)
    for (p, q), ridge in zip(vor.ridge_points.tolist(), vor.ridge_vertices):
        if -1 not in ridge:  # a finite ridge joins two different circles
            assert not np.allclose(vor.vertices[ridge[0]], vor.vertices[ridge[1]], rtol=0, atol=1e-12)
    assert len(vor.vertices) == len({tuple(np.round(c, 9)) for c in vor.vertices})


@pytest.mark.parametrize("seed", range(5))
def test_halfspace_corners_equal_brute_force_on_integer_planes(seed):
    """Integer planes around the origin (many meeting in one corner, some repeated or redundant):
    the corners equal those found by solving every triple of planes and keeping the feasible ones,
    one per distinct corner."""
    import itertools

    rng = np.random.default_rng(300 + seed)
    normals = rng.integers(-2, 3, size=(14, 3)).astype(float)
    normals = normals[np.abs(normals).sum(axis=1) > 0]
    halfspaces = np.column_stack([normals, -rng.integers(1, 3, size=len(normals)).astype(float)])
    halfspaces = np.vstack([halfspaces, np.column_stack([np.vstack([np.eye(3), -np.eye(3)]), -3 * np.ones(6)]), halfspaces[:2]])
    hs = HalfspaceIntersection(halfspaces, np.zeros(3))
    brute = set()
    for rows in itertools.combinations(range(len(halfspaces)), 3):
        a = halfspaces[list(rows), :3]
        if abs(np.linalg.det(a)) < 1e-9:
            continue
        x = np.linalg.solve(a, -halfspaces[list(rows), 3])
        if (halfspaces[:, :3] @ x + halfspaces[:, 3] <= 1e-9).all():
            brute.add(tuple(np.round(x, 9) + 0.0))
    ours = {tuple(np.round(x, 9) + 0.0) for x in hs.intersections}
    assert ours == brute and len(hs.intersections) == len(brute)
    for corner, facet in zip(hs.intersections, hs.dual_facets):
        values = halfspaces[:, :3] @ corner + halfspaces[:, 3]
        assert np.abs(values[facet]).max() < 1e-9 and values.max() < 1e-9
        assert sorted(facet) == sorted(set(facet))
