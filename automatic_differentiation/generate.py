# SPDX-License-Identifier: BSD-3-Clause
"""Regenerates custom_conditions/generated/ (every formulation x geometry case).

    python automatic_differentiation/generate.py [--output-dir DIR]

One translation unit per (formulation, dimension, slave nodes, master nodes) with the local RHS
and LHS kernels of the mortar contact conditions (frictionless and frictional), plus the header
declaring them.
The output depends only on the formulations and the sympy version (bit for bit).
"""

from __future__ import annotations

import argparse
import importlib.util
import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parent
sys.dont_write_bytecode = True  # keep the source tree clean
sys.path.insert(0, str(HERE))

import codegen  # noqa: E402

FORMULATIONS = [
    "ALM_frictionless_mortar_condition",
    "ALM_frictionless_components_mortar_condition",
    "penalty_frictionless_mortar_condition",
    "ALM_frictional_mortar_condition",
    "penalty_frictional_mortar_condition",
]
HEADER = "mortar_kernels.h"
DATA = "MortarKernelData"


def load(folder: str):
    spec = importlib.util.spec_from_file_location(f"{folder}.formulation", HERE / folder / "formulation.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def local_size(f, case: codegen.Case) -> int:
    size = case.dim * (case.slave + case.master)
    if f.MULTIPLIERS:
        size += case.slave * (case.dim if f.VECTOR_MULTIPLIER else 1)
    return size


def preamble(names: set, f, kinematics: bool) -> list:
    lines = []
    if kinematics or names & {"D", "M", "x1", "x2", "n1", "g", "s"}:
        lines.append("  const auto& kinematics = *data.kinematics;")
    sources = {
        "D": "kinematics.D",
        "M": "kinematics.M",
        "x1": "kinematics.slave_coordinates",
        "x2": "kinematics.master_coordinates",
        "n1": "kinematics.slave_normals",
        "g": "kinematics.weighted_gap",
        "lm": "data.vector_multiplier" if f.VECTOR_MULTIPLIER else "data.normal_pressure",
        "eps": "data.penalty",
        "df": "data.dynamic_factor",
        "mu": "data.friction_coefficient",
        "tau": "data.friction_threshold",
        "s": "data.weighted_slip",
    }
    for name, source in sources.items():
        if name in names:
            lines.append(f"  const auto& {name} = {source};")
    scalars = {"k": "data.scale_factor", "ct": "data.tangent_factor", "cslip": "data.slip_augmentation"}
    for name, source in scalars.items():
        if name in names:
            lines.append(f"  const double {name} = {source};")
    return lines


def branches(f) -> list:
    """(C++ guard of slave node {j}, functional) in if / else-if / else order: frictionless nodes
    are active or inactive, frictional ones slip, stick (both ACTIVE) or inactive."""
    if getattr(f, "FRICTIONAL", False):
        return [("data.active[{j}] && data.slip[{j}]", f.slip), ("data.active[{j}]", f.stick), (None, f.inactive)]
    return [("data.active[{j}]", f.active), (None, f.inactive)]


def node_branches(f, sym, case, emit) -> list:
    """One if / else chain per slave node: the node's contribution depends on its own flags only
    (never 2^n or 3^n cases)."""
    lines = []
    for j in range(case.slave):
        lines.append(f"  // slave node {j}")
        opened = False
        for guard, branch in branches(f):
            functional = branch(sym, j)
            body = emit(codegen.derive(sym, j, functional, f.MULTIPLIERS), j) if functional != 0 else []
            if guard is not None:
                lines.append(f"  {'} else if' if opened else 'if'} ({guard.format(j=j)}) {{")
                opened = True
            elif body:
                lines.append("  } else {")
            lines += body
        lines.append("  }")
    return lines


def translation_unit(folder: str, f, case: codegen.Case) -> str:
    sym = codegen.Symbols(case, f.VECTOR_MULTIPLIER)
    data_type = f"{DATA}<{case.dim}, {case.slave}, {case.master}>"
    size = local_size(f, case)

    rhs_body = node_branches(f, sym, case, lambda b, j: codegen.emit_rhs_branch(b, "    "))
    lhs_body = node_branches(f, sym, case, lambda b, j: codegen.emit_lhs_branch(b, j, "    "))
    uses_chain = any("ChainRule(kinematics" in line for line in lhs_body)

    out = [
        "// SPDX-License-Identifier: BSD-3-Clause",
        codegen.STAMP.format(source=f"automatic_differentiation/{folder}"),
        f"// {f.FUNCTION} mortar contact, {case.token}: local residual and its exact tangent.",
        f'#include "custom_conditions/generated/{HEADER}"',
        "",
        "namespace mc::generated {",
        "",
        f"void {f.FUNCTION}RHS(const {data_type}& data, Vector& rhs) {{",
        f"  assert(rhs.size() == {size});",
    ]
    out += preamble(codegen.used_names(rhs_body), f, False)
    out += rhs_body
    out += ["}", "", f"void {f.FUNCTION}LHS(const {data_type}& data, Matrix& lhs, Matrix* normal_sensitivity) {{"]
    out.append(f"  assert(lhs.rows() == {size} && lhs.cols() == {size});")
    out.append(f"  assert(!normal_sensitivity || (normal_sensitivity->rows() == {size} && "
               f"normal_sensitivity->cols() == {case.dim * case.slave}));")
    out += preamble(codegen.used_names(lhs_body), f, uses_chain)
    if uses_chain:
        out.append(f"  Eigen::Matrix<double, {size}, {case.slave}> cD;")
        out.append(f"  Eigen::Matrix<double, {size}, {case.master}> cM;")
        out.append(f"  Eigen::Matrix<double, {size}, 1> cG;")
        out.append(f"  Eigen::Matrix<double, {size}, {case.dim}> cN;")
        if getattr(f, "FRICTIONAL", False):
            out.append(f"  Eigen::Matrix<double, {size}, {case.dim}> cS;")
    out += lhs_body
    out += ["}", "", "}  // namespace mc::generated", ""]
    return "\n".join(out)


def header(modules) -> str:
    out = [
        "// SPDX-License-Identifier: BSD-3-Clause",
        codegen.STAMP.format(source="automatic_differentiation/codegen.py"),
        "// Local kernels of the mortar contact conditions, one overload per formulation and geometry case.",
        "// RHS: adds the pair's residual (external-force sign) to rhs; LHS: adds -d rhs/d dofs to lhs at",
        "// fixed slave normals and, given normal_sensitivity, -d rhs/d n (columns: slave node-major",
        "// normal components) to it. All expect zeroed, correctly sized arguments (DoF order: master u,",
        "// slave u, multipliers).",
        "#pragma once",
        "",
        "#include <cassert>",
        "#include <cmath>",
        "",
        '#include "custom_conditions/mortar_kernel_data.h"',
        "",
        "namespace mc::generated {",
        "",
    ]
    for _, f in modules:
        for case in codegen.CASES:
            data_type = f"{DATA}<{case.dim}, {case.slave}, {case.master}>"
            out.append(f"void {f.FUNCTION}RHS(const {data_type}& data, Vector& rhs);")
            out.append(f"void {f.FUNCTION}LHS(const {data_type}& data, Matrix& lhs, "
                       "Matrix* normal_sensitivity = nullptr);")
        out.append("")
    out += ["}  // namespace mc::generated", ""]
    return "\n".join(out)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--output-dir", type=pathlib.Path, default=HERE.parent / "custom_conditions" / "generated")
    args = parser.parse_args(argv)
    args.output_dir.mkdir(parents=True, exist_ok=True)
    modules = [(folder, load(folder)) for folder in FORMULATIONS]
    files = {HEADER: header(modules)}
    for folder, f in modules:
        for case in codegen.CASES:
            files[f"{f.FAMILY}_{case.file_stem}.cpp"] = translation_unit(folder, f, case)
    for name, text in files.items():
        (args.output_dir / name).write_text(text, encoding="utf-8", newline="\n")
        print(f"wrote {args.output_dir / name} ({text.count(chr(10))} lines)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
