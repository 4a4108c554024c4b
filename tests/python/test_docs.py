"""Issue 15, item 3: the documentation site (docs/, Sphinx + MyST) builds without a warning, its
parameter reference lists every key the owners declare, and its API pages carry the docstrings
of the compiled classes."""
from __future__ import annotations

import json
import os
import re
import subprocess
import sys

import pytest

import mortarcontact as mc
from mortarcontact.solvers.convergence_history import ConvergenceHistory
from mortarcontact.solvers.solver_settings import STRUCTURAL_DEFAULTS

pytest.importorskip("sphinx", reason="sphinx is not installed (make deps installs it)")
pytest.importorskip("myst_parser", reason="myst-parser is not installed (make deps installs it)")

DOCS = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "docs"))


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    out = tmp_path_factory.mktemp("docs")
    build = subprocess.run([sys.executable, "-m", "sphinx", "-E", "-W", "--keep-going", "-q", "-b", "html", DOCS,
                            str(out)], capture_output=True, text=True, timeout=600)
    assert build.returncode == 0 and not build.stderr.strip(), build.stdout + build.stderr
    return out


def _text(site, page: str) -> str:
    return re.sub(r"\s+", " ", re.sub(r"<[^>]+>", " ", (site / page).read_text()))


def test_docs_build_without_warnings_and_have_the_pages(site):
    for page in ("index.html", "overview.html", "tutorials.html", "DESIGN.html", "parameters.html", "api.html"):
        assert (site / page).is_file(), page
    assert "Data flow of a run" in _text(site, "DESIGN.html")
    assert "mc.Analysis(model,parameters)" in _text(site, "tutorials.html").replace(" ", "")


def test_parameter_reference_lists_every_declared_key_with_its_default(site):
    text = _text(site, "parameters.html")
    for owner in (json.loads(mc.Parameters(STRUCTURAL_DEFAULTS).WriteJsonString()),
                  json.loads(ConvergenceHistory.GetDefaultParameters().WriteJsonString()),
                  json.loads(mc._core.ContactSearchProcess.GetDefaultParameters().WriteJsonString())):
        for key in owner:
            assert key in text, key
    # a default read from its C++ owner, and the audit's verdict beside a key
    assert re.search(r"search_factor 3\.5 acts", text)
    assert re.search(r"parallel_type OpenMP rejects: MPI runs are not implemented", text)


def test_api_pages_carry_the_compiled_docstrings(site):
    text = _text(site, "api.html").replace(" ", "")
    for fragment in ("CreateNewNodes", "Createsmanynodesinonecall", "CreateNewProperties", "import_meshio",
                     "classmortarcontact.Analysis", "Viewsandcopies"):
        assert fragment in text, fragment
