# SPDX-License-Identifier: BSD-3-Clause
"""Cattaneo-Mindlin partial slip: the Hertz cases of ``hertz`` with Coulomb friction, a normal
approach followed by a tangential shift, and the closed forms they are checked against.

The bodies are the Hertz cylinder (2D, plane strain, full model) or sphere (3D, ``hertz3dgrid``
meshes mirrored about x = 0: the half model y >= 0, since a load along x is not symmetric about
x = 0) on the elastic block, both of the same material, so that the normal and the tangential
problems decouple (Dundurs' beta = 0): the pressure stays Hertz's while the tangential load Q
grows. The top of the curved body is pushed down to the Hertz approach in ``NORMAL_STEPS`` load
steps, then held there and shifted along x in ``TANGENTIAL_STEPS`` more steps (end time 1).
The shift is a calibrated estimate that brings Q to about 0.87 mu P; the checks use the computed
forces (the block-bottom reactions), not the shift.

Closed forms (Johnson, Contact Mechanics, 1985, sections 7.1 and 7.2), for a tangential load
Q < mu P growing from zero at constant P:
    2D: c = a sqrt(1 - Q / (mu P)),
        q(x) = mu p0 [sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - x^2/c^2)]   (second term for |x| < c)
    3D: c = a (1 - Q / (mu P))^(1/3), q(r) = mu p0 [sqrt(1 - r^2/a^2) - (c/a) sqrt(1 - r^2/c^2)]
with a and p0 from Hertz for the computed P (``hertz.hertz_2d`` / ``hertz_3d``). The contact
centre moves with the shift, so positions are measured from the centre of the computed pressure
(a least-squares fit of p^2 = A + B x + C (x^2 + y^2), which Hertz' profile satisfies exactly).
The size of the stick zone is measured from the mortar nodal areas of its nodes (NODAL_AREA:
half its length in 2D, the radius of a disc of its area in 3D), the same estimator for any
mesh, which does not depend on where the zone's centre is. In 3D it is cross-checked by a second,
independent measure: the c whose closed-form profile fits the nodal tangential tractions best
(area-weighted least squares over the active nodes), which uses every node's value rather than
its stick / slip flag. On hertz3dgrid_15k (h = 0.1 a) both give c 0.02 to 0.05 a below
Cattaneo-Mindlin, on hertz3dgrid_30k (h = 0.075 a) 0.02 to 0.045 a: the offset, about 0.4 h,
shrinks with the mesh (figures in test_cattaneo_mindlin_3d).
A nodal dual multiplier is the traction averaged with the node's standard shape function (its
row of D), so in 2D the nodal traction is compared with the closed form averaged in the same
way; in 3D with its point value at the node (no surface mesh at hand), which overstates the
error where the closed form is steep: next to the stick-zone edge, whose inner term has an
infinite slope there.

    python -m mortarcontact.cases.cattaneo_mindlin --dim 2 --label 8k --out /tmp/cases
"""
from __future__ import annotations

import argparse
import copy
import json
import math
import os
import sys

import numpy as np

from . import hertz
from .mesh_files import write_json_files

FRICTION_COEFFICIENT = 0.3
NORMAL_STEPS = 8
TANGENTIAL_STEPS = 8
#: Top shift along x at the end (t = 1) for Q of about 0.87 mu P (calibrated on hertz2d_8k and
#: hertz3dgrid_15k; depends little on the mesh). In 3D 5e-3 gave Q / (mu P) 0.22, 0.42, 0.60,
#: 0.76, 0.89, 0.97, 0.98 (gross sliding) over the first seven shift steps.
SHIFT = {2: 7.0e-3, 3: 3.2e-3}


