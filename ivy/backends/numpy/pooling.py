"""numpy backend: max and average pools, channel-last, as explicit sliding windows."""

from __future__ import annotations

import numpy as np

from ivy.backends import _nn_args as A
from ivy.backends.numpy.convolutions import _flatten_batch, _windows


def _pool(x, kernel, strides, padding, nd, fn, average):
    x = np.asarray(x)
    A.check_pool_input(x.shape, nd, fn)
    k = A.as_tuple(kernel, nd, "kernel", fn)
    s = A.as_tuple(strides, nd, "strides", fn)
    x, lead = _flatten_batch(x, nd)
    sizes = x.shape[1:-1]
    pads = A.pool_pads(padding, sizes, k, s, fn)
    out_sizes = A.output_sizes(sizes, k, s, pads, fn)
    ones = (1,) * nd
    if average:
        xp = np.pad(x, ((0, 0), *pads, (0, 0)))
        mask = np.pad(np.ones((1, *sizes, 1), x.dtype), ((0, 0), *pads, (0, 0)))
        total = np.zeros((x.shape[0], *out_sizes, x.shape[-1]), x.dtype)
        count = np.zeros((1, *out_sizes, 1), x.dtype)
        for offset in np.ndindex(*k):
            index = _windows(offset, ones, s, out_sizes)
            total += xp[index]
            count += mask[index]
        out = total / count
    else:
        low = -np.inf if np.issubdtype(x.dtype, np.floating) else np.iinfo(x.dtype).min
        xp = np.pad(x, ((0, 0), *pads, (0, 0)), constant_values=low)
        out = np.full((x.shape[0], *out_sizes, x.shape[-1]), low, x.dtype)
        for offset in np.ndindex(*k):
            np.maximum(out, xp[_windows(offset, ones, s, out_sizes)], out=out)
    return out.reshape(lead + out.shape[1:])


def max_pool1d(x, kernel, strides, padding, /):
    return _pool(x, kernel, strides, padding, 1, "max_pool1d", False)


def max_pool2d(x, kernel, strides, padding, /):
    return _pool(x, kernel, strides, padding, 2, "max_pool2d", False)


def max_pool3d(x, kernel, strides, padding, /):
    return _pool(x, kernel, strides, padding, 3, "max_pool3d", False)


def avg_pool1d(x, kernel, strides, padding, /):
    return _pool(x, kernel, strides, padding, 1, "avg_pool1d", True)


def avg_pool2d(x, kernel, strides, padding, /):
    return _pool(x, kernel, strides, padding, 2, "avg_pool2d", True)


def avg_pool3d(x, kernel, strides, padding, /):
    return _pool(x, kernel, strides, padding, 3, "avg_pool3d", True)
