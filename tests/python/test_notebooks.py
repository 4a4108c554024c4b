"""Issue 15, item 3: the tutorial notebooks (examples/notebooks, jupytext percent scripts) run
cell by cell in a Jupyter kernel (jupytext + nbclient), as a user opening them would run them.
Each ends with assertions against its closed-form answer, so a notebook that runs is one that
is right."""
from __future__ import annotations

import os
import shutil

import pytest

jupytext = pytest.importorskip("jupytext", reason="jupytext is not installed (make deps installs it)")
nbclient = pytest.importorskip("nbclient", reason="nbclient is not installed (make deps installs it)")

NOTEBOOKS = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "examples", "notebooks"))


@pytest.mark.parametrize("name", sorted(n for n in os.listdir(NOTEBOOKS) if n.endswith(".py")))
def test_notebook_executes(name):
    if name == "hertz_2d.py":
        pytest.importorskip("gmsh", reason="gmsh is not installed")
    if name == "cpp_condition.py" and shutil.which("cmake") is None:
        pytest.skip("cmake is not available")
    notebook = jupytext.read(os.path.join(NOTEBOOKS, name))
    assert any(cell.cell_type == "markdown" for cell in notebook.cells)
    client = nbclient.NotebookClient(notebook, timeout=300, kernel_name="python3",
                                     resources={"metadata": {"path": NOTEBOOKS}})
    client.execute()
    outputs = [output for cell in notebook.cells if cell.cell_type == "code" for output in cell.get("outputs", [])]
    assert not [o for o in outputs if o.get("output_type") == "error"]