def write_case(dim: int, label: str, out_dir: str, friction: float = FRICTION_COEFFICIENT,
               mortar_type: str = "ALMContactFrictional", shift: float | None = None, mpc: bool = False) -> str:
    """Writes the Hertz case ``hertz2d_<label>`` (2D) or the half model of ``hertz3dgrid_<label>``
    (3D), made frictional and followed by the tangential shift; returns its folder. With ``mpc``:
    frictional MPC contact (mpc_contact_settings and mpc_contact_process, contact_type Frictional)
    instead of ``mortar_type``."""
    family = "hertz2d" if dim == 2 else "hertz3dgrid"
    folder = hertz.write_case(family, label, out_dir, half=dim == 3, mpc=mpc)
    name = os.path.basename(folder)
    materials_file = os.path.join(folder, f"{name}_materials.json")
    with open(materials_file) as f:
        materials = json.load(f)
    for entry in materials["properties"]:
        entry["Material"]["Variables"]["FRICTION_COEFFICIENT"] = friction
    parameters_file = os.path.join(folder, "ProjectParameters.json")
    with open(parameters_file) as f:
        parameters = json.load(f)
    solver = parameters["solver_settings"]
    if mpc:
        solver["mpc_contact_settings"]["contact_type"] = "Frictional"
    else:
        solver["contact_settings"]["mortar_type"] = mortar_type
    solver["buffer_size"] = 3
    dt = 1.0 / (NORMAL_STEPS + TANGENTIAL_STEPS)
    t_normal = NORMAL_STEPS * dt
    solver["time_stepping"]["time_step"] = dt
    contact = parameters["processes"]["contact_process_list"][0]["Parameters"]
    contact["contact_type"] = "FrictionalPureSlip" if mortar_type.endswith("PureSlip") and not mpc else "Frictional"
    constraints = parameters["processes"]["constraints_process_list"]
    top = next(p for p in constraints if p["Parameters"]["model_part_name"] == "Structure.DISPLACEMENT_top")
    with open(os.path.join(folder, "hertz.json")) as f:
        reference = json.load(f)
    delta = reference["applied_displacement"]
    axis = dim - 1
    # Two intervals rather than min()/max() in one expression: Kratos 10.4's function parser
    # rejects those, and both codes must read the files.
    approach = top["Parameters"]
    approach["constrained"] = [True, True, dim == 3]
    approach["value"] = [0.0, 0.0, 0.0]
    approach["value"][axis] = f"-{delta!r}*t/{t_normal!r}"
    approach["interval"] = [0.0, t_normal + 0.5 * dt]
    sliding = copy.deepcopy(top)
    shift = SHIFT[dim] if shift is None else shift
    sliding["Parameters"]["value"] = [f"{shift!r}*(t-{t_normal!r})/{1.0 - t_normal!r}", 0.0, 0.0]
    sliding["Parameters"]["value"][axis] = -delta
    sliding["Parameters"]["interval"] = [t_normal + 0.5 * dt, "End"]
    constraints.append(sliding)
    if dim == 3 and not mpc:
        # The half model's symmetry holds for the contact traction too: t_y = 0 on y = 0, so the
        # multiplier's y component is fixed there as the displacement's is. Without it that
        # component has no equation of its own (the fixed DISPLACEMENT_Y row is a reaction), only
        # the sticking nodes' constraint on the weighted y-slip of one-sided supports, which ties the
        # block's u_y off the plane: step 1 of hertz3dgrid_15k then diverged or stopped on a
        # singular multiplier row of a node on the plane; with it, 3 iterations.
        constraints.append(hertz.assign_displacement("Contact_slave_sym_y", [False, True, False], [0.0, 0.0, 0.0],
                                                     variable="VECTOR_LAGRANGE_MULTIPLIER"))
    reference.update(friction_coefficient=friction, normal_steps=NORMAL_STEPS, tangential_steps=TANGENTIAL_STEPS,
                     relations=reference["relations"] + ("; c = a sqrt(1 - Q/(mu P))" if dim == 2 else
                                                         "; c = a (1 - Q/(mu P))^(1/3)"))
    write_json_files(folder, {os.path.basename(materials_file): materials, "ProjectParameters.json": parameters,
                              "hertz.json": reference})
    return folder


