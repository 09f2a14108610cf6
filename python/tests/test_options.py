# Every setting of the library: the residual solvers and the sparse solvers compiled in agree on analytic
# cases, on triangle meshes and on polygon soups; the reduced residual, the unfiltered labels, one thread;
# bad values raise ValueError naming the setting and its allowed values.
import itertools

import numpy as np
import pytest

import swn
from conftest import edge_values, polyline_halfedges, quad_torus, torus, torus_rectangle_loop


def test_the_solvers_compiled_in():
    assert set(swn.LP_SOLVERS) <= {"lemon", "lemon-simplex", "glpk"} and swn.LP_SOLVERS
    assert set(swn.LINEAR_SOLVERS) <= {"cholmod", "ldlt"} and "ldlt" in swn.LINEAR_SOLVERS


@pytest.mark.parametrize("lp_solver, linear_solver", list(itertools.product(swn.LP_SOLVERS, swn.LINEAR_SOLVERS)))
def test_backends_agree_on_broken_curves(lp_solver, linear_solver):
    nu, nv = 24, 12
    V, F, idx = torus(nu, nv)
    meridian = [idx(5, j) for j in range(nv + 1)]
    loop = torus_rectangle_loop(idx, 10, 15, 3, 8)
    curves = [meridian[:5], meridian[7:], loop[:-2]]   # both broken: the residual problem runs
    inside = np.array([(10 <= f // (2 * nv) < 15) and (3 <= (f % (2 * nv)) // 2 < 8) for f in range(len(F))])
    settings = dict(lp_solver=lp_solver, linear_solver=linear_solver)
    r = swn.winding_numbers(V, F, curves, **settings)
    assert r.report["lp_ran"]
    assert (r.W == inside).all()
    assert (r.G == edge_values(r.edges, polyline_halfedges(meridian))).all()
    s = swn.Solver(V, F, linear_solver=linear_solver).solve(curves, lp_solver=lp_solver)
    assert (s.W == r.W).all() and (s.G == r.G).all()
    # a polygon soup: the quads of the same torus
    _, Q, _ = quad_torus(nu, nv)
    q = swn.winding_numbers(V, Q, curves, **settings)
    assert (q.W == inside[::2]).all()
    assert (q.G == edge_values(q.edges, polyline_halfedges(meridian))).all()


def test_reduced_residual_epsilon_and_one_thread():
    nu, nv = 24, 12
    V, F, idx = torus(nu, nv)
    meridian = [idx(5, j) for j in range(nv + 1)]
    exact = swn.winding_numbers(V, F, [meridian[:5], meridian[7:]])
    for settings in (dict(reduced_residual=True, epsilon=0.05), dict(concurrency=False), dict(epsilon=0.001)):
        r = swn.winding_numbers(V, F, [meridian[:5], meridian[7:]], **settings)
        assert r.report["reduced_residual"] == settings.get("reduced_residual", False)
        assert (r.W == exact.W).all() and (r.G == exact.G).all()


def test_unfiltered_labels_split_the_torus_along_the_meridian():
    nu, nv = 24, 12
    V, F, idx = torus(nu, nv)
    meridian = [idx(5, j) for j in range(nv + 1)]
    for quads in (False, True):
        faces = quad_torus(nu, nv)[1] if quads else F
        r = swn.winding_numbers(V, faces, [meridian], filter_nonbounding_loops=False)
        assert (r.G == 0).all() and (r.g == 0).all()
        # u grows by 1 around the torus from the meridian: rounded, two regions of one label each, which the
        # meridian and a contour of u near the opposite meridian separate
        assert sorted(np.unique(r.W).tolist()) in ([0, 1], [-1, 0])
        on = edge_values(r.edges, polyline_halfedges(meridian)) != 0
        assert (r.bounding[on] != 0).all()
        assert 0.3 < np.mean(r.W == r.W.max()) < 0.7
        assert swn.winding_numbers(V, faces, [meridian]).W.tolist() == [0] * len(faces)


@pytest.mark.parametrize("settings, message", [
    (dict(lp_solver="simplex"), "lp_solver must be one of " + ", ".join(map(repr, swn.LP_SOLVERS)) + " (compiled in), not 'simplex'"),
    (dict(linear_solver="umfpack"), "linear_solver must be one of " + ", ".join(map(repr, swn.LINEAR_SOLVERS)) + " (compiled in), not 'umfpack'"),
    (dict(reduced_residual="yes"), "reduced_residual must be True or False, not 'yes'"),
    (dict(filter_nonbounding_loops=None), "filter_nonbounding_loops must be True or False, not None"),
    (dict(concurrency=2), "concurrency must be True or False, not 2"),
    (dict(verbose="no"), "verbose must be True or False, not 'no'"),
    (dict(epsilon=0), "epsilon must be positive and finite, not 0"),
    (dict(epsilon=float("nan")), "epsilon must be positive and finite, not nan"),
    (dict(epsilon="small"), "epsilon must be positive and finite, not 'small'"),
    (dict(soup="no"), "soup must be True or False, not 'no'"),
])
def test_bad_settings(settings, message):
    V, F, idx = torus(8, 6)
    loop = torus_rectangle_loop(idx, 1, 3, 1, 3)
    with pytest.raises(ValueError) as e:
        swn.winding_numbers(V, F, [loop], **settings)
    assert str(e.value) == message
    if "soup" not in settings:
        with pytest.raises(ValueError) as e:
            if "linear_solver" in settings:
                swn.Solver(V, F, **settings)
            else:
                swn.Solver(V, F).solve([loop], **settings)
        assert str(e.value) == message


def test_completed_homology_class_keeps_a_meridian_with_a_half_gap():
    # 6 of a meridian's 12 edges drawn: the broken curve's harmonic part has a period below 1/2 around the
    # tube, so Eq. 11 (the default) rounds G to nothing; with completed_homology_class the residual problem
    # is in the class of the meridian closed along its gap, and G is that meridian (12 edges, upwards).
    # One label everywhere either way. On a polygon soup the same.
    nu, nv = 24, 12
    V, F, idx = torus(nu, nv)
    half = [idx(12, j) for j in range(7)]
    meridian = [(idx(12, j), idx(12, j + 1)) for j in range(nv)]
    for soup in (False, True):
        plain = swn.winding_numbers(V, F, [half], soup=soup)
        assert plain.report["interior_endpoints"] == 2
        assert not plain.G.any() and len(set(plain.W.tolist())) == 1
        r = swn.winding_numbers(V, F, [half], soup=soup, completed_homology_class=True)
        assert (r.G == edge_values(r.edges, meridian)).all()
        assert len(set(r.W.tolist())) == 1
    solver = swn.Solver(V, F)
    assert (solver.solve([half], completed_homology_class=True).G == edge_values(solver.edges, meridian)).all()
    with pytest.raises(ValueError, match="completed_homology_class"):
        swn.winding_numbers(V, F, [half], completed_homology_class="yes")
