# SPDX-License-Identifier: BSD-3-Clause
"""Scalar augmented Lagrangian frictionless mortar contact (derivation in README.md)."""

FAMILY = "alm_frictionless"
FUNCTION = "ALMFrictionless"
VECTOR_MULTIPLIER = False
MULTIPLIERS = True


def active(sym, j):
    """Contact zone: augmented pressure times the virtual normal jump, plus k g_j dlambda_j."""
    g = sym.weighted_gap(j)
    augmented_pressure = sym.k * sym.lm[j] + sym.eps[j] * g
    normal_jump = sum(nc * jc for nc, jc in zip(sym.n1[j], sym.test_jump(j)))
    return sym.df[j] * augmented_pressure * normal_jump + sym.k * g * sym.wl[j]


def inactive(sym, j):
    """Gap zone: the multiplier is driven to zero."""
    return -sym.k**2 / sym.eps[j] * sym.lm[j] * sym.wl[j]
