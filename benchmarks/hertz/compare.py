#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 4: mortarcontact against Kratos 10.4 on the same Hertz case files, side by side.

For each case the two codes run alternately (mortarcontact, Kratos, mortarcontact, ...), each run
in a fresh subprocess with the same OMP_NUM_THREADS: mortarcontact through its analysis stage
(what ``python -m mortarcontact run`` executes), Kratos in the benchmark's own venv. Reported:
medians of the analysis time, the ratio ours / Kratos, Newton iterations per load step, peak
resident memory, both codes' errors against Hertz and mortarcontact's time per phase. Writes
benchmarks/hertz/results.md and benchmarks/hertz/time_vs_dofs.png (log-log, time against DoFs,
both codes).

A code that cannot run a case (mortarcontact before contact is implemented: "not implemented")
is reported as "not available"; its later repetitions are skipped.

    python benchmarks/hertz/compare.py                                  # hertz2d_2k, hertz3d_15k, 3 runs
    python benchmarks/hertz/compare.py --cases all --repeat 5
    python benchmarks/hertz/compare.py --cases hertz3d_600k --codes mortarcontact \
        --linear-solver '{"solver_type": "petsc", "petsc_options": {"pc_type": "fieldsplit"}}'

``--codes mortarcontact`` leaves Kratos out (reported "not run"): for the sizes where one Kratos run
would take hours. ``--reuse-kratos`` takes Kratos' records of an earlier run of this script
(results/CASE_kratos_I.json) where they exist instead of running Kratos again: Kratos does not
change between two measurements of ours, and its 3D runs take minutes each (the machine line
then says so; the two codes no longer alternate). ``--linear-solver`` sets mortarcontact's
linear_solver_settings (the case files keep the Kratos spelling both codes read).
"""
from __future__ import annotations

import argparse
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from mortarcontact.cases.hertz import all_case_names, load_reference

import harness

CODES = ("mortarcontact", "kratos")


def _cell(summary: dict, key: str, fmt: str = "{:.2f}") -> str:
    return fmt.format(summary[key]) if summary.get("status") == "ok" else summary.get("status", "n/a")


def _errors(summary: dict) -> str:
    if summary.get("status") != "ok" or not summary.get("hertz"):
        return "n/a"
    h = summary["hertz"]
    return f"{harness.fmt_pct(h['peak_pressure_error'])} / {harness.fmt_pct(h['half_width_fit_error'])}"


def table(rows) -> str:
    lines = ["| case | DoFs | time ours [s] | time Kratos [s] | ours / Kratos | CPU ours / Kratos "
             "| Newton its ours | Newton its Kratos | peak RSS ours / Kratos [MB] | Hertz p / a error ours "
             "| Hertz p / a error Kratos |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for name, hertz, s in rows:
        ours, kratos = s["mortarcontact"], s["kratos"]
        both = ours.get("status") == "ok" and kratos.get("status") == "ok"
        ratio = f"{ours['analysis_seconds'] / kratos['analysis_seconds']:.2f}" if both else "n/a"
        cpu = (f"{ours['analysis_cpu_seconds'] / kratos['analysis_cpu_seconds']:.2f}"
               if both and ours['analysis_cpu_seconds'] > 0 and kratos['analysis_cpu_seconds'] > 0 else "n/a")
        its = {c: (", ".join(map(str, s[c]["iterations"])) if s[c].get("status") == "ok" else "n/a") for c in CODES}
        rss = " / ".join(_cell(s[c], "peak_rss_mb", "{:.0f}") for c in CODES)
        lines.append(f"| {name} | {hertz['counts']['dofs']} | {_cell(ours, 'analysis_seconds')} "
                     f"| {_cell(kratos, 'analysis_seconds')} | {ratio} | {cpu} | {its['mortarcontact']} "
                     f"| {its['kratos']} | {rss} | {_errors(ours)} | {_errors(kratos)} |")
    return "\n".join(lines)


#: (column title, phase keys summed) of the per-phase table; "rest" is Python, I/O, DoF numbering,
#: sparsity pattern, constraint reduction and Dirichlet rows.
PHASE_COLUMNS = (("search", ("search",)), ("mortar gap + normals", ("weighted_gap", "normals")),
                 ("contact assembly", ("conditions",)), ("element assembly", ("elements",)),
                 ("linear solve", ("solve",)), ("rest", ("dof_setup", "build_other", "rest")))


def phase_table(rows) -> str:
    """mortarcontact's time per phase (medians over the runs, seconds and share of the total)."""
    head = " | ".join(title for title, _ in PHASE_COLUMNS)
    lines = [f"| case | DoFs | total [s] | {head} | Newton its | factorizations | Krylov solves (its) |",
             "|---|---|---|" + "---|" * len(PHASE_COLUMNS) + "---|---|---|"]
    for name, hertz, s in rows:
        ours = s["mortarcontact"]
        if ours.get("status") != "ok" or not ours.get("phases"):
            continue
        total = ours["analysis_seconds"]
        cells = []
        for _, keys in PHASE_COLUMNS:
            seconds = sum(ours["phases"][k] for k in keys)
            cells.append(f"{seconds:.3f} ({100.0 * seconds / total:.0f} %)")
        c = ours.get("linear_solver_counters") or {}
        work = (f"{c['factorizations']} | {c['krylov_solves']} ({c['krylov_iterations']})" if c else "n/a | n/a")
        lines.append(f"| {name} | {hertz['counts']['dofs']} | {total:.2f} | " + " | ".join(cells)
                     + f" | {sum(ours['iterations'])} | {work} |")
    return "\n".join(lines) if len(lines) > 2 else ""


