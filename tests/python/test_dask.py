"""hullkit.dask on a real local cluster: 2 worker processes, 1 thread each. The distributed hull
equals hullkit.hull of the whole cloud bit for bit (Dask arrays and lists of files), route
batches equal local checks (the scene read by the workers or sent to them; a long route cut
between tasks, its pieces' reports joined), and a worker killed
mid-job, a hull or route batches, changes nothing (Dask recomputes what was lost; check_routes
sends a lost scene again)."""
import hashlib
import json
import os
import signal
import threading
import time

import numpy as np
import pytest

import dask.array as da
from distributed import Client, LocalCluster

import hullkit
import hullkit.dask

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data")


@pytest.fixture(scope="module")
def client():
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    with Client(cluster) as c:
        yield c
    cluster.close()


def timeless(report):
    """A route report without its timings, which differ from run to run."""
    return {k: v for k, v in report.items() if k not in ("build_seconds", "seconds")}


def same_hull(distributed, local):
    assert distributed.dimension == local.dimension
    np.testing.assert_array_equal(distributed.triangles, local.triangles.astype(np.int64))
    np.testing.assert_array_equal(distributed.vertices, local.vertices.astype(np.int64))
    assert distributed.volume == local.volume and distributed.area == local.area  # the same bits


def test_dask_array_hull_equals_the_local_hull(client):
    rng = np.random.default_rng(1)
    points = np.concatenate([rng.normal(size=(150000, 3)), np.round(rng.random((30000, 3)) * 8) / 8])
    array = da.from_array(points, chunks=(17000, 3))  # uneven chunks, repeats across chunks
    result = hullkit.dask.hull(array, client=client)
    assert result.point_count == len(points)
    same_hull(result, hullkit.hull(points))
    # Dask's own scheduler (no client) and other fan-ins give the same.
    same_hull(hullkit.dask.hull(array, fan_in=2), hullkit.hull(points))


def test_files_hull_equals_the_hull_of_their_concatenation(client, tmp_path):
    rng = np.random.default_rng(2)
    parts = [rng.random((n, 3)) for n in (20000, 1, 35000, 7)]
    paths = []
    for k, part in enumerate(parts):
        path = tmp_path / f"part-{k}.txt"
        np.savetxt(path, part, fmt="%.17g")
        paths.append(str(path))
    result = hullkit.dask.hull(paths, client=client)
    whole = np.concatenate(parts)
    assert result.point_count == len(whole)
    same_hull(result, hullkit.hull(whole))
    np.testing.assert_array_equal(result.points, whole[result.index])


def test_files_with_the_same_points_keep_the_lowest_global_index(client, tmp_path):
    # Files are merged before all their counts are known; identical points in different files
    # (a grid, written whole into each file, shuffled) must still resolve to the lowest index
    # of the whole, as hullkit.hull of the concatenation does, for every reduction shape.
    grid = np.stack(np.meshgrid(*[np.arange(6.0)] * 3, indexing="ij"), axis=-1).reshape(-1, 3)
    rng = np.random.default_rng(5)
    parts = [rng.permutation(grid) for _ in range(7)] + [grid[:1]]
    paths = []
    for k, part in enumerate(parts):
        path = tmp_path / f"grid-{k}.xyz"
        np.savetxt(path, part, fmt="%.17g")
        paths.append(str(path))
    whole = np.concatenate(parts)
    for fan_in in (2, 3, 16):
        result = hullkit.dask.hull(paths, client=client, fan_in=fan_in)
        assert result.point_count == len(whole)
        same_hull(result, hullkit.hull(whole))


def test_flat_and_degenerate_partitions(client):
    flat = np.random.default_rng(3).random((40000, 3))
    flat[:, 2] = 1.5
    result = hullkit.dask.hull(da.from_array(flat, chunks=(9000, 3)), client=client)
    same_hull(result, hullkit.hull(flat))
    assert result.dimension == 2


