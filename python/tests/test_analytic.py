# Cases with known answers: loops that bound a region (labels counted exactly), a meridian of a torus that
# bounds nothing (it is G), broken curves, and the bookkeeping of the binding (face order, corners, edges).
import numpy as np
import pytest

import swn
from conftest import (edge_values, grid_disk, grid_rectangle_loop, icosahedron, polyline_halfedges, torus,
                      torus_rectangle_loop)


def vertex_link(F, v):
    """The halfedges (a, b) opposite to v in the faces (v, a, b) around it: a counter-clockwise loop around v."""
    link = []
    for f in F:
        if v in f:
            k = list(f).index(v)
            link.append((f[(k + 1) % 3], f[(k + 2) % 3]))
    return np.array(link)


def test_icosahedron_loop_around_a_vertex():
    V, F = icosahedron()
    link = vertex_link(F, 0)
    r = swn.winding_numbers(V, F, link)
    around = np.array([0 in f for f in F])
    assert around.sum() == 5
    assert (r.W[around] == 1).all() and (r.W[~around] == 0).all()
    # the completion of a closed curve is the curve; nothing is nonbounding on a sphere
    assert (r.bounding == edge_values(r.edges, link)).all()
    assert (r.G == 0).all() and np.abs(r.g).max() < 1e-9
    assert r.report["genus"] == 0 and r.report["components"] == 1 and r.report["curve_edges"] == 5
    # the same loop as a closed vertex polyline, and reversed: the inside is one lower than the outside
    polyline = list(link[:, 0]) + [link[0, 0]]
    order = [polyline[0]]
    for _ in range(5):   # follow the halfedges from vertex to vertex
        order.append(dict(link.tolist())[order[-1]])
    assert (swn.winding_numbers(V, F, [order]).W == r.W).all()
    assert (swn.winding_numbers(V, F, [order[::-1]]).W == -r.W).all()


@pytest.mark.parametrize("form", ["polyline", "halfedges"])
def test_grid_disk_rectangle(form):
    n = 12
    V, F = grid_disk(n)
    loop, inside = grid_rectangle_loop(n, 3, 8, 2, 6)
    curves = [loop] if form == "polyline" else polyline_halfedges(loop)
    r = swn.winding_numbers(V, F, curves)
    expected = np.zeros(len(F), int)
    expected[inside] = 1
    assert (r.W == expected).all()
    assert r.W.dtype == np.int32 and r.W.shape == (len(F),)
    assert (r.bounding == edge_values(r.edges, polyline_halfedges(loop))).all()
    # a closed curve on a disk: w is the indicator of the region at every corner
    assert r.w.shape == (len(F), 3)
    assert np.allclose(r.w, expected[:, None], atol=1e-7)
    assert (r.G == 0).all()


def test_multiplicities_and_orientation():
    n = 10
    V, F = grid_disk(n)
    loop, inside = grid_rectangle_loop(n, 2, 5, 2, 5)
    h = polyline_halfedges(loop)
    for m, label in [(2, 2), (-1, -1), (3, 3)]:
        for r in (swn.winding_numbers(V, F, h, np.full(len(h), m)), swn.winding_numbers(V, F, [loop], [m]),
                  swn.winding_numbers(V, F, h, m)):
            assert (r.W[inside] == label).all() and (np.delete(r.W, inside) == 0).all()
    # two nested loops: 2 in the inner region, 1 in the ring, 0 outside
    inner, inner_faces = grid_rectangle_loop(n, 3, 4, 3, 4)
    r = swn.winding_numbers(V, F, [loop, inner])
    assert (r.W[inner_faces] == 2).all()
    assert sorted(np.unique(r.W, return_counts=True)[1].tolist()) == [2, 16, 200 - 18]
    # a halfedge and its opposite cancel
    r = swn.winding_numbers(V, F, np.vstack([h, h[:3, ::-1]]))
    assert r.report["curve_edges"] == len(h) - 3


