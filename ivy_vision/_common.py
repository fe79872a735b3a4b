"""Private building blocks shared by the ivy_vision modules.

Every helper takes the backend namespace ``xp`` first: the public functions resolve the framework
once (``xp = ivy.get_framework(...)``) and pass it down, so no helper pays dispatch.

Batch and image dimensions. A matrix argument ``[*B, m, n]`` defines the batch dimensions ``B``;
a coordinate or pixel argument ``[*B, *I, n]`` has those batch dimensions in front (equal, or 1 on
either side to broadcast), then any number of "image" dimensions ``I`` (``(H, W)`` for an image,
``(N,)`` for a list of points, ``()`` for one point).
"""

from __future__ import annotations

import math

from ivy_vision._checks import InputError, check_shape

#: Channel counts of the representations, named for error messages.
CHANNELS = {
    1: "depth [..., H, W, 1]",
    2: "pixel coordinates [..., 2]",
    3: "depth-scaled pixel coordinates [u*d, v*d, d] or 3-D points [..., 3]",
}


def index_dtype(xp):
    """The backend's default integer dtype, for indices: int64, or int32 where 64-bit types
    are disabled (jax without ``jax_enable_x64``)."""
    return xp.dtype(xp.arange(1))


def shape_of(xp, x) -> tuple:
    return tuple(xp.shape(x))


def check_last_dim(xp, x, sizes, what: str) -> int:
    """Raise an InputError unless ``x``'s last axis has one of ``sizes`` entries; return it."""
    shape = shape_of(xp, x)
    sizes = (sizes,) if isinstance(sizes, int) else tuple(sizes)
    if len(shape) == 0 or shape[-1] not in sizes:
        want = " or ".join(str(s) for s in sizes)
        raise InputError(
            f"{what} must have {want} channels in its last axis; got shape {shape}. "
            f"Images are channel-last [..., H, W, C]."
        )
    return shape[-1]


def check_matrix(xp, m, rows, cols, what: str) -> tuple:
    """Raise an InputError unless ``m`` is ``[..., rows, cols]``; return its batch shape."""
    shape = shape_of(xp, m)
    rows = rows if isinstance(rows, int) else tuple(rows)
    check_shape(shape, ("...", rows, cols), what)
    return shape[:-2]


def check_image(xp, x, what: str, channels=None) -> tuple:
    """Raise an InputError unless ``x`` is an image ``[..., H, W, C]`` (with one of
    ``channels`` channels if given); return ``(H, W)``. A missing channel axis and a
    channel-first image are named as such, with the fix."""
    shape = shape_of(xp, x)
    want = "C" if channels is None else channels
    hint = "Images are channel-last [..., H, W, C]."
    single = channels == 1 or channels == (1,)
    if len(shape) == 2 and single:
        hint = f"Give the channel axis: {what}[..., None] has shape {(*shape, 1)}."
    elif channels is not None and len(shape) >= 3:
        sizes = (channels,) if isinstance(channels, int) else tuple(channels)
        if shape[-1] not in sizes and shape[-3] in sizes:
            hint = (
                f"It looks channel-first [..., C, H, W]; images are channel-last: move the "
                f"channel axis last (shape {(*shape[:-3], shape[-2], shape[-1], shape[-3])})."
            )
    check_shape(shape, ("...", "H", "W", want), what, hint)
    return shape[-3], shape[-2]


def reject_channel_first(xp, image, what: str, dims: tuple, dims_of: str) -> None:
    """Raise an InputError when ``image`` ``[..., H', W', C']`` looks like a channel-first
    image of the size ``dims = (H, W)`` of its companion ``dims_of``: ``(W', C') == (H, W)``
    while ``(H', W') != (H, W)``."""
    shape = shape_of(xp, image)
    if tuple(shape[-2:]) == tuple(dims) and tuple(shape[-3:-1]) != tuple(dims):
        raise InputError(
            f"{what} of shape {shape} looks channel-first [..., C, H, W] ({dims_of} is "
            f"{dims[0]} x {dims[1]}); images are channel-last [..., H, W, C]: move the channel "
            f"axis last (shape {(*shape[:-3], shape[-2], shape[-1], shape[-3])})."
        )


def broadcast_batch(batch_a: tuple, batch_b: tuple, what_a: str, what_b: str) -> tuple:
    """The broadcast of two batch shapes of equal length, or an InputError naming both."""
    if len(batch_a) != len(batch_b):
        raise InputError(
            f"{what_a} has batch shape {batch_a} but {what_b} has {batch_b}; give both "
            f"the same leading batch dimensions."
        )
    out = []
    for a, b in zip(batch_a, batch_b):
        if a != b and a != 1 and b != 1 and a is not None and b is not None:
            raise InputError(
                f"the batch dimensions of {what_a} {batch_a} and {what_b} {batch_b} do not "
                f"match (nor broadcast); give both the same leading batch dimensions."
            )
        out.append(b if a == 1 else a)
    return tuple(out)


def broadcast_right(batch_a: tuple, batch_b: tuple, what_a: str, what_b: str) -> tuple:
    """numpy's broadcast of two batch shapes (aligned on the right), or an InputError."""
    n = max(len(batch_a), len(batch_b))
    a = (1,) * (n - len(batch_a)) + tuple(batch_a)
    b = (1,) * (n - len(batch_b)) + tuple(batch_b)
    return broadcast_batch(a, b, what_a, what_b)


