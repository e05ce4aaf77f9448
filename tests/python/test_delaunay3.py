"""hullkit.delaunay3 and hullkit.verify_delaunay3 against scipy.spatial.Delaunay (Qhull) in 3D: the
same tetrahedra in general position, hullkit's exact verifier accepting the result and rejecting
tampered ones, grids (where Qhull leaves flat tetrahedra), lower dimensions, duplicates, errors,
threads and input conversions."""
import doctest
import time

import numpy as np
import pytest
import scipy.spatial

import hullkit
import hullkit.spatial


def row_set(simplices):
    return set(map(tuple, np.sort(np.asarray(simplices, dtype=np.int64), axis=1).tolist()))


def six_volumes(points, tetrahedra):
    """Six times each tetrahedron's signed volume (exact for small integer coordinates)."""
    a, b, c, d = (points[np.asarray(tetrahedra, dtype=np.int64)[:, k]] for k in range(4))
    return np.einsum("ij,ij->i", np.cross(b - a, c - a), d - a)


def grid(nx, ny, nz):
    axes = np.meshgrid(np.arange(float(nx)), np.arange(float(ny)), np.arange(float(nz)), indexing="ij")
    return np.stack(axes, axis=-1).reshape(-1, 3)


def test_docstring_examples_run():
    for function in (hullkit.delaunay3, hullkit.verify_delaunay3, hullkit.spatial.Delaunay,
                     hullkit.Delaunay3.locate, hullkit.Delaunay3.voronoi):
        finder = doctest.DocTestFinder(recurse=False)
        runner = doctest.DocTestRunner()
        for test in finder.find(function, function.__name__, globs={}):
            runner.run(test)
        assert runner.failures == 0 and runner.tries > 0, function.__name__


@pytest.mark.parametrize("seed", [1, 2])
def test_matches_scipy_in_general_position(seed):
    points = np.random.default_rng(seed).random((3000, 3))
    ours, theirs = hullkit.delaunay3(points), scipy.spatial.Delaunay(points)
    assert ours.dimension == 3 and ours.duplicate_count == 0
    assert ours.tetrahedra.dtype == np.uint32 and ours.tetrahedra.shape == theirs.simplices.shape
    assert ours.neighbors.dtype == np.int32 and ours.neighbors.shape == ours.tetrahedra.shape
    assert ours.hull.dtype == np.uint32 and ours.hull.shape[1] == 3
    assert row_set(ours.tetrahedra) == row_set(theirs.simplices)
    assert row_set(ours.hull) == row_set(theirs.convex_hull)
    np.testing.assert_array_equal(ours.representative, np.arange(3000))
    assert (six_volumes(points, ours.tetrahedra) > 0).all()  # positively oriented
    # uint32 indices index like intc ones
    np.testing.assert_array_equal(points[ours.tetrahedra], points[ours.tetrahedra.astype(np.intc)])
    # neighbors[t, k]: the tetrahedron across the face opposite corner k, -1 exactly on the hull
    tets = ours.tetrahedra.astype(np.int64)
    across = ours.neighbors.astype(np.int64)
    t, k = np.nonzero(across >= 0)
    u = across[t, k]
    shared = (tets[u][:, :, None] == tets[t][:, None, :]).any(axis=1).sum(axis=1)
    assert (shared == 3).all()  # they share a face ...
    assert not (tets[u] == tets[t, k][:, None]).any()  # ... and not the corner opposite it
    assert (across[u] == t[:, None]).any(axis=1).all()  # and it points back
    t, k = np.nonzero(across < 0)
    faces = [tuple(sorted(set(row) - {row[j]})) for row, j in zip(tets[t].tolist(), k.tolist())]
    assert set(faces) == row_set(ours.hull) and len(faces) == len(ours.hull)
    for name in ("tetrahedra", "neighbors", "hull", "representative"):
        with pytest.raises(ValueError):
            getattr(ours, name)[0] = 0  # read-only views of the core's result
    report = hullkit.verify_delaunay3(points, ours.tetrahedra)
    assert report["ok"] and report["problem_count"] == 0, report["problems"]
    assert report["distinct_points"] == 3000 and report["hull_triangles"] == len(ours.hull)
    assert hullkit.verify_delaunay3(points, ours)["ok"]
    # Qhull's simplices come in either orientation, which the verifier refuses; turned positive
    # they pass the same exact check.
    qhull = theirs.simplices.copy()
    report = hullkit.verify_delaunay3(points, qhull)
    assert not report["ok"] and "negatively oriented" in report["problems"][0]
    negative = six_volumes(points, qhull) < 0
    qhull[negative, :2] = qhull[negative, 1::-1]
    assert hullkit.verify_delaunay3(points, qhull)["ok"]


