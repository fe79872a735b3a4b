"""Arguments of the creation functions, read the same way on every backend."""

from __future__ import annotations

from ivy.errors import DtypeError, InvalidValueError


def linspace_dtype(start, stop, dtype, backend: str) -> str | None:
    """The dtype name of ``linspace``'s result when ``dtype`` is None: complex64 for complex
    bounds (the Array API allows them), float32 otherwise; and a real ``dtype`` with complex
    bounds raises :class:`ivy.errors.DtypeError` (numpy would drop the imaginary parts)."""
    is_complex = isinstance(start, complex) or isinstance(stop, complex)
    if dtype is None:
        return "complex64" if is_complex else "float32"
    name = dtype if isinstance(dtype, str) else None
    if is_complex and name is not None and not name.startswith("complex"):
        raise DtypeError(
            f"complex bounds {start!r}, {stop!r} need a complex dtype, not {name}.",
            function="linspace",
            argument="dtype",
            backend=backend,
        )
    return None


def check_fill_value(fill_value, dtype_name: str, backend: str) -> None:
    """A Python int ``fill_value`` outside the range of the integer dtype ``dtype_name`` raises
    OverflowError (as numpy does), never wraps around."""
    if type(fill_value) is not int or not dtype_name.startswith(("int", "uint")):
        return
    import numpy as np

    info = np.iinfo(dtype_name)
    if not info.min <= fill_value <= info.max:
        raise OverflowError(
            f"ivy.full ({backend} backend), argument 'fill_value': Python integer "
            f"{fill_value} is out of bounds for {dtype_name} ({info.min} to {info.max}); use a "
            "wider dtype."
        )


def beyond_int64(backend: str) -> OverflowError:
    """The error of ``asarray`` given, without a dtype, Python ints beyond int64, the default
    integer dtype: numpy would make them uint64 (or float64 beside negative ones, or objects),
    torch and jax refuse them."""
    return OverflowError(
        f"ivy.asarray ({backend} backend), argument 'obj': a Python integer is beyond int64, the "
        "default integer dtype. Give dtype='uint64' for values up to 2**64 - 1."
    )


def check_python_data(data, backend: str) -> None:
    """Raise :func:`beyond_int64`'s error where numpy read Python data (no dtype of its own) as
    ``data`` of uint64 or objects, which only Python ints beyond int64 give. (A list that mixes
    such an int with smaller ones, ``[1, 2**63]``, numpy reads as float64: telling it from a
    list of floats would cost a pass over every float list, and it is left as numpy reads it.)"""
    if data.dtype.kind in "uO":
        raise beyond_int64(backend)


def has_int_beyond_int64(obj) -> bool:
    """Whether the Python data ``obj`` (nested lists and tuples) holds an int beyond int64."""
    if type(obj) is int:
        return not -(2**63) <= obj < 2**63
    if isinstance(obj, (list, tuple)):
        return any(has_int_beyond_int64(v) for v in obj)
    return False


def check_step(step, backend: str) -> None:
    """``arange``'s ``step`` must not be 0 (numpy and jax divided by it, torch and tensorflow
    returned an empty range: a plausible answer to a call that has none)."""
    if isinstance(step, (int, float)) and step == 0:
        raise InvalidValueError(
            "step must not be 0 (the range would never reach stop); give a positive step to "
            "count up or a negative one to count down.",
            function="arange",
            argument="step",
            backend=backend,
        )