def split_batch(xp, x, batch: tuple, what: str, matrix_what: str) -> tuple:
    """Split ``x`` ``[*B', *I, n]`` into ``(B', I)`` for a matrix batch ``B`` (``len(B') ==
    len(B)``), raising an InputError when ``x`` has too few dimensions."""
    shape = shape_of(xp, x)
    nb = len(batch)
    if len(shape) < nb + 1:
        raise InputError(
            f"{what} of shape {shape} has fewer leading dimensions than the batch shape "
            f"{batch} of {matrix_what}; give it the batch dimensions [*batch, ..., C] in front."
        )
    return shape[:nb], shape[nb:-1]


def transform(xp, coords, mat, what: str = "coords", matrix_what: str = "the matrix"):
    """``mat @ coords`` for every vector: coords ``[*B, *I, n]``, mat ``[*B, m, n]`` ->
    ``[*B, *I, m]``; one matrix product per batch item."""
    batch = shape_of(xp, mat)[:-2]
    cb, image = split_batch(xp, coords, batch, what, matrix_what)
    out_batch = broadcast_batch(cb, batch, what, matrix_what)
    n = shape_of(xp, mat)[-1]
    if shape_of(xp, coords)[-1] != n:
        raise InputError(
            f"{what} has {shape_of(xp, coords)[-1]} components but {matrix_what} "
            f"{shape_of(xp, mat)} expects {n}."
        )
    if cb != out_batch:
        coords = xp.broadcast_to(coords, (*out_batch, *image, n))
    flat = xp.reshape(coords, (*out_batch, math.prod(image), n))
    out = xp.matmul(flat, xp.swapaxes(mat, -1, -2))
    return xp.reshape(out, (*out_batch, *image, shape_of(xp, mat)[-2]))


def affine(xp, coords, mat, what: str = "coords", matrix_what: str = "the matrix"):
    """``mat @ [coords, 1]`` for ``[m, n + 1]`` matrices and ``n``-vectors (or, when ``coords``
    already has ``n + 1`` components, ``mat @ coords``), without building homogeneous vectors."""
    n1 = shape_of(xp, mat)[-1]
    if shape_of(xp, coords)[-1] == n1:
        return transform(xp, coords, mat, what, matrix_what)
    linear = transform(xp, coords, mat[..., :, : n1 - 1], what, matrix_what)
    ni = len(shape_of(xp, linear)) - len(shape_of(xp, mat)) + 1
    rows = shape_of(xp, mat)[-2]  # (not -1: an empty batch leaves it undetermined)
    offset = xp.reshape(mat[..., :, n1 - 1], (*shape_of(xp, mat)[:-2], *(1,) * ni, rows))
    return linear + offset


def homogeneous(xp, coords):
    """Append a 1 to each vector (``[..., n]`` -> ``[..., n + 1]``)."""
    return xp.concat([coords, xp.ones_like(coords[..., 0:1])], axis=-1)


def euclidean(xp, coords, n: int = 3):
    """The first ``n`` components of homogeneous (or plain) coordinates."""
    return coords[..., 0:n]


def pixel_grid(xp, image_dims, dtype, device, homogeneous_coords=True):
    """``[H, W, 3]`` (or ``[H, W, 2]``) pixel coordinates ``[x, y, 1]``: x = column, y = row."""
    h, w = int(image_dims[0]), int(image_dims[1])
    xs = xp.arange(w, dtype=dtype, device=device)
    ys = xp.arange(h, dtype=dtype, device=device)
    gx = xp.broadcast_to(xs[None, :], (h, w))
    gy = xp.broadcast_to(ys[:, None], (h, w))
    parts = [gx, gy]
    if homogeneous_coords:
        parts.append(xp.ones_like(gx))
    return xp.stack(parts, axis=-1)


def image_dims_of(image_dims, what: str = "image_dims") -> tuple:
    """``(H, W)`` as Python ints, or an InputError (also for sizes that are not whole numbers,
    which ``int`` would round down to a plausible image size)."""
    try:
        h, w = (int(d) for d in image_dims)
        whole = all(float(d) == int(d) for d in image_dims)
    except (TypeError, ValueError):
        raise InputError(f"{what} must be (height, width); got {image_dims!r}.") from None
    if not whole:
        raise InputError(
            f"{what} must be whole numbers of pixels (height, width); got {image_dims!r}."
        )
    if h <= 0 or w <= 0:
        raise InputError(f"{what} must be positive (height, width); got {(h, w)}.")
    return h, w


def concrete(xp, x):
    """``x`` as a numpy array when its values are known (eager mode), else None (traced by
    ``jax.jit``, ``tf.function`` or ``torch.compile``): the checks of values run eagerly only."""
    try:
        import numpy as np

        return np.asarray(xp.to_numpy(x))
    except Exception:  # a tracer or symbolic tensor has no values to check
        return None


def normalize(xp, v):
    """Unit vectors along the last axis, with finite gradients at the zero vector."""
    return xp.safe_divide(v, xp.safe_norm(v, axis=-1, keepdims=True))
