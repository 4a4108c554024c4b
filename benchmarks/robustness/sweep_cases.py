#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 10: the cases of the robustness sweep, frictionless two-body contact in the Kratos input
format: a gmsh file with physical groups (mortarcontact reads it with input_type "gmsh"; Kratos 10.4
the mdpa that mortarcontact.cases.mesh_files.write_kratos_mdpa makes of it) + materials.json +
ProjectParameters.json.

Every case is one upper body pressed onto a lower body along the vertical axis (y in 2D, z in
3D). The lower body, [-W/2, W/2]^(d-1) x [-H, 0], is clamped at its bottom; the upper body's top
is pushed down (displacement control, all components prescribed) or loaded (force control, the
lateral components held). A variant (class ``Variant``) combines:

- dimension and element types of the upper and lower bodies (tri / quad, tet / hex; mixed
  interfaces such as a tet slave on a hex master), structured (numpy) or unstructured (gmsh)
- the interface shape: ``flat``; ``curved`` (the upper body's underside is a cylinder / sphere of
  radius R, Hertz-like); ``inclined`` (both faces tilted by 15 degrees about the y axis, load still
  vertical); and the whole model rotated (``rot30``: by 30 degrees about z in 2D, about (1,1,1)
  in 3D, the prescribed displacement rotated with it)
- the element size ratio r = h_upper / h_lower (0.25 ... 4; 1 +- 0.001: same element count,
  upper body 0.1 % wider or narrower, so that its interface nodes sit just beside the lower ones)
- overhangs: the upper body wider (``overhang-slave``), the lower one wider (``overhang-master``)
  or both bodies shifted by W/4 against each other (``overhang-both``); in 3D in x only or in x and y
- the initial gap at the first contact point: 1e-3 (``gap``), 0 (``zero``), -2e-4 (``pen``)
- load steps (1, 4, 20); displacement control (``disp``) or force control by LINE_LOAD /
  SURFACE_LOAD on top conditions or POINT_LOAD on the top nodes (only without an initial gap:
  force control across a gap leaves the upper body free)
- roles: the upper body is the slave, or with ``swapped`` the lower one (the same geometry, so
  "overhang-slave" and r keep naming the upper body)
- formulation: ALMContactFrictionless (``alm``), ALMContactFrictionlessComponents (``comp``),
  PenaltyContactFrictionless (``penalty``), ALMContactFrictional (``fric``, Coulomb friction with the
  coefficient ``mu`` of both bodies, issue 12); ``nv``: normal_variation nodal_elemental_derivatives
- ``shift`` (frictional cases): the indentation (displacement control, ``steps`` steps) is followed
  by as many steps in which the top is held at its depth and moved along x by SHIFT
- kinematics: small displacement (``sd``, the default), total Lagrangian with the linear law
  (``tl``, Saint Venant-Kirchhoff), updated Lagrangian with the neo-Hookean law (``ul``)
- interface sub-model-parts with nodes only (the contact process builds the faces) or with
  explicit LineCondition2D2N / SurfaceCondition3D{3,4}N (``conditions``).

The sub-model-parts carry fixed names (Contact_slave, Contact_master, DISPLACEMENT_bottom,
DISPLACEMENT_top, LOAD_top, Parts_upper, Parts_lower), so one runner reads every case.

    python benchmarks/robustness/sweep_cases.py --list
    python benchmarks/robustness/sweep_cases.py --filter 2d_quad --out /tmp/cases
