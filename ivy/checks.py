"""Declarative checks of the arguments of public functions, shared by the applied libraries.

A public function states the shape each array argument must have, and :func:`checked` does the
rest, the same way on every backend, before any framework sees the arrays:

- a wrong shape raises :class:`InputError` naming the function, the argument, the expected shape,
  the shape it got and the fix (never a framework's ``IndexError``, ``InvalidArgumentError`` or a
  silently wrong answer from a slice that happened to fit);
- the array arguments are brought to one floating dtype, ivy's rule for functions of real
  numbers: integer and boolean arrays compute in float32, and floating arrays of different
  precisions promote (float32 with float64 is float64), as numpy, torch and jax do and as
  tensorflow would refuse to.

Shape specs read as the docstrings do: ``("...", 3, 3)`` is a batch of 3x3 matrices (any leading
dimensions), ``("...", "H", "W", 1)`` an image with one channel; ``"..."`` stands for any number
of leading dimensions (first only), a name for any size, an int for that size, a tuple of ints for
one of those sizes.

Example:
    >>> @checked(quaternion=("...", 4))
    ... def norm(quaternion, *, f=None):
    ...     return (quaternion ** 2).sum(-1) ** 0.5
    >>> norm(np.array([0, 0, 3, 4]))            # an integer array computes in float32
    np.float32(5.0)
    >>> norm(np.ones(3))
    Traceback (most recent call last):
    ...
    ivy.checks.InputError: norm: quaternion must be [..., 4]; got shape (3,).
"""

from __future__ import annotations

import functools
import inspect

from ivy.core._floats import common_floating
from ivy.errors import IvyError

__all__ = ["InputError", "checked", "check_shape", "check_floating_dtype", "describe", "shape_of"]

_PYTHON_SCALARS = (bool, int, float, complex)


class InputError(IvyError, ValueError):
    """Bad input to a public function: ``str()`` is ``"<function>: <message>"``."""

    def __init__(self, message: str, function: str | None = None):
        super().__init__(message)
        self.message = message
        self.function = function

    def __str__(self) -> str:
        return f"{self.function}: {self.message}" if self.function else self.message


def describe(spec) -> str:
    """``("...", "H", "W", (3, 4))`` -> ``"[..., H, W, 3 or 4]"``."""

    def entry(e):
        if isinstance(e, tuple):
            return " or ".join(str(v) for v in e)
        return str(e)

    return "[" + ", ".join(entry(e) for e in spec) + "]"


def shape_of(x) -> tuple | None:
    """The shape of an array as a tuple (None for a size unknown while tracing), or None when
    even its number of dimensions is unknown."""
    try:
        return tuple(x.shape)
    except (TypeError, ValueError):  # a symbolic tensor of unknown rank
        return None


def check_shape(shape: tuple, spec, what: str, hint: str = "") -> dict:
    """Raise an :class:`InputError` unless ``shape`` matches ``spec``; return the sizes of the
    named dimensions.

    Args:
        shape: the argument's shape (a size of None, unknown while tracing, matches anything).
        spec: ``"..."`` first for any leading dimensions, then per dimension a name (any size),
            an int or a tuple of ints.
        what: the argument's name, for the message.
        hint: how to fix it, appended to the message.

    Returns:
        ``{name: size}`` for the named dimensions.

    Example:
        >>> check_shape((2, 4, 5, 1), ("...", "H", "W", 1), "depth")
        {'H': 4, 'W': 5}
    """
    spec = tuple(spec)
    leading = bool(spec) and spec[0] == "..."
    dims = spec[1:] if leading else spec
    shape = tuple(shape)
    fits = len(shape) >= len(dims) if leading else len(shape) == len(dims)
    named = {}
    if fits:
        tail = shape[len(shape) - len(dims) :]
        for size, want in zip(tail, dims):
            if isinstance(want, str):
                named[want] = size
            elif size is not None and size not in (want if isinstance(want, tuple) else (want,)):
                fits = False
    if not fits:
        raise InputError(
            f"{what} must be {describe(spec)}; got shape {shape}." + (f" {hint}" if hint else "")
        )
    return named


def check_floating_dtype(dtype, what: str = "dtype") -> None:
    """Raise an :class:`InputError` unless ``dtype`` (a name or a framework's dtype) is a
    floating one: a function of real values given an integer dtype would answer with values
    rounded to integers, plausible and wrong.

    Example:
        >>> check_floating_dtype("int32")
        Traceback (most recent call last):
        ...
        ivy.checks.InputError: dtype must be a floating dtype (float32, float64); got 'int32'.
    """
    if dtype is not None and not _is_floating(dtype):
        raise InputError(f"{what} must be a floating dtype (float32, float64); got {dtype!r}.")


