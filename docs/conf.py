# SPDX-License-Identifier: BSD-3-Clause
"""Sphinx configuration of the documentation site (``make docs``). Sphinx, not MkDocs: autodoc
imports the built package, so the API pages show the docstrings and signatures of the compiled
pybind11 classes as Python sees them (MkDocs' mkdocstrings reads source files, which the C++
bindings are not); MyST lets the Markdown files of the repository (README.md, docs/DESIGN.md)
be pages as they are."""
from __future__ import annotations

import os
import re
import sys

import mortarcontact

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "_ext"))

project = "mortarcontact"
author = "the mortarcontact developers"
copyright = "the mortarcontact developers, BSD-3-Clause"  # noqa: A001 (Sphinx's name)
release = mortarcontact.__version__
extensions = ["myst_parser", "sphinx.ext.autodoc", "sphinx.ext.mathjax", "parameter_reference"]
myst_enable_extensions = ["dollarmath"]
myst_heading_anchors = 3
source_suffix = {".md": "markdown"}
exclude_patterns = ["_build"]
autodoc_member_order = "bysource"
html_theme = "alabaster"
html_title = f"mortarcontact {release}"
html_static_path = []


def _arguments_as_fields(app, what, name, obj, options, lines):
    """The docstrings list arguments as ``name: what it is`` with indented continuation lines;
    as reStructuredText field lists (``:name: ...``) they render as such instead of as broken
    definition lists."""
    for i, line in enumerate(lines):
        match = re.match(r"([A-Za-z_]\w*): (.*)", line)
        if match:
            lines[i] = f":{match.group(1)}: {match.group(2)}"


def setup(app):
    app.connect("autodoc-process-docstring", _arguments_as_fields)