def orient(a, b, c, d):
    return float(np.dot(np.cross(b - a, c - a), d - a))


def two_three_flip(points, tetrahedra):
    """The first 2-3 flip that applies: tetrahedra (a b c p) and (a b c q) sharing face abc where
    segment pq crosses the triangle abc become (a b p q), (b c p q), (c a p q), each oriented."""
    lookup = {}
    for t, row in enumerate(tetrahedra.tolist()):
        for k in range(4):
            face = tuple(sorted(row[:k] + row[k + 1:]))
            if face in lookup:
                u, q = lookup[face]
                p = row[k]
                a, b, c = face
                sides = [orient(points[p], points[q], points[x], points[y]) for x, y in ((a, b), (b, c), (c, a))]
                if all(side > 0 for side in sides) or all(side < 0 for side in sides):
                    new = []
                    for x, y in ((a, b), (b, c), (c, a)):
                        tet = [x, y, p, q]
                        if orient(*points[tet]) < 0:
                            tet[0], tet[1] = tet[1], tet[0]
                        new.append(tet)
                    kept = np.delete(tetrahedra, [t, u], axis=0)
                    return np.concatenate([kept, np.array(new, dtype=tetrahedra.dtype)])
            else:
                lookup[face] = (t, row[k])
    raise AssertionError("no 2-3 flip applies")


def test_verifier_rejects_tampered_tetrahedralizations():
    points = np.random.default_rng(3).random((400, 3))
    good = np.array(hullkit.delaunay3(points).tetrahedra)
    flipped = good.copy()
    flipped[7, [0, 1]] = flipped[7, [1, 0]]  # one tetrahedron turned inside out
    missing = good[1:]
    doubled = np.concatenate([good, good[:1]])
    moved = good.copy()
    moved[0, 3] = next(i for i in range(400) if i not in good[0])  # a corner that is not its own
    for name, tampered in (("flipped", flipped), ("missing", missing), ("doubled", doubled), ("moved", moved)):
        report = hullkit.verify_delaunay3(points, tampered)
        assert not report["ok"] and report["problem_count"] > 0 and report["problems"], name
    # A valid tetrahedralization that is not Delaunay: two tetrahedra across an interior face
    # whose union is convex replaced by the three around the segment joining their apexes.
    flipped_23 = two_three_flip(points, good)
    report = hullkit.verify_delaunay3(points, flipped_23)
    assert not report["ok"] and report["problem_count"] > 0
    assert hullkit.verify_delaunay3(points, flipped_23, perturbed=False)["ok"] is False
    out_of_range = good.copy()
    out_of_range[0, 0] = 400
    report = hullkit.verify_delaunay3(points, out_of_range)
    assert not report["ok"] and "has index 400 but there are 400 points" in report["problems"][0]
    with pytest.raises(hullkit.HullkitError, match=r"shape \(m, 4\)"):
        hullkit.verify_delaunay3(points, good[:, :3])


def test_grid_no_flat_tetrahedra_where_qhull_leaves_some():
    points = grid(6, 5, 4)
    ours, theirs = hullkit.delaunay3(points), scipy.spatial.Delaunay(points)
    box = 5 * 4 * 3
    ours_volumes = six_volumes(points, ours.tetrahedra)  # integers: exact in float64
    theirs_volumes = six_volumes(points, theirs.simplices)
    assert (ours_volumes > 0).all()  # none flat, all positively oriented
    assert ours_volumes.sum() == 6 * box  # they fill the box exactly
    assert len(ours.tetrahedra) == 6 * box  # every unit cube in six (the tie rule's choice)
    # Qhull (scipy's default options) leaves flat slivers on the cospherical cubes here: 95 of its
    # 455 simplices have zero volume; the rest fill the box too.
    assert (theirs_volumes == 0).sum() > 0
    assert np.abs(theirs_volumes).sum() == 6 * box
    assert hullkit.verify_delaunay3(points, ours.tetrahedra)["ok"]
    # The answer depends only on the points, not on their order.
    order = np.random.default_rng(5).permutation(len(points))
    shuffled = hullkit.delaunay3(points[order])
    assert row_set(order[shuffled.tetrahedra.astype(np.int64)]) == row_set(ours.tetrahedra)


