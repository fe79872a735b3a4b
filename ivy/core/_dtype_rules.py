"""Dtype rules by dtype name, independent of any framework: kinds, type promotion, casting and
numerical limits.

The framework-agnostic data type functions (``ivy.finfo('float32')``, ``ivy.result_type('int8',
'uint8')``, ...) use these rules when no framework is involved; backends whose framework has no
such function (or a different one) use them too, converting their dtypes to names and back.

Promotion follows the Array API table within a kind (bool, integers, real floating, complex
floating). Across kinds, which the standard leaves to implementations, ivy follows torch, jax and
tensorflow's ivy backend: a bool or integer dtype with a floating (or complex) dtype gives that
floating (or complex) dtype; int64 with uint64 gives float64 (as numpy and jax do).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from functools import reduce
from typing import Any

from ivy.dtypes import DEFAULT_COMPLEX, DEFAULT_FLOAT, DEFAULT_INT, DTYPE_NAMES

__all__ = [
    "KINDS",
    "FInfo",
    "IInfo",
    "name_of",
    "kind_of",
    "promote",
    "result_type",
    "can_cast",
    "isdtype",
    "finfo",
    "iinfo",
    "REFUSED_KINDS",
    "refused_kind",
]

_SIGNED = frozenset({"int8", "int16", "int32", "int64"})
_UNSIGNED = frozenset({"uint8", "uint16", "uint32", "uint64"})
_REAL = frozenset({"float16", "float32", "float64"})
_COMPLEX = frozenset({"complex64", "complex128"})

# The kinds of ``isdtype``, by the Array API's names.
KINDS: dict[str, frozenset[str]] = {
    "bool": frozenset({"bool"}),
    "signed integer": _SIGNED,
    "unsigned integer": _UNSIGNED,
    "integral": _SIGNED | _UNSIGNED,
    "real floating": _REAL,
    "complex floating": _COMPLEX,
    "numeric": _SIGNED | _UNSIGNED | _REAL | _COMPLEX,
}

_BITS = {
    name: int("".join(c for c in name if c.isdigit()) or 8) for name in DTYPE_NAMES
}  # complex: of both parts
_DEFAULT_OF_KIND = {0: "bool", 1: DEFAULT_INT, 2: DEFAULT_FLOAT, 3: DEFAULT_COMPLEX}
_COMPLEX_OF = {"float16": "complex64", "float32": "complex64", "float64": "complex128"}
_REAL_OF = {"complex64": "float32", "complex128": "float64"}


@dataclass(frozen=True)
class FInfo:
    """Machine limits of a floating dtype (the Array API's ``finfo_object``).

    Attributes:
        bits: number of bits.
        eps: difference between 1.0 and the next representable value.
        max: largest finite value.
        min: smallest (most negative) finite value.
        smallest_normal: smallest positive normal value.
        dtype: the real floating dtype these limits describe (float32 for complex64): a name in
            the framework-agnostic ``ivy.finfo``, the framework's own dtype in a backend.
    """

    bits: int
    eps: float
    max: float
    min: float
    smallest_normal: float
    dtype: Any


@dataclass(frozen=True)
class IInfo:
    """Machine limits of an integer dtype (the Array API's ``iinfo_object``).

    Attributes:
        bits: number of bits.
        max: largest value.
        min: smallest value.
        dtype: the dtype: a name in the framework-agnostic ``ivy.iinfo``, the framework's own
            dtype in a backend.
    """

    bits: int
    max: int
    min: int
    dtype: Any


def name_of(dtype) -> str:
    """The ivy name of ``dtype``: a name, or anything numpy reads as a dtype (``np.float32``,
    ``np.dtype('int8')``, jax's dtypes). Raises TypeError for anything else."""
    if isinstance(dtype, str):
        if dtype in DTYPE_NAMES:
            return dtype
    else:
        import numpy as np  # imported when needed: ``import ivy`` imports no array library

        try:
            name = np.dtype(dtype).name
        except TypeError:
            name = None
        if name in DTYPE_NAMES:
            return name
    raise TypeError(f"Unknown dtype {dtype!r}; use one of {', '.join(DTYPE_NAMES)}.")


def kind_of(name: str) -> int:
    """0 bool, 1 integer, 2 real floating, 3 complex floating."""
    if name == "bool":
        return 0
    if name in _REAL:
        return 2
    if name in _COMPLEX:
        return 3
    return 1


def promote(a: str, b: str) -> str:
    """The promoted dtype of two dtype names (see the module docstring for the rules)."""
    if a == b:
        return a
    ka, kb = kind_of(a), kind_of(b)
    if min(ka, kb) <= 1 < max(ka, kb):
        return a if ka > kb else b
    if min(ka, kb) == 0:  # bool with an integer
        return a if ka > kb else b
    if ka == 1:
        return _promote_integers(a, b)
    # floating: the wider precision, complex if either is complex
    bits = max(_BITS[a] // (2 if ka == 3 else 1), _BITS[b] // (2 if kb == 3 else 1))
    if max(ka, kb) == 3:
        return "complex128" if bits == 64 else "complex64"
    return f"float{bits}"


def _promote_integers(a: str, b: str) -> str:
    """The Array API's integer table; int64 with uint64, which it leaves open, gives float64."""
    sa, sb = a in _SIGNED, b in _SIGNED
    if sa == sb:
        return a if _BITS[a] >= _BITS[b] else b
    signed, unsigned = (a, b) if sa else (b, a)
    if _BITS[unsigned] < _BITS[signed]:
        return signed
    if _BITS[unsigned] == 64:
        return "float64"
    return f"int{2 * _BITS[unsigned]}"


def _scalar_kind(value) -> int:
    if isinstance(value, bool):
        return 0
    if isinstance(value, int):
        return 1
    return 2 if isinstance(value, float) else 3


def result_type(names, scalars=()) -> str:
    """The dtype of an operation on arrays of dtypes ``names`` and Python ``scalars``.

    Scalars take the dtype of the arrays when of the same or a lower kind (``int8`` and ``1``
    give ``int8``), else the default dtype of their kind (complex keeps float64's precision).
    """
    names = list(names)
    if not names:
        raise TypeError("result_type needs at least one array or dtype (not only Python scalars).")
    dtype = reduce(promote, names)
    top = max((_scalar_kind(s) for s in scalars), default=0)
    k = kind_of(dtype)
    if top <= k:
        return dtype
    if top == 3 and k == 2:
        return _COMPLEX_OF[dtype]
    return _DEFAULT_OF_KIND[top]


def default_of(scalars) -> str:
    """The dtype of Python ``scalars`` alone: the default dtype of the highest kind among them
    (``where(c, 1.5, 2)`` is float32)."""
    return _DEFAULT_OF_KIND[max(_scalar_kind(s) for s in scalars)]


def can_cast(from_: str, to: str) -> bool:
    """True when promoting ``from_`` with ``to`` by the Array API's table gives ``to``: within a
    kind, or a real floating dtype to a complex one. Across kinds (``bool`` to ``int8``,
    ``int64`` to ``float64``), which the table leaves out, False."""
    ka, kb = kind_of(from_), kind_of(to)
    if ka != kb and not (ka == 2 and kb == 3):
        return False
    return promote(from_, to) == to


def isdtype(name: str, kind, name_of: Callable[[Any], str] = name_of) -> bool:
    """Whether dtype ``name`` is of ``kind``: a kind name (``'real floating'``...), a dtype (by
    ``name_of``), or a tuple of these (any of them)."""
    if isinstance(kind, tuple):
        return any(isdtype(name, k, name_of) for k in kind)
    if isinstance(kind, str) and kind in KINDS:
        return name in KINDS[kind]
    if isinstance(kind, str) and kind not in DTYPE_NAMES:
        raise ValueError(
            f"Unknown dtype kind {kind!r}; use one of {', '.join(map(repr, KINDS))}, a dtype, "
            f"or a tuple of these."
        )
    return name == name_of(kind)


def finfo(name: str, native: Callable[[str], Any] = str) -> FInfo:
    """Limits of the floating dtype ``name`` (complex: of its real part); ``native`` maps the name
    of the real dtype to the ``dtype`` attribute."""
    if kind_of(name) < 2:
        raise TypeError(f"finfo needs a floating dtype, got {name}; use iinfo for integers.")
    import numpy as np

    real = _REAL_OF.get(name, name)
    info = np.finfo(real)
    return FInfo(
        bits=int(info.bits),
        eps=float(info.eps),
        max=float(info.max),
        min=float(info.min),
        smallest_normal=float(info.smallest_normal),
        dtype=native(real),
    )


def iinfo(name: str, native: Callable[[str], Any] = str) -> IInfo:
    """Limits of the integer dtype ``name``; ``native`` maps the name to the ``dtype`` attribute."""
    if kind_of(name) != 1:
        raise TypeError(f"iinfo needs an integer dtype, got {name}; use finfo for floating ones.")
    import numpy as np

    info = np.iinfo(name)
    return IInfo(bits=int(info.bits), max=int(info.max), min=int(info.min), dtype=native(name))


# The dtype kinds (0 bool, 1 integer, 2 real floating, 3 complex) that a function does not take,
# on every backend (the Array API standard's table, with ivy's extension: functions of real
# numbers take integers and bools, computed in float32). A call that a backend refuses with such
# a dtype raises ivy's DtypeError (a TypeError) on every backend (``ivy/core/_diagnose.py``).
_NO_COMPLEX = (
    "atan2 copysign hypot nextafter logaddexp signbit ceil floor trunc greater greater_equal "
    "less less_equal maximum minimum remainder floor_divide"
)
REFUSED_KINDS: dict[str, frozenset[int]] = {
    **{name: frozenset({3}) for name in _NO_COMPLEX.split()},
    **{
        name: frozenset({2, 3})
        for name in (
            "bitwise_and bitwise_or bitwise_xor bitwise_invert bitwise_left_shift "
            "bitwise_right_shift"
        ).split()
    },
}
_KIND_WORDS = ("bool", "integer", "real floating", "complex floating")


def refused_kind(function: str, names, scalars=()) -> str | None:
    """The kind (in words) of the operands' dtypes ``names`` (and Python ``scalars``) that
    ``function`` does not take, or None. The promoted dtype counts too (int64 with uint64 is
    float64)."""
    refused = REFUSED_KINDS.get(function)
    if not refused or not names:
        return None
    kinds = [kind_of(n) for n in names] + [kind_of(result_type(names, scalars))]
    for k in kinds:
        if k in refused:
            return _KIND_WORDS[k]
    return None
