"""Convolutions, channel-last as in the paper.

Layout (every backend, every function):

- input ``x``: ``[N, W, C]`` (1-D), ``[N, H, W, C]`` (2-D), ``[N, D, H, W, C]`` (3-D); more
  leading batch axes are allowed and kept;
- filters of ``conv*d``: ``[fw, in, out]``, ``[fh, fw, in, out]``, ``[fd, fh, fw, in, out]``
  (tf's ``HWIO``);
- filters of ``conv*d_transpose``: ``[..., out, in]``, as tf does: the transposed convolution is
  the gradient (with respect to its input) of the ``conv*d`` that uses the same filters, read as
  ``[..., in', out']`` with ``in' = out`` and ``out' = in``;
- filters of ``depthwise_conv2d``: ``[fh, fw, C]`` (one 2-D filter per channel, multiplier 1).

``strides`` and ``dilations`` are an int or one int per spatial axis. ``padding`` is ``'SAME'``
(tf's rule: output size ``ceil(size / stride)``, the odd pad at the end), ``'VALID'`` (no
padding), an int (that many zeros on every side) or one ``(low, high)`` pair (or int) per spatial
axis.

Backends: torch ``torch.nn.functional.conv*`` (permuted to channel-first and back), jax
``lax.conv_general_dilated``, tensorflow ``tf.nn.convolution`` / ``conv_transpose`` /
``depthwise_conv2d``, numpy explicit sliding windows (one matrix product per kernel tap).
"""

from __future__ import annotations

from collections.abc import Sequence

from ivy.core._dispatch import dispatch
from ivy.typing import Array, Framework, Shape

__all__ = [
    "conv1d",
    "conv2d",
    "conv3d",
    "conv1d_transpose",
    "conv2d_transpose",
    "conv3d_transpose",
    "depthwise_conv2d",
]


@dispatch("x", "filters")
def conv1d(
    x: Array,
    filters: Array,
    strides: int | Sequence[int],
    padding: str | int | Sequence[int | tuple[int, int]],
    /,
    *,
    dilations: int | Sequence[int] = 1,
    f: Framework = None,
) -> Array:
    """1-D convolution (cross-correlation, as in every framework), channel-last.

    Args:
        x: input ``[N, W, in]``.
        filters: ``[fw, in, out]``.
        strides: int or ``(sw,)``.
        padding: ``'SAME'``, ``'VALID'``, an int or ``[(low, high)]``.
        dilations: int or ``(dw,)``: spacing between the filter's taps.

    Returns:
        ``[N, W_out, out]``; with 'SAME', ``W_out = ceil(W / sw)``.

    Example:
        >>> ivy.conv1d(np.ones((1, 5, 1)), np.ones((3, 1, 1)), 1, "SAME")[0, :, 0]
        array([2., 3., 3., 3., 2.])
    """


@dispatch("x", "filters")
def conv2d(
    x: Array,
    filters: Array,
    strides: int | Sequence[int],
    padding: str | int | Sequence[int | tuple[int, int]],
    /,
    *,
    dilations: int | Sequence[int] = 1,
    f: Framework = None,
) -> Array:
    """2-D convolution (cross-correlation), channel-last.

    Args:
        x: input ``[N, H, W, in]``.
        filters: ``[fh, fw, in, out]``.
        strides: int or ``(sh, sw)``.
        padding: ``'SAME'``, ``'VALID'``, an int or ``[(top, bottom), (left, right)]``.
        dilations: int or ``(dh, dw)``.

    Returns:
        ``[N, H_out, W_out, out]``.

    Example:
        >>> ivy.conv2d(np.ones((1, 4, 4, 3)), np.ones((3, 3, 3, 8)), 2, "SAME").shape
        (1, 2, 2, 8)
    """


@dispatch("x", "filters")
def conv3d(
    x: Array,
    filters: Array,
    strides: int | Sequence[int],
    padding: str | int | Sequence[int | tuple[int, int]],
    /,
    *,
    dilations: int | Sequence[int] = 1,
    f: Framework = None,
) -> Array:
    """3-D convolution (cross-correlation), channel-last.

    Args:
        x: input ``[N, D, H, W, in]``.
        filters: ``[fd, fh, fw, in, out]``.
        strides: int or ``(sd, sh, sw)``.
        padding: ``'SAME'``, ``'VALID'``, an int or three ``(low, high)`` pairs.
        dilations: int or ``(dd, dh, dw)``.

    Returns:
        ``[N, D_out, H_out, W_out, out]``.

    Example:
        >>> ivy.conv3d(np.ones((1, 4, 4, 4, 1)), np.ones((2, 2, 2, 1, 5)), 1, "VALID").shape
        (1, 3, 3, 3, 5)
    """