def _matcher(spec, what: str, hint: str = ""):
    """A function of an array that raises like :func:`check_shape` unless its shape matches
    ``spec``, and returns its leading (``"..."``) dimensions (None when ``spec`` has none, or the
    shape is unknown); compiled once per spec, for the fast path of every call."""
    spec = tuple(spec)
    leading = bool(spec) and spec[0] == "..."
    dims = spec[1:] if leading else spec
    n = len(dims)
    fixed = [
        (i - n, v if isinstance(v, tuple) else (v,))
        for i, v in enumerate(dims)
        if not isinstance(v, str)
    ]

    def match(x):
        try:
            shape = tuple(x.shape)
        except (TypeError, ValueError):  # a symbolic tensor of unknown rank
            return None
        size = len(shape)
        if size < n or (size != n and not leading):
            check_shape(shape, spec, what, hint)
        for axis, allowed in fixed:
            if shape[axis] not in allowed and shape[axis] is not None:
                check_shape(shape, spec, what, hint)
        return shape[: size - n] if leading else None

    return match


def _shared_names(shapes: dict) -> dict:
    """``{name: {argument: axis}}`` for the dimension names that several specs share (their
    sizes must agree), the axis counted from the end."""
    where: dict = {}
    for key, spec in shapes.items():
        dims = spec[1:] if spec and spec[0] == "..." else spec
        for i, entry in enumerate(dims):
            if isinstance(entry, str):
                where.setdefault(entry, {})[key] = i - len(dims)
    return {name: args for name, args in where.items() if len(args) > 1}


def _same_named_sizes(shared: dict, arrays: dict) -> None:
    """Raise an :class:`InputError` unless the dimensions that share a name have one size."""
    for name, axes in shared.items():
        sizes = {}
        for key, axis in axes.items():
            shape = shape_of(arrays[key]) if key in arrays else None
            if shape is not None and len(shape) >= -axis and shape[axis] is not None:
                sizes[key] = shape[axis]
        if len(set(sizes.values())) > 1:
            listed = ", ".join(f"{key} {shape_of(arrays[key])}" for key in sizes)
            raise InputError(
                f"the dimension {name} must have one size in every argument; got {listed}."
            )


def _batch_shapes_broadcast(batches: dict) -> None:
    """Raise an :class:`InputError` unless the batch shapes ``{argument: shape}`` broadcast
    (numpy's rules, aligned on the right)."""
    shapes = list(batches.values())
    if all(s == shapes[0] for s in shapes[1:]):
        return
    n = max(len(s) for s in batches.values())
    for axis in range(1, n + 1):
        sizes = {name: s[-axis] for name, s in batches.items() if len(s) >= axis}
        known = {v for v in sizes.values() if v not in (1, None)}
        if len(known) > 1:
            listed = ", ".join(f"{name} {batches[name]}" for name in batches)
            raise InputError(
                f"the batch dimensions of {listed} do not broadcast together; give every "
                f"argument the same leading batch dimensions (or 1 where it is shared)."
            )


def _as_arrays(args: list, kwargs: dict, slots, shapes: dict, found: list):
    """Make arrays of the lists, tuples and scalars given for the arguments with a shape (in
    place, added to ``found``), in the function's framework; return its namespace."""
    import ivy

    given = [args[i] for i, _ in slots if i < len(args)] + list(kwargs.values())
    xp = ivy.get_framework(*(v for v in given if v is not None), f=kwargs.get("f"))
    places = [(key, args, i) for i, key in slots if i < len(args)]
    places += [(key, kwargs, key) for key in kwargs if key in shapes]
    for key, holder, where in places:
        value = holder[where]
        if key in shapes and value is not None and not hasattr(value, "shape"):
            holder[where] = xp.asarray(value)
            found.append((key, holder, where))
    return xp


