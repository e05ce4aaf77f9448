"""hullkit.triangulate_polygon and hullkit.triangulate (Triangle's dictionary and switches):
checked exactly with fractions (orientation, area), against scipy's Delaunay (Qhull) where no
segment constrains anything, and for their errors."""

from fractions import Fraction

import numpy as np
import pytest
import scipy.spatial

import hullkit

SQUARE_WITH_HOLE = {
    "vertices": [[0, 0], [4, 0], [4, 4], [0, 4], [1, 1], [3, 1], [3, 3], [1, 3]],
    "segments": [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4]],
    "holes": [[2, 2]],
}


def twice_areas(points, triangles):
    """Exact twice-areas of the triangles (positive counter-clockwise)."""
    out = []
    for a, b, c in triangles:
        (ax, ay), (bx, by), (cx, cy) = (map(Fraction, points[i]) for i in (a, b, c))
        out.append((bx - ax) * (cy - ay) - (by - ay) * (cx - ax))
    return out


def test_triangulate_polygon_square_with_hole_and_bowtie():
    r = hullkit.triangulate_polygon([0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 3, 1, 3, 3, 1, 3], [4])
    areas = twice_areas(r["coords"], r["triangles"])
    assert all(a < 0 for a in areas)  # clockwise with y up, as hullkit.delaunay's
    assert -sum(areas) == 24
    assert r["triangles"].shape == (8, 3) and r["constrained"].shape == (24,)
    filled = hullkit.triangulate_polygon(np.array([[0, 0], [4, 0], [4, 4], [0, 4], [1, 1], [3, 1], [3, 3], [1, 3]]), [4], fill="nonzero")
    assert -sum(twice_areas(filled["coords"], filled["triangles"])) == 32
    bowtie = hullkit.triangulate_polygon([[0, 0], [2, 2], [2, 0], [0, 2]])
    assert bowtie["crossing_count"] == 1
    assert bowtie["coords"][4].tolist() == [1.0, 1.0]
    assert -sum(twice_areas(bowtie["coords"], bowtie["triangles"])) == 4


def test_triangulate_as_triangle_takes_it():
    t = hullkit.triangulate(SQUARE_WITH_HOLE, "pneQ")
    areas = twice_areas(t["vertices"], t["triangles"])
    assert all(a > 0 for a in areas)  # counter-clockwise, as Triangle's
    assert sum(areas) == 24
    assert {tuple(sorted(s)) for s in t["segments"].tolist()} == {tuple(sorted(s)) for s in SQUARE_WITH_HOLE["segments"]}
    assert len(t["edges"]) == 16
    # neighbors[t][k] is across from corner k: it shares the two other corners.
    for i, row in enumerate(t["neighbors"]):
        for k, n in enumerate(row):
            if n >= 0:
                shared = set(t["triangles"][i]) - {t["triangles"][i][k]}
                assert shared <= set(t["triangles"][n])
    # Without the hole point the hole is meshed; without p, segments are not used at all.
    no_hole = {k: v for k, v in SQUARE_WITH_HOLE.items() if k != "holes"}
    assert sum(twice_areas(*(lambda d: (d["vertices"], d["triangles"]))(hullkit.triangulate(no_hole, "p")))) == 32


def test_triangulate_without_constraints_is_scipys_delaunay():
    rng = np.random.default_rng(4)
    points = rng.random((500, 2))
    ours = hullkit.triangulate({"vertices": points})
    theirs = scipy.spatial.Delaunay(points)
    assert {tuple(sorted(t)) for t in ours["triangles"].tolist()} == {tuple(sorted(t)) for t in theirs.simplices.tolist()}


