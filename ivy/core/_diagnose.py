"""What went wrong when a backend refused a call: the typed error that names the function, the
argument and the backend (``ivy/errors.py``).

A framework-agnostic call (``ivy.take(x, i)``) that a backend refuses comes here, and only then:
the call itself costs nothing more. The arguments are bound to the stub's parameters and
checked, in order, for what the frameworks report each in their own words:

- a dtype the backend has no kernel for (torch's ``"add_stub" not implemented for 'UInt16'``,
  tensorflow's ``Value for attr 'T' of uint8 is not in the list of allowed values``):
  :class:`~ivy.errors.UnsupportedError` naming the dtype;
- an axis out of range or repeated: :class:`~ivy.errors.AxisError`;
- array arguments whose shapes do not broadcast: :class:`~ivy.errors.ShapeError`;
- indices out of range: :class:`~ivy.errors.IndexOutOfBoundsError`.

When none of these explains the error, a framework's error for bad input whose builtin class
is not already a ``ValueError``, ``TypeError`` or ``IndexError`` (tensorflow's
``InvalidArgumentError``, torch's ``RuntimeError``) becomes an :class:`InvalidArgumentError` of
the kind its message says; anything else is raised as it was.
"""

from __future__ import annotations

import inspect
import re
from collections.abc import Callable, Sequence
from typing import Any

from ivy.core._dispatch import FUNCTIONS, REGISTRY
from ivy.errors import (
    AxisError,
    DtypeError,
    IndexOutOfBoundsError,
    InvalidArgumentError,
    InvalidValueError,
    IvyError,
    LinAlgError,
    ShapeError,
    UnsupportedError,
)

# The parameters that hold axes, and how many axes the result has beyond the input's (an axis
# of expand_dims or stack may name a new last axis).
AXIS_PARAMETERS = ("axis", "axes", "axis0", "axis1", "source", "destination")
_NEW_AXES = {"expand_dims": "axis", "stack": 1}
_NO_AXIS_CHECK = frozenset({"tensordot", "fftn", "ifftn", "rfftn", "irfftn"})  # other meanings

# Functions that broadcast all their array arguments together.
_BROADCASTING_GROUPS = frozenset({"elementwise"})
_BROADCASTING = frozenset(
    {"where", "clip", "isclose", "allclose", "safe_divide", "safe_atan2", "broadcast_arrays"}
)

_KERNEL_MESSAGES = (
    re.compile(r"not implemented for '(\w+)'"),  # torch
    re.compile(r"of (\w+) is not in the list of allowed values"),  # tensorflow
    re.compile(r"does not support (\w+) input"),  # torch argmax of bool
    re.compile(r"No kernel for (\w+)"),
)
_TORCH_DTYPES = {
    "Bool": "bool",
    "Char": "int8",
    "Byte": "uint8",
    "Short": "int16",
    "Int": "int32",
    "Long": "int64",
    "UInt16": "uint16",
    "UInt32": "uint32",
    "UInt64": "uint64",
    "Half": "float16",
    "Float": "float32",
    "Double": "float64",
    "ComplexFloat": "complex64",
    "ComplexDouble": "complex128",
    "bool": "bool",
}
_SHAPE_WORDS = re.compile(
    r"(incompatible shapes|must match the size|broadcast|shape mismatch|size mismatch|"
    r"inconsistent tensor size|operands could not be|Dimensions must be equal)",
    re.IGNORECASE,
)
# The framework error classes that stand for bad input without being the builtin error of its
# kind (tensorflow's InvalidArgumentError, torch's RuntimeError and LinAlgError, jax's runtime
# errors).
_FRAMEWORK_ERRORS = frozenset(
    {"InvalidArgumentError", "RuntimeError", "_LinAlgError", "LinAlgError", "JaxRuntimeError"}
)
_INDEX_WORDS = re.compile(r"(out of bounds|out of range|index \S+ is out)", re.IGNORECASE)


