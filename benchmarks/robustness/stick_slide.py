#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 12: how far the sticking slave nodes of one code slide over a load step, from two
iterates.py dumps of that code (the converged end of step S-1 and of step S: K larger than the
step's iterations). A node that sticks through step S must keep its place on the master: its
relative tangential motion over the step (slave displacement minus the master displacement at
the node, tangential to the slave normal) vanishes up to the mesh's interpolation error.

The master displacement at a slave node is that of a master node beneath it, along the master
node's normal (matching meshes: exact), else the least-squares linear fit of the displacements of
the nearest master nodes, which misses the master's local indentation (up to 1e-4 here).

    python stick_slide.py BEFORE.json AFTER.json
"""
from __future__ import annotations

import argparse
import json
import sys

import numpy as np

NEAREST = 6
COINCIDENT = 1e-3  # of the interface size: the current master normals lean a little


def load(path: str) -> dict:
    with open(path) as f:
        return {(row["part"], row["id"]): row for row in json.load(f)}


def master_displacement(state: dict, point: np.ndarray, normal: np.ndarray) -> np.ndarray:
    masters = [row for (part, _), row in state.items() if part == "Contact_master"]
    coordinates = np.array([[row["x"], row["y"], row["z"]] for row in masters])
    offsets = coordinates - point
    normals = np.array([row["normal"] if np.linalg.norm(row["normal"]) > 0.0 else normal for row in masters])
    in_plane = np.linalg.norm(offsets - normals * np.sum(offsets * normals, axis=1)[:, None], axis=1)
    if in_plane.min() <= COINCIDENT * np.linalg.norm(offsets, axis=1).max():
        return np.array(masters[int(np.argmin(in_plane))]["u"])
    nearest = np.argsort(np.linalg.norm(offsets, axis=1))[:NEAREST]
    # Centred on the neighbours, so that a direction in which they do not vary (a flat master seen
    # from a slave node above it) gets a zero column instead of one collinear with the constant.
    centre = coordinates[nearest].mean(axis=0)
    basis = np.hstack([np.ones((len(nearest), 1)), coordinates[nearest] - centre])
    values = np.array([masters[i]["u"] for i in nearest])
    fit, *_ = np.linalg.lstsq(basis, values, rcond=None)
    return fit[0] + (point - centre) @ fit[1:]


def relative_displacement(state: dict, node: dict, normal: np.ndarray) -> np.ndarray:
    point = np.array([node["x"], node["y"], node["z"]])
    return np.array(node["u"]) - master_displacement(state, point, normal)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("before")
    parser.add_argument("after")
    args = parser.parse_args(argv)
    before, after = load(args.before), load(args.after)
    print("node  state  |tangential slide|  |normal approach|  |lambda_t|/|lambda_n|")
    slides = []
    for key, node in sorted(after.items()):
        if key[0] != "Contact_slave" or not node["active"]:
            continue
        normal = np.array(node["normal"])
        motion = relative_displacement(after, node, normal) - relative_displacement(before, before[key], normal)
        tangential = motion - normal * normal.dot(motion)
        multiplier = np.array(node["lm_vector"] or [0.0, 0.0, 0.0])
        lambda_t = multiplier - normal * normal.dot(multiplier)
        ratio = np.linalg.norm(lambda_t) / max(abs(normal.dot(multiplier)), 1e-300)
        state = "slip" if node["slip"] else "stick"
        print(f"{key[1]:5d}  {state:5s}  {np.linalg.norm(tangential):17.3e}  {abs(normal.dot(motion)):16.3e}"
              f"  {ratio:20.3f}")
        if not node["slip"]:
            slides.append(np.linalg.norm(tangential))
    if slides:
        print(f"sticking nodes: {len(slides)}, largest slide {max(slides):.3e}, mean {np.mean(slides):.3e}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
