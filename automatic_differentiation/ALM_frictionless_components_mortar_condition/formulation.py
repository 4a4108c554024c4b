# SPDX-License-Identifier: BSD-3-Clause
"""Vector (components) augmented Lagrangian frictionless mortar contact (derivation in README.md)."""

FAMILY = "alm_frictionless_components"
FUNCTION = "ALMFrictionlessComponents"
VECTOR_MULTIPLIER = True
MULTIPLIERS = True


def _tangential(n, v):
    """v - n (n . v)."""
    nv = sum(a * b for a, b in zip(n, v))
    return [vc - nc * nv for vc, nc in zip(v, n)]


def active(sym, j):
    """Contact zone: augmented traction k lambda + eps g n against the virtual jump, the normal
    constraint k g (n . dlambda) and the penalised tangential multiplier."""
    n = sym.n1[j]
    g = sym.weighted_gap(j)
    augmented = [sym.k * lc + sym.eps[j] * g * nc for lc, nc in zip(sym.lm[j], n)]
    work = sum(a * b for a, b in zip(augmented, sym.test_jump(j)))
    normal_constraint = sym.k * g * sum(nc * wc for nc, wc in zip(n, sym.wl[j]))
    tangential = sum(a * b for a, b in zip(_tangential(n, sym.lm[j]), _tangential(n, sym.wl[j])))
    return sym.df[j] * work + normal_constraint - sym.k**2 / sym.eps[j] * tangential


def inactive(sym, j):
    """Gap zone: every component of the multiplier is driven to zero."""
    return -sym.k**2 / sym.eps[j] * sum(lc * wc for lc, wc in zip(sym.lm[j], sym.wl[j]))
