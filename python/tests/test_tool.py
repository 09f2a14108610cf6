# The readers of the tool in Python, and agreement with the swn tool: on the authors' demo files the module
# gives the tool's labels, corners, w, bounding chain and G (the tool is run from the test, on the same
# build's executable), and the outcomes the README quotes.
import json
import subprocess
import warnings

import numpy as np
import pytest

import swn
from conftest import DATA, edge_values

DEMO = DATA / "swn-demo"
CASES = [("torus.obj", "torus-phi.txt"), ("bunny.obj", "bunny-brokenheart.txt"), ("annulus.obj", "annulus.txt"),
         ("DoubleTorusWithLoops.obj", None)]


# annulus.obj has two vertices at the same position
pytestmark = pytest.mark.filterwarnings("ignore:2 vertices have exactly the same position:swn.MeshWarning")


def solve_demo(mesh, curve):
    c = swn.load(DEMO / mesh, None if curve is None else DEMO / curve)
    return c, swn.winding_numbers(c.V, c.F, c.halfedges, c.multiplicities)


def read_chain_obj(path, edges):
    """The chain of a curve OBJ written by the tool (nonbounding.obj, ...) on the edges (a, b) of `edges`."""
    vertices, halfedges = [], []
    for line in open(path):
        if line.startswith("# mesh vertices:"):
            vertices = [int(x) for x in line.split(":")[1].split()]
        elif line.startswith("l "):
            p = [vertices[int(x) - 1] for x in line.split()[1:]]
            halfedges += list(zip(p[:-1], p[1:]))
    return edge_values(edges, halfedges)


def read_w_obj(path):
    """The corners (m x 3 vertex indices) and w (m x 3, NaN where the tool wrote `vt 0 0`) of the tool's w.obj."""
    vt, faces = [], []
    for line in open(path):
        if line.startswith("vt "):
            x, y = map(float, line.split()[1:3])
            vt.append(x if y == 1 else np.nan)
        elif line.startswith("f "):
            faces.append([int(c.split("/")[0]) - 1 for c in line.split()[1:]])
    return np.array(faces), np.array(vt).reshape(-1, 3)


@pytest.mark.parametrize("mesh, curve", CASES)
def test_agrees_with_the_tool(tmp_path, swn_tool, mesh, curve):
    c, r = solve_demo(mesh, curve)
    out = tmp_path / "out"
    args = [swn_tool, str(DEMO / mesh), "--output-dir", str(out), "--quiet"]
    subprocess.run(args + ([] if curve is None else ["--curve", str(DEMO / curve)]), check=True)
    assert (np.loadtxt(out / "labels.txt", dtype=int) == r.W).all()
    corners, w = read_w_obj(out / "w.obj")
    assert (corners == c.F).all()
    assert np.array_equal(np.isnan(w), np.isnan(r.w)) and np.allclose(w, r.w, atol=1e-6, equal_nan=True)
    assert (read_chain_obj(out / "nonbounding.obj", r.edges) == r.G).all()
    assert (read_chain_obj(out / "bounding.obj", r.edges) == r.bounding).all()
    summary = json.load(open(out / "summary.json"))
    assert summary["solved_mesh"]["vertices"] == len(c.V) and summary["solved_mesh"]["faces"] == len(c.F)
    assert summary["curve"]["edges"] == r.report["curve_edges"] == len(c.halfedges)
    assert summary["solved_mesh"]["genus"] == r.report["genus"]


def test_demo_outcomes():
    """The outcomes of the authors' demo that the README quotes."""
    c, r = solve_demo("torus.obj", "torus-phi.txt")
    assert np.count_nonzero(r.G) == 78 and len(np.unique(r.W)) == 2
    c, r = solve_demo("bunny.obj", "bunny-brokenheart.txt")
    assert len(c.V) == 14318 and np.count_nonzero(r.W) == 1008
    c, r = solve_demo("annulus.obj", "annulus.txt")
    assert sorted(np.unique(r.W, return_counts=True)[1]) == [3402, 3702]
    c, r = solve_demo("DoubleTorusWithLoops.obj", None)
    assert sorted(np.unique(r.W, return_counts=True)[1]) == [582, 17149, 17237]


def test_read_mesh_keeps_the_file_order():
    V, F = swn.read_mesh(DEMO / "torus.obj")
    v = [l.split()[1:4] for l in open(DEMO / "torus.obj") if l.startswith("v ")]
    f = [[int(x.split("/")[0]) - 1 for x in l.split()[1:]] for l in open(DEMO / "torus.obj") if l.startswith("f ")]
    assert V.dtype == np.float64 and (V == np.array(v, float)).all()
    assert F.dtype == np.int64 and (F == np.array(f)).all()


def test_curve_files_in_the_three_formats(tmp_path):
    V, F = swn.read_mesh(DEMO / "torus.obj")
    r = swn.winding_numbers(V, F, [[0, 1, 49, 48, 0]])
    polylines = tmp_path / "loop.txt"
    polylines.write_text("# swn polylines\n0 1 49 48 0   # a loop around two faces\n")
    halfedges = tmp_path / "twice.txt"
    halfedges.write_text("# swn halfedges\nh 0 1 2\nh 1 49 2\nh 49 48 2\nh 48 0 2\n")
    authors = tmp_path / "authors.txt"
    authors.write_text("#offset 0\nv 0\nv 1\nv 49\nv 48\nl 0 1 2 3 0\n")
    for path, m in [(polylines, 1), (halfedges, 2), (authors, 1)]:
        c = swn.read_curve(path, V, F)
        assert c.V is not V and (c.V == V).all() and (c.F == F).all()   # closed: nothing cut, nothing refined
        assert (c.multiplicities == m).all() and len(c.halfedges) == 4
        assert c.info["cut_vertices"] == 0 and c.info["refinement_vertices"] == 0
        q = swn.winding_numbers(c.V, c.F, c.halfedges, c.multiplicities)
        assert (q.W == m * r.W).all() and np.count_nonzero(q.W) == 2


def test_read_curve_cuts_and_refines(tmp_path):
    V, F = swn.read_mesh(DEMO / "torus.obj")
    c = swn.read_curve(DEMO / "torus-phi.txt", V, F)
    assert c.info["refinement_vertices"] == 59 and len(c.V) == len(V) + 59
    assert (c.V[:len(V)] == V).all()
    plain = swn.read_curve(DEMO / "torus-phi.txt", V, F, refine_short_pieces=False)
    assert (plain.V == V).all() and (plain.F == F).all() and plain.info["refinement_vertices"] == 0
    assert (plain.multiplicities == 1).all() and len(plain.halfedges) == 147 - 59


def test_reader_warnings(tmp_path):
    obj = tmp_path / "tri.obj"
    obj.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf 1 2 3\nl 1 2\n")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        V, F = swn.read_mesh(obj)
    messages = [str(w.message) for w in caught]
    assert all(issubclass(w.category, swn.MeshWarning) for w in caught)
    assert any("1 unreferenced vertices kept as isolated vertices (3)" in m for m in messages)
    assert any("curve records (l, c) are not read by read_mesh(); swn.load() reads them" in m for m in messages)
    assert V.shape == (4, 3) and F.tolist() == [[0, 1, 2]]
