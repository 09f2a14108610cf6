# Curves off the mesh: 3D polylines (polylines_to_chain()) and stamped 2D drawings (stamp_polylines()) are
# put on the edges of a cut mesh whose faces name the input face they are pieces of; known areas inside.
import numpy as np
import pytest

import swn
from conftest import DATA, grid_disk, torus

# A parallelogram with its corners on vertices of grid_disk(10), its sides across the edges (inside a face a
# curve is the chord between the points where it crosses the face's border: corners inside faces are cut);
# area |(0.5, 0.1) x (0.1, 0.5)| = 0.24, counter-clockwise seen from +z
SQUARE = [[0.2, 0.2], [0.7, 0.3], [0.8, 0.8], [0.3, 0.7], [0.2, 0.2]]
AREA = 0.24
TOP_DOWN = [[0, 0, 1], [1, 0, 0], [0, 1, 0], [0, 0, -1]]                             # (x, y) -> (x, y, 0)


def areas(V, F):
    return 0.5 * np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1)


def check_pieces(c, V, F):
    """the faces of the cut mesh tile the input faces they name; the input's faces come first"""
    assert c.face_origin.shape == (len(c.F),) and c.face_origin.dtype == np.int64
    assert (c.face_origin[:len(F)] == np.arange(len(F))).all() and c.face_origin.max() < len(F)
    assert np.allclose(np.bincount(c.face_origin, areas(c.V, c.F), len(F)), areas(V, F), rtol=1e-12, atol=1e-15)
    added = c.info["cut_vertices"] + c.info["refinement_vertices"]
    assert added > 0 and len(c.V) == len(V) + added


def inside_area(c, label):
    r = swn.winding_numbers(c.V, c.F, c.halfedges, c.multiplicities)
    assert set(np.unique(r.W).tolist()) == {0, label}
    return areas(c.V, c.F)[r.W == label].sum()


def test_stamped_square_in_a_given_frame_has_its_area():
    V, F = grid_disk(10)
    c = swn.stamp_polylines(V, F, [SQUARE], frame=TOP_DOWN)
    check_pieces(c, V, F)
    assert np.allclose(c.info["frame"], TOP_DOWN)
    assert inside_area(c, 1) == pytest.approx(AREA, abs=1e-12)
    # the same parallelogram moved by 0.05 along x (its corners on edges) as a closed 3D polyline above the plane
    p = swn.polylines_to_chain(V, F, [np.column_stack([np.array(SQUARE) + [0.05, 0], np.full(5, 0.05)])])
    check_pieces(p, V, F)
    assert p.info["points"] == 5 and p.info["points_off_surface"] == 0 and p.info["failed_walks"] == 0
    assert p.info["pieces"] == [[[0, 1, 2, 3, 0]]]
    assert inside_area(p, 1) == pytest.approx(AREA, abs=1e-12)


def test_pieces_along_the_border_are_dropped_and_counted():
    V, F = grid_disk(4)
    # along the bottom border only: nothing is left, and the error says why
    with pytest.raises(ValueError, match="along the border"):
        swn.polylines_to_chain(V, F, [np.array([[0.0, 0, 0], [0.5, 0, 0], [1.0, 0, 0]])])
    # from the border across the grid and back along the border: the border piece is dropped and counted
    stroke = np.array([[0.5, 0, 0], [0.5, 0.5, 0], [1.0, 0.5, 0], [1.0, 0.0, 0], [0.75, 0.0, 0]])
    p = swn.polylines_to_chain(V, F, [stroke])
    assert p.info["border_pieces"] == 1 and p.info["curves"] == 1
    q = swn.polylines_to_chain(V, F, [stroke[:3]])   # the same stroke without its border piece
    assert q.info["border_pieces"] == 0
    assert sorted(map(tuple, p.halfedges.tolist())) == sorted(map(tuple, q.halfedges.tolist()))


