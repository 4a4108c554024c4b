# SPDX-License-Identifier: BSD-3-Clause
"""Issue 10: small structural cases (Kratos input format) that mortarcontact and Kratos 10.4 both run.

Every case is a cantilever-like block clamped on x = 0 (2D plane and 3D) or an axisymmetric ring
(x = radius in [1, 2], supported axially on z = 0), meshed with one element type, one
constitutive law and one kind of load, ramped linearly over two load steps. The meshes are
structured, then mapped by y -> y (1 + 0.1 x / L) so that no element is a rectangle. Everything
is deterministic: the same call writes the same bytes.

Families (see ``all_cases``):
- matrix: every registered element (small displacement, total and updated Lagrangian, plain and
  axisymmetric, every geometry) x every law Kratos 10.4 also has, under the distributed load of
  the element's own order (LINE_LOAD in 2D, SURFACE_LOAD in 3D);
- loads: every load type (point, line, surface, positive and negative face pressure, body
  force, axisymmetric point and line loads) on one element per dimension and kinematics;
- dynamic: implicit Bossak and Newmark on a small and a finite-strain cantilever;
- check: Kratos' axisymmetric small-displacement element without mesh motion, and a homogeneous
  axisymmetric finite stretch with a closed form;
- cantilever_plane_stress: the THICKNESS = 0.1 plane-stress cantilever of issue 10 (Timoshenko).

    python parity_cases.py OUTPUT_DIR [--filter SUBSTRING]
"""
from __future__ import annotations

import argparse
import itertools
import json
import os
from dataclasses import dataclass, field

import numpy as np

YOUNG, POISSON, DENSITY = 1000.0, 0.3, 1.0
PLANE_THICKNESS = 0.1

# Element nodes as averages of the cell corners (lattice points of the doubled grid), in the
# node order of the Kratos geometries.
_SQUARE = ((0, 0), (1, 0), (1, 1), (0, 1))
_CUBE = ((0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1))
_QUAD_EDGES = ((0, 1), (1, 2), (2, 3), (3, 0))
_HEX_EDGES = ((0, 1), (1, 2), (2, 3), (3, 0), (0, 4), (1, 5), (2, 6), (3, 7), (4, 5), (5, 6), (6, 7), (7, 4))
_HEX_FACES = ((0, 1, 2, 3), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7), (4, 5, 6, 7))
_TRI_EDGES = ((0, 1), (1, 2), (2, 0))
_TET_EDGES = ((0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3))
# Two counter-clockwise triangles per square; six positive Kuhn tetrahedra per cube around the
# 0-6 diagonal (neighbouring cubes share their face diagonals); two prisms per cube.
_SQUARE_TRIANGLES = ((0, 1, 2), (0, 2, 3))
_KUHN = ((0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6))
_CUBE_PRISMS = ((0, 1, 2, 4, 5, 6), (0, 2, 3, 4, 6, 7))

# Outward faces (2D: edges) of each element, in the node order of the face geometry.
_FACES = {
    "Triangle2D3": ((0, 1), (1, 2), (2, 0)),
    "Triangle2D6": ((0, 1, 3), (1, 2, 4), (2, 0, 5)),
    "Quadrilateral2D4": ((0, 1), (1, 2), (2, 3), (3, 0)),
    "Quadrilateral2D8": ((0, 1, 4), (1, 2, 5), (2, 3, 6), (3, 0, 7)),
    "Quadrilateral2D9": ((0, 1, 4), (1, 2, 5), (2, 3, 6), (3, 0, 7)),
    "Tetrahedra3D4": ((1, 2, 3), (0, 3, 2), (0, 1, 3), (0, 2, 1)),
    "Tetrahedra3D10": ((1, 2, 3, 5, 9, 8), (0, 3, 2, 7, 9, 6), (0, 1, 3, 4, 8, 7), (0, 2, 1, 6, 5, 4)),
    "Prism3D6": ((0, 2, 1), (3, 4, 5), (0, 1, 4, 3), (1, 2, 5, 4), (2, 0, 3, 5)),
}
_HEX_FACE_NODES = ((3, 2, 1, 0, 10, 9, 8, 11, 20), (0, 1, 5, 4, 8, 13, 16, 12, 21), (2, 6, 5, 1, 14, 17, 13, 9, 22),
                   (7, 6, 2, 3, 18, 14, 10, 15, 23), (7, 3, 0, 4, 15, 11, 12, 19, 24), (4, 5, 6, 7, 16, 17, 18, 19, 25))