def test_errors_name_the_file_and_line(client, tmp_path):
    bad = tmp_path / "bad.txt"
    bad.write_text("0 0 0\n1 2 oops\n")
    with pytest.raises(hullkit.HullkitError, match=r"bad.txt:2"):
        hullkit.dask.hull([str(bad)], client=client)
    with pytest.raises(hullkit.HullkitError, match="shape"):
        hullkit.dask.hull(da.zeros((10, 4), chunks=5), client=client)


def test_route_batches_equal_local_checks(client):
    scene = os.path.join(DATA, "route", "crane.json")  # mesh files: read here, and by the workers
    rng = np.random.default_rng(4)
    routes = [np.cumsum(rng.normal(scale=3.0, size=(5, 3)), axis=0) for _ in range(60)]
    reports = hullkit.dask.check_routes(scene, routes, client=client)
    checker = hullkit.RouteChecker(scene)
    assert [timeless(r) for r in reports] == [timeless(checker.check(route)) for route in routes]
    assert any(not r["clear"] for r in reports) and any(r["clear"] for r in reports)
    with pytest.raises(hullkit.HullkitError, match="routes\\[1\\]"):
        hullkit.dask.check_routes(scene, [routes[0], np.zeros((1, 3))], client=client)
    bad = {"traverse": {"parts": [{"box": {"min": [0, 0, 0], "max": [1, 1, 1]}}]}, "obstacles": [], "margn": 1}
    with pytest.raises(hullkit.HullkitError, match="margn"):  # raised on a worker, with the core's message
        hullkit.dask.check_routes(bad, routes[:3], client=client)
    with pytest.raises(hullkit.HullkitError, match="routes\\[2\\] must be numbers"):
        hullkit.dask.check_routes(scene, [routes[0], routes[1], [["a", "b", "c"]] * 2], client=client)


def unit_quaternions(rng, count):
    q = rng.normal(size=(count, 4))
    return q / np.linalg.norm(q, axis=1, keepdims=True)


def test_route_batches_with_legs_that_turn(client):
    # Some routes turn (a unit quaternion per waypoint), others translate (None): the reports of
    # a local RouteChecker, on the cluster and on Dask's local scheduler.
    scene = os.path.join(DATA, "route", "crane.json")
    rng = np.random.default_rng(8)
    # Routes of 2 to 7 waypoints: the batches pack them (and their rotations) into flat arrays.
    routes = [np.cumsum(rng.normal(scale=3.0, size=(2 + k % 6, 3)), axis=0) for k in range(40)]
    rotations = [unit_quaternions(rng, len(route)) if k % 3 else None for k, route in enumerate(routes)]
    checker = hullkit.RouteChecker(scene)
    expected = [timeless(checker.check(route, rotations=turn)) for route, turn in zip(routes, rotations)]
    assert any("rotation" in leg for r in expected for leg in r["legs"])  # the turning legs report their orientation
    assert [timeless(r) for r in hullkit.dask.check_routes(scene, routes, client=client, rotations=rotations)] == expected
    assert [timeless(r) for r in hullkit.dask.check_routes(scene, routes, rotations=rotations, batch=7)] == expected
    with pytest.raises(hullkit.HullkitError, match="39 entries for 40 routes"):
        hullkit.dask.check_routes(scene, routes, client=client, rotations=rotations[:39])
    with pytest.raises(hullkit.HullkitError, match="rotations\\[1\\] has 2 rows for the 3 waypoints"):
        hullkit.dask.check_routes(scene, routes, client=client, rotations=[None, rotations[1][:2]] + rotations[2:])
    with pytest.raises(hullkit.HullkitError, match="rotations\\[2\\] must have shape"):
        hullkit.dask.check_routes(scene, routes, client=client, rotations=[None, None, np.ones((4, 3))] + rotations[3:])
    not_unit = [None] * 40
    not_unit[5] = np.full((7, 4), 0.9)
    with pytest.raises(hullkit.HullkitError):  # raised on a worker, with the core's message
        hullkit.dask.check_routes(scene, routes, client=client, rotations=not_unit)