def test_triangulate_pslg_exterior_and_convex():
    l_shape = {"vertices": [[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]], "segments": [[i, (i + 1) % 6] for i in range(6)]}
    assert sum(twice_areas(*(lambda d: (d["vertices"], d["triangles"]))(hullkit.triangulate(l_shape, "p")))) == 6
    assert sum(twice_areas(*(lambda d: (d["vertices"], d["triangles"]))(hullkit.triangulate(l_shape, "pc")))) == 7
    assert sum(twice_areas(*(lambda d: (d["vertices"], d["triangles"]))(hullkit.triangulate(l_shape, "p", convex=True)))) == 7


def test_clear_errors():
    with pytest.raises(hullkit.HullkitError, match="switch 'o' \\(second-order triangles"):
        hullkit.triangulate(SQUARE_WITH_HOLE, "po2")
    with pytest.raises(hullkit.HullkitError, match="keep_segments must be 0"):
        hullkit.triangulate_polygon([0, 0, 1, 0, 0, 1], keep_segments=3)
    with pytest.raises(hullkit.HullkitError, match="switch 'A' \\(regional attributes\\) needs 'p'"):
        hullkit.triangulate(SQUARE_WITH_HOLE, "A")
    with pytest.raises(hullkit.HullkitError, match=r"tri\['regions'\] must have shape"):
        hullkit.triangulate({**SQUARE_WITH_HOLE, "regions": [[0.5, 0.5, 1]]}, "pa")
    with pytest.raises(hullkit.HullkitError, match="min_angle must be from 0 to 34"):
        hullkit.triangulate(SQUARE_WITH_HOLE, "pq40")
    with pytest.raises(hullkit.HullkitError, match="switch 'p' takes no number"):
        hullkit.triangulate(SQUARE_WITH_HOLE, "p2")
    with pytest.raises(hullkit.HullkitError, match="max_steiner_points"):
        hullkit.triangulate(SQUARE_WITH_HOLE, "pa0.0001S50")
    with pytest.raises(hullkit.HullkitError, match="max_area must be"):
        hullkit.triangulate_polygon([0, 0, 1, 0, 0, 1], max_area=-2)
    with pytest.raises(hullkit.HullkitError, match="unknown switch '!'"):
        hullkit.triangulate(SQUARE_WITH_HOLE, "p!")
    with pytest.raises(hullkit.HullkitError, match="must index the 8 vertices"):
        hullkit.triangulate({**SQUARE_WITH_HOLE, "segments": [[0, 8]]}, "p")
    with pytest.raises(hullkit.HullkitError, match="fill must be"):
        hullkit.triangulate_polygon([0, 0, 1, 0, 0, 1], fill="winding")
    with pytest.raises(hullkit.HullkitError, match="hole_indices"):
        hullkit.triangulate_polygon([0, 0, 1, 0, 0, 1, 1, 1], [3, 1])
    with pytest.raises(hullkit.HullkitError) as error:
        hullkit.triangulate_polygon([0, 0, 1, 0, np.nan, 1])
    assert error.value.point == 2


def smallest_angle(points, triangles):
    p = np.asarray(points)[np.asarray(triangles)]
    best = 180.0
    for k in range(3):
        u = p[:, (k + 1) % 3] - p[:, k]
        v = p[:, (k + 2) % 3] - p[:, k]
        angle = np.degrees(np.arctan2(np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]), (u * v).sum(axis=1)))
        best = min(best, float(angle.min()))
    return best


