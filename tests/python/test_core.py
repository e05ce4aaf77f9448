"""hullkit's own Python API: verify, HullBuilder (pieces equal the whole), readers and route
checks (the same reports as the `hullkit route` command)."""
import json
import os
import subprocess

import numpy as np
import pytest

import hullkit

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data")


def test_verify_accepts_hulls_and_rejects_a_wrong_one():
    points = np.random.default_rng(1).random((2000, 3))
    h = hullkit.hull(points)
    assert hullkit.verify(points, h)["ok"]
    assert hullkit.verify(points, h.triangles)["ok"]
    report = hullkit.verify(points, h.triangles[:-1])  # a hole
    assert not report["ok"] and report["problems"]
    flat = points.copy()
    flat[:, 2] = 0.0
    assert hullkit.verify(flat, hullkit.hull(flat))["ok"]


@pytest.mark.parametrize("piece", [1, 7, 1000])
def test_builder_pieces_give_the_hull_of_the_whole(piece):
    rng = np.random.default_rng(piece)
    points = np.concatenate([rng.random((3000, 3)), np.round(rng.random((500, 3)) * 4) / 4])  # repeats, coplanar
    whole = hullkit.hull(points)
    builder = hullkit.HullBuilder()
    order = rng.permutation(np.arange(0, len(points), piece))
    for first in order:
        builder.add(points[first:first + piece], int(first))
    out = builder.finish()
    assert out["point_count"] == len(points)
    np.testing.assert_array_equal(out["index"][out["hull"].triangles], whole.triangles)
    assert out["hull"].volume == whole.volume and out["hull"].area == whole.area
    again = hullkit.HullBuilder()
    again.add_indexed(out["points"], out["index"])  # the map-reduce step: vertices with their indices
    merged = again.finish()
    np.testing.assert_array_equal(merged["index"][merged["hull"].triangles], whole.triangles)


def test_builder_errors():
    builder = hullkit.HullBuilder()
    points = np.random.default_rng(5).random((100, 3))
    builder.add(points, 0)
    with pytest.raises(hullkit.HullkitError, match="twice"):
        builder.add(points, 0)  # the same indices again
    with pytest.raises(hullkit.HullkitError, match="first_index"):
        hullkit.HullBuilder().add(np.zeros((1, 3)), -1)
    bad = np.zeros((4, 3))
    bad[2, 2] = np.nan
    with pytest.raises(hullkit.HullkitError, match="point 12"):
        hullkit.HullBuilder().add(bad, 10)


def test_readers(tmp_path):
    path = tmp_path / "cloud.txt"
    points = np.random.default_rng(3).random((5000, 3))
    np.savetxt(path, points, fmt="%.17g")
    np.testing.assert_array_equal(hullkit.read_points(path), points)
    np.testing.assert_array_equal(hullkit.read_points(path, threads=1), points)
    vertices, triangles = hullkit.read_mesh(os.path.join(DATA, "cube.obj"))
    assert vertices.shape == (8, 3) and triangles.shape == (12, 3) and triangles.dtype == np.uint32
    bad = tmp_path / "bad.txt"
    bad.write_text("0 0 0\n1 1 1\n1 x 2\n")
    with pytest.raises(hullkit.HullkitError, match=r"bad.txt:3"):
        hullkit.read_points(bad)
    with pytest.raises(hullkit.HullkitError, match="cannot open"):
        hullkit.read_points(tmp_path / "missing.txt")
    with pytest.raises(hullkit.HullkitError, match="cannot open"):
        hullkit.read_mesh(tmp_path / "missing.obj")


def cli_report(scene_path, *args):
    cli = os.environ.get("HULLKIT_CLI", os.path.join(os.path.dirname(__file__), "..", "..", "build", "native", "hullkit"))
    assert os.path.exists(cli), f"{cli} is missing: build the command first (bash scripts/build.sh cli)"
    run = subprocess.run([cli, "route", scene_path, *args], capture_output=True, text=True)
    assert run.returncode in (0, 1), run.stderr
    return json.loads(run.stdout)


