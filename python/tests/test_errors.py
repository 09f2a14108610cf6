# Errors become Python exceptions with the messages of the library and of the tool's readers: ValueError
# for bad input (InputError, a ValueError with the file and line, for files), TypeError for arrays of the
# wrong kind; and the tool prints the same messages for the same files.
import subprocess

import numpy as np
import pytest

import swn
from conftest import DATA, grid_disk, icosahedron

TETRA_V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
TETRA_F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])


# surfaces that are not oriented 2-manifold triangle meshes: Solver refuses them, winding_numbers() solves
# them as polygon soups (test_soup.py)
@pytest.mark.parametrize("V, F, message", [
    (TETRA_V, np.array([[0, 2, 1, 3]]), "face 0 has 4 vertices: only triangle meshes are supported"),
    (TETRA_V, [[0, 2, 1], [0, 1, 3], [0, 3, 2, 1], [1, 2, 3]], "face 2 has 4 vertices: only triangle meshes are supported"),
    (TETRA_V, np.array([[0, 2, 1], [0, 2, 3]]), "faces 0 and 1 both traverse edge (0, 2) in the same direction"),
    (np.vstack([TETRA_V, [[1, 1, 1]]]), np.vstack([TETRA_F, [[0, 2, 4]]]),
     "non-manifold edge (0, 2): shared by more than two faces"),
    (TETRA_V, np.array([[0, 1, 2], [0, 1, 2]]), "both traverse edge (0, 1) in the same direction"),
])
def test_solver_needs_an_oriented_manifold_triangle_mesh(V, F, message):
    with pytest.raises(ValueError) as e:
        swn.Solver(V, F)
    assert message in str(e.value)


@pytest.mark.parametrize("V, F, message", [
    (TETRA_V, [[0, 2, 1], [0, 1]], "face 1 has 2 vertices (a face needs at least 3)"),
    (TETRA_V, np.array([[0, 1]]), "face 0 has 2 vertices (a face needs at least 3)"),
    (TETRA_V, np.array([[0, 2, 9]]), "face 0 refers to vertex 9 (0-based) but there are only 4 vertices"),
    (TETRA_V, np.array([[0, 2, -1]]), "face 0 refers to vertex -1 (a negative index)"),
    (TETRA_V, np.array([[0, 2, 2]]), "face 0 has a repeated vertex (0, 2, 2)"),
    (np.where(np.arange(12).reshape(4, 3) == 4, np.nan, TETRA_V), TETRA_F, "vertex 1 has a non-finite coordinate (NaN)"),
    (TETRA_V, np.zeros((0, 3), int), "the mesh has no faces"),
    (TETRA_V, [], "the mesh has no faces"),
    (TETRA_V, [[0, 2, 1, 3], [0, 2, 9, 1]], "face 1 refers to vertex 9 (0-based) but there are only 4 vertices"),
    (np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0]], float), np.array([[0, 1, 3], [1, 2, 3], [0, 2, 1]]),
     "face 2 has zero area (degenerate triangle)"),
    (TETRA_V[:, :2], TETRA_F, "V must be an (n, 3) array of vertex coordinates, not of shape (4, 2)"),
])
def test_invalid_meshes_raise_value_error(V, F, message):
    with pytest.raises(ValueError) as e:
        swn.Solver(V, F)
    assert message in str(e.value)
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(")", r"\)")):
        swn.winding_numbers(V, F, [[0, 1]])


def test_arrays_of_the_wrong_kind_raise_type_error():
    with pytest.raises(TypeError, match="F must hold integer vertex indices"):
        swn.Solver(TETRA_V, TETRA_F.astype(float))
    with pytest.raises(TypeError, match="V must hold real coordinates"):
        swn.Solver(TETRA_V.astype(str), TETRA_F)
    with pytest.raises(TypeError, match=r"curves\[0\] must hold integers"):
        swn.winding_numbers(TETRA_V, TETRA_F, [[0.0, 1.0]])


