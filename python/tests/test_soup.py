# Polygon meshes and polygon soups (nonmanifold, nonorientable, dual chains) through the library's
# polygon_soup_winding_numbers(): labels per input polygon, with analytic answers.
import numpy as np
import pytest

import swn
from conftest import (edge_values, grid_rectangle_loop, mobius_strip, polyline_halfedges, quad_torus, torus,
                      torus_rectangle_loop)


def quad_cells(nu, nv, i0, i1, j0, j1):
    """the quads (i, j), i in [i0, i1), j in [j0, j1) of quad_torus(nu, nv)"""
    inside = np.zeros(nu * nv, bool)
    for i in range(i0, i1):
        inside[i * nv + np.arange(j0, j1)] = True
    return inside


def test_quad_torus_labels_per_quad():
    nu, nv = 24, 12
    V, Q, idx = quad_torus(nu, nv)
    loop = torus_rectangle_loop(idx, 6, 11, 2, 7)
    r = swn.winding_numbers(V, Q, [loop])
    assert r.polygon_soup.startswith("face 0 has 4 vertices")
    inside = quad_cells(nu, nv, 6, 11, 2, 7)
    assert r.W.shape == (len(Q),) and (r.W[inside] == 1).all() and (r.W[~inside] == 0).all()
    assert r.w.shape == (len(Q), 4)
    assert r.report["faces"] == len(Q) and r.report["genus"] == 1 and (r.G == 0).all()
    assert (r.bounding == edge_values(r.edges, polyline_halfedges(loop))).all()
    # the edges are the quads' sides (no diagonal), in order of first appearance
    assert len(r.edges) == 2 * len(Q) and r.edges[:4].tolist() == [[Q[0, k], Q[0, (k + 1) % 4]] for k in range(4)]
    # a list of polygons is the same input; the triangulated torus gives each quad's label to its two triangles
    assert (swn.winding_numbers(V, Q.tolist(), [loop]).W == r.W).all()
    _, T, _ = torus(nu, nv)
    assert (swn.winding_numbers(V, T, [loop]).W == np.repeat(r.W, 2)).all()


def test_quad_torus_meridian_is_nonbounding():
    nu, nv = 24, 12
    V, Q, idx = quad_torus(nu, nv)
    meridian = [idx(5, j) for j in range(nv + 1)]
    for curves in ([meridian], [meridian[:5], meridian[7:]]):     # closed, and broken (completed)
        r = swn.winding_numbers(V, Q, curves)
        assert (r.W == 0).all() and (r.bounding == 0).all()
        assert (r.G == edge_values(r.edges, polyline_halfedges(meridian))).all()


def test_triangle_mesh_as_a_soup_matches_the_mesh_route():
    nu, nv = 24, 12
    V, F, idx = torus(nu, nv)
    meridian = [idx(5, j) for j in range(nv + 1)]
    curves = [meridian[:5], meridian[7:], torus_rectangle_loop(idx, 10, 15, 3, 8)]
    mesh = swn.winding_numbers(V, F, curves)
    soup = swn.winding_numbers(V, F, curves, soup=True)
    assert mesh.polygon_soup == "" and soup.polygon_soup == "soup=True"
    assert (soup.edges == mesh.edges).all()
    assert (soup.W == mesh.W).all() and (soup.G == mesh.G).all() and (soup.bounding == mesh.bounding).all()
    assert np.allclose(soup.w, mesh.w, atol=1e-6, equal_nan=True) and np.allclose(soup.g, mesh.g, atol=1e-6)


@pytest.mark.parametrize("n, path, region", [
    (16, [[3, 4], [9, 8]], [4, 5, 6, 7, 8]),            # away from the twist
    (16, [[13, 14], [2, 1]], [14, 15, 0, 1]),           # across the twisted gluing
])
def test_mobius_strip_dual_chain(n, path, region):
    V, Q = mobius_strip(n)
    r = swn.winding_numbers(V, Q, dual_chain=path)
    expected = np.zeros(n, int)
    expected[region] = 1
    assert (r.W == expected).all()
    assert r.report["nonorientable_edges"] == 1
    # the same chain as face pairs, and reversed
    pairs = np.array([p for p in path])
    assert (swn.winding_numbers(V, Q, dual_chain=pairs).W == expected).all()
    assert (swn.winding_numbers(V, Q, dual_chain=pairs[:, ::-1]).W == -expected).all()


def test_mobius_strip_of_triangles_is_solved_as_a_soup():
    n = 16
    V, Q = mobius_strip(n)
    T = np.vstack([Q[:, [0, 1, 2]], Q[:, [0, 2, 3]]])            # quad i: triangles i and n + i
    with pytest.raises(ValueError, match="not consistently oriented"):
        swn.Solver(V, T)
    r = swn.winding_numbers(V, T, dual_chain=[[n + 3, 4], [9, n + 8]])   # quads 4..8
    assert "in the same direction: the surface is not consistently oriented" in r.polygon_soup
    expected = np.zeros(n, int)
    expected[4:9] = 1
    assert (r.W == np.concatenate([expected, expected])).all()