for _n, _k in (("Hexahedra3D8", 4), ("Hexahedra3D20", 8), ("Hexahedra3D27", 9)):
    _FACES[_n] = tuple(f[:_k] for f in _HEX_FACE_NODES)

#: geometry name of an element suffix
GEOMETRIES = {"2D3N": "Triangle2D3", "2D6N": "Triangle2D6", "2D4N": "Quadrilateral2D4", "2D8N": "Quadrilateral2D8",
              "2D9N": "Quadrilateral2D9", "3D4N": "Tetrahedra3D4", "3D10N": "Tetrahedra3D10", "3D8N": "Hexahedra3D8",
              "3D20N": "Hexahedra3D20", "3D27N": "Hexahedra3D27", "3D6N": "Prism3D6"}
KINEMATICS = {"small": "SmallDisplacementElement", "total": "TotalLagrangianElement",
              "updated": "UpdatedLagrangianElement"}
#: laws of each state that mortarcontact and Kratos 10.4 both register (HyperElasticAxisym2DLaw
#: is mortarcontact's only: Kratos 10.4 has no axisymmetric Neo-Hookean law)
LAWS = {
    "plane_stress": ("LinearElasticPlaneStress2DLaw", "KirchhoffSaintVenantPlaneStress2DLaw"),
    "plane_strain": ("LinearElasticPlaneStrain2DLaw", "HyperElasticPlaneStrain2DLaw",
                     "KirchhoffSaintVenantPlaneStrain2DLaw"),
    "axisym": ("LinearElasticAxisym2DLaw",),
    "3d": ("LinearElastic3DLaw", "HyperElastic3DLaw", "KirchhoffSaintVenant3DLaw"),
}
LAW_TAGS = {"LinearElastic": "linear", "HyperElastic": "neohookean", "KirchhoffSaintVenant": "svk"}