"""
from __future__ import annotations

import argparse
import dataclasses
import math
import os
import re
import sys

import numpy as np

from mortarcontact.cases import hertz  # gmsh meshing, Kuhn tetrahedra
from mortarcontact.cases.mesh_files import write_case_mesh, write_json_files

HERE = os.path.dirname(os.path.abspath(__file__))

DEFAULT_OUT = os.path.join(HERE, "cases")

WIDTH = 1.0
LOWER_HEIGHT = 0.5
UPPER_HEIGHT = {"flat": 0.5, "inclined": 0.5, "curved": 0.6}
RADIUS = 1.0
INCLINATION = math.radians(15.0)
ROTATION = math.radians(30.0)
YOUNG = {"upper": 1000.0, "lower": 2000.0}  # unequal, so that swapping the roles changes the problem
POISSON = 0.3
GAPS = {"gap": 1e-3, "zero": 0.0, "pen": -2e-4}
APPROACH = {"flat": 0.01, "inclined": 0.01, "curved": 0.02}  # prescribed top displacement beyond the gap
LOAD = {"flat": 10.0, "inclined": 10.0, "curved": 4.0}  # force control: load per unit top area
SHIFT = 0.02  # tangential shift of the top after the indentation (frictional cases)
H_LOWER = {2: 1.0 / 16.0, 3: 1.0 / 5.0}
H_LOWER_COARSE = {2: 1.0 / 5.0, 3: 1.0 / 3.0}  # the smallest cases that still show each failure
MAX_LAYERS_3D = 6  # through-thickness element layers of a fine 3D body (keeps the DoFs in the thousands)

FORMULATIONS = {
    "alm": ("ALMContactFrictionless", "Frictionless", "alm_contact_process", "ALMContactProcess"),
    "comp": ("ALMContactFrictionlessComponents", "FrictionlessComponents", "alm_contact_process",
             "ALMContactProcess"),
    "penalty": ("PenaltyContactFrictionless", "Frictionless", "penalty_contact_process", "PenaltyContactProcess"),
    "fric": ("ALMContactFrictional", "Frictional", "alm_contact_process", "ALMContactProcess"),
}
KINEMATICS = {"sd": ("SmallDisplacementElement", "LinearElastic"),
              "tl": ("TotalLagrangianElement", "LinearElastic"),
              "ul": ("UpdatedLagrangianElement", "HyperElastic")}
NODES_PER_ELEMENT = {"tri": 3, "quad": 4, "tet": 4, "hex": 8}
# Local faces (2D: edges) of each element type; orientation is fixed afterwards (outward).
LOCAL_FACES = {
    "tri": [(0, 1), (1, 2), (2, 0)],
    "quad": [(0, 1), (1, 2), (2, 3), (3, 0)],
    "tet": [(0, 1, 2), (0, 1, 3), (1, 2, 3), (0, 2, 3)],
    "hex": [(0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)],
}


@dataclasses.dataclass(frozen=True)
class Variant:
    dim: int
    upper: str  # element type of the upper body: tri, quad (2D); tet, hex (3D)
    lower: str
    shape: str = "flat"  # flat, curved, inclined
    ratio: float = 1.0  # h_upper / h_lower
    overhang: str = "none"  # none, slave, master, both; 3D: with -x or -xy
    gap: str = "gap"  # gap, zero, pen
    control: str = "disp"  # disp, line, surface, point
    steps: int = 4
    formulation: str = "alm"
    swapped: bool = False
    nv: bool = False
    kinematics: str = "sd"
    rotated: bool = False
    mesher: str = "grid"  # grid (numpy, structured) or gmsh (unstructured triangles / tetrahedra)
    conditions: bool = False
    coarse: bool = False  # lower body's element size H_LOWER_COARSE
    mu: float = 0.0  # friction coefficient (formulation "fric")
    shift: bool = False  # tangential shift after the indentation

    @property
    def name(self) -> str:
        elements = self.upper if self.upper == self.lower else f"{self.upper}-on-{self.lower}"
        control = "disp" if self.control == "disp" else f"{self.control}-load"
        parts = [f"{self.dim}d", elements, self.shape, f"r{self.ratio:g}", f"overhang-{self.overhang}", self.gap,
                 control, f"{self.steps}step" + ("s" if self.steps > 1 else ""), self.formulation]
        if self.formulation == "fric":
            parts.append(f"mu{self.mu:g}")
        if self.shift:
            parts.append("shift")
        parts += [flag for flag, on in (("nv", self.nv), ("swapped", self.swapped), ("rot30", self.rotated),
                                        ("gmsh", self.mesher == "gmsh"), ("conditions", self.conditions),
                                        ("coarse", self.coarse))
                  if on]
        if self.kinematics != "sd":
            parts.append(self.kinematics)
        return "_".join(parts)

    @property
    def symmetric(self) -> bool:
        """Mesh, geometry and loading mirror-symmetric about the vertical plane(s) through the axis,
        so that the exact discrete solution has no lateral reaction."""
        return (self.mesher == "grid" and self.shape != "inclined" and not self.overhang.startswith("both")
                and not self.rotated and {self.upper, self.lower} <= {"quad", "hex"})

    def check(self) -> None:
        kinds = ("tri", "quad") if self.dim == 2 else ("tet", "hex")
        assert self.upper in kinds and self.lower in kinds, self
        assert self.control in (("disp", "line", "point") if self.dim == 2 else ("disp", "surface", "point")), self
        assert self.control == "disp" or (self.gap != "gap" and not self.rotated), self  # rigid-body mode
        assert self.mesher == "grid" or ("quad" not in (self.upper, self.lower)
                                         and "hex" not in (self.upper, self.lower))
        direction = self.overhang.partition("-")[2]
        assert (self.overhang == "none") or (direction in ("x", "xy")) == (self.dim == 3), self
        assert (self.formulation == "fric") == (self.mu > 0.0), self
        assert not self.shift or (self.formulation == "fric" and self.control == "disp" and not self.rotated), self

    @property
    def frictional(self) -> bool:
        return self.formulation == "fric"


# -- the sweep --------------------------------------------------------------------------------
def variants() -> list[Variant]:
    """The cases, by family: each varies one or two aspects of a small base case."""
    b2 = Variant(2, "quad", "quad", ratio=0.5)
    b3 = Variant(3, "hex", "hex", ratio=0.5)
    r = dataclasses.replace
    out = []
    # element types and mixed interfaces, flat and curved
    for base, kinds in ((b2, ("tri", "quad")), (b3, ("tet", "hex"))):
        for upper in kinds:
            for lower in kinds:
                out += [r(base, upper=upper, lower=lower), r(base, upper=upper, lower=lower, shape="curved")]
    # element size ratios (1 +- 0.001: nearly matching nodes)
    for ratio in (0.25, 0.5, 0.999, 1.0, 1.001, 2.0, 4.0):
        out += [r(b2, ratio=ratio), r(b2, upper="tri", lower="tri", shape="curved", ratio=ratio)]
    for ratio in (0.25, 0.999, 1.0, 1.001, 2.0, 4.0):
        out.append(r(b3, ratio=ratio))
    for ratio in (1.0, 2.0):  # coarser, the upper body's cap has no node near its apex
        out.append(r(b3, upper="tet", shape="curved", ratio=ratio))
    # overhangs: flat and curved, 2D and 3D in one and in two directions
    for overhang in ("slave", "master", "both"):
        out += [r(b2, overhang=overhang), r(b2, shape="curved", overhang=overhang),
                r(b2, upper="tri", lower="tri", overhang=overhang, ratio=1.0)]
        for direction in ("x", "xy"):
            out += [r(b3, overhang=f"{overhang}-{direction}"),
                    r(b3, shape="curved", overhang=f"{overhang}-{direction}")]
    out.append(r(b2, shape="curved", overhang="slave", upper="tri", lower="tri", ratio=1.0, steps=1))
    # gap, zero gap and penetration under displacement and force control
    for gap in ("gap", "zero", "pen"):
        out += [r(b2, gap=gap), r(b2, shape="curved", gap=gap), r(b3, gap=gap), r(b3, shape="curved", gap=gap)]
    for gap in ("zero", "pen"):
        out += [r(b2, gap=gap, control="line"), r(b2, gap=gap, control="point"), r(b3, gap=gap, control="surface"),
                r(b2, shape="curved", gap=gap, control="line"), r(b3, shape="curved", gap=gap, control="surface")]
    out += [r(b3, gap="pen", control="point"), r(b2, shape="inclined", gap="zero", control="line"),
            r(b3, upper="tet", lower="tet", gap="pen", control="surface")]
    # load steps
    for steps in (1, 20):
        out += [r(b2, steps=steps), r(b2, shape="curved", steps=steps), r(b3, steps=steps),
                r(b3, shape="curved", steps=steps)]
    # formulations, normal variation
    for formulation in ("comp", "penalty"):
        out += [r(b2, formulation=formulation), r(b2, shape="curved", formulation=formulation),
                r(b2, upper="tri", overhang="slave", formulation=formulation),
                r(b3, formulation=formulation), r(b3, shape="curved", formulation=formulation),
                r(b3, upper="tet", overhang="both-xy", formulation=formulation),
                r(b2, gap="pen", control="line", formulation=formulation)]
    out += [r(b2, nv=True), r(b2, shape="curved", nv=True), r(b3, nv=True), r(b3, shape="curved", nv=True),
            r(b2, shape="curved", nv=True, formulation="comp"), r(b2, shape="inclined", nv=True)]
    out += [r(b2, nv=True, formulation="penalty"), r(b2, shape="curved", nv=True, formulation="penalty"),
            r(b3, nv=True, formulation="penalty"), r(b3, shape="curved", nv=True, formulation="penalty"),
            r(b2, gap="pen", control="line", nv=True, formulation="penalty")]
    # inclined and rotated models
    for base in (b2, b3):
        out += [r(base, shape="inclined"), r(base, shape="inclined", ratio=2.0),
                r(base, rotated=True), r(base, shape="curved", rotated=True), r(base, shape="inclined", rotated=True)]
    out.append(r(b2, upper="tri", lower="tri", shape="curved", overhang="both", rotated=True))
    # roles exchanged on the same geometry
    out += [r(b2, swapped=True), r(b2, shape="curved", swapped=True), r(b2, overhang="slave", swapped=True),
            r(b2, upper="tri", ratio=4.0, swapped=True), r(b3, swapped=True), r(b3, shape="curved", swapped=True),
            r(b3, upper="tet", overhang="slave-xy", swapped=True), r(b2, shape="inclined", swapped=True)]
    # finite strain kinematics
    for kinematics in ("tl", "ul"):
        out += [r(b2, kinematics=kinematics), r(b2, shape="curved", kinematics=kinematics),
                r(b3, kinematics=kinematics), r(b3, upper="tet", shape="curved", kinematics=kinematics)]
    # unstructured (gmsh) meshes
    for ratio in (0.5, 1.0, 2.0):
        out += [Variant(2, "tri", "tri", shape="curved", ratio=ratio, mesher="gmsh"),
                Variant(3, "tet", "tet", shape="curved", ratio=ratio, mesher="gmsh")]
    out += [Variant(2, "tri", "tri", ratio=0.7, overhang="master", mesher="gmsh"),
            Variant(3, "tet", "tet", ratio=1.3, overhang="both-x", mesher="gmsh")]
    # explicit interface conditions
    out += [r(b2, conditions=True), r(b2, shape="curved", upper="tri", conditions=True), r(b3, conditions=True),
            r(b3, upper="tet", shape="curved", conditions=True)]
    # the smallest cases that show what the families above show (tests/python/test_robustness_sweep.py)
    c2 = Variant(2, "quad", "quad", ratio=0.5, steps=1, coarse=True)
    c3 = Variant(3, "hex", "hex", ratio=0.5, steps=1, coarse=True)
    out += [c2, r(c2, overhang="master"), r(c2, ratio=1.0, overhang="both"), r(c2, shape="curved"),
            r(c2, upper="tri", lower="tri", shape="curved", ratio=1.0, overhang="slave"),
            r(c2, ratio=0.25, steps=4), r(c2, formulation="comp"), r(c2, formulation="penalty"), r(c2, rotated=True),
            r(c2, gap="pen", control="line"), c3, r(c3, upper="tet"), r(c3, overhang="slave-xy", steps=4),
            r(c3, shape="curved"), r(c3, upper="tet", shape="curved", ratio=1.0), r(c3, overhang="both-xy")]
    out += frictional_variants()
    unique = list(dict.fromkeys(out))
    for v in unique:
        v.check()
    return unique


def frictional_variants() -> list[Variant]:
    """Issue 12: static indentation followed by a tangential shift with Coulomb friction (mu 0.1 to
    0.8), flat and curved, matching and non-matching meshes, the slave overhanging the master,
    structured and unstructured, 2D and 3D."""
    r = dataclasses.replace
    f2 = Variant(2, "quad", "quad", ratio=0.5, formulation="fric", mu=0.3, shift=True)
    f3 = Variant(3, "hex", "hex", ratio=0.5, formulation="fric", mu=0.3, shift=True)
    out = []
    for shape in ("flat", "curved"):
        out += [r(f2, shape=shape, mu=mu) for mu in (0.1, 0.3, 0.8)]
        out += [r(f2, shape=shape, ratio=1.0), r(f2, shape=shape, overhang="slave")]
        out += [r(f3, shape=shape, mu=mu) for mu in ((0.1, 0.3, 0.8) if shape == "curved" else (0.3,))]
        out += [r(f3, shape=shape, ratio=1.0), r(f3, shape=shape, overhang="slave-x")]
    out += [r(f2, upper="tri", lower="tri", shape="curved", ratio=1.0),
            r(f3, upper="tet", shape="curved"),
            Variant(2, "tri", "tri", shape="curved", ratio=1.0, mesher="gmsh", formulation="fric", mu=0.3, shift=True),
            Variant(3, "tet", "tet", shape="curved", ratio=1.0, mesher="gmsh", formulation="fric", mu=0.3, shift=True)]
    return out


def by_name() -> dict[str, Variant]:
    return {v.name: v for v in variants()}


# -- meshing ----------------------------------------------------------------------------------
def grid_body(dim: int, lo: np.ndarray, hi: np.ndarray, counts: list[int], kind: str):
    """Structured mesh of the box [lo, hi]: nodes (n, 3) and 0-based cells, positively oriented
    (quads counter-clockwise; hexahedra bottom then top face; triangles and Kuhn tetrahedra
    from splitting them)."""
    axes = [np.linspace(lo[i], hi[i], counts[i] + 1) for i in range(dim)]
    grid = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, dim)
    xyz = np.zeros((len(grid), 3))
    xyz[:, :dim] = grid
    index = np.arange(len(grid)).reshape([c + 1 for c in counts])
    if dim == 2:
        i, j = np.meshgrid(np.arange(counts[0]), np.arange(counts[1]), indexing="ij")
        a, b, c, d = index[i, j], index[i + 1, j], index[i + 1, j + 1], index[i, j + 1]
        quads = np.stack([a, b, c, d], axis=-1).reshape(-1, 4)
        if kind == "quad":
            return xyz, quads
        return xyz, np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    i, j, k = np.meshgrid(*(np.arange(c) for c in counts), indexing="ij")
    corner = {(di, dj, dk): index[i + di, j + dj, k + dk].ravel() for di in (0, 1) for dj in (0, 1) for dk in (0, 1)}
    if kind == "hex":
        order = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
        return xyz, np.stack([corner[c] for c in order], axis=-1)
    tets = np.concatenate([np.stack([corner[c] for c in tet], axis=-1) for tet in hertz.KUHN_TETRAHEDRA])
    return xyz, hertz.oriented_tetrahedra(xyz, tets)


def gmsh_body(dim: int, lo: np.ndarray, hi: np.ndarray, size: float):
    """Unstructured triangles / tetrahedra of the box [lo, hi] with a uniform size."""
    import gmsh

    def box():
        if dim == 2:
            gmsh.model.occ.addRectangle(lo[0], lo[1], 0.0, hi[0] - lo[0], hi[1] - lo[1])
        else:
            gmsh.model.occ.addBox(*lo, *(hi - lo))
        gmsh.model.occ.synchronize()

    [(xyz, cells)] = hertz.mesh_bodies(dim, lambda *_: size, box)
    return xyz, cells


def oriented_faces(xyz: np.ndarray, cells: np.ndarray, kind: str, on: np.ndarray) -> np.ndarray:
    """The element faces (2D: edges) whose nodes all satisfy the mask ``on``, numbered so that
    their normal points out of their element."""
    faces = []
    for local in LOCAL_FACES[kind]:
        nodes = cells[:, local]
        keep = on[nodes].all(axis=1)
        nodes, owners = nodes[keep], cells[keep]
        p = xyz[nodes]
        if len(local) == 2:
            edge = p[:, 1] - p[:, 0]
            normal = np.column_stack([edge[:, 1], -edge[:, 0], np.zeros(len(edge))])
        else:
            normal = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
        outward = np.einsum("ij,ij->i", normal, p.mean(axis=1) - xyz[owners].mean(axis=1)) > 0.0
        faces.append(np.where(outward[:, None], nodes, nodes[:, ::-1]))
    return np.concatenate(faces)


def _rotation(dim: int) -> np.ndarray:
    if dim == 2:
        c, s = math.cos(ROTATION), math.sin(ROTATION)
        return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    axis = np.ones(3) / math.sqrt(3.0)
    k = np.array([[0.0, -axis[2], axis[1]], [axis[2], 0.0, -axis[0]], [-axis[1], axis[0], 0.0]])
    return np.eye(3) + math.sin(ROTATION) * k + (1.0 - math.cos(ROTATION)) * k @ k


def _widths(v: Variant) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Lateral extents (per horizontal axis) of the upper and lower bodies and the upper body's
    centre."""
    n = v.dim - 1
    upper, lower, centre = np.full(n, WIDTH), np.full(n, WIDTH), np.zeros(n)
    kind, _, direction = v.overhang.partition("-")
    axes = range(n) if v.dim == 2 or direction == "xy" else [0]
    for a in axes:
        if kind == "slave":
            lower[a] = 0.6 * WIDTH
        elif kind == "master":
            upper[a] = 0.6 * WIDTH
        elif kind == "both":
            centre[a] = 0.25 * WIDTH
    return upper, lower, centre