def explain(ns: Any, name: str, err: Exception, args: tuple, kwargs: dict) -> Exception:
    """The error to raise for ``err``, which backend ``ns`` raised in ``ivy.<name>(*args,
    **kwargs)``: a typed ivy error naming the function, the argument and the backend, or
    ``err`` itself."""
    if isinstance(err, IvyError):
        return err
    try:
        bound = _bind(name, args, kwargs)
        checks = (
            _refused_dtype,
            _empty_reduction,
            _unsupported_dtype,
            _axes,
            _squeeze,
            _broadcast,
            _shapes,
            _indices,
        )
        for check in checks:
            try:
                found = check(ns, name, bound, err)
            except InvalidArgumentError as typed:  # a check that raises what it finds
                return typed
            if found is not None:
                return found
    except Exception:  # noqa: BLE001 - a diagnosis never hides the original error
        return err
    return _by_message(ns, name, err)


def _bind(name: str, args: tuple, kwargs: dict) -> dict[str, Any]:
    sig = inspect.signature(FUNCTIONS[name])
    return dict(sig.bind(*args, **kwargs).arguments)


def _is_array(value: Any) -> bool:
    return hasattr(value, "shape") and hasattr(value, "dtype") and not isinstance(value, type)


def _dtype_of(ns: Any, value: Any) -> str | None:
    try:
        return ns.dtype(value, as_str=True)
    except Exception:  # noqa: BLE001
        return None


def _arrays(bound: dict[str, Any]) -> list[tuple[str, Any]]:
    return [(k, v) for k, v in bound.items() if _is_array(v)]


def _refused_dtype(ns: Any, name: str, bound: dict, err: Exception) -> Exception | None:
    """A dtype that the function takes on no backend (``_dtype_rules.REFUSED_KINDS``)."""
    from ivy.core._dtype_rules import refused_kind

    arrays = _arrays(bound)
    names = [_dtype_of(ns, v) for _, v in arrays]
    if not names or None in names:
        return None
    scalars = [v for v in bound.values() if type(v) in (bool, int, float, complex)]
    kind = refused_kind(name, names, scalars)
    if kind is None:
        return None
    described = ", ".join(f"{k} of dtype {n}" for (k, _), n in zip(arrays, names))
    return DtypeError(
        f"takes no {kind} input (got {described}). Cast first (ivy.astype).",
        function=name,
        argument=", ".join(k for k, _ in arrays),
        backend=ns.backend,
    )


_REDUCTIONS_OF_NONEMPTY = frozenset({"max", "min", "argmax", "argmin"})


def _empty_reduction(ns: Any, name: str, bound: dict, err: Exception) -> Exception | None:
    """max, min, argmax, argmin over an empty axis (they have no identity)."""
    if name not in _REDUCTIONS_OF_NONEMPTY or not _is_array(bound.get("x")):
        return None
    shape = tuple(bound["x"].shape)
    axis = bound.get("axis")
    axes = range(len(shape)) if axis is None else _axis_values(axis) or []
    if any(-len(shape) <= a < len(shape) and shape[a] == 0 for a in axes):
        return InvalidValueError(
            f"reduces an empty axis (shape {shape}), which has no {name} value.",
            function=name,
            argument="x",
            backend=ns.backend,
        )
    return None


def _size(shape: Sequence[int]) -> int:
    out = 1
    for n in shape:
        out *= n
    return out


def _shapes(ns: Any, name: str, bound: dict, err: Exception) -> Exception | None:
    """reshape to a shape of another size; matmul and tensordot of axes of different sizes."""
    if name == "reshape" and _is_array(bound.get("x")):
        shape = bound.get("shape")
        shape = (shape,) if isinstance(shape, int) else tuple(shape)
        size = _size(bound["x"].shape)
        known = _size(n for n in shape if n != -1)
        if (-1 not in shape and known != size) or (-1 in shape and (known == 0 or size % known)):
            return ShapeError(
                f"cannot reshape an array of shape {tuple(bound['x'].shape)} (size {size}) "
                f"to {shape}.",
                function=name,
                argument="shape",
                backend=ns.backend,
            )
    if name in ("concat", "stack") and isinstance(bound.get("arrays"), (list, tuple)):
        shapes = [tuple(v.shape) for v in bound["arrays"] if _is_array(v)]
        axis = bound.get("axis", 0)
        if len(shapes) > 1 and isinstance(axis, int):
            keep = [
                tuple(n for i, n in enumerate(s) if name == "stack" or i != axis % max(len(s), 1))
                for s in shapes
            ]
            if len(set(keep)) > 1 or len({len(s) for s in shapes}) > 1:
                return ShapeError(
                    f"the arrays' shapes {shapes} differ "
                    + ("" if name == "stack" else f"in axes other than {axis}")
                    + ".",
                    function=name,
                    argument="arrays",
                    backend=ns.backend,
                )
    if name in ("matmul", "tensordot", "vecdot") and _is_array(bound.get("x1")):
        a, b = tuple(bound["x1"].shape), tuple(bound.get("x2").shape)
        if name == "matmul" and a and b:
            inner = (a[-1], b[-2] if len(b) > 1 else b[0])
        elif name == "tensordot" and isinstance(bound.get("axes", 2), int):
            k = bound.get("axes", 2)
            inner = (a[len(a) - k :], b[:k])
        else:
            return None
        if inner[0] != inner[1]:
            return ShapeError(
                f"the contracted axes differ in size: x1 of shape {a}, x2 of shape {b}.",
                function=name,
                argument="x1, x2",
                backend=ns.backend,
            )
    return None


