"""Voxel grids: points (and their features) binned into a regular 3-D grid.

Example:
    >>> points = np.array([[0.1, 0.1, 0.1], [0.9, 0.9, 0.9], [0.2, 0.1, 0.1]])
    >>> grid, dims, res, lower = coords_to_voxel_grid(points, (2, 2, 2), coord_bounds=(0, 0, 0, 1, 1, 1))
    >>> grid[0, 0, 0]                       # mean point, then the count
    array([0.15, 0.1 , 0.1 , 2.  ])
"""

from __future__ import annotations

import ivy
from ivy.typing import Array, Framework
from ivy_vision import _common as C
from ivy_vision import _splat as S
from ivy_vision._checks import InputError, checked

__all__ = ["coords_to_voxel_grid"]

MODES = ("DIMS", "RES")


def _per_batch(xp, spec, size, batch, like, what):
    """``spec`` (``size`` numbers, or an array ``[*B, size]``) as an array ``[*B, 1, size]``."""
    if hasattr(spec, "shape") and not isinstance(spec, (tuple, list)):
        arr = xp.astype(xp.asarray(spec, device=xp.dev(like)), xp.dtype(like))
    else:
        values = [float(v) for v in spec]
        if len(values) != size:
            raise InputError(f"{what} must have {size} values; got {len(values)}.")
        arr = xp.asarray(values, dtype=xp.dtype(like), device=xp.dev(like))
    if C.shape_of(xp, arr)[-1:] != (size,):
        raise InputError(f"{what} must be [..., {size}]; got shape {C.shape_of(xp, arr)}.")
    return xp.broadcast_to(arr[..., None, :], (*batch, 1, size))


