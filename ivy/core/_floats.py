"""Floating-point arguments of compositions: integers and bools are computed in float32 (the
default float dtype), as everywhere in ivy, and mixed floating dtypes promote."""

from __future__ import annotations

_PYTHON_SCALARS = (bool, int, float, complex)


def is_floating(name: str) -> bool:
    """True for the name of a real or complex floating dtype."""
    return "float" in name or "complex" in name


def floating(xp, x):
    """``x`` as an array, cast to float32 when it is not of a floating or complex dtype (the
    rule of every backend's functions of real numbers, ``ivy/backends/_reals.py``)."""
    if not hasattr(x, "dtype"):
        x = xp.asarray(x)
    return x if is_floating(xp.dtype(x, as_str=True)) else xp.astype(x, "float32")


def common_floating(xp, *values):
    """``values`` (arrays, or Python scalars) as arrays of one floating dtype: the promoted dtype
    of the floating arrays among them, or float32 when there are none."""
    arrays = [v for v in values if not isinstance(v, _PYTHON_SCALARS)]
    floats = [a for a in arrays if is_floating(xp.dtype(a, as_str=True))]
    target = xp.result_type(*floats) if floats else xp.float32
    device = xp.dev(arrays[0]) if arrays else None
    out = []
    for v in values:
        if isinstance(v, _PYTHON_SCALARS):
            out.append(xp.asarray(v, dtype=target, device=device))
        elif xp.dtype(v) == target:
            out.append(v)
        else:
            out.append(xp.astype(v, target))
    return out
