"""The bounds of ``clip``, the same on every backend: the result keeps the dtype of ``x``
whatever the bounds' dtypes (Array API 2024.12), and every value of the result lies within the
bounds.

For an integer ``x``, a bound outside its dtype's range is clamped to that range (``clip(uint8,
-1, 100)`` leaves small values alone, where a cast of -1 to uint8 would make it 255), and a
floating bound rounds inward (a lower bound up, an upper bound down). Array bounds of another
dtype are converted the same way, by the backend namespace's own functions.
"""

from __future__ import annotations

import math
from typing import Any

from ivy.core import _dtype_rules as rules
from ivy.errors import DtypeError


def clip_bounds(ns: Any, x: Any, low: Any, high: Any) -> tuple[Any, Any]:
    """``(low, high)`` for ``clip(x, low, high)`` on the backend namespace ``ns``: None, Python
    numbers, or arrays of ``x``'s dtype."""
    dtype = ns.dtype(x, as_str=True)
    kind = rules.kind_of(dtype)
    if kind == 3:
        raise DtypeError(
            "clip needs real numbers (complex numbers have no order); clip the real and imaginary "
            "parts separately.",
            function="clip",
            argument="x",
            backend=ns.backend,
        )
    return _bound(ns, low, dtype, kind, lower=True), _bound(ns, high, dtype, kind, lower=False)


def _bound(ns: Any, value: Any, dtype: str, kind: int, *, lower: bool) -> Any:
    if value is None:
        return None
    if isinstance(value, (bool, int, float)):
        return _scalar_bound(value, dtype, kind, lower)
    if not hasattr(value, "dtype"):
        value = ns.asarray(value)
    own = ns.dtype(value, as_str=True)
    if own == dtype:
        return value
    if kind == 0:  # bool: the bound's truth
        return ns.astype(value, dtype)
    if kind == 2:  # a floating x: the bound in x's dtype
        return ns.astype(value, dtype)
    return _integer_array_bound(ns, value, own, dtype, lower)


def _scalar_bound(value: float | int | bool, dtype: str, kind: int, lower: bool) -> Any:
    if kind != 1:
        return value
    if isinstance(value, float):
        if math.isnan(value):
            return None  # no integer compares with NaN: the bound bounds nothing
        if math.isinf(value):
            return None if (value < 0) == lower else (_info(dtype, lower=not lower))
        value = math.ceil(value) if lower else math.floor(value)
    info = rules.iinfo(dtype)
    return min(max(int(value), info.min), info.max)


def _info(dtype: str, *, lower: bool) -> int:
    info = rules.iinfo(dtype)
    return info.min if lower else info.max


def _integer_array_bound(ns: Any, value: Any, own: str, dtype: str, lower: bool) -> Any:
    """An array bound of dtype ``own`` for an integer ``x`` of ``dtype``: clamped to the range
    of ``dtype`` (rounded inward first when floating), then cast."""
    info = rules.iinfo(dtype)
    if rules.kind_of(own) == 1:
        own_info = rules.iinfo(own)
        if own_info.min >= info.min and own_info.max <= info.max:
            return ns.astype(value, dtype)  # every value fits
        wide = "int64" if own != "uint64" and dtype != "uint64" else "float64"
        if wide == "int64":
            v = ns.astype(value, "int64")
            v = ns.minimum(ns.maximum(v, max(info.min, -(2**63))), min(info.max, 2**63 - 1))
            return ns.astype(v, dtype)
        value = ns.astype(value, "float64")
    v = ns.astype(value, "float64")
    v = ns.ceil(v) if lower else ns.floor(v)
    low, high = float(info.min), float(info.max)
    below, above = ns.less_equal(v, low), ns.greater_equal(v, high)
    nan = ns.isnan(v)
    safe = ns.where(ns.logical_or(ns.logical_or(below, above), nan), ns.zeros_like(v), v)
    cast = ns.astype(safe, dtype)
    # (NaN bounds bound nothing: the dtype's extreme on the side they bound)
    cast = ns.where(
        ns.logical_or(below, ns.logical_and(nan, ns.asarray(lower))),
        _fill(ns, info.min, dtype),
        cast,
    )
    return ns.where(
        ns.logical_or(above, ns.logical_and(nan, ns.asarray(not lower))),
        _fill(ns, info.max, dtype),
        cast,
    )


def _fill(ns: Any, value: int, dtype: str) -> Any:
    return ns.full((), value, dtype=dtype)
