"""hullkit.spatial in 4 to 8 dimensions (the core's hull_nd and delaunay_nd): the same hulls,
triangulations and point locations as scipy's Qhull on points in general position, exact answers
on cospherical grids and cube corners, every Delaunay simplex's circumsphere empty (checked with
exact rational arithmetic), and clear errors on flat input."""
import itertools
from fractions import Fraction

import numpy as np
import pytest
import scipy.spatial as sp

import hullkit
from hullkit.spatial import ConvexHull, Delaunay, Voronoi


def as_sets(rows):
    return {tuple(sorted(row)) for row in np.asarray(rows).tolist()}


def exact_det(rows):
    """The determinant of a square list of Fractions (Bareiss-free: Gaussian elimination)."""
    a = [list(row) for row in rows]
    n, det = len(a), Fraction(1)
    for c in range(n):
        pivot = next((r for r in range(c, n) if a[r][c] != 0), None)
        if pivot is None:
            return Fraction(0)
        if pivot != c:
            a[c], a[pivot] = a[pivot], a[c]
            det = -det
        det *= a[c][c]
        for r in range(c + 1, n):
            factor = a[r][c] / a[c][c]
            for k in range(c, n):
                a[r][k] -= factor * a[c][k]
    return det


def lifted_row(point):
    x = [Fraction(v) for v in point]
    return x + [sum(v * v for v in x), Fraction(1)]


@pytest.mark.parametrize("dims,count", [(4, 40), (5, 40), (6, 25), (8, 12)])
def test_hull_and_delaunay_agree_with_qhull_in_general_position(dims, count):
    points = np.random.default_rng(dims).random((count, dims))
    hull, reference = ConvexHull(points), sp.ConvexHull(points)
    assert as_sets(hull.simplices) == as_sets(reference.simplices)
    assert hull.vertices.tolist() == sorted(reference.vertices.tolist())
    assert hull.volume == pytest.approx(reference.volume, rel=1e-12)
    assert hull.area == pytest.approx(reference.area, rel=1e-12)
    # Outward unit normals: every point on the inner side of every facet's plane.
    assert np.allclose(np.linalg.norm(hull.equations[:, :-1], axis=1), 1)
    assert (points @ hull.equations[:, :-1].T + hull.equations[:, -1] <= 1e-12).all()
    # Neighbours share all corners but one.
    for f, row in enumerate(hull.neighbors):
        for k, g in enumerate(row):
            assert set(hull.simplices[g]) == set(np.delete(hull.simplices[f], k)) | (set(hull.simplices[g]) - set(hull.simplices[f]))
            assert len(set(hull.simplices[g]) & set(hull.simplices[f])) == dims - 1
    tri, qhull = Delaunay(points), sp.Delaunay(points)
    assert as_sets(tri.simplices) == as_sets(qhull.simplices)
    assert as_sets(tri.convex_hull) == as_sets(reference.simplices)
    queries = np.random.default_rng(dims + 10).random((300, dims)) * 1.2 - 0.1
    found, expected = tri.find_simplex(queries), qhull.find_simplex(queries)
    assert [tuple(sorted(tri.simplices[i])) if i >= 0 else None for i in found] == \
        [tuple(sorted(qhull.simplices[i])) if i >= 0 else None for i in expected]
    # Barycentric coordinates from the transform put each query in its simplex.
    inside = found >= 0
    t = tri.transform[found[inside]]
    c = np.einsum("ijk,ik->ij", t[:, :dims], queries[inside] - t[:, dims])
    assert (c >= -1e-9).all() and (c.sum(axis=1) <= 1 + 1e-9).all()


def test_every_delaunay_simplex_is_exactly_empty_in_5d():
    points = np.random.default_rng(5).random((30, 5))
    tri = Delaunay(points)
    for simplex in tri.simplices:
        rows = [lifted_row(points[i]) for i in simplex]
        orientation = exact_det([r[:5] + [Fraction(1)] for r in rows])
        assert orientation > 0  # positively oriented, never flat
        for q in range(len(points)):
            if q not in simplex:
                # Strictly outside the circumsphere: with the corners positively oriented and the
                # lift before the ones column, the determinant is negative (a lifted point above).
                assert exact_det(rows + [lifted_row(points[q])]) < 0
    # The simplices fill the hull exactly once.
    volumes = [abs(exact_det([[Fraction(v) for v in points[i] - points[s[0]]] for i in s[1:]])) for s in tri.simplices]
    assert float(sum(volumes)) / 120 == pytest.approx(ConvexHull(points).volume, rel=1e-12)


