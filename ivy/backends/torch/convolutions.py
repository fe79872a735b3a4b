"""torch backend: the one convolution, channel-last.

torch's own kernels (``torch.nn.functional.conv*``, ``conv_transpose*``) in its channel-first
layout: the input is permuted to ``[N, C, ...]`` and the result back (the permuted tensors are
views, which torch runs with its channels-last kernels). Padding that torch cannot express
(asymmetric) is added with ``F.pad`` first; transposed convolutions are computed in full and
then cropped.
"""

from __future__ import annotations

import torch
import torch.nn.functional as F

_CONV = {1: F.conv1d, 2: F.conv2d, 3: F.conv3d}
_CONV_TRANSPOSE = {1: F.conv_transpose1d, 2: F.conv_transpose2d, 3: F.conv_transpose3d}


def tensors(*values):
    """Tensors as they are; numpy arrays and lists converted (``f='torch'`` on numpy input)."""
    return tuple(v if isinstance(v, torch.Tensor) else torch.as_tensor(v) for v in values)


def channels_first(x, nd):
    """``[N, *spatial, C]`` as ``[N, C, *spatial]``."""
    return x.permute(0, nd + 1, *range(1, nd + 1))


def channels_last(y, nd):
    return y.permute(0, *range(2, nd + 2), 1)


def torch_pads(pads):
    """``(low, high)`` pairs per spatial axis as ``F.pad``'s flat list, last axis first."""
    return [p for lo_hi in reversed(pads) for p in lo_hi]


def conv_general(x, filters, strides, padding, dilations, /, *, groups=1, transpose=False):
    x, filters = tensors(x, filters)
    nd = len(strides)
    xc = channels_first(x, nd)
    # forward: [out, in / groups, *kernel]; transpose: [in, out, *kernel]
    weight = filters.permute(nd + 1, nd, *range(nd))
    if transpose:
        y = _CONV_TRANSPOSE[nd](xc, weight, None, strides, 0, 0, 1, dilations)
        crop = tuple(slice(lo, n - hi) for (lo, hi), n in zip(padding, y.shape[2:]))
        return channels_last(y[(slice(None), slice(None), *crop)], nd)
    if all(lo == hi for lo, hi in padding):
        y = _CONV[nd](xc, weight, None, strides, [lo for lo, _ in padding], dilations, groups)
    else:
        y = _CONV[nd](F.pad(xc, torch_pads(padding)), weight, None, strides, 0, dilations, groups)
    return channels_last(y, nd)
