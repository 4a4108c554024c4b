"""Draws plate_with_hole.png from the last VTU written by the run: the hoop stress field around the
hole, and sigma_xx along the symmetry line x = 0 against Kirsch's closed form for an infinite
plate, sigma_xx(r) = S (1 + a^2 / (2 r^2) + 3 a^4 / (2 r^4)), whose peak at the hole is 3 S."""
from __future__ import annotations

import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import meshio
import numpy as np
from matplotlib.collections import PolyCollection

HOLE_RADIUS, APPLIED_STRESS = 1.0, 100.0


def latest_vtu(folder: str) -> str:
    files = sorted(glob.glob(os.path.join(folder, "**", "*.vtu"), recursive=True), key=os.path.getmtime)
    if not files:
        sys.exit(f"no .vtu file under {folder}: run the case first")
    return files[-1]


def main() -> None:
    mesh = meshio.read(latest_vtu("vtk_output"))
    quads = mesh.get_cells_type("quad")
    stress = np.asarray(mesh.get_cell_data("CAUCHY_STRESS_VECTOR", "quad"))
    sxx = stress[:, 0]
    points = mesh.points[:, :2]
    centers = points[quads].mean(axis=1)

    fig, (ax_field, ax_line) = plt.subplots(1, 2, figsize=(13, 5.5))
    polys = PolyCollection(points[quads], array=sxx, cmap="turbo", edgecolors="face", linewidths=0.2)
    ax_field.add_collection(polys)
    ax_field.set_xlim(0, 4)
    ax_field.set_ylim(0, 4)
    ax_field.set_aspect("equal")
    ax_field.set_title(r"$\sigma_{xx}$ near the hole (quarter model, tension along x)")
    fig.colorbar(polys, ax=ax_field, label=r"$\sigma_{xx}$")

    # Elements touching the symmetry line x = 0: their centers are closest to it.
    near_axis = np.argsort(centers[:, 0])[: max(8, int(np.sqrt(len(quads))))]
    r = centers[near_axis, 1]
    order = np.argsort(r)
    r_exact = np.linspace(HOLE_RADIUS, 10.0, 300)
    kirsch = APPLIED_STRESS * (1 + HOLE_RADIUS**2 / (2 * r_exact**2) + 3 * HOLE_RADIUS**4 / (2 * r_exact**4))
    ax_line.plot(r_exact, kirsch, "k-", label="Kirsch (infinite plate)")
    ax_line.plot(r[order], sxx[near_axis][order], "o", ms=4, label="mortarcontact (element centers)")
    ax_line.set_xlabel("distance from the hole centre along x = 0")
    ax_line.set_ylabel(r"$\sigma_{xx}$")
    ax_line.set_title(f"Stress concentration: peak / applied = {sxx[near_axis].max() / APPLIED_STRESS:.2f} (Kirsch: 3)")
    ax_line.grid(alpha=0.3)
    ax_line.legend()
    fig.tight_layout()
    fig.savefig("plate_with_hole.png", dpi=120)
    print("wrote plate_with_hole.png")


if __name__ == "__main__":
    main()