def test_a_long_route_is_cut_between_workers_and_its_report_joined(client):
    # One route of 400 legs, and one of 3 legs, cut into batches of 1, 7, 64 legs and the default
    # (two tasks per worker): the same reports, leg for leg, as one local check of each route;
    # also with turning legs, without clearances, and with samples.
    scene = os.path.join(DATA, "route", "crane.json")
    rng = np.random.default_rng(21)
    routes = [np.cumsum(rng.normal(scale=2.0, size=(401, 3)), axis=0), np.cumsum(rng.normal(scale=2.0, size=(4, 3)), axis=0)]
    rotations = [unit_quaternions(rng, 401), None]
    rotations[0][::3] = rotations[0][1::3][: len(rotations[0][::3])]  # some legs keep their orientation
    checker = hullkit.RouteChecker(scene)
    for options in ({}, {"rotations": rotations}, {"clearance": False}, {"samples": 2}):
        turns = options.get("rotations", [None, None])
        local = {k: v for k, v in options.items() if k != "rotations"}
        expected = [timeless(checker.check(route, rotations=turn, **local)) for route, turn in zip(routes, turns)]
        assert not expected[0]["clear"] and any(leg["status"] == "clear" for leg in expected[0]["legs"])
        for batch in (1, 7, 64, None):
            reports = hullkit.dask.check_routes(scene, routes, client=client, batch=batch, **options)
            assert [timeless(r) for r in reports] == expected, (options, batch)
    # Without clearances a clear leg has none: a route that starts with 150 clear legs far from
    # everything, then meets the crane, joins pieces with no min_clearance and pieces with one.
    far = np.cumsum(np.full((150, 3), 0.5), axis=0) + 1000.0
    mixed = np.concatenate([far[::-1], routes[0]])
    assert checker.check(far, clearance=False)["min_clearance"] is None
    expected = timeless(checker.check(mixed, clearance=False))
    assert expected["min_clearance"] is not None
    for batch in (7, 64, None):
        assert timeless(hullkit.dask.check_routes(scene, [mixed], client=client, batch=batch, clearance=False)[0]) == expected
    # The default batch: 403 legs in 4 tasks, the long route in all of them.
    batches = hullkit.dask._batches(routes, [None, None], 101)
    assert [[(route, first, len(points)) for route, first, points, _ in pieces] for pieces in batches] == [
        [(0, 0, 102)], [(0, 101, 102)], [(0, 202, 102)], [(0, 303, 98), (1, 0, 4)]]
    # A waypoint the core rejects, in the route's third piece: its index in the whole route.
    bad = routes[0].copy()
    bad[150, 1] = 1e301
    with pytest.raises(hullkit.HullkitError) as here:
        checker.check(bad)
    with pytest.raises(hullkit.HullkitError) as there:
        hullkit.dask.check_routes(scene, [routes[1], bad], client=client, batch=64)
    assert "waypoint 150" in str(here.value) and str(there.value) == f"routes[1]: {here.value}"
    not_unit = rotations[0].copy()
    not_unit[333] *= 1.01
    with pytest.raises(hullkit.HullkitError) as here:
        checker.check(routes[0], rotations=not_unit)
    with pytest.raises(hullkit.HullkitError) as there:
        hullkit.dask.check_routes(scene, routes, rotations=[not_unit, None], batch=64)  # Dask's local scheduler
    assert "waypoint 333" in str(here.value) and str(there.value) == f"routes[0]: {here.value}"


def scene_digest(scene):
    text, _, files = hullkit.dask._self_contained(scene)
    return hullkit.dask._digest(text, files)


def sent_to_workers(client, scene):
    return (client.id, scene_digest(scene)) in hullkit.dask._scattered


def set_worker_reading(client, on):
    def switch():
        import hullkit.dask as module
        module._read_on_workers = on
    client.run(switch)


