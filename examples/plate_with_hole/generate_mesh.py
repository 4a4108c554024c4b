"""Writes plate_with_hole.mdpa: a quarter of a square plate (side 2L) with a central hole of radius
a under uniaxial tension, meshed with structured quadrilaterals graded towards the hole.

Two patches split along the diagonal map the annulus between the hole (arc) and the outer
edges; nodes are shared on the diagonal. Sub-model-parts: Parts_plate (elements),
DISPLACEMENT_symmetry_x (edge x = 0, u_x = 0), DISPLACEMENT_symmetry_y (edge y = 0, u_y = 0),
Load_right (LineLoadCondition2D2N on x = L).
Usage: python generate_mesh.py [n_circumferential_per_patch] [n_radial]
"""
from __future__ import annotations

import math
import sys

A, L = 1.0, 10.0


def build(n_t: int, n_r: int, grading: float = 1.12):
    # Radial parameter with geometric grading: fine near the hole.
    w = [grading ** k for k in range(n_r)]
    s = [0.0]
    for wk in w:
        s.append(s[-1] + wk)
    s = [v / s[-1] for v in s]
    node_id = {}
    coords = []

    def node(key, x, y):
        if key not in node_id:
            node_id[key] = len(coords) + 1
            coords.append((x, y))
        return node_id[key]

    quads = []
    for patch in (0, 1):
        grid = {}
        for i in range(n_t + 1):
            t = i / n_t
            theta = (t * math.pi / 4) if patch == 0 else (math.pi / 4 + t * math.pi / 4)
            inner = (A * math.cos(theta), A * math.sin(theta))
            outer = (L, L * math.tan(theta)) if patch == 0 else (L / math.tan(theta), L)
            for j, sj in enumerate(s):
                x = inner[0] + sj * (outer[0] - inner[0])
                y = inner[1] + sj * (outer[1] - inner[1])
                # Global keys make the diagonal (patch 0, i = n_t) and (patch 1, i = 0) coincide.
                angle_index = i if patch == 0 else n_t + i
                grid[i, j] = node((angle_index, j), x, y)
        for i in range(n_t):
            for j in range(n_r):
                # Counter-clockwise: radial direction, then angle increases.
                quads.append((grid[i, j], grid[i, j + 1], grid[i + 1, j + 1], grid[i + 1, j]))
    return coords, quads


def write(path: str, coords, quads) -> None:
    tol = 1e-9
    sym_x = [k + 1 for k, (x, y) in enumerate(coords) if abs(x) < tol]
    sym_y = [k + 1 for k, (x, y) in enumerate(coords) if abs(y) < tol]
    right = sorted(((y, k + 1) for k, (x, y) in enumerate(coords) if abs(x - L) < tol))
    load_edges = [(right[k][1], right[k + 1][1]) for k in range(len(right) - 1)]
    # Edge (n1 -> n2) with increasing y on x = L runs counter-clockwise: outward normal +x.
    with open(path, "w") as f:
        f.write("Begin ModelPartData\nEnd ModelPartData\n\nBegin Properties 0\nEnd Properties\n\n")
        f.write("Begin Nodes\n")
        for k, (x, y) in enumerate(coords):
            f.write(f"{k + 1:8d} {x:.12e} {y:.12e} 0.0\n")
        f.write("End Nodes\n\nBegin Elements SmallDisplacementElement2D4N\n")
        for e, q in enumerate(quads):
            f.write(f"{e + 1:8d} 0 {q[0]} {q[1]} {q[2]} {q[3]}\n")
        f.write("End Elements\n\nBegin Conditions LineLoadCondition2D2N\n")
        for c, (n1, n2) in enumerate(load_edges):
            f.write(f"{c + 1:8d} 0 {n1} {n2}\n")
        f.write("End Conditions\n\n")

        def sub(name, nodes=(), elements=(), conditions=()):
            f.write(f"Begin SubModelPart {name}\n  Begin SubModelPartNodes\n")
            for n in nodes:
                f.write(f"    {n}\n")
            f.write("  End SubModelPartNodes\n  Begin SubModelPartElements\n")
            for e in elements:
                f.write(f"    {e}\n")
            f.write("  End SubModelPartElements\n  Begin SubModelPartConditions\n")
            for c in conditions:
                f.write(f"    {c}\n")
            f.write("  End SubModelPartConditions\nEnd SubModelPart\n\n")

        sub("Parts_plate", range(1, len(coords) + 1), range(1, len(quads) + 1))
        sub("DISPLACEMENT_symmetry_x", sym_x)
        sub("DISPLACEMENT_symmetry_y", sym_y)
        sub("Load_right", sorted({n for e in load_edges for n in e}), (), range(1, len(load_edges) + 1))


if __name__ == "__main__":
    n_t = int(sys.argv[1]) if len(sys.argv) > 1 else 24
    n_r = int(sys.argv[2]) if len(sys.argv) > 2 else 32
    coords, quads = build(n_t, n_r)
    write("plate_with_hole.mdpa", coords, quads)
    print(f"plate_with_hole.mdpa: {len(coords)} nodes, {len(quads)} quadrilaterals")
