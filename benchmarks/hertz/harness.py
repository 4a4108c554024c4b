# SPDX-License-Identifier: BSD-3-Clause
"""Issue 4: shared pieces of the Hertz benchmark harness (run_kratos.py, compare.py).

- The Kratos virtual environment: Kratos is never a dependency of mortarcontact. The harness
  creates its own venv (``$MORTARCONTACT_KRATOS_VENV``, default ``benchmarks/hertz/.venv``) and
  installs the five Kratos 10.4 wheels there with pip; Kratos then runs in a subprocess with that
  venv's Python (case_runner.py).
- Case generation on demand (mortarcontact.cases.hertz) and one subprocess per run, with a fixed
  OpenMP thread count for both codes (OpenMP spinning on a shared, loaded machine otherwise
  distorts timings by an order of magnitude).
- Medians over repeated runs, with the Hertz evaluation of mortarcontact.cases.hertz.

How the contact pressure is read from each code's record: mortarcontact.cases.hertz.evaluate.
"""
from __future__ import annotations

import json
import math
import os
import statistics
import subprocess
import sys
import time

from mortarcontact.cases.hertz import SIZES, all_case_names, evaluate, write_case
from mortarcontact.cases.mesh_files import write_kratos_mdpa

HERE = os.path.dirname(os.path.abspath(__file__))

KRATOS_VERSION = "10.4.4"
#: ConstitutiveLawsApplication holds HyperElastic3DLaw and KirchhoffSaintVenant3DLaw since Kratos 9
KRATOS_PACKAGES = ["KratosMultiphysics", "KratosStructuralMechanicsApplication",
                   "KratosContactStructuralMechanicsApplication", "KratosLinearSolversApplication",
                   "KratosConstitutiveLawsApplication"]
RESULTS_DIR = os.path.join(HERE, "results")
RUNNER = os.path.join(HERE, "case_runner.py")


def kratos_venv_dir() -> str:
    return os.environ.get("MORTARCONTACT_KRATOS_VENV", os.path.join(HERE, ".venv"))


def kratos_python(install: bool = True) -> str:
    """Python of the Kratos venv, created and filled on first use."""
    venv = kratos_venv_dir()
    python = os.path.join(venv, "bin", "python")
    probe = [python, "-c", "import KratosMultiphysics.ContactStructuralMechanicsApplication, "
                           "KratosMultiphysics.LinearSolversApplication, "
                           "KratosMultiphysics.ConstitutiveLawsApplication"]
    if os.path.exists(python) and subprocess.run(probe, capture_output=True).returncode == 0:
        return python
    if not install:
        raise RuntimeError(f"no Kratos venv at {venv}")
    print(f"Installing Kratos {KRATOS_VERSION} into {venv} ...", flush=True)
    if not os.path.exists(python):
        subprocess.run([sys.executable, "-m", "venv", venv], check=True)
    subprocess.run([python, "-m", "pip", "install", "-q", "--disable-pip-version-check"]
                   + [f"{p}=={KRATOS_VERSION}" for p in KRATOS_PACKAGES], check=True)
    result = subprocess.run(probe, capture_output=True, text=True)
    if result.returncode != 0:
        raise RuntimeError(f"Kratos does not import in {venv}:\n{result.stderr[-2000:]}")
    return python


def ensure_case(name: str, cases_dir: str) -> str:
    folder = os.path.join(cases_dir, name)
    if not os.path.exists(os.path.join(folder, "hertz.json")):
        family, _, label = name.partition("_")
        if family not in SIZES or label not in SIZES[family]:
            raise SystemExit(f"unknown case {name!r}; known: {', '.join(all_case_names())}")
        print(f"Generating {name} ...", flush=True)
        write_case(family, label, cases_dir)
    return folder


