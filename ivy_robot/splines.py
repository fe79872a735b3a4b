"""Spline paths through anchor values, differentiable with respect to the anchors.

Two interpolants, both exact at the anchors:

- ``"polyharmonic"`` (the original ivy_robot's interpolator): ``s(x) = sum_i w_i phi(|x - c_i|) +
  v_0 + v . x`` with ``phi(r) = r`` (order 1), ``r**2 log r`` (order 2, the thin-plate spline) or
  ``r**3`` (order 3), and a linear term; ``w, v`` solve ``[[Phi, P], [P^T, 0]] [w; v] = [f; 0]``.
  It equals ``scipy.interpolate.RBFInterpolator(kernel='linear' | 'thin_plate_spline' | 'cubic',
  degree=1)`` and works for anchor points of any dimension.
- ``"bspline"``: the interpolating cubic B-spline with not-a-knot ends, on a 1-D parameter
  (``scipy.interpolate.make_interp_spline(x, y, k=3)``); it needs at least 4 anchors. Outside
  the anchors it extrapolates the first and last polynomial pieces, as scipy does.

Both are linear in the anchor values: the gradient with respect to them flows through one linear
solve, on every backend.
"""

from __future__ import annotations

import ivy
from ivy.typing import Array, Framework
from ivy_robot import _arrays as A

__all__ = ["sample_spline_path", "spline_weights", "polyharmonic_kernel"]

_METHODS = ("polyharmonic", "bspline")


def polyharmonic_kernel(sq_dist: Array, order: int, *, f: Framework = None) -> Array:
    """The polyharmonic radial basis function of the squared distance.

    ``r`` for order 1, ``r**2 log r`` for order 2 (0 at ``r = 0``) and ``r**3`` for order 3, with
    finite gradients at ``r = 0``.

    Args:
        sq_dist: squared distances ``r**2`` (``>= 0``), any shape.
        order: 1, 2 or 3.
        f: framework name or namespace; inferred from ``sq_dist`` if None.

    Returns:
        ``phi(r)``, of ``sq_dist``'s shape and dtype.

    Example:
        >>> polyharmonic_kernel(np.array([0.0, 4.0]), 3)
        array([0., 8.])
    """
    xp = ivy.get_framework(sq_dist, f=f)
    return _phi(xp, sq_dist, order)


def _phi(xp, sq_dist, order):
    if order == 1:
        return xp.safe_sqrt(sq_dist)
    if order == 2:
        positive = sq_dist > 0
        log = xp.log(xp.where(positive, sq_dist, xp.ones_like(sq_dist)))
        return 0.5 * sq_dist * log
    if order == 3:
        return sq_dist * xp.safe_sqrt(sq_dist)
    raise ValueError(f"polyharmonic spline: order must be 1, 2 or 3, got {order!r}")


def _sq_dists(xp, x, y):
    """``|x_i - y_j|**2`` *[..., N, M]* for points *[..., N, D]* and *[..., M, D]*."""
    diff = x[..., :, None, :] - y[..., None, :, :]
    return xp.sum(diff * diff, axis=-1)


def _polyharmonic(xp, anchor_points, anchor_values, sample_points, order):
    dim = anchor_points.shape[-1]
    if anchor_points.shape[-2] < dim + 1:
        raise ValueError(
            f"sample_spline_path: the linear term needs at least {dim + 1} anchors in "
            f"{dim}-D, got {anchor_points.shape[-2]}"
        )
    phi = _phi(xp, _sq_dists(xp, anchor_points, anchor_points), order)
    poly = xp.concat([xp.ones_like(anchor_points[..., 0:1]), anchor_points], axis=-1)
    lhs = xp.concat(
        [
            xp.concat([phi, poly], axis=-1),
            xp.concat([xp.swapaxes(poly, -1, -2), xp.zeros_like(poly[..., : dim + 1, :])], axis=-1),
        ],
        axis=-2,
    )
    rhs = xp.concat([anchor_values, xp.zeros_like(anchor_values[..., : dim + 1, :])], axis=-2)
    coeffs = xp.solve(lhs, rhs)
    sample_phi = _phi(xp, _sq_dists(xp, sample_points, anchor_points), order)
    sample_poly = xp.concat([xp.ones_like(sample_points[..., 0:1]), sample_points], axis=-1)
    return xp.matmul(xp.concat([sample_phi, sample_poly], axis=-1), coeffs)