def test_route_batches_read_the_scene_on_the_workers_or_send_it(client, tmp_path):
    # Workers that see the scene's files read them (nothing is sent); workers that cannot are sent
    # the bytes read here, and send_scene=True sends them without trying. Every way gives the
    # reports of a local RouteChecker.
    (tmp_path / "plate.obj").write_text("v 4 -5 -5\nv 4 5 -5\nv 4 0 5\nf 1 2 3\nf 1 3 2\n")
    rng = np.random.default_rng(9)
    routes = [np.cumsum(rng.normal(scale=2.0, size=(4, 3)), axis=0) for _ in range(30)]

    def scene(margin):  # a new scene (new bytes) for each way, so that no worker has its checker
        path = tmp_path / f"scene-{margin}.json"
        path.write_text(json.dumps({"traverse": {"parts": [{"box": {"min": [-0.5, -0.5, -0.5], "max": [0.5, 0.5, 0.5]}}]},
                                    "obstacles": [{"mesh": "plate.obj"}], "margin": margin}))
        return str(path)

    def expected(path):
        checker = hullkit.RouteChecker(path)
        return [timeless(checker.check(route)) for route in routes]

    read = scene(0.0)
    assert [timeless(r) for r in hullkit.dask.check_routes(read, routes, client=client)] == expected(read)
    assert not sent_to_workers(client, read)
    assert sum(not r["clear"] for r in expected(read)) > 0

    pushed = scene(0.25)
    assert [timeless(r) for r in hullkit.dask.check_routes(pushed, routes, client=client, send_scene=True)] == expected(pushed)
    assert sent_to_workers(client, pushed)

    set_worker_reading(client, False)  # as on machines that do not see these files
    try:
        unseen = scene(0.5)
        assert [timeless(r) for r in hullkit.dask.check_routes(unseen, routes, client=client)] == expected(unseen)
        assert sent_to_workers(client, unseen)
    finally:
        set_worker_reading(client, True)
    with pytest.raises(hullkit.HullkitError, match="send_scene"):
        hullkit.dask.check_routes(read, routes, client=client, send_scene="yes")
    with pytest.raises(hullkit.HullkitError, match="batch"):
        hullkit.dask.check_routes(read, routes, client=client, batch=0)


def test_a_worker_uses_a_scene_file_only_if_it_holds_the_bytes_read_here(tmp_path):
    path = tmp_path / "scene.json"
    path.write_text(json.dumps({"traverse": {"parts": [{"box": {"min": [0, 0, 0], "max": [1, 1, 1]}}]}, "obstacles": []}))
    batch = hullkit.dask._packed([(0, 0, np.array([[0.0, 0, 0], [3, 0, 0]]), None)])
    digest = scene_digest(str(path))
    # The same bytes: checked there. Other bytes (the file changed after it was read here, or
    # another machine's file at the same path): the client is asked to send its bytes.
    assert json.loads(hullkit.dask._check_batch((digest, "scene.json", str(path), None), *batch, True, 0, 1))[0]["clear"]
    other = hashlib.sha256(b"other").hexdigest()
    assert isinstance(hullkit.dask._check_batch((other, "scene.json", str(path), None), *batch, True, 0, 1),
                      hullkit.dask._SceneNotHere)
    assert isinstance(hullkit.dask._check_batch((other, "scene.json", str(tmp_path / "gone.json"), None), *batch, True, 0, 1),
                      hullkit.dask._SceneNotHere)


def test_route_batches_with_a_gltf_whose_buffer_is_a_file(client, tmp_path):
    # The traverse is a .gltf in a subfolder whose vertex and index data are in a .bin beside
    # it: both files are read here, and sent with the scene to workers that cannot read them.
    corners = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype="<f4")
    faces = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                      [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]], dtype="<u2")
    data = corners.tobytes() + faces.tobytes()
    (tmp_path / "parts").mkdir()
    (tmp_path / "parts" / "box.bin").write_bytes(data)
    gltf = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 1]},
                          {"bufferView": 1, "componentType": 5123, "count": 36, "type": "SCALAR"}],
            "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 96}, {"buffer": 0, "byteOffset": 96, "byteLength": 72}],
            "buffers": [{"uri": "box.bin", "byteLength": len(data)}]}
    (tmp_path / "parts" / "box.gltf").write_text(json.dumps(gltf))
    scene = tmp_path / "scene.json"
    scene.write_text(json.dumps({"traverse": {"parts": [{"mesh": "parts/box.gltf"}]},
                                 "obstacles": [{"box": {"min": [4, -5, -5], "max": [4.2, 5, 5]}}]}))
    routes = [np.array([[0.0, 0, 0], [10, 0, 0]]), np.array([[0.0, 2, 0], [0, 8, 0]]), np.array([[0.0, 0, 0], [2.5, 0, 0]])]
    checker = hullkit.RouteChecker(str(scene))
    expected = [timeless(checker.check(route)) for route in routes]
    assert [r["clear"] for r in expected] == [False, True, True]
    set_worker_reading(client, False)  # the workers get the .gltf and the .bin from here
    try:
        for _ in range(2):  # the second call reuses the scene on the workers
            assert [timeless(r) for r in hullkit.dask.check_routes(str(scene), routes, client=client)] == expected
        assert sent_to_workers(client, str(scene))
    finally:
        set_worker_reading(client, True)
    (tmp_path / "parts" / "box.bin").unlink()
    with pytest.raises(hullkit.HullkitError, match="box.bin: cannot open"):
        hullkit.dask.check_routes(str(scene), routes, client=client)


