"""torch's uint16, uint32 and uint64: torch holds them, but most of its kernels refuse them
(``"add_stub" not implemented for 'UInt16'``), and it promotes them with no other dtype.

Each torch function that may refuse them is wrapped by :func:`unsigned_safe`: the native runs
first, and only when it raises with such an input does the wrapper compute through a type where
that is exact. The operands are first promoted by ivy's rules (``ivy/core/_dtype_rules.py``);
then, by the kind of function:

- ``"arith"`` (sums, products, bitwise functions, left shifts): in int64, whose wrap-around
  modulo 2**64 is uint64's, and cast back (uint16 and uint32 wrap there too);
- ``"order"`` (comparisons, maxima and minima, sorting, searching): on an int64 key that orders
  as the values do (uint64: its bits with the top bit flipped), mapped back where values come out;
- ``"move"`` (functions that move elements without computing on them: flips, gathers, ``where``):
  on the same bits seen as the signed type of the same width;
- ``"divide"`` (floor division, remainder, right shift): in int64, exact for uint16 and uint32,
  and for uint64 values below 2**63; larger uint64 values raise
  :class:`ivy.errors.UnsupportedError` naming the dtype.

The wrapper carries the native as ``__ivy_native__``: ivy's dispatchers call the native and hand
only what it refuses to the wrapper, so ``ivy.add(x, y)`` costs what ``torch.add`` costs.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Sequence
from typing import Any

import torch

from ivy.core import _dtype_rules as rules
from ivy.errors import UnsupportedError

WIDE_UNSIGNED = frozenset({torch.uint16, torch.uint32, torch.uint64})
SIGNED_OF = {torch.uint16: torch.int16, torch.uint32: torch.int32, torch.uint64: torch.int64}
_NAMES = {t: str(t).rpartition(".")[2] for t in (*SIGNED_OF, *SIGNED_OF.values())}
_TOP_BIT = -(2**63)


def _name(dtype: torch.dtype) -> str:
    return str(dtype).rpartition(".")[2]


def _dtype(name: str) -> torch.dtype:
    return getattr(torch, name)


def is_wide_unsigned(value: Any) -> bool:
    return isinstance(value, torch.Tensor) and value.dtype in WIDE_UNSIGNED


def promoted(values: Sequence[Any]) -> torch.dtype | None:
    """The dtype of the tensors among ``values`` promoted by ivy's rules, with the Python scalars
    among them (None when there is no tensor)."""
    names = [_name(v.dtype) for v in values if isinstance(v, torch.Tensor)]
    if not names:
        return None
    scalars = [v for v in values if isinstance(v, (bool, int, float, complex))]
    return _dtype(rules.result_type(names, scalars))


def order_key(x: torch.Tensor) -> torch.Tensor:
    """int64 values that order as ``x`` (of a wide unsigned dtype) does."""
    if x.dtype is torch.uint64:
        return x.view(torch.int64) ^ _TOP_BIT
    return x.to(torch.int64)


def from_order_key(key: torch.Tensor, dtype: torch.dtype) -> torch.Tensor:
    if dtype is torch.uint64:
        return (key ^ _TOP_BIT).view(torch.uint64)
    return key.to(dtype)


def _scalar_key(value: Any, dtype: torch.dtype, name: str) -> Any:
    if dtype is not torch.uint64 or not isinstance(value, int) or isinstance(value, bool):
        return value
    if not 0 <= value < 2**64:
        raise UnsupportedError(
            f"ivy.{name} (torch backend): comparing uint64 with the Python int {value}, which is "
            f"outside uint64's range, is not supported."
        )
    return value + _TOP_BIT


def _fits_int64(x: torch.Tensor) -> bool:
    return x.dtype is not torch.uint64 or bool((x.view(torch.int64) >= 0).all())


def _map(values: Sequence[Any], data: Sequence[int], fn: Callable[[Any], Any]) -> list[Any]:
    out = list(values)
    for i in data:
        if i < len(out):
            out[i] = fn(out[i])
    return out


def _unsigned_fallback(
    native: Callable, name: str, kind: str, data: Sequence[int], args: tuple, kwargs: dict
) -> Any:
    values = [args[i] for i in data if i < len(args)]
    dtype = promoted(values)
    if dtype is None:
        return None
    args = tuple(_map(args, data, lambda v: v.to(dtype) if isinstance(v, torch.Tensor) else v))
    if dtype not in WIDE_UNSIGNED:
        return native(*args, **kwargs)  # promoted out of the refused dtypes (uint16 + int8)
    if kind == "arith":
        out = native(*_map(args, data, _to_int64), **kwargs)
        return out.to(dtype) if out.dtype is torch.int64 else out
    if kind == "divide":
        tensors = [v for v in (args[i] for i in data if i < len(args)) if is_wide_unsigned(v)]
        if not all(_fits_int64(t) for t in tensors):
            raise UnsupportedError(
                f"ivy.{name} (torch backend): torch has no {name} kernel for uint64, and values of "
                f"2**63 or more do not fit int64, through which ivy computes it. Use numpy, jax "
                f"or tensorflow for such values."
            )
        out = native(*_map(args, data, _to_int64), **kwargs)
        return out.to(dtype) if out.dtype is torch.int64 else out
    if kind == "order":
        keyed = _map(
            args,
            data,
            lambda v: order_key(v) if isinstance(v, torch.Tensor) else _scalar_key(v, dtype, name),
        )
        out = native(*keyed, **kwargs)
        return _from_keys(out, dtype)
    if kind == "move":
        signed = SIGNED_OF[dtype]
        out = native(*_map(args, data, lambda v: _view(v, signed)), **kwargs)
        return _view_back(out, signed, dtype)
    raise ValueError(kind)


def _to_int64(v: Any) -> Any:
    return v.to(torch.int64) if isinstance(v, torch.Tensor) else v


def _view(v: Any, signed: torch.dtype) -> Any:
    if isinstance(v, torch.Tensor) and v.dtype in SIGNED_OF:
        return v.view(signed)
    return v


def _view_back(out: Any, signed: torch.dtype, dtype: torch.dtype) -> Any:
    if isinstance(out, torch.Tensor):
        return out.view(dtype) if out.dtype is signed else out
    if isinstance(out, tuple) and hasattr(out, "_fields"):  # torch's named tuples (values, ...)
        return type(out)(*(_view_back(o, signed, dtype) for o in out))
    if isinstance(out, (tuple, list)):
        return type(out)(_view_back(o, signed, dtype) for o in out)
    return out


def _from_keys(out: Any, dtype: torch.dtype) -> Any:
    """Results of ``"order"`` functions: keys (int64 values) back to ``dtype``; bools and indices
    as they are. Index results are int64 too, so the wrapped functions that return both say
    which is which by their named tuples (values first)."""
    if isinstance(out, torch.Tensor):
        return from_order_key(out, dtype) if out.dtype is torch.int64 else out
    if isinstance(out, tuple) and hasattr(out, "_fields"):  # (values, indices)
        values, *rest = out
        return type(out)(from_order_key(values, dtype), *rest)
    return out


def unsigned_safe(native: Callable, name: str, kind: str, data: Sequence[int] = (0, 1)) -> Callable:
    """``native`` (a torch function), computing uint16, uint32 and uint64 inputs, which it
    refuses, as the module docstring says.

    Args:
        native: the torch function.
        name: the ivy function's name (for messages).
        kind: ``"arith"``, ``"order"``, ``"move"`` or ``"divide"``.
        data: the positions of the arguments that hold values (not indices, conditions or
            options); they are promoted together.
    """

    @functools.wraps(native)
    def fn(*args: Any, **kwargs: Any) -> Any:
        try:
            return native(*args, **kwargs)
        except (NotImplementedError, RuntimeError, TypeError):
            if not any(is_wide_unsigned(args[i]) for i in data if i < len(args)):
                raise
        out = _unsigned_fallback(native, name, kind, data, args, kwargs)
        if out is None:
            raise UnsupportedError(f"ivy.{name} (torch backend): no tensor input to compute on.")
        return out

    fn.__name__ = fn.__qualname__ = name
    fn.__ivy_native__ = native
    del fn.__wrapped__
    return fn


def work_dtype(dtype: torch.dtype | None) -> torch.dtype | None:
    """The dtype to compute in for a result of ``dtype``: int64 for the wide unsigned ones."""
    return torch.int64 if dtype in WIDE_UNSIGNED else dtype


__all__ = [
    "WIDE_UNSIGNED",
    "SIGNED_OF",
    "is_wide_unsigned",
    "order_key",
    "from_order_key",
    "promoted",
    "unsigned_safe",
    "work_dtype",
]
_ = _NAMES