def test_stamped_svg_in_the_fitted_frame(tmp_path):
    V, F = grid_disk(10)
    # SQUARE in SVG coordinates (y downwards), 6 x 6 units: looking down -z, SVG x is +x and SVG y is -y, and
    # fill=0.6 of the mesh's extent makes a unit 0.1 and puts the corners on SQUARE's
    svg = tmp_path / "square.svg"
    svg.write_text('<svg xmlns="http://www.w3.org/2000/svg"><path d="M 0 0 L 5 -1 L 6 -6 L 1 -5 Z"/></svg>\n')
    c = swn.stamp_polylines(V, F, svg, fill=0.6)
    check_pieces(c, V, F)
    origin, x_axis, y_axis, direction = c.info["frame"]
    assert np.allclose(x_axis, [0.1, 0, 0]) and np.allclose(y_axis, [0, -0.1, 0]) and np.allclose(direction, [0, 0, -1])
    assert inside_area(c, 1) == pytest.approx(AREA, abs=1e-9)
    # the drawing given as 2D polylines: the same cut and curves; reversed: the inside is one lower
    d = swn.stamp_polylines(V, F, [[[0, 0], [5, -1], [6, -6], [1, -5], [0, 0]]], fill=0.6)
    assert np.array_equal(d.V, c.V) and np.array_equal(d.F, c.F) and np.array_equal(d.halfedges, c.halfedges)
    assert inside_area(swn.stamp_polylines(V, F, [[[0, 0], [1, -5], [6, -6], [5, -1], [0, 0]]], fill=0.6), -1) == \
        pytest.approx(AREA, abs=1e-9)


def test_3d_polyline_loop_around_the_tube_is_nonbounding():
    nu, nv, R, r = 24, 12, 1.0, 0.4
    V, F, idx = torus(nu, nv, R, r)
    a = 2 * np.pi * 5.5 / nu                     # between two rings of vertices
    b = np.linspace(0, 2 * np.pi, 61)
    loop = np.column_stack([(R + r * np.cos(b)) * np.cos(a), (R + r * np.cos(b)) * np.sin(a), r * np.sin(b)])
    loop[-1] = loop[0]                           # closed
    c = swn.polylines_to_chain(V, F, [loop])
    check_pieces(c, V, F)
    assert c.info["points_off_surface"] == 0 and c.info["failed_walks"] == 0 and c.info["curves"] == 1
    w = swn.winding_numbers(c.V, c.F, c.halfedges, c.multiplicities)
    assert (w.W == 0).all() and (w.bounding == 0).all()
    assert np.count_nonzero(w.G) == len(c.halfedges) >= nv     # the loop itself, closed: G is the curve


def test_readers_give_the_input_face_of_every_face():
    V, F = swn.read_mesh(DATA / "swn-demo" / "torus.obj")
    c = swn.load(DATA / "swn-demo" / "torus.obj", DATA / "swn-demo" / "torus-phi.txt")
    check_pieces(c, V, F)
    assert (swn.read_curve(DATA / "swn-demo" / "torus-phi.txt", V, F).face_origin == c.face_origin).all()


def test_errors():
    V, F = grid_disk(6)
    with pytest.raises(ValueError, match="no curve on the surface"):
        swn.polylines_to_chain(V, F, [[[0.2, 0.2, 5], [0.6, 0.6, 5]]])
    # a closed stroke inside one face: it crosses no edge, and the error says so
    with pytest.raises(ValueError, match="no curve left on the surface: the polylines cross no edge of the mesh"):
        swn.polylines_to_chain(V, F, [np.array([[0.2, 0.1, 0], [0.6, 0.2, 0], [0.7, 0.5, 0], [0.2, 0.1, 0]]) / 6])
    with pytest.raises(ValueError, match=r"polylines\[0\] must be a \(k, 3\) array of points"):
        swn.polylines_to_chain(V, F, [[[0.2, 0.2], [0.6, 0.6]]])
    with pytest.raises(ValueError, match=r"polylines\[0\]: point 1 has a non-finite coordinate"):
        swn.polylines_to_chain(V, F, [[[0.2, 0.2, 0], [np.nan, 0.6, 0]]])
    with pytest.raises(ValueError, match="the stamped drawing misses the mesh"):
        swn.stamp_polylines(V, F, [SQUARE], frame=[[5, 5, 1], [1, 0, 0], [0, 1, 0], [0, 0, -1]])
    with pytest.raises(ValueError, match=r"frame must be four 3-vectors"):
        swn.stamp_polylines(V, F, [SQUARE], frame=TOP_DOWN[:3])
    with pytest.raises(ValueError, match="fill must be positive and finite"):
        swn.stamp_polylines(V, F, [SQUARE], fill=0)
    with pytest.raises(ValueError, match="projection_tolerance must be positive and finite"):
        swn.polylines_to_chain(V, F, [[[0.2, 0.2, 0], [0.6, 0.6, 0]]], projection_tolerance=-1)
    with pytest.raises(swn.InputError, match="no such file"):
        swn.stamp_polylines(V, F, "missing.svg")
