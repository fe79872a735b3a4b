"""Constants of ivy_mechanics' kernels (private): Taylor coefficients for the small-angle branches
of :func:`ivy.taylor_switch`, and angle wrapping.

Each series is in powers of ``x**2``; four terms are exact to far below float64 precision where
``taylor_switch`` uses them (``|x| < 1e-2``: the first dropped term is below ``1e-20``).
"""

from __future__ import annotations

import math

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


def wrap_angle(xp, angle):
    """Map angles in ``[-2 pi, 2 pi]`` to ``(-pi, pi]`` (piecewise linear: gradient 1)."""
    angle = xp.where(angle > PI, angle - TWO_PI, angle)
    return xp.where(angle <= -PI, angle + TWO_PI, angle)
