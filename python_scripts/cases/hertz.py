# SPDX-License-Identifier: BSD-3-Clause
"""Scalable Hertz contact cases in the Kratos input format, and their evaluation against Hertz theory.

Three families, meshed with gmsh, written as a gmsh file with physical groups + ProjectParameters.json
+ materials.json; mortarcontact reads the mesh with ``input_type`` ``"gmsh"``, Kratos 10.4 the mdpa
that ``mesh_files.write_kratos_mdpa`` makes of it:

- ``hertz2d``: plane-strain cylinder of radius R (its lower half, full model) pressed onto an
  elastic block [-W, W] x [-H, 0]; linear triangles (SmallDisplacementElement2D3N) refined
  around the contact point. A half model is not used: with the slave and master interfaces both
  ending on the symmetry line inside the contact zone, Kratos' multipliers of the first slave
  nodes oscillate and grow with refinement (2.7 p0 at 30k DoFs) while the reaction stays right.
- ``hertz3d``: sphere of radius R (the lower half, quarter model x, y >= 0) pressed onto an
  elastic block [0, W]^2 x [-H, 0]; linear tetrahedra (SmallDisplacementElement3D4N).
- ``hertz3dgrid``: the same sphere, block, material and loading, but each body meshed with a
  structured zone at the contact (a box of cubes of side h, each cut into the six Kuhn tetrahedra
  around one diagonal, the same in every cube), the rest unstructured and conforming. On the
  unstructured ``hertz3d`` meshes the nodal pressures scatter by +-5 % around the Hertz profile
  (a surface node's pressure follows the number and shapes of its tetrahedra), so the nodal peak
  is the largest of that scatter (+7.6 % at 15k DoFs, +6.3 % at 50k, the same in Kratos 10.4),
  not the axis value. On the structured zone every node sees the same tetrahedra, the scatter is
  gone and the nodal peak converges. The cube diagonal is chosen symmetric under x <-> y, so the
  two symmetry planes see the same mesh; the sphere is rotated so that the poles and the seam of
  its parametrisation lie outside the quarter model (a pole at the contact point would spoil the
  structured surface mesh).

Both bodies are linear elastic (same E, nu), small displacements. In 3D the symmetry planes carry
rollers (u_x = 0 on x = 0, u_y = 0 on y = 0); in 2D u_x = 0 on the cylinder top. The block bottom
is clamped and the flat top of the curved body is pushed down by delta * t in 4 load steps
(t = 0.25 ... 1). Frictionless ALM
(``ALMContactFrictionless`` / ``alm_contact_process``), or MPC contact (``write_case(..., mpc=True)``:
``mpc_contact_settings`` / ``mpc_contact_process``); the curved body is the slave.
The interface sub-model-parts hold nodes only (the contact process builds the faces): the part of
the arc / cap with |x| (or r) <= 4 a and the part of the block top with |x| (or r) <= 5 a, a being
the target contact half-width / radius.

Hertz theory (two identical bodies: 1/E* = 2 (1 - nu^2) / E), for the total force P of the full
model (per unit thickness in 2D):
    2D line contact:  a = sqrt(4 P R / (pi E*)),        p0 = 2 P / (pi a)
    3D point contact: a = (3 P R / (4 E*))^(1/3),       p0 = 3 P / (2 pi a^2),  delta = a^2 / R
In 2D the approach delta depends on the bodies' size (no closed form), and in 3D the Hertz delta
is the approach of points far from the contact, not of the finite bodies' boundaries: the
applied displacement is therefore an estimate that gives a/R close to the target, and the
checks compare the computed peak pressure and half-width with Hertz for the computed force
(the block-bottom reaction, times 4 for the 3D symmetry). ``hertz.json`` next to each case
holds the geometry, the material, the target values and the relations.

    python -m mortarcontact.cases.hertz --out cases                    # all sizes
    python -m mortarcontact.cases.hertz --cases hertz2d_2k,hertz3d_15k --out /tmp/cases

They are the benchmarks' cases (benchmarks/hertz), the demo's (examples/hertz_cylinder) and the
tests'; gmsh (PyPI) is needed to mesh them.
"""
from __future__ import annotations

import argparse
import itertools
import json
import math
import os
import sys

import numpy as np

from .mesh_files import write_case_mesh, write_json_files

RADIUS = 1.0
YOUNG = 1000.0
POISSON = 0.3
TARGET_A_OVER_R = 0.1
LOAD_STEPS = 4

# Mesh size h(d) = scale * min(H_MAX, H_CONTACT + GRADING * max(0, d - D_FINE)) at distance d
# from the initial contact point; ``scale`` per size label (DoFs approximately as labelled).
GEOMETRY = {
    2: {"block_width": 2.0, "block_height": 2.0, "h_contact": 0.01, "grading": 0.3, "d_fine": 0.16,
        "h_max": 0.25},
    3: {"block_width": 1.5, "block_height": 1.5, "h_contact": 0.0135, "grading": 0.3, "d_fine": 0.15,
        "h_max": 0.3},
}
SIZES = {
    "hertz2d": {"2k": 1.38, "8k": 0.69, "30k": 0.356, "100k": 0.195, "250k": 0.123},
    "hertz3d": {"15k": 0.836, "50k": 0.524, "150k": 0.343, "600k": 0.2, "2m": 0.142},
    "hertz3dgrid": {"15k": 1.0, "30k": 0.75, "50k": 0.6, "80k": 0.5},
}
# hertz3dgrid: cube side ``scale * spacing`` in the structured zones, the sphere's [0, L]^2 x [0, D]
# and the block's [0, L]^2 x [-D, 0] (L = 1.2 a, 1.4 a, D = 0.8 a: the whole contact area and the
# depth of the largest stress gradients); the block's cubes are ``master_ratio`` times larger (the
# meshes do not match); outside, h = scale * min(h_max, spacing + grading * distance to the zone).
GRID = {"spacing": 0.01, "slave_zone": (0.12, 0.08), "master_zone": (0.14, 0.08), "master_ratio": 1.1,
        "grading": 0.3, "h_max": 0.3}