@dispatch("x", "filters")
def conv1d_transpose(
    x: Array,
    filters: Array,
    strides: int | Sequence[int],
    padding: str | int | Sequence[int | tuple[int, int]],
    /,
    *,
    output_shape: Shape | None = None,
    dilations: int | Sequence[int] = 1,
    f: Framework = None,
) -> Array:
    """1-D transposed convolution (the gradient of :func:`conv1d` with respect to its input).

    Args:
        x: input ``[N, W, in]``.
        filters: ``[fw, out, in]`` (tf's layout: output channels before input channels).
        strides: int or ``(sw,)``: the upsampling factor.
        padding: ``'SAME'``, ``'VALID'``, an int or ``[(low, high)]``: the padding of the forward
            convolution, cropped from the full result.
        output_shape: the output's spatial size ``(W_out,)`` or full shape ``[N, W_out, out]``.
            Default: ``W * sw`` for 'SAME', ``(W - 1) * sw + dw * (fw - 1) + 1 - low - high``
            otherwise. A larger size (by less than ``sw``) extends the result with zeros; a
            size that a forward convolution would not map back to ``W`` raises ValueError.
        dilations: int or ``(dw,)``.

    Returns:
        ``[N, W_out, out]``.

    Example:
        >>> ivy.conv1d_transpose(np.ones((1, 3, 1)), np.ones((2, 1, 1)), 2, "VALID")[0, :, 0]
        array([1., 1., 1., 1., 1., 1.])
    """


@dispatch("x", "filters")
def conv2d_transpose(
    x: Array,
    filters: Array,
    strides: int | Sequence[int],
    padding: str | int | Sequence[int | tuple[int, int]],
    /,
    *,
    output_shape: Shape | None = None,
    dilations: int | Sequence[int] = 1,
    f: Framework = None,
) -> Array:
    """2-D transposed convolution (the gradient of :func:`conv2d` with respect to its input).

    Args:
        x: input ``[N, H, W, in]``.
        filters: ``[fh, fw, out, in]`` (tf's layout).
        strides: int or ``(sh, sw)``.
        padding: ``'SAME'``, ``'VALID'``, an int or two ``(low, high)`` pairs.
        output_shape: ``(H_out, W_out)`` or ``[N, H_out, W_out, out]``; default as in
            :func:`conv1d_transpose`, per axis.
        dilations: int or ``(dh, dw)``.

    Returns:
        ``[N, H_out, W_out, out]``.

    Example:
        >>> ivy.conv2d_transpose(np.ones((1, 4, 4, 8)), np.ones((3, 3, 2, 8)), 2, "SAME").shape
        (1, 8, 8, 2)
    """


@dispatch("x", "filters")
def conv3d_transpose(
    x: Array,
    filters: Array,
    strides: int | Sequence[int],
    padding: str | int | Sequence[int | tuple[int, int]],
    /,
    *,
    output_shape: Shape | None = None,
    dilations: int | Sequence[int] = 1,
    f: Framework = None,
) -> Array:
    """3-D transposed convolution (the gradient of :func:`conv3d` with respect to its input).

    Args:
        x: input ``[N, D, H, W, in]``.
        filters: ``[fd, fh, fw, out, in]`` (tf's layout).
        strides: int or ``(sd, sh, sw)``.
        padding: ``'SAME'``, ``'VALID'``, an int or three ``(low, high)`` pairs.
        output_shape: ``(D_out, H_out, W_out)`` or the full output shape; default as in
            :func:`conv1d_transpose`, per axis.
        dilations: int or ``(dd, dh, dw)``.

    Returns:
        ``[N, D_out, H_out, W_out, out]``.

    Example:
        >>> x = np.ones((1, 2, 2, 2, 4))
        >>> ivy.conv3d_transpose(x, np.ones((2, 2, 2, 3, 4)), 2, "VALID").shape
        (1, 4, 4, 4, 3)
    """


@dispatch("x", "filters")
def depthwise_conv2d(
    x: Array,
    filters: Array,
    strides: int | Sequence[int],
    padding: str | int | Sequence[int | tuple[int, int]],
    /,
    *,
    dilations: int | Sequence[int] = 1,
    f: Framework = None,
) -> Array:
    """Depthwise 2-D convolution: each channel convolved with its own 2-D filter.

    Args:
        x: input ``[N, H, W, C]``.
        filters: ``[fh, fw, C]`` (channel multiplier 1).
        strides: int or ``(sh, sw)``.
        padding: ``'SAME'``, ``'VALID'``, an int or two ``(low, high)`` pairs.
        dilations: int or ``(dh, dw)``.

    Returns:
        ``[N, H_out, W_out, C]``.

    Example:
        >>> ivy.depthwise_conv2d(np.ones((1, 5, 5, 3)), np.ones((3, 3, 3)), 1, "VALID").shape
        (1, 3, 3, 3)
    """
