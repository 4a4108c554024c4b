# SPDX-License-Identifier: BSD-3-Clause
"""Vector (components) augmented Lagrangian frictionless mortar contact (derivation in README.md)."""

from codegen import dot

FAMILY = "alm_frictionless_components"
FUNCTION = "ALMFrictionlessComponents"
VECTOR_MULTIPLIER = True
MULTIPLIERS = True


def active(sym, j):
    """Contact zone: augmented traction k lambda + eps g n against the virtual jump, the normal
    constraint k g (n . dlambda) and the penalised tangential multiplier."""
    n = sym.n1[j]
    g = sym.weighted_gap(j)
    augmented = [sym.k * lc + sym.eps[j] * g * nc for lc, nc in zip(sym.lm[j], n)]
    work = dot(augmented, sym.test_jump(j))
    normal_constraint = sym.k * g * dot(n, sym.wl[j])
    tangential = dot(sym.tangential(j, sym.lm[j]), sym.tangential(j, sym.wl[j]))
    return sym.df[j] * work + normal_constraint - sym.k**2 / sym.eps[j] * tangential


def inactive(sym, j):
    """Gap zone: every component of the multiplier is driven to zero."""
    return -sym.k**2 / sym.eps[j] * dot(sym.lm[j], sym.wl[j])
