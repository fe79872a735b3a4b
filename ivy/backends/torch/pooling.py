"""torch backend: the one pool, channel-last, with torch's own kernels.

Padding torch cannot express natively (asymmetric, or wider than half the window) is added with
``F.pad`` first: ``-inf`` for max pools; for average pools zeros, and the sums are divided by the
number of real (unpadded) entries in each window, as tf does for 'SAME'.
"""

from __future__ import annotations

import math

import torch
import torch.nn.functional as F

from ivy._args import nn as A
from ivy.backends.torch.convolutions import channels_first, channels_last, tensors, torch_pads
from ivy.errors import UnsupportedError

_MAX = {1: F.max_pool1d, 2: F.max_pool2d, 3: F.max_pool3d}
# Integer dtypes whose every value float64 holds exactly (int64 and uint64 do not).
_EXACT_IN_FLOAT64 = frozenset(
    {torch.int8, torch.int16, torch.int32, torch.uint8, torch.uint16, torch.uint32, torch.bool}
)
_AVG = {1: F.avg_pool1d, 2: F.avg_pool2d, 3: F.avg_pool3d}


def pool_general(x, kernel, strides, padding, /, *, reduction="max"):
    (x,) = tensors(x)
    average = A.averages(reduction)
    if not (average or x.is_floating_point() or x.is_complex()):
        # (the core computes averages of integers in float32, ``ivy/core/pooling.py``)
        if x.dtype in _EXACT_IN_FLOAT64:  # torch has no integer max pools: exact in float64
            out = pool_general(x.to(torch.float64), kernel, strides, padding, reduction=reduction)
            return out.to(x.dtype)
        else:
            raise UnsupportedError(
                f"torch has no max pool of {str(x.dtype)[6:]}: ivy computes integers of up to 32 "
                "bits through float64, which holds them exactly, but not 64-bit ones. Cast to "
                "float64 first (exact up to 2**53), or use another backend."
            )
    nd = len(kernel)
    xc = channels_first(x, nd)
    if all(lo == hi and 2 * lo <= k for (lo, hi), k in zip(padding, kernel)):
        p = [lo for lo, _ in padding]
        if average:
            y = _AVG[nd](xc, kernel, strides, p, count_include_pad=False)
        else:
            y = _MAX[nd](xc, kernel, strides, p)
    elif average:
        sizes = tuple(x.shape[1:-1])
        counts = A.window_counts(sizes, kernel, strides, padding) / math.prod(kernel)
        mean = _AVG[nd](F.pad(xc, torch_pads(padding)), kernel, strides)  # padding counted
        y = mean / torch.as_tensor(counts, dtype=x.dtype, device=x.device)
    else:
        y = _MAX[nd](F.pad(xc, torch_pads(padding), value=-float("inf")), kernel, strides)
    return channels_last(y, nd)
