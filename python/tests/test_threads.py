# The GIL is released while the library works: another Python thread runs during a solve, and solves on
# one Solver from several threads give the results of sequential ones.
import threading
import time

import numpy as np

import swn
from conftest import torus


def test_gil_is_released_during_a_solve():
    nu, nv = 160, 80
    V, F, idx = torus(nu, nv)
    meridian = [idx(7, j) for j in range(nv + 1)]
    curves = [meridian[:20], meridian[24:]]
    solver = swn.Solver(V, F)
    started, done = threading.Event(), threading.Event()
    result = {}

    def solve():
        started.set()
        result["r"] = solver.solve(curves, concurrency=False)
        done.set()

    thread = threading.Thread(target=solve)
    thread.start()
    started.wait()
    last, gap = time.perf_counter(), 0.0
    while not done.is_set():          # pure Python work: it runs only while the solving thread lets go of the GIL
        now = time.perf_counter()
        gap, last = max(gap, now - last), now
    thread.join()
    r = result["r"]
    solve_time = r.report["times"]["total"]
    assert solve_time > 0.1           # long enough to tell
    # Python's thread switch interval is 5 ms: a held GIL would stop this loop for the whole solve
    assert gap < 0.5 * solve_time, (gap, solve_time)
    assert np.count_nonzero(r.G) == nv


def test_concurrent_solves_on_one_solver():
    nu, nv = 24, 12
    V, F, idx = torus(nu, nv)
    solver = swn.Solver(V, F)
    curves = [[[idx(i, j) for j in range(nv + 1)][:k]] for i, k in [(1, 6), (5, 13), (9, 9), (13, 4)]]
    expected = [solver.solve(c) for c in curves]
    got = [None] * len(curves)

    def solve(k):
        got[k] = solver.solve(curves[k])

    threads = [threading.Thread(target=solve, args=(k,)) for k in range(len(curves))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for e, g in zip(expected, got):
        assert (e.W == g.W).all() and (e.G == g.G).all() and np.allclose(e.g, g.g, atol=1e-9)