@checked
def coords_to_voxel_grid(
    coords: Array,
    voxel_shape_spec,
    mode: str = "DIMS",
    coord_bounds=None,
    features: Array | None = None,
    *,
    f: Framework = None,
) -> tuple:
    """Bin points into a voxel grid holding, per voxel, the mean point, the mean features and
    the number of points.

    Binning follows ``numpy.histogramdd``: with bounds ``[lo, hi]`` and ``n`` voxels along an
    axis the voxels are ``[lo + k res, lo + (k + 1) res)``, the last one closed (it includes
    ``hi``); points outside the bounds are left out. Without ``coord_bounds`` the bounds are
    each batch item's own extent. Points with a NaN or infinite coordinate are left out.
    ``'DIMS'`` mode gives the number of voxels along x, y, z
    (static shapes: it compiles); ``'RES'`` mode gives the voxel size, the number of voxels
    being ``ceil(extent / res)`` (the resolution is then adjusted to ``extent / dims``) and the
    grid the largest over the batch (each item's voxels start at its lower corner); the number
    of voxels then depends on the data, so ``'RES'`` runs eagerly only.

    Args:
        coords: points *[batch_shape, num_points, 3 or 4]* (homogeneous ones are accepted).
        voxel_shape_spec: ``(nx, ny, nz)`` voxels (``'DIMS'``) or ``(rx, ry, rz)`` voxel sizes
            (``'RES'``), numbers or an array *[batch_shape, 3]*.
        mode: ``'DIMS'`` or ``'RES'``.
        coord_bounds: ``(x_min, y_min, z_min, x_max, y_max, z_max)`` or an array
            *[batch_shape, 6]*; each item's extent if None.
        features: point features *[batch_shape, num_points, num_feats]* (averaged per voxel).
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``(voxel_grid [batch_shape, nx, ny, nz, 3 + num_feats + 1], dims [batch_shape, 3],
        resolutions [batch_shape, 3], lower_corners [batch_shape, 3])``; empty voxels are 0.

    Example:
        >>> grid, dims, res, lower = coords_to_voxel_grid(np.array([[0., 0, 0], [4., 2, 1]]), (2, 1, 1))
        >>> grid[..., -1].ravel(), res
        (array([1., 1.]), array([2., 2., 1.]))
    """
    xp = ivy.get_framework(coords, features, f=f)
    if mode not in MODES:
        raise InputError(f"mode must be 'DIMS' or 'RES'; got {mode!r}.")
    C.check_last_dim(xp, coords, (3, 4), "coords")
    shape = C.shape_of(xp, coords)
    if len(shape) < 2:
        raise InputError(f"coords must be [..., num_points, 3]; got shape {shape}.")
    batch, n = shape[:-2], shape[-2]
    points = coords[..., 0:3]
    if features is not None:
        fshape = C.shape_of(xp, features)
        if fshape[:-1] != shape[:-1]:
            raise InputError(
                f"features {fshape} must be [..., num_points, num_feats] with the leading "
                f"shape {shape[:-1]} of coords."
            )
    # points with a NaN or infinite coordinate are left out (and bound no extent)
    finite = xp.all(xp.isfinite(points), axis=-1)
    if coord_bounds is None:
        known = finite[..., None]
        inf = xp.full_like(points, float("inf"))
        lower = xp.min(xp.where(known, points, inf), axis=-2, keepdims=True)
        upper = xp.max(xp.where(known, points, -inf), axis=-2, keepdims=True)
        valid = finite
    else:
        bounds = _per_batch(xp, coord_bounds, 6, batch, points, "coord_bounds")
        lower, upper = bounds[..., 0:3], bounds[..., 3:6]
        inside = xp.logical_and(points >= lower, points <= upper)
        valid = xp.all(inside, axis=-1)
    extent = upper - lower
    spec = _per_batch(xp, voxel_shape_spec, 3, batch, points, "voxel_shape_spec")
    if mode == "DIMS":
        try:
            grid_dims = tuple(int(v) for v in voxel_shape_spec)
        except TypeError:
            values = C.concrete(xp, spec)
            if values is None:
                raise InputError(
                    "in 'DIMS' mode under compilation, give voxel_shape_spec as Python ints."
                ) from None
            grid_dims = tuple(int(v) for v in values.reshape(-1, 3).max(axis=0))
        dims = xp.astype(spec, xp.dtype(points))
    else:
        dims = xp.maximum(xp.ceil(xp.safe_divide(extent, spec)), xp.ones_like(spec))
        values = C.concrete(xp, dims)
        if values is None:
            raise InputError(
                "'RES' mode sizes the grid from the data, so it cannot be "
                "compiled; use 'DIMS' mode with Python ints."
            )
        grid_dims = tuple(int(v) for v in values.reshape(-1, 3).max(axis=0))
    if min(grid_dims) < 1:
        raise InputError(f"the grid needs at least one voxel per axis; got {grid_dims}.")
    res = xp.safe_divide(extent, dims)
    # histogramdd's bins: floor of the scaled offset; the upper bound goes into the last voxel
    scaled = xp.safe_divide(points - lower, res)
    index = xp.minimum(xp.floor(scaled), dims - 1)
    index = xp.where(index < 0, xp.zeros_like(index), index)
    # no index is computed from a left-out point's (possibly NaN) offset
    index = xp.where(valid[..., None], index, xp.zeros_like(index))
    index = xp.astype(index, C.index_dtype(xp))
    gx, gy, gz = grid_dims
    flat = (index[..., 0] * gy + index[..., 1]) * gz + index[..., 2]
    size = gx * gy * gz
    flat = xp.where(valid, flat, xp.full_like(flat, size))
    values = [points] if features is None else [points, xp.astype(features, xp.dtype(points))]
    values = xp.concat([*values, xp.ones_like(points[..., 0:1])], axis=-1)
    values = xp.where(valid[..., None], values, xp.zeros_like(values))  # no inf - inf in sums
    flat_all, b = S.global_indices(xp, flat, size)
    width = C.shape_of(xp, values)[-1]
    sums = S.scatter_rows(xp, flat_all, xp.reshape(values, (b * n, width)), b * size + 1)
    counts = sums[:, -1:]
    grid = xp.concat([xp.safe_divide(sums[:, :-1], counts), counts], axis=-1)
    grid = xp.reshape(grid[: b * size], (*batch, gx, gy, gz, width))
    return grid, dims[..., 0, :], res[..., 0, :], lower[..., 0, :]