def test_coplanar_points_give_the_planar_triangulation():
    rng = np.random.default_rng(6)
    # Integer points on a tilted plane, exactly: origin + s u + t v with u, v orthogonal and of the
    # same length (a similarity, so the plane's Delaunay triangulation is that of (s, t)).
    st = rng.choice(10**6, size=(600, 2), replace=False).astype(float)
    u, v = np.array([1.0, 2.0, 2.0]), np.array([2.0, 1.0, -2.0])
    points = np.array([7.0, -3.0, 11.0]) + st[:, :1] * u + st[:, 1:] * v
    d = hullkit.delaunay3(points)
    assert d.dimension == 2
    assert d.tetrahedra.shape == (0, 4) and d.hull.shape == (0, 3)
    assert d.triangles.dtype == np.uint32 and d.neighbors.shape == d.triangles.shape
    assert row_set(d.triangles) == row_set(scipy.spatial.Delaunay(st).simplices)
    np.testing.assert_allclose(d.normal, [2 / 3, -2 / 3, 1 / 3], atol=1e-15)
    tri = d.triangles.astype(np.int64)
    a, b, c = (points[tri[:, k]] for k in range(3))
    assert (np.cross(b - a, c - a) @ d.normal > 0).all()  # counter-clockwise seen from the normal
    t, k = np.nonzero(d.neighbors >= 0)
    across = d.neighbors[t, k].astype(np.int64)
    assert not (tri[across] == tri[t, k][:, None]).any()
    assert ((tri[across][:, :, None] == tri[t][:, None, :]).any(axis=1).sum(axis=1) == 2).all()
    with pytest.raises(scipy.spatial.QhullError):
        scipy.spatial.Delaunay(points)
    flat = hullkit.spatial.Delaunay(points)
    assert flat.dimension == 2 and flat.nsimplex == 0 and flat.simplices.shape == (0, 4)
    assert row_set(flat.convex_hull) == row_set(d.triangles)


def test_collinear_one_point_and_none():
    steps = np.random.default_rng(7).permutation(50).astype(float)
    line = np.array([1.0, 2.0, 3.0]) + steps[:, None] * np.array([0.5, -1.0, 2.0])
    d = hullkit.delaunay3(line)
    assert d.dimension == 1 and d.tetrahedra.shape == (0, 4) and d.triangles.shape == (0, 3)
    along = np.diff(steps[d.vertices])  # in order along the line, one way or the other
    assert len(d.vertices) == 50 and ((along > 0).all() or (along < 0).all())
    s = hullkit.spatial.Delaunay(line)
    assert s.nsimplex == 0 and s.convex_hull.shape == (0, 3)
    ip, ix = s.vertex_neighbor_vertices
    middle = int(np.flatnonzero(steps == 20)[0])
    assert sorted(steps[ix[ip[middle]:ip[middle + 1]]].tolist()) == [19.0, 21.0]
    one = hullkit.delaunay3([[1.0, 2.0, 3.0]] * 3)
    assert one.dimension == 0 and one.vertices.tolist() == [0] and one.duplicate_count == 2
    assert one.representative.tolist() == [0, 0, 0]
    none = hullkit.delaunay3(np.zeros((0, 3)))
    assert none.dimension == -1 and none.tetrahedra.shape == (0, 4) and len(none.vertices) == 0


def test_duplicates_are_merged_into_their_first_copy():
    rng = np.random.default_rng(8)
    points = rng.random((500, 3))
    repeated = np.concatenate([points, points[:20], points[5:8]])
    d, plain = hullkit.delaunay3(repeated), hullkit.delaunay3(points)
    assert d.duplicate_count == 23
    assert row_set(d.tetrahedra) == row_set(plain.tetrahedra)
    expected = np.concatenate([np.arange(500), np.arange(20), np.arange(5, 8)])
    np.testing.assert_array_equal(d.representative, expected)
    assert d.tetrahedra.max() < 500  # the later copies are no corner
    assert hullkit.verify_delaunay3(repeated, d.tetrahedra)["ok"]
    ours, theirs = hullkit.spatial.Delaunay(repeated), scipy.spatial.Delaunay(repeated)
    # Both list the duplicates as "coplanar": each with a simplex and the vertex standing for it.
    assert ours.coplanar.shape == theirs.coplanar.shape == (23, 3)
    assert ours.coplanar[:, 0].tolist() == list(range(500, 523))
    for point, simplex, vertex in ours.coplanar:
        assert (repeated[point] == repeated[vertex]).all() and vertex in ours.simplices[simplex]


