#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 13, item 2: the Hertz cases with MPC contact against ALM and Hertz, ours and Kratos 10.4's, on
the same files (mortarcontact.cases.hertz, ``write_case(..., mpc=True)`` for MPC).

    python benchmarks/hertz/mpc_vs_alm.py [--cases hertz2d_2k,hertz2d_8k,hertz3d_15k] [--out DIR]
Prints a markdown table (peak pressure and contact half-width against Hertz for each run's own force,
Newton iterations per step, analysis time) and writes it to results_mpc.md.
Environment: MORTARCONTACT_KRATOS_VENV (as run_kratos.py).
"""
from __future__ import annotations

import argparse
import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from mortarcontact.cases.hertz import evaluate, load_reference, write_case  # noqa: E402

import harness  # noqa: E402

#: Kratos' wheels have no UMFPACK: both codes use a direct LU (ours: UMFPACK)
KRATOS_SOLVER = 'solver_settings.linear_solver_settings={"solver_type": "LinearSolversApplication.sparse_lu"}'


def row(label: str, record: dict, hertz: dict) -> str:
    iterations = [s["iterations"] for s in record.get("steps", [])]
    converged = all(s["converged"] for s in record.get("steps", [])) and record.get("status") == "ok"
    if not converged:
        return (f"| {label} | not converged (iterations {iterations}; bottom / top reaction "
                f"{record.get('reactions', {}).get('DISPLACEMENT_bottom', float('nan')):.4g} / "
                f"{-record.get('reactions', {}).get('DISPLACEMENT_top', float('nan')):.4g}) | | | | "
                f"{record.get('analysis_seconds', float('nan')):.2f} |")
    e = evaluate(record, hertz)
    return (f"| {label} | {e['force']:.5g} | {e['peak_pressure']:.4g} ({harness.fmt_pct(e['peak_pressure_error'])}) | "
            f"{e['half_width_fit']:.4g} ({harness.fmt_pct(e['half_width_fit_error'])}) | {iterations} | "
            f"{record['analysis_seconds']:.2f} |")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cases", default="hertz2d_2k,hertz2d_8k,hertz3d_15k")
    parser.add_argument("--out", default=None, help="folder of the cases and records (default: a temporary one)")
    args = parser.parse_args(argv)
    kratos = harness.kratos_python()
    lines = [harness.machine_line(1), "",
             "| run | force P | peak pressure (vs Hertz) | half-width a, fit (vs Hertz) | Newton iterations per step "
             "| analysis s |", "|---|---|---|---|---|---|"]
    with tempfile.TemporaryDirectory() as scratch:
        out = args.out or scratch
        for case in args.cases.split(","):
            family, _, size = case.partition("_")
            for mpc in (False, True):
                folder = write_case(family, size, out, linear_solver="LinearSolversApplication.sparse_lu", mpc=mpc)
                hertz = load_reference(folder)
                name = os.path.basename(folder)
                for code, python, overrides in (("mortarcontact", None, []), ("kratos", kratos, [KRATOS_SOLVER])):
                    record = harness.run_once(code, folder, os.path.join(out, f"{name}_{code}.json"), 1, python,
                                              overrides=overrides)
                    lines.append(row(f"{name} {'Kratos 10.4' if code == 'kratos' else 'ours'}", record, hertz))
    text = "\n".join(lines) + "\n"
    print(text)
    harness.write_report(os.path.join(HERE, "results_mpc.md"), "# Hertz: MPC against ALM\n\n" + text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
