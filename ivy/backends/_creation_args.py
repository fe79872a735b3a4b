"""Arguments of the creation functions, read the same way on every backend."""

from __future__ import annotations

from ivy.errors import DtypeError


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