def test_bad_input_raises_hullkit_error_naming_the_point():
    points = np.random.default_rng(9).random((50, 3))
    points[17, 1] = np.nan
    with pytest.raises(hullkit.HullkitError, match=r"point 17\b.*non-finite") as caught:
        hullkit.delaunay3(points)
    assert caught.value.point == 17 and isinstance(caught.value, ValueError)
    points[17, 1] = 0.5
    points[31, 2] = -np.inf
    with pytest.raises(hullkit.HullkitError, match=r"point 31\b") as caught:
        hullkit.delaunay3(points)
    assert caught.value.point == 31
    with pytest.raises(hullkit.HullkitError, match=r"shape \(n, 3\)"):
        hullkit.delaunay3(np.zeros((5, 2)))
    with pytest.raises(hullkit.HullkitError, match=r"shape \(n, 3\)"):
        hullkit.delaunay3(np.zeros(6))
    with pytest.raises(hullkit.HullkitError, match="convertible to float64"):
        hullkit.delaunay3([["a", "b", "c"]])
    with pytest.raises(hullkit.HullkitError, match="threads"):
        hullkit.delaunay3(np.zeros((4, 3)), threads=-1)


def test_conversions_float32_lists_and_strided():
    base = np.random.default_rng(10).random((2000, 3))
    single = base.astype(np.float32)
    d = hullkit.delaunay3(single)
    assert d.points.dtype == np.float64
    np.testing.assert_array_equal(d.tetrahedra, hullkit.delaunay3(single.astype(np.float64)).tetrahedra)
    small = base[:60]
    np.testing.assert_array_equal(hullkit.delaunay3(small.tolist()).tetrahedra, hullkit.delaunay3(small).tetrahedra)
    wide = np.random.default_rng(11).random((2000, 5))
    strided = wide[:, 1:4]  # not contiguous
    assert not strided.flags.c_contiguous
    np.testing.assert_array_equal(hullkit.delaunay3(strided).tetrahedra,
                                  hullkit.delaunay3(np.ascontiguousarray(strided)).tetrahedra)
    fortran = np.asfortranarray(base)
    np.testing.assert_array_equal(hullkit.delaunay3(fortran).tetrahedra, hullkit.delaunay3(base).tetrahedra)
    contiguous = np.ascontiguousarray(base)
    assert hullkit.delaunay3(contiguous).points is contiguous  # used as it is, no copy


def test_large_input_threads_give_identical_arrays():
    points = np.random.default_rng(12).random((200_000, 3))
    start = time.perf_counter()
    one = hullkit.delaunay3(points, threads=1)
    seconds = time.perf_counter() - start
    two = hullkit.delaunay3(points, threads=2)
    for name in ("tetrahedra", "neighbors", "hull", "representative"):
        np.testing.assert_array_equal(getattr(one, name), getattr(two, name), err_msg=name)
    # About 2.5 s on a shared 2-core machine (scipy: about 18 s); the bound only catches a
    # pathological slowdown, not noise.
    assert seconds < 60
    assert 6 * len(points) < len(one.tetrahedra) < 7 * len(points)
    assert int((one.neighbors < 0).sum()) == len(one.hull)  # a face slot without neighbour per hull face
    assert hullkit.verify_delaunay3(points, one.tetrahedra)["ok"]