# -- Hertz theory -----------------------------------------------------------------------------
def effective_modulus(young: float = YOUNG, poisson: float = POISSON) -> float:
    """E* of two bodies of the same material: 1/E* = 2 (1 - nu^2) / E."""
    return young / (2.0 * (1.0 - poisson ** 2))


def hertz_2d(force: float, radius: float, e_star: float) -> dict:
    """Line contact of a cylinder on a flat, force per unit thickness."""
    a = math.sqrt(4.0 * force * radius / (math.pi * e_star))
    return {"force": force, "half_width": a, "peak_pressure": 2.0 * force / (math.pi * a)}


def hertz_3d(force: float, radius: float, e_star: float) -> dict:
    """Point contact of a sphere on a flat."""
    a = (3.0 * force * radius / (4.0 * e_star)) ** (1.0 / 3.0)
    return {"force": force, "half_width": a, "peak_pressure": 3.0 * force / (2.0 * math.pi * a * a),
            "approach": a * a / radius}


def force_for_half_width(dim: int, a: float, radius: float, e_star: float) -> float:
    return math.pi * a * a * e_star / (4.0 * radius) if dim == 2 else 4.0 * e_star * a ** 3 / (3.0 * radius)


def applied_displacement(dim: int, radius: float, block_height: float) -> float:
    """Estimate of the top displacement that gives the target a. 2D: the approach of a cylinder's
    centre line to its contact plus that of a layer of depth H, each (1 - nu^2) P / (pi E)
    (2 ln(4 R / a) - 1) and (2 ln(2 H / a) - 1); 3D: Hertz a^2 / R less the Boussinesq
    displacement (3 - 2 nu) P / (4 pi G d) still left at the depth R and H of the boundaries.
    Only a/R near the target matters: the checks use the computed force."""
    e_star = effective_modulus()
    a = TARGET_A_OVER_R * radius
    force = force_for_half_width(dim, a, radius, e_star)
    if dim == 2:
        c = (1.0 - POISSON ** 2) * force / (math.pi * YOUNG)
        return c * ((2.0 * math.log(4.0 * radius / a) - 1.0) + (2.0 * math.log(2.0 * block_height / a) - 1.0))
    shear = YOUNG / (2.0 * (1.0 + POISSON))
    left = (3.0 - 2.0 * POISSON) * force / (4.0 * math.pi * shear) * (1.0 / radius + 1.0 / block_height)
    return a * a / radius - left


# -- meshing ----------------------------------------------------------------------------------
def _size_callback(dim: int, scale: float):
    g = GEOMETRY[dim]

    def size(_entity_dim, _tag, x, y, z, _lc):
        d = math.sqrt(x * x + y * y + z * z) if dim == 3 else math.sqrt(x * x + y * y)
        return scale * min(g["h_max"], g["h_contact"] + g["grading"] * max(0.0, d - g["d_fine"]))

    return size


def _set_mesh_options(gmsh) -> None:
    """Sizes from the size callback only; Frontal-Delaunay surfaces, Delaunay volumes, optimized."""
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
    gmsh.option.setNumber("Mesh.Algorithm", 6)
    gmsh.option.setNumber("Mesh.Algorithm3D", 1)
    gmsh.option.setNumber("Mesh.Optimize", 1)


def _mesh_body(gmsh, dim: int, size, build) -> tuple[np.ndarray, np.ndarray]:
    """Meshes one body in a fresh gmsh model with the size callback ``size``; returns (coords (n, 3),
    connectivity (m, dim+1)) with 0-based local node indices, elements positively oriented."""
    gmsh.model.add("body")
    build()
    _set_mesh_options(gmsh)
    gmsh.model.mesh.setSizeCallback(size)
    gmsh.model.mesh.generate(dim)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    coords = np.asarray(coords).reshape(-1, 3)
    element_type = 2 if dim == 2 else 4
    _, node_tags = gmsh.model.mesh.getElementsByType(element_type)
    gmsh.model.remove()
    cells = np.asarray(node_tags, dtype=np.int64).reshape(-1, dim + 1)
    used = np.unique(cells)
    index = np.full(int(tags.max()) + 1, -1, dtype=np.int64)
    index[np.asarray(tags, dtype=np.int64)] = np.arange(len(tags))
    local = np.full(int(tags.max()) + 1, -1, dtype=np.int64)
    local[used] = np.arange(len(used))
    xyz = coords[index[used]]
    cells = local[cells]
    if dim == 2:
        p = xyz[cells]
        e1, e2 = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
        signed = e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0]
        flip = signed < 0.0
        cells[flip] = cells[flip][:, [0, 2, 1]]
    else:
        p = xyz[cells]
        signed = np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p[:, 3] - p[:, 0])
        flip = signed < 0.0
        cells[flip] = cells[flip][:, [0, 2, 1, 3]]
    return xyz, cells


