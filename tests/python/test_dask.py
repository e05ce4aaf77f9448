"""hullkit.dask on a real local cluster: 2 worker processes, 1 thread each. The distributed hull
equals hullkit.hull of the whole cloud bit for bit (Dask arrays and lists of files), route
batches equal local checks, and a worker killed mid-job changes nothing (Dask recomputes what
was lost)."""
import os
import signal
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
    scene = os.path.join(DATA, "route", "crane.json")  # mesh files: read here, sent inline
    rng = np.random.default_rng(4)
    routes = [np.cumsum(rng.normal(scale=3.0, size=(5, 3)), axis=0) for _ in range(60)]
    reports = hullkit.dask.check_routes(scene, routes, client=client)
    checker = hullkit.RouteChecker(scene)
    strip = lambda r: {k: v for k, v in r.items() if k not in ("build_seconds", "seconds")}
    assert [strip(r) for r in reports] == [strip(checker.check(route)) for route in routes]
    assert any(not r["clear"] for r in reports) and any(r["clear"] for r in reports)
    with pytest.raises(hullkit.HullkitError, match="routes\\[1\\]"):
        hullkit.dask.check_routes(scene, [routes[0], np.zeros((1, 3))], client=client)
    bad = {"traverse": {"parts": [{"box": {"min": [0, 0, 0], "max": [1, 1, 1]}}]}, "obstacles": [], "margn": 1}
    with pytest.raises(hullkit.HullkitError, match="margn"):  # raised on a worker, with the core's message
        hullkit.dask.check_routes(bad, routes[:3], client=client)


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
