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

Every function here is written once, as a composition: it checks the arguments, resolves the
padding to explicit ``(low, high)`` pairs and folds extra leading batch axes into one, then calls
the backends' one primitive, :func:`conv_general`. Backends: torch ``torch.nn.functional.conv*``
(permuted to channel-first and back), jax ``lax.conv_general_dilated``, tensorflow
``tf.nn.conv*d`` / ``conv*d_transpose`` / ``depthwise_conv2d``, numpy explicit sliding windows
(one matrix product per kernel tap).
"""

from __future__ import annotations

from collections.abc import Sequence

from ivy import framework_handler as _fh
from ivy._args import nn as A
from ivy.core._dispatch import composition, dispatch
from ivy.typing import Array, Framework, Shape

__all__ = [
    "conv_general",
    "conv1d",
    "conv2d",
    "conv3d",
    "conv1d_transpose",
    "conv2d_transpose",
    "conv3d_transpose",
    "depthwise_conv2d",
]


@composition
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
    return _conv(
        _fh.get_framework(x, filters, f=f), x, filters, strides, padding, dilations, 1, "conv1d"
    )


@composition
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
    return _conv(
        _fh.get_framework(x, filters, f=f), x, filters, strides, padding, dilations, 2, "conv2d"
    )


@composition
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
    return _conv(
        _fh.get_framework(x, filters, f=f), x, filters, strides, padding, dilations, 3, "conv3d"
    )


@composition
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
    return _conv_transpose(
        _fh.get_framework(x, filters, f=f),
        x,
        filters,
        strides,
        padding,
        output_shape,
        dilations,
        1,
        "conv1d_transpose",
    )


@composition
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
    return _conv_transpose(
        _fh.get_framework(x, filters, f=f),
        x,
        filters,
        strides,
        padding,
        output_shape,
        dilations,
        2,
        "conv2d_transpose",
    )


@composition
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
    return _conv_transpose(
        _fh.get_framework(x, filters, f=f),
        x,
        filters,
        strides,
        padding,
        output_shape,
        dilations,
        3,
        "conv3d_transpose",
    )


@composition
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
    return _conv(
        _fh.get_framework(x, filters, f=f),
        x,
        filters,
        strides,
        padding,
        dilations,
        2,
        "depthwise_conv2d",
        depthwise=True,
    )


@dispatch("x", "filters")
def conv_general(
    x: Array,
    filters: Array,
    strides: tuple[int, ...],
    padding: str | tuple[tuple[int, int], ...],
    dilations: tuple[int, ...],
    /,
    *,
    groups: int = 1,
    transpose: bool = False,
    f: Framework = None,
) -> Array:
    """The backends' one convolution, under every function of this group (prefer those: they
    check their arguments and resolve the padding; this takes them resolved, unchecked).

    Args:
        x: ``[N, *spatial, C_in]``, one batch axis, ``nd = len(strides)`` spatial axes.
        filters: ``[*kernel, C_in / groups, C_out]``; with ``transpose``, ``[*kernel, C_out,
            C_in]`` (tf's layout; ``groups`` 1).
        strides: ``nd`` ints.
        padding: ``nd`` ``(low, high)`` pairs: zeros added to the input; with ``transpose``,
            entries cropped from the full result, whose size is ``(n - 1) * s + d * (k - 1) + 1``
            per axis (``low + high`` at most that). ``'SAME'`` or ``'VALID'`` only where the
            spatial sizes are unknown before run time (tensorflow graphs).
        dilations: ``nd`` ints.
        groups: feature groups: input and output channels split into this many groups, each
            convolved with its own filters (``C_in`` groups with ``C_out = C_in``: depthwise).
        transpose: the transposed convolution (the gradient of the forward one with respect
            to its input).

    Returns:
        ``[N, *spatial_out, C_out]``.

    Example:
        >>> ivy.conv_general(np.ones((1, 5, 1)), np.ones((3, 1, 1)), (1,), ((1, 1),), (1,))[0, :, 0]
        array([2., 3., 3., 3., 2.])
    """


def _as_array(xp, a):
    return a if hasattr(a, "shape") else xp.asarray(a)


def _known(sizes) -> tuple[int, ...]:
    """Sizes for a reshape: an unknown size (None, in a tensorflow graph) becomes -1."""
    return tuple(-1 if n is None else n for n in sizes)


def _fold_batch(xp, x, nd: int):
    """``x`` ``[*lead, *spatial, C]`` as ``[N, *spatial, C]``, and ``lead`` (None when ``x``
    already has one batch axis); :func:`_unfold_batch` undoes it on a result."""
    shape = tuple(x.shape)
    lead = shape[: len(shape) - nd - 1]
    if len(lead) == 1:
        return x, None
    return xp.reshape(xp.asarray(x), (-1, *_known(shape[len(lead) :]))), lead


def _unfold_batch(xp, y, lead):
    if lead is None:
        return y
    return xp.reshape(y, (*_known(lead), *_known(tuple(y.shape)[1:])))


def _conv(xp, x, filters, strides, padding, dilations, nd, fn, *, depthwise=False):
    x, filters = _as_array(xp, x), _as_array(xp, filters)
    x_shape, f_shape = tuple(x.shape), tuple(filters.shape)
    if depthwise:
        A.check_depthwise(x_shape, f_shape, fn)
    else:
        A.check_conv(x_shape, f_shape, nd, fn)
    s = A.as_tuple(strides, nd, "strides", fn)
    d = A.as_tuple(dilations, nd, "dilations", fn)
    windows = A.effective_windows(f_shape[:nd], d)
    sizes = x_shape[len(x_shape) - nd - 1 : -1]
    pads = A.resolve_pads(A.parse_padding(padding, nd, fn), sizes, windows, s, fn)
    x, lead = _fold_batch(xp, x, nd)
    if depthwise:  # [fh, fw, C] -> [fh, fw, 1, C]: one group per channel
        y = xp.conv_general(x, xp.expand_dims(filters, axis=-2), s, pads, d, groups=f_shape[-1])
    else:
        y = xp.conv_general(x, filters, s, pads, d)
    return _unfold_batch(xp, y, lead)


def _conv_transpose(xp, x, filters, strides, padding, output_shape, dilations, nd, fn):
    x, filters = _as_array(xp, x), _as_array(xp, filters)
    x_shape, f_shape = tuple(x.shape), tuple(filters.shape)
    A.check_conv(x_shape, f_shape, nd, fn, transpose=True)
    s = A.as_tuple(strides, nd, "strides", fn)
    d = A.as_tuple(dilations, nd, "dilations", fn)
    sizes = x_shape[len(x_shape) - nd - 1 : -1]
    out_sizes, lows, full_sizes = A.transpose_geometry(
        sizes, A.effective_windows(f_shape[:nd], d), s, padding, output_shape, fn, f_shape[-2]
    )
    crops, extend = A.transpose_crops(lows, out_sizes, full_sizes)
    x, lead = _fold_batch(xp, x, nd)
    y = xp.conv_general(x, filters, s, crops, d, transpose=True)
    if any(extend):
        y = xp.constant_pad(y, ((0, 0), *((0, e) for e in extend), (0, 0)))
    return _unfold_batch(xp, y, lead)