def build(v: Variant) -> dict:
    """Meshes both bodies of a variant; returns coordinates, cells and the node sets and faces
    the case needs (no files)."""
    dim, vertical = v.dim, v.dim - 1
    w_upper, w_lower, centre = _widths(v)
    h_lower = (H_LOWER_COARSE if v.coarse else H_LOWER)[dim]
    h_upper = v.ratio * h_lower
    nearly_matching = abs(v.ratio - 1.0) < 0.01
    t_upper = UPPER_HEIGHT[v.shape]
    gap = GAPS[v.gap]

    def counts(widths, height, h):
        layers = max(2, round(height / h))
        if dim == 3:
            layers = min(layers, MAX_LAYERS_3D)
        return [max(1, round(w / h)) for w in widths] + [layers]

    if nearly_matching:  # the lower body's element count, the width stretched by r
        n_upper = counts(w_upper, t_upper, h_lower)
        w_upper = w_upper * v.ratio
    else:
        n_upper = counts(w_upper, t_upper, h_upper)
    bodies = {}
    for key, widths, middle, height, n, kind in (
            ("upper", w_upper, centre, t_upper, n_upper, v.upper),
            ("lower", w_lower, np.zeros(dim - 1), LOWER_HEIGHT, counts(w_lower, LOWER_HEIGHT, h_lower), v.lower)):
        lo = np.append(middle - 0.5 * widths, 0.0 if key == "upper" else -height)
        hi = np.append(middle + 0.5 * widths, height if key == "upper" else 0.0)
        if v.mesher == "gmsh":
            xyz, cells = gmsh_body(dim, lo, hi, h_upper if key == "upper" else h_lower)
        else:
            xyz, cells = grid_body(dim, lo, hi, n, kind)
        tol = 1e-9 * WIDTH
        s = xyz[:, vertical].copy()
        bodies[key] = {"xyz": xyz, "cells": cells, "kind": kind, "area": float(np.prod(widths)),
                       "interface": np.abs(s) < tol, "end": np.abs(s - (height if key == "upper" else -height)) < tol}
        # Map the reference box onto the body: the interface surface moves to its shape, the
        # opposite face stays flat, the nodes in between follow linearly.
        lateral = xyz[:, :dim - 1]
        if v.shape == "curved" and key == "upper":
            r2 = ((lateral - centre) ** 2).sum(axis=1)
            surface = RADIUS - np.sqrt(RADIUS ** 2 - r2)
        elif v.shape == "inclined":
            surface = math.tan(INCLINATION) * lateral[:, 0]
        else:
            surface = np.zeros(len(xyz))
        if key == "upper":
            xyz[:, vertical] = gap + surface + s * (height - surface) / height
        else:
            xyz[:, vertical] = s + surface * (s + height) / height
    return bodies


