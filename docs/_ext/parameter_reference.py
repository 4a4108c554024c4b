# SPDX-License-Identifier: BSD-3-Clause
"""The parameter reference: every settings block of a case, its keys and their
defaults, read from the classes that own them (their ``GetDefaultParameters`` and the Python
defaults tables, docs/DESIGN.md section 3) when the documentation is built, so the page cannot
drift from the code. Where tests/python/settings_audit.tsv records what a key does in
mortarcontact (acts, warns, rejects, out of scope), that is shown beside it. The Markdown is
put in place of the marker of docs/parameters.md when Sphinx reads that page."""
from __future__ import annotations

import csv
import json
import os

AUDIT = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "python", "settings_audit.tsv")
#: process python_module -> its block name in settings_audit.tsv
AUDIT_BLOCK = {"alm_contact_process": "contact_process", "penalty_contact_process": "contact_process"}
DEFAULT_WIDTH = 60
#: where the generated Markdown goes in docs/parameters.md
MARKER = "<!-- parameter-reference -->"


def owners() -> list[tuple[str, str, dict]]:
    """(block path, owner, defaults as a dict) for every settings block, in case-file order."""
    from mortarcontact import _core
    from mortarcontact.contact_strategies import CRITERIA_SETTINGS
    from mortarcontact.process_factory import PROCESS_REGISTRY
    from mortarcontact.project_parameters import PROBLEM_DATA_DEFAULTS, RESTART_OPTIONS_DEFAULTS
    from mortarcontact.solvers.contact_mechanical_solver import CONTACT_SETTINGS
    from mortarcontact.solvers.convergence_history import ConvergenceHistory
    from mortarcontact.solvers.solver_settings import STRUCTURAL_DEFAULTS

    def parsed(parameters) -> dict:
        if isinstance(parameters, str):
            parameters = _core.Parameters(parameters)
        return json.loads(parameters.WriteJsonString())

    blocks = [
        ("problem_data", "project_parameters.PROBLEM_DATA_DEFAULTS", parsed(PROBLEM_DATA_DEFAULTS)),
        ("solver_settings", "solvers/solver_settings.py STRUCTURAL_DEFAULTS", parsed(STRUCTURAL_DEFAULTS)),
        ("solver_settings.convergence_history", "ConvergenceHistory.GetDefaultParameters()",
         parsed(ConvergenceHistory.GetDefaultParameters())),
        ("solver_settings.contact_settings", "ContactMechanicalSolver CONTACT_SETTINGS", parsed(CONTACT_SETTINGS)),
        ("solver_settings.contact_settings", "convergence_criteria_factory CRITERIA_SETTINGS",
         parsed(CRITERIA_SETTINGS)),
        ("solver_settings.contact_settings", "BlockContactCriteria::GetContactSettingsDefaults()",
         parsed(_core.BlockContactCriteria.GetContactSettingsDefaults())),
        ("solver_settings.contact_settings", "ResidualBasedNewtonRaphsonContactStrategy::GetDefaultParameters()",
         parsed(_core.ResidualBasedNewtonRaphsonContactStrategy.GetDefaultParameters())),
        ("solver_settings.contact_settings", "BaseMortarConvergenceCriteria::GetDefaultParameters()",
         parsed(_core.BaseMortarConvergenceCriteria.GetDefaultParameters())),
    ]
    for (module, python_module), cls in sorted(PROCESS_REGISTRY.items(), key=lambda item: item[0][1]):
        defaults = cls.GetDefaultParameters()
        if defaults is not None:
            blocks.append((f"{python_module} ({module}).Parameters", f"{cls.__name__}.GetDefaultParameters()",
                           parsed(defaults)))
    blocks.append(("restart_options (legacy top-level block)", "project_parameters.RESTART_OPTIONS_DEFAULTS",
                   parsed(RESTART_OPTIONS_DEFAULTS)))
    return blocks


def audit() -> dict:
    """(block, key) -> (status, evidence) of settings_audit.tsv."""
    with open(AUDIT) as f:
        rows = [row for row in csv.reader((line for line in f if not line.startswith("#")), delimiter="\t") if row]
    return {(row[0], row[1]): (row[2], row[4] if len(row) > 4 else "") for row in rows if len(row) >= 3}


def flatten(defaults: dict, prefix: str = "") -> list[tuple[str, object]]:
    """(dotted key, default) of every key; sub-blocks are listed key by key after their own row,
    except the per-interface slots ("0" ... "9"), which are one value."""
    rows = []
    for key, value in defaults.items():
        path = f"{prefix}{key}"
        if isinstance(value, dict) and value and not all(k.isdigit() for k in value):
            rows.append((path, "{...}"))
            rows += flatten(value, path + ".")
        else:
            rows.append((path, value))
    return rows


def _audit_block(block: str) -> str:
    """The block's name in settings_audit.tsv: the process's python_module, or the block path."""
    head = block.split(" ")[0]
    return "assign_process" if head.startswith("assign_") else AUDIT_BLOCK.get(head, head)


def _code(text: str) -> str:
    """Inline code in a Markdown table cell."""
    text = text.replace("`", "'").replace("|", "\\|")
    return f"`{text}`" if text else "`\"\"`"


def render() -> str:
    """The reference as Markdown: one section per block, one table per owner."""
    statuses = audit()
    lines = []
    seen_blocks = set()
    for block, owner, defaults in owners():
        if block not in seen_blocks:
            lines += [f"## `{block}`", ""]
            seen_blocks.add(block)
        audit_block = _audit_block(block)
        whole = statuses.get((audit_block, "*"))
        lines += [f"Declared by `{owner}`." + (f" The whole block {whole[0]}: {whole[1]}." if whole else ""), "",
                  "| key | default | in mortarcontact |", "|---|---|---|"]
        for key, value in flatten(defaults):
            shown = value if isinstance(value, str) else json.dumps(value)
            if len(shown) > DEFAULT_WIDTH:
                shown = shown[:DEFAULT_WIDTH - 3] + "..."
            subblock, _, leaf = key.rpartition(".")
            status, evidence = statuses.get((audit_block + (f".{subblock}" if subblock else ""), leaf), ("", ""))
            note = f"{status}: {evidence}" if evidence else status
            note = note.replace("|", "\\|").replace("`", "'").replace("\n", " ")
            lines.append(f"| {_code(key)} | {_code(shown)} | {note} |")
        lines.append("")
    return "\n".join(lines)


def _insert(app, docname, source):
    """Fills the page holding the marker with the reference, before it is parsed."""
    if MARKER in source[0]:
        source[0] = source[0].replace(MARKER, render())


def setup(app):
    app.connect("source-read", _insert)
    return {"version": "1", "parallel_read_safe": True}