def pair_table(rows) -> str:
    """Contact cost per pair (the linear-scaling target): search time per pair and search, mortar
    gap + normals and contact assembly per pair and Newton iteration (mortarcontact, medians)."""
    lines = ["| case | contact pairs | searches | search [us / pair] | mortar gap + normals [us / pair / it] "
             "| contact assembly [us / pair / it] |", "|---|---|---|---|---|---|"]
    for name, _, s in rows:
        ours = s["mortarcontact"]
        pairs, searches = ours.get("contact_pairs"), ours.get("searches")
        if ours.get("status") != "ok" or not ours.get("phases") or not pairs or not searches:
            continue
        phases, iterations = ours["phases"], sum(ours["iterations"])
        per_it = 1e6 / (pairs * iterations)
        lines.append(f"| {name} | {pairs} | {searches} | {1e6 * phases['search'] / (pairs * searches):.1f} "
                     f"| {(phases['weighted_gap'] + phases['normals']) * per_it:.1f} "
                     f"| {phases['conditions'] * per_it:.1f} |")
    return "\n".join(lines) if len(lines) > 2 else ""


def plot(rows, path: str) -> bool:
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return False
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for code, marker in (("mortarcontact", "o"), ("kratos", "s")):
        for family, style in (("hertz2d", "-"), ("hertz3d", "--"), ("hertz3dgrid", ":")):
            points = sorted((h["counts"]["dofs"], s[code]["analysis_seconds"]) for name, h, s in rows
                            if name.partition("_")[0] == family and s[code].get("status") == "ok")
            if points:
                ax.loglog(*zip(*points), marker=marker, linestyle=style, label=f"{code} {family[5:]}")
    ax.set_xlabel("DoFs")
    ax.set_ylabel("analysis time [s]")
    ax.set_title("Hertz cases, 4 load steps")
    ax.grid(True, which="both", alpha=0.3)
    if ax.get_legend_handles_labels()[0]:
        ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return True