def checked(fn=None, /, *, exact=(), broadcast=False, hints=None, **shapes):
    """Decorate a public function: check its array arguments' shapes, bring them to one
    floating dtype, and name the function in every :class:`InputError` raised inside it.

    Args:
        fn: the function (when used bare, ``@checked``).
        exact: names of array arguments left as they are (integer ids, boolean masks).
        broadcast: check that the leading (``"..."``) dimensions of the arguments in ``shapes``
            broadcast together.
        hints: argument name -> how to fix a wrong shape, appended to the message.
        **shapes: argument name -> shape spec (see :func:`check_shape`). A Python list or tuple
            given for such an argument is made an array of the function's framework.

    Returns:
        The decorated function (or a decorator, when called with options only).

    The arrays given for the other arguments annotated as arrays (``Array``, ``Array | None``)
    are cast too, unless named in ``exact``. The framework is resolved as the function resolves it (``f=`` first, then the
    global framework, then the arrays), and only when an argument needs a conversion.

    Example:
        >>> @checked(rot_mat=("...", 3, 3))
        ... def trace(rot_mat, *, f=None):
        ...     return rot_mat[..., 0, 0] + rot_mat[..., 1, 1] + rot_mat[..., 2, 2]
        >>> trace(np.eye(3, 4))
        Traceback (most recent call last):
        ...
        ivy.checks.InputError: trace: rot_mat must be [..., 3, 3]; got shape (3, 4).
    """
    if fn is None:
        return lambda f_: _checked(f_, frozenset(exact), broadcast, hints or {}, shapes)
    return _checked(fn, frozenset(exact), broadcast, hints or {}, shapes)


def _checked(fn, exact: frozenset, broadcast: bool, hints: dict, shapes: dict):
    name = fn.__qualname__
    params = list(inspect.signature(fn).parameters.values())
    positional = [p.name for p in params if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
    unknown = (set(shapes) | exact) - {p.name for p in params}
    if unknown:
        raise TypeError(f"checked({name}): no arguments named {sorted(unknown)}")
    # the arguments whose arrays are cast: those annotated as arrays, and those given a shape
    numeric = ({p.name for p in params if "Array" in str(p.annotation)} | set(shapes)) - exact
    slots = [(i, key) for i, key in enumerate(positional) if key in numeric]
    matchers = {key: _matcher(spec, key, hints.get(key, "")) for key, spec in shapes.items()}
    shared = _shared_names(shapes)

    def prepare(args: list, kwargs: dict) -> None:
        """Check and convert the arguments in place."""
        found = []  # (name, holder, key) of every array argument, to check and convert
        lists = False  # a list or scalar given for an argument with a shape
        n = len(args)
        for i, key in slots:
            if i < n:
                value = args[i]
                if hasattr(value, "shape") and not isinstance(value, _PYTHON_SCALARS):
                    found.append((key, args, i))
                elif value is not None and key in shapes:
                    lists = True
        for key, value in kwargs.items():
            if key in numeric:
                if hasattr(value, "shape") and not isinstance(value, _PYTHON_SCALARS):
                    found.append((key, kwargs, key))
                elif value is not None and key in shapes:
                    lists = True
        xp = None
        if lists:
            xp = _as_arrays(args, kwargs, slots, shapes, found)
        if not found:
            return
        batches = {}
        for key, holder, where in found:
            match = matchers.get(key)
            if match is not None:
                batch = match(holder[where])
                if batch is not None:
                    batches[key] = batch
        if broadcast and len(batches) > 1:
            _batch_shapes_broadcast(batches)
        if shared:
            _same_named_sizes(shared, {key: holder[where] for key, holder, where in found})
        _to_one_floating_dtype(xp, found, kwargs.get("f"))

    @functools.wraps(fn)
    def public(*args, **kwargs):
        try:
            args = list(args)
            prepare(args, kwargs)
            return fn(*args, **kwargs)
        except InputError as error:
            raise InputError(error.message, name) from None

    public.__checked_shapes__ = dict(shapes)
    return public


_FLOATING: dict = {}  # (dtype's type, dtype) -> whether it is a floating (real or complex) dtype


def _is_floating(dtype) -> bool:
    floating = getattr(dtype, "is_floating_point", None)
    if isinstance(floating, bool):  # torch: read directly, no global cache for torch.compile
        return floating or bool(dtype.is_complex)  # to trace (a cache holding other libraries'
    key = (type(dtype), dtype)  # dtypes split its graph); the type first: they never compare
    try:
        return _FLOATING[key]
    except (KeyError, TypeError):
        text = getattr(dtype, "name", None) or str(dtype)
        floating = "float" in text or "complex" in text
        try:
            _FLOATING[key] = floating
        except TypeError:  # not hashable
            pass
        return floating


def _to_one_floating_dtype(xp, found: list, f) -> None:
    """Cast the arrays ``(name, holder, key)`` to one floating dtype (ivy's rule,
    ``ivy.core._floats``), in place, only where they are not of one floating dtype already."""
    first = found[0][1][found[0][2]].dtype
    if _is_floating(first) and all(h[w].dtype == first for _, h, w in found[1:]):
        return  # the common case: nothing to do
    values = [h[w] for _, h, w in found]
    if xp is None:
        import ivy

        xp = ivy.get_framework(*values, f=f)
    for (_, holder, where), value in zip(found, common_floating(xp, *values)):
        holder[where] = value
