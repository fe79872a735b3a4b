"""Inputs for ``scripts/profile_overhead.py``: for each core function, arrays of about 10,000
elements built from its signature (a table of parameter names, and overrides by function and by
name pattern). A function that cannot be given inputs is skipped with the reason."""

from __future__ import annotations

import dataclasses
import inspect
import re
from collections.abc import Callable
from typing import Any

import numpy as np

N_ELEMENTS = 10_000


@dataclasses.dataclass(frozen=True)
class A:
    """An array to build on each backend: ``shape``, ``dtype`` and uniform values in
    [low, high) (integers: [low, high))."""

    shape: tuple
    dtype: str = "float32"
    low: float = 0.1
    high: float = 0.9
    sort: bool = False
    spd: bool = False  # a batch of symmetric positive-definite matrices (last two axes)


SQUARE = (100, 100)  # 10,000 elements
X = A(SQUARE)
_INT = A(SQUARE, "int32", 0, 100)
_BOOL = A(SQUARE, "bool")
# Values for required parameters, by name.
BY_NAME: dict[str, Any] = {
    "x": X,
    "x1": X,
    "obj": X,
    "params": X,
    "pred": X,
    "q": A((4, 50, 50)),
    "k": A((4, 50, 50)),
    "v": A((4, 50, 50)),
    "x2": A(SQUARE, low=0.5, high=1.5),
    "target": A(SQUARE, low=0.0, high=1.0),
    "condition": A(SQUARE, "bool"),
    "arrays": [X, A(SQUARE, low=0.5, high=1.5)],
    "shape": SQUARE,
    "axes": (1, 0),
    "axis0": 0,
    "axis1": 1,
    "repeats": 2,
    "repetitions": (2, 1),
    "shift": 1,
    "depth": 10,
    "fill_value": 1.0,
    "dtype": "int32",  # astype/cast: a real conversion on every backend (no float64 on jax)
    "weight": X,
    "prob": 0.5,
}
_CONV_X = {1: A((1, 1000, 10)), 2: A((1, 32, 32, 10)), 3: A((1, 10, 10, 10, 10))}
_CONV_W = {1: A((3, 10, 10)), 2: A((3, 3, 10, 10)), 3: A((3, 3, 3, 10, 10))}
OVERRIDES: dict[str, dict[str, Any]] = {
    "acosh": {"x": A(SQUARE, low=1.1, high=2.0)},
    # Optional arguments whose defaults would make the call trivial (a copy, a view):
    "clip": {"min": 0.2, "max": 0.5},
    "squeeze": {"x": A((100, 1, 100))},
    "reshape": {"shape": (50, 200)},
    "broadcast_to": {"x": A((1, 100))},
    "cross": {"x1": A((3334, 3)), "x2": A((3334, 3), low=0.5, high=1.5)},
    "inv": {"x": A(SQUARE, low=-1.0, high=1.0)},
    "pinv": {"x": A(SQUARE, low=-1.0, high=1.0)},
    "svd": {"x": A(SQUARE, low=-1.0, high=1.0)},
    "gather_nd": {"indices": A((10_000, 2), "int32", 0, 100)},
    "scatter_nd": {
        "indices": A((10_000, 2), "int32", 0, 100),
        "updates": A((10_000,)),
        "shape": SQUARE,
    },
    "take": {"indices": A((100,), "int32", 0, 100), "axis": 0},
    "one_hot": {"indices": A((1000,), "int32", 0, 10), "depth": 10},
    "split": {"num_or_size_splits": 4},
    "arange": {"start": 0, "stop": N_ELEMENTS},
    "linspace": {"start": 0.0, "stop": 1.0, "num": N_ELEMENTS},
    "eye": {"n_rows": 100},
    "randint": {"low": 0, "high": 10, "shape": SQUARE},
    "random_uniform": {"shape": SQUARE},
    "random_normal": {"shape": SQUARE},
    "linear": {"bias": A((100,))},
    "broadcast_arrays": {"arrays": [A((1, 100)), A((100, 1))]},
    "meshgrid": {"arrays": [A((100,)), A((100,))]},
    "result_type": {"arrays_and_dtypes": [X, X]},
    "can_cast": {"from_": "int32", "to": "float32"},
    "finfo": {"type": X},
    "iinfo": {"type": _INT},
    "isdtype": {"dtype": "float32", "kind": "real floating"},
    "moveaxis": {"source": 0, "destination": 1},
    "cholesky": {"x": A(SQUARE, spd=True)},
    "constant_pad": {"pad_width": ((1, 1), (1, 1))},
    "zero_pad": {"pad_width": ((1, 1), (1, 1))},
    "einsum": {"equation": "ij,jk->ik", "operands": [X, X]},
    "fftfreq": {"n": N_ELEMENTS},
    "rfftfreq": {"n": N_ELEMENTS},
    "gather_flat": {"indices": A((N_ELEMENTS,), "int32", 0, N_ELEMENTS)},
    "scatter_flat": {
        "indices": A((N_ELEMENTS,), "int32", 0, N_ELEMENTS),
        "updates": A((N_ELEMENTS,)),
        "size": N_ELEMENTS,
    },
    "gradient_image": {"x": A((1, 50, 50, 4))},
    "bilinear_resample": {"x": A((1, 50, 50, 4)), "warp": A((1, 2500, 2), low=0.0, high=49.0)},
    "stack_images": {"images": [A((25, 25, 4))] * 4},
    "linear_resample": {"num_samples": 200},
    "matrix_power": {"n": 3},
    "outer": {"x1": A((100,)), "x2": A((100,), low=0.5, high=1.5)},
    "to_framework": {"framework": "numpy"},
    "vector_to_skew_symmetric_matrix": {"vector": A((3334, 3))},
    "searchsorted": {"x1": A((N_ELEMENTS,), sort=True), "x2": A((N_ELEMENTS,))},
    "categorical_cross_entropy": {"target": A(SQUARE, low=0.0, high=0.02)},
    "lstm_update": {
        "x": A((10, 10, 100), low=-1.0, high=1.0),
        "init_h": A((10, 25), low=-1.0, high=1.0),
        "init_c": A((10, 25), low=-1.0, high=1.0),
        "kernel": A((100, 100), low=-0.1, high=0.1),
        "recurrent_kernel": A((25, 100), low=-0.1, high=0.1),
        "bias": A((100,), low=-0.1, high=0.1),
    },
    **{
        f"conv{d}d": {"x": _CONV_X[d], "filters": _CONV_W[d], "strides": 1, "padding": "SAME"}
        for d in (1, 2, 3)
    },
    **{
        f"conv{d}d_transpose": {
            "x": _CONV_X[d],
            "filters": _CONV_W[d],
            "strides": 1,
            "padding": "SAME",
        }
        for d in (1, 2, 3)
    },
    "depthwise_conv2d": {
        "x": _CONV_X[2],
        "filters": A((3, 3, 10)),
        "strides": 1,
        "padding": "SAME",
    },
    **{
        f"{kind}_pool{d}d": {"x": _CONV_X[d], "kernel": 2, "strides": 2, "padding": "VALID"}
        for kind in ("max", "avg")
        for d in (1, 2, 3)
    },
}
# Overrides by name pattern, applied before the per-function ones.
PATTERN_OVERRIDES: list[tuple[str, dict[str, Any]]] = [
    (r"bitwise_.*", {"x": _INT, "x1": _INT, "x2": A(SQUARE, "int32", 0, 8)}),
    (r"cumulative_.*", {"axis": 1}),
    (r"unique_.*", {"x": A((N_ELEMENTS,), "int32", 0, 1000)}),
    (r"logical_.*", {"x": _BOOL, "x1": _BOOL, "x2": A(SQUARE, "bool")}),
    (r"real|imag|conj", {"x": A(SQUARE, "complex64")}),
]
HIGHER_ORDER_PARAMS = {"fn", "func", "function", "loss_fn"}


