"""numpy backend: the one convolution, channel-last, as explicit sliding windows.

It loops over the kernel's offsets (9 for a 3x3 kernel) and adds one matrix product of a strided
view of the padded input per offset: numpy has no convolution of its own. A transposed
convolution scatters the same products into its full result, which is then cropped.
"""

from __future__ import annotations

import numpy as np


def windows(offset, dilations, strides, out_sizes):
    """Index of the strided view of the padded input that kernel tap ``offset`` multiplies."""
    return (slice(None),) + tuple(
        slice(j * d, j * d + (o - 1) * s + 1, s)
        for j, d, s, o in zip(offset, dilations, strides, out_sizes)
    )


def _grouped(patch, w, groups):
    """``patch`` ``[..., C_in]`` times the filter tap ``w`` ``[C_in / groups, C_out]``."""
    if groups == 1:
        return patch @ w
    per_in, out = w.shape
    if per_in == 1 and out == groups:  # depthwise, multiplier 1
        return patch * w[0]
    w = w.reshape(per_in, groups, out // groups).transpose(1, 0, 2)
    patch = patch.reshape(*patch.shape[:-1], groups, per_in)
    return np.einsum("...gi,gio->...go", patch, w).reshape(*patch.shape[:-2], out)


def conv_general(x, filters, strides, padding, dilations, /, *, groups=1, transpose=False):
    x, filters = np.asarray(x), np.asarray(filters)
    nd = len(strides)
    kernel = filters.shape[:nd]
    dtype = np.result_type(x, filters)
    if transpose:
        sizes = x.shape[1:-1]
        full_sizes = tuple(
            (n - 1) * s + d * (k - 1) + 1 for n, s, d, k in zip(sizes, strides, dilations, kernel)
        )
        full = np.zeros((x.shape[0], *full_sizes, filters.shape[-2]), dtype)
        for offset in np.ndindex(*kernel):
            full[windows(offset, dilations, strides, sizes)] += x @ filters[offset].T
        crop = tuple(slice(lo, n - hi) for (lo, hi), n in zip(padding, full_sizes))
        return full[(slice(None), *crop)]
    padded = np.pad(x, ((0, 0), *padding, (0, 0)))
    out_sizes = tuple(
        (n - d * (k - 1) - 1) // s + 1
        for n, d, k, s in zip(padded.shape[1:-1], dilations, kernel, strides)
    )
    out = np.zeros((x.shape[0], *out_sizes, filters.shape[-1]), dtype)
    for offset in np.ndindex(*kernel):
        patch = padded[windows(offset, dilations, strides, out_sizes)]
        out += _grouped(patch, filters[offset], groups)
    return out
