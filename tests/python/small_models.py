"""Small models built in Python for the process and output tests."""
from __future__ import annotations

import numpy as np
import pytest

import mortarcontact as mc


def square_grid(nx: int = 2, ny: int = 2, name: str = "Structure", model=None):
    """A root part with (nx+1)*(ny+1) nodes on [0, nx] x [0, ny], historical DISPLACEMENT and
    REACTION, DISPLACEMENT DoFs, and sub parts ``bottom`` (y = 0), ``top`` (y = ny) and
    ``Parts.inner`` (the interior nodes). Returns (model, root part)."""
    model = model if model is not None else mc.Model()
    root = model.CreateModelPart(name, 2)
    for var in (mc.DISPLACEMENT, mc.REACTION):
        root.AddNodalSolutionStepVariable(var)
    node_id = 0
    for j in range(ny + 1):
        for i in range(nx + 1):
            node_id += 1
            root.CreateNewNode(node_id, float(i), float(j), 0.0)
    for axis in "XYZ":
        mc.VariableUtils.AddDof(root, mc.GetVariable(f"DISPLACEMENT_{axis}"), mc.GetVariable(f"REACTION_{axis}"))
    ids = np.arange(1, node_id + 1).reshape(ny + 1, nx + 1)
    root.CreateSubModelPart("bottom").AddNodes([int(i) for i in ids[0]])
    root.CreateSubModelPart("top").AddNodes([int(i) for i in ids[-1]])
    inner = root.CreateSubModelPart("Parts").CreateSubModelPart("inner")
    inner.AddNodes([int(i) for i in ids[1:-1, 1:-1].ravel()])
    return model, root


def advance(part, dt: float) -> float:
    """Starts the next step: TIME += dt (STEP += 1, history shifted) and DELTA_TIME = dt."""
    time = float(part.ProcessInfo.GetValue(mc.TIME)) + dt
    part.GetRootModelPart().CloneTimeStep(time)
    part.ProcessInfo.SetValue(mc.DELTA_TIME, dt)
    return time


def quad_elements(root, nx: int, ny: int, name: str = "SmallDisplacementElement2D4N"):
    """Quadrilateral elements over the grid of ``square_grid`` (skips the test if ``name`` is
    not registered)."""
    if name not in mc.ElementNames():
        pytest.skip(f"element {name} is not registered yet")
    props = root.CreateNewProperties(1)
    element_id = 0
    for j in range(ny):
        for i in range(nx):
            element_id += 1
            n0 = j * (nx + 1) + i + 1
            root.CreateNewElement(name, element_id, [n0, n0 + 1, n0 + nx + 2, n0 + nx + 1], props)
    return element_id


def parameters(text: str):
    return mc.Parameters(text)