def _earlier_record(path: str) -> dict | None:
    """A successful record written by an earlier run, or None. Its subprocess wall time, which
    run_once measures and the file lacks, is the runner's own (process start to the end)."""
    try:
        with open(path) as f:
            record = json.load(f)
    except (OSError, ValueError):
        return None
    if record.get("status") != "ok":
        return None
    record.setdefault("wall_seconds", record.get("process_seconds", record["analysis_seconds"]))
    return record


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cases", default="hertz2d_2k,hertz3d_15k", help="comma-separated case names or 'all'")
    parser.add_argument("--repeat", type=int, default=3, help="alternating runs per code and case (medians)")
    parser.add_argument("--threads", type=int, default=1, help="OMP_NUM_THREADS of both codes")
    parser.add_argument("--cases-dir", default=os.path.join(harness.HERE, "cases"))
    parser.add_argument("--output", default=os.path.join(harness.HERE, "results.md"))
    parser.add_argument("--plot", default=os.path.join(harness.HERE, "time_vs_dofs.png"))
    parser.add_argument("--codes", default=",".join(CODES), help="which codes run (comma-separated)")
    parser.add_argument("--linear-solver", help="mortarcontact's linear_solver_settings (JSON) instead of the case's")
    parser.add_argument("--reuse-kratos", action="store_true",
                        help="Kratos' records of an earlier run (results/CASE_kratos_I.json) instead of new runs")
    args = parser.parse_args(argv)
    names = all_case_names() if args.cases == "all" else args.cases.split(",")
    codes = args.codes.split(",")
    if not codes or any(c not in CODES for c in codes):
        parser.error(f"--codes: choose among {', '.join(CODES)}")
    pythons = {"mortarcontact": sys.executable}
    if "kratos" in codes:
        pythons["kratos"] = harness.kratos_python()
    rows = []
    for name in names:
        folder = harness.ensure_case(name, args.cases_dir)
        hertz = load_reference(folder)
        records = {c: [] for c in codes}
        for i in range(args.repeat):
            for code in codes:
                if records[code] and records[code][0].get("status") != "ok":
                    continue  # a code that cannot run the case is not retried
                out = os.path.join(harness.RESULTS_DIR, f"{name}_{code}_{i}.json")
                if code == "kratos" and args.reuse_kratos and (earlier := _earlier_record(out)):
                    records[code].append(earlier)
                    continue
                records[code].append(harness.run_once(code, folder, out, args.threads, pythons[code],
                                                      linear_solver=args.linear_solver))
        summary = {c: harness.summarize(records[c], hertz) if c in codes else {"status": "not run"} for c in CODES}
        with open(os.path.join(harness.RESULTS_DIR, f"{name}_compare.json"), "w") as f:
            json.dump(summary, f, indent=1)
        rows.append((name, hertz, summary))
        print(table(rows[-1:]).splitlines()[-1], flush=True)
        if phase_table(rows[-1:]):
            print(phase_table(rows[-1:]).splitlines()[-1], flush=True)
    notes = []
    for name, _, s in rows:
        for code in codes:
            if s[code].get("status") != "ok":
                notes.append(f"- {name}, {code}: {s[code].get('status')}: {s[code].get('error', '').strip()[:300]}")
    blas = sorted({lib for _, _, s in rows for lib in s["mortarcontact"].get("blas") or []})
    if blas:
        notes.append(f"- BLAS used by mortarcontact's sparse solvers: {', '.join(f'`{b}`' for b in blas)}")
    has_plot = plot(rows, args.plot)
    text = ("# Hertz benchmarks: mortarcontact against Kratos 10.4\n\n"
            "Generated by `benchmarks/hertz/compare.py`: same case files, alternating runs, medians of "
            f"{args.repeat} runs of the analysis time (read, set-up, 4 load steps; imports excluded; CPU: the "
            "process's CPU time over the same span, less sensitive to the other jobs of a shared machine). "
            "Hertz errors: "
            "peak nodal pressure / fitted half-width against Hertz theory for the computed force "
            "(see results_kratos.md for the definitions).\n\n"
            f"Machine: {harness.machine_line(args.threads)}.\n\n"
            + ("Kratos' records are those of an earlier run of this script (`--reuse-kratos`), not "
               "alternated with ours.\n\n" if args.reuse_kratos else "")
            + (f"mortarcontact's linear_solver_settings: `{args.linear_solver}` (the cases' own: "
               f"`sparse_lu`, UMFPACK for mortarcontact).\n\n" if args.linear_solver else "")
            + ("Kratos not run (`--codes`): with its direct solvers one run of hertz3d_50k already takes "
               "16 to 20 minutes here (results_large.md).\n\n" if "kratos" not in codes else "")
            + table(rows) + "\n"
            + (f"\nmortarcontact per phase (medians; timed in C++ with one clock read per phase and call: "
               f"the contact search, the mortar weighted gap and nodal normals of the criteria, the "
               f"condition and element loops of the assembly, the linear solver with its symbolic "
               f"analysis; the linear solver's numeric factorizations and the solves GMRES answered with "
               f"kept factors, with their iterations):\n\n{phases}\n" if (phases := phase_table(rows)) else "")
            + (f"\nContact cost per pair (pairs of the last search; a Newton iteration builds the "
               f"system and the residual):\n\n{pairs}\n" if (pairs := pair_table(rows)) else "")
            + ("\n" + "\n".join(notes) + "\n" if notes else "")
            + (f"\n![time against DoFs]({os.path.basename(args.plot)})\n" if has_plot else ""))
    harness.write_report(args.output, text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