def test_torus_meridian_is_nonbounding():
    nu, nv = 24, 12
    V, F, idx = torus(nu, nv)
    meridian = [idx(5, j) for j in range(nv + 1)]
    r = swn.winding_numbers(V, F, [meridian])
    assert r.report["genus"] == 1
    assert (r.W == r.W[0]).all() and (r.W == 0).all()
    assert (r.G == edge_values(r.edges, polyline_halfedges(meridian))).all()
    assert (r.bounding == 0).all()
    assert np.allclose(r.g, r.G, atol=1e-6)


def test_torus_broken_meridian_is_completed():
    nu, nv = 24, 12
    V, F, idx = torus(nu, nv)
    meridian = [idx(5, j) for j in range(nv + 1)]
    broken = [meridian[:5], meridian[7:]]      # two edges missing
    r = swn.winding_numbers(V, F, broken)
    assert r.report["interior_endpoints"] == 2
    assert (r.W == 0).all()
    assert (r.G == edge_values(r.edges, polyline_halfedges(meridian))).all()
    # NaN at the two interior endpoints, finite elsewhere
    ends = np.isin(F, [meridian[4], meridian[7]])
    assert np.isnan(r.w[ends]).all() and np.isfinite(r.w[~ends]).all()


def test_torus_broken_loop_bounds_a_region():
    nu, nv = 32, 16
    V, F, idx = torus(nu, nv)
    loop = torus_rectangle_loop(idx, 8, 14, 3, 9)
    inside = np.array([(8 <= f // (2 * nv) < 14) and (3 <= (f % (2 * nv)) // 2 < 9) for f in range(len(F))])
    r = swn.winding_numbers(V, F, [loop[:-2]])      # the last two edges missing
    assert (r.W[inside] == 1).all() and (r.W[~inside] == 0).all()
    assert (r.bounding == edge_values(r.edges, polyline_halfedges(loop))).all()
    assert (r.G == 0).all()


def test_outputs_follow_the_input_face_order():
    nu, nv = 16, 8
    V, F, idx = torus(nu, nv)
    curves = [[idx(2, j) for j in range(nv - 2)], torus_rectangle_loop(idx, 6, 11, 3, 6)[:-1]]
    r = swn.winding_numbers(V, F, curves)
    rng = np.random.default_rng(1)
    p = rng.permutation(len(F))
    rotated = np.roll(F[p], 1, axis=1)           # each face starts at its last vertex
    q = swn.winding_numbers(V, rotated, curves)
    assert (q.W == r.W[p]).all()
    assert np.allclose(np.roll(r.w[p], 1, axis=1), q.w, equal_nan=True, atol=1e-7)
    # edges are renumbered, the chains per vertex pair are not
    as_dict = lambda res, values: {tuple(sorted(e)): v * (1 if e[0] < e[1] else -1)
                                   for e, v in zip(res.edges.tolist(), values.tolist())}
    assert as_dict(q, q.G) == as_dict(r, r.G) and as_dict(q, q.bounding) == as_dict(r, r.bounding)


def test_solver_reuse_matches_fresh_solves():
    nu, nv = 24, 12
    V, F, idx = torus(nu, nv)
    meridian = [idx(5, j) for j in range(nv + 1)]
    curves = [[meridian[:5], meridian[7:]],
              [torus_rectangle_loop(idx, 3, 9, 2, 5)],
              [meridian],
              [[idx(i, 0) for i in range(nu + 1)]]]
    solver = swn.Solver(V, F)
    assert solver.report["genus"] == 1 and solver.report["faces"] == len(F)
    assert solver.number_of_vertices == len(V) and solver.number_of_faces == len(F)
    first = [solver.solve(c) for c in curves]
    again = [solver.solve(c, concurrency=False) for c in curves]
    assert again[3].report["jump_laplacian_reused"]
    # the broken meridian again: the kept 0-form Laplacian with an update for its two endpoints
    assert again[0].report["jump_laplacian_reused"] and again[0].report["jump_laplacian_update_rank"] > 0
    for c, a, b in zip(curves, first, again):
        fresh = swn.winding_numbers(V, F, c)
        for res in (a, b):
            assert (res.W == fresh.W).all() and (res.G == fresh.G).all() and (res.bounding == fresh.bounding).all()
            assert np.allclose(res.g, fresh.g, atol=1e-8) and np.allclose(res.w, fresh.w, equal_nan=True, atol=1e-8)


def test_sketching_resolves_start_from_the_last_answer():
    # the paper's sketching use: a broken meridian kept, a broken square stroke moved step by step; each
    # re-solve starts the residual from the last answer (the solver's kept residual solver) and gives
    # the labels and G of a fresh solve
    nu, nv = 30, 12
    V, F, idx = torus(nu, nv)
    meridian = [idx(3, j) for j in range(nv + 1)]
    solver = swn.Solver(V, F)
    warm = 0
    for step in range(5):
        square = torus_rectangle_loop(idx, 10 + step, 15 + step, 2, 6)[1:]   # a gap of one edge
        curves = [meridian[:5], meridian[7:], square]
        r = solver.solve(curves)
        if step == 0:
            assert not r.report["residual_warm_started"]
        warm += r.report["residual_warm_started"]
        fresh = swn.winding_numbers(V, F, curves)
        assert not fresh.report["residual_warm_started"]
        assert (r.W == fresh.W).all() and (r.G == fresh.G).all()
        assert (r.G != 0).sum() >= nv   # the completed meridian
    assert warm >= 3


def test_reduced_residual_and_epsilon():
    nu, nv = 24, 12
    V, F, idx = torus(nu, nv)
    meridian = [idx(5, j) for j in range(nv + 1)]
    r = swn.winding_numbers(V, F, [meridian[:5], meridian[7:]], reduced_residual=True, epsilon=0.05)
    assert r.report["reduced_residual"]
    assert (r.G == edge_values(r.edges, polyline_halfedges(meridian))).all()


def test_inputs_as_lists_and_other_dtypes():
    V, F = icosahedron()
    link = vertex_link(F, 0)
    r = swn.winding_numbers(V.tolist(), F.tolist(), link.tolist())
    s = swn.winding_numbers(V.astype(np.float32), F.astype(np.uint16), link.astype(np.int32))
    assert (r.W == s.W).all() and r.W[F[:, 0] == 0].tolist() == [1] * 5


@pytest.mark.parametrize("layout", ["C", "F", "strided"])
@pytest.mark.parametrize("fdtype", [np.int64, np.int32, np.uint32])
@pytest.mark.parametrize("vdtype", [np.float64, np.float32])
def test_dtypes_and_memory_layouts_give_identical_results(vdtype, fdtype, layout):
    nu, nv = 16, 8
    V, F, idx = torus(nu, nv)
    V = V.astype(np.float32).astype(np.float64)        # the same coordinates in either precision
    curves = [[idx(2, j) for j in range(nv - 2)], torus_rectangle_loop(idx, 6, 11, 3, 6)[:-1]]
    ref = swn.winding_numbers(V, F, curves)

    def arrange(a, dtype):
        if layout == "strided":                        # every other column of a wider array
            wide = np.zeros((a.shape[0], 2 * a.shape[1]), dtype)
            wide[:, ::2] = a
            return wide[:, ::2]
        return np.asarray(a, dtype=dtype, order=layout)

    Vx, Fx = arrange(V, vdtype), arrange(F, fdtype)
    assert Vx.dtype == vdtype and Fx.dtype == fdtype
    r = swn.winding_numbers(Vx, Fx, curves)
    assert (r.W == ref.W).all() and (r.G == ref.G).all() and (r.edges == ref.edges).all()
    assert np.array_equal(r.w, ref.w, equal_nan=True) and np.array_equal(r.g, ref.g)
    s = swn.Solver(Vx, Fx).solve(curves)
    assert (s.W == ref.W).all() and np.array_equal(s.w, ref.w, equal_nan=True)
    q = swn.winding_numbers(Vx, Fx, curves, soup=True)   # the soup route reads them alike
    assert (q.W == ref.W).all() and (q.G == ref.G).all()
