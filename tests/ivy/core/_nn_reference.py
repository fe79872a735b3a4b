"""Independent references for the convolutions and pools (channel-last), in numpy float64, and
what their tests share: inputs, dtypes, the geometry strategies.

The references loop over output positions and kernel taps, and compute 'SAME' padding from tf's
documented rule (the tf backend passes 'SAME' to tf itself, so the rule is checked too).
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import settings
from hypothesis import strategies as st

from tests.helpers import HYPOTHESIS

FLOATS = ("float32", "float64")

# Fewer examples than the shared profile: jax compiles every new shape.
GEOMETRY = settings(HYPOTHESIS, max_examples=15)

PADDINGS = st.one_of(
    st.sampled_from(["SAME", "VALID"]),
    st.tuples(st.integers(0, 2), st.integers(0, 2)).map(lambda p: [p]),
)


def random_array(shape, dtype, seed):
    return np.random.default_rng(100 + seed).standard_normal(shape).astype(dtype)


def as_tuple(v, nd):
    return (v,) * nd if isinstance(v, int) else tuple(v)


def ref_pads(padding, sizes, windows, strides):
    """(low, high) per axis; 'SAME' by tf's rule: out = ceil(n / s), the odd pad at the end."""
    nd = len(sizes)
    if padding == "VALID":
        return [(0, 0)] * nd
    if padding == "SAME":
        pads = []
        for n, w, s in zip(sizes, windows, strides):
            total = max((math.ceil(n / s) - 1) * s + w - n, 0)
            pads.append((total // 2, total - total // 2))
        return pads
    if isinstance(padding, int):
        return [(padding, padding)] * nd
    return [(p, p) if isinstance(p, int) else tuple(p) for p in padding]


def ref_conv(x, w, strides, padding, dilations, depthwise=False, groups=1):
    """Cross-correlation of x [N, *S, C] with w [*K, C / groups, O] (or [*K, C] depthwise), in
    float64; with ``groups``, output channel o sees input group o // (O / groups)."""
    x, w = x.astype(np.float64), w.astype(np.float64)
    nd = x.ndim - 2
    kernel = w.shape[:nd]
    s, d = as_tuple(strides, nd), as_tuple(dilations, nd)
    windows = [di * (k - 1) + 1 for k, di in zip(kernel, d)]
    pads = ref_pads(padding, x.shape[1:-1], windows, s)
    xp = np.pad(x, [(0, 0), *pads, (0, 0)])
    out_sizes = [(xp.shape[1 + i] - windows[i]) // s[i] + 1 for i in range(nd)]
    channels = x.shape[-1] if depthwise else w.shape[-1]
    out = np.zeros((x.shape[0], *out_sizes, channels))
    per_in, per_out = x.shape[-1] // groups, channels // groups
    for o in np.ndindex(*out_sizes):
        for tap in np.ndindex(*kernel):
            at = tuple(oi * si + ti * di for oi, si, ti, di in zip(o, s, tap, d))
            patch = xp[(slice(None), *at)]
            if depthwise:
                out[(slice(None), *o)] += patch * w[tap]
                continue
            for g in range(groups):
                inputs = patch[:, g * per_in : (g + 1) * per_in]
                outputs = slice(g * per_out, (g + 1) * per_out)
                out[(slice(None), *o, outputs)] += inputs @ w[tap][:, outputs]
    return out


def ref_conv_transpose(x, w, strides, padding, dilations, out_sizes):
    """Scatter definition: out[i * s + j * d - low] += x[i] @ w[j].T, with w [*K, O, C]."""
    x, w = x.astype(np.float64), w.astype(np.float64)
    nd = x.ndim - 2
    kernel = w.shape[:nd]
    s, d = as_tuple(strides, nd), as_tuple(dilations, nd)
    windows = [di * (k - 1) + 1 for k, di in zip(kernel, d)]
    lows = [lo for lo, _ in ref_pads(padding, out_sizes, windows, s)]
    out = np.zeros((x.shape[0], *out_sizes, w.shape[-2]))
    for i in np.ndindex(*x.shape[1:-1]):
        for tap in np.ndindex(*kernel):
            at = tuple(ii * si + ti * di - lo for ii, si, ti, di, lo in zip(i, s, tap, d, lows))
            if all(0 <= a < n for a, n in zip(at, out_sizes)):
                out[(slice(None), *at)] += x[(slice(None), *i)] @ w[tap].T
    return out


def ref_pool(x, kernel, strides, padding, average):
    """Max or mean over each window's real entries (padding never counts), float64."""
    x = x.astype(np.float64)
    nd = x.ndim - 2
    k, s = as_tuple(kernel, nd), as_tuple(strides, nd)
    pads = ref_pads(padding, x.shape[1:-1], k, s)
    sizes = x.shape[1:-1]
    out_sizes = [(n + lo + hi - ki) // si + 1 for n, (lo, hi), ki, si in zip(sizes, pads, k, s)]
    out = np.zeros((x.shape[0], *out_sizes, x.shape[-1]))
    for o in np.ndindex(*out_sizes):
        box = []
        for oi, si, ki, (lo, _), n in zip(o, s, k, pads, sizes):
            start = oi * si - lo
            box.append(slice(max(start, 0), min(start + ki, n)))
        window = x[(slice(None), *box)].reshape(x.shape[0], -1, x.shape[-1])
        out[(slice(None), *o)] = window.mean(1) if average else window.max(1)
    return out
