# Selection cleanup (the library's clean_face_selection() and clean_edge_selection()). Faces: on a torus (no
# border, no corner) with a band of quads as the true region, isolated flipped faces are restored exactly and
# random noise is cut at least fivefold; the border chain is the region's boundary. Edges: the border of a
# rectangle on a grid disk with gaps, reversed pieces and spurious pieces gives the rectangle. With a border: the
# two sides of a band across a grid disk give the band; isolated and random noise on the band are removed; an exact
# rectangle comes back unchanged.
import numpy as np
import pytest

import swn
from conftest import edge_values, grid_disk, grid_rectangle_loop, polyline_halfedges, torus

NU, NV = 32, 16
V, F, _ = torus(NU, NV)
BAND = np.arange(len(F)) // 2 // NV                  # quad (i, j) is faces 2 (i NV + j) and + 1
REGION = (BAND >= 8) & (BAND < 20)                   # 12 x 16 quads: between the meridians i = 8 and i = 20


def rings():
    """for every face, the faces sharing a vertex with it (itself included)"""
    at = [[] for _ in range(len(V))]
    for f, t in enumerate(F):
        for v in t:
            at[v].append(f)
    return [set(g for v in t for g in at[v]) for t in F]


def isolated_faces(seed, count):
    """`count` faces drawn at random (a fixed seed) whose rings are pairwise disjoint, each ring on one side of the
    region's border: every one of them, flipped, differs from all the faces around it, and no other face from more
    than one of them"""
    ring = rings()
    chosen, taken = [], set()
    for f in np.random.RandomState(seed).permutation(len(F)):
        if len(chosen) == count:
            break
        if ring[f] & taken or len(set(REGION[list(ring[f])])) > 1:
            continue
        chosen.append(int(f))
        taken |= ring[f]
    assert len(chosen) == count
    return chosen


def boundary_of(faces, selected):
    """the boundary of the selected faces as a chain on the edges (the sides of two selected faces cancel)"""
    return [(t[k], t[(k + 1) % 3]) for f, t in enumerate(faces) if selected[f] for k in range(3)]


def boundary(selected):
    return boundary_of(F, selected)


def test_clean_selection_keeps_the_region_and_what_is_all_or_nothing():
    c = swn.clean_face_selection(V, F, REGION)
    assert isinstance(c, swn.CleanSelection) and c.selected.dtype == bool and c.selected.shape == (len(F),)
    assert (c.selected == REGION).all()
    assert (c.bounding == edge_values(c.edges, boundary(REGION))).all() and np.count_nonzero(c.bounding) == 2 * NV
    assert (c.edges == swn.Solver(V, F).edges).all()
    for everything in (False, True):
        assert (swn.clean_face_selection(V, F, np.full(len(F), everything)).selected == everything).all()


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_isolated_flipped_faces_are_restored(seed):
    flipped = isolated_faces(seed, 12)
    noisy = REGION.copy()
    noisy[flipped] ^= True
    assert REGION[flipped].any() and not REGION[flipped].all()     # holes in the region and specks outside it
    c = swn.clean_face_selection(V, F, noisy)
    assert (c.selected == REGION).all()
    assert (c.bounding == edge_values(c.edges, boundary(REGION))).all()
    assert c.report["interior_endpoints"] == 0 and c.report["curve_edges"] == 2 * NV
    # the selection as face indices, with every solver and other settings: the same region
    indices = np.flatnonzero(noisy).astype(np.int32)
    for lp in swn.LP_SOLVERS:
        for linear in swn.LINEAR_SOLVERS:
            r = swn.clean_face_selection(V, F, indices, lp_solver=lp, linear_solver=linear, epsilon=0.05,
                                         reduced_residual=lp == swn.LP_SOLVERS[0], concurrency=False)
            assert (r.selected == REGION).all(), (lp, linear)
    # a single flipped face inside the region
    one = REGION.copy()
    one[np.flatnonzero(REGION)[100]] = False
    assert (swn.clean_face_selection(V, F, one).selected == REGION).all()


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_random_noise_is_mostly_removed(seed):
    # every face flipped with probability 0.08 (the C++ test on a sphere uses 0.11): the wrong faces drop at
    # least fivefold, and the border chain is the boundary of what is selected
    noisy = REGION ^ (np.random.RandomState(seed).random_sample(len(F)) < 0.08)
    before = np.count_nonzero(noisy != REGION)
    c = swn.clean_face_selection(V, F, noisy)
    after = np.count_nonzero(c.selected != REGION)
    assert before > 60 and 5 * after < before, (before, after)
    assert (c.bounding == edge_values(c.edges, boundary(c.selected))).all()


N = 20
VG, FG = grid_disk(N)
def test_clean_edge_selection_closes_gaps_and_drops_spurious_pieces():
    loop_vertices, inside = grid_rectangle_loop(N, 5, 15, 4, 13)
    rectangle = np.zeros(len(FG), bool)
    rectangle[inside] = True
    loop = polyline_halfedges(loop_vertices)
    # unoriented (every third edge reversed), with a gap every 7 edges
    selected = np.array([h[::-1] if k % 3 == 0 else h for k, h in enumerate(loop) if k % 7 != 3])
    idx = lambda a, b: a + (N + 1) * b
    spurious = np.array([[idx(1, 17), idx(2, 17)], [idx(17, 1), idx(17, 2)], [idx(18, 18), idx(19, 18)]])
    for selection in (selected, np.vstack([selected, spurious])):
        c = swn.clean_edge_selection(VG, FG, selection)
        assert (c.selected == rectangle).all()
        assert (c.bounding == edge_values(c.edges, loop)).all()
        assert c.report["interior_endpoints"] > 0
    # the same selection as a boolean mask of the edges
    mask = edge_values(c.edges, np.vstack([selected, spurious])) != 0
    assert (swn.clean_edge_selection(VG, FG, mask, lp_solver=swn.LP_SOLVERS[-1]).selected == rectangle).all()
    # a region of more than half of the surface, a gap every third edge: its inside all the same
    big_loop, big_inside = grid_rectangle_loop(N, 1, 19, 1, 19)
    big = np.zeros(len(FG), bool)
    big[big_inside] = True
    h = polyline_halfedges(big_loop)
    assert (swn.clean_edge_selection(VG, FG, h[np.arange(len(h)) % 3 != 1]).selected == big).all()


