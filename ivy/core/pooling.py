"""Max and average pooling, channel-last as in the paper.

``x`` is ``[N, W, C]``, ``[N, H, W, C]`` or ``[N, D, H, W, C]`` (more leading batch axes are
allowed); ``kernel`` and ``strides`` are an int or one int per spatial axis; ``padding`` is
``'SAME'``, ``'VALID'``, an int or one ``(low, high)`` pair per spatial axis (each pad smaller
than the window).

Padding never counts: max pools pad with ``-inf``, and average pools divide each window's sum by
the number of real (unpadded) entries in it. That is tf's rule for 'SAME' (torch's
``count_include_pad=False``), applied to explicit padding too.

Every pool is written once, as a composition: it checks the arguments, resolves the padding to
explicit ``(low, high)`` pairs and folds extra leading batch axes into one, then calls the
backends' one primitive, :func:`pool_general`. Backends: torch ``F.max_pool*``/``F.avg_pool*``
(channel-first permutation), jax ``lax.reduce_window``, tensorflow ``tf.nn.max_pool``/``avg_pool``
(float64 3-D pools, which tf's CPU lacks, run as a 2-D then a 1-D pool), numpy explicit sliding
windows.
"""

from __future__ import annotations

from collections.abc import Sequence

from ivy import framework_handler as _fh
from ivy._args import nn as A
from ivy.core._dispatch import composition, dispatch
from ivy.core.convolutions import _as_array, _fold_batch, _unfold_batch
from ivy.typing import Array, Framework

__all__ = [
    "pool_general",
    "max_pool1d",
    "max_pool2d",
    "max_pool3d",
    "avg_pool1d",
    "avg_pool2d",
    "avg_pool3d",
]


@composition
def max_pool1d(
    x: Array,
    kernel: int | Sequence[int],
    strides: int | Sequence[int],
    padding: str | int | Sequence[int | tuple[int, int]],
    /,
    *,
    f: Framework = None,
) -> Array:
    """Maximum over sliding windows of ``x`` ``[N, W, C]``.

    Args:
        x: input ``[N, W, C]``.
        kernel: window size, int or ``(kw,)``.
        strides: int or ``(sw,)``.
        padding: ``'SAME'``, ``'VALID'``, an int or ``[(low, high)]``.

    Returns:
        ``[N, W_out, C]``.

    Example:
        >>> ivy.max_pool1d(np.arange(5.).reshape(1, 5, 1), 2, 2, "SAME")[0, :, 0]
        array([1., 3., 4.])
    """
    return _pool(_fh.get_framework(x, f=f), x, kernel, strides, padding, 1, "max_pool1d", "max")


@composition
def max_pool2d(
    x: Array,
    kernel: int | Sequence[int],
    strides: int | Sequence[int],
    padding: str | int | Sequence[int | tuple[int, int]],
    /,
    *,
    f: Framework = None,
) -> Array:
    """Maximum over sliding windows of ``x`` ``[N, H, W, C]``.

    Args:
        x: input ``[N, H, W, C]``.
        kernel: window size, int or ``(kh, kw)``.
        strides: int or ``(sh, sw)``.
        padding: ``'SAME'``, ``'VALID'``, an int or two ``(low, high)`` pairs.

    Returns:
        ``[N, H_out, W_out, C]``.

    Example:
        >>> ivy.max_pool2d(np.ones((1, 4, 4, 3)), 2, 2, "VALID").shape
        (1, 2, 2, 3)
    """
    return _pool(_fh.get_framework(x, f=f), x, kernel, strides, padding, 2, "max_pool2d", "max")


@composition
def max_pool3d(
    x: Array,
    kernel: int | Sequence[int],
    strides: int | Sequence[int],
    padding: str | int | Sequence[int | tuple[int, int]],
    /,
    *,
    f: Framework = None,
) -> Array:
    """Maximum over sliding windows of ``x`` ``[N, D, H, W, C]``.

    Args:
        x: input ``[N, D, H, W, C]``.
        kernel: window size, int or ``(kd, kh, kw)``.
        strides: int or ``(sd, sh, sw)``.
        padding: ``'SAME'``, ``'VALID'``, an int or three ``(low, high)`` pairs.

    Returns:
        ``[N, D_out, H_out, W_out, C]``.

    Example:
        >>> ivy.max_pool3d(np.ones((1, 4, 4, 4, 3)), 2, 2, "VALID").shape
        (1, 2, 2, 2, 3)
    """
    return _pool(_fh.get_framework(x, f=f), x, kernel, strides, padding, 3, "max_pool3d", "max")


