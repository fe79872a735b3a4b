"""The machinery of the differential test (``test_same_answer.py``): cases, native inputs, and
the comparison of what each backend answers.

A :class:`Case` holds the arguments of one call, written once with numpy arrays. Each backend
gets them converted with the framework's own functions (``tests/helpers.native``), so that a bug
in ``ivy.asarray`` cannot hide another; callables given as :class:`PerBackend` are built per
backend (the loss of a gradient, the body of a loop). Every backend's answer is reduced to plain
data (:func:`outcome`: dtype name, shape and values of each array, in nested tuples; or the kind
of error raised) and the backends are compared with the first one: same dtypes, same shapes,
values equal within the tolerance of the dtype (NaN equal to NaN; the sign of a zero ignored).
"""

from __future__ import annotations

import dataclasses
import warnings
from collections.abc import Callable
from typing import Any

import numpy as np

import ivy
from tests.helpers import TOLERANCES, dtype_name, native, numpy_of


class PerBackend:
    """An argument built per backend: ``make(xp)`` with ``xp`` the backend namespace."""

    def __init__(self, make: Callable[[Any], Any], label: str = "fn"):
        self.make, self.label = make, label

    def __repr__(self) -> str:
        return self.label


@dataclasses.dataclass
class Case:
    """One call: ``fn(*args, **kwargs)`` on every backend.

    Attributes:
        args, kwargs: numpy arrays (converted to each backend), lists and tuples of them,
            :class:`PerBackend` values, and anything else as it is (Python scalars, dtype names).
        raises: the error every backend must raise (a builtin class such as ``IndexError``),
            or None: every backend must answer.
        post: reduces a backend's answer before comparison (for answers defined up to a sign,
            such as eigenvectors, or random ones, of which only dtype and shape agree).
        tol: tolerance overrides (``rtol``, ``atol``) for float results.
        backends: the backends the case runs on (None: all; e.g. the differentiable ones).
        label: shown in failure messages.
    """

    args: tuple = ()
    kwargs: dict = dataclasses.field(default_factory=dict)
    raises: type | None = None
    post: Callable[[Any, Any], Any] | None = None
    tol: dict = dataclasses.field(default_factory=dict)
    backends: tuple[str, ...] | None = None
    label: str = ""

    def describe(self) -> str:
        if self.label:
            return self.label
        parts = [_short(a) for a in self.args] + [
            f"{k}={_short(v)}" for k, v in self.kwargs.items()
        ]
        return ", ".join(parts)


def C(*args: Any, **kwargs: Any) -> Case:  # noqa: N802 - reads like a call in the tables
    """A :class:`Case` of ``fn(*args, **kwargs)``; options of the case itself are passed with a
    leading underscore: ``C(x, axis=0, _raises=IndexError, _tol={'rtol': 1e-4})``."""
    options = {k[1:]: kwargs.pop(k) for k in list(kwargs) if k.startswith("_")}
    return Case(args, kwargs, **options)


def _short(value: Any) -> str:
    if isinstance(value, np.ndarray):
        return f"{value.dtype.name}{list(value.shape)}"
    if isinstance(value, (list, tuple)) and any(isinstance(v, np.ndarray) for v in value):
        inner = ", ".join(_short(v) for v in value)
        return f"[{inner}]" if isinstance(value, list) else f"({inner})"
    return repr(value)


# ----------------------------------------------------------------------------------------------
# Inputs
# ----------------------------------------------------------------------------------------------


def to_backend(value: Any, backend: str, xp: Any) -> Any:
    """``value`` with its numpy arrays converted to ``backend``'s arrays (by the framework's own
    functions) and its :class:`PerBackend` values built."""
    if isinstance(value, np.ndarray):
        return native(value, backend)
    if isinstance(value, PerBackend):
        return value.make(xp)
    if isinstance(value, list):
        return [to_backend(v, backend, xp) for v in value]
    if isinstance(value, tuple):
        return tuple(to_backend(v, backend, xp) for v in value)
    if isinstance(value, dict):
        return {k: to_backend(v, backend, xp) for k, v in value.items()}
    return value


# ----------------------------------------------------------------------------------------------
# Answers as plain data
# ----------------------------------------------------------------------------------------------


@dataclasses.dataclass(frozen=True)
class Arr:
    """An array answer: dtype name and values (a numpy array, whose shape is the answer's)."""

    dtype: str
    values: np.ndarray


@dataclasses.dataclass(frozen=True)
class Raised:
    """An error answer: the builtin class it belongs to, every builtin class of
    :data:`ERROR_KINDS` it is an instance of, and its message."""

    kind: str
    message: str
    kinds: frozenset = frozenset()


# The builtin errors a backend's error is classified by, most specific first.
ERROR_KINDS = (
    IndexError,
    ValueError,
    TypeError,
    NotImplementedError,
    ZeroDivisionError,
    OverflowError,
)


def _error_kind(err: BaseException) -> str:
    for kind in ERROR_KINDS:
        if isinstance(err, kind):
            return kind.__name__
    return f"other ({type(err).__module__}.{type(err).__name__})"


def _error_kinds(err: BaseException) -> frozenset:
    return frozenset(kind.__name__ for kind in ERROR_KINDS if isinstance(err, kind))


def _is_array(value: Any) -> bool:
    return hasattr(value, "shape") and hasattr(value, "dtype") and not isinstance(value, type)


