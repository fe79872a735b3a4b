"""numpy backend: the one pool, channel-last, as explicit sliding windows."""

from __future__ import annotations

import numpy as np

from ivy._args import nn as A
from ivy.backends.numpy.convolutions import windows


def pool_general(x, kernel, strides, padding, /, *, reduction="max"):
    x = np.asarray(x)
    nd = len(kernel)
    sizes = x.shape[1:-1]
    out_sizes = tuple(
        (n + lo + hi - k) // s + 1 for n, (lo, hi), k, s in zip(sizes, padding, kernel, strides)
    )
    ones = (1,) * nd
    pads = ((0, 0), *padding, (0, 0))
    if A.averages(reduction):
        padded = np.pad(x, pads)
        mask = np.pad(np.ones((1, *sizes, 1), x.dtype), pads)
        total = np.zeros((x.shape[0], *out_sizes, x.shape[-1]), x.dtype)
        count = np.zeros((1, *out_sizes, 1), x.dtype)
        for offset in np.ndindex(*kernel):
            index = windows(offset, ones, strides, out_sizes)
            total += padded[index]
            count += mask[index]
        return total / count
    low = -np.inf if np.issubdtype(x.dtype, np.floating) else np.iinfo(x.dtype).min
    padded = np.pad(x, pads, constant_values=low)
    out = np.full((x.shape[0], *out_sizes, x.shape[-1]), low, x.dtype)
    for offset in np.ndindex(*kernel):
        np.maximum(out, padded[windows(offset, ones, strides, out_sizes)], out=out)
    return out
