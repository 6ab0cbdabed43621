"""The GIL is released while prepare and deform run; the progress callback runs Python meanwhile."""

import sys
import threading
import time

import numpy as np
import pytest

import dgwarp

from conftest import grid_with_hole


@pytest.fixture(scope="module")
def grid():
    # 90,601 nodes, 1,200 on the boundary: an IDW step takes tens of milliseconds.
    return grid_with_hole(300)


class Counter:
    """A second Python thread that counts while it can run."""

    def __init__(self):
        self.count = 0
        self.stop = threading.Event()
        self.thread = threading.Thread(target=self.run)

    def run(self):
        while not self.stop.is_set():
            self.count += 1
            time.sleep(0.0002)  # gives the GIL back, so the main thread never waits for it

    def __enter__(self):
        # A switch interval longer than the test: a thread holding the GIL keeps it until it
        # releases it itself, so the counter only advances during a call that releases it.
        self.interval = sys.getswitchinterval()
        sys.setswitchinterval(30)
        self.thread.start()
        while self.count == 0:
            time.sleep(0.001)
        return self

    def __exit__(self, *exc):
        self.stop.set()
        self.thread.join()
        sys.setswitchinterval(self.interval)


def squeeze(plan):
    x = plan.boundary_points
    d = np.zeros((len(x), 2))
    d[plan.moving] = (x[plan.moving] - 0.5) * [0.1, -0.2]
    return d


def test_a_second_thread_runs_during_prepare_and_deform(grid):
    with Counter() as counter:
        before = counter.count
        plan = dgwarp.prepare(grid, moving=["body"], method="idw")
        during_prepare = counter.count - before
        d = squeeze(plan)
        out = np.empty_like(grid.points)
        before = counter.count
        start = time.perf_counter()
        while time.perf_counter() - start < 0.3:  # a few steps (IDW: tens of ms each)
            plan.deform(translation=d, out=out)
        during_deform = counter.count - before
    assert during_deform > 0
    assert during_prepare >= 0  # IDW's prepare is short; DG-IDW's below
    with Counter() as counter:
        before = counter.count
        start = time.perf_counter()
        while time.perf_counter() - start < 0.3:
            dgwarp.prepare(grid, moving=["body"], method="dg-idw")
        assert counter.count - before > 0


def test_progress_is_called_with_the_gil_and_ends_at_one(grid):
    seen = []
    plan = dgwarp.prepare(grid, moving=["body"], method="idw", progress=seen.append)
    assert seen[-1] == 1.0
    seen.clear()
    plan.deform(translation=squeeze(plan), progress=seen.append)
    assert len(seen) > 2 and seen == sorted(seen) and seen[-1] == 1.0 and 0 <= seen[0]
    seen.clear()
    dgwarp.prepare(grid, moving=["body"], progress=lambda f: seen.append(threading.get_ident()))
    assert len(seen) > 2


def test_an_exception_in_the_callback_stops_the_call(grid):
    plan = dgwarp.prepare(grid, moving=["body"], method="idw")
    calls = []

    def stop(fraction):
        calls.append(fraction)
        if fraction > 0.2:
            raise KeyboardInterrupt("stop")

    with pytest.raises(KeyboardInterrupt, match="stop"):
        plan.deform(translation=squeeze(plan), progress=stop)
    assert max(calls) < 1.0  # stopped before the end

    def fail(fraction):
        raise RuntimeError("no")

    with pytest.raises(RuntimeError, match="no"):
        dgwarp.prepare(grid, moving=["body"], progress=fail)
    # Still usable afterwards.
    assert np.isfinite(plan.deform(translation=squeeze(plan))).all()


def test_threads_share_one_plan(grid):
    plan = dgwarp.prepare(grid, moving=["body"])
    d = squeeze(plan)
    expected = plan.deform(translation=d)
    results = [None] * 4

    def work(i):
        results[i] = plan.deform(translation=d * 1.0)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all(np.array_equal(r, expected) for r in results)


def test_ctrl_c_stops_a_long_deform_without_a_progress_callback():
    # Issue #27, item 11: without a callback, KeyboardInterrupt came only when the call ended.
    # An IDW step on 1,442,401 nodes and 5,760 boundary nodes (seconds); SIGINT is sent soon
    # after it starts. Stopped early, the step leaves rows of `out` unwritten (NaN); before the
    # fix it wrote them all and Python raised KeyboardInterrupt only after it returned.
    import os
    import signal

    big = grid_with_hole(1200)
    plan = dgwarp.prepare(big, moving=["body"], method="idw")
    d = squeeze(plan)
    out = np.full_like(big.points, np.nan)
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(0.2, os.kill, (os.getpid(), signal.SIGINT))
    try:
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            plan.deform(translation=d, out=out)
            time.sleep(30)  # never reached after the fix; before it, where the interrupt lands
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)
    assert np.isnan(out).any(), "the step ran to its end before the interrupt was raised"


def test_dg_idw_and_dg_harmonic_steps_report_progress_per_block(grid):
    # Issue #27, item 11: they reported once, at the end.
    for method in ("dg-idw", "dg-harmonic"):
        plan = dgwarp.prepare(grid, moving=["body"], method=method)
        seen = []
        plan.deform(translation=squeeze(plan), progress=seen.append)
        assert len(seen) > 2 and seen == sorted(seen) and seen[-1] == 1.0, method


def test_threads_making_gmsh_cases_and_writing_cgns_at_once_get_what_one_thread_gets(tmp_path):
    # Gmsh (dgwarp.case) and libcgns keep process-wide state, and these calls release the GIL:
    # the library runs one Gmsh session and one CGNS file at a time, whatever thread asks.
    expected = dgwarp.case("naca0012")
    expected.write(tmp_path / "expected.cgns")
    reference = dgwarp.read(tmp_path / "expected.cgns")
    results, errors = [None] * 4, []

    def work(k):
        try:
            mesh = dgwarp.case("naca0012")
            mesh.write(tmp_path / f"thread{k}.cgns")
            results[k] = (mesh, dgwarp.read(tmp_path / f"thread{k}.cgns"))
        except Exception as e:  # noqa: BLE001 (reported below)
            errors.append(e)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert errors == []
    for mesh, read_back in results:
        assert np.array_equal(mesh.points, expected.points)
        assert np.array_equal(read_back.points, reference.points)
