# SPDX-License-Identifier: BSD-3-Clause
"""Issue 4: shared pieces of the Hertz benchmark harness (run_kratos.py, compare.py).

- The Kratos virtual environment: Kratos is never a dependency of mortarcontact. The harness
  creates its own venv (``$MORTARCONTACT_KRATOS_VENV``, default ``benchmarks/hertz/.venv``) and
  installs the five Kratos 10.4 wheels there with pip; Kratos then runs in a subprocess with that
  venv's Python (case_runner.py).
- Case generation on demand (generate_cases.py) and one subprocess per run, with a fixed
  OpenMP thread count for both codes (OpenMP spinning on a shared, loaded machine otherwise
  distorts timings by an order of magnitude).
- Evaluation against Hertz theory.

Contact pressure. Kratos' ALM unknown LAGRANGE_MULTIPLIER_CONTACT_PRESSURE is the multiplier
divided by the scale factor k (ProcessInfo SCALE_FACTOR, automatic k = E/h): the nodal normal
contact pressure is p = -k * lambda (compression positive). With dual (biorthogonal) multiplier
shape functions the nodal multiplier is already a pressure, not a nodal force, so no division by
a tributary area is needed; AUGMENTED_NORMAL_CONTACT_PRESSURE = k * lambda + epsilon * weighted gap
equals -p at converged active nodes (zero weighted gap) and is used when SCALE_FACTOR cannot be
read. The harness checks this reading: the
pressure integrated over the slave surface (piecewise linear, times the symmetry factor) must equal
the reaction force.
"""
from __future__ import annotations

import json
import math
import os
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import generate_cases  # noqa: E402

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
                           "KratosMultiphysics.LinearSolversApplication, KratosMultiphysics.ConstitutiveLawsApplication"]
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
        if family not in generate_cases.SIZES or label not in generate_cases.SIZES[family]:
            raise SystemExit(f"unknown case {name!r}; known: {', '.join(generate_cases.all_case_names())}")
        print(f"Generating {name} ...", flush=True)
        generate_cases.write_case(family, label, cases_dir)
    return folder


def load_hertz(folder: str) -> dict:
    with open(os.path.join(folder, "hertz.json")) as f:
        return json.load(f)


def run_once(code: str, folder: str, output: str, threads: int, python: str | None = None,
             timeout: float = 6 * 3600, linear_solver: str | None = None, all_nodes: bool = False,
             overrides: list[str] = ()) -> dict:
    """One run in a fresh subprocess; returns the runner's record (status, timings, raw fields),
    status "timeout" when the run is stopped after ``timeout`` seconds.
    ``linear_solver``: mortarcontact's linear_solver_settings (JSON) in place of the case's;
    ``all_nodes``: see case_runner.py --all-nodes; ``overrides``: its --set items."""
    python = python or sys.executable
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


# -- Hertz evaluation -------------------------------------------------------------------------
def _least_squares_line(xs, ys):
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    slope = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx
    return my - slope * mx, slope


def _integrate_2d(points):
    points = sorted(points)
    return sum(0.5 * (p0 + p1) * (x1 - x0) for (x0, p0), (x1, p1) in zip(points, points[1:]))


def _integrate_3d(xs, ys, ps):
    import numpy as np
    from scipy.spatial import Delaunay

    xy = np.column_stack([xs, ys])
    tri = Delaunay(xy)
    p = np.asarray(ps)
    total = 0.0
    for simplex in tri.simplices:
        a, b, c = xy[simplex]
        area = 0.5 * abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
        total += area * p[simplex].mean()
    return total


def evaluate(record: dict, hertz: dict) -> dict:
    """Peak pressure, half-width and force of a finished run against Hertz for its own force."""
    if record.get("status") != "ok":
        return {}
    dim, symmetry, radius = hertz["dimension"], hertz["symmetry_factor"], hertz["radius"]
    e_star = hertz["effective_modulus"]
    force = abs(record["reactions"]["DISPLACEMENT_bottom"]) * symmetry
    theory = (generate_cases.hertz_2d if dim == 2 else generate_cases.hertz_3d)(force, radius, e_star)
    scale = (record.get("process_info") or {}).get("SCALE_FACTOR")
    nodes = []
    for n in record["slave"]:
        if n["lm"] is not None and scale is not None:
            p = -scale * n["lm"]
        else:
            p = -(n["augmented"] or 0.0) if n["active"] else 0.0
        r = abs(n["x"]) if dim == 2 else math.hypot(n["x"], n["y"])
        nodes.append((r, max(p, 0.0), n))
    peak = max(p for _, p, _ in nodes)
    active_r = [r for r, p, _ in nodes if p > 0.0]
    inactive_r = [r for r, p, _ in nodes if p <= 0.0 and r > max(active_r)]
    edge = 0.5 * (max(active_r) + min(inactive_r)) if inactive_r else max(active_r)
    fit_nodes = [(r * r, p * p) for r, p, _ in nodes if p >= 0.3 * peak]
    intercept, slope = _least_squares_line([x for x, _ in fit_nodes], [y for _, y in fit_nodes]) \
        if len(fit_nodes) >= 3 else (float("nan"), float("nan"))
    p0_fit = math.sqrt(intercept) if intercept > 0 else float("nan")
    a_fit = math.sqrt(-intercept / slope) if intercept > 0 and slope < 0 else float("nan")
    if dim == 2:
        integrated = symmetry * _integrate_2d([(n["x"], p) for _, p, n in nodes])
    else:
        integrated = symmetry * _integrate_3d([n["x"] for _, _, n in nodes], [n["y"] for _, _, n in nodes],
                                              [p for _, p, _ in nodes])
    return {
        "force": force, "force_from_pressure": integrated, "active_nodes": len(active_r),
        "hertz_half_width": theory["half_width"], "hertz_peak_pressure": theory["peak_pressure"],
        "peak_pressure": peak, "peak_pressure_error": peak / theory["peak_pressure"] - 1.0,
        "p0_fit": p0_fit, "p0_fit_error": p0_fit / theory["peak_pressure"] - 1.0,
        "half_width_fit": a_fit, "half_width_fit_error": a_fit / theory["half_width"] - 1.0,
        "half_width_edge": edge, "half_width_edge_error": edge / theory["half_width"] - 1.0,
        "a_over_r": a_fit / radius,
        "hertz_force_for_applied_displacement": (4.0 / 3.0 * e_star * math.sqrt(radius)
                                                 * hertz["applied_displacement"] ** 1.5 if dim == 3 else None),
    }


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