def write_case(v: Variant, out_dir: str = DEFAULT_OUT) -> str:
    """Writes one case into ``out_dir/<name>/`` and returns that folder."""
    name = v.name
    folder = os.path.join(out_dir, name)
    os.makedirs(folder, exist_ok=True)
    bodies = build(v)
    dim = v.dim
    offset = len(bodies["upper"]["xyz"])
    coords = np.vstack([bodies["upper"]["xyz"], bodies["lower"]["xyz"]])
    for body, shift in ((bodies["upper"], 0), (bodies["lower"], offset)):
        body["nodes"] = shift + np.arange(len(body["xyz"]))
        body["global_cells"] = body["cells"] + shift
    if v.rotated:
        coords = coords @ _rotation(dim).T
    element_stem, law = KINEMATICS[v.kinematics]
    element_blocks, parts, first = [], {}, 1
    for key in ("upper", "lower"):
        body = bodies[key]
        cells = body["global_cells"]
        element_blocks.append((f"{element_stem}{dim}D{cells.shape[1]}N", first, cells))
        parts[f"Parts_{key}"] = {"nodes": body["nodes"], "elements": first + np.arange(len(cells))}
        first += len(cells)
    on = np.zeros(len(coords), dtype=bool)
    slave_key, master_key = ("lower", "upper") if v.swapped else ("upper", "lower")
    condition_blocks, first_condition = [], 1

    def faces_of(key, mask):
        body = bodies[key]
        on[:] = False
        on[body["nodes"][mask]] = True
        return oriented_faces(coords, body["global_cells"], body["kind"], on)

    for role, key in (("slave", slave_key), ("master", master_key)):
        faces = faces_of(key, bodies[key]["interface"])
        part = {"nodes": np.unique(faces)}
        if v.conditions:
            stem = "LineCondition2D2N" if dim == 2 else f"SurfaceCondition3D{faces.shape[1]}N"
            condition_blocks.append((stem, first_condition, faces))
            part["conditions"] = first_condition + np.arange(len(faces))
            first_condition += len(faces)
        parts[f"Contact_{role}"] = part
    parts["DISPLACEMENT_bottom"] = {"nodes": bodies["lower"]["nodes"][bodies["lower"]["end"]]}
    top = bodies["upper"]["nodes"][bodies["upper"]["end"]]
    parts["DISPLACEMENT_top"] = {"nodes": top}
    if v.control in ("line", "surface"):
        faces = faces_of("upper", bodies["upper"]["end"])
        stem = "LineLoadCondition2D2N" if dim == 2 else f"SurfaceLoadCondition3D{faces.shape[1]}N"
        condition_blocks.append((stem, first_condition, faces))
        parts["LOAD_top"] = {"nodes": top, "conditions": first_condition + np.arange(len(faces))}
    elif v.control == "point":
        condition_blocks.append((f"PointLoadCondition{dim}D1N", first_condition, top[:, None]))
        parts["LOAD_top"] = {"nodes": top, "conditions": first_condition + np.arange(len(top))}
    for part_name, content in parts.items():
        if len(content["nodes"]) == 0:
            raise RuntimeError(f"{name}: sub-model-part {part_name} is empty")
    model_import = write_case_mesh(os.path.join(folder, f"{name}.msh"), coords, element_blocks, parts,
                                   condition_blocks)
    files = {f"{name}_materials.json": materials(dim, law, v.mu),
             "ProjectParameters.json": project_parameters(v, len(top), bodies["upper"]["area"], model_import)}
    write_json_files(folder, files)
    return folder


