"""Numerical building blocks shared by ivy_mechanics (private).

Every helper takes the backend namespace ``xp`` first: the public functions resolve the framework
once and pass it down, so no helper pays dispatch.

Singular points and gradients. ``where(c, f(x), g(x))`` differentiates both branches, so a branch
that is singular where it is *not* selected still poisons the gradient (0 * inf = nan). The
helpers below use the "double where": the input of the singular expression is replaced by a
harmless value where that expression is not selected, and then the output is selected. No epsilon
is ever added inside a square root or a denominator, and no value is clamped.

Small angles use Taylor series in ``x**2`` below ``SMALL_ANGLE_SQ`` (|x| < 1e-2), where four
terms are exact to far below float64 precision (the first dropped term is < 1e-20).
"""

from __future__ import annotations

import math

SMALL_ANGLE_SQ = 1e-4

# Taylor coefficients in powers of x**2.
SINC = (1.0, -1.0 / 6.0, 1.0 / 120.0, -1.0 / 5040.0)  # sin(x) / x
HALF_SIN_OVER_X = (0.5, -1.0 / 48.0, 1.0 / 3840.0, -1.0 / 645120.0)  # sin(x / 2) / x
COS_HALF = (1.0, -1.0 / 8.0, 1.0 / 384.0, -1.0 / 46080.0)  # cos(x / 2)
ONE_MINUS_COS_OVER_X2 = (0.5, -1.0 / 24.0, 1.0 / 720.0, -1.0 / 40320.0)  # (1 - cos x) / x**2
X_MINUS_SIN_OVER_X3 = (1.0 / 6.0, -1.0 / 120.0, 1.0 / 5040.0, -1.0 / 362880.0)  # (x - sin x) / x**3
ATAN_OVER_X = (1.0, -1.0 / 3.0, 1.0 / 5.0, -1.0 / 7.0)  # atan(x) / x
# (1 - (x / 2) cot(x / 2)) / x**2, the coefficient of hat(w)**2 in the inverse SE(3) Jacobian.
SE3_LOG_D = (1.0 / 12.0, 1.0 / 720.0, 1.0 / 30240.0, 1.0 / 1209600.0)

PI = math.pi
TWO_PI = 2.0 * math.pi
HALF_PI = 0.5 * math.pi


def horner(x2, coeffs):
    """The polynomial ``sum(c_i * x2**i)``, evaluated by Horner's rule."""
    acc = x2 * coeffs[-1] + coeffs[-2]
    for c in reversed(coeffs[:-2]):
        acc = acc * x2 + c
    return acc


def split_small(xp, x2, threshold=SMALL_ANGLE_SQ):
    """``(small, x)``: the mask ``x2 < threshold`` and ``sqrt(x2)`` where not small (1 where small,
    so that expressions in ``x`` stay finite, with finite gradients, where they are not used)."""
    small = x2 < threshold
    return small, xp.sqrt(xp.where(small, xp.ones_like(x2), x2))


def safe_sqrt(xp, x2):
    """``sqrt(x2)`` for ``x2 >= 0`` whose gradient at 0 is 0 instead of inf (no epsilon)."""
    positive = x2 > 0
    root = xp.sqrt(xp.where(positive, x2, xp.ones_like(x2)))
    return xp.where(positive, root, xp.zeros_like(x2))


def sum_sq(xp, v, keepdims=True):
    """Sum of squares over the last axis."""
    return xp.sum(v * v, axis=-1, keepdims=keepdims)


def safe_norm(xp, v, keepdims=True):
    """Euclidean norm over the last axis, with a zero (not nan) gradient at the zero vector."""
    return safe_sqrt(xp, sum_sq(xp, v, keepdims))


def safe_hypot(xp, a, b):
    """``sqrt(a**2 + b**2)`` with a zero gradient at (0, 0)."""
    return safe_sqrt(xp, a * a + b * b)


def safe_atan2(xp, y, x):
    """``atan2(y, x)``, 0 at (0, 0), with finite gradients there (atan2's own are 0/0 = nan)."""
    origin = xp.logical_and(xp.equal(x, 0), xp.equal(y, 0))
    return xp.atan2(y, xp.where(origin, xp.ones_like(x), x))


def wrap_angle(xp, angle):
    """Map angles in ``[-2 pi, 2 pi]`` to ``(-pi, pi]`` (piecewise linear: gradient 1)."""
    angle = xp.where(angle > PI, angle - TWO_PI, angle)
    return xp.where(angle <= -PI, angle + TWO_PI, angle)


def stack_vector(xp, components):
    """Stack same-shaped arrays along a new last axis."""
    return xp.stack(components, axis=-1)


def stack_matrix(xp, rows):
    """Build ``[..., n, m]`` from a list of n rows of m same-shaped arrays (no reshape, so it
    works with unknown batch shapes under tf.function)."""
    return xp.stack([xp.stack(row, axis=-1) for row in rows], axis=-2)


def transpose_last(xp, m):
    """Swap the last two axes."""
    return xp.swapaxes(m, -1, -2)


def matvec(xp, m, v):
    """``m @ v`` for matrices ``[..., n, k]`` and vectors ``[..., k]`` (batch dims broadcast)."""
    return xp.matmul(m, v[..., None])[..., 0]


def cross(xp, a, b):
    """Cross product over the last axis, written elementwise (broadcasts on every backend)."""
    ax, ay, az = a[..., 0], a[..., 1], a[..., 2]
    bx, by, bz = b[..., 0], b[..., 1], b[..., 2]
    return xp.stack([ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx], axis=-1)