def run_once(code: str, folder: str, output: str, threads: int, python: str | None = None,
             timeout: float = 6 * 3600, linear_solver: str | None = None, all_nodes: bool = False,
             overrides: list[str] = ()) -> dict:
    """One run in a fresh subprocess; returns the runner's record (status, timings, raw fields),
    status "timeout" when the run is stopped after ``timeout`` seconds.
    ``linear_solver``: mortarcontact's linear_solver_settings (JSON) in place of the case's;
    ``all_nodes``: see case_runner.py --all-nodes; ``overrides``: its --set items."""
    python = python or sys.executable
    if code == "kratos":
        write_kratos_mdpa(folder)
    extra = ["--linear-solver", linear_solver] if linear_solver and code == "mortarcontact" else []
    extra += ["--all-nodes"] if all_nodes else []
    extra += [arg for item in overrides for arg in ("--set", item)]
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    os.makedirs(os.path.dirname(output), exist_ok=True)
    log = os.path.splitext(output)[0] + ".log"
    started = time.perf_counter()
    if os.path.exists(output):
        os.remove(output)
    with open(log, "w") as out:
        try:
            completed = subprocess.run([python, RUNNER, "--code", code, *extra, folder, output], stdout=out,
                                       stderr=subprocess.STDOUT, env=env, timeout=timeout)
        except subprocess.TimeoutExpired:
            return {"code": code, "status": "timeout", "error": f"stopped after {timeout:g} s",
                    "wall_seconds": time.perf_counter() - started}
    wall = time.perf_counter() - started
    if completed.returncode != 0 or not os.path.exists(output):
        with open(log) as f:
            tail = f.read()[-1500:]
        return {"code": code, "status": "failed", "error": f"runner exit {completed.returncode}: {tail}",
                "wall_seconds": wall}
    with open(output) as f:
        record = json.load(f)
    record["wall_seconds"] = wall
    record["log"] = log
    return record


def summarize(records: list[dict], hertz: dict) -> dict:
    """Medians over repeated runs of one code on one case, plus the Hertz evaluation of the last."""
    ok = [r for r in records if r.get("status") == "ok"]
    if not ok:
        first = records[0] if records else {}
        return {"status": first.get("status", "failed"), "error": first.get("error", "")}
    last = ok[-1]
    phases = None
    if all(r.get("phases") for r in ok):
        phases = {k: statistics.median(r["phases"][k] for r in ok) for k in ok[0]["phases"]}
    return {
        "status": "ok", "runs": len(ok),
        "analysis_seconds": statistics.median(r["analysis_seconds"] for r in ok),
        "analysis_cpu_seconds": statistics.median(r.get("analysis_cpu_seconds", math.nan) for r in ok),
        "linear_solver_counters": last.get("linear_solver_counters"),
        "setup_seconds": statistics.median(r["setup_seconds"] for r in ok),
        "wall_seconds": statistics.median(r["wall_seconds"] for r in ok),
        "peak_rss_mb": statistics.median(r["peak_rss_mb"] for r in ok),
        "iterations": [s["iterations"] for s in last["steps"]],
        "converged": all(s["converged"] is not False for s in last["steps"]),
        "step_seconds": [s["seconds"] for s in last["steps"]],
        "hertz": evaluate(last, hertz),
        "phases": phases,
        "blas": last.get("blas", []),
        "contact_pairs": last.get("contact_pairs"),
        "searches": last.get("searches"),
    }


def fmt_pct(x) -> str:
    return "n/a" if x is None or (isinstance(x, float) and math.isnan(x)) else f"{100.0 * x:+.1f} %"


def machine_line(threads: int) -> str:
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    return (f"{os.cpu_count()} cores, OMP_NUM_THREADS={threads} for both codes, load average "
            f"{load:.1f} at the end of the run, {time.strftime('%Y-%m-%d %H:%M')}")


def write_report(path: str, text: str) -> None:
    """Writes a results file and says where."""
    with open(path, "w") as f:
        f.write(text)
    print(f"wrote {path}")