def _bspline_basis(xp, x, knots, count):
    """Cubic B-spline basis functions *[..., S, count]* at ``x`` *[..., S]* for the numpy knot
    vector ``knots`` (Cox-de Boor).

    Outside the knots the polynomial piece of the nearest interval continues (as scipy's
    ``BSpline(extrapolate=True)``): points before the first interval count as inside it, points
    at or after the end of the last interval count as inside the last one. The recurrence then
    evaluates that piece's polynomial, so the path extrapolates smoothly instead of dropping to
    0. A NaN point stays NaN."""
    t = [float(k) for k in knots]
    intervals = [i for i in range(len(t) - 1) if t[i] < t[i + 1]]
    first, last = intervals[0], intervals[-1]
    x = x[..., None]
    lo, hi = A.to_backend(xp, t[:-1], x), A.to_backend(xp, t[1:], x)
    inside = xp.logical_and(x >= lo, x < hi)
    is_first = xp.asarray([i == first for i in range(len(t) - 1)], device=xp.dev(x))
    is_last = xp.asarray([i == last for i in range(len(t) - 1)], device=xp.dev(x))
    before = xp.logical_and(is_first, x < lo)
    after = xp.logical_and(is_last, x >= hi)
    basis = xp.astype(xp.logical_or(inside, xp.logical_or(before, after)), x.dtype)
    for degree in range(1, 4):
        m = len(t) - 1 - degree
        left_den = [t[i + degree] - t[i] for i in range(m)]
        right_den = [t[i + degree + 1] - t[i + 1] for i in range(m)]
        ti = A.to_backend(xp, t[:m], x)
        tr = A.to_backend(xp, t[degree + 1 : degree + 1 + m], x)
        inv_l = A.to_backend(xp, [1.0 / v if v > 0 else 0.0 for v in left_den], x)
        inv_r = A.to_backend(xp, [1.0 / v if v > 0 else 0.0 for v in right_den], x)
        basis = (x - ti) * inv_l * basis[..., :m] + (tr - x) * inv_r * basis[..., 1 : m + 1]
    return basis[..., :count]


def _not_a_knot(points):
    """scipy's not-a-knot knot vector for cubic interpolation at the numpy ``points``."""
    import numpy as np

    return np.concatenate([[points[0]] * 4, points[2:-2], [points[-1]] * 4])


def _bspline(xp, anchor_points, anchor_values, sample_points):
    import numpy as np

    if anchor_points.shape[-1] != 1 or sample_points.shape[-1] != 1:
        raise ValueError(
            "sample_spline_path: the bspline method needs a 1-D parameter: anchor_points and "
            "sample_points of shape [..., N, 1]"
        )
    n = anchor_points.shape[-2]
    if n < 4:
        raise ValueError(f"sample_spline_path: the cubic bspline needs at least 4 anchors, got {n}")
    try:
        params = np.asarray(ivy.to_numpy(anchor_points), dtype=np.float64)
    except Exception as err:
        raise ValueError(
            "sample_spline_path: the bspline method needs concrete anchor_points (its knots "
            "are built from them); pass them as constants, not traced values"
        ) from err
    params = params.reshape(-1, n)
    if not np.all(params == params[0]):
        raise ValueError(
            "sample_spline_path: bspline anchor_points must be the same in every batch"
        )
    params = params[0]
    if np.any(np.diff(params) <= 0):
        raise ValueError("sample_spline_path: bspline anchor_points must be strictly increasing")
    knots = _not_a_knot(params)
    collocation = _bspline_basis(xp, anchor_points[..., 0], knots, n)
    coeffs = xp.solve(collocation, anchor_values + xp.zeros_like(collocation[..., 0:1]))
    return xp.matmul(_bspline_basis(xp, sample_points[..., 0], knots, n), coeffs)


