# python/README.md stays true: its ```python snippets run (from the repository's root, as written) and
# their asserts hold; every public name of the package and every setting of its functions is documented.
import inspect
import os
import re
import subprocess
import sys

import pytest

import swn
from conftest import DATA, REPO

README = REPO / "python" / "README.md"
SNIPPETS = re.findall(r"```python\n(.*?)```", README.read_text(), re.S)


@pytest.mark.parametrize("k", range(len(SNIPPETS)))
def test_snippet_runs(k, tmp_path):
    script = tmp_path / f"snippet{k}.py"
    prologue = "import warnings, swn\nwarnings.simplefilter('error', swn.MeshWarning)\n"
    script.write_text(prologue + SNIPPETS[k].replace('"data/', f'"{DATA}/'))
    package = os.path.dirname(os.path.dirname(os.path.abspath(swn.__file__)))   # the swn imported here
    p = subprocess.run([sys.executable, str(script)], cwd=tmp_path, capture_output=True, text=True,
                       env=dict(os.environ, PYTHONPATH=package))
    assert p.returncode == 0, SNIPPETS[k] + "\n" + p.stdout + p.stderr


def test_snippets_are_there():
    assert len(SNIPPETS) >= 2 and all("assert" in s for s in SNIPPETS)


def test_every_name_and_setting_is_documented():
    text = README.read_text()
    for name in swn.__all__:
        assert f"`{name}" in text or f"swn.{name}" in text, name
    functions = [swn.winding_numbers, swn.Solver, swn.Solver.solve, swn.read_mesh, swn.read_curve, swn.load]
    functions += [swn.polylines_to_chain, swn.stamp_polylines, swn.clean_face_selection, swn.clean_edge_selection]
    for f in functions:
        for p in inspect.signature(f).parameters.values():
            if p.kind == p.KEYWORD_ONLY:
                assert f"`{p.name}`" in text, f"{f.__qualname__}: {p.name}"
    for field in swn.WindingNumbers.__dataclass_fields__:
        assert f"| `{field}` |" in text, field