def glued_tori(nu, nv, glue):
    """Two triangle tori: B is A mirrored through the plane of A's vertex 0 (faces reversed, so oriented
    outwards), sharing vertex 0 ('vertex', a nonmanifold vertex) or the edge (0, 1) ('edge', four faces on it).
    Returns V, F, idx and B's vertex of every vertex index of A."""
    V, F, idx = torus(nu, nv)
    VB = V.copy()
    VB[:, 0] = 2 * V[0, 0] - V[:, 0]
    shared = [0] if glue == "vertex" else [0, 1]
    of_b = np.arange(len(V)) + len(V)
    of_b[shared] = shared
    return np.vstack([V, VB]), np.vstack([F, of_b[F[:, ::-1]]]), idx, of_b   # B's copies of the shared: unreferenced


@pytest.mark.parametrize("glue, problem", [("vertex", "non-manifold vertex 0"), ("edge", "non-manifold edge (0, 1)")])
def test_glued_tori(glue, problem):
    nu, nv = 32, 16
    V, F, idx, of_b = glued_tori(nu, nv, glue)
    loop_a = torus_rectangle_loop(idx, 8, 14, 3, 9)
    loop_b = of_b[torus_rectangle_loop(idx, 18, 24, 5, 10)]
    with pytest.warns(swn.MeshWarning, match="unreferenced vertices"):
        r = swn.winding_numbers(V, F, [loop_a, loop_b], [1, -2])
    assert r.polygon_soup.startswith(problem)
    in_a = np.array([(8 <= f // (2 * nv) < 14) and (3 <= (f % (2 * nv)) // 2 < 9) for f in range(2 * nu * nv)])
    in_b = np.array([(18 <= f // (2 * nv) < 24) and (5 <= (f % (2 * nv)) // 2 < 10) for f in range(2 * nu * nv)])
    expected = np.concatenate([in_a.astype(int), 2 * in_b.astype(int)])   # B's faces are reversed: -2 is +2 inside
    assert (r.W == expected).all()
    assert (r.G == 0).all()
    key = "nonmanifold_vertices" if glue == "vertex" else "nonmanifold_edges"
    assert r.report[key] >= 1


def mixed_grid(n):
    """The unit square as n x n cells: quads, except the cells of odd rows split into two triangles; returns
    V, the faces (a list) and the cell of every face."""
    idx = lambda a, b: a + (n + 1) * b
    i, j = np.meshgrid(np.arange(n + 1), np.arange(n + 1), indexing="xy")
    V = np.column_stack([i.ravel() / n, j.ravel() / n, np.zeros((n + 1) ** 2)])
    F, cell = [], []
    for b in range(n):
        for a in range(n):
            q = [idx(a, b), idx(a + 1, b), idx(a + 1, b + 1), idx(a, b + 1)]
            pieces = [q] if b % 2 == 0 else [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]
            F += pieces
            cell += [(a, b)] * len(pieces)
    return V, F, cell


def test_mixed_polygons():
    n = 10
    V, F, cell = mixed_grid(n)
    loop, _ = grid_rectangle_loop(n, 2, 7, 3, 8)
    r = swn.winding_numbers(V, F, [loop])
    expected = np.array([1 if 2 <= a < 7 and 3 <= b < 8 else 0 for a, b in cell])
    assert (r.W == expected).all()
    # corners of faces of mixed sizes: one flat array, face by face; w is the indicator on a disk
    sizes = np.array([len(f) for f in F])
    assert r.w.shape == (sizes.sum(),)
    assert np.allclose(r.w, np.repeat(expected, sizes), atol=1e-7)


def test_bad_dual_chains_and_soup_curves():
    V, Q = mobius_strip(12)
    cases = [
        (dict(dual_chain=[[11, 12]]), "dual_chain: face index 12 is out of range (12 faces)"),
        (dict(dual_chain=[[0, 5]]), "dual chain pair 0 (0, 5): the two polygons share no edge"),
        (dict(dual_chain=np.zeros((2, 3), int)), "dual_chain given as an array must be face pairs of shape (k, 2), "
                                                 "not of shape (2, 3); give face paths as a list of sequences"),
        (dict(curves=[[0, 13]]), "curves[0]: vertices 0 and 13 are not joined by an edge of the mesh"),  # a diagonal
        (dict(), "no curve: give curves, a dual_chain, or both"),
    ]
    for settings, message in cases:
        with pytest.raises(ValueError) as e:
            swn.winding_numbers(V, Q, **settings)
        assert str(e.value) == message