@pytest.mark.parametrize("dims", [4, 5])
def test_cospherical_grids_and_cube_corners(dims):
    # Corners of the unit cube: all on one sphere (the lifted points span one dimension less).
    corners = np.array(list(itertools.product((0.0, 1.0), repeat=dims)))
    tri = Delaunay(corners)
    volumes = np.abs(np.linalg.det(corners[tri.simplices[:, 1:]] - corners[tri.simplices[:, :1]]))
    assert (volumes > 0.5).all()  # integer volumes times d!: never flat
    assert volumes.sum() / np.prod(np.arange(1, dims + 1)) == pytest.approx(1.0)
    # All simplices share the one circumsphere.
    core = hullkit._core.TriangulationNd(corners, False)
    assert (core.group == 0).all()
    # A grid with repeats: repeated points are listed as coplanar with their representative.
    axis = np.linspace(0, 1, 3)
    grid = np.array(list(itertools.product(axis, repeat=dims)))
    tri = Delaunay(np.concatenate([grid, grid[:5]]))
    volumes = np.abs(np.linalg.det(grid[tri.simplices[:, 1:]] - grid[tri.simplices[:, :1]]))
    assert volumes.min() > 1e-3 and volumes.sum() / np.prod(np.arange(1, dims + 1)) == pytest.approx(1.0)
    assert tri.coplanar[:, 0].tolist() == list(range(len(grid), len(grid) + 5))
    assert tri.coplanar[:, 2].tolist() == list(range(5))
    assert set(np.unique(tri.simplices)) == set(range(len(grid)))
    # Every grid point is found in a simplex of its own (on faces: the lowest-indexed one).
    found = tri.find_simplex(grid)
    assert (found >= 0).all()
    assert all(i in tri.simplices[s] for i, s in enumerate(found))
    assert (tri.find_simplex(grid + 2.0) == -1).all()


def test_furthest_site_in_4d():
    points = np.random.default_rng(7).random((25, 4))
    tri, qhull = Delaunay(points, furthest_site=True), sp.Delaunay(points, furthest_site=True)
    assert as_sets(tri.simplices) == as_sets(qhull.simplices)
    # Every point inside or on each simplex's circumsphere.
    centre = np.array([np.linalg.solve(2 * (points[s[1:]] - points[s[0]]),
                                       (points[s[1:]] ** 2).sum(1) - (points[s[0]] ** 2).sum()) for s in tri.simplices])
    radius = np.linalg.norm(points[tri.simplices[:, 0]] - centre, axis=1)
    distance = np.linalg.norm(points[None, :, :] - centre[:, None, :], axis=2)
    assert (distance <= radius[:, None] * (1 + 1e-12)).all()


def test_voronoi_in_4d_against_qhull():
    points = np.random.default_rng(11).random((40, 4))
    vor, reference = Voronoi(points), sp.Voronoi(points)
    assert len(vor.vertices) == len(reference.vertices)
    ours = np.round(vor.vertices, 9)
    theirs = np.round(reference.vertices, 9)
    # Every ridge of Qhull's is here; Qhull leaves out the unbounded ridges with fewer than 4 listed
    # vertices (a hull edge with one to two simplices around it), which are 3-dimensional all the same.
    ours_ridges, qhull_ridges = as_sets(vor.ridge_points), as_sets(reference.ridge_points)
    assert qhull_ridges <= ours_ridges
    for pair in ours_ridges - qhull_ridges:
        assert -1 in vor.ridge_dict[pair] and len(vor.ridge_dict[pair]) < 4
    for pair in qhull_ridges:
        mine = vor.ridge_dict[pair] if pair in vor.ridge_dict else vor.ridge_dict[pair[::-1]]
        other = reference.ridge_dict[pair] if pair in reference.ridge_dict else reference.ridge_dict[pair[::-1]]
        assert (-1 in mine) == (-1 in other) and len(mine) == len(other)
        assert {tuple(np.round(vor.vertices[i], 9)) for i in mine if i >= 0} == \
            {tuple(np.round(reference.vertices[i], 9)) for i in other if i >= 0}
    # The same vertices (circumcentres), matched by position.
    assert {tuple(v) for v in ours.tolist()} == {tuple(v) for v in theirs.tolist()}
    # Regions: the same vertex positions per point, -1 for unbounded cells.
    for p in range(len(points)):
        mine = vor.regions[vor.point_region[p]]
        other = reference.regions[reference.point_region[p]]
        assert (-1 in mine) == (-1 in other)
        assert {tuple(v) for v in ours[[i for i in mine if i >= 0]].tolist()} == \
            {tuple(v) for v in theirs[[i for i in other if i >= 0]].tolist()}
        if -1 not in mine:
            assert vor.volumes[p] == pytest.approx(sp.ConvexHull(reference.vertices[other]).volume, rel=1e-9)
        else:
            assert vor.volumes[p] == np.inf


def rounded_sets(vor, indices):
    return {tuple(np.round(vor.vertices[i], 9)) if i >= 0 else None for i in indices}


