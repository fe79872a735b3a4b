"""Scattering points into pixels (private): the depth buffer and per-pixel means shared by
forward warping and ``quantize_to_image``.

Every point gets a flat pixel index in ``[0, H*W)``, or the extra "discard" slot ``H*W`` when it
falls outside the image (or is invalid), so the shapes never depend on the data and the code
compiles under ``jax.jit`` and ``tf.function``.
"""

from __future__ import annotations

import math

from ivy_vision import _common as C


def pixel_indices(xp, x, y, valid, image_dims):
    """Flat indices ``[*B, N]`` (the default integer dtype) of the nearest pixels of the points ``(x, y)``, each
    ``[*B, N]`` (``floor(x + 0.5)``), ``H*W`` where invalid or outside; and the validity."""
    h, w = image_dims
    col = xp.floor(x + 0.5)
    row = xp.floor(y + 0.5)
    inside = xp.logical_and(
        xp.logical_and(col >= 0, col <= w - 1), xp.logical_and(row >= 0, row <= h - 1)
    )
    if valid is not None:
        inside = xp.logical_and(inside, valid)
    zero = xp.zeros_like(col)
    col = xp.astype(xp.where(inside, col, zero), C.index_dtype(xp))
    row = xp.astype(xp.where(inside, row, zero), C.index_dtype(xp))
    flat = xp.where(inside, row * w + col, xp.full_like(row, h * w))
    return flat, inside


def global_indices(xp, flat, size):
    """Indices into the concatenated buffers of every batch item: ``[*B, N]`` -> ``[prod(B)*N]``
    with the discard slots of all items mapped to the last slot, ``prod(B) * size``."""
    shape = C.shape_of(xp, flat)
    batch = math.prod(shape[:-1])
    offsets = xp.reshape(
        xp.arange(batch, dtype=xp.dtype(flat), device=xp.dev(flat)) * size, (*shape[:-1], 1)
    )
    discard = flat == size
    out = xp.where(discard, xp.full_like(flat, batch * size), flat + offsets)
    return xp.reshape(out, (-1,)), batch


def scatter_rows(xp, indices, values, total, reduction="sum"):
    """Scatter rows ``values`` ``[M, C]`` at ``indices`` ``[M]`` into ``[total, C]``."""
    return xp.scatter_nd(
        indices[:, None], values, (total, C.shape_of(xp, values)[-1]), reduction=reduction
    )


def min_depth_winners(xp, indices, depth, total):
    """Which points have the least depth of their pixel: ``[M]`` booleans (ties all win)."""
    buffer = xp.scatter_flat(indices, depth, total, reduction="min")
    return depth == xp.take(buffer, indices, axis=0)


def unflatten(xp, buffer, batch_shape, image_dims, batch):
    """``[batch * H * W + 1, C]`` -> ``[*B, H, W, C]`` (the discard slot dropped)."""
    h, w = image_dims
    c = C.shape_of(xp, buffer)[-1]
    return xp.reshape(buffer[: batch * h * w], (*batch_shape, h, w, c))