def sample_spline_path(
    anchor_points: Array,
    anchor_values: Array,
    sample_points: Array,
    order: int = 3,
    *,
    method: str = "polyharmonic",
    f: Framework = None,
) -> Array:
    """Sample the spline through ``(anchor_points, anchor_values)`` at ``sample_points``.

    Args:
        anchor_points: anchor locations *[batch_shape, num_anchors, point_dim]* (for a path,
            ``point_dim = 1``: times in [0, 1], not necessarily evenly spaced).
        anchor_values: values at the anchors *[batch_shape, num_anchors, value_dim]*.
        sample_points: where to sample *[batch_shape, num_samples, point_dim]*.
        order: polyharmonic order: 1 (piecewise linear in 1-D), 2 (thin-plate) or 3 (cubic);
            the ``bspline`` method is cubic (order 3).
        method: ``"polyharmonic"`` or ``"bspline"`` (see the module docstring).
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        The path at the sample points *[batch_shape, num_samples, value_dim]*.

    Example:
        >>> t = np.linspace(0, 1, 4)[:, None]
        >>> values = np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 1.0], [3.0, 0.0]])
        >>> sample_spline_path(t, values, np.linspace(0, 1, 50)[:, None]).shape
        (50, 2)
    """
    xp = ivy.get_framework(anchor_points, anchor_values, sample_points, f=f)
    if method not in _METHODS:
        raise ValueError(f"sample_spline_path: method must be one of {_METHODS}, got {method!r}")
    for name, arr in (("anchor_points", anchor_points), ("anchor_values", anchor_values)):
        A.check_floating(xp, arr, name, "sample_spline_path")
    if len(anchor_points.shape) < 2 or len(sample_points.shape) < 2:
        raise ValueError(
            "sample_spline_path: anchor_points and sample_points need shape [..., N, point_dim]; "
            "reshape 1-D parameters to [..., N, 1]"
        )
    if anchor_points.shape[-1] != sample_points.shape[-1]:
        raise ValueError(
            f"sample_spline_path: anchor_points have dimension {anchor_points.shape[-1]} but "
            f"sample_points {sample_points.shape[-1]}"
        )
    if anchor_values.shape[-2] != anchor_points.shape[-2]:
        raise ValueError(
            f"sample_spline_path: {anchor_points.shape[-2]} anchor_points but "
            f"{anchor_values.shape[-2]} anchor_values; give one value row per anchor"
        )
    if method == "bspline":
        if order != 3:
            raise ValueError(
                f"sample_spline_path: the bspline method is cubic (order 3), got {order}"
            )
        return _bspline(xp, anchor_points, anchor_values, sample_points)
    if order not in (1, 2, 3):
        raise ValueError(f"sample_spline_path: order must be 1, 2 or 3, got {order!r}")
    return _polyharmonic(xp, anchor_points, anchor_values, sample_points, order)


def spline_weights(
    anchor_points: Array,
    sample_points: Array,
    order: int = 3,
    *,
    method: str = "polyharmonic",
    f: Framework = None,
) -> Array:
    """The matrix ``W`` with ``sample_spline_path(anchor_points, V, sample_points) == W @ V``
    for every ``V``: the path is linear in the anchor values, so fixed anchor and sample points
    give a constant matrix, and sampling a path is one matrix product (what the planners do).

    Args:
        anchor_points: anchor locations *[num_anchors, point_dim]*.
        sample_points: sample locations *[num_samples, point_dim]*.
        order: as :func:`sample_spline_path`.
        method: as :func:`sample_spline_path`.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        *[num_samples, num_anchors]*.

    Example:
        >>> t, s = np.linspace(0, 1, 5)[:, None], np.linspace(0, 1, 100)[:, None]
        >>> W = spline_weights(t, s)
        >>> values = np.random.default_rng(0).normal(size=(5, 3))
        >>> bool(np.allclose(W @ values, sample_spline_path(t, values, s)))
        True
    """
    xp = ivy.get_framework(anchor_points, sample_points, f=f)
    n = anchor_points.shape[-2]
    eye = xp.eye(n, dtype=anchor_points.dtype, device=xp.dev(anchor_points))
    return sample_spline_path(anchor_points, eye, sample_points, order, method=method, f=xp)