class Unbuildable(Exception):
    """No inputs can be built for a function (the reason is the message)."""


def _overrides(name: str) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for pattern, values in PATTERN_OVERRIDES:
        if re.fullmatch(pattern, name):
            out.update(values)
    out.update(OVERRIDES.get(name, {}))
    return out


def input_spec(name: str, fn: Callable) -> tuple[list, dict]:
    """(positional specs, keyword specs) for ``fn`` from its signature and the tables above."""
    params = [p for p in inspect.signature(fn).parameters.values() if p.name != "f"]
    override = _overrides(name)
    for p in params:
        if p.name in HIGHER_ORDER_PARAMS and p.default is p.empty:
            raise Unbuildable(f"takes a function ({p.name}): higher-order, not timed per call")
    args: list = []
    kwargs: dict = {}
    gap = False  # a positional parameter was left to its default: later ones go by keyword
    for i, p in enumerate(params):
        if p.kind is p.VAR_KEYWORD:
            continue
        if p.name in override:
            value = override[p.name]
        elif p.kind is p.VAR_POSITIONAL:
            if p.name not in BY_NAME:
                raise Unbuildable(f"no input rule for *{p.name} (add one to OVERRIDES)")
            value = BY_NAME[p.name]
        elif p.default is p.empty:
            if p.name not in BY_NAME:
                raise Unbuildable(
                    f"no input rule for required parameter {p.name!r} (add one to OVERRIDES)"
                )
            value = BY_NAME[p.name]
        elif p.kind is p.POSITIONAL_ONLY and any(q.name in override for q in params[i + 1 :]):
            value = p.default  # a later positional-only parameter is given
        else:
            gap = gap or p.kind is p.POSITIONAL_OR_KEYWORD
            continue
        if p.kind is p.VAR_POSITIONAL:
            args.extend(value)
        elif p.kind is p.POSITIONAL_ONLY or (
            p.kind is p.POSITIONAL_OR_KEYWORD and not kwargs and not gap
        ):
            args.append(value)
        else:
            kwargs[p.name] = value
    return args, kwargs


def materialize(spec: Any, ns: Any, rng: np.random.Generator) -> Any:
    """Arrays of backend ``ns`` for the ``A`` leaves of ``spec`` (lists, tuples, dicts kept)."""
    if isinstance(spec, A):
        if spec.dtype == "bool":
            value = rng.random(spec.shape) < 0.5
        elif spec.dtype.startswith("complex"):
            shape = spec.shape
            value = rng.uniform(spec.low, spec.high, shape) + 1j * rng.uniform(0, 1, shape)
            value = value.astype(spec.dtype)
        elif spec.dtype.startswith("int"):
            value = rng.integers(int(spec.low), int(spec.high), spec.shape, dtype=spec.dtype)
        else:
            value = rng.uniform(spec.low, spec.high, spec.shape).astype(spec.dtype)
            if spec.spd:
                n = spec.shape[-1]
                value = (value @ np.swapaxes(value, -1, -2) / n + np.eye(n)).astype(spec.dtype)
        return ns.asarray(np.sort(value, axis=None).reshape(spec.shape) if spec.sort else value)
    if isinstance(spec, list):
        return [materialize(s, ns, rng) for s in spec]
    if isinstance(spec, tuple):
        return tuple(materialize(s, ns, rng) for s in spec)
    if isinstance(spec, dict):
        return {k: materialize(s, ns, rng) for k, s in spec.items()}
    return spec
