# The label of a chosen face (anchor_face) and the per-region confidence of the labels (the library's
# label_anchor_face and Label_confidence): analytic answers on a grid disk and a quad torus.
import numpy as np
import pytest

import swn
from conftest import grid_disk, grid_rectangle_loop, mobius_strip, quad_torus, torus, torus_rectangle_loop


def test_anchor_face_fixes_the_labels_constant():
    n = 10
    V, F = grid_disk(n)
    loop, inside = grid_rectangle_loop(n, 3, 8, 2, 6)
    default = swn.winding_numbers(V, F, [loop])
    outside = np.setdiff1d(np.arange(len(F)), inside)
    assert (default.W[inside] == 1).all() and (default.W[outside] == 0).all()
    r = swn.winding_numbers(V, F, [loop], anchor_face=inside[3])
    assert (r.W == default.W - 1).all() and (r.G == default.G).all() and np.allclose(r.w, default.w - 1, atol=1e-9)
    assert (swn.winding_numbers(V, F, [loop], anchor_face=outside[0]).W == default.W).all()
    assert (swn.Solver(V, F).solve([loop], anchor_face=int(inside[0])).W == r.W).all()
    # on a polygon soup: the quads of a torus
    nu, nv = 16, 8
    Vt, Q, idx = quad_torus(nu, nv)
    quads = [i * nv + j for i in range(3, 7) for j in range(2, 5)]
    s = swn.winding_numbers(Vt, Q, [torus_rectangle_loop(idx, 3, 7, 2, 5)], anchor_face=np.int64(quads[0]))
    expected = np.full(len(Q), -1)
    expected[quads] = 0
    assert (s.W == expected).all()
    with pytest.raises(ValueError, match="label_anchor_face: the face is not a face of the mesh"):
        swn.winding_numbers(V, F, [loop], anchor_face=len(F))
    with pytest.raises(ValueError, match=r"label_anchor_face: polygon 128 is out of range \(128 polygons\)"):
        swn.winding_numbers(Vt, Q, [torus_rectangle_loop(idx, 3, 7, 2, 5)], anchor_face=len(Q))
    with pytest.raises(ValueError, match="anchor_face must be a face index"):
        swn.winding_numbers(V, F, [loop], anchor_face=-1)


def mean_interior_edge_length(V, F):
    sides = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    edges, count = np.unique(sides, axis=0, return_counts=True)
    interior = edges[count == 2]
    return np.linalg.norm(V[interior[:, 0]] - V[interior[:, 1]], axis=1).mean()


@pytest.mark.parametrize("epsilon", [0.01, 0.05])
def test_confidence_of_a_region_inside_a_loop(epsilon):
    n = 10
    V, F = grid_disk(n)
    loop, inside = grid_rectangle_loop(n, 3, 8, 2, 6)
    r = swn.winding_numbers(V, F, [loop], epsilon=epsilon, confidence=True)
    c = r.confidence
    assert isinstance(c, swn.LabelConfidence) and len(c.regions) == 2
    k = c.region[inside[0]]
    assert (c.region[inside] == k).all() and (np.delete(c.region, inside) != k).all()
    # a region inside a complete loop of length L costs epsilon L, L in mean interior edge lengths
    cost = epsilon * (2 * (5 + 4) / n) / mean_interior_edge_length(V, F)
    assert c.regions[k]["flip_cost"] == pytest.approx(cost, rel=1e-9)
    assert c.regions[k]["label"] == 1 and c.regions[k]["flip_delta"] == -1 and c.regions[k]["faces"] == len(inside)
    assert c.regions[k]["area"] == pytest.approx(len(inside) / (2 * n * n), rel=1e-12)
    assert not c.regions[k]["largest_in_component"] and c.regions[1 - k]["largest_in_component"]
    assert np.allclose(c.face_cost[inside], cost, rtol=1e-9)
    # the second-best labeling flips it: no region at all
    assert c.second_best_region == k and c.second_best_cost == pytest.approx(cost, rel=1e-9)
    assert (c.second_best_W == 0).all()
    # the same from a Solver; none without asking
    s = swn.Solver(V, F).solve([loop], epsilon=epsilon, confidence=True).confidence
    assert np.array_equal(s.face_cost, c.face_cost) and (s.second_best_W == c.second_best_W).all()
    assert swn.winding_numbers(V, F, [loop]).confidence is None