def without_timings(report):
    return {k: v for k, v in report.items() if k not in ("build_seconds", "seconds")}


def test_route_reports_equal_the_command():
    scene_path = os.path.join(DATA, "route", "crane.json")
    report = hullkit.check_route(scene_path)
    assert not report["clear"] and [leg["status"] for leg in report["legs"]] == ["hit", "clear", "clear"]
    assert without_timings(report) == without_timings(cli_report(scene_path))
    checker = hullkit.RouteChecker(scene_path)
    moved = checker.check(np.array([[0, 20, 0], [10, 20, 0]], dtype=float))
    assert moved["clear"] and moved["legs"][0]["status"] == "clear"
    assert without_timings(checker.check(threads=1)) == without_timings(checker.check(threads=2))


def test_route_scene_as_a_dict_with_numpy_meshes():
    box = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)
    from scipy.spatial import ConvexHull as Reference  # only to triangulate the box
    tris = Reference(box).simplices
    scene = {
        "traverse": {"parts": [{"name": "cube", "vertices": box, "triangles": tris}]},
        "obstacles": [{"name": "wall", "box": {"min": [5, -5, -5], "max": [5.5, 5, 5]}}],
        "route": np.array([[0.0, 0, 0], [10, 0, 0]]),
        "margin": 0.0,
    }
    report = hullkit.check_route(scene)
    leg = report["legs"][0]
    assert leg["status"] == "hit" and leg["obstacle"] == "wall"
    lo, hi = leg["fraction"]
    assert lo <= 0.4 <= hi and hi - lo <= 1e-9  # the cube's face x = 1 reaches x = 5 at 0.4
    clear = hullkit.RouteChecker(scene).check([[0, 10, 0], [10, 10, 0]])
    assert clear["clear"] and clear["legs"][0]["clearance"] == pytest.approx(5.0)  # y 10 against the wall's 5


def test_numpy_meshes_are_written_as_json_dumps_writes_them():
    # The core writes a dict scene's 2-D arrays (hullkit._json_rows): byte for byte what json.dumps
    # writes of their lists (Python's float repr: -0.0, 1e-05, 1e+16, subnormals, huge values);
    # other arrays (non-finite, 1-D, booleans, uint64) are left to json.dumps.
    rng = np.random.default_rng(6)
    floats = rng.normal(size=(4000, 3)) * np.exp2(rng.integers(-1074, 1000, size=(4000, 3)))
    floats[:7] = [[-0.0, 0.0, 5e-324], [1e300, -1.7976931348623157e308, 2.0**63 + 2048], [0.1, 1 / 3, 1e22],
                  [123456789012345680000.0, 1e-7, -2.5], [float(2**53 + 1), 1.0, -1.0], [1e16, 1e15, 0.0001],
                  [0.00001, 123.456, 1234567890123456.7]]
    for array in (floats, (rng.normal(size=(500, 3)) * 1e3).astype(np.float32), rng.integers(-2**62, 2**62, size=(300, 3)),
                  np.arange(12, dtype=np.uint16).reshape(4, 3), np.ones((2, 5))):
        assert hullkit._json_rows(array) == json.dumps(array.tolist())
    assert hullkit._json_rows(np.array([[1.0, np.nan, 0.0]])) is None
    assert hullkit._json_rows(np.array([1.0, 2.0])) is None
    assert hullkit._json_rows(np.array([[True, False]])) is None
    assert hullkit._json_rows(np.ones((2, 3), dtype=np.longdouble)) is None
    assert hullkit._json_rows(np.array([[2**63]], dtype=np.uint64)) is None
    # A scene with them: the same reports as its json.dumps text, and the same message for NaN.
    box = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float) - 0.5
    faces = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                      [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])
    wall = floats[5:905] * 0 + rng.random((900, 3)) * [0.1, 8, 8] + [4, -4, -4]
    scene = {"traverse": {"parts": [{"name": "box", "vertices": box, "triangles": faces}]},
             "obstacles": [{"name": "cloud", "vertices": wall, "triangles": rng.integers(0, 900, size=(600, 3))}]}
    plain = json.loads(json.dumps(scene, default=lambda a: a.tolist()))
    route = [[0.0, 0, 0], [9, 0, 0], [9, 6, 0]]
    assert hullkit.RouteChecker(scene).check(route)["legs"] == hullkit.RouteChecker(plain).check(route)["legs"]
    scene["obstacles"][0]["vertices"] = wall.copy()
    scene["obstacles"][0]["vertices"][7, 1] = np.nan
    with pytest.raises(hullkit.HullkitError) as error:
        hullkit.RouteChecker(scene)
    with pytest.raises(hullkit.HullkitError) as error_of_lists:
        hullkit.RouteChecker(json.loads(json.dumps(scene, default=lambda a: a.tolist())))
    assert str(error.value) == str(error_of_lists.value)