def _unsupported_dtype(ns: Any, name: str, bound: dict, err: Exception) -> Exception | None:
    text = str(err)
    for pattern in _KERNEL_MESSAGES:
        match = pattern.search(text)
        if match:
            dtype = _TORCH_DTYPES.get(match.group(1), match.group(1))
            arg = next((k for k, v in _arrays(bound) if _dtype_of(ns, v) == dtype), None)
            return UnsupportedError(
                f"ivy.{name} ({ns.backend} backend)"
                + (f", argument {arg!r}" if arg else "")
                + f": {ns.backend} has no kernel for {dtype}. Cast the input to a dtype it "
                f"supports first (ivy.astype), or use another backend."
            )
    return None


def _axis_values(value: Any) -> list[int] | None:
    if isinstance(value, bool):
        return None
    if isinstance(value, int):
        return [value]
    if isinstance(value, (tuple, list)) and all(
        isinstance(v, int) and not isinstance(v, bool) for v in value
    ):
        return list(value)
    return None


def _axes(ns: Any, name: str, bound: dict, err: Exception) -> Exception | None:
    if name in _NO_AXIS_CHECK:
        return None
    arrays = _arrays(bound)
    if not arrays:
        first = bound.get("arrays")
        if isinstance(first, (list, tuple)) and first and _is_array(first[0]):
            arrays = [("arrays", first[0])]
        else:
            return None
    ndim = len(arrays[0][1].shape)
    for param in AXIS_PARAMETERS:
        axes = _axis_values(bound.get(param))
        if axes is None:
            continue
        extra = _NEW_AXES.get(name, 0)
        if extra == "axis":
            extra = len(axes)
        rank = ndim + extra
        bad = [a for a in axes if not -rank <= a < rank]
        if bad:
            return AxisError(
                AxisError.out_of_range(bad[0], rank),
                function=name,
                argument=param,
                backend=ns.backend,
            )
        if len({a % rank for a in axes}) != len(axes) and rank:
            return AxisError(
                f"repeated axis in {tuple(axes)}.",
                function=name,
                argument=param,
                backend=ns.backend,
            )
    return None


def _squeeze(ns: Any, name: str, bound: dict, err: Exception) -> Exception | None:
    if name != "squeeze" or bound.get("axis") is None:
        return None
    from ivy._args.axes import check_squeezable, normalize_axes

    shape = tuple(bound["x"].shape)
    axes = normalize_axes(bound["axis"], len(shape), name, ns.backend)
    check_squeezable(shape, axes, bound["axis"], ns.backend)
    return None


def broadcast_shapes(*shapes: Sequence[int]) -> tuple[int, ...] | None:
    """The broadcast of ``shapes`` (None entries are unknown sizes), or None if they do not
    broadcast."""
    out: list[Any] = []
    for shape in shapes:
        shape = list(shape)
        if len(shape) > len(out):
            out = [1] * (len(shape) - len(out)) + out
        shape = [1] * (len(out) - len(shape)) + shape
        for i, (a, b) in enumerate(zip(out, shape)):
            if a == 1 or a is None:
                out[i] = b if a == 1 else a
            elif b not in (1, a, None):
                return None
    return tuple(out)