# -- meshes -------------------------------------------------------------------------------------
def _cell_nodes(geometry: str, corners: list[tuple]) -> list[tuple]:
    """Lattice points (doubled grid) of one element whose corner lattice points are given."""
    def mid(*indices):
        return tuple(sum(corners[i][d] for i in indices) // len(indices) for d in range(len(corners[0])))

    if geometry in ("Triangle2D3", "Quadrilateral2D4", "Tetrahedra3D4", "Hexahedra3D8", "Prism3D6"):
        return list(corners)
    if geometry == "Triangle2D6":
        return list(corners) + [mid(*e) for e in _TRI_EDGES]
    if geometry == "Tetrahedra3D10":
        return list(corners) + [mid(*e) for e in _TET_EDGES]
    if geometry in ("Quadrilateral2D8", "Quadrilateral2D9"):
        nodes = list(corners) + [mid(*e) for e in _QUAD_EDGES]
        return nodes + ([mid(0, 1, 2, 3)] if geometry == "Quadrilateral2D9" else [])
    nodes = list(corners) + [mid(*e) for e in _HEX_EDGES]
    if geometry == "Hexahedra3D27":
        nodes += [mid(*f) for f in _HEX_FACES] + [mid(*range(8))]
    return nodes


def block_mesh(geometry: str, cells: tuple, size: tuple, origin: tuple):
    """Node coordinates (n, 3) and 1-based connectivity of a structured block of `cells` cells."""
    dim = len(cells)
    elements = []
    for cell in itertools.product(*(range(c) for c in cells)):
        base = [2 * c for c in cell]
        corners = [tuple(b + 2 * o for b, o in zip(base, offset)) for offset in (_SQUARE if dim == 2 else _CUBE)]
        if geometry.startswith("Triangle"):
            pieces = [[corners[i] for i in t] for t in _SQUARE_TRIANGLES]
        elif geometry.startswith("Tetrahedra"):
            pieces = [[corners[i] for i in t] for t in _KUHN]
        elif geometry.startswith("Prism"):
            pieces = [[corners[i] for i in t] for t in _CUBE_PRISMS]
        else:
            pieces = [corners]
        elements += [_cell_nodes(geometry, piece) for piece in pieces]
    points = sorted({p for e in elements for p in e})
    ids = {p: k + 1 for k, p in enumerate(points)}
    lattice = np.array(points, dtype=float)
    coords = np.zeros((len(points), 3))
    coords[:, :dim] = np.array(origin) + lattice / (2 * np.array(cells)) * np.array(size)
    length = size[0]
    coords[:, 1] = origin[1] + (coords[:, 1] - origin[1]) * (1.0 + 0.1 * (coords[:, 0] - origin[0]) / length)
    return coords, [[ids[p] for p in e] for e in elements]


def boundary_faces(geometry: str, connectivity, coords, axis: int, value: float):
    """Outward-oriented faces (edges in 2D) of the elements that lie on the plane x_axis = value."""
    faces = []
    for element in connectivity:
        for face in _FACES[geometry]:
            nodes = [element[i] for i in face]
            if all(abs(coords[n - 1][axis] - value) < 1e-12 for n in nodes):
                faces.append(nodes)
    return faces


# -- case description ---------------------------------------------------------------------------
@dataclass
class Case:
    name: str
    state: str                     # plane_stress | plane_strain | axisym | 3d
    element: str                   # registered element name
    law: str
    load: str                      # key of LOADS
    family: str
    cells: tuple = ()
    dynamic: str = ""              # "" (static) | bossak | newmark
    steps: int = 2
    extra: dict = field(default_factory=dict)

    @property
    def dim(self) -> int:
        return 3 if self.state == "3d" else 2


def _law_tag(law: str) -> str:
    return next(tag for stem, tag in LAW_TAGS.items() if law.startswith(stem))


def _geometry_of(element: str) -> str:
    return GEOMETRIES[element[element.index("Element") + len("Element"):]]


def _state_tag(state: str) -> str:
    return {"plane_stress": "ps", "plane_strain": "pe", "axisym": "ax", "3d": "3d"}[state]


def _element_name(state: str, kinematics: str, suffix: str) -> str:
    return ("Axisym" if state == "axisym" else "") + KINEMATICS[kinematics] + suffix


def all_cases() -> list[Case]:
    cases = []
    for state, laws in LAWS.items():
        suffixes = [s for s in GEOMETRIES if s.startswith("3D" if state == "3d" else "2D")]
        load = "surface" if state == "3d" else "line"
        for kinematics, suffix, law in itertools.product(KINEMATICS, suffixes, laws):
            element = _element_name(state, kinematics, suffix)
            name = f"matrix_{_state_tag(state)}_{element}_{_law_tag(law)}"
            cases.append(Case(name, state, element, law, load, "matrix"))
    load_types = {
        "plane_stress": ("point", "line", "positive_pressure", "negative_pressure", "body"),
        "plane_strain": ("point", "line", "positive_pressure", "negative_pressure", "body"),
        "axisym": ("point", "axisym_point", "line", "positive_pressure", "negative_pressure", "body"),
        "3d": ("point", "line3d", "surface", "positive_pressure", "negative_pressure", "body"),
    }
    for state, loads in load_types.items():
        suffix = "3D8N" if state == "3d" else "2D4N"
        law = LAWS[state][0] if state != "plane_strain" else "HyperElasticPlaneStrain2DLaw"
        for kinematics, load in itertools.product(KINEMATICS, loads):
            element = _element_name(state, kinematics, suffix)
            cases.append(Case(f"loads_{_state_tag(state)}_{kinematics}_{load}", state, element, law, load, "loads"))
        # quadratic load conditions
        for suffix in (("3D20N", "3D27N", "3D10N", "3D6N") if state == "3d" else ("2D8N",)):
            for load in (("surface", "positive_pressure") if state == "3d" else ("line", "positive_pressure")):
                element = _element_name(state, "total", suffix)
                cases.append(Case(f"loads_{_state_tag(state)}_total_{suffix}_{load}", state, element, law, load,
                                  "loads"))
    # Kratos' linear strategy: one solve per step on the mesh moved by the previous steps.
    for state, load in (("plane_stress", "line"), ("plane_strain", "positive_pressure"), ("3d", "surface"),
                        ("3d", "negative_pressure")):
        suffix = "3D8N" if state == "3d" else "2D4N"
        cases.append(Case(f"loads_{_state_tag(state)}_small_{load}_linear_analysis", state,
                          f"SmallDisplacementElement{suffix}", LAWS[state][0], load, "loads",
                          extra={"analysis_type": "linear"}))
    for scheme, kinematics in itertools.product(("bossak", "newmark"), ("small", "total")):
        element = _element_name("plane_strain", kinematics, "2D4N")
        law = "LinearElasticPlaneStrain2DLaw" if kinematics == "small" else "HyperElasticPlaneStrain2DLaw"
        cases.append(Case(f"dynamic_pe_{scheme}_{kinematics}", "plane_strain", element, law, "line", "dynamic",
                          dynamic=scheme, steps=5))
    # Checks of Kratos' axisymmetric elements: the small-displacement cases without mesh motion,
    # and a homogeneous finite stretch with a closed form (see run.py).
    for load in ("point", "body"):
        cases.append(Case(f"check_ax_small_{load}_fixed_mesh", "axisym", "AxisymSmallDisplacementElement2D4N",
                          "LinearElasticAxisym2DLaw", load, "check", extra={"move_mesh_flag": False}))
    cases.append(Case("check_ax_total_stretch", "axisym", "AxisymTotalLagrangianElement2D4N",
                      "LinearElasticAxisym2DLaw", "stretch", "check", extra={"mapped": False, "stretch": 1.1}))
    cases.append(Case("cantilever_plane_stress", "plane_stress", "SmallDisplacementElement2D8N",
                      "LinearElasticPlaneStress2DLaw", "line", "cantilever", cells=(20, 2), steps=1,
                      extra={"length": 10.0, "height": 1.0, "load": 0.01, "mapped": False}))
    return cases


# -- loads ---------------------------------------------------------------------------------------
#: load: (condition stem (None: the face's own), variable, where it applies)
LOADS = {
    "point": ("PointLoadCondition", "POINT_LOAD", "tip_node"),
    "axisym_point": ("AxisymPointLoadCondition", "POINT_LOAD", "tip_node"),
    "line": ("LineLoadCondition", "LINE_LOAD", "loaded_face"),
    "line3d": ("LineLoadCondition", "LINE_LOAD", "tip_edge"),
    "surface": ("SurfaceLoadCondition", "SURFACE_LOAD", "loaded_face"),
    "positive_pressure": (None, "POSITIVE_FACE_PRESSURE", "pressure_face"),
    "negative_pressure": (None, "NEGATIVE_FACE_PRESSURE", "pressure_face"),
    "body": (None, "VOLUME_ACCELERATION", "body"),
    "stretch": (None, "DISPLACEMENT", "top_nodes"),
}
#: (plane 2D | axisym | 3d, load): value at the end time. Rotations of about 0.1 rad (2D, 3D) or
#: hoop strains of a few per cent (axisymmetric): the finite-strain formulations and the
#: configuration-dependent loads differ visibly from their small-strain counterparts.
VALUES = {
    ("2d", "point"): [0.0, -0.15, 0.0], ("2d", "line"): [0.05, -0.15, 0.0], ("2d", "pressure"): 0.04,
    ("2d", "body"): [0.0, -1.0, 0.0],
    ("axisym", "point"): [0.0, -20.0, 0.0], ("axisym", "axisym_point"): [0.0, -3.0, 0.0],
    ("axisym", "line"): [30.0, -10.0, 0.0], ("axisym", "pressure"): 30.0, ("axisym", "body"): [20.0, -20.0, 0.0],
    ("3d", "point"): [0.0, 0.0, -1.0], ("3d", "line3d"): [0.0, 0.5, -2.0], ("3d", "surface"): [0.3, 0.0, -2.0],
    ("3d", "pressure"): 1.0, ("3d", "body"): [0.0, 0.0, -2.0],
}


def _value(case: Case):
    if case.family == "cantilever":
        return [0.0, -case.extra["load"], 0.0]
    if case.load == "stretch":
        return None
    key = "pressure" if case.load.endswith("pressure") else case.load
    return VALUES[(case.state if case.state in ("axisym", "3d") else "2d", key)]


def timoshenko_tip_deflection(case: Case) -> float:
    """Tip deflection of the cantilever case by Timoshenko beam theory: P = q h (LINE_LOAD q is a
    force per unit length of the tip edge), delta = P L^3 / (3 E I) + P L / (k G A), I = t h^3 / 12,
    A = t h, k = 5/6."""
    length, height, q, t = case.extra["length"], case.extra["height"], case.extra["load"], PLANE_THICKNESS
    force = q * height
    shear_modulus = YOUNG / (2.0 * (1.0 + POISSON))
    return (force * length**3 / (3.0 * YOUNG * t * height**3 / 12.0)
            + force * length / (5.0 / 6.0 * shear_modulus * t * height))


def reference_volume(case: Case) -> float:
    """Volume of the (mapped) block or ring of a case, times THICKNESS in plane 2D."""
    if case.state == "axisym":  # 2 pi int_1^2 r (1 + 0.1 (r - 1)) dr
        return 2.0 * np.pi * (0.9 * 1.5 + 0.1 * 7.0 / 3.0)
    if case.state == "3d":
        return 3.0 * 1.0 * 1.0 * 1.05
    return 4.0 * 1.0 * 1.05 * PLANE_THICKNESS


def body_acceleration(case: Case) -> np.ndarray:
    return np.array(_value(case), dtype=float)


def stretch_solution(case: Case, coords: np.ndarray) -> tuple[np.ndarray, float]:
    """Homogeneous uniaxial stretch of the ring (LinearElasticAxisym2DLaw read as St. Venant-
    Kirchhoff in total Lagrangian form, free lateral faces): radial displacement of every node
    and the axial reaction on the stretched face, S_zz = E E_zz, P_zz = lambda_z S_zz, over the
    annulus pi (2^2 - 1^2)."""
    stretch = case.extra["stretch"]
    strain_z = 0.5 * (stretch**2 - 1.0)
    radial = np.sqrt(1.0 - 2.0 * POISSON * strain_z)
    return (radial - 1.0) * coords[:, 0], stretch * YOUNG * strain_z * np.pi * 3.0


def supported_nodes(case: Case) -> list[int]:
    """Nodes with a prescribed displacement component: where reactions are compared."""
    parts = build(case)["parts"]
    return sorted(parts["support"]["nodes"]) + (sorted(parts["load"]["nodes"]) if case.load == "stretch" else [])


def cantilever_tip_nodes(case: Case) -> list[int]:
    coords = build(case)["coords"]
    return [k + 1 for k, x in enumerate(coords) if abs(x[0] - case.extra["length"]) < 1e-12]


# -- writing ------------------------------------------------------------------------------------
def _fmt(x: float) -> str:
    return f"{x:.16e}"


def build(case: Case) -> dict:
    """Mesh, conditions and sub-model parts of a case."""
    geometry = _geometry_of(case.element)
    dim = case.dim
    if case.state == "axisym":
        cells, size, origin = (4, 4), (1.0, 1.0), (1.0, 0.0)
    elif dim == 2:
        cells, size = case.cells or (8, 2), (case.extra.get("length", 4.0), case.extra.get("height", 1.0))
        origin = (0.0, 0.0)
    else:
        cells, size, origin = (3, 2, 2), (3.0, 1.0, 1.0), (0.0, 0.0, 0.0)
    coords, connectivity = block_mesh(geometry, cells, size, origin)
    if case.extra.get("mapped") is False:
        coords[:, :dim] = np.array(origin) + _unmapped(coords, size, origin, dim)
    far = origin[0] + size[0]
    conditions, parts = {}, {}
    all_nodes = range(1, len(coords) + 1)
    parts["Parts_solid"] = {"nodes": all_nodes, "elements": range(1, len(connectivity) + 1)}
    if case.state == "axisym":
        bottom = [k + 1 for k, x in enumerate(coords) if abs(x[1]) < 1e-12]
        parts["support"] = {"nodes": bottom}
    else:
        parts["support"] = {"nodes": [k + 1 for k, x in enumerate(coords) if abs(x[0] - origin[0]) < 1e-12]}
    stem, _variable, where = LOADS[case.load]
    if where == "tip_node":
        node = max(range(len(coords)), key=lambda k: tuple(coords[k])) + 1  # the far top corner
        conditions[f"{stem}{dim}D1N"] = [[node]]
        parts["load"] = {"nodes": [node], "conditions": [1]}
    elif where in ("loaded_face", "pressure_face"):
        if where == "loaded_face":
            faces = boundary_faces(geometry, connectivity, coords, 0, far)
        elif case.state == "axisym":
            faces = boundary_faces(geometry, connectivity, coords, 0, origin[0])  # the bore
        elif dim == 2:
            faces = _top_faces(geometry, connectivity, coords, size, origin)
        else:
            faces = boundary_faces(geometry, connectivity, coords, 2, size[2])
        if stem is None:
            stem = "LineLoadCondition" if dim == 2 else "SurfaceLoadCondition"
        if case.state == "axisym":
            stem = "Axisym" + stem
        by_size = {}
        for face in faces:
            by_size.setdefault(f"{stem}{dim}D{len(face)}N", []).append(face)
        conditions.update(by_size)
        parts["load"] = {"nodes": sorted({n for f in faces for n in f}), "conditions": range(1, len(faces) + 1)}
    elif where == "top_nodes":
        parts["load"] = {"nodes": [k + 1 for k, x in enumerate(coords) if abs(x[1] - size[1]) < 1e-12]}
    elif where == "tip_edge":
        edge = [k + 1 for k, x in enumerate(coords) if abs(x[0] - far) < 1e-12 and abs(x[2] - size[2]) < 1e-12]
        edge.sort(key=lambda n: coords[n - 1][1])
        lines = [[a, b] for a, b in itertools.pairwise(edge)]
        conditions[f"{stem}3D2N"] = lines
        parts["load"] = {"nodes": edge, "conditions": range(1, len(lines) + 1)}
    return {"coords": coords, "elements": {case.element: connectivity}, "conditions": conditions, "parts": parts}


def _unmapped(coords, size, origin, dim):
    """Undo the y mapping (the cantilever of issue 10 is a straight beam)."""
    x = coords[:, :dim] - np.array(origin)
    x[:, 1] = x[:, 1] / (1.0 + 0.1 * x[:, 0] / size[0])
    return x


def _top_faces(geometry, connectivity, coords, size, origin):
    """Edges on the mapped top y = H (1 + 0.1 x / L), which is not a coordinate line."""
    def on_top(n):
        x = coords[n - 1]
        return abs(x[1] - (origin[1] + size[1] * (1.0 + 0.1 * (x[0] - origin[0]) / size[0]))) < 1e-12

    return [[e[i] for i in face] for e in connectivity for face in _FACES[geometry] if all(on_top(e[i]) for i in face)]


def write_mdpa(path: str, mesh: dict) -> None:
    lines = ["Begin ModelPartData", "End ModelPartData", "", "Begin Properties 1", "End Properties", "",
             "Begin Nodes"]
    lines += [f"{k + 1} {_fmt(x[0])} {_fmt(x[1])} {_fmt(x[2])}" for k, x in enumerate(mesh["coords"])]
    lines += ["End Nodes", ""]
    for block, entities, prop in (("Elements", mesh["elements"], 1), ("Conditions", mesh["conditions"], 1)):
        counter = 0
        for name, cells in entities.items():
            lines.append(f"Begin {block} {name}")
            for cell in cells:
                counter += 1
                lines.append(f"{counter} {prop} " + " ".join(str(n) for n in cell))
            lines += [f"End {block}", ""]
    for name, content in mesh["parts"].items():
        lines.append(f"Begin SubModelPart {name}")
        for key, block in (("nodes", "Nodes"), ("elements", "Elements"), ("conditions", "Conditions")):
            lines.append(f"  Begin SubModelPart{block}")
            lines += [f"    {int(i)}" for i in content.get(key, [])]
            lines.append(f"  End SubModelPart{block}")
        lines += ["End SubModelPart", ""]
    with open(path, "w") as f:
        f.write("\n".join(lines))


def materials(case: Case) -> dict:
    variables = {"YOUNG_MODULUS": YOUNG, "POISSON_RATIO": POISSON, "DENSITY": DENSITY}
    if case.state in ("plane_stress", "plane_strain"):
        variables["THICKNESS"] = PLANE_THICKNESS
    return {"properties": [{"model_part_name": "Structure.Parts_solid", "properties_id": 1,
                            "Material": {"constitutive_law": {"name": case.law}, "Variables": variables,
                                         "Tables": {}}}]}


def _assign(module: str, part: str, variable: str, value, **extra) -> dict:
    return {"python_module": module, "kratos_module": "KratosMultiphysics",
            "Parameters": {"model_part_name": part, "variable_name": variable, "value": value,
                           "interval": [0.0, "End"], **extra}}


def project_parameters(case: Case) -> dict:
    end_time = float(case.steps) if not case.dynamic else 0.05 * case.steps
    dt = 1.0 if not case.dynamic else 0.05
    ramp = "t" if not case.dynamic else "1.0"  # dynamic cases: a suddenly applied load
    support = [0.0, 0.0, 0.0]
    constrained = [True, True, True]
    if case.state == "axisym":
        support, constrained = [None, 0.0, None], [False, True, False]
    constraints = [_assign("assign_vector_variable_process", "Structure.support", "DISPLACEMENT", support,
                           constrained=constrained)]
    _, variable, where = LOADS[case.load]
    value = _value(case)
    scale = f"/{case.steps}*{ramp}" if ramp == "t" else ""
    if where == "top_nodes":
        rise = round(case.extra["stretch"] - 1.0, 12)  # the ring is 1 high
        constraints.append(_assign("assign_vector_variable_process", "Structure.load", variable,
                                   [None, f"{rise}{scale}", None], constrained=[False, True, False]))
        loads = []
    elif where == "body":
        loads = [_assign("assign_vector_variable_process", "Structure.Parts_solid", variable,
                         [f"{v}{scale}" if ramp == "t" else v for v in value], constrained=[False, False, False])]
    elif isinstance(value, list):
        loads = [_assign("assign_vector_variable_to_conditions_process", "Structure.load", variable,
                         [f"{v}{scale}" if ramp == "t" else v for v in value])]
    else:
        loads = [_assign("assign_scalar_variable_to_conditions_process", "Structure.load", variable,
                         f"{value}{scale}" if ramp == "t" else value)]
    solver = {
        "solver_type": "Dynamic" if case.dynamic else "Static", "model_part_name": "Structure",
        "domain_size": case.dim, "echo_level": 0, "analysis_type": case.extra.get("analysis_type", "non_linear"),
        "model_import_settings": {"input_type": "mdpa", "input_filename": "model"},
        "material_import_settings": {"materials_filename": "materials.json"},
        "time_stepping": {"time_step": dt},
        "convergence_criterion": "displacement_criterion",
        "displacement_relative_tolerance": 1e-11, "displacement_absolute_tolerance": 1e-14, "max_iteration": 60,
        "linear_solver_settings": {"solver_type": "sparse_lu"},
        "rotation_dofs": False,
    }
    if case.dynamic:
        solver.update({"time_integration_method": "implicit", "scheme_type": case.dynamic})
    if "move_mesh_flag" in case.extra:
        solver["move_mesh_flag"] = case.extra["move_mesh_flag"]
    return {"problem_data": {"problem_name": case.name, "parallel_type": "OpenMP", "echo_level": 0,
                             "start_time": 0.0, "end_time": end_time},
            "solver_settings": solver,
            "processes": {"constraints_process_list": constraints, "loads_process_list": loads},
            "output_processes": {}}


def write_case(case: Case, folder: str) -> str:
    os.makedirs(folder, exist_ok=True)
    write_mdpa(os.path.join(folder, "model.mdpa"), build(case))
    with open(os.path.join(folder, "materials.json"), "w") as f:
        json.dump(materials(case), f, indent=2)
    with open(os.path.join(folder, "ProjectParameters.json"), "w") as f:
        json.dump(project_parameters(case), f, indent=2)
    return folder


def selected(pattern: str | None) -> list[Case]:
    """Cases whose name contains one of the comma-separated substrings of `pattern` (all if None)."""
    cases = all_cases()
    if not pattern:
        return cases
    keys = [p for p in pattern.split(",") if p]
    return [c for c in cases if any(k in c.name for k in keys)]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("output")
    parser.add_argument("--filter", help="comma-separated substrings of case names")
    args = parser.parse_args(argv)
    cases = selected(args.filter)
    for case in cases:
        write_case(case, os.path.join(args.output, case.name))
    print(f"{len(cases)} cases in {args.output}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