def test_locate_vertices_centroids_outside_and_nearest():
    rng = np.random.default_rng(21)
    points = rng.random((3000, 3))
    d = hullkit.delaunay3(points)
    # An input point is a vertex: found in the lowest-indexed tetrahedron around it, which has it
    # as a corner, with weight exactly 1 there and 0 elsewhere; its nearest point is itself.
    found = d.locate(points, barycentric=True, nearest=True, threads=2)
    t, w = found["tetrahedron"], found["barycentric"]
    assert t.dtype == np.int32 and t.shape == (3000,) and w.shape == (3000, 4)
    corners = d.tetrahedra[t]
    at = corners == np.arange(3000)[:, None]
    assert at.sum(axis=1).tolist() == [1] * 3000
    assert (w[at] == 1).all() and (w[~at] == 0).all()
    around = [[] for _ in range(3000)]
    for k, tet in enumerate(d.tetrahedra.tolist()):
        for v in tet:
            around[v].append(k)
    assert t.tolist() == [min(ks) for ks in around]
    assert found["nearest"].tolist() == list(range(3000))
    # Centroids: strictly inside their own tetrahedron, weights 1/4 up to rounding; as scipy finds.
    centroids = points[d.tetrahedra].mean(axis=1)
    inside = d.locate(centroids, barycentric=True)
    np.testing.assert_array_equal(inside["tetrahedron"], np.arange(len(d.tetrahedra)))
    np.testing.assert_allclose(inside["barycentric"], 0.25, atol=1e-9)
    theirs = scipy.spatial.Delaunay(points)
    ours_sets = [tuple(sorted(tet)) for tet in d.tetrahedra[inside["tetrahedron"]].tolist()]
    theirs_sets = [tuple(sorted(tet)) for tet in theirs.simplices[theirs.find_simplex(centroids)].tolist()]
    assert ours_sets == theirs_sets
    # Random queries: nearest by brute force (exact squared distances of these doubles agree with
    # the ordering here except in ties, which random points do not have), outside ones -1 and NaN.
    queries = rng.random((500, 3)) * 1.4 - 0.2
    q = d.locate(queries, barycentric=True, nearest=True, threads=1)
    brute = np.argmin(((queries[:, None, :] - points[None, :, :]) ** 2).sum(axis=2), axis=1)
    np.testing.assert_array_equal(q["nearest"], brute)
    outside = q["tetrahedron"] < 0
    np.testing.assert_array_equal(outside, theirs.find_simplex(queries) < 0)
    assert np.isnan(q["barycentric"][outside]).all()
    got = np.einsum("qk,qkd->qd", q["barycentric"][~outside], points[d.tetrahedra[q["tetrahedron"][~outside]]])
    np.testing.assert_allclose(got, queries[~outside], atol=1e-12)
    # The same answers on any number of threads; only the asked arrays come back.
    again = d.locate(queries, barycentric=True, nearest=True, threads=3)
    for key in ("tetrahedron", "barycentric", "nearest"):
        np.testing.assert_array_equal(q[key], again[key])
    assert set(d.locate(queries).keys()) == {"tetrahedron"}


def test_locate_errors_and_flat_input():
    d = hullkit.delaunay3(grid(3, 3, 3))
    with pytest.raises(hullkit.HullkitError, match="query 1") as caught:
        d.locate([[0.5, 0.5, 0.5], [np.nan, 0, 0]])
    assert caught.value.point == 1
    with pytest.raises(hullkit.HullkitError, match="shape"):
        d.locate([[0.5, 0.5]])
    flat = hullkit.delaunay3([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]])
    assert flat.dimension == 2
    assert flat.locate([[0.2, 0.2, 0.0]])["tetrahedron"].tolist() == [-1]
    assert hullkit.spatial.Delaunay([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]]).find_simplex([[0.2, 0.2, 0]]).tolist() == [-1]


def test_voronoi_grid_cells_and_scipy_volumes():
    # A 4x4x4 grid: the 8 inner points' cells are unit cubes (one vertex per grid cube, shared by
    # its cospherical tetrahedra), the 56 on the hull unbounded.
    v = hullkit.delaunay3(grid(4, 4, 4)).voronoi()
    inner = [i for i, (x, y, z) in enumerate(grid(4, 4, 4).tolist()) if 0 < x < 3 and 0 < y < 3 and 0 < z < 3]
    assert v["volume"][inner].tolist() == [1.0] * 8
    assert np.isinf(v["volume"]).sum() == 56
    assert v["vertices"].shape == (27, 3)
    np.testing.assert_array_equal(np.sort(v["vertices"], axis=0), np.sort(grid(3, 3, 3) + 0.5, axis=0))
    # Random points: each bounded cell's volume is the volume of the hull of scipy's Voronoi region.
    rng = np.random.default_rng(8)
    points = rng.random((400, 3))
    ours = hullkit.delaunay3(points).voronoi()
    theirs = scipy.spatial.Voronoi(points)
    bounded = 0
    for i in range(400):
        region = theirs.regions[theirs.point_region[i]]
        if -1 in region or not region:
            assert np.isinf(ours["volume"][i])
            continue
        bounded += 1
        expected = scipy.spatial.ConvexHull(theirs.vertices[region]).volume
        assert ours["volume"][i] == pytest.approx(expected, rel=1e-9)
    assert bounded > 100
    # Faces: each separates two points joined by a Delaunay edge; a cell's faces name the point.
    fp = ours["face_points"]
    assert fp.shape[1] == 2 and (fp[:, 0] < fp[:, 1]).all()
    offsets, faces = ours["cell_offsets"], ours["cell_faces"]
    for i in range(400):
        assert all(i in fp[f].tolist() for f in faces[offsets[i]:offsets[i + 1]])