def test_quality_meshes_as_triangle_makes_them():
    plain = hullkit.triangulate(SQUARE_WITH_HOLE, "p")
    for opts, angle, area in (("pq", 20, None), ("pq30", 30, None), ("pa0.1", None, 0.1), ("pq25a0.2D", 25, 0.2)):
        mesh = hullkit.triangulate(SQUARE_WITH_HOLE, opts)
        areas = twice_areas(mesh["vertices"], mesh["triangles"])
        assert all(a > 0 for a in areas)  # counter-clockwise, as Triangle's
        assert sum(areas) == sum(twice_areas(plain["vertices"], plain["triangles"])) == 24  # exact: points on the rings
        assert len(mesh["vertices"]) > 8, opts
        if angle:
            assert smallest_angle(mesh["vertices"], mesh["triangles"]) >= angle, opts
        if area:
            assert max(areas) <= 2 * area, opts
    # Keywords do what switches do, and give the same mesh.
    by_keyword = hullkit.triangulate(SQUARE_WITH_HOLE, "p", min_angle=30)
    assert np.array_equal(by_keyword["triangles"], hullkit.triangulate(SQUARE_WITH_HOLE, "pq30")["triangles"])
    # Regional areas with a bare 'a': the left region gets finer triangles than the global bound.
    split = {
        "vertices": [[0, 0], [2, 0], [4, 0], [4, 2], [2, 2], [0, 2]],
        "segments": [[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 0], [1, 4]],
        "regions": [[1, 1, 0, 0.05], [3, 1, 0, 0]],
    }
    mesh = hullkit.triangulate(split, "pa0.5a")
    pts, tris = mesh["vertices"], mesh["triangles"]
    areas = np.array(twice_areas(pts, tris), dtype=float) / 2
    left = pts[tris].mean(axis=1)[:, 0] < 2
    assert areas[left].max() <= 0.05 and areas[~left].max() <= 0.5 and areas[~left].max() > 0.05
    assert "regions" in mesh


def test_regional_attributes_as_triangles_A_switch():
    split = {
        "vertices": [[0, 0], [2, 0], [4, 0], [4, 2], [2, 2], [0, 2]],
        "segments": [[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 0], [1, 4]],
        "regions": [[1, 1, 7.5, 0.05], [3, 1, -1, 0], [3.5, 1.5, 2, 0]],  # the last two in one region: 2 wins
    }
    for opts in ("pA", "pAq30", "pAa"):
        mesh = hullkit.triangulate(split, opts)
        attributes = mesh["triangle_attributes"]
        assert attributes.shape == (len(mesh["triangles"]), 1)
        left = mesh["vertices"][mesh["triangles"]].mean(axis=1)[:, 0] < 2
        assert (attributes[left, 0] == 7.5).all() and (attributes[~left, 0] == 2).all(), opts
    # A region without a seed gets 0, as Triangle gives it; without 'A' no attributes.
    one = hullkit.triangulate({**split, "regions": [[3, 1, 4, 0]]}, "pA")
    left = one["vertices"][one["triangles"]].mean(axis=1)[:, 0] < 2
    assert (one["triangle_attributes"][left] == 0).all() and (one["triangle_attributes"][~left] == 4).all()
    assert (hullkit.triangulate({k: v for k, v in split.items() if k != "regions"}, "pA")["triangle_attributes"] == 0).all()
    assert "triangle_attributes" not in hullkit.triangulate(split, "p")


def test_no_steiner_points_on_kept_segments_Y_switch():
    split = {
        "vertices": [[0, 0], [2, 0], [4, 0], [4, 4], [2, 4], [0, 4]],
        "segments": [[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 0], [1, 4]],
    }

    def split_segments(mesh):  # (outline pieces, middle pieces): the segment edges on each
        seg = mesh["vertices"][mesh["segments"]]
        middle = (seg[:, :, 0] == 2).all(axis=1)
        return int((~middle).sum()), int(middle.sum())

    for opts, keyword, outline, middle_whole in (("pq25a0.1", 0, None, False), ("pq25a0.1Y", 1, 6, False),
                                                  ("pq25a0.1YY", 2, 6, True)):
        mesh = hullkit.triangulate(split, opts)
        assert np.array_equal(mesh["triangles"], hullkit.triangulate(split, "pq25a0.1", keep_segments=keyword)["triangles"])
        areas = np.array(twice_areas(mesh["vertices"], mesh["triangles"]), dtype=float) / 2
        assert areas.sum() == 16 and areas.max() <= 0.1, opts
        pieces, middle = split_segments(mesh)
        assert (pieces == outline) if outline else pieces > 6, opts
        assert (middle == 1) == middle_whole, opts
    ring = hullkit.triangulate_polygon([0, 0, 10, 0, 10, 10, 0, 10], max_area=0.5, keep_segments=1)
    assert ring["steiner_count"] > 0 and len(ring["coords"]) - ring["steiner_count"] == 4
    flat = ring["triangles"].ravel()
    boundary = [(flat[e], flat[e - 2 if e % 3 == 2 else e + 1]) for e in np.flatnonzero(ring["constrained"])]
    assert len(boundary) == 4 and all(a < 4 and b < 4 for a, b in boundary)  # the four sides, whole