@pytest.mark.parametrize("shape", [(2, 2, 2, 2), (3, 3, 3, 3), (4, 3, 3, 2), (3, 3, 2, 2, 2)])
def test_voronoi_of_grids_in_4d_and_5d(shape):
    # Every cell of a grid is a cube around its point: one vertex per grid cell (its centre, where
    # the cell's 2^k corners are cospherical), a ridge exactly for each pair of points one step
    # apart along an axis (diagonal neighbours meet in less than a ridge), its vertices the centres
    # of the grid cells around that grid edge, unbounded when the edge lies on the grid's boundary.
    points = np.array(list(itertools.product(*[range(n) for n in shape])), dtype=float)
    k = len(shape)
    vor = Voronoi(points)
    centres = {tuple(x + 0.5 for x in c) for c in itertools.product(*[range(n - 1) for n in shape])}
    assert len(vor.vertices) == len(centres)
    assert {tuple(v) for v in vor.vertices.tolist()} == centres  # exactly
    index = {tuple(p): i for i, p in enumerate(points.tolist())}
    edges = set()
    for p in points.tolist():
        for axis in range(k):
            q = list(p)
            q[axis] += 1
            if tuple(q) in index:
                edges.add((index[tuple(p)], index[tuple(q)]))
    assert as_sets(vor.ridge_points) == edges
    upper = np.array(shape) - 1
    for (i, j), ridge in zip(vor.ridge_points.tolist(), vor.ridge_vertices):
        a, b = points[i], points[j]
        axis = int(np.flatnonzero(a != b)[0])
        low = min(a[axis], b[axis])
        around = set()
        for offsets in itertools.product((-0.5, 0.5), repeat=k - 1):
            centre = np.insert(a[np.arange(k) != axis] + offsets, axis, low + 0.5)
            if ((centre > 0) & (centre < upper)).all():
                around.add(tuple(centre))
        boundary = bool(((np.delete(a, axis) == 0) | (np.delete(a, axis) == np.delete(upper, axis))).any())
        assert {tuple(vor.vertices[v]) for v in ridge if v >= 0} == around
        assert (-1 in ridge) == boundary and len(ridge) == len(set(ridge))
    inside = ((points > 0) & (points < upper)).all(axis=1)
    volumes = vor.volumes
    assert (volumes[inside] == 1.0).all() and np.isinf(volumes[~inside]).all()
    for p in range(len(points)):
        region = vor.regions[vor.point_region[p]]
        assert (-1 in region) == (not inside[p])
        assert len([v for v in region if v >= 0]) == sum(
            1 for c in centres if (np.abs(np.array(c) - points[p]) == 0.5).all())


def ridge_margin(points, i, j):
    """How far inside the bisector of points i and j the nearest other point can be kept (a linear
    program: the largest t with |x - p_i|^2 + t <= |x - p_k|^2 for every other k, x on the
    bisector, t <= 1): positive exactly when the cells of i and j share a face of full dimension."""
    from scipy.optimize import linprog
    others = [k for k in range(len(points)) if k not in (i, j)]
    a_ub = np.c_[2 * (points[others] - points[i]), np.ones(len(others))]
    b_ub = (points[others] ** 2).sum(axis=1) - points[i] @ points[i]
    a_eq = np.r_[2 * (points[j] - points[i]), 0.0][None]
    b_eq = [points[j] @ points[j] - points[i] @ points[i]]
    k = points.shape[1]
    result = linprog(np.r_[np.zeros(k), -1.0], A_ub=a_ub, b_ub=b_ub, A_eq=a_eq, b_eq=b_eq,
                     bounds=[(None, None)] * k + [(None, 1.0)])
    assert result.status == 0
    return -result.fun


def test_voronoi_of_cospherical_points_in_4d_against_qhull():
    # Random subsets of a 4^4 lattice: many groups of cospherical points of every size. Vertices
    # and regions are Qhull's (it merges those simplices too). Qhull also lists, as ridges, pairs
    # whose cells meet in less than a 3-dimensional face; the ridges here are exactly the pairs
    # whose cells share a 3-dimensional face (checked for every pair by a linear program on the
    # first subset), with Qhull's vertices where both list a pair.
    lattice = np.array(list(itertools.product(range(4), repeat=4)), dtype=float)
    for seed in range(3):
        points = lattice[np.random.default_rng(seed).choice(len(lattice), 60, replace=False)]
        vor, reference = Voronoi(points), sp.Voronoi(points)
        assert {tuple(v) for v in np.round(vor.vertices, 9).tolist()} == \
            {tuple(v) for v in np.round(reference.vertices, 9).tolist()}
        for p in range(len(points)):
            assert rounded_sets(vor, vor.regions[vor.point_region[p]]) == \
                rounded_sets(reference, reference.regions[reference.point_region[p]])
        ours = {tuple(sorted(pair)): ridge for pair, ridge in zip(vor.ridge_points.tolist(), vor.ridge_vertices)}
        for pair, ridge in zip(reference.ridge_points.tolist(), reference.ridge_vertices):
            if tuple(sorted(pair)) in ours:
                assert rounded_sets(vor, ours[tuple(sorted(pair))]) - {None} == rounded_sets(reference, ridge) - {None}
        for pair, ridge in ours.items():
            cells = [rounded_sets(vor, vor.regions[vor.point_region[p]]) for p in pair]
            assert rounded_sets(vor, ridge) <= cells[0] & cells[1]
        if seed == 0:
            for i, j in itertools.combinations(range(len(points)), 2):
                assert (ridge_margin(points, i, j) > 1e-7) == ((i, j) in ours), (i, j)