# -- parameters -------------------------------------------------------------------------------
def materials(dim: int, law: str, mu: float = 0.0) -> dict:
    suffix = "PlaneStrain2DLaw" if dim == 2 else "3DLaw"
    properties = []
    for pid, key in ((1, "upper"), (2, "lower")):
        variables = {"YOUNG_MODULUS": YOUNG[key], "POISSON_RATIO": POISSON, "DENSITY": 1.0}
        if mu > 0.0:
            variables["FRICTION_COEFFICIENT"] = mu
        if dim == 2:
            variables["THICKNESS"] = 1.0
        properties.append({"model_part_name": f"Structure.Parts_{key}", "properties_id": pid,
                           "Material": {"name": key, "constitutive_law": {"name": law + suffix},
                                        "Variables": variables, "Tables": {}}})
    return {"properties": properties}


def _vector_process(module: str, process: str, part: str, variable: str, value: list,
                    constrained: list | None = None) -> dict:
    parameters = {"model_part_name": f"Structure.{part}", "variable_name": variable, "interval": [0.0, "End"],
                  "value": value}
    if constrained is not None:
        parameters["constrained"] = constrained
    return {"python_module": module, "kratos_module": "KratosMultiphysics", "process_name": process,
            "Parameters": parameters}


def _time_expression(component) -> float | str:
    return 0.0 if component == 0.0 else f"{float(component)!r}*t"


