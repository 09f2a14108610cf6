#!/usr/bin/env python3
"""The paper's sketching use (Sec. 5.3) from Python: a torus of NU x NV quads (2 NU NV triangles), a broken
meridian kept, a broken square stroke moved by one grid step before each solve. Prints, per stroke, the
re-solve on one swn.Solver (the strokes one after the other), then a fresh swn.winding_numbers() of each
stroke's curves (wall seconds), and checks that they give the same labels and G. Not a test: see SPEED.md ("Interactive re-solve").

    PYTHONPATH=build/python /usr/bin/python3 benchmark/sketch.py [NU NV STROKES]
"""
import sys
import time

import numpy as np

import swn


def torus(nu, nv, R=3.0, r=1.0):
    a = 2 * np.pi * np.arange(nu) / nu
    b = 2 * np.pi * np.arange(nv) / nv
    A, B = np.meshgrid(a, b, indexing="ij")
    V = np.column_stack([((R + r * np.cos(B)) * np.cos(A)).ravel(), ((R + r * np.cos(B)) * np.sin(A)).ravel(),
                         (r * np.sin(B)).ravel()])
    i, j = np.meshgrid(np.arange(nu), np.arange(nv), indexing="ij")
    at = lambda i, j: (i % nu) * nv + (j % nv)
    F = np.concatenate([np.stack([at(i, j), at(i + 1, j), at(i + 1, j + 1)], -1).reshape(-1, 3),
                        np.stack([at(i, j), at(i + 1, j + 1), at(i, j + 1)], -1).reshape(-1, 3)])
    return V, F, at


def main(nu=316, nv=158, strokes=8):
    V, F, at = torus(nu, nv)
    meridian = [int(at(nu // 8, j)) for j in range(1, nv - 1)]   # a gap of 3 edges
    side = nv // 4
    solver = swn.Solver(V, F)
    print(f"{len(F)} faces, {strokes} strokes")

    def curves(k):
        i0, j0 = nu // 2 + k, nv // 4
        square = ([at(i0 + t, j0) for t in range(side)] + [at(i0 + side, j0 + t) for t in range(side)] +
                  [at(i0 + side - t, j0 + side) for t in range(side)] + [at(i0, j0 + side - t) for t in range(side - 1)])
        return [meridian, [int(x) for x in square]]   # the square with a gap of one edge

    # the strokes one after the other on one solver, as a sketching session runs them (the last result kept
    # while the next is solved, the labels and G of each kept for the check); the fresh solves that check them
    # come afterwards (between re-solves they would leave the allocator's heap grown)
    results = []
    for k in range(strokes):
        stroke = curves(k)
        t0 = time.perf_counter()
        r = solver.solve(stroke)
        t1 = time.perf_counter()
        results.append((r.W.copy(), r.G.copy()))
        print(f"stroke {k}: re-solve {t1 - t0:.3f} s (residual step {r.report['times']['residual']:.3f} s, "
              f"warm {r.report['residual_warm_started']}, "
              f"jump Laplacian update rank {r.report['jump_laplacian_update_rank']})")
    for k, (W, G) in enumerate(results):
        t1 = time.perf_counter()
        fresh = swn.winding_numbers(V, F, curves(k))
        t2 = time.perf_counter()
        same = (W == fresh.W).all() and (G == fresh.G).all()
        print(f"stroke {k}: fresh {t2 - t1:.3f} s, {'same' if same else 'DIFFERENT'} labels and G")
        if not same:
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(*[int(a) for a in sys.argv[1:4]]))
