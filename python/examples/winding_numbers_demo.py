"""Surface winding numbers from Python (numpy in, numpy out).

1. A loop with a gap on a grid made with numpy: the region it bounds is labelled 1.
2. The authors' torus with the letter Phi drawn with gaps, read as the swn tool reads it: the broken
   meridian bounds nothing and comes back as G, the broken loop bounds the inside of the letter.
3. The same Solver, reused for another curve on the torus.

Usage: python3 winding_numbers_demo.py [DATA_DIR]   (default: data/swn-demo of the source tree)
Exits with status 1 if a result is not the expected one.
"""
import pathlib
import sys

import numpy as np

import swn

data = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2] / "data" / "swn-demo"

# 1. A 20 x 20 grid of the unit square, two counter-clockwise triangles per cell; vertex (i, j) = i + 21 j.
n = 20
i, j = np.meshgrid(np.arange(n + 1), np.arange(n + 1))
V = np.column_stack([i.ravel() / n, j.ravel() / n, np.zeros(i.size)])
c = (i[:-1, :-1] + (n + 1) * j[:-1, :-1]).ravel()            # lower-left corner of every cell
F = np.vstack([np.column_stack([c, c + 1, c + n + 2]), np.column_stack([c, c + n + 2, c + n + 1])])
v = lambda a, b: a + (n + 1) * b
square = ([v(a, 5) for a in range(5, 15)] + [v(15, b) for b in range(5, 15)] +
          [v(a, 15) for a in range(15, 5, -1)] + [v(5, b) for b in range(15, 4, -1)])
r = swn.winding_numbers(V, F, [square[:-3]])                  # counter-clockwise, its last 3 edges missing
print(f"grid: {np.count_nonzero(r.W == 1)} faces labelled 1 (the 10 x 10 cells inside: 200), "
      f"bounding chain of {np.count_nonzero(r.bounding)} edges")
ok = np.count_nonzero(r.W == 1) == 200 and np.count_nonzero(r.W) == 200

# 2. Files: the mesh, and the curve put on its edges (short pieces ending inside are refined, as in the tool).
curve = swn.load(data / "torus.obj", data / "torus-phi.txt")
solver = swn.Solver(curve.V, curve.F)
r = solver.solve(curve.halfedges, curve.multiplicities)
labels, counts = np.unique(r.W, return_counts=True)
print(f"torus-phi: {len(curve.F)} faces, labels {dict(zip(labels.tolist(), counts.tolist()))}, "
      f"G on {np.count_nonzero(r.G)} edges (the completed meridian), solved in {r.report['times']['total']:.2f} s")
G_halfedges = np.where(r.G[:, None] > 0, r.edges, r.edges[:, ::-1])[r.G != 0]   # G as halfedges (a, b)
ok = ok and np.count_nonzero(r.G) == 78 and len(labels) == 2

# 3. Another curve on the same mesh: G itself, a closed loop around the handle, bounds nothing.
again = solver.solve(G_halfedges)
print(f"G as input: labels {np.unique(again.W).tolist()}, G again on {np.count_nonzero(again.G)} edges")
ok = ok and (again.W == 0).all() and (again.G == r.G).all()
sys.exit(0 if ok else 1)