def project_parameters(v: Variant, top_nodes: int, top_area: float, model_import: dict) -> dict:
    dim, vertical = v.dim, v.dim - 1
    down = np.zeros(3)
    down[vertical] = -1.0
    if v.rotated:
        down = _rotation(dim) @ down
    constraints = [hertz.assign_displacement("DISPLACEMENT_bottom", [True] * 3, [0.0] * 3)]
    loads = []
    if v.control == "disp" and v.shift:
        # Two intervals, as Kratos 10.4's function parser knows no min / max: down to the depth
        # by t = 1/2, then held there and moved along x.
        depth = (APPROACH[v.shape] + GAPS[v.gap]) * down
        half_step = 0.25 / v.steps
        approach = hertz.assign_displacement("DISPLACEMENT_top", [True] * 3,
                                             [0.0 if c == 0.0 else f"{2.0 * float(c)!r}*t" for c in depth])
        approach["Parameters"]["interval"] = [0.0, 0.5 + half_step]
        sliding = hertz.assign_displacement("DISPLACEMENT_top", [True] * 3,
                                            [f"{2.0 * SHIFT!r}*(t-0.5)", *[float(c) for c in depth[1:]]])
        sliding["Parameters"]["interval"] = [0.5 + half_step, "End"]
        constraints += [approach, sliding]
    elif v.control == "disp":
        value = [_time_expression(c) for c in (APPROACH[v.shape] + GAPS[v.gap]) * down]
        constraints.append(hertz.assign_displacement("DISPLACEMENT_top", [True] * 3, value))
    else:  # lateral components held, the vertical one loaded
        held = [axis < vertical for axis in range(3)]
        constraints.append(hertz.assign_displacement("DISPLACEMENT_top", held, [0.0] * 3))
        force = LOAD[v.shape] * (top_area if v.control == "point" else 1.0)
        if v.control == "point":
            force /= top_nodes
        variable = {"line": "LINE_LOAD", "surface": "SURFACE_LOAD", "point": "POINT_LOAD"}[v.control]
        loads.append(_vector_process("assign_vector_variable_to_conditions_process",
                                     "AssignVectorVariableToConditionsProcess", "LOAD_top", variable,
                                     [_time_expression(c) for c in force * down]))
    mortar_type, contact_type, module, process = FORMULATIONS[v.formulation]
    contact = {"model_part_name": "Structure", "contact_type": contact_type,
               "contact_model_part": {"0": ["Contact_slave", "Contact_master"]},
               "assume_master_slave": {"0": ["Contact_slave"]}}
    if v.nv:
        contact["normal_variation"] = "nodal_elemental_derivatives"
    solver_extra = {"buffer_size": 3} if v.frictional else {}
    return {
        "problem_data": {"problem_name": v.name, "parallel_type": "OpenMP", "echo_level": 0,
                         "start_time": 0.0, "end_time": 1.0},
        "solver_settings": {
            **solver_extra,
            "model_part_name": "Structure", "domain_size": dim, "solver_type": "Static", "echo_level": 0,
            "analysis_type": "non_linear",
            "model_import_settings": model_import,
            "material_import_settings": {"materials_filename": f"{v.name}_materials.json"},
            "contact_settings": {"mortar_type": mortar_type},
            "time_stepping": {"time_step": 1.0 / (2 * v.steps if v.shift else v.steps)},
            "block_builder": True, "line_search": False, "compute_reactions": True,
            # Tight tolerances: a solution within 1e-6 of Kratos' is only asked of converged
            # iterates that are themselves that close to the exact discrete solution.
            "convergence_criterion": "contact_residual_criterion",
            "displacement_relative_tolerance": 1e-6, "displacement_absolute_tolerance": 1e-12,
            "residual_relative_tolerance": 1e-6, "residual_absolute_tolerance": 1e-12,
            "max_iteration": 30,
            "linear_solver_settings": {"solver_type": "LinearSolversApplication.sparse_lu"},
        },
        "processes": {
            "constraints_process_list": constraints,
            "loads_process_list": loads,
            "contact_process_list": [{
                "python_module": module,
                "kratos_module": "KratosMultiphysics.ContactStructuralMechanicsApplication",
                "process_name": process, "Parameters": contact}],
        },
        "output_processes": {},
    }


def select(pattern: str | None = None, names: list[str] | None = None) -> list[Variant]:
    """Variants whose name matches the regular expression ``pattern`` and is in ``names``."""
    chosen = variants()
    if pattern:
        chosen = [v for v in chosen if re.search(pattern, v.name)]
    if names is not None:
        known = by_name()
        unknown = [n for n in names if n not in known]
        if unknown:
            raise SystemExit(f"unknown case(s): {', '.join(unknown)}")
        chosen = [v for v in chosen if v.name in names]
    return chosen


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--filter", help="regular expression on the case names")
    parser.add_argument("--out", default=DEFAULT_OUT)
    parser.add_argument("--list", action="store_true", help="print the names only")
    args = parser.parse_args(argv)
    for v in select(args.filter):
        if args.list:
            print(v.name)
            continue
        folder = write_case(v, args.out)
        print(f"{v.name} -> {folder}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