def outcome(value: Any) -> Any:
    """``value`` (a backend's answer) as plain data: :class:`Arr` for arrays, tuples for
    sequences (named tuples included), dicts, dtype names for dtypes, Python values as they
    are."""
    if _is_array(value):
        return Arr(dtype_name(value), np.asarray(numpy_of(value)))
    if isinstance(value, (list, tuple)):
        return tuple(outcome(v) for v in value)
    if isinstance(value, dict):
        return {k: outcome(v) for k, v in value.items()}
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return {f.name: outcome(getattr(value, f.name)) for f in dataclasses.fields(value)}
    if isinstance(value, (bool, int, float, complex, str, type(None))):
        return value
    if isinstance(value, np.generic):
        return Arr(value.dtype.name, np.asarray(value))
    try:  # a native dtype object (torch's has no numpy name: read it from its text)
        text = str(value)
        native = text.split(".", 1)[1] if text.startswith("torch.") else value
        return ivy.core._dtype_rules.name_of(getattr(native, "name", native))
    except TypeError:
        return repr(value)


def run_case(fn_name: str, case: Case, backend: str) -> Any:
    """The outcome of ``ivy.<fn_name>(*args, f=backend, **kwargs)`` (a :class:`Raised` when it
    raises)."""
    xp = getattr(ivy, backend)
    fn = getattr(ivy, fn_name)  # the agnostic function, as users call it
    args = to_backend(case.args, backend, xp)
    kwargs = {**to_backend(case.kwargs, backend, xp), "f": backend}
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            answer = fn(*args, **kwargs)
            if case.post is not None:
                answer = case.post(answer, xp)
            return outcome(answer)
    except Exception as err:  # noqa: BLE001 - every error is an answer to compare
        text = str(err).splitlines()[0][:160] if str(err) else ""
        return Raised(_error_kind(err), f"{type(err).__name__}: {text}", _error_kinds(err))


# ----------------------------------------------------------------------------------------------
# Comparison
# ----------------------------------------------------------------------------------------------


def differences(a: Any, b: Any, tol: dict, path: str = "") -> list[str]:
    """Where the outcomes ``a`` and ``b`` differ (empty when they agree)."""
    where = path or "answer"
    if isinstance(a, Raised) or isinstance(b, Raised):
        if isinstance(a, Raised) and isinstance(b, Raised) and a.kind == b.kind:
            return []
        return [f"{where}: {_show(a)} vs {_show(b)}"]
    if isinstance(a, Arr) and isinstance(b, Arr):
        if a.dtype != b.dtype:
            return [f"{where}: dtype {a.dtype} vs {b.dtype}"]
        if a.values.shape != b.values.shape:
            return [f"{where}: shape {a.values.shape} vs {b.values.shape}"]
        if not _values_agree(a.values, b.values, a.dtype, tol):
            return [f"{where}: values\n      {_brief(a.values)}\n   vs {_brief(b.values)}"]
        return []
    if isinstance(a, tuple) and isinstance(b, tuple):
        if len(a) != len(b):
            return [f"{where}: {len(a)} items vs {len(b)}"]
        return [
            d for i, (x, y) in enumerate(zip(a, b)) for d in differences(x, y, tol, f"{path}[{i}]")
        ]
    if isinstance(a, dict) and isinstance(b, dict):
        if set(a) != set(b):
            return [f"{where}: keys {sorted(a)} vs {sorted(b)}"]
        return [d for k in a for d in differences(a[k], b[k], tol, f"{path}.{k}")]
    if isinstance(a, float) and isinstance(b, float):
        if _values_agree(np.asarray(a), np.asarray(b), "float64", tol):
            return []
    if type(a) is not type(b) or a != b:
        return [f"{where}: {a!r} vs {b!r}"]
    return []


def _values_agree(a: np.ndarray, b: np.ndarray, dtype: str, tol: dict) -> bool:
    if dtype in TOLERANCES:
        rule = {**TOLERANCES[dtype], **tol}
        with np.errstate(invalid="ignore"):
            return bool(np.all(np.isclose(a, b, equal_nan=True, **rule)))
    return bool(np.array_equal(a, b))


def _brief(values: np.ndarray) -> str:
    text = np.array2string(values, threshold=12, precision=8)
    return text.replace("\n", " ")


def _show(value: Any) -> str:
    if isinstance(value, Raised):
        return f"raises {value.kind} ({value.message})"
    if isinstance(value, Arr):
        return f"{value.dtype}{list(value.values.shape)} {_brief(value.values)}"
    return repr(value)


def disagreements(fn_name: str, case: Case, backends: tuple[str, ...]) -> list[str]:
    """What the backends disagree on in ``case`` (against the first backend), and any backend
    that raises where none should, or does not raise the error the case names."""
    chosen = [b for b in backends if case.backends is None or b in case.backends]
    answers = {b: run_case(fn_name, case, b) for b in chosen}
    found = []
    if case.raises is not None:
        for b, answer in answers.items():
            if not (isinstance(answer, Raised) and case.raises.__name__ in answer.kinds):
                found.append(f"{b}: {_show(answer)}, expected to raise {case.raises.__name__}")
        return found
    for b, answer in answers.items():
        if isinstance(answer, Raised):
            found.append(f"{b}: {_show(answer)}")
    if found:
        return found
    first = chosen[0]
    for b in chosen[1:]:
        for d in differences(answers[first], answers[b], case.tol):
            found.append(f"{first} vs {b}: {d}")
    return found
