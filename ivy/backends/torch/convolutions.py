"""torch backend: convolutions, channel-last.

torch's own kernels (``torch.nn.functional.conv*``) in its channel-first layout: the input is
permuted to ``[N, C, ...]`` and the result back (the permuted tensors are views, which torch runs
with its channels-last kernels). Padding that torch cannot express (asymmetric 'SAME') is added
with ``F.pad`` first; transposed convolutions are computed in full and then cropped.
"""

from __future__ import annotations

import torch
import torch.nn.functional as F

from ivy.backends import _nn_args as A

_CONV = {1: F.conv1d, 2: F.conv2d, 3: F.conv3d}
_CONV_TRANSPOSE = {1: F.conv_transpose1d, 2: F.conv_transpose2d, 3: F.conv_transpose3d}


def tensors(*values):
    """Tensors as they are; numpy arrays and lists converted (``f='torch'`` on numpy input)."""
    return tuple(v if isinstance(v, torch.Tensor) else torch.as_tensor(v) for v in values)


def channels_first(x, nd):
    """``[N, *spatial, C]`` as ``[N, C, *spatial]`` (more leading axes folded into N)."""
    lead = tuple(x.shape[: x.dim() - nd - 1])
    if x.dim() > nd + 2:
        x = x.reshape((-1,) + tuple(x.shape[x.dim() - nd - 1 :]))
    return x.permute(0, nd + 1, *range(1, nd + 1)), lead


def channels_last(y, nd, lead):
    y = y.permute(0, *range(2, nd + 2), 1)
    return y.reshape(lead + tuple(y.shape[1:])) if len(lead) != 1 else y


def torch_pads(pads):
    """``(low, high)`` pairs per spatial axis as ``F.pad``'s flat list, last axis first."""
    return [p for lo_hi in reversed(pads) for p in lo_hi]


def _padded(x, pads):
    """``x`` (channel-first) padded with zeros, and the symmetric padding left for torch."""
    if all(lo == hi for lo, hi in pads):
        return x, [lo for lo, _ in pads]
    return F.pad(x, torch_pads(pads)), 0


def _conv(x, filters, strides, padding, dilations, nd, fn):
    x, filters = tensors(x, filters)
    A.check_conv(x.shape, filters.shape, nd, fn)
    kernel = tuple(filters.shape[:nd])
    s = A.as_tuple(strides, nd, "strides", fn)
    d = A.as_tuple(dilations, nd, "dilations", fn)
    sizes = tuple(x.shape[x.dim() - nd - 1 : -1])
    windows = A.effective_windows(kernel, d)
    pads = A.explicit_pads(A.parse_padding(padding, nd, fn), sizes, windows, s)
    A.output_sizes(sizes, windows, s, pads, fn)
    xc, lead = channels_first(x, nd)
    xc, torch_padding = _padded(xc, pads)
    weight = filters.permute(nd + 1, nd, *range(nd))  # [out, in, *kernel]
    y = _CONV[nd](xc, weight, None, s, torch_padding, d)
    return channels_last(y, nd, lead)


def _conv_transpose(x, filters, strides, padding, output_shape, dilations, nd, fn):
    x, filters = tensors(x, filters)
    A.check_conv(x.shape, filters.shape, nd, fn, transpose=True)
    kernel = tuple(filters.shape[:nd])
    s = A.as_tuple(strides, nd, "strides", fn)
    d = A.as_tuple(dilations, nd, "dilations", fn)
    sizes = tuple(x.shape[x.dim() - nd - 1 : -1])
    out_sizes, lows, full_sizes = A.transpose_geometry(
        sizes, A.effective_windows(kernel, d), s, padding, output_shape, fn, filters.shape[-2]
    )
    xc, lead = channels_first(x, nd)
    weight = filters.permute(nd + 1, nd, *range(nd))  # [in, out, *kernel]
    y = _CONV_TRANSPOSE[nd](xc, weight, None, s, 0, 0, 1, d)
    crop = [(-lo, n + lo - full) for lo, n, full in zip(lows, out_sizes, full_sizes)]
    if any(c != (0, 0) for c in crop):
        y = F.pad(y, torch_pads(crop))  # negative pads crop
    return channels_last(y, nd, lead)


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
    x, filters = tensors(x, filters)
    A.check_depthwise(x.shape, filters.shape, fn)
    kernel = tuple(filters.shape[:2])
    s = A.as_tuple(strides, 2, "strides", fn)
    d = A.as_tuple(dilations, 2, "dilations", fn)
    sizes = tuple(x.shape[-3:-1])
    windows = A.effective_windows(kernel, d)
    pads = A.explicit_pads(A.parse_padding(padding, 2, fn), sizes, windows, s)
    A.output_sizes(sizes, windows, s, pads, fn)
    xc, lead = channels_first(x, 2)
    xc, torch_padding = _padded(xc, pads)
    weight = filters.permute(2, 0, 1).unsqueeze(1)  # [C, 1, fh, fw]
    y = F.conv2d(xc, weight, None, s, torch_padding, d, filters.shape[-1])
    return channels_last(y, 2, lead)
