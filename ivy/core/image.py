"""Images, written once as compositions.

Images are channel-last, ``[..., H, W, C]``, with any number of leading batch axes. Pixel ``(i,
j)`` (row ``i``, column ``j``) is at coordinates ``x = j``, ``y = i``: pixel centres lie on
integer coordinates, ``x`` runs along the width and ``y`` down the height.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from ivy import framework_handler as _fh
from ivy.core._dispatch import composition
from ivy.typing import Array, Framework

__all__ = ["bilinear_resample", "gradient_image", "stack_images"]


def _floating(xp, x, like=None):
    """``x``, or ``x`` cast to float32 (or to ``like``'s dtype) when it is not floating."""
    name = xp.dtype(x, as_str=True)
    if "float" in name or "complex" in name:
        return x
    return xp.astype(x, "float32" if like is None else xp.dtype(like, as_str=True))


@composition
def bilinear_resample(x: Array, warp: Array, /, *, f: Framework = None) -> Array:
    """Sample images at continuous pixel coordinates by bilinear interpolation.

    Coordinates outside the image are clamped to its border (the edge pixels extend outwards).
    The result is differentiable in ``x`` and, between pixel centres, in ``warp``.

    Args:
        x: images ``[..., H, W, C]``.
        warp: floating coordinates ``[..., N, 2]`` as ``(x, y)`` pairs (column, then row), with
            the same batch axes as ``x``.

    Returns:
        ``[..., N, C]``, in ``warp``'s dtype for integer images.

    Example: ``ivy.bilinear_resample(img, np.array([[0.5, 0.]]))`` is the mean of pixels
    ``(0, 0)`` and ``(0, 1)``.
    """
    xp = _fh.get_framework(x, warp, f=f)
    x_shape, w_shape = tuple(xp.shape(x)), tuple(xp.shape(warp))
    if len(x_shape) < 3 or w_shape[-1:] != (2,) or w_shape[:-2] != x_shape[:-3]:
        raise ValueError(
            f"bilinear_resample: x must be [..., H, W, C] and warp [..., N, 2] with the same "
            f"batch axes; got x {x_shape} and warp {w_shape}."
        )
    *batch, h, w, c = x_shape
    n = w_shape[-2]
    b = math.prod(batch)
    x = _floating(xp, x, like=warp)
    pixels = xp.reshape(x, (b, h * w, c))
    coords = xp.reshape(warp, (b, n, 2))
    px = xp.clip(coords[..., 0], 0.0, float(w - 1))
    py = xp.clip(coords[..., 1], 0.0, float(h - 1))
    x0, y0 = xp.floor(px), xp.floor(py)
    wx, wy = (px - x0)[..., None], (py - y0)[..., None]
    x1, y1 = xp.clip(x0 + 1, 0.0, float(w - 1)), xp.clip(y0 + 1, 0.0, float(h - 1))
    batch_index = xp.broadcast_to(xp.reshape(xp.arange(b), (b, 1)), (b, n))
    index_dtype = xp.dtype(batch_index)

    def at(yy, xx):
        flat = xp.astype(yy, index_dtype) * w + xp.astype(xx, index_dtype)
        return xp.gather_nd(pixels, xp.stack([batch_index, flat], axis=-1))  # [b, n, c]

    top = at(y0, x0) * (1 - wx) + at(y0, x1) * wx
    bottom = at(y1, x0) * (1 - wx) + at(y1, x1) * wx
    return xp.reshape(top * (1 - wy) + bottom * wy, (*batch, n, c))


@composition
def gradient_image(x: Array, /, *, f: Framework = None) -> tuple[Array, Array]:
    """Forward differences of images along the height and the width.

    ``dy[..., i, j, :] = x[..., i + 1, j, :] - x[..., i, j, :]`` and ``dx[..., i, j, :] =
    x[..., i, j + 1, :] - x[..., i, j, :]``; the last row of ``dy`` and the last column of ``dx``
    are 0 (as ``tf.image.image_gradients``).

    Args:
        x: images ``[..., H, W, C]``; integer images are computed in float32 (their differences
            are signed).

    Returns:
        ``(dy, dx)``, each ``[..., H, W, C]``.
    """
    xp = _fh.get_framework(x, f=f)
    if len(xp.shape(x)) < 3:
        raise ValueError(f"gradient_image: x must be [..., H, W, C]; got {xp.shape(x)}.")
    x = _floating(xp, x)
    dy = x[..., 1:, :, :] - x[..., :-1, :, :]
    dx = x[..., :, 1:, :] - x[..., :, :-1, :]
    dy = xp.concat([dy, xp.zeros_like(x[..., :1, :, :])], axis=-3)
    dx = xp.concat([dx, xp.zeros_like(x[..., :, :1, :])], axis=-2)
    return dy, dx


def _image_grid(
    count: int, height: int, width: int, aspect_ratio: tuple[float, float] = (1, 1)
) -> tuple[int, int]:
    """``(rows, columns)`` of the grid :func:`stack_images` uses for ``count`` images (a helper
    of stack_images, not public API).

    The grid has no empty row, and its aspect ratio (``rows * height`` to ``columns * width``) is
    the closest to ``aspect_ratio`` (height to width) on a log scale; ties go to fewer blank
    cells, then to fewer rows.
    """
    target = math.log(aspect_ratio[0] / aspect_ratio[1])
    best = None
    for rows in range(1, count + 1):
        cols = math.ceil(count / rows)
        if (rows - 1) * cols >= count:
            continue  # the last row would be empty
        error = round(abs(math.log(rows * height / (cols * width)) - target), 9)
        key = (error, rows * cols - count, rows)
        if best is None or key < best[0]:
            best = (key, (rows, cols))
    return best[1]


@composition
def stack_images(
    images: Sequence[Array],
    /,
    *,
    desired_aspect_ratio: tuple[float, float] = (1, 1),
    f: Framework = None,
) -> Array:
    """Tile images of one shape into a single image, in a grid whose aspect ratio is as close as
    possible to ``desired_aspect_ratio``.

    The images fill the grid row by row; the cells left over in the last row are black (0). The
    grid has no empty row, and its aspect ratio (``rows * H`` to ``columns * W``) is the closest
    to ``desired_aspect_ratio`` on a log scale; ties go to fewer blank cells, then fewer rows.

    Args:
        images: a list of images ``[..., H, W, C]`` of the same shape.
        desired_aspect_ratio: ``(height, width)`` proportions of the result.

    Returns:
        ``[..., rows * H, columns * W, C]``.

    Example: four ``[H, W, C]`` images with ``desired_aspect_ratio=(1, 1)`` and ``H == W`` give
    a ``2 x 2`` grid, ``[2H, 2W, C]``.
    """
    images = list(images)
    if not images:
        raise ValueError("stack_images: needs at least one image.")
    xp = _fh.get_framework(images, f=f)
    shape = tuple(xp.shape(images[0]))
    if len(shape) < 3 or any(tuple(xp.shape(im)) != shape for im in images):
        raise ValueError(
            f"stack_images: the images must all be [..., H, W, C] of one shape; got "
            f"{[tuple(xp.shape(im)) for im in images]}."
        )
    rows, cols = _image_grid(len(images), shape[-3], shape[-2], desired_aspect_ratio)
    cells = images + [xp.zeros_like(images[0])] * (rows * cols - len(images))
    lines = [xp.concat(cells[r * cols : (r + 1) * cols], axis=-2) for r in range(rows)]
    return xp.concat(lines, axis=-3)
