# The example runs, and the package installs with pip into a fresh virtual environment without network:
# `pip install --no-build-isolation --no-index ./python`, with Debian's setuptools as the build backend,
# numpy from the system's site packages. ctest gives the build directory (SWN_CMAKE_BUILD_DIR), which
# setup.py then builds and installs from instead of compiling the module a second time.
import os
import subprocess
import sys

import pytest

from conftest import DATA, REPO

EXAMPLE = REPO / "python" / "examples" / "winding_numbers_demo.py"


def test_example_runs():
    p = subprocess.run([sys.executable, str(EXAMPLE), str(DATA / "swn-demo")], capture_output=True, text=True)
    assert p.returncode == 0, p.stdout + p.stderr
    assert "G on 78 edges" in p.stdout


def test_pip_install_into_a_venv(tmp_path):
    build = os.environ.get("SWN_CMAKE_BUILD_DIR")
    if not build:
        pytest.skip("SWN_CMAKE_BUILD_DIR is not set (ctest sets it)")
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)], check=True)
    python = str(venv / "bin" / "python")
    env = dict(os.environ, SWN_CMAKE_BUILD_DIR=build, PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1")
    env.pop("PYTHONPATH", None)   # the build tree's swn must not be the one imported
    p = subprocess.run([python, "-m", "pip", "install", "--no-build-isolation", "--no-index", str(REPO / "python")],
                       env=env, capture_output=True, text=True)
    assert p.returncode == 0, p.stdout + p.stderr
    where = subprocess.run([python, "-c", "import swn; print(swn.__file__)"], env=env, cwd=tmp_path,
                           capture_output=True, text=True, check=True).stdout.strip()
    assert where.startswith(str(venv))
    p = subprocess.run([python, str(EXAMPLE), str(DATA / "swn-demo")], env=env, cwd=tmp_path, capture_output=True,
                       text=True)
    assert p.returncode == 0, p.stdout + p.stderr


def test_meshio_example(tmp_path):
    meshio = pytest.importorskip("meshio")   # Debian's python3-meshio (scripts/install-deps)
    import numpy as np
    from conftest import quad_torus, torus_rectangle_loop
    nu, nv = 16, 8
    V, Q, idx = quad_torus(nu, nv)
    loop = torus_rectangle_loop(idx, 3, 7, 2, 5)
    segments = np.column_stack([loop[:-1], loop[1:]])
    source, out = tmp_path / "torus.vtu", tmp_path / "labels.vtu"
    meshio.write(source, meshio.Mesh(V, [("quad", Q), ("line", segments)]))
    p = subprocess.run([sys.executable, str(REPO / "python" / "examples" / "meshio_labels.py"), str(source), str(out)],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stdout + p.stderr
    assert "solved as a polygon soup (face 0 has 4 vertices)" in p.stdout
    labels = meshio.read(out).cell_data["swn_W"]
    inside = np.array([3 <= q // nv < 7 and 2 <= q % nv < 5 for q in range(len(Q))])
    assert (labels[0] == inside).all() and (labels[1] == 0).all()