def mesh_2d(scale: float):
    import gmsh

    g = GEOMETRY[2]
    r, w, h = RADIUS, g["block_width"], g["block_height"]

    def cylinder():
        geo = gmsh.model.geo
        left, bottom, right = geo.addPoint(-r, r, 0), geo.addPoint(0, 0, 0), geo.addPoint(r, r, 0)
        centre = geo.addPoint(0, r, 0)
        arcs = [geo.addCircleArc(left, centre, bottom), geo.addCircleArc(bottom, centre, right)]
        loop = geo.addCurveLoop([*arcs, geo.addLine(right, left)])
        geo.addPlaneSurface([loop])
        geo.synchronize()

    def block():
        gmsh.model.occ.addRectangle(-w, -h, 0, 2.0 * w, h)
        gmsh.model.occ.synchronize()

    return mesh_bodies(2, _size_callback(2, scale), cylinder, block)


def mesh_3d(scale: float):
    import gmsh

    g = GEOMETRY[3]
    r, w, h = RADIUS, g["block_width"], g["block_height"]

    def sphere():
        occ = gmsh.model.occ
        occ.intersect([(3, occ.addSphere(0, 0, r, r))], [(3, occ.addBox(0, 0, 0, r, r, r))])
        occ.synchronize()

    def block():
        gmsh.model.occ.addBox(0, 0, -h, w, w, h)
        gmsh.model.occ.synchronize()

    return mesh_bodies(3, _size_callback(3, scale), sphere, block)


# The six tetrahedra of the unit cube around its diagonal (0,0,0)-(1,1,1) (Kuhn): one per order
# in which the path from corner 000 to 111 walks along x, y and z.
KUHN_TETRAHEDRA = []
for _order in itertools.permutations(range(3)):
    _corner = [0, 0, 0]
    _tet = [tuple(_corner)]
    for _axis in _order:
        _corner[_axis] = 1
        _tet.append(tuple(_corner))
    KUHN_TETRAHEDRA.append(_tet)


def oriented_tetrahedra(xyz: np.ndarray, cells: np.ndarray) -> np.ndarray:
    p = xyz[cells]
    signed = np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p[:, 3] - p[:, 0])
    if (np.abs(signed) < 1e-14 * np.abs(signed).max()).any():
        raise RuntimeError("degenerate tetrahedra")
    cells = cells.copy()
    cells[signed < 0.0] = cells[signed < 0.0][:, [0, 2, 1, 3]]
    return cells


def _structured_zone(gmsh, volume: int, n_xy: int, n_z: int, corner: tuple, arrangement: tuple) -> None:
    """Transfinite curves and faces of the zone ``volume`` (a hexahedron with four vertical edges);
    ``arrangement`` gives the diagonals of the faces at x = corner[0], y = corner[1] and z = corner[2]
    (the faces shared with the unstructured rest)."""
    faces = [t for _, t in gmsh.model.getBoundary([(3, volume)], oriented=False)]
    curves = {t for _, t in gmsh.model.getBoundary([(2, f) for f in faces], combined=False, oriented=False)}
    for curve in curves:
        ends = gmsh.model.getBoundary([(1, curve)], oriented=False)
        p, q = (np.array(gmsh.model.getValue(0, t, [])) for _, t in ends)
        e = np.abs(q - p)
        gmsh.model.mesh.setTransfiniteCurve(curve, (n_z if e[2] > max(e[0], e[1]) else n_xy) + 1)
    for face in faces:
        com = gmsh.model.occ.getCenterOfMass(2, face)
        which = next((i for i in range(3) if abs(com[i] - corner[i]) < 1e-9), 0)
        gmsh.model.mesh.setTransfiniteSurface(face, arrangement[which])