# -- closed forms -----------------------------------------------------------------------------
def stick_radius(dim: int, a: float, load_ratio: float) -> float:
    """Stick-zone half-width (2D) or radius (3D) for Q / (mu P) = ``load_ratio``."""
    return a * (math.sqrt(1.0 - load_ratio) if dim == 2 else (1.0 - load_ratio) ** (1.0 / 3.0))


def tangential_traction(r, a: float, c: float, p0: float, friction: float):
    """Cattaneo-Mindlin traction at the distance ``r`` from the centre (2D and 3D alike)."""
    r = np.asarray(r, dtype=float)
    outer = np.sqrt(np.clip(1.0 - r * r / (a * a), 0.0, None))
    inner = np.sqrt(np.clip(1.0 - r * r / (c * c), 0.0, None)) if c > 0.0 else 0.0
    return friction * p0 * (outer - (c / a) * inner)


def hat_average(profile, x: np.ndarray) -> np.ndarray:
    """``profile`` averaged with the piecewise linear shape function of each node of the sorted
    positions ``x`` (2D): what a nodal dual multiplier holds. The end nodes get the point value."""
    out = np.asarray(profile(x), dtype=float).copy()
    for j in range(1, len(x) - 1):
        s = np.linspace(x[j - 1], x[j + 1], 801)
        w = np.interp(s, x[j - 1:j + 2], [0.0, 1.0, 0.0])
        out[j] = np.sum(w * profile(s)) / np.sum(w)
    return out


def _pressure_centre(xy: np.ndarray, p: np.ndarray) -> np.ndarray:
    """Centre (x0, y0) of a Hertz pressure: least squares on p^2 = A + B x + C y + D (x^2 + y^2)
    over the nodes above 30 % of the peak."""
    m = p > 0.3 * p.max()
    x, y = xy[m, 0], xy[m, 1]
    columns = [np.ones(m.sum()), x, y, x * x + y * y]
    if not np.any(y):
        columns.pop(2)
    coef = np.linalg.lstsq(np.column_stack(columns), p[m] ** 2, rcond=None)[0]
    d = coef[-1]
    return np.array([-coef[1] / (2.0 * d), -coef[2] / (2.0 * d) if len(coef) == 4 else 0.0])


def zone_size(dim: int, areas: np.ndarray, symmetry: float = 1.0) -> float:
    """Half-width (2D) or radius (3D) of a zone from the mortar nodal areas of its nodes: a node
    stands for its share of the interface, so a contiguous set of nodes ends half-way to the
    next node. ``symmetry``: the whole zone's area over the model's (2 for the 3D half model)."""
    total = symmetry * float(np.sum(areas))
    return 0.5 * total if dim == 2 else math.sqrt(total / math.pi)


