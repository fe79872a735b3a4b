"""Max and average pooling, channel-last as in the paper.

``x`` is ``[N, W, C]``, ``[N, H, W, C]`` or ``[N, D, H, W, C]`` (more leading batch axes are
allowed); ``kernel`` and ``strides`` are an int or one int per spatial axis; ``padding`` is
``'SAME'``, ``'VALID'``, an int or one ``(low, high)`` pair per spatial axis (each pad smaller
than the window).

Padding never counts: max pools pad with ``-inf``, and average pools divide each window's sum by
the number of real (unpadded) entries in it. That is tf's rule for 'SAME' (torch's
``count_include_pad=False``), applied to explicit padding too.

Backends: torch ``F.max_pool*``/``F.avg_pool*`` (channel-first permutation), jax
``lax.reduce_window``, tensorflow ``tf.nn.max_pool``/``avg_pool`` (float64 3-D pools, which tf's
CPU lacks, run as a 2-D then a 1-D pool), numpy explicit sliding windows.
"""

from __future__ import annotations

from collections.abc import Sequence

from ivy.core._dispatch import dispatch
from ivy.typing import Array, Framework

__all__ = ["max_pool1d", "max_pool2d", "max_pool3d", "avg_pool1d", "avg_pool2d", "avg_pool3d"]


@dispatch
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


@dispatch
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


@dispatch
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


@dispatch
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


@dispatch
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


@dispatch
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
