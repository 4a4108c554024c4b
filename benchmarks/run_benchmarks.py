#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 2 (speed): assembly and linear-solve benchmark of a 3D linear-elastic block.

A unit cube of n^3 cells, meshed with SmallDisplacementElement3D8N hexahedra or
SmallDisplacementElement3D4N tetrahedra (6 per cell, Kuhn split, conforming), LinearElastic3DLaw,
under uniaxial compression with rollers: u_x = 0 on x = 0, u_y = 0 on y = 0, u_z = 0 on z = 0
and u_z = -delta on z = H. The exact solution u = (nu delta x/H, nu delta y/H, -delta z/H) is
linear, so both meshes reproduce it to round-off: the benchmark checks it on every run.

Every case runs in a fresh subprocess so that its peak resident memory is its own. Per case:
mesh generation (numpy), mdpa writing and reading (mc.ReadModelPart), DoF set-up, sparsity
pattern, assembly (median of --repeat builds) and the direct solve (CHOLMOD by default,
UMFPACK for reference at the smallest size), from the builder's own timers.

Repeated assemblies use a stand-in linear solver (conjugate gradients whose tolerance is met
before any iteration) so that they do not refactorize: the builder times the assembly on its
own, and the stand-in costs one matrix-vector product per build.

    python benchmarks/run_benchmarks.py                      # 0.1M, 0.5M, 1M DoFs -> results.md
    python benchmarks/run_benchmarks.py --sizes 0.1M --repeat 3
    python benchmarks/run_benchmarks.py --quick              # a few thousand DoFs, seconds