def test_voronoi_of_the_4d_cross_polytope():
    # Its 8 corners lie on one sphere: one vertex (the centre), a ridge for each of the 24 edges
    # (unbounded), none between opposite corners, whose cells meet only at the centre.
    points = np.vstack([np.eye(4), -np.eye(4)])
    vor = Voronoi(points)
    assert vor.vertices.tolist() == [[0.0, 0.0, 0.0, 0.0]]
    assert as_sets(vor.ridge_points) == {(i, j) for i in range(8) for j in range(i + 1, 8) if j != i + 4}
    assert all(sorted(ridge) == [-1, 0] for ridge in vor.ridge_vertices)
    assert all(sorted(vor.regions[r]) == [-1, 0] for r in vor.point_region)
    assert np.isinf(vor.volumes).all()


def test_errors_name_the_problem():
    with pytest.raises(hullkit.HullkitError, match="lie in a flat of 3 dimensions"):
        ConvexHull(np.c_[np.random.default_rng(1).random((20, 3)), np.zeros(20)])
    with pytest.raises(hullkit.HullkitError, match="lie in a flat of 3 dimensions"):
        Delaunay(np.c_[np.random.default_rng(1).random((20, 3)), np.ones(20)])
    with pytest.raises(hullkit.HullkitError, match="at least 6 points"):
        ConvexHull(np.random.default_rng(1).random((5, 5)))
    points = np.random.default_rng(2).random((20, 4))
    points[7, 2] = np.nan
    with pytest.raises(hullkit.HullkitError, match="point 7 has a non-finite coordinate 2") as caught:
        Delaunay(points)
    assert caught.value.point == 7
    with pytest.raises(hullkit.HullkitError, match="QG, Qc and Qi in 4 dimensions"):
        ConvexHull(np.random.default_rng(3).random((20, 4)), qhull_options="Qc")


def test_incremental_in_5d_is_the_single_call():
    points = np.random.default_rng(9).random((40, 5))
    grown = Delaunay(points[:10], incremental=True)
    grown.add_points(points[10:])
    assert as_sets(grown.simplices) == as_sets(Delaunay(points).simplices)


def test_halfspace_intersection_of_a_4d_cube_and_cross_polytope():
    from hullkit.spatial import HalfspaceIntersection
    # The 4-cube |x_i| <= 1: 8 halfspaces, 16 corners where 4 planes meet.
    cube = np.hstack([np.vstack([np.eye(4), -np.eye(4)]), -np.ones((8, 1))])
    hs = HalfspaceIntersection(cube, np.zeros(4))
    assert sorted(map(tuple, hs.intersections.tolist())) == sorted(itertools.product((-1.0, 1.0), repeat=4))
    assert all(len(f) == 4 for f in hs.dual_facets) and len(hs.dual_facets) == 16
    assert hs.dual_volume == pytest.approx(2 ** 4 / 24)  # the dual: the cross-polytope of radius 1
    # The cross-polytope sum |x_i| <= 1: 16 halfspaces, 8 corners where 8 planes meet (merged facets).
    signs = np.array(list(itertools.product((-1.0, 1.0), repeat=4)))
    cross = np.hstack([signs, -np.ones((16, 1))])
    hs = HalfspaceIntersection(cross, np.zeros(4))  # dual points exactly the signs: 8 exactly coplanar per facet
    corners = sorted(map(tuple, np.round(hs.intersections, 12).tolist()))
    assert corners == sorted(map(tuple, np.vstack([np.eye(4), -np.eye(4)]).tolist()))
    assert sorted(len(f) for f in hs.dual_facets) == [8] * 8
    # Every corner lies on exactly its facet's planes, inside all the others.
    for corner, facet in zip(hs.intersections, hs.dual_facets):
        values = cross[:, :4] @ corner + cross[:, 4]
        assert np.allclose(values[facet], 0) and (np.delete(values, facet) < -1e-9).all()
    with pytest.raises(hullkit.HullkitError, match="unbounded"):
        HalfspaceIntersection(cube[:7], np.zeros(4))
