# SPDX-License-Identifier: BSD-3-Clause
"""Penalty frictionless mortar contact (derivation in README.md)."""

FAMILY = "penalty_frictionless"
FUNCTION = "PenaltyFrictionless"
VECTOR_MULTIPLIER = False
MULTIPLIERS = False


def active(sym, j):
    """Penetrating node: the penalty pressure eps g_j against the virtual normal jump."""
    g = sym.weighted_gap(j)
    normal_jump = sum(nc * jc for nc, jc in zip(sym.n1[j], sym.test_jump(j)))
    return sym.df[j] * sym.eps[j] * g * normal_jump


def inactive(sym, j):
    """Open node: no contribution."""
    return 0