"""
from __future__ import annotations

import argparse
import datetime
import gc
import json
import os
import platform
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ELEMENTS = {"hex": "SmallDisplacementElement3D8N", "tet": "SmallDisplacementElement3D4N"}
YOUNG, POISSON, DELTA = 1.0e5, 0.3, 1.0e-3
# Kuhn split of a cube (vertices numbered as a Hexahedra3D8) into 6 tetrahedra around the 0-6
# diagonal; every one is positively oriented and neighbouring cubes share face diagonals.
KUHN = ((0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6))


# --------------------------------------------------------------------------------------------
# Sizes
# --------------------------------------------------------------------------------------------

def parse_size(text: str) -> int:
    """'0.1M', '500k' or '3000' -> a DoF count."""
    t = text.strip().lower()
    factor = 1
    if t.endswith("m"):
        factor, t = 1_000_000, t[:-1]
    elif t.endswith("k"):
        factor, t = 1_000, t[:-1]
    return round(float(t) * factor)


def cells_for(dofs: int) -> int:
    """Cells per edge whose 3 (n+1)^3 DoFs are closest to `dofs`."""
    return max(1, round((dofs / 3.0) ** (1.0 / 3.0)) - 1)


def size_label(dofs: int) -> str:
    return f"{dofs / 1e6:.2f}M" if dofs >= 100_000 else f"{dofs / 1e3:.1f}k"


# --------------------------------------------------------------------------------------------
# Mesh (numpy) and mdpa
# --------------------------------------------------------------------------------------------

def block_mesh(n: int, element: str):
    """Node coordinates (N, 3) and 1-based connectivity (E, 8) or (6E, 4) of the unit cube."""
    g = np.linspace(0.0, 1.0, n + 1)
    z, y, x = np.meshgrid(g, g, g, indexing="ij")  # node id = 1 + i + (n+1) (j + (n+1) k)
    coords = np.column_stack([x.ravel(), y.ravel(), z.ravel()])
    i, j, k = np.meshgrid(np.arange(n), np.arange(n), np.arange(n), indexing="ij")
    i, j, k = i.ravel(), j.ravel(), k.ravel()
    m = n + 1
    node = lambda a, b, c: 1 + a + m * (b + m * c)  # noqa: E731
    hexes = np.column_stack([node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                             node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
                             node(i, j + 1, k + 1)])
    if element == "hex":
        return coords, hexes
    tets = np.stack([hexes[:, list(t)] for t in KUHN], axis=1).reshape(-1, 4)
    return coords, tets


def check_orientation(coords: np.ndarray, cells: np.ndarray) -> None:
    """Every tetrahedron (or the 0-1-3-4 corner of every hexahedron) has positive volume."""
    c = cells - 1
    a, b, d, e = (c[:, 0], c[:, 1], c[:, 2], c[:, 3]) if cells.shape[1] == 4 else (c[:, 0], c[:, 1], c[:, 3], c[:, 4])
    volume = np.einsum("ij,ij->i", np.cross(coords[b] - coords[a], coords[d] - coords[a]), coords[e] - coords[a])
    if not (volume > 0).all():
        raise RuntimeError(f"{int((volume <= 0).sum())} cells are inverted")


def write_mdpa(path: Path, coords: np.ndarray, cells: np.ndarray, element: str) -> None:
    ids = np.arange(1, len(coords) + 1)
    faces = {"bottom": coords[:, 2] == 0.0, "top": coords[:, 2] == 1.0,
             "xmin": coords[:, 0] == 0.0, "ymin": coords[:, 1] == 0.0}
    with open(path, "w") as f:
        f.write("Begin ModelPartData\nEnd ModelPartData\n\nBegin Properties 1\nEnd Properties\n\nBegin Nodes\n")
        np.savetxt(f, np.column_stack([ids, coords]), fmt="%d %.17g %.17g %.17g")
        f.write("End Nodes\n\n")
        f.write(f"Begin Elements {ELEMENTS[element]}\n")
        body = np.column_stack([np.arange(1, len(cells) + 1), np.ones(len(cells), dtype=np.int64), cells])
        np.savetxt(f, body, fmt="%d")
        f.write("End Elements\n\n")
        for name, mask in faces.items():
            f.write(f"Begin SubModelPart {name}\n  Begin SubModelPartNodes\n")
            np.savetxt(f, ids[mask], fmt="%d")
            f.write("  End SubModelPartNodes\nEnd SubModelPart\n\n")


# --------------------------------------------------------------------------------------------
# One case, in its own process
# --------------------------------------------------------------------------------------------

def loaded_blas() -> str:
    """The BLAS library mapped into this process (what CHOLMOD's supernodal kernels run on)."""
    try:
        for line in Path("/proc/self/maps").read_text().splitlines():
            path = line.split()[-1]
            if "blas" in os.path.basename(path) and "scipy" not in path and "numpy" not in path:
                return os.path.realpath(path)
    except OSError:
        pass
    return "unknown"


def peak_rss_mb() -> float:
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0  # kB on Linux


def run_case(element: str, n: int, solver: str, repeat: int, out: Path) -> None:
    """Runs one case and rewrites `out` (JSON) after each phase, so that a case stopped by the
    time limit still reports what it measured."""
    import mortarcontact as mc

    result: dict = {"element": element, "cells": n, "solver": solver, "repeat": repeat,
                    "threads": int(os.environ.get("OMP_NUM_THREADS", os.cpu_count() or 1))}

    def save(phase: str) -> None:
        result["phase"] = phase
        result["peak_rss_mb"] = peak_rss_mb()
        out.write_text(json.dumps(result))

    mc.RegisterStructuralMechanics()
    t = time.perf_counter()
    coords, cells = block_mesh(n, element)
    check_orientation(coords, cells)
    result["mesh_s"] = time.perf_counter() - t
    result["nodes"], result["elements"] = len(coords), len(cells)

    with tempfile.TemporaryDirectory() as tmp:
        mdpa = Path(tmp) / "block.mdpa"
        t = time.perf_counter()
        write_mdpa(mdpa, coords, cells, element)
        result["mdpa_write_s"] = time.perf_counter() - t
        result["mdpa_mb"] = mdpa.stat().st_size / 2**20
        del cells
        model = mc.Model()
        part = model.CreateModelPart("Structure")
        part.AddNodalSolutionStepVariable(mc.DISPLACEMENT)
        part.AddNodalSolutionStepVariable(mc.REACTION)
        t = time.perf_counter()
        mc.ReadModelPart(part, str(mdpa))
        result["mdpa_read_s"] = time.perf_counter() - t

    materials = {"properties": [{"model_part_name": "Structure", "properties_id": 1, "Material": {
        "constitutive_law": {"name": "LinearElastic3DLaw"},
        "Variables": {"YOUNG_MODULUS": YOUNG, "POISSON_RATIO": POISSON}, "Tables": {}}}]}
    mc.ReadMaterials(model, mc.Parameters(json.dumps(materials)))
    component = {axis: mc.GetVariable(f"DISPLACEMENT_{axis}") for axis in "XYZ"}
    for axis in "XYZ":
        mc.VariableUtils.AddDof(part, component[axis], mc.GetVariable(f"REACTION_{axis}"))
    for face, axis, value in (("xmin", "X", 0.0), ("ymin", "Y", 0.0), ("bottom", "Z", 0.0), ("top", "Z", -DELTA)):
        mc.VariableUtils.AssignNodalScalar(part.GetSubModelPart(face), component[axis], value, True)
    save("mesh")

    # Repeated assemblies with the stand-in solver.
    stand_in = mc.CreateLinearSolver(mc.Parameters(
        '{"solver_type": "cg", "preconditioner_type": "none", "tolerance": 1e30, "max_iteration": 1}'))
    builder = mc.BlockBuilderAndSolver(stand_in)
    strategy = mc.LinearStrategy(part, mc.StaticScheme(), builder, compute_reactions=False, move_mesh=False)
    builds = []
    for _ in range(repeat):
        before = builder.GetTimings().build
        strategy.Solve()
        builds.append(builder.GetTimings().build - before)
    timings = builder.GetTimings()
    result.update(dofs=builder.NumberOfDofs(), nnz=builder.SystemMatrixNonZeros(), dof_setup_s=timings.dof_setup,
                  sparsity_s=timings.sparsity, builds_s=builds, build_s=statistics.median(builds))
    del strategy, builder, stand_in
    gc.collect()
    save("assembly")
    if solver == "none":
        result["blas"] = loaded_blas()
        save("done")
        return

    # The direct solve, from the exact solution's boundary values (the repeated solves above
    # left the displacements untouched).
    linear_solver = mc.CreateLinearSolver(mc.Parameters(json.dumps({"solver_type": solver})))
    builder = mc.BlockBuilderAndSolver(linear_solver)
    strategy = mc.LinearStrategy(part, mc.StaticScheme(), builder, compute_reactions=False, move_mesh=False)
    strategy.Solve()
    timings = builder.GetTimings()
    result.update(solve_s=timings.solve, solve_case_build_s=timings.build)

    x = part.NodeCoordinates(True)
    u = part.GetNodalValues(mc.DISPLACEMENT)
    exact = np.column_stack([POISSON * DELTA * x[:, 0], POISSON * DELTA * x[:, 1], -DELTA * x[:, 2]])
    result["max_error"] = float(np.abs(u - exact).max() / DELTA)
    result["blas"] = loaded_blas()
    save("done")


# --------------------------------------------------------------------------------------------
# Driver
# --------------------------------------------------------------------------------------------

def machine_info() -> dict:
    cpu = "unknown"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    memory = ""
    try:
        for line in Path("/proc/meminfo").read_text().splitlines():
            if line.startswith("MemTotal"):
                memory = f"{int(line.split()[1]) / 2**20:.1f} GiB"
    except OSError:
        pass
    return {"cpu": cpu, "cores": os.cpu_count(), "memory": memory, "python": platform.python_version(),
            "date": datetime.datetime.now().strftime("%Y-%m-%d %H:%M"), "load": os.getloadavg()[0]}


def launch(element: str, n: int, solver: str, repeat: int, timeout: float) -> dict:
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "case.json"
        command = [sys.executable, str(Path(__file__).resolve()), "--case", element, str(n), solver,
                   "--repeat", str(repeat), "--case-output", str(out)]
        status = "ok"
        start = time.perf_counter()
        try:
            done = subprocess.run(command, timeout=timeout, capture_output=True, text=True)
            if done.returncode != 0:
                last = done.stderr.strip().splitlines()[-1] if done.stderr.strip() else ""
                status = f"failed (exit {done.returncode}): {last}"
        except subprocess.TimeoutExpired:
            status = f"stopped after {timeout:.0f} s"
        result = json.loads(out.read_text()) if out.exists() else {"element": element, "cells": n, "solver": solver}
        result["status"] = status if result.get("phase") == "done" or status != "ok" else "incomplete"
        result["wall_s"] = time.perf_counter() - start
        return result


def fmt(value, digits: int = 2) -> str:
    if value is None:
        return "—"
    if isinstance(value, float):
        return f"{value:.{digits}f}" if abs(value) >= 10 ** -digits or value == 0 else f"{value:.1e}"
    return str(value)


def table(results: list[dict]) -> str:
    head = ("| mesh | DoFs | nnz | mesh gen s | mdpa write s | mdpa read s | DoF set-up s | sparsity s | "
            "assembly s (median) | solver | factorize+solve s | solve / assembly | peak RSS MB | kB / DoF | "
            "max error / δ | status |")
    rows = [head, "|" + "---|" * (head.count("|") - 1)]
    for r in results:
        build, solve = r.get("build_s"), r.get("solve_s")
        dofs = r.get("dofs")
        rows.append("| " + " | ".join([
            f"{r['element']} {r['cells']}³" + (" ×6" if r["element"] == "tet" else ""),
            f"{dofs:,}" if dofs else "—",
            f"{r['nnz']:,}" if r.get("nnz") else "—",
            fmt(r.get("mesh_s")), fmt(r.get("mdpa_write_s")), fmt(r.get("mdpa_read_s")),
            fmt(r.get("dof_setup_s")), fmt(r.get("sparsity_s")), fmt(build, 3), r["solver"], fmt(solve),
            fmt(solve / build, 1) if build and solve else "—",
            fmt(r.get("peak_rss_mb"), 0),
            fmt(r["peak_rss_mb"] * 1024.0 / dofs, 2) if dofs and r.get("peak_rss_mb") else "—",
            fmt(r.get("max_error"), 2), r.get("status", "")]) + " |")
    return "\n".join(rows)


def write_results(path: Path, results: list[dict], info: dict, args) -> None:
    lines = [
        "# Benchmark results: 3D linear-elastic block (issue 2)",
        "",
        f"Generated by `python benchmarks/run_benchmarks.py {' '.join(args.argv)}` on {info['date']}."
        .replace("  ", " "),
        "",
        f"Machine: {info['cpu']}, {info['cores']} cores, {info['memory']}; Python {info['python']}; "
        f"OpenMP threads: {results[0].get('threads', '?') if results else '?'}; BLAS used by the solvers: "
        f"{', '.join(sorted({'`' + r['blas'] + '`' for r in results if r.get('blas')})) or 'unknown'}; "
        f"1-minute load average {info['load']:.1f} at the start and {os.getloadavg()[0]:.1f} at the end "
        "(times are wall-clock: other work on the machine inflates them).",
        "",
        "Unit cube, uniaxial compression with rollers (exact solution linear), LinearElastic3DLaw; "
        "hexahedra SmallDisplacementElement3D8N, tetrahedra SmallDisplacementElement3D4N (6 per cell). "
        "Each row is a fresh process. *assembly* is the median of the builds (element loop, "
        f"scatter into the fixed pattern, Dirichlet rows; {args.repeat} builds); *factorize+solve* "
        "is the solver's time in the builder: symbolic analysis, symmetry check, numeric "
        "factorization and solve. Peak RSS is the process's ru_maxrss (mesh, model, matrix, factor).",
        "",
        table(results),
        "",
    ]
    if any(r["solver"] == "none" for r in results):
        lines += [f"Rows with solver *none* time the assembly only: the direct solve is skipped above "
                  f"--solve-up-to {args.solve_up_to} DoFs.", ""]
    notes = [r for r in results if r.get("status") not in ("ok", None)]
    for r in notes:
        lines.append(f"- {r['element']} {r['cells']}³ with {r['solver']}: {r['status']} "
                     f"(last phase reached: {r.get('phase', 'none')}).")
    path.write_text("\n".join(lines) + "\n")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sizes", default="0.1M,0.5M,1M", help="comma-separated DoF counts (e.g. 0.1M,500k,3000)")
    parser.add_argument("--elements", default="hex,tet", help="hex, tet or both")
    parser.add_argument("--repeat", type=int, default=5, help="assemblies per case (median reported)")
    parser.add_argument("--umfpack-up-to", default="0.15M", help="also run UMFPACK for sizes up to this many DoFs")
    parser.add_argument("--solve-up-to", default="0.6M",
                        help="run the direct solver only up to this many DoFs (CHOLMOD's factor of a 3D block "
                             "grows like DoFs^(4/3) in memory and DoFs^2 in time); larger cases time the assembly only")
    parser.add_argument("--timeout", type=float, default=900.0, help="seconds per case before it is stopped")
    parser.add_argument("--output", default=str(HERE / "results.md"), help="markdown file written")
    parser.add_argument("--quick", action="store_true", help="smoke run: ~3k DoFs, 2 builds")
    parser.add_argument("--case", nargs=3, metavar=("ELEMENT", "CELLS", "SOLVER"), help=argparse.SUPPRESS)
    parser.add_argument("--case-output", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    args.argv = sys.argv[1:] if argv is None else argv

    if args.case:
        element, cells, solver = args.case
        run_case(element, int(cells), solver, args.repeat, Path(args.case_output))
        return 0

    if args.quick:
        args.sizes, args.repeat = "3000", min(args.repeat, 2)
    elements = [e.strip() for e in args.elements.split(",") if e.strip()]
    for e in elements:
        if e not in ELEMENTS:
            parser.error(f"unknown element '{e}' (use hex or tet)")
    umfpack_limit = parse_size(args.umfpack_up_to)
    solve_limit = parse_size(args.solve_up_to)
    info = machine_info()
    results = []
    for dofs in (parse_size(s) for s in args.sizes.split(",")):
        n = cells_for(dofs)
        for element in elements:
            solvers = ["cholmod"] + (["umfpack"] if dofs <= umfpack_limit else []) if dofs <= solve_limit else ["none"]
            for solver in solvers:
                print(f"{element} {n}^3 ({size_label(3 * (n + 1) ** 3)} DoFs), {solver} ...", flush=True)
                r = launch(element, n, solver, args.repeat, args.timeout)
                results.append(r)
                print(f"  {r['status']}: assembly {fmt(r.get('build_s'), 3)} s, solve {fmt(r.get('solve_s'))} s, "
                      f"peak {fmt(r.get('peak_rss_mb'), 0)} MB, max error / delta {fmt(r.get('max_error'))}",
                      flush=True)
    print()
    print(table(results))
    write_results(Path(args.output), results, info, args)
    print(f"\nwritten to {args.output}")
    return 0 if all(r.get("status") == "ok" for r in results) else 1


if __name__ == "__main__":
    sys.exit(main())