def evaluate_step(dim: int, radius: float, e_star: float, friction: float, force: np.ndarray,
                  nodes: dict, symmetry: float = 1.0) -> dict:
    """One converged step against the closed forms.

    ``force``: the total force on the curved body (the block-bottom reaction with its sign
    reversed, times the symmetry factor; components x, y[, z]); ``nodes``: arrays over the slave
    nodes: ``x`` (current coordinates, (n, 3)), ``active``, ``slip`` (flags), ``area`` (NODAL_AREA), ``normal``
    ((n, 3), unit nodal normals), ``traction`` ((n, 3), the multiplier times SCALE_FACTOR);
    ``symmetry``: the symmetry factor of the model, which scales the zones' areas.
    Returns P, Q, Q / (mu P), Hertz' a and p0, the stick-zone size measured and in theory, how far
    the slipping nodes' tractions are from the cone (slip_rule_error) and the sticking ones' outside
    it (stick_excess), both over p0, the errors of the nodal tangential tractions against the closed
    form (2D: averaged; 3D: point values, and the c of the best-fitting profile) and in 2D the
    resultant of the nodal tractions (x, y; the normal part has an x component too, as the contact
    centre leaves the lowest point of the cylinder)."""
    axis = dim - 1
    P, Q = -force[axis], abs(force[0])
    theory = (hertz.hertz_2d if dim == 2 else hertz.hertz_3d)(P, radius, e_star)
    a, p0 = theory["half_width"], theory["peak_pressure"]
    t = nodes["traction"]
    n = nodes["normal"]
    pressure = -np.einsum("ij,ij->i", t, n)
    tangential = t + pressure[:, None] * n
    lateral = nodes["x"][:, [0, 1]] if dim == 3 else np.column_stack([nodes["x"][:, 0], np.zeros(len(t))])
    centre = _pressure_centre(lateral, pressure)
    active, slip = nodes["active"], nodes["slip"]
    ratio = Q / (friction * P)
    c_theory = stick_radius(dim, a, ratio)
    stick = active & ~slip
    c = zone_size(dim, nodes["area"][stick], symmetry)
    out = {"P": P, "Q": Q, "force": [float(f) for f in force], "load_ratio": ratio, "a": a, "p0": p0,
           "centre": centre.tolist(),
           "c": c, "c_theory": c_theory, "c_error": (c - c_theory) / a,
           "a_from_areas": zone_size(dim, nodes["area"][active], symmetry),
           "active_nodes": int(active.sum()), "stick_nodes": int(stick.sum()),
           "slip_rule_error": float(np.max(np.abs(np.linalg.norm(tangential[active & slip], axis=1)
                                                  - friction * pressure[active & slip]), initial=0.0) / p0),
           # how far a sticking node's traction lies outside the cone (0 inside), over p0
           "stick_excess": float(np.max(np.linalg.norm(tangential[stick], axis=1) - friction * pressure[stick],
                                        initial=0.0) / p0)}
    if dim == 3:
        radius_from_centre = np.linalg.norm(lateral - centre, axis=1)
        q, weight = np.linalg.norm(tangential, axis=1), np.where(active, nodes["area"], 0.0)

        def profile_error(c_trial):
            return np.abs(q - tangential_traction(radius_from_centre, a, c_trial, p0, friction)) / (friction * p0)

        def rms(c_trial):
            return float(np.sqrt(np.sum(weight * profile_error(c_trial) ** 2) / np.sum(weight)))

        trials = np.linspace(0.0, 1.0, 1001) * a
        c_fit = float(trials[np.argmin([rms(c_trial) for c_trial in trials])])
        out.update(c_fit=c_fit, c_fit_error=(c_fit - c_theory) / a, traction_error_rms=rms(c_theory),
                   traction_error_max=float(profile_error(c_theory)[active].max()))
    if dim == 2:
        x = lateral[:, 0] - centre[0]
        order = np.argsort(x)
        x, q, traction = x[order], np.abs(tangential[order, 0]), t[order]
        expected = hat_average(lambda s: tangential_traction(s, a, c_theory, p0, friction), x)
        error = np.abs(q - expected) / (friction * p0)
        inside = np.abs(x) < a
        out.update(traction_error_max=float(error.max()),
                   traction_error_rms=float(np.sqrt(np.mean(error[inside] ** 2))),
                   traction_force=np.trapezoid(traction[:, :2], x, axis=0).tolist())
    return out


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--dim", type=int, choices=(2, 3), default=2)
    parser.add_argument("--label", default="8k", help="size label of hertz2d (2D) or hertz3dgrid (3D)")
    parser.add_argument("--out", required=True, help="output folder")
    parser.add_argument("--friction", type=float, default=FRICTION_COEFFICIENT)
    args = parser.parse_args(argv)
    print(write_case(args.dim, args.label, args.out, args.friction))
    return 0


if __name__ == "__main__":
    sys.exit(main())