def test_user_refinement_test_u_switch():
    # Triangle's triunsuitable: a size field, small triangles near (0, 0) only.
    calls = []

    def unsuitable(a, b, c, area):
        calls.append(area)
        cx, cy = (a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3
        return area > 0.01 + 0.05 * (cx * cx + cy * cy)

    square = {"vertices": [[0, 0], [4, 0], [4, 4], [0, 4]], "segments": [[0, 1], [1, 2], [2, 3], [3, 0]]}
    mesh = hullkit.triangulate(square, "pqu", unsuitable=unsuitable)
    assert calls and all(area > 0 for area in calls)  # counter-clockwise corners, in the input's units
    points = mesh["vertices"][mesh["triangles"]]
    areas = np.array(twice_areas(mesh["vertices"], mesh["triangles"]), dtype=float) / 2
    assert areas.sum() == 16 and smallest_angle(mesh["vertices"], mesh["triangles"]) >= 20
    centre = points.mean(axis=1)
    assert (areas <= 0.01 + 0.05 * (centre ** 2).sum(axis=1)).all()
    assert areas[(centre ** 2).sum(axis=1) < 0.5].max() <= 0.04 < areas.max()
    polygon = hullkit.triangulate_polygon([0, 0, 4, 0, 4, 4, 0, 4], unsuitable=unsuitable)
    assert polygon["steiner_count"] == len(mesh["vertices"]) - 4 or polygon["steiner_count"] > 0
    # Errors: 'u' without the function; the function's own exception; a result that is not a bool.
    with pytest.raises(hullkit.HullkitError, match="switch 'u'.*needs the test as unsuitable="):
        hullkit.triangulate(square, "pu")

    def broken(a, b, c, area):
        raise ZeroDivisionError("from the test")

    with pytest.raises(ZeroDivisionError, match="from the test"):
        hullkit.triangulate(square, "pu", unsuitable=broken)
    with pytest.raises(hullkit.HullkitError, match="unsuitable must return True or False"):
        hullkit.triangulate(square, "pu", unsuitable=lambda a, b, c, area: "yes")
    with pytest.raises(hullkit.HullkitError, match="unsuitable must be a function"):
        hullkit.triangulate_polygon([0, 0, 1, 0, 0, 1], unsuitable=3)


def test_triangulate_polygon_quality_keywords():
    r = hullkit.triangulate_polygon([0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 3, 1, 3, 3, 1, 3], [4], min_angle=28, max_area=0.3)
    assert r["steiner_count"] == len(r["coords"]) - 8 > 0
    assert r["unrefined_count"] == 0
    assert smallest_angle(r["coords"], r["triangles"]) >= 28
    assert -sum(twice_areas(r["coords"], r["triangles"])) == 24


def smallest_angle(points, triangles):
    """Degrees, measured (not decided) in floating point."""
    p = np.asarray(points, dtype=float)[np.asarray(triangles)]
    best = 180.0
    for k in range(3):
        u = p[:, (k + 1) % 3] - p[:, k]
        w = p[:, (k + 2) % 3] - p[:, k]
        angle = np.degrees(np.arctan2(np.abs(u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0]), (u * w).sum(axis=1)))
        best = min(best, angle.min())
    return best