@pytest.mark.parametrize("epsilon", [0.01, 0.05])
def test_confidence_on_a_polygon_soup_is_that_of_every_polygons_region(epsilon):
    # a quad torus (triangulated internally along the diagonal (i, j)-(i+1, j+1), as torus()) with a meridian
    # and a loop around 4 x 4 quads: the region inside costs epsilon L (L in mean interior edge lengths, the
    # diagonals included); the soup gives every quad the values of its region, the same as the triangulated
    # torus gives its two triangles on the mesh route and on the soup route
    nu, nv = 24, 12
    V, Q, idx = quad_torus(nu, nv)
    _, T, _ = torus(nu, nv)
    loop = torus_rectangle_loop(idx, 10, 14, 2, 6)
    curves = [[idx(3, j) for j in range(nv + 1)], loop]
    s = swn.winding_numbers(V, Q, curves, epsilon=epsilon, confidence=True)
    assert s.polygon_soup.startswith("face 0 has 4 vertices")
    c = s.confidence
    assert isinstance(c, swn.LabelConfidence) and len(c.regions) == 2
    inside = np.zeros(len(Q), bool)
    inside[[i * nv + j for i in range(10, 14) for j in range(2, 6)]] = True
    k = c.region[inside][0]
    assert (c.region[inside] == k).all() and (c.region[~inside] == 1 - k).all()
    L = np.linalg.norm(V[loop[1:]] - V[loop[:-1]], axis=1).sum()
    cost = epsilon * L / mean_interior_edge_length(V, T)
    assert c.regions[k]["flip_cost"] == pytest.approx(cost, rel=1e-9)
    assert c.regions[1 - k]["flip_cost"] == pytest.approx(cost, rel=1e-9)
    assert c.regions[k]["faces"] == 32 and c.regions[1 - k]["faces"] == len(T) - 32   # triangles
    assert (s.W[inside] == c.regions[k]["label"]).all() and (s.W[~inside] == c.regions[1 - k]["label"]).all()
    assert np.allclose(c.face_cost, cost, rtol=1e-9) and c.face_cost.shape == (len(Q),)
    assert c.second_best_region == k and (c.second_best_W == c.regions[1 - k]["label"]).all()
    for route in (swn.winding_numbers(V, T, curves, epsilon=epsilon, confidence=True),
                  swn.winding_numbers(V, T, curves, epsilon=epsilon, confidence=True, soup=True)):
        t = route.confidence
        assert (route.W == np.repeat(s.W, 2)).all() and (t.second_best_W == np.repeat(c.second_best_W, 2)).all()
        assert np.allclose(t.face_cost, np.repeat(c.face_cost, 2), rtol=1e-12)
        assert (t.region == np.repeat(c.region, 2)).all() and t.second_best_region == c.second_best_region
        assert [r["faces"] for r in t.regions] == [r["faces"] for r in c.regions]
    # a Möbius strip with a dual chain: two regions, the quads between the jumps and the others; none without asking
    Vm, M = mobius_strip(12)
    m = swn.winding_numbers(Vm, M, dual_chain=[[2, 3], [7, 6]], epsilon=epsilon, confidence=True).confidence
    assert len(m.regions) == 2 and (m.region[3:7] == m.region[3]).all() and (np.delete(m.region, range(3, 7)) != m.region[3]).all()
    assert swn.winding_numbers(V, Q, curves).confidence is None