def test_a_worker_killed_mid_job_changes_nothing(client):
    array = da.random.RandomState(7).random_sample((2_400_000, 3), chunks=(60_000, 3))
    points = array.compute()
    expected = hullkit.hull(points)
    future = client.compute(hullkit.dask.hull_graph(array))
    pids = client.run(os.getpid)
    victim = None
    deadline = time.time() + 60
    while victim is None and time.time() < deadline:
        held = {w for workers in client.who_has().values() for w in workers}
        victim = next((w for w in held if w in pids), None)
        time.sleep(0.005)
    assert victim is not None, "no partial result appeared on a worker"
    assert not future.done(), "the job finished before a worker could be killed"
    os.kill(pids[victim], signal.SIGKILL)  # its partial results are lost; the nanny restarts it
    merged = future.result(timeout=300)
    same_hull(hullkit.dask.DaskHull(merged), expected)
    client.wait_for_workers(2, timeout=60)


def started_route_job(client, tmp_path, margin, send_scene):
    """check_routes of 3000 routes through the crane scene (its margin set to ``margin``: new bytes,
    so that no worker has this checker yet) in a thread, returned once batches are running on the
    workers: (the reports a local checker gives, the thread, the dict it puts "reports" in)."""
    scene = tmp_path / "scene.json"
    crane = json.load(open(os.path.join(DATA, "route", "crane.json")))
    for shape in crane["traverse"]["parts"] + crane["obstacles"]:
        if "mesh" in shape:  # the crane's mesh files, where they are
            shape["mesh"] = os.path.join(DATA, "route", shape["mesh"])
    crane["margin"] = margin
    scene.write_text(json.dumps(crane))
    rng = np.random.default_rng(12)
    routes = [np.cumsum(rng.normal(scale=2.0, size=(6, 3)), axis=0) for _ in range(3000)]
    checker = hullkit.RouteChecker(str(scene))
    expected = [timeless(checker.check(route)) for route in routes]
    done = {}
    job = threading.Thread(target=lambda: done.update(reports=hullkit.dask.check_routes(
        str(scene), routes, client=client, batch=247, send_scene=send_scene)))  # most tasks end inside a route
    job.start()
    deadline = time.time() + 60
    while not client.processing() or not any(client.processing().values()):
        assert time.time() < deadline, "no batch started"
        time.sleep(0.005)
    time.sleep(0.05)  # the workers have their checkers and are checking legs
    assert job.is_alive(), "the job finished before the cluster could be disturbed"
    return expected, job, done


@pytest.mark.parametrize("send_scene", [False, True])
def test_a_worker_killed_mid_route_batches_changes_nothing(client, tmp_path, send_scene):
    # The nanny restarts the killed worker; its batches run again, on the other worker or on the
    # new one, which reads the scene file itself (or gets the bytes sent) and builds its checker.
    pids = client.run(os.getpid)
    expected, job, done = started_route_job(client, tmp_path, 0.05 if send_scene else 0.1, send_scene)
    victim = next(iter(pids.values()))
    os.kill(victim, signal.SIGKILL)
    job.join(timeout=300)
    assert [timeless(r) for r in done["reports"]] == expected
    client.wait_for_workers(2, timeout=60)
    assert victim not in client.run(os.getpid).values()  # it was killed, and replaced