def _mesh_grid_body(gmsh, build, size) -> tuple[np.ndarray, np.ndarray]:
    """Meshes one body of hertz3dgrid. gmsh meshes the structured zone's faces and nodes
    (transfinite) and the rest (unstructured, on the zone's faces); the zone's tetrahedra are ours:
    gmsh's own split of a transfinite volume into tetrahedra neither follows one diagonal in every
    cube nor always matches the triangles of the faces. The diagonals of the shared faces are set by
    their arrangement (Left / Right, relative to each face's parametrisation): the combinations
    are tried until the Kuhn split with a diagonal symmetric under x <-> y reproduces them."""
    last = None
    for arrangement in _ARRANGEMENTS:
        gmsh.model.add("body")
        zone, n_xy, n_z, lo, hi, bottom, shared_corner = build()
        _structured_zone(gmsh, zone, n_xy, n_z, shared_corner, arrangement)
        _set_mesh_options(gmsh)
        gmsh.model.mesh.setSizeCallback(size)
        gmsh.model.mesh.setTransfiniteVolume(zone)
        gmsh.model.mesh.generate(3)
        tags, coords, _ = gmsh.model.mesh.getNodes()
        coords = np.asarray(coords).reshape(-1, 3)
        index = np.full(int(tags.max()) + 1, -1, dtype=np.int64)
        index[np.asarray(tags, dtype=np.int64)] = np.arange(len(tags))
        rest, shared = [], set()
        for _, volume in gmsh.model.getEntities(3):
            if volume == zone:
                continue
            types, _, nodes = gmsh.model.mesh.getElements(3, volume)
            if list(types) != [4]:
                raise RuntimeError(f"element types {list(types)} in the unstructured part")
            rest.append(index[np.asarray(nodes[0], dtype=np.int64)].reshape(-1, 4))
            shared |= {t for _, t in gmsh.model.getBoundary([(3, volume)], oriented=False)}
        target = set()
        for face in {t for _, t in gmsh.model.getBoundary([(3, zone)], oriented=False)} & shared:
            _, _, nodes = gmsh.model.mesh.getElements(2, face)
            target |= {tuple(t) for t in np.sort(index[np.asarray(nodes[0], dtype=np.int64)].reshape(-1, 3), axis=1)}
        zone_tags, _, _ = gmsh.model.mesh.getNodes(3, zone, includeBoundary=True)
        zone_nodes = np.unique(index[np.asarray(zone_tags, dtype=np.int64)])
        gmsh.model.remove()
        # grid indices: x and y uniform, z uniform between the curved (or flat) bottom and the flat top
        x, y, z = coords[zone_nodes].T
        i = np.rint((x - lo[0]) / (hi[0] - lo[0]) * n_xy).astype(int)
        j = np.rint((y - lo[1]) / (hi[1] - lo[1]) * n_xy).astype(int)
        zb = bottom(x, y)
        zt = np.where(np.abs(zb - lo[2]) < np.abs(zb - hi[2]), hi[2], lo[2])
        k = np.rint((z - zb) / (zt - zb) * n_z).astype(int)
        grid = np.full((n_xy + 1, n_xy + 1, n_z + 1), -1, dtype=np.int64)
        grid[i, j, k] = zone_nodes
        if len(zone_nodes) != grid.size or (grid < 0).any():
            raise RuntimeError(f"structured zone: {len(zone_nodes)} nodes for a {grid.shape} grid")
        ii, jj, kk = (a.ravel() for a in np.meshgrid(np.arange(n_xy), np.arange(n_xy), np.arange(n_z), indexing="ij"))
        for fx, fz in ((0, 0), (1, 0), (0, 1), (1, 1)):  # diagonal (+-1, +-1, +-1), same sign in x and y
            cells = np.vstack([np.column_stack([grid[ii + (a ^ fx), jj + (b ^ fx), kk + (c ^ fz)] for a, b, c in tet])
                               for tet in KUHN_TETRAHEDRA])
            faces = np.sort(np.concatenate([np.delete(cells, m, axis=1) for m in range(4)]), axis=1)
            if target <= {tuple(f) for f in faces}:
                return _compact(coords, np.vstack([*rest, cells]))
        last = arrangement
    raise RuntimeError(f"no face arrangement (last tried {last}) matches a Kuhn split of the structured zone")


_ARRANGEMENTS = [("Left", "Right", "Right"), ("Left", "Left", "Right")] + [
    a for a in itertools.product(("Left", "Right"), repeat=3)
    if a not in (("Left", "Right", "Right"), ("Left", "Left", "Right"))]


def _compact(coords: np.ndarray, cells: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    used = np.unique(cells)
    local = np.full(len(coords), -1, dtype=np.int64)
    local[used] = np.arange(len(used))
    xyz = coords[used]
    return xyz, oriented_tetrahedra(xyz, local[cells])


def _box_distance(x: float, y: float, z: float, lo, hi) -> float:
    d = [max(lo[i] - v, 0.0, v - hi[i]) for i, v in enumerate((x, y, z))]
    return math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2])


