"""jax backend: convolutions, channel-last, with ``jax.lax.conv_general_dilated``.

Channel-last is native to lax (dimension numbers ``NHWC``/``HWIO``). A transposed convolution is
the same primitive with the input dilated by the strides and the kernel flipped.
"""

from __future__ import annotations

import jax.numpy as jnp
from jax import lax

from ivy.backends import _nn_args as A

_SPATIAL = {1: "W", 2: "HW", 3: "DHW"}


def _dimension_numbers(nd, kernel_tail):
    spatial = _SPATIAL[nd]
    return ("N" + spatial + "C", spatial + kernel_tail, "N" + spatial + "C")


def flatten_batch(x, nd):
    lead = x.shape[: x.ndim - nd - 1]
    return x.reshape((-1,) + x.shape[x.ndim - nd - 1 :]), lead


def _same_dtype(x, filters):
    dtype = jnp.result_type(x, filters)
    return x.astype(dtype), filters.astype(dtype)


def _conv(x, filters, strides, padding, dilations, nd, fn):
    x, filters = jnp.asarray(x), jnp.asarray(filters)
    A.check_conv(x.shape, filters.shape, nd, fn)
    kernel = filters.shape[:nd]
    s = A.as_tuple(strides, nd, "strides", fn)
    d = A.as_tuple(dilations, nd, "dilations", fn)
    x, lead = flatten_batch(x, nd)
    windows = A.effective_windows(kernel, d)
    pads = A.explicit_pads(A.parse_padding(padding, nd, fn), x.shape[1:-1], windows, s)
    A.output_sizes(x.shape[1:-1], windows, s, pads, fn)
    x, filters = _same_dtype(x, filters)
    y = lax.conv_general_dilated(
        x, filters, s, pads, rhs_dilation=d, dimension_numbers=_dimension_numbers(nd, "IO")
    )
    return y.reshape(lead + y.shape[1:])


def _conv_transpose(x, filters, strides, padding, output_shape, dilations, nd, fn):
    x, filters = jnp.asarray(x), jnp.asarray(filters)
    A.check_conv(x.shape, filters.shape, nd, fn, transpose=True)
    kernel = filters.shape[:nd]
    s = A.as_tuple(strides, nd, "strides", fn)
    d = A.as_tuple(dilations, nd, "dilations", fn)
    x, lead = flatten_batch(x, nd)
    sizes = x.shape[1:-1]
    windows = A.effective_windows(kernel, d)
    out_sizes, lows, _ = A.transpose_geometry(
        sizes, windows, s, padding, output_shape, fn, filters.shape[-2]
    )
    pads = [
        (w - 1 - lo, n - (size - 1) * st - 1 + lo)
        for w, lo, n, size, st in zip(windows, lows, out_sizes, sizes, s)
    ]
    x, filters = _same_dtype(x, filters)
    y = lax.conv_general_dilated(
        x,
        jnp.flip(filters, axis=tuple(range(nd))),
        (1,) * nd,
        pads,
        lhs_dilation=s,
        rhs_dilation=d,
        dimension_numbers=_dimension_numbers(nd, "OI"),
    )
    return y.reshape(lead + y.shape[1:])


def conv1d(x, filters, strides, padding, /, *, dilations=1):
    return _conv(x, filters, strides, padding, dilations, 1, "conv1d")


def conv2d(x, filters, strides, padding, /, *, dilations=1):
    return _conv(x, filters, strides, padding, dilations, 2, "conv2d")


def conv3d(x, filters, strides, padding, /, *, dilations=1):
    return _conv(x, filters, strides, padding, dilations, 3, "conv3d")


def conv1d_transpose(x, filters, strides, padding, /, *, output_shape=None, dilations=1):
    return _conv_transpose(
        x, filters, strides, padding, output_shape, dilations, 1, "conv1d_transpose"
    )


def conv2d_transpose(x, filters, strides, padding, /, *, output_shape=None, dilations=1):
    return _conv_transpose(
        x, filters, strides, padding, output_shape, dilations, 2, "conv2d_transpose"
    )


def conv3d_transpose(x, filters, strides, padding, /, *, output_shape=None, dilations=1):
    return _conv_transpose(
        x, filters, strides, padding, output_shape, dilations, 3, "conv3d_transpose"
    )


def depthwise_conv2d(x, filters, strides, padding, /, *, dilations=1):
    fn = "depthwise_conv2d"
    x, filters = jnp.asarray(x), jnp.asarray(filters)
    A.check_depthwise(x.shape, filters.shape, fn)
    kernel = filters.shape[:2]
    s = A.as_tuple(strides, 2, "strides", fn)
    d = A.as_tuple(dilations, 2, "dilations", fn)
    x, lead = flatten_batch(x, 2)
    windows = A.effective_windows(kernel, d)
    pads = A.explicit_pads(A.parse_padding(padding, 2, fn), x.shape[1:-1], windows, s)
    A.output_sizes(x.shape[1:-1], windows, s, pads, fn)
    x, filters = _same_dtype(x, filters)
    channels = filters.shape[-1]
    y = lax.conv_general_dilated(
        x,
        filters.reshape(*kernel, 1, channels),
        s,
        pads,
        rhs_dilation=d,
        dimension_numbers=_dimension_numbers(2, "IO"),
        feature_group_count=channels,
    )
    return y.reshape(lead + y.shape[1:])