def test_bad_curves():
    V, F = icosahedron()
    solver = swn.Solver(V, F)
    cases = [
        ([[0, 11, 5], [0, 3]], "curves[1]: vertices 0 and 3 are not joined by an edge of the mesh"),
        ([[0, 12]], "curves[0]: vertex index 12 is out of range (12 vertices)"),
        (np.array([[0, 11], [5, 5]]), "curves[1]: vertices 5 and 5 are not joined by an edge of the mesh"),
        (np.array([[0, 11, 5]]), "curves given as an array must be halfedges of shape (k, 2), not of shape (1, 3); give vertex polylines as a list of sequences"),
        ([0, 11, 5], "curves[0] must be a sequence of vertex indices (a polyline), not of shape ()"),
        ([[0, 11, 5]], "epsilon must be positive and finite, not -1"),
    ]
    for curves, message in cases:
        with pytest.raises(ValueError) as e:
            solver.solve(curves, epsilon=-1 if "epsilon" in message else 0.01)
        assert str(e.value) == message
    with pytest.raises(ValueError, match=r"multiplicities must have one value per curve \(2\)"):
        solver.solve([[0, 11], [11, 5]], [1, 2, 3])
    # the solver is still usable after errors
    assert solver.solve([[0, 11, 5, 0]]).W.max() == 1


def test_curve_on_the_border_is_invalid_input():
    V, F = grid_disk(4)
    with pytest.raises(ValueError) as e:
        swn.winding_numbers(V, F, [[0, 1, 2]])
    assert str(e.value).startswith("edge ") and "is on the border of the mesh and carries the chain value" in str(e.value)


def write(path, text):
    path.write_text(text)
    return str(path)


def tool_error(tool, *args):
    """The error line the swn tool prints for these arguments, without its 'swn: error: ' prefix."""
    p = subprocess.run([tool, *args, "--quiet"], capture_output=True, text=True)
    assert p.returncode == 2, p.stderr
    return p.stderr.strip().removeprefix("swn: error: ")


def test_reader_errors_are_input_errors(tmp_path):
    with pytest.raises(swn.InputError) as e:
        swn.read_mesh(tmp_path / "missing.obj")
    assert str(e.value) == f"{tmp_path / 'missing.obj'}: no such file"
    assert e.value.line is None and e.value.reason == "no such file" and isinstance(e.value, ValueError)

    bad = write(tmp_path / "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n")
    with pytest.raises(swn.InputError) as e:
        swn.read_mesh(bad)
    assert e.value.file == bad and e.value.line == 4 and str(e.value).startswith(bad + ":4: ")

    V, F = swn.read_mesh(DATA / "swn-demo" / "torus.obj")
    curve = write(tmp_path / "curve.txt", "# swn polylines\n0 1\n0 2 7\n")
    with pytest.raises(swn.InputError) as e:
        swn.read_curve(curve, V, F)
    assert e.value.line == 3 and "does not lie in a single face" in e.value.reason
    with pytest.raises(swn.InputError) as e:
        swn.load(DATA / "swn-demo" / "torus.obj")
    assert e.value.reason == "no curve: give a curve file, or `l` lines in an OBJ mesh"


def test_reader_messages_are_the_tools(tmp_path, swn_tool):
    torus = str(DATA / "swn-demo" / "torus.obj")
    V, F = swn.read_mesh(torus)
    bad_mesh = write(tmp_path / "bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 nan\n3 0 1 2\n")
    with pytest.raises(swn.InputError) as e:
        swn.read_mesh(bad_mesh)
    assert str(e.value) == tool_error(swn_tool, bad_mesh, "--curve", bad_mesh)
    for text in ["#offset 0\nv 0\nv 7\nl 0 1\n", "# swn halfedges\nh 0 1 2000\n", "#offset 0\ne 99999 0.5\n"]:
        curve = write(tmp_path / "curve.txt", text)
        with pytest.raises(swn.InputError) as e:
            swn.read_curve(curve, V, F)
        assert str(e.value) == tool_error(swn_tool, torus, "--curve", curve)
