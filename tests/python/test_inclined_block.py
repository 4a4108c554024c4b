"""Issue 12: a block on an inclined plane, Coulomb friction, implicit dynamics (Bossak). The plane
is the top of a clamped base; the slope is in the gravity, g (sin theta, -cos theta), applied to the
block from rest at t = 0. With tan theta < mu the block sticks (its displacement is the elastic
settling alone, about 1e-6 of its size); above, it slides with the rigid-body acceleration
a = g (sin theta - mu cos theta): its mean displacement along the slope follows a t^2 / 2.

Plane strain, linear quadrilaterals, ALMContactFrictional with the block as the slave. The block is
stiff (its first elastic periods are about 1e-3, against time steps of 1e-2 that Bossak's numerical
damping filters), so that its motion is the rigid body's."""
from __future__ import annotations

import contextlib
import math

import numpy as np
import pytest

import mortarcontact as mc
from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
from mortarcontact.project_parameters import read_project_parameters

from case_builder import write_block_on_base

GRAVITY = 10.0
SLOPE = math.atan(0.5)  # tan theta = 0.5
BLOCK = (0.5, 0.25)  # width, height
BASE = (2.0, 0.25)
TIME_STEP, END_TIME = 0.01, 0.5


def write_inclined_block(folder, friction: float, slip_augmentation: float) -> str:
    return write_block_on_base(
        folder, "inclined_block", block=BLOCK, base=BASE, cells=(8, 4, 24, 3), friction=friction,
        gravity=(GRAVITY, (math.sin(SLOPE), -math.cos(SLOPE), 0.0)), end_time=END_TIME, time_step=TIME_STEP,
        solver={"solver_type": "Dynamic", "time_integration_method": "implicit", "scheme_type": "bossak",
                "buffer_size": 3, "contact_settings": {"mortar_type": "ALMContactFrictional"},
                "convergence_criterion": "contact_residual_criterion", "max_iteration": 15,
                "residual_relative_tolerance": 1e-8, "residual_absolute_tolerance": 1e-12},
        contact=("alm_contact_process", {"contact_type": "Frictional",
                                         "slip_augmentation_coefficient": slip_augmentation}))


class BlockHistory(StructuralMechanicsAnalysis):
    """Mean displacement of the block along the slope after each step."""

    def __init__(self, model, params):
        super().__init__(model, params, progress=False)
        self.history = []

    def FinalizeSolutionStep(self):
        super().FinalizeSolutionStep()
        part = self.model["Structure"]
        block = part.GetSubModelPart("Parts_block")
        u = np.array([n.GetSolutionStepValue(mc.GetVariable("DISPLACEMENT")) for n in block.Nodes])
        self.history.append((part.GetProcessInfo().GetValue(mc.GetVariable("TIME")), float(u[:, 0].mean()),
                             float(u[:, 1].mean()), len(self.solver.LastIterationHistory())))


def slide(folder, friction: float, slip_augmentation: float = 1.0) -> np.ndarray:
    path = write_inclined_block(str(folder), friction, slip_augmentation)
    with contextlib.chdir(folder):
        analysis = BlockHistory(mc.Model(), read_project_parameters(path))
        analysis.Run()
    return np.array(analysis.history)


def test_block_slides_with_the_coulomb_acceleration(tmp_path):
    """With slip_augmentation_coefficient 1 the slip direction is that of the augmented tangential
    traction k lambda_t + c_tau eps s, which follows the slip. Bossak starts from a zero
    acceleration, so the velocity lags by about a dt / 2 from the first step on: the fit is
    x = v0 t + a t^2 / 2, and the history stays within a dt t / 2 of a t^2 / 2."""
    friction = 0.3
    history = slide(tmp_path, friction)
    t, x = history[:, 0], history[:, 1]
    a = GRAVITY * (math.sin(SLOPE) - friction * math.cos(SLOPE))
    (lag, fitted), *_ = np.linalg.lstsq(np.column_stack([t, t * t / 2]), x, rcond=None)
    error = np.abs(x - 0.5 * a * t * t).max() / (0.5 * a * END_TIME ** 2)
    print(f"sliding: a = {a:.4f}, fitted {fitted:.4f} ({fitted / a - 1:+.2e}), initial velocity lag {lag:.2e} "
          f"(a dt / 2 = {a * TIME_STEP / 2:.2e}); largest deviation from a t^2/2: {error:.2e} of the final slip "
          f"{0.5 * a * END_TIME ** 2:.4f}; Newton iterations per step {history[:, 3].astype(int).tolist()}")
    assert fitted == pytest.approx(a, rel=1e-2)
    assert abs(lag) < a * TIME_STEP
    assert error < 3e-2
    assert abs(history[:, 2]).max() < 1e-4 * BLOCK[1]  # it stays on the plane
    assert history[:, 3].max() <= 6


@pytest.mark.xfail(strict=True, reason="with Kratos' default slip_augmentation_coefficient 0 the slip direction is "
                   "the tangential multiplier's own, not tied to the slip: at t = 0.24 (slip 0.045) Newton cycles "
                   "between two iterates with unchanged active and slip sets (15 iterations), and the block then "
                   "moves back up the slope")
def test_block_slides_with_the_default_slip_augmentation(tmp_path):
    history = slide(tmp_path, 0.3, slip_augmentation=0.0)
    a = GRAVITY * (math.sin(SLOPE) - 0.3 * math.cos(SLOPE))
    assert np.all(np.diff(history[:, 1]) > 0.0)
    assert history[-1, 1] == pytest.approx(0.5 * a * END_TIME ** 2, rel=3e-2)


def test_block_sticks_below_the_friction_angle(tmp_path):
    history = slide(tmp_path, 0.6)
    sliding = 0.5 * GRAVITY * (math.sin(SLOPE) - 0.3 * math.cos(SLOPE)) * END_TIME ** 2
    print(f"sticking: largest mean displacement along the slope {abs(history[:, 1]).max():.2e} "
          f"(sliding with mu = 0.3 would reach {sliding:.3f}); Newton iterations {history[:, 3].astype(int).tolist()}")
    assert abs(history[:, 1]).max() < 1e-5 * BLOCK[0]