@pytest.mark.parametrize("how", ["holders killed", "cancelled"])
def test_the_scene_sent_to_the_workers_lost_mid_route_batches_changes_nothing(client, tmp_path, how):
    # Scattered data cannot be computed again: when every worker holding the scene dies (Dask's
    # active memory manager may have left one copy) or the scene is cancelled, the batches that
    # need it are cancelled. check_routes sends the scene again and runs them: the same reports.
    pids = client.run(os.getpid)
    expected, job, done = started_route_job(client, tmp_path, 0.06 if how == "cancelled" else 0.07, True)
    scene = next(f for (owner, _), f in reversed(list(hullkit.dask._scattered.items())) if owner == client.id)
    if how == "cancelled":
        client.cancel(scene)
    else:
        for address in client.who_has(scene)[scene.key]:
            os.kill(pids[address], signal.SIGKILL)
    job.join(timeout=300)
    assert [timeless(r) for r in done["reports"]] == expected
    client.wait_for_workers(2, timeout=60)


def test_interpolation_blockwise_equals_the_local_call(client):
    from hullkit.interpolate import CloughTocher2DInterpolator, LinearNDInterpolator, NearestNDInterpolator

    rng = np.random.default_rng(50)
    xy, xyz = rng.random((3000, 2)), rng.random((2000, 3))
    values2, values3 = np.sin(3 * xy[:, 0]) + xy[:, 1], xyz.sum(axis=1)
    q2 = rng.random((4, 2500, 2)) * 1.2 - 0.1  # leading shape (4, 2500), some outside the hull
    q3 = rng.random((9000, 3)) * 1.2 - 0.1
    cases = [
        (LinearNDInterpolator(xy, values2, fill_value=-1.0), q2, {}),
        (LinearNDInterpolator(xyz, np.stack([values3, 1j * values3], axis=1)), q3, {}),
        (NearestNDInterpolator(xyz, np.arange(2000)), q3, {"distance_upper_bound": 0.05}),
        (NearestNDInterpolator(xy, np.arange(3000)), q2, {}),
        (CloughTocher2DInterpolator(xy, np.stack([values2, 2 * values2], axis=1), rescale=True), q2, {}),
    ]
    before = sum(client.run(lambda: hullkit.dask._builds).values())
    for interpolator, queries, options in cases:
        chunks = (2, 700, 2) if queries.ndim == 3 else (1300, 3)
        lazy = hullkit.dask.interpolate(interpolator, da.from_array(queries, chunks=chunks), **options)
        local = interpolator(queries, **options)
        assert lazy.shape == local.shape and lazy.dtype == local.dtype
        out = lazy.compute()
        assert out.dtype == local.dtype
        np.testing.assert_array_equal(out, local)  # bit for bit (NaN where local has NaN)
    # Each worker built each interpolator at most once, whatever the number of blocks it evaluated.
    built = sum(client.run(lambda: hullkit.dask._builds).values()) - before
    assert len(cases) <= built <= 2 * len(cases)


def test_interpolation_errors(client):
    from hullkit.interpolate import LinearNDInterpolator

    f = LinearNDInterpolator(np.random.default_rng(51).random((50, 2)), np.arange(50.0))
    with pytest.raises(hullkit.HullkitError, match="must be a Dask array"):
        hullkit.dask.interpolate(f, np.zeros((3, 2)))
    with pytest.raises(hullkit.HullkitError, match=r"shape \(\.\.\., 2\)"):
        hullkit.dask.interpolate(f, da.zeros((3, 3)))
    with pytest.raises(hullkit.HullkitError, match="needs an interpolator of hullkit.interpolate"):
        hullkit.dask.interpolate(lambda q: q, da.zeros((3, 2)))
    with pytest.raises(hullkit.HullkitError, match="takes no query options"):
        hullkit.dask.interpolate(f, da.zeros((3, 2)), distance_upper_bound=1.0)
    with pytest.raises(hullkit.HullkitError, match="threads must be"):
        hullkit.dask.interpolate(f, da.zeros((3, 2)), threads=-1)
