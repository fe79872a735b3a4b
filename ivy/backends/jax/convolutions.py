"""jax backend: the one convolution, channel-last, with ``jax.lax.conv_general_dilated``.

Channel-last is native to lax (dimension numbers ``NHWC``/``HWIO``). A transposed convolution is
the same primitive with the input dilated by the strides and the kernel flipped; its crops are
negative padding.
"""

from __future__ import annotations

import jax.numpy as jnp
from jax import lax

from ivy._args import nn as A

_SPATIAL = {1: "W", 2: "HW", 3: "DHW"}


def _dimension_numbers(nd, kernel_tail):
    spatial = _SPATIAL[nd]
    return ("N" + spatial + "C", spatial + kernel_tail, "N" + spatial + "C")


def conv_general(x, filters, strides, padding, dilations, /, *, groups=1, transpose=False):
    x, filters = jnp.asarray(x), jnp.asarray(filters)
    dtype = jnp.result_type(x, filters)
    x, filters = x.astype(dtype), filters.astype(dtype)
    nd = len(strides)
    if transpose:
        windows = A.effective_windows(filters.shape[:nd], dilations)
        return lax.conv_general_dilated(
            x,
            jnp.flip(filters, axis=tuple(range(nd))),
            (1,) * nd,
            [(w - 1 - lo, w - 1 - hi) for w, (lo, hi) in zip(windows, padding)],
            lhs_dilation=strides,
            rhs_dilation=dilations,
            dimension_numbers=_dimension_numbers(nd, "OI"),
        )
    if groups > 1 and dtype == jnp.float64:
        return _grouped_one_by_one(x, filters, strides, padding, dilations, groups)
    return lax.conv_general_dilated(
        x,
        filters,
        strides,
        padding,
        rhs_dilation=dilations,
        dimension_numbers=_dimension_numbers(nd, "IO"),
        feature_group_count=groups,
    )


def _grouped_one_by_one(x, filters, strides, padding, dilations, groups):
    """A grouped float64 convolution as one convolution per group: XLA's grouped float64
    convolution on the CPU lets a NaN (or inf) of one group reach the outputs of every other
    (NaN times the zeros between groups), where numpy, torch and tensorflow keep the groups
    apart; in float32 it does not."""
    nd = len(strides)
    cin, cout = x.shape[-1] // groups, filters.shape[-1] // groups
    parts = [
        lax.conv_general_dilated(
            x[..., g * cin : (g + 1) * cin],
            filters[..., g * cout : (g + 1) * cout],
            strides,
            padding,
            rhs_dilation=dilations,
            dimension_numbers=_dimension_numbers(nd, "IO"),
        )
        for g in range(groups)
    ]
    return jnp.concatenate(parts, axis=-1)
