"""The framework-agnostic functions added for the Array API have its signatures: the same
parameter names, positional-only (``/``) and keyword-only (``*``) markers and defaults, plus ivy's
keyword-only ``f=None``. Type hints are not compared (``test_type_hints.py`` checks those)."""

from __future__ import annotations

import inspect

import pytest

import ivy

SIGNATURES = {
    "meshgrid": "(*arrays, indexing='xy')",
    "tril": "(x, /, *, k=0)",
    "triu": "(x, /, *, k=0)",
    "from_dlpack": "(x, /, *, device=None, copy=None)",
    "astype": "(x, dtype, /, *, copy=True, device=None)",
    "can_cast": "(from_, to, /)",
    "finfo": "(type, /)",
    "iinfo": "(type, /)",
    "isdtype": "(dtype, kind)",
    "result_type": "(*arrays_and_dtypes)",
    **{
        name: "(x1, x2, /)"
        for name in [
            "bitwise_and",
            "bitwise_left_shift",
            "bitwise_or",
            "bitwise_right_shift",
            "bitwise_xor",
            "copysign",
            "hypot",
            "logaddexp",
            "nextafter",
        ]
    },
    **{
        name: "(x, /)"
        for name in ["bitwise_invert", "conj", "imag", "real", "reciprocal", "signbit"]
    },
    "broadcast_arrays": "(*arrays)",
    "moveaxis": "(x, source, destination, /)",
    "nonzero": "(x, /)",
    "searchsorted": "(x1, x2, /, *, side='left', sorter=None)",
    "count_nonzero": "(x, /, *, axis=None, keepdims=False)",
    "unique_all": "(x, /)",
    "unique_counts": "(x, /)",
    "unique_inverse": "(x, /)",
    "unique_values": "(x, /)",
    "argsort": "(x, /, *, axis=-1, descending=False, stable=True)",
    "sort": "(x, /, *, axis=-1, descending=False, stable=True)",
    "cumulative_sum": "(x, /, *, axis=None, dtype=None, include_initial=False)",
    "cumulative_prod": "(x, /, *, axis=None, dtype=None, include_initial=False)",
    "all": "(x, /, *, axis=None, keepdims=False)",
    "any": "(x, /, *, axis=None, keepdims=False)",
    "diff": "(x, /, *, axis=-1, n=1, prepend=None, append=None)",
    "take_along_axis": "(x, indices, /, *, axis=-1)",  # 2024.12
}


def _with_f(signature: str) -> str:
    """The standard's signature with ivy's ``f=None`` appended (keyword-only)."""
    inner = signature[1:-1]
    if "*" in inner.replace("**", ""):
        return f"({inner}, f=None)"
    return f"({inner}, *, f=None)" if inner else "(*, f=None)"


def _without_hints(sig: inspect.Signature) -> inspect.Signature:
    """``sig`` with its parameters' and return's annotations removed."""
    return sig.replace(
        parameters=[p.replace(annotation=p.empty) for p in sig.parameters.values()],
        return_annotation=sig.empty,
    )


@pytest.mark.parametrize("name", sorted(SIGNATURES))
def test_signature_follows_the_standard(name):
    sig = _without_hints(inspect.signature(getattr(ivy, name)))
    assert str(sig) == _with_f(SIGNATURES[name])