def test_an_exact_rectangle_comes_back_unchanged():
    # on the grid (diagonals from (a, b) to (a + 1, b + 1)) the outer triangle of the lower-right and of the
    # upper-left corner cell has two sides on the rectangle's border: a tooth, kept since no other face near it
    # is noise
    loop_vertices, inside = grid_rectangle_loop(N, 5, 15, 4, 13)
    rectangle = np.zeros(len(FG), bool)
    rectangle[inside] = True
    c = swn.clean_face_selection(VG, FG, rectangle)
    assert (c.selected == rectangle).all()
    assert (c.bounding == edge_values(c.edges, polyline_halfedges(loop_vertices))).all()


BAND = (np.arange(len(FG)) // 2 // N >= 5) & (np.arange(len(FG)) // 2 // N < 15)   # the rows 5 to 14 of cells


@pytest.mark.parametrize("gap", [3, 5, 7, 11])
def test_the_two_sides_of_a_band_across_a_disk_give_the_band(gap):
    # two open curves from border to border, unoriented, with gaps: the border of the mesh closes them into a
    # loop around the band
    idx = lambda a, b: a + (N + 1) * b
    sides = np.array([[idx(a, b), idx(a + 1, b)] for b in (5, 15) for a in range(N)])
    selected = np.array([h[::-1] if k % 3 == 0 else h for k, h in enumerate(sides) if k % gap != 3 % gap])
    c = swn.clean_edge_selection(VG, FG, selected)
    assert (c.selected == BAND).all()
    assert (c.bounding != 0).sum() == 2 * N and c.report["interior_endpoints"] > 0


@pytest.mark.parametrize("seed", [1, 2, 3, 4, 5])
def test_noise_on_a_band_across_a_disk_is_removed(seed):
    # isolated flipped faces on both sides of the band's border (the faces at the border of the mesh included)
    # come back exactly; every face flipped with probability 0.08: the wrong faces drop at least fourfold
    # (measured 68 -> 7, 56 -> 4, 67 -> 14, 72 -> 6, 67 -> 0)
    ring = [set(g for v in t for g in np.flatnonzero((FG == v).any(axis=1))) for t in FG]
    chosen, taken = [], set()
    for f in np.random.RandomState(seed).permutation(len(FG)):
        if len(chosen) < 20 and not ring[f] & taken and len(set(BAND[list(ring[f])])) == 1:
            chosen.append(f)
            taken |= ring[f]
    noisy = BAND.copy()
    noisy[chosen] ^= True
    assert (swn.clean_face_selection(VG, FG, noisy).selected == BAND).all()
    noisy = BAND ^ (np.random.RandomState(seed).random_sample(len(FG)) < 0.08)
    before = np.count_nonzero(noisy != BAND)
    c = swn.clean_face_selection(VG, FG, noisy)
    after = np.count_nonzero(c.selected != BAND)
    assert before > 40 and 4 * after < before, (before, after)
    # the bounding chain: the boundary of the cleaned faces inside the mesh (not along its border)
    interior = edge_values(c.edges, boundary_of(FG, np.ones(len(FG), bool))) == 0
    assert (c.bounding == edge_values(c.edges, boundary_of(FG, c.selected)) * interior).all()


def test_bad_selections_are_refused():
    with pytest.raises(ValueError, match=r"selection: a boolean mask needs one value per face \(800\), not shape \(3,\)"):
        swn.clean_face_selection(VG, FG, np.ones(3, bool))
    with pytest.raises(ValueError, match=r"selection: face index 800 is out of range \(800 faces\)"):
        swn.clean_face_selection(VG, FG, [800])
    with pytest.raises(ValueError, match=r"selection: 800 integers, all 0 or 1, look like a mask of the faces"):
        swn.clean_face_selection(VG, FG, np.zeros(len(FG), np.int8))
    with pytest.raises(TypeError, match="selection must be a boolean mask of the faces or an array of face indices"):
        swn.clean_face_selection(VG, FG, [0.5])
    with pytest.raises(ValueError, match=r"selection\[1\]: vertices 0 and 23 are not joined by an edge of the mesh"):
        swn.clean_edge_selection(VG, FG, [[0, 1], [0, 23]])
    with pytest.raises(ValueError, match=r"selection\[0\]: vertex index 441 is out of range \(441 vertices\)"):
        swn.clean_edge_selection(VG, FG, [[441, 0]])
    with pytest.raises(ValueError, match=r"selection: a boolean mask needs one value per edge \(1240"):
        swn.clean_edge_selection(VG, FG, np.ones(5, bool))
    with pytest.raises(TypeError, match="selection must be edges as vertex pairs"):
        swn.clean_edge_selection(VG, FG, [0, 1, 2])
    with pytest.raises(ValueError, match="epsilon must be positive"):
        swn.clean_face_selection(VG, FG, np.zeros(len(FG), bool), epsilon=0)
    with pytest.raises(ValueError, match="face 0 has 4 vertices"):
        swn.clean_face_selection(VG, [[0, 1, 22, 21]], [0])