@composition
def avg_pool1d(
    x: Array,
    kernel: int | Sequence[int],
    strides: int | Sequence[int],
    padding: str | int | Sequence[int | tuple[int, int]],
    /,
    *,
    f: Framework = None,
) -> Array:
    """Mean over sliding windows of ``x`` ``[N, W, C]``; padding is not counted.

    Args:
        x: input ``[N, W, C]``.
        kernel: window size, int or ``(kw,)``.
        strides: int or ``(sw,)``.
        padding: ``'SAME'``, ``'VALID'``, an int or ``[(low, high)]``.

    Returns:
        ``[N, W_out, C]``.

    Example:
        >>> ivy.avg_pool1d(np.arange(5.).reshape(1, 5, 1), 2, 2, "SAME")[0, :, 0]
        array([0.5, 2.5, 4. ])
    """
    return _pool(_fh.get_framework(x, f=f), x, kernel, strides, padding, 1, "avg_pool1d", "mean")


@composition
def avg_pool2d(
    x: Array,
    kernel: int | Sequence[int],
    strides: int | Sequence[int],
    padding: str | int | Sequence[int | tuple[int, int]],
    /,
    *,
    f: Framework = None,
) -> Array:
    """Mean over sliding windows of ``x`` ``[N, H, W, C]``; padding is not counted.

    Args:
        x: input ``[N, H, W, C]``.
        kernel: window size, int or ``(kh, kw)``.
        strides: int or ``(sh, sw)``.
        padding: ``'SAME'``, ``'VALID'``, an int or two ``(low, high)`` pairs.

    Returns:
        ``[N, H_out, W_out, C]``.

    Example:
        >>> ivy.avg_pool2d(np.ones((1, 5, 5, 3)), 2, 2, "SAME").shape
        (1, 3, 3, 3)
    """
    return _pool(_fh.get_framework(x, f=f), x, kernel, strides, padding, 2, "avg_pool2d", "mean")


@composition
def avg_pool3d(
    x: Array,
    kernel: int | Sequence[int],
    strides: int | Sequence[int],
    padding: str | int | Sequence[int | tuple[int, int]],
    /,
    *,
    f: Framework = None,
) -> Array:
    """Mean over sliding windows of ``x`` ``[N, D, H, W, C]``; padding is not counted.

    Args:
        x: input ``[N, D, H, W, C]``.
        kernel: window size, int or ``(kd, kh, kw)``.
        strides: int or ``(sd, sh, sw)``.
        padding: ``'SAME'``, ``'VALID'``, an int or three ``(low, high)`` pairs.

    Returns:
        ``[N, D_out, H_out, W_out, C]``.

    Example:
        >>> ivy.avg_pool3d(np.ones((1, 4, 4, 4, 3)), 2, 2, "VALID").shape
        (1, 2, 2, 2, 3)
    """
    return _pool(_fh.get_framework(x, f=f), x, kernel, strides, padding, 3, "avg_pool3d", "mean")


@dispatch
def pool_general(
    x: Array,
    kernel: tuple[int, ...],
    strides: tuple[int, ...],
    padding: str | tuple[tuple[int, int], ...],
    /,
    *,
    reduction: str = "max",
    f: Framework = None,
) -> Array:
    """The backends' one pool, under every function of this group (prefer those: they check
    their arguments and resolve the padding; this takes them resolved, unchecked).

    Args:
        x: ``[N, *spatial, C]``, one batch axis, ``nd = len(kernel)`` spatial axes.
        kernel: ``nd`` ints, the window.
        strides: ``nd`` ints.
        padding: ``nd`` ``(low, high)`` pairs, each smaller than the window; padding never
            counts (a max ignores it, a mean divides by the real entries of its window).
            ``'SAME'`` or ``'VALID'`` only where the spatial sizes are unknown before run time
            (tensorflow graphs).
        reduction: ``'max'`` or ``'mean'``.

    Returns:
        ``[N, *spatial_out, C]``.

    Example:
        >>> ivy.pool_general(np.arange(5.).reshape(1, 5, 1), (2,), (2,), ((0, 1),))[0, :, 0]
        array([1., 3., 4.])
    """


def _pool(xp, x, kernel, strides, padding, nd, fn, reduction):
    x = _as_array(xp, x)
    shape = tuple(x.shape)
    A.check_pool_input(shape, nd, fn)
    k = A.as_tuple(kernel, nd, "kernel", fn)
    s = A.as_tuple(strides, nd, "strides", fn)
    pads = A.pool_pads(padding, shape[len(shape) - nd - 1 : -1], k, s, fn)
    if A.averages(reduction) and not xp.isdtype(x.dtype, ("real floating", "complex floating")):
        x = xp.astype(x, xp.float32)  # an average of integers is float32, on every backend
    x, lead = _fold_batch(xp, x, nd)
    return _unfold_batch(xp, xp.pool_general(x, k, s, pads, reduction=reduction), lead)
