"""numpy backend: convolutions, channel-last, as explicit sliding windows.

Each one loops over the kernel's offsets (9 for a 3x3 kernel) and adds one matrix product of a
strided view of the padded input per offset: numpy has no convolution of its own.
"""

from __future__ import annotations

import numpy as np

from ivy.backends import _nn_args as A


def _windows(offset, dilations, strides, out_sizes):
    """Index of the strided view of the padded input that kernel tap ``offset`` multiplies."""
    return (slice(None),) + tuple(
        slice(j * d, j * d + (o - 1) * s + 1, s)
        for j, d, s, o in zip(offset, dilations, strides, out_sizes)
    )


def _flatten_batch(x, nd):
    lead = x.shape[: x.ndim - nd - 1]
    return x.reshape((-1,) + x.shape[x.ndim - nd - 1 :]), lead


def _conv(x, filters, strides, padding, dilations, nd, fn):
    x, filters = np.asarray(x), np.asarray(filters)
    A.check_conv(x.shape, filters.shape, nd, fn)
    kernel = filters.shape[:nd]
    s = A.as_tuple(strides, nd, "strides", fn)
    d = A.as_tuple(dilations, nd, "dilations", fn)
    x, lead = _flatten_batch(x, nd)
    windows = A.effective_windows(kernel, d)
    pads = A.explicit_pads(A.parse_padding(padding, nd, fn), x.shape[1:-1], windows, s)
    out_sizes = A.output_sizes(x.shape[1:-1], windows, s, pads, fn)
    xp = np.pad(x, ((0, 0), *pads, (0, 0)))
    out = np.zeros((x.shape[0], *out_sizes, filters.shape[-1]), np.result_type(x, filters))
    for offset in np.ndindex(*kernel):
        out += xp[_windows(offset, d, s, out_sizes)] @ filters[offset]
    return out.reshape(lead + out.shape[1:])


def _conv_transpose(x, filters, strides, padding, output_shape, dilations, nd, fn):
    x, filters = np.asarray(x), np.asarray(filters)
    A.check_conv(x.shape, filters.shape, nd, fn, transpose=True)
    kernel = filters.shape[:nd]
    s = A.as_tuple(strides, nd, "strides", fn)
    d = A.as_tuple(dilations, nd, "dilations", fn)
    x, lead = _flatten_batch(x, nd)
    sizes = x.shape[1:-1]
    out_sizes, lows, full_sizes = A.transpose_geometry(
        sizes, A.effective_windows(kernel, d), s, padding, output_shape, fn, filters.shape[-2]
    )
    full = np.zeros((x.shape[0], *full_sizes, filters.shape[-2]), np.result_type(x, filters))
    for offset in np.ndindex(*kernel):
        full[_windows(offset, d, s, sizes)] += x @ filters[offset].T
    return _crop_or_pad(full, lows, out_sizes).reshape(lead + (*out_sizes, full.shape[-1]))


def _crop_or_pad(full, lows, out_sizes):
    """``full[:, lo : lo + n, ..., :]`` per spatial axis, extended with zeros past its end."""
    out = np.zeros((full.shape[0], *out_sizes, full.shape[-1]), full.dtype)
    src, dst = [slice(None)], [slice(None)]
    for lo, n, size in zip(lows, out_sizes, full.shape[1:-1]):
        m = max(min(n, size - lo), 0)
        src.append(slice(lo, lo + m))
        dst.append(slice(0, m))
    out[tuple(dst)] = full[tuple(src)]
    return out


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
    x, filters = np.asarray(x), np.asarray(filters)
    A.check_depthwise(x.shape, filters.shape, fn)
    kernel = filters.shape[:2]
    s = A.as_tuple(strides, 2, "strides", fn)
    d = A.as_tuple(dilations, 2, "dilations", fn)
    x, lead = _flatten_batch(x, 2)
    windows = A.effective_windows(kernel, d)
    pads = A.explicit_pads(A.parse_padding(padding, 2, fn), x.shape[1:-1], windows, s)
    out_sizes = A.output_sizes(x.shape[1:-1], windows, s, pads, fn)
    xp = np.pad(x, ((0, 0), *pads, (0, 0)))
    out = np.zeros((x.shape[0], *out_sizes, x.shape[-1]), np.result_type(x, filters))
    for offset in np.ndindex(*kernel):
        out += xp[_windows(offset, d, s, out_sizes)] * filters[offset]
    return out.reshape(lead + out.shape[1:])