def test_route_errors_name_the_field():
    with pytest.raises(hullkit.HullkitError, match="margn|unknown"):
        hullkit.check_route({"traverse": {"parts": [{"box": {"min": [0, 0, 0], "max": [1, 1, 1]}}]},
                             "route": [[0, 0, 0], [1, 0, 0]], "margn": 1})
    no_route = {"traverse": {"parts": [{"box": {"min": [0, 0, 0], "max": [1, 1, 1]}}]}, "obstacles": []}
    with pytest.raises(hullkit.HullkitError, match="no route"):
        hullkit.RouteChecker(no_route).check()
    with pytest.raises(hullkit.HullkitError, match="cannot open"):
        hullkit.check_route("/nonexistent/scene.json")
    with pytest.raises(hullkit.HullkitError, match="at least 2 waypoints"):
        hullkit.RouteChecker(no_route).check([[0, 0, 0]])


def test_route_legs_that_turn_as_rotations_or_in_the_scene():
    # A bar 3 long along y passes a slot 1 wide at x in [5, 6] only when turned to lie along x.
    slot = {
        "traverse": {"parts": [{"name": "bar", "box": {"min": [-0.2, -1.5, -0.2], "max": [0.2, 1.5, 0.2]}}]},
        "obstacles": [{"name": "low", "box": {"min": [5, -10, -1], "max": [6, -0.5, 1]}},
                      {"name": "high", "box": {"min": [5, 0.5, -1], "max": [6, 10, 1]}}],
    }
    yaw90 = [np.sqrt(0.5), 0, 0, np.sqrt(0.5)]
    checker = hullkit.RouteChecker(slot)
    first = checker.check([[0, 0, 0], [0, 0, 0], [12, 0, 0]], rotations=[[1, 0, 0, 0], yaw90, yaw90])
    assert first["clear"]
    passing = checker.check([[0, 0, 0], [12, 0, 0]], rotations=np.array([[1.0, 0, 0, 0], yaw90]))
    leg = passing["legs"][0]
    assert leg["status"] == "hit" and leg["fraction"][1] - leg["fraction"][0] <= 1e-7 and len(leg["rotation"]) == 4
    # The same route written in the scene gives the same report.
    in_scene = dict(slot, route=[[0, 0, 0], {"position": [12, 0, 0], "rotation": {"quaternion": yaw90}}])
    assert without_timings(hullkit.check_route(in_scene)) == without_timings(passing)
    with pytest.raises(hullkit.HullkitError, match="one row per waypoint"):
        checker.check([[0, 0, 0], [1, 0, 0]], rotations=[[1, 0, 0, 0]])
    with pytest.raises(hullkit.HullkitError, match="not a unit quaternion"):
        checker.check([[0, 0, 0], [1, 0, 0]], rotations=[[1, 0, 0, 0], [1, 0, 0, 0.5]])


def test_the_installed_package_carries_its_licence():
    import importlib.metadata

    licences = [f for f in importlib.metadata.files("hullkit") if f.name.upper().startswith("LICEN")]
    assert licences, "the installed distribution has no licence file"
    text = licences[0].read_text()
    assert "MIT" in text or "Permission is hereby granted" in text
    assert importlib.metadata.metadata("hullkit")["License"] == "MIT"
