# SPDX-License-Identifier: BSD-3-Clause
"""Augmented Lagrangian frictional mortar contact, Coulomb and Tresca (derivation in README.md).

Vector multiplier lambda_j; lbar_n = k n.lambda + eps g is the augmented normal pressure, T(v) =
v - n (n.v) the tangential part at slave node j, and b = tau - mu lbar_n the friction bound of a
slipping node (Coulomb: tau = 0; Tresca: mu = 0)."""

from codegen import dot

FAMILY = "alm_frictional"
FUNCTION = "ALMFrictional"
VECTOR_MULTIPLIER = True
MULTIPLIERS = True
FRICTIONAL = True


def _normal_pressure(sym, j):
    return sym.k * dot(sym.n1[j], sym.lm[j]) + sym.eps[j] * sym.weighted_gap(j)


def stick(sym, j):
    """Stick: the augmented traction lbar_n n + lbar_t (lbar_t = k T(lambda) + c_tau eps s) against
    the virtual jump, the normal constraint k g (n . wl) and the stick constraint k s . T(wl)."""
    n, s = sym.n1[j], sym.weighted_slip(j)
    traction = [sym.k * lc + sym.eps[j] * sym.weighted_gap(j) * nc + sym.ct * sym.eps[j] * sc
                for lc, nc, sc in zip(sym.lm[j], n, s)]
    work = dot(traction, sym.test_jump(j))
    normal_constraint = sym.k * sym.weighted_gap(j) * dot(n, sym.wl[j])
    stick_constraint = sym.k * dot(s, sym.tangential(j, sym.wl[j]))
    return sym.df[j] * work + normal_constraint + stick_constraint


def slip(sym, j):
    """Slip: the traction lbar_n n + b d (d = lbar_t / |lbar_t|, lbar_t = k T(lambda) + c_slip c_tau
    eps s, b = tau - mu lbar_n) against the virtual jump, the normal constraint and the tangential
    constraint -k^2/eps T(wl) . (T(lambda) - b d / k) driving k T(lambda) to the limit.

    Kratos scales that constraint by k^2/(c_tau eps): the same solutions (a constant factor per
    row), but the multiplier rows are Cartesian, k g n - s T(limit) with s the scale, so at every
    iteration the rotation of the slave normal carries the tangential residual into the gap
    equation, amplified by s / k = k / (c_tau eps) against the normal row's k: 40 with the default
    c_tau = 0.025 and k = eps. On the Cattaneo-Mindlin shift (hertz2d_2k, normal variation) Newton then
    converged linearly (factors 0.3 to 1e-3 with exact tangents) and step 7 of 8 diverged. With
    k^2/eps the slip row has the units and scale of the stick row (k s . T(wl)) and the normal
    row (k g), and Newton converges quadratically (tests/python/test_newton_convergence.py)."""
    n, s = sym.n1[j], sym.weighted_slip(j)
    pressure = _normal_pressure(sym, j)
    lm_t = sym.tangential(j, sym.lm[j])
    augmented_t = [sym.k * lc + sym.cs * sym.ct * sym.eps[j] * sc for lc, sc in zip(lm_t, s)]
    direction = sym.direction(j, augmented_t)
    bound = sym.tau[j] - sym.mu[j] * pressure
    traction = [pressure * nc + bound * dc for nc, dc in zip(n, direction)]
    work = dot(traction, sym.test_jump(j))
    normal_constraint = sym.k * sym.weighted_gap(j) * dot(n, sym.wl[j])
    limit = [lc - bound * dc / sym.k for lc, dc in zip(lm_t, direction)]
    tangential = -(sym.k**2 / sym.eps[j]) * dot(sym.tangential(j, sym.wl[j]), limit)
    return sym.df[j] * work + normal_constraint + tangential


def inactive(sym, j):
    """Gap zone: every component of the multiplier is driven to zero."""
    return -sym.k**2 / sym.eps[j] * dot(sym.lm[j], sym.wl[j])

