# Meshes with known answers for the tests of the Python module, and the paths the tests need.
import os
import pathlib

import numpy as np
import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
DATA = pathlib.Path(os.environ.get("SWN_DATA_DIR", REPO / "data"))


def icosahedron():
    """The regular icosahedron, faces oriented outwards."""
    t = (1 + 5 ** 0.5) / 2
    V = np.array([[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t],
                  [0, -1, -t], [0, 1, -t], [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]], float)
    F = np.array([[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4],
                  [11, 10, 2], [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8],
                  [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1]])
    n = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    assert (np.einsum("ij,ij->i", n, V[F].mean(axis=1)) > 0).all()
    return V, F


def grid_disk(n):
    """The unit square as an (n+1) x (n+1) grid of vertices, vertex (i, j) = i + (n+1) j, two triangles per
    cell, oriented counter-clockwise seen from +z."""
    i, j = np.meshgrid(np.arange(n + 1), np.arange(n + 1), indexing="xy")
    V = np.column_stack([i.ravel() / n, j.ravel() / n, np.zeros((n + 1) ** 2)])
    idx = lambda a, b: a + (n + 1) * b
    F = []
    for b in range(n):
        for a in range(n):
            F += [[idx(a, b), idx(a + 1, b), idx(a + 1, b + 1)], [idx(a, b), idx(a + 1, b + 1), idx(a, b + 1)]]
    return V, np.array(F)


def grid_rectangle_loop(n, a0, a1, b0, b1):
    """The counter-clockwise loop around the cells [a0, a1) x [b0, b1) of grid_disk(n), as a closed vertex
    polyline, and the faces inside it."""
    idx = lambda a, b: a + (n + 1) * b
    loop = ([idx(a, b0) for a in range(a0, a1)] + [idx(a1, b) for b in range(b0, b1)] +
            [idx(a, b1) for a in range(a1, a0, -1)] + [idx(a0, b) for b in range(b1, b0 - 1, -1)])
    inside = [2 * (a + n * b) + k for b in range(b0, b1) for a in range(a0, a1) for k in range(2)]
    return loop, inside


def torus(nu, nv, R=1.0, r=0.4):
    """A torus of revolution, nu x nv quads split in two, vertex (i, j) = (i mod nu) nv + (j mod nv): i around
    the axis, j around the tube (a meridian is i = const)."""
    a = 2 * np.pi * np.arange(nu) / nu
    b = 2 * np.pi * np.arange(nv) / nv
    A, B = np.meshgrid(a, b, indexing="ij")
    V = np.column_stack([((R + r * np.cos(B)) * np.cos(A)).ravel(), ((R + r * np.cos(B)) * np.sin(A)).ravel(),
                         (r * np.sin(B)).ravel()])
    idx = lambda i, j: (i % nu) * nv + (j % nv)
    F = []
    for i in range(nu):
        for j in range(nv):
            F += [[idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)], [idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)]]
    return V, np.array(F), idx


def torus_rectangle_loop(idx, i0, i1, j0, j1):
    """The closed loop around the quads [i0, i1) x [j0, j1) of torus(), counter-clockwise seen from outside
    the torus, as a vertex polyline."""
    return ([idx(i, j0) for i in range(i0, i1)] + [idx(i1, j) for j in range(j0, j1)] +
            [idx(i, j1) for i in range(i1, i0, -1)] + [idx(i0, j) for j in range(j1, j0 - 1, -1)])


def edge_values(edges, halfedges, multiplicities=None):
    """The chain of the halfedges on the edges (a, b) of `edges`: +m from a to b, -m from b to a."""
    where = {(int(a), int(b)): e for e, (a, b) in enumerate(edges)}
    chain = np.zeros(len(edges), int)
    m = np.ones(len(halfedges), int) if multiplicities is None else multiplicities
    for (s, t), k in zip(halfedges, m):
        if (s, t) in where:
            chain[where[(s, t)]] += k
        else:
            chain[where[(t, s)]] -= k
    return chain


def polyline_halfedges(polyline):
    return np.column_stack([polyline[:-1], polyline[1:]])


@pytest.fixture(scope="session")
def swn_tool():
    """The swn tool of the same build (ctest sets SWN_TOOL), or skip."""
    tool = os.environ.get("SWN_TOOL")
    if not tool or not os.path.exists(tool):
        pytest.skip("the swn tool is not available (SWN_TOOL)")
    return tool


def quad_torus(nu, nv, R=1.0, r=0.4):
    """torus() with its quads unsplit: quad q = i nv + j is (idx(i, j), idx(i+1, j), idx(i+1, j+1), idx(i, j+1)),
    made of the triangles 2q and 2q + 1 of torus()."""
    V, F, idx = torus(nu, nv, R, r)
    Q = np.array([[idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)] for i in range(nu) for j in range(nv)])
    return V, Q, idx


def mobius_strip(n, R=1.0, w=0.3):
    """A Möbius strip of n quads: vertices t_i = i and b_i = n + i across the strip at angle 2 pi i / n, quad i =
    (t_i, b_i, b_{i+1}, t_{i+1}); the last quad is glued to the first with a half twist (t_n = b_0, b_n = t_0),
    so that quads n - 1 and 0 traverse their common edge the same way."""
    a = 2 * np.pi * np.arange(n) / n
    across = np.column_stack([np.cos(a / 2) * np.cos(a), np.cos(a / 2) * np.sin(a), np.sin(a / 2)])
    centre = np.column_stack([R * np.cos(a), R * np.sin(a), np.zeros(n)])
    V = np.vstack([centre + w * across, centre - w * across])
    t = lambda i: i if i < n else n + (i - n)     # t_n = b_0
    b = lambda i: n + i if i < n else i - n       # b_n = t_0
    Q = np.array([[t(i), b(i), b(i + 1), t(i + 1)] for i in range(n)])
    return V, Q