def _broadcast(ns: Any, name: str, bound: dict, err: Exception) -> Exception | None:
    info = REGISTRY.get(name)
    if name not in _BROADCASTING and (info is None or info.group not in _BROADCASTING_GROUPS):
        return None
    arrays = _arrays(bound)
    if isinstance(bound.get("arrays"), (list, tuple)):
        arrays += [(f"arrays[{i}]", v) for i, v in enumerate(bound["arrays"]) if _is_array(v)]
    if len(arrays) < 2:
        return None
    shapes = [tuple(v.shape) for _, v in arrays]
    if broadcast_shapes(*shapes) is not None:
        return None
    described = ", ".join(f"{k} of shape {s}" for (k, _), s in zip(arrays, shapes))
    return ShapeError(
        f"the shapes do not broadcast together: {described}.",
        function=name,
        argument=", ".join(k for k, _ in arrays),
        backend=ns.backend,
    )


def _index_bounds(name: str, bound: dict) -> tuple[str, Any, Callable[[Any], str | None]] | None:
    """(argument, indices, check) for the functions that index: ``check(numpy indices)`` says
    what is out of range, or None."""
    import numpy as np

    def within(size: int, negative: bool = True) -> Callable[[Any], str | None]:
        def check(idx):
            low = -size if negative else 0
            bad = idx[(idx < low) | (idx >= size)]
            if bad.size:
                valid = f"{low} to {size - 1}" if size else "none: the axis is empty"
                return f"index {bad.flat[0]} is out of bounds for size {size} (valid: {valid})."
            return None

        return check

    def per_column(shape: Sequence[int]) -> Callable[[Any], str | None]:
        def check(idx):
            if idx.ndim == 0 or idx.shape[-1] > len(shape):
                return None
            for k in range(idx.shape[-1]):
                found = within(shape[k])(idx[..., k])
                if found:
                    return f"column {k}: {found}"
            return None

        return check

    if name in ("take", "take_along_axis"):
        x, axis = bound["x"], bound.get("axis", -1 if name == "take_along_axis" else None)
        size = int(np.prod(x.shape)) if axis is None else x.shape[axis]
        return "indices", bound["indices"], within(size)
    if name == "put_rows" and len(bound["x"].shape):
        return "indices", bound["indices"], within(bound["x"].shape[0])
    if name == "gather_flat":
        return "indices", bound["indices"], within(int(np.prod(bound["params"].shape)))
    if name == "gather_nd":
        return "indices", bound["indices"], per_column(bound["params"].shape)
    if name == "scatter_nd":
        shape = bound["shape"]
        return (
            "indices",
            bound["indices"],
            per_column((shape,) if isinstance(shape, int) else shape),
        )
    if name == "scatter_flat":
        return "indices", bound["indices"], within(bound["size"])
    if name == "one_hot":
        return "indices", bound["indices"], within(bound["depth"], negative=False)
    return None


def _indices(ns: Any, name: str, bound: dict, err: Exception) -> Exception | None:
    import numpy as np

    found = _index_bounds(name, bound)
    if found is None:
        return None
    argument, indices, check = found
    idx = np.asarray(ns.to_numpy(indices) if _is_array(indices) else indices)
    if idx.dtype.kind not in "iu":
        return None
    problem = check(idx)
    if problem is None:
        return None
    return IndexOutOfBoundsError(problem, function=name, argument=argument, backend=ns.backend)


def _is_linalg(name: str) -> bool:
    info = REGISTRY.get(name)
    return info is not None and info.group.startswith("linalg")


def _by_message(ns: Any, name: str, err: Exception) -> Exception:
    """A framework's own error class for bad input (tf's InvalidArgumentError, torch's
    RuntimeError) as an ivy error of the kind its message says; other errors as they are."""
    if type(err).__name__ not in _FRAMEWORK_ERRORS:
        return err
    text = str(err).strip().splitlines()[0] if str(err).strip() else type(err).__name__
    kind: type[InvalidArgumentError] | None = None
    if _SHAPE_WORDS.search(text):
        kind = ShapeError
    elif _INDEX_WORDS.search(text):
        kind = IndexOutOfBoundsError
    elif _is_linalg(name):
        kind = LinAlgError
    else:
        kind = InvalidValueError
    if kind is None:
        return err
    return kind(text[:300], function=name, backend=ns.backend)
