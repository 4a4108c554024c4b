# SPDX-License-Identifier: BSD-3-Clause
"""Penalty frictional mortar contact, Coulomb and Tresca (derivation in README.md)."""

from codegen import dot

FAMILY = "penalty_frictional"
FUNCTION = "PenaltyFrictional"
VECTOR_MULTIPLIER = False
MULTIPLIERS = False
FRICTIONAL = True


def stick(sym, j):
    """Stick: the penalty traction eps g n + c_tau eps s against the virtual jump."""
    eps, g = sym.eps[j], sym.weighted_gap(j)
    traction = [eps * g * nc + sym.ct * eps * sc for nc, sc in zip(sym.n1[j], sym.weighted_slip(j))]
    return sym.df[j] * dot(traction, sym.test_jump(j))


def slip(sym, j):
    """Slip: the traction eps g n + b d, b = tau - mu eps g (Coulomb: tau = 0; Tresca: mu = 0),
    d = s / |s| (the direction of the augmented tangent pressure c_tau eps s), against the virtual
    jump."""
    eps, g, s = sym.eps[j], sym.weighted_gap(j), sym.weighted_slip(j)
    direction = sym.direction(j, s)
    bound = sym.tau[j] - sym.mu[j] * eps * g
    traction = [eps * g * nc + bound * dc for nc, dc in zip(sym.n1[j], direction)]
    return sym.df[j] * dot(traction, sym.test_jump(j))


def inactive(sym, j):
    """Open node: no contribution."""
    return 0
