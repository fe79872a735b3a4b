"""torch backend: max and average pools, channel-last, with torch's own kernels.

Padding torch cannot express natively (asymmetric, or wider than half the window) is added with
``F.pad`` first: ``-inf`` for max pools; for average pools zeros, and the sums are divided by the
number of real (unpadded) entries in each window, as tf does for 'SAME'.
"""

from __future__ import annotations

import math

import torch
import torch.nn.functional as F

from ivy.backends import _nn_args as A
from ivy.backends.torch.convolutions import channels_first, channels_last, tensors, torch_pads

_MAX = {1: F.max_pool1d, 2: F.max_pool2d, 3: F.max_pool3d}
_AVG = {1: F.avg_pool1d, 2: F.avg_pool2d, 3: F.avg_pool3d}


def _pool(x, kernel, strides, padding, nd, fn, average):
    (x,) = tensors(x)
    A.check_pool_input(x.shape, nd, fn)
    k = A.as_tuple(kernel, nd, "kernel", fn)
    s = A.as_tuple(strides, nd, "strides", fn)
    sizes = tuple(x.shape[x.dim() - nd - 1 : -1])
    pads = A.pool_pads(padding, sizes, k, s, fn)
    xc, lead = channels_first(x, nd)
    native = all(lo == hi and 2 * lo <= w for (lo, hi), w in zip(pads, k))
    if native:
        p = [lo for lo, _ in pads]
        if average:
            y = _AVG[nd](xc, k, s, p, count_include_pad=False)
        else:
            y = _MAX[nd](xc, k, s, p)
    elif average:
        counts = A.window_counts(sizes, k, s, pads) / math.prod(k)
        mean = _AVG[nd](F.pad(xc, torch_pads(pads)), k, s)  # padding counted
        y = mean / torch.as_tensor(counts, dtype=x.dtype, device=x.device)
    else:
        y = _MAX[nd](F.pad(xc, torch_pads(pads), value=-float("inf")), k, s)
    return channels_last(y, nd, lead)


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