def mesh_3d_grid(scale: float):
    """hertz3dgrid: structured contact zones (Kuhn tetrahedra), unstructured elsewhere."""
    import gmsh

    g = GEOMETRY[3]
    r, w, hb = RADIUS, g["block_width"], g["block_height"]
    h = scale * GRID["spacing"]
    hm = h * GRID["master_ratio"]
    (ls, ds), (lb, db) = GRID["slave_zone"], GRID["master_zone"]
    ns, nzs = max(2, round(ls / h)), max(2, round(ds / h))
    nm, nzm = max(2, round(lb / hm)), max(2, round(db / hm))
    centre = np.array([0.0, 0.0, r])
    # rotation of the sphere: its polar axis (OCC: z) to (1, -1, 0)/sqrt(2) and its seam (the
    # half-plane of OCC's x axis) towards (-1, -1, 1)/sqrt(3); neither meets the quarter x, y >= 0, z <= r
    polar = np.array([1.0, -1.0, 0.0]) / math.sqrt(2.0)
    seam = np.array([-1.0, -1.0, 1.0]) / math.sqrt(3.0)
    rotation = np.column_stack([seam, np.cross(polar, seam), polar])
    affine = np.column_stack([rotation, centre - rotation @ centre]).ravel().tolist()

    def volume_in(lo, hi):
        for dim, tag in gmsh.model.getEntities(3):
            com = gmsh.model.occ.getCenterOfMass(dim, tag)
            if all(lo[i] < com[i] < hi[i] for i in range(3)):
                return tag
        raise RuntimeError("structured zone not found")

    def sphere():
        occ = gmsh.model.occ
        ball = occ.addSphere(0, 0, r, r)
        occ.affineTransform([(3, ball)], affine)
        quarter, _ = occ.intersect([(3, ball)], [(3, occ.addBox(0, 0, 0, r, r, r))])
        occ.fragment(quarter, [(3, occ.addBox(0, 0, 0, ls, ls, ds))])
        occ.synchronize()
        for dim, tag in gmsh.model.getEntities(3):  # the corner of the zone's box below the sphere
            if np.linalg.norm(np.array(occ.getCenterOfMass(dim, tag)) - centre) > r:
                occ.remove([(dim, tag)], recursive=True)
        occ.synchronize()
        lo, hi = (0.0, 0.0, 0.0), (ls, ls, ds)
        return volume_in(lo, hi), ns, nzs, lo, hi, lambda x, y: r - np.sqrt(r * r - x * x - y * y), (ls, ls, ds)

    def block():
        occ = gmsh.model.occ
        occ.fragment([(3, occ.addBox(0, 0, -hb, w, w, hb))], [(3, occ.addBox(0, 0, -db, lb, lb, db))])
        occ.synchronize()
        lo, hi = (0.0, 0.0, -db), (lb, lb, 0.0)
        return volume_in(lo, hi), nm, nzm, lo, hi, lambda x, y: np.zeros_like(x), (lb, lb, -db)

    def size_near(lo, hi, h0):
        def size(_entity_dim, _tag, x, y, z, _lc):
            return min(scale * GRID["h_max"], h0 + GRID["grading"] * _box_distance(x, y, z, lo, hi))
        return size

    gmsh.initialize(["-noenv"], readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.option.setNumber("General.NumThreads", 1)
        return [_mesh_grid_body(gmsh, sphere, size_near((0, 0, 0), (ls, ls, ds), h)),
                _mesh_grid_body(gmsh, block, size_near((0, 0, -db), (lb, lb, 0), hm))]
    finally:
        gmsh.finalize()


def mesh_bodies(dim: int, size, *builders):
    """Meshes each body built by ``builders`` (gmsh geometry calls) with linear triangles or
    tetrahedra; ``size(entity_dim, tag, x, y, z, lc)`` gives the mesh size."""
    import gmsh

    gmsh.initialize(["-noenv"], readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.option.setNumber("General.NumThreads", 1)
        return [_mesh_body(gmsh, dim, size, build) for build in builders]
    finally:
        gmsh.finalize()


def _boundary_faces(cells: np.ndarray) -> set:
    """Faces (sorted node tuples) that belong to exactly one element."""
    k = cells.shape[1]
    faces = np.concatenate([np.delete(cells, i, axis=1) for i in range(k)])
    faces = np.sort(faces, axis=1)
    unique, counts = np.unique(faces, axis=0, return_counts=True)
    return {tuple(f) for f in unique[counts == 1]}


def check_conforming(xyz: np.ndarray, cells: np.ndarray, dim: int) -> None:
    """3D: every face of one tetrahedron only lies on the body's outer boundary (the planes of its
    bounding box, or the sphere): a face on the boundary of a single tetrahedron inside the body
    would be a crack (a non-conforming structured zone)."""
    if dim != 3:
        return
    faces = np.array(sorted(_boundary_faces(cells)))
    p = xyz[faces]
    tol = 1e-9 * RADIUS
    ok = (np.abs(np.linalg.norm(p - np.array([0.0, 0.0, RADIUS]), axis=2) - RADIUS) < 1e-7 * RADIUS).all(axis=1)
    for axis in range(3):
        for value in (xyz[:, axis].min(), xyz[:, axis].max()):
            ok |= (np.abs(p[:, :, axis] - value) < tol).all(axis=1)
    if not ok.all():
        raise RuntimeError(f"{(~ok).sum()} boundary faces inside the body (non-conforming mesh), "
                           f"e.g. at {p[~ok][0].mean(axis=0)}")


def interface_faces(cells: np.ndarray, interface: np.ndarray) -> np.ndarray:
    """Element faces (sorted node rows) whose nodes all lie in ``interface``: what a contact process
    builds from a node-only interface part. Raises if one of them is not on the boundary, which
    would make the generated interface wrong."""
    flags = np.zeros(int(cells.max()) + 1, dtype=bool)
    flags[interface] = True
    k = cells.shape[1]
    faces = np.concatenate([np.delete(cells, i, axis=1) for i in range(k)])
    faces = np.unique(np.sort(faces[flags[faces].all(axis=1)], axis=1), axis=0)
    boundary = _boundary_faces(cells)
    inner = [tuple(f) for f in faces if tuple(f) not in boundary]
    if inner:
        raise RuntimeError(f"{len(inner)} interior faces have all their nodes on the interface, e.g. {inner[0]}")
    return faces


def mirrored_about_x(xyz: np.ndarray, cells: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The body and its mirror image about the plane x = 0, as one conforming mesh: the nodes on
    the plane are shared, the mirrored tetrahedra re-oriented."""
    on_plane = np.abs(xyz[:, 0]) < 1e-9 * RADIUS
    image = np.flatnonzero(~on_plane)
    index = np.arange(len(xyz))
    index[image] = len(xyz) + np.arange(len(image))
    mirrored = xyz[image] * np.array([-1.0, 1.0, 1.0])
    return np.vstack([xyz, mirrored]), np.vstack([cells, index[cells][:, [0, 2, 1, 3]]])


# -- writing ----------------------------------------------------------------------------------
def build_case(family: str, label: str, half: bool = False) -> dict:
    """Meshes a case and returns everything needed to write it (no files). ``half`` (3D): the
    half model y >= 0 (the quarter mirrored about x = 0), for loads along x that break the
    symmetry about that plane (Cattaneo-Mindlin)."""
    dim = 2 if family == "hertz2d" else 3
    scale = SIZES[family][label]
    g = GEOMETRY[dim]
    mesher = mesh_2d if dim == 2 else mesh_3d_grid if family == "hertz3dgrid" else mesh_3d
    (xc, cc), (xb, cb) = mesher(scale)
    if half and dim == 3:
        (xc, cc), (xb, cb) = mirrored_about_x(xc, cc), mirrored_about_x(xb, cb)
    for cells in (cc, cb):
        check_conforming(xc if cells is cc else xb, cells, dim)
    tol = 1e-9 * RADIUS
    a = TARGET_A_OVER_R * RADIUS
    top_axis = dim - 1  # y in 2D, z in 3D
    centre = np.zeros(3)
    centre[top_axis] = RADIUS

    def radial(x):  # distance from the loading axis
        return np.abs(x[:, 0]) if dim == 2 else np.hypot(x[:, 0], x[:, 1])

    on_curve = np.abs(np.linalg.norm(xc - centre, axis=1) - RADIUS) < 1e-7 * RADIUS
    slave = np.flatnonzero(on_curve & (xc[:, top_axis] < RADIUS - tol) & (radial(xc) <= 4.0 * a))
    master = np.flatnonzero((np.abs(xb[:, top_axis]) < tol) & (radial(xb) <= 5.0 * a))
    # Keep only nodes of whole interface faces: a node without a face would get a multiplier that
    # no condition couples (Kratos skips such nodes; a stricter code would find a singular system).
    slave_faces = interface_faces(cc, slave)
    master_faces = interface_faces(cb, master)
    slave, master = np.unique(slave_faces), np.unique(master_faces)
    nc = len(xc)
    coords = np.vstack([xc, xb])
    parts = {
        curved_part(dim): {"nodes": np.arange(nc), "elements": "curved"},
        "Parts_block": {"nodes": nc + np.arange(len(xb)), "elements": "block"},
        "DISPLACEMENT_top": {"nodes": np.flatnonzero(np.abs(xc[:, top_axis] - RADIUS) < tol)},
        "DISPLACEMENT_bottom": {"nodes": nc + np.flatnonzero(np.abs(xb[:, top_axis] + g["block_height"]) < tol)},
    }
    if dim == 3 and not half:
        parts["DISPLACEMENT_sym_x"] = {"nodes": np.flatnonzero(np.abs(coords[:, 0]) < tol)}
    if dim == 3:
        parts["DISPLACEMENT_sym_y"] = {"nodes": np.flatnonzero(np.abs(coords[:, 1]) < tol)}
    parts["Contact_slave"] = {"nodes": slave}
    if half and dim == 3:  # where a vector multiplier needs the symmetry condition (cattaneo_mindlin)
        parts["Contact_slave_sym_y"] = {"nodes": slave[np.abs(coords[slave, 1]) < tol]}
    parts["Contact_master"] = {"nodes": nc + master}
    for name in parts:
        if len(parts[name]["nodes"]) == 0:
            raise RuntimeError(f"{family}_{label}: sub-model-part {name} is empty")
    return {"family": family, "label": label, "dim": dim, "scale": scale, "half": half and dim == 3, "coords": coords,
            "curved_cells": cc, "block_cells": cb + nc, "parts": parts,
            "slave_faces": len(slave_faces), "master_faces": len(master_faces)}


def write_mesh(path: str, case: dict) -> dict:
    """The case's gmsh file; returns its model_import_settings. The curved body's elements are
    numbered first, then the block's; the other sub model parts hold nodes only."""
    dim = case["dim"]
    element = "SmallDisplacementElement2D3N" if dim == 2 else "SmallDisplacementElement3D4N"
    n_curved = len(case["curved_cells"])
    first = {"curved": 1, "block": n_curved + 1}
    ranges = {"curved": np.arange(1, n_curved + 1),
              "block": n_curved + np.arange(1, len(case["block_cells"]) + 1)}
    blocks = [(element, first[key], case[f"{key}_cells"]) for key in ("curved", "block")]
    parts = {name: {"nodes": content["nodes"], **({"elements": ranges[content["elements"]]}
                                                  if "elements" in content else {})}
             for name, content in case["parts"].items()}
    return write_case_mesh(path, case["coords"], blocks, parts)


def assign_displacement(part: str, constrained: list, value: list, variable: str = "DISPLACEMENT") -> dict:
    # A free component gets null, not 0.0: a number would be assigned (without fixity) at the
    # start of every step in both codes, snapping the nodes on the symmetry planes and the top
    # back to zero displacement in that component. On hertz3d_50k that jolt (4.6e-3 on faces
    # of 7e-3) made our step 3 diverge (Kratos 10.4 recovered).
    value = [v if fixed else None for v, fixed in zip(value, constrained)]
    return {"python_module": "assign_vector_variable_process", "kratos_module": "KratosMultiphysics",
            "process_name": "AssignVectorVariableProcess",
            "Parameters": {"model_part_name": f"Structure.{part}", "variable_name": variable,
                           "interval": [0.0, "End"], "constrained": constrained, "value": value}}


def project_parameters(name: str, dim: int, delta: float, linear_solver: str, model_import: dict,
                       half: bool = False, mpc: bool = False) -> dict:
    """The case's ProjectParameters: ALM contact, or with ``mpc`` multipoint-constraint contact
    (mpc_contact_settings, mpc_contact_process and the structural residual criterion, as Kratos'
    MPC cases)."""
    axis = dim - 1
    top_value: list = [0.0, 0.0, 0.0]
    top_value[axis] = f"-{delta!r}*t"
    top_fix = [dim == 2, False, False]  # 2D: u_x = 0 on the top removes the cylinder's rigid sliding
    top_fix[axis] = True
    constraints = []
    if dim == 3 and not half:
        constraints.append(assign_displacement("DISPLACEMENT_sym_x", [True, False, False], [0.0, 0.0, 0.0]))
    if dim == 3:
        constraints.append(assign_displacement("DISPLACEMENT_sym_y", [False, True, False], [0.0, 0.0, 0.0]))
    constraints += [assign_displacement("DISPLACEMENT_bottom", [True, True, True], [0.0, 0.0, 0.0]),
                    assign_displacement("DISPLACEMENT_top", top_fix, top_value)]
    body = "Contact_slave"
    contact = {"python_module": "alm_contact_process", "process_name": "ALMContactProcess",
               "solver": {"contact_settings": {"mortar_type": "ALMContactFrictionless"},
                          "convergence_criterion": "contact_residual_criterion"}}
    if mpc:
        contact = {"python_module": "mpc_contact_process", "process_name": "MPCContactProcess",
                   "solver": {"mpc_contact_settings": {"contact_type": "Frictionless"},
                              "convergence_criterion": "residual_criterion"}}
    return {
        "problem_data": {"problem_name": name, "parallel_type": "OpenMP", "echo_level": 0,
                         "start_time": 0.0, "end_time": 1.0},
        "solver_settings": {
            "model_part_name": "Structure", "domain_size": dim, "solver_type": "Static", "echo_level": 0,
            "analysis_type": "non_linear",
            "model_import_settings": model_import,
            "material_import_settings": {"materials_filename": f"{name}_materials.json"},
            **contact["solver"],
            "time_stepping": {"time_step": 1.0 / LOAD_STEPS},
            "block_builder": True, "line_search": False, "compute_reactions": True,
            "displacement_relative_tolerance": 1e-4, "displacement_absolute_tolerance": 1e-9,
            "residual_relative_tolerance": 1e-4, "residual_absolute_tolerance": 1e-9,
            "max_iteration": 30,
            "linear_solver_settings": {"solver_type": linear_solver},
        },
        "processes": {
            "constraints_process_list": constraints,
            "loads_process_list": [],
            "contact_process_list": [{
                "python_module": contact["python_module"],
                "kratos_module": "KratosMultiphysics.ContactStructuralMechanicsApplication",
                "process_name": contact["process_name"],
                "Parameters": {"model_part_name": "Structure", "contact_type": "Frictionless",
                               "contact_model_part": {"0": [body, "Contact_master"]},
                               "assume_master_slave": {"0": [body]}},
            }],
        },
        "output_processes": {},
    }


def curved_part(dim: int) -> str:
    return "Parts_cylinder" if dim == 2 else "Parts_sphere"


def materials(dim: int) -> dict:
    law = "LinearElasticPlaneStrain2DLaw" if dim == 2 else "LinearElastic3DLaw"
    variables = {"YOUNG_MODULUS": YOUNG, "POISSON_RATIO": POISSON, "DENSITY": 1.0}
    if dim == 2:
        variables["THICKNESS"] = 1.0
    curved = curved_part(dim)
    return {"properties": [
        {"model_part_name": f"Structure.{part}", "properties_id": pid,
         "Material": {"name": part, "constitutive_law": {"name": law}, "Variables": dict(variables), "Tables": {}}}
        for pid, part in ((1, curved), (2, "Parts_block"))]}


def hertz_reference(case: dict, delta: float, mpc: bool = False) -> dict:
    dim = case["dim"]
    g = GEOMETRY[dim]
    e_star = effective_modulus()
    a = TARGET_A_OVER_R * RADIUS
    force = force_for_half_width(dim, a, RADIUS, e_star)
    target = hertz_2d(force, RADIUS, e_star) if dim == 2 else hertz_3d(force, RADIUS, e_star)
    n_nodes = len(case["coords"])
    n_slave = len(case["parts"]["Contact_slave"]["nodes"])
    return {
        "case": f"{case['family']}_{case['label']}", "dimension": dim, "contact": "mpc" if mpc else "alm",
        "model": ("full model, plane strain" if dim == 2 else "half model (y >= 0)" if case["half"]
                  else "quarter model (x >= 0, y >= 0)"
                  + (", structured contact zones (Kuhn tetrahedra)" if case["family"] == "hertz3dgrid" else "")),
        "symmetry_factor": 1 if dim == 2 else 2 if case["half"] else 4,
        "radius": RADIUS, "block_width": g["block_width"], "block_height": g["block_height"],
        "young_modulus": YOUNG, "poisson_ratio": POISSON, "effective_modulus": e_star,
        "applied_displacement": delta, "load_steps": LOAD_STEPS, "mesh_scale": case["scale"],
        "h_contact": case["scale"] * (GRID["spacing"] if case["family"] == "hertz3dgrid" else g["h_contact"]),
        "target": dict(target, a_over_r=target["half_width"] / RADIUS),
        "relations": ("a = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi a), P per unit thickness" if dim == 2 else
                      "a = (3 P R / (4 E*))^(1/3), p0 = 3 P / (2 pi a^2), delta = a^2 / R"),
        "force_from": "sum of REACTION over Structure.DISPLACEMENT_bottom (vertical component) x symmetry_factor",
        "counts": {"nodes": n_nodes, "elements": len(case["curved_cells"]) + len(case["block_cells"]),
                   "curved_elements": len(case["curved_cells"]), "block_elements": len(case["block_cells"]),
                   "slave_nodes": n_slave, "master_nodes": len(case["parts"]["Contact_master"]["nodes"]),
                   "slave_faces": case["slave_faces"], "master_faces": case["master_faces"],
                   "dofs": dim * n_nodes + n_slave},
    }


def write_case(family: str, label: str, out_dir: str,
               linear_solver: str = "LinearSolversApplication.sparse_lu", half: bool = False, mpc: bool = False) -> str:
    """Generates one case into ``out_dir/<family>_<label>/`` (3D ``half``: the half model, in
    ``<family>_<label>_half/``; ``mpc``: MPC contact, in ``<family>_<label>_mpc/``) and returns that
    folder."""
    name = f"{family}_{label}" + ("_half" if half and family != "hertz2d" else "") + ("_mpc" if mpc else "")
    folder = os.path.join(out_dir, name)
    os.makedirs(folder, exist_ok=True)
    case = build_case(family, label, half)
    dim = case["dim"]
    delta = applied_displacement(dim, RADIUS, GEOMETRY[dim]["block_height"])
    model_import = write_mesh(os.path.join(folder, f"{name}.msh"), case)
    write_json_files(folder, {
        f"{name}_materials.json": materials(dim),
        "ProjectParameters.json": project_parameters(name, dim, delta, linear_solver, model_import, case["half"], mpc),
        "hertz.json": hertz_reference(case, delta, mpc)})
    return folder


def all_case_names() -> list[str]:
    return [f"{family}_{label}" for family, labels in SIZES.items() for label in labels]


def _least_squares_line(xs, ys):
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    slope = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx
    return my - slope * mx, slope


def _integrate_2d(points):
    points = sorted(points)
    return sum(0.5 * (p0 + p1) * (x1 - x0) for (x0, p0), (x1, p1) in itertools.pairwise(points))


def _integrate_3d(xs, ys, ps):
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


def load_reference(folder: str) -> dict:
    """The case's ``hertz.json`` (geometry, material, targets; written by write_case)."""
    with open(os.path.join(folder, "hertz.json")) as f:
        return json.load(f)


def evaluate(record: dict, hertz: dict) -> dict:
    """Peak pressure, half-width and force of a finished run against Hertz for its own force.

    ``record``: ``status``, ``reactions["DISPLACEMENT_bottom"]`` (the block-bottom reaction),
    ``process_info["SCALE_FACTOR"]`` and, per slave node, ``x``, ``y``, ``lm``
    (LAGRANGE_MULTIPLIER_CONTACT_PRESSURE or None), ``augmented`` and ``active`` (the records of
    benchmarks/hertz/case_runner.py). ``hertz``: load_reference(case folder).

    The ALM unknown is the multiplier over the scale factor k (ProcessInfo SCALE_FACTOR): the
    normal contact pressure is p = -k lambda (compression positive); with dual multipliers the
    nodal multiplier is already a pressure. AUGMENTED_NORMAL_CONTACT_PRESSURE (-p at converged
    active nodes) is used when there is no multiplier (penalty), -NORMAL_CONTACT_STRESS (``normal_contact_stress``)
    for MPC contact (``hertz["contact"]`` "mpc"). The pressure integrated over the
    slave surface (times the symmetry factor) must equal the reaction: ``force_from_pressure``.
    """
    if record.get("status") != "ok":
        return {}
    dim, symmetry, radius = hertz["dimension"], hertz["symmetry_factor"], hertz["radius"]
    e_star = hertz["effective_modulus"]
    force = abs(record["reactions"]["DISPLACEMENT_bottom"]) * symmetry
    theory = (hertz_2d if dim == 2 else hertz_3d)(force, radius, e_star)
    scale = (record.get("process_info") or {}).get("SCALE_FACTOR")
    nodes = []
    for n in record["slave"]:
        if hertz.get("contact") == "mpc":  # no multipliers: the pressure from the reactions
            p = -(n["normal_contact_stress"] or 0.0)
        elif n["lm"] is not None and scale is not None:
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


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cases", default="all", help="comma-separated names (e.g. hertz2d_2k,hertz3d_15k) or 'all'")
    parser.add_argument("--out", required=True, help="output folder")
    parser.add_argument("--linear-solver", default="LinearSolversApplication.sparse_lu")
    args = parser.parse_args(argv)
    names = all_case_names() if args.cases == "all" else args.cases.split(",")
    for name in names:
        family, _, label = name.partition("_")
        if family not in SIZES or label not in SIZES[family]:
            parser.error(f"unknown case {name!r}; known: {', '.join(all_case_names())}")
        folder = write_case(family, label, args.out, args.linear_solver)
        with open(os.path.join(folder, "hertz.json")) as f:
            counts = json.load(f)["counts"]
        print(f"{name}: {counts['nodes']} nodes, {counts['elements']} elements, {counts['dofs']} DoFs, "
              f"{counts['slave_nodes']} slave / {counts['master_nodes']} master nodes -> {folder}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