def test_refine_an_earlier_output_r_switch():
    mesh = hullkit.triangulate(SQUARE_WITH_HOLE, "p")
    assert len(mesh["triangles"]) == 8
    refined = hullkit.triangulate(mesh, "rq30a0.1")  # the earlier output's 'holes' and 'segments' do not apply
    areas = twice_areas(refined["vertices"], refined["triangles"])
    assert all(a > 0 for a in areas) and sum(areas) == 24  # the annulus, its hole kept, counter-clockwise
    assert max(areas) <= Fraction(2 * 0.1)
    assert smallest_angle(refined["vertices"], refined["triangles"]) >= 30 - 1e-9
    assert np.array_equal(refined["vertices"][:8], np.asarray(SQUARE_WITH_HOLE["vertices"], dtype=float))
    centroids = refined["vertices"][refined["triangles"]].mean(axis=1)
    assert not ((centroids > 1) & (centroids < 3)).all(axis=1).any()
    # Segments: the boundary's edges, each once, add up to the two squares' perimeters.
    seg = refined["vertices"][refined["segments"]]
    assert np.isclose(np.linalg.norm(seg[:, 1] - seg[:, 0], axis=1).sum(), 16 + 8)
    # Refining again changes nothing that is already fine, and gives the same arrays every time.
    again = hullkit.triangulate(mesh, "rq30a0.1")
    assert np.array_equal(again["triangles"], refined["triangles"]) and np.array_equal(again["vertices"], refined["vertices"])


def test_refine_with_a_bound_per_triangle_ra():
    square = {"vertices": [[0, 0], [2, 0], [2, 2], [0, 2]], "triangles": [[0, 1, 2], [0, 2, 3]],
              "triangle_max_area": [0.01, -1]}
    out = hullkit.triangulate(square, "ra", max_area=0.5)
    tri, v = out["triangles"], out["vertices"]
    areas = [float(a) / 2 for a in twice_areas(v, tri)]
    assert sum(twice_areas(v, tri)) == 8
    below = [a for t, a in zip(tri, areas) if (v[t][:, 0] >= v[t][:, 1]).all()]  # in triangle 0 (x >= y)
    above = [a for t, a in zip(tri, areas) if (v[t][:, 0] <= v[t][:, 1]).all()]
    assert len(below) + len(above) == len(tri)  # the diagonal is kept: no triangle crosses it
    assert max(below) <= 0.01 and len(below) >= 200
    assert max(above) <= 0.5 and len(above) < len(below) / 4


def test_refine_errors():
    mesh = {"vertices": [[0, 0], [1, 0], [1, 1], [0, 1]], "triangles": [[0, 1, 2], [0, 2, 3]]}
    with pytest.raises(hullkit.HullkitError, match="add switch 'r'"):
        hullkit.triangulate(mesh, "q")
    with pytest.raises(hullkit.HullkitError, match="tri needs 'triangles'"):
        hullkit.triangulate({"vertices": mesh["vertices"]}, "r")
    with pytest.raises(hullkit.HullkitError, match=r"tri\['triangle_max_area'\], shape"):
        hullkit.triangulate(mesh, "ra")
    with pytest.raises(hullkit.HullkitError, match="holds 1 numbers for 2 triangles"):
        hullkit.triangulate({**mesh, "triangle_max_area": [0.1]}, "ra")
    with pytest.raises(hullkit.HullkitError, match="must index the 4 vertices"):
        hullkit.triangulate({**mesh, "triangles": [[0, 1, 4]]}, "r")
    with pytest.raises(hullkit.HullkitError, match="triangles 0 and 1 overlap"):
        hullkit.triangulate({**mesh, "triangles": [[0, 1, 2], [0, 1, 2]]}, "r")
    with pytest.raises(hullkit.HullkitError, match="triangle 1 .* has no area"):
        hullkit.triangulate({**mesh, "triangles": [[0, 1, 2], [0, 2, 0]]}, "r")
    with pytest.raises(hullkit.HullkitError, match="'A' .* does not apply with 'r'"):
        hullkit.triangulate(mesh, "rA")
