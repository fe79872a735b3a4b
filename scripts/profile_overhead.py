"""Runtime overhead of ivy's abstraction per function and backend, split into the paper's three
groups (backend, Ivy compilable, Ivy eager), measured without rewriting any source.

Usage:
    .venv/bin/python scripts/profile_overhead.py [--functions sin,clip,lstm_update]
        [--backends numpy,torch,jax,tensorflow] [--out DIR] [--library euler_to_rot_mat]
        [--repeats 7] [--sample-ms 2] [--compiled all|compositions|none]
        [--torch-compile all|compositions|none] [--threads 1] [--clock cpu|wall]

What is measured
----------------
Every function that ivy's core declares (``ivy.core._dispatch.DISPATCHED`` and ``COMPOSITIONS``,
discovered at run time) and a few functions of the applied libraries (``library_cases()``:
``ivy_mechanics.euler_to_rot_mat`` on 10,000 rotations, ...), on every selected backend, with
inputs of about 10,000 elements (float32 unless the function needs otherwise) on the CPU. Inputs
are built from each function's signature (a table of parameter names, and short tables of
overrides by function and by name pattern); a function that cannot be given inputs, or that
raises, is listed as skipped with the reason, as are aliases (the same object under another
name) and higher-order functions (``grad``, ``compile_fn``, ...).

For each function ``fn`` and backend ``b`` it times, interleaved sample by sample:

1. ``native``: the native call(s) that implement ``fn`` (see below);
2. ``ivy.<b>.fn``: the backend function;
3. ``ivy.fn`` with the framework inferred from the inputs (functions with no array input cannot
   infer: there ``ivy.fn(..., f=b)`` stands for it);
4. ``ivy.fn(..., f=b)``;
5. ``ivy.fn`` after ``ivy.set_framework(b)`` (``ivy.fn`` is then ``ivy.<b>.fn`` itself);
6. ``ops``: the native calls that ``ivy.<b>.fn`` makes, replayed without ivy around them, and
   ``primary`` (jax only, see below);
7. compiled: ``ivy.compile_fn`` of a function calling ``ivy.fn`` against the framework's own
   compiler (``jax.jit``, ``tf.function(autograph=False)``, ``torch.compile``) applied to the
   native version. numpy has no compiler; torch.compile takes seconds per function, so by
   default only compositions and library functions are compiled on torch.

Which native calls implement a function (no source is rewritten, so it stays true as the code
changes):

- ``ivy.<b>.fn`` is the framework's own object (``ivy.torch.sin is torch.sin``): native is that
  object. ``ivy.<b>.fn`` then adds nothing, and its two timings measure the noise.
- ``ivy.<b>.fn`` is a shim: it is run once under the framework's own interception
  (``scripts/_native_trace.py``), which lists the native calls it makes with their arguments:
  torch ``TorchFunctionMode`` (torch functions, Tensor methods and operators, outermost calls
  only); numpy ``__array_function__``/``__array_ufunc__`` of an ndarray subclass (numpy
  functions, ufuncs, operators, a few methods); tensorflow and jax ``sys.setprofile`` call
  events (the framework's public Python functions that ivy's code calls: ``tf.reduce_mean``,
  ``jnp.zeros``), plus each framework's op-level record (tf op callbacks, jax ``make_jaxpr``),
  which can be replayed inside a compiler. The *primary* calls are those named like the function
  (after normalising case, underscores, ``reduce_``/``V2``, and a short table of synonyms: clip
  ~ clamp, concat ~ cat, ...); native = the primary calls replayed on their recorded arguments.
  The other calls are the wrapper's extra ops (Ivy compilable). Where no call is named like the
  function, every call is primary: nothing is attributed to Ivy compilable (a conservative
  choice; the CSV says ``primary_matched=False`` and the summary lists these rows).
- compositions and library functions: a hand-written native version where one is listed here
  (``HANDWRITTEN``: ``torch.softmax``, ``jax.nn.sigmoid``, a plain LSTM loop, ...; library:
  Euler angles and quaternions to matrices); other compositions: the native calls they make,
  replayed (the same computation, written natively as a straight line).

The three groups partition the eager time of ``ivy.fn`` (framework inferred), "total":

- backend = native;
- Ivy compilable = ops - primary: the extra native calls the wrapper makes (a cast, a transpose,
  the ``where`` around torch's ``sign`` that fixes NaN), which would stay in a compiled graph; for
  compositions with a hand-written version, what ivy's native calls cost beyond it; 0 where
  ``ivy.<b>.fn`` is the native object;
- Ivy eager = total - backend - Ivy compilable: Python work that compilation removes (dispatch,
  type inference, dtype and shape lookups, argument conversion).

Negative differences (noise, or ivy faster than the reference) are clipped to 0 in the groups and
kept, signed, in the overheads:

- eager overhead % = (total - native) / native;
- compiled overhead % = (compiled ivy - compiled native) / compiled native where both were
  compiled (``compiled_source=measured``; it includes what ``ivy.compile_fn`` adds per call,
  e.g. jax's PRNG key threading), else Ivy compilable / backend (``estimated``: what would remain
  if compilation removed exactly the Python work).

Noise and caveats
-----------------
- Times are CPU time of this process (``--clock cpu``, ``time.process_time``) with one intra-op
  thread per framework (``--threads 1``): on a busy shared machine, wall time mostly measures the
  other processes (medians off by 5x on a 2-core machine at load 12), while CPU time of a
  single-threaded call is what the call costs. ``--clock wall`` measures elapsed time instead.
- Each variant gets ``--repeats`` samples of ``number`` calls (about ``--sample-ms`` per sample),
  the variants taking turns in a shuffled order; medians are reported. ``noise_pct`` is the
  largest interquartile range among a row's variants relative to its median; ``same_object_pct``
  compares the two timings of one object (native and ``ivy.<b>.fn`` where they are the same),
  the spread of identical calls. Differences of a few percent, or below a microsecond, are noise.
- jax dispatches asynchronously: every jax call is followed by ``jax.block_until_ready``.
- Replays: one call is made directly on its recorded arguments; several run as generated
  straight-line code in which each call reads the outputs of earlier ones (as hand-written code
  would, data staying as hot in the caches as in the original call).
- jax's jitted ``jax.numpy`` functions are C++ objects that raise no Python call event, so where
  no Python-level jax function named like the function is called, native is the primary jaxpr
  equations, each replayed as a ``jax.jit`` of that equation (how ``jax.numpy`` runs eagerly);
  Python that such a function runs before dispatching then lands in Ivy eager. jax's ``ops`` and
  ``primary`` are always jaxpr equations, so a ``jax.numpy`` call that lowers to several
  equations is replayed as several dispatches.
- numpy's recorder does not see numpy calls on plain arrays (after ``np.asarray`` inside a
  shim). When the result comes from such calls ("trace incomplete" in the row's note), native is
  the numpy functions written in Python that are named like the function (``np.linalg.inv``,
  ``np.fft.fft``, seen through ``sys.setprofile``), else all of ``ivy.<b>.fn`` counts as backend
  (``native_source=untraced``): such rows show only dispatch as overhead.
- A single function's compiled comparison measures mostly the compiler's call overhead (about
  200 us for ``tf.function`` here), so its percentages are small differences of large, noisy
  numbers; compositions and library functions are where the compiled comparison matters.

Outputs in ``--out`` (default ``profile_overhead_out``): ``overhead.csv`` (one row per function and
backend, skipped ones included with the reason), ``overhead.png`` (per function, averaged over
backends, cumulative bars on a log scale coloured by group, as the paper's figure) and
``summary.md`` (the printed summary: per backend the median overheads in eager and compiled mode
and the functions with the largest overhead; compositions and library functions against
hand-written native code; the skipped functions).
"""

from __future__ import annotations

import argparse
import csv
import dataclasses
import inspect
import math
import os
import re
import statistics
import sys
import time
import timeit
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Any


def _thread_env(threads: int) -> None:
    """Intra-op threads of every framework, through the variables they read when they load."""
    if threads <= 0:
        return
    n = str(threads)
    for var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
        os.environ.setdefault(var, n)
    os.environ.setdefault("TF_NUM_INTRAOP_THREADS", n)
    os.environ.setdefault("TF_NUM_INTEROP_THREADS", n)
    flags = os.environ.get("XLA_FLAGS", "")
    if "intra_op_parallelism_threads" not in flags:
        os.environ["XLA_FLAGS"] = (
            f"{flags} --xla_cpu_multi_thread_eigen=false intra_op_parallelism_threads={n}"
        ).strip()


if __name__ == "__main__":  # before numpy (BLAS) and the frameworks are imported
    _argv = sys.argv[1:]
    _threads = next(
        (v for a, v in zip(_argv, [*_argv[1:], ""]) if a == "--threads"),
        next((a.split("=", 1)[1] for a in _argv if a.startswith("--threads=")), "1"),
    )
    _thread_env(int(_threads) if _threads.lstrip("-").isdigit() else 1)

_HERE = Path(__file__).resolve().parent
for _path in (_HERE, _HERE.parent / "benchmarks", _HERE.parent):
    if str(_path) not in sys.path:
        sys.path.insert(0, str(_path))

import numpy as np  # noqa: E402
from _native_trace import (  # noqa: E402
    Op,
    Trace,
    api_calls,
    as_array_function,
    flatten_arrays,
    program,
)
from _native_trace import trace as trace_native  # noqa: E402
from _timing import (  # noqa: E402
    calls_per_sample,
    interleaved_samples,
    median,
    relative_spread,
)

import ivy  # noqa: E402

BACKENDS = ("numpy", "torch", "jax", "tensorflow")
COMPILERS = ("torch", "jax", "tensorflow")
N_ELEMENTS = 10_000
GROUPS = ("backend", "Ivy compilable", "Ivy eager")
GROUP_COLOURS = {"backend": "#4c72b0", "Ivy compilable": "#dd8452", "Ivy eager": "#55a868"}

# ----------------------------------------------------------------------------------------------
# Inputs: from the signature, by parameter name, with per-function overrides
# ----------------------------------------------------------------------------------------------


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


# ----------------------------------------------------------------------------------------------
# Hand-written native versions (compositions and library functions)
# ----------------------------------------------------------------------------------------------


def _native_module(backend: str):
    if backend == "numpy":
        return np
    if backend == "torch":
        import torch

        return torch
    if backend == "jax":
        import jax.numpy as jnp

        return jnp
    import tensorflow as tf

    return tf


def _native_sigmoid(backend: str):
    if backend == "torch":
        import torch

        return torch.sigmoid
    if backend == "jax":
        import jax

        return jax.nn.sigmoid
    if backend == "tensorflow":
        import tensorflow as tf

        return tf.sigmoid
    return lambda z: 0.5 * (np.tanh(0.5 * z) + 1.0)


def _native_softmax(backend: str):
    if backend == "torch":
        import torch

        return lambda x: torch.softmax(x, -1)
    if backend == "jax":
        import jax

        return jax.nn.softmax
    if backend == "tensorflow":
        import tensorflow as tf

        return tf.nn.softmax

    def softmax(x):
        e = np.exp(x - x.max(-1, keepdims=True))
        return e / e.sum(-1, keepdims=True)

    return softmax


def _native_split_unstack(backend: str) -> tuple[Callable, Callable]:
    """The framework's own ``split(z, n, axis)`` into n equal pieces and ``unstack(x, axis)``."""
    if backend == "torch":
        import torch

        return (lambda z, n, axis: torch.chunk(z, n, dim=axis)), (
            lambda x, axis: torch.unbind(x, dim=axis)
        )
    if backend == "jax":
        import jax.numpy as jnp

        return (lambda z, n, axis: jnp.split(z, n, axis=axis)), (
            lambda x, axis: jnp.unstack(x, axis=axis)
        )
    if backend == "tensorflow":
        import tensorflow as tf

        return (lambda z, n, axis: tf.split(z, n, axis=axis)), (
            lambda x, axis: tf.unstack(x, axis=axis)
        )
    return (lambda z, n, axis: np.split(z, n, axis=axis)), (
        lambda x, axis: list(np.moveaxis(x, axis, 0))
    )


def _native_lstm(backend: str):
    """A plain LSTM loop with the framework's own functions (gates i, f, g, o)."""
    m, sig = _native_module(backend), _native_sigmoid(backend)
    split, unstack = _native_split_unstack(backend)

    def lstm(x, init_h, init_c, kernel, recurrent_kernel, bias=None, recurrent_bias=None):
        projected = m.matmul(x, kernel)
        if bias is not None:
            projected = projected + bias
        if recurrent_bias is not None:
            projected = projected + recurrent_bias
        h, c, hs = init_h, init_c, []
        for x_t in unstack(projected, -2):
            i, f_, g, o = split(x_t + m.matmul(h, recurrent_kernel), 4, -1)
            c = sig(f_) * c + sig(i) * m.tanh(g)
            h = sig(o) * m.tanh(c)
            hs.append(h)
        return m.stack(hs, -2), (h, c)

    return lstm


def _native_layer_norm(backend: str):
    if backend == "torch":
        import torch

        return lambda x: torch.nn.functional.layer_norm(x, x.shape[-1:], eps=1e-5)
    if backend == "tensorflow":
        import tensorflow as tf

        def layer_norm(x):
            mean, var = tf.nn.moments(x, axes=[-1], keepdims=True)
            return (x - mean) * tf.math.rsqrt(var + 1e-5)

        return layer_norm
    m = _native_module(backend)

    def layer_norm(x):
        mean = m.mean(x, -1, keepdims=True)
        centred = x - mean
        return centred / m.sqrt(m.mean(centred * centred, -1, keepdims=True) + 1e-5)

    return layer_norm


def _native_linear(backend: str):
    if backend == "torch":
        import torch

        return torch.nn.functional.linear
    if backend == "tensorflow":
        import tensorflow as tf

        return lambda x, w, b=None: tf.matmul(x, w, transpose_b=True) + b
    m = _native_module(backend)
    return lambda x, w, b=None: m.matmul(x, m.swapaxes(w, 0, 1)) + b


def _native_attention(backend: str):
    if backend == "torch":
        import torch

        return torch.nn.functional.scaled_dot_product_attention
    m, softmax = _native_module(backend), _native_softmax(backend)
    if backend == "tensorflow":
        import tensorflow as tf

        def attention(q, k, v):
            s = tf.matmul(q, k, transpose_b=True) * (1.0 / math.sqrt(q.shape[-1]))
            return tf.matmul(softmax(s), v)

        return attention

    def attention(q, k, v):
        s = m.matmul(q, m.swapaxes(k, -1, -2)) * (1.0 / math.sqrt(q.shape[-1]))
        return m.matmul(softmax(s), v)

    return attention


def _native_relu(backend: str):
    if backend == "torch":
        import torch

        return torch.relu
    if backend == "jax":
        import jax

        return jax.nn.relu
    if backend == "tensorflow":
        import tensorflow as tf

        return tf.nn.relu
    return lambda x: np.maximum(x, 0)


# Composition name -> backend -> native callable with the composition's arguments (minus f).
HANDWRITTEN: dict[str, Callable[[str], Callable]] = {
    "lstm_update": _native_lstm,
    "softmax": _native_softmax,
    "sigmoid": _native_sigmoid,
    "relu": _native_relu,
    "layer_norm": _native_layer_norm,
    "linear": _native_linear,
    "scaled_dot_product_attention": _native_attention,
}


def _euler_zyx_native(backend: str):
    """Extrinsic 'zyx' Euler angles (a about z, then b about y, then c about x) to matrices,
    R = Rx(c) Ry(b) Rz(a), written with the framework's own functions."""
    m = _native_module(backend)
    unstack = _native_split_unstack(backend)[1]

    def euler_to_rot_mat(e):
        a, b, c = unstack(e, -1)
        ca, sa, cb, sb, cc, sc = m.cos(a), m.sin(a), m.cos(b), m.sin(b), m.cos(c), m.sin(c)
        rows = [
            m.stack([cb * ca, -cb * sa, sb], -1),
            m.stack([cc * sa + sc * sb * ca, cc * ca - sc * sb * sa, -sc * cb], -1),
            m.stack([sc * sa - cc * sb * ca, sc * ca + cc * sb * sa, cc * cb], -1),
        ]
        return m.stack(rows, -2)

    return euler_to_rot_mat


def _quat_to_rot_mat_native(backend: str):
    """Quaternions [x, y, z, w] to rotation matrices (normalised first, as ivy_mechanics and
    scipy do), with the framework's functions."""
    m = _native_module(backend)
    unstack = _native_split_unstack(backend)[1]

    def quaternion_to_rot_mat(q):
        x, y, z, w = unstack(q, -1)
        s = 2.0 / (x * x + y * y + z * z + w * w)
        rows = [
            m.stack([1 - s * (y * y + z * z), s * (x * y - z * w), s * (x * z + y * w)], -1),
            m.stack([s * (x * y + z * w), 1 - s * (x * x + z * z), s * (y * z - x * w)], -1),
            m.stack([s * (x * z - y * w), s * (y * z + x * w), 1 - s * (x * x + y * y)], -1),
        ]
        return m.stack(rows, -2)

    return quaternion_to_rot_mat


def _unit_quaternions(shape: tuple) -> Callable:
    def build(ns, rng):
        q = rng.normal(size=shape).astype("float32")
        return ns.asarray(q / np.linalg.norm(q, axis=-1, keepdims=True))

    return build


@dataclasses.dataclass
class LibraryCase:
    name: str
    function: Callable  # framework-agnostic, takes f=
    inputs: Callable  # (ns, rng) -> the array argument
    native: Callable[[str], Callable]  # backend -> native callable of the same argument


def library_cases() -> dict[str, LibraryCase]:
    import ivy_mechanics as mech

    angles = A((N_ELEMENTS, 3), low=-math.pi, high=math.pi)
    return {
        "euler_to_rot_mat": LibraryCase(
            "ivy_mechanics.euler_to_rot_mat",
            lambda e, f=None: mech.euler_to_rot_mat(e, "zyx", f=f),
            lambda ns, rng: materialize(angles, ns, rng),
            _euler_zyx_native,
        ),
        "quaternion_to_rot_mat": LibraryCase(
            "ivy_mechanics.quaternion_to_rot_mat",
            lambda q, f=None: mech.quaternion_to_rot_mat(q, f=f),
            _unit_quaternions((N_ELEMENTS, 4)),
            _quat_to_rot_mat_native,
        ),
    }


# ----------------------------------------------------------------------------------------------
# Which traced ops implement a function
# ----------------------------------------------------------------------------------------------

_SYNONYMS = {
    "add": "addv2 iadd radd",
    "subtract": "sub rsub isub",
    "multiply": "mul rmul imul",
    "divide": "div truediv realdiv rtruediv truedivide",
    "floor_divide": "floordiv rfloordiv",
    "remainder": "mod floormod fmod rem",
    "pow": "power rpow",
    "negative": "neg",
    "positive": "pos identity",
    "equal": "eq",
    "not_equal": "ne",
    "greater": "gt",
    "greater_equal": "ge",
    "less": "lt",
    "less_equal": "le",
    "abs": "absolute",
    "acos": "arccos",
    "asin": "arcsin",
    "atan": "arctan",
    "atan2": "arctan2",
    "acosh": "arccosh",
    "asinh": "arcsinh",
    "atanh": "arctanh",
    "sign": "sgn",
    "round": "rint",
    "clip": "clamp clipbyvalue maximum minimum",
    "concat": "concatenate cat",
    "permute_dims": "transpose permute",
    "transpose": "permute",
    "swapaxes": "transpose swapdims permute",
    "expand_dims": "unsqueeze",
    "flip": "reverse",
    "stack": "pack",
    "unstack": "unbind unpack",
    "split": "splitv splitwithsizes tensorsplit arraysplit",
    "broadcast_to": "expand broadcastindim",
    "repeat": "repeatinterleave",
    "tile": "repeat",
    "max": "amax maximumreduce",
    "min": "amin minimumreduce",
    "sum": "addreduce",
    "prod": "multiplyreduce",
    "astype": "cast to convertelementtype type",
    "cast": "to convertelementtype type",
    "reshape": "view",
    "matmul": "batchmatmul dotgeneral dot mm bmm",
    "where": "select selectn",
    "take": "gather indexselect",
    "scatter_nd": "tensorscatteradd scatter scatteradd indexput",
    "inv": "matrixinverse linalginv",
    "pinv": "linalgpinv",
    "svd": "linalgsvd",
    "norm": "linalgvectornorm euclideannorm",
    "vector_norm": "linalgvectornorm norm",
    "cross": "linalgcross",
    "to_list": "tolist",
    "to_numpy": "numpy asarray",
    "std": "reducestd",
    "var": "reducevariance",
    "random_uniform": "uniform randomuniform rand",
    "random_normal": "normal randomstandardnormal randn",
    "randint": "randomuniformint",
    "shuffle": "randomshuffle randperm permutation",
    "stop_gradient": "detach",
    "full": "fill",
    "arange": "range",
    "one_hot": "onehot",
}
for _d in (1, 2, 3):
    _SYNONYMS[f"conv{_d}d"] = "convolution convgeneraldilated conv"
    _SYNONYMS[f"conv{_d}d_transpose"] = "convtranspose convolution convgeneraldilated conv"
    _SYNONYMS[f"max_pool{_d}d"] = "maxpool reducewindowmax reducewindow"
    _SYNONYMS[f"avg_pool{_d}d"] = "avgpool reducewindowsum reducewindow"
_SYNONYMS["depthwise_conv2d"] = "depthwiseconv2dnative convgeneraldilated conv2d convolution"


def _norm(name: str) -> str:
    name = name.split(":")[-1].lower()
    name = re.sub(r"[^a-z0-9]", "", name)
    name = re.sub(r"v[23]$", "", name)
    return name[6:] if name.startswith("reduce") and len(name) > 6 else name


def _matches(fn_name: str, native_name: str) -> bool:
    """Whether a native function or op called ``native_name`` implements ``fn_name``."""
    target, n = _norm(fn_name), _norm(native_name)
    if n == target or n in {_norm(s) for s in _SYNONYMS.get(fn_name, "").split()}:
        return True
    return min(len(n), len(target)) >= 4 and (target in n or n in target)


def primary_ops(fn_name: str, ops: list[Op]) -> tuple[list[Op], bool]:
    """(the ops that implement ``fn_name``, whether any op was recognised by its name)."""
    found = [op for op in ops if _matches(fn_name, op.match_name)]
    if found:
        return found, True
    return list(ops), len(ops) == 1


# ----------------------------------------------------------------------------------------------
# Measurement
# ----------------------------------------------------------------------------------------------


@dataclasses.dataclass
class Config:
    repeats: int = 7
    sample_s: float = 0.002
    compiled: str = "all"  # which rows get compiled timings: all | compositions | none
    torch_compile: str = "compositions"
    seed: int = 0
    clock: Callable[[], float] = time.process_time


@dataclasses.dataclass
class Entry:
    name: str  # the function's name in ivy (or the library case's display name)
    kind: str  # function | composition | library
    agnostic: Callable  # the framework-agnostic function (takes f=)
    stmt: str  # how the agnostic function is reached in a timed statement ("ivy.sin", "g")
    library: LibraryCase | None = None


FIELDS = (
    "kind function backend status reason native_source native_ops ivy_ops primary_matched "
    "number repeats native_us primary_us ops_us backend_fn_us inferred_us f_us set_us "
    "compiled_ivy_us "
    "compiled_native_us compile_s total_us backend_us ivy_compilable_us ivy_eager_us "
    "eager_overhead_pct compiled_overhead_pct compiled_source noise_pct same_object_pct wall_s note"
).split()


def _is_native_object(obj: Any) -> bool:
    module = getattr(obj, "__module__", None) or getattr(type(obj), "__module__", "")
    return not str(module).startswith(("ivy", "scripts", "_native_trace"))


def _sync_for(backend: str) -> Callable:
    if backend != "jax":
        return lambda out: out
    import jax

    def sync(out):
        try:
            return jax.block_until_ready(out)
        except Exception:  # non-array outputs (shapes, dtypes)
            return out

    return sync


def _compiler(backend: str) -> Callable[[Callable], Callable]:
    if backend == "jax":
        import jax

        return jax.jit
    if backend == "tensorflow":
        import tensorflow as tf

        return lambda fn: tf.function(fn, autograph=False)
    if backend == "torch":
        import torch

        return torch.compile
    raise ValueError(f"{backend} has no compiler")


def _wants_compiled(entry: Entry, backend: str, cfg: Config) -> bool:
    if backend not in COMPILERS or cfg.compiled == "none":
        return False
    if cfg.compiled == "compositions" and entry.kind == "function":
        return False
    if backend == "torch":
        return cfg.torch_compile == "all" or (
            cfg.torch_compile == "compositions" and entry.kind != "function"
        )
    return True


def _us(seconds: float) -> float:
    return seconds * 1e6


def _fmt_ops(ops: list[Op]) -> str:
    return " ".join(op.name for op in ops)


def measure(entry: Entry, backend: str, cfg: Config, rng: np.random.Generator) -> dict:
    """One CSV row: the timings of ``entry`` on ``backend`` and the groups derived from them."""
    row: dict[str, Any] = {"kind": entry.kind, "function": entry.name, "backend": backend}
    ns = ivy.get_framework(f=backend)
    notes: list[str] = []
    # -- inputs and the calls ------------------------------------------------------------------
    if entry.library is not None:
        args, kwargs = (entry.library.inputs(ns, rng),), {}
        backend_fn = None
    else:
        pos, kw = input_spec(entry.name, entry.agnostic)
        args, kwargs = materialize(tuple(pos), ns, rng), materialize(kw, ns, rng)
        backend_fn = getattr(ns, entry.name)
    agnostic = entry.agnostic
    direct = backend_fn if backend_fn is not None else (lambda *a, **k: agnostic(*a, f=ns, **k))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        reference = direct(*args, **kwargs)
        try:
            agnostic(*args, **kwargs)
            inferable = True
        except ivy.errors.NoFrameworkError:
            inferable = False
            notes.append("no array input to infer from: total = f=")
    # -- the native reference ------------------------------------------------------------------
    nat = _native_reference(entry, backend, backend_fn, direct, args, kwargs, reference, notes)
    row.update(
        native_source=nat.source,
        native_ops=nat.names,
        ivy_ops=nat.ivy_ops,
        primary_matched=nat.matched,
    )
    # -- timers ------------------------------------------------------------------------------
    env: dict[str, Any] = {
        "ivy": ivy,
        "ns": ns,
        "g": agnostic,
        "d": direct,
        "a": args,
        "k": kwargs,
        "b": backend,
        "sync": _sync_for(backend),
    }
    env["nc"], env["na"], env["nk"] = nat.call
    stmts = {"native": "sync(nc(*na, **nk))"}
    if nat.primary is not None:
        env["pc"], env["pa"], env["pk"] = nat.primary
        stmts["primary"] = "sync(pc(*pa, **pk))"
    if nat.ops is not None:
        env["rc"], env["ra"], env["rk"] = nat.ops
        stmts["ops"] = "sync(rc(*ra, **rk))"
    target = entry.stmt
    if backend_fn is not None:
        stmts["backend_fn"] = f"sync(ns.{entry.name}(*a, **k))"
    else:
        stmts["backend_fn"] = "sync(d(*a, **k))"
    if inferable:
        stmts["inferred"] = f"sync({target}(*a, **k))"
    stmts["f"] = f"sync({target}(*a, f=b, **k))"
    stmts["set"] = f"sync({target}(*a, **k))"
    compile_s = float("nan")
    if _wants_compiled(entry, backend, cfg):
        try:
            compile_s = _add_compiled(entry, backend, args, kwargs, nat.program, env, stmts)
        except Exception as error:
            notes.append(f"compiled timing failed ({type(error).__name__}: {str(error)[:80]})")
            stmts.pop("compiled_ivy", None)
            stmts.pop("compiled_native", None)
    timers = {v: timeit.Timer(s, globals=env, timer=cfg.clock) for v, s in stmts.items()}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for variant, timer in timers.items():  # warm-up (caches, lazy initialisation)
            if variant == "set":
                with ivy.set_framework(backend):
                    timer.timeit(1)
            else:
                timer.timeit(1)
        number = calls_per_sample(timers["backend_fn"], target_s=cfg.sample_s)
        samples = interleaved_samples(
            timers,
            number,
            cfg.repeats,
            around={"set": lambda: ivy.set_framework(backend)},
            seed=cfg.seed,
        )
    med = {v: median(s) for v, s in samples.items()}
    row.update(number=number, repeats=cfg.repeats, compile_s=compile_s)
    for variant in VARIANTS:
        row[f"{variant}_us"] = _us(med[variant]) if variant in med else float("nan")
    row["noise_pct"] = 100 * max(relative_spread(s) for s in samples.values())
    row["same_object_pct"] = (
        100 * (med["backend_fn"] - med["native"]) / med["native"]
        if nat.source == "native object"
        else math.nan
    )
    _groups(row)
    row["status"], row["reason"], row["note"] = "ok", "", "; ".join(notes)
    return row


VARIANTS = (
    "native",
    "primary",
    "ops",
    "backend_fn",
    "inferred",
    "f",
    "set",
    "compiled_ivy",
    "compiled_native",
)


@dataclasses.dataclass
class Native:
    call: tuple  # (c, a, k): the native reference, timed as c(*a, **k)
    source: str
    names: str
    ivy_ops: str = ""
    matched: bool = True
    primary: tuple | None = None  # the primary ops, op level (when native is API level)
    ops: tuple | None = None  # every compute op of ivy's call, op level
    program: tuple | None = None  # (fn, arrays) for the native compiler


def _native_reference(entry, backend, backend_fn, direct, args, kwargs, reference, notes):
    """How ``entry`` runs natively on ``backend`` (see the module docstring)."""
    if backend_fn is not None and _is_native_object(backend_fn):
        return Native(
            (backend_fn, args, kwargs),
            "native object",
            getattr(backend_fn, "__qualname__", repr(backend_fn)),
            getattr(backend_fn, "__qualname__", repr(backend_fn)),
            program=as_array_function(backend, backend_fn, args, kwargs),
        )
    tr: Trace | None = None
    compute: list[Op] = []
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            tr, _ = trace_native(backend, direct, args, kwargs)
        compute = [op for op in tr.ops if op.compute]
    except Exception as error:  # e.g. make_jaxpr of a function returning a dtype
        notes.append(f"trace failed ({type(error).__name__}: {str(error)[:80]})")
    if tr is not None and tr.incomplete:
        notes.append(
            "trace incomplete: numpy calls on plain arrays (after np.asarray) are not seen; "
            "native = numpy's Python functions named like the function, if any"
        )
        compute = []
    ops = _replay(tr, compute) if compute else None
    ivy_ops = _fmt_ops(compute)
    # tf and jax: the framework's public Python functions that ivy's code calls (tf.reduce_mean,
    # jnp.zeros), the level at which a user writes native code. Complete for tf, whose public
    # functions are Python; jax's jitted functions are C++ objects that this does not see.
    api: list = []
    incomplete = tr is not None and tr.incomplete
    if backend in ("jax", "tensorflow") or incomplete:
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                calls = api_calls(backend, direct, args, kwargs)
        except Exception:
            calls = None
        api = [c for c in calls or () if flatten_arrays(backend, c.output)]
    if backend == "tensorflow" and api:
        ops = _api_replay(api)
        ivy_ops = " ".join(c.qualname.rsplit(".", 1)[-1] for c in api)
    handwritten = None
    if entry.library is not None:
        handwritten = entry.library.native(backend)
    elif entry.name in HANDWRITTEN:
        handwritten = HANDWRITTEN[entry.name](backend)
    if handwritten is not None:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            expected = handwritten(*args, **kwargs)
        if not _close(backend, expected, reference):
            notes.append("hand-written native differs from ivy's result")
        return Native(
            (handwritten, args, kwargs),
            "hand-written",
            getattr(handwritten, "__qualname__", "hand-written"),
            ivy_ops,
            ops=ops,
            program=as_array_function(backend, handwritten, args, kwargs),
        )
    named = [c for c in api if _matches(entry.name, c.name)]
    if not compute:
        if incomplete and named and entry.kind == "function":  # numpy functions in Python
            names = " ".join(c.qualname for c in named)
            return Native(_api_replay(named), "API call", names, names, program=None)
        notes.append("no native op recorded: ivy.<b>.fn counted as backend")
        return Native((direct, args, kwargs), "untraced", "", "")
    if entry.kind != "function":  # a composition: the native calls it makes, as they are
        program_ = program(tr, compute) if all(op.graph_ok for op in compute) else None
        return Native(ops, "traced ops (all)", ivy_ops, ivy_ops, program=program_)
    chosen, matched = primary_ops(entry.name, compute)
    primary = _replay(tr, chosen)
    program_ = program(tr, chosen) if all(op.graph_ok for op in chosen) else None
    native = Native(primary, "traced ops", _fmt_ops(chosen), ivy_ops, matched, None, ops, program_)
    if not named and backend == "tensorflow" and not _matched_by_name(entry.name, chosen):
        named = api  # nothing named like the function at either level: all of it is native
    if named:
        native.call = _api_replay(named)
        native.source = "API call"
        native.names = " ".join(c.qualname for c in named)
        native.matched = any(_matches(entry.name, c.name) for c in named)
        if backend == "jax":  # ops are jaxpr equations: extra ops = ops - primary equations
            native.primary = primary
    return native


def _matched_by_name(name: str, ops: list[Op]) -> bool:
    return any(_matches(name, op.match_name) for op in ops)


def _api_replay(calls) -> tuple[Callable, tuple, dict]:
    if len(calls) == 1:
        return calls[0].func, calls[0].args, calls[0].kwargs
    bound = [(c.func, c.args, c.kwargs) for c in calls]

    def replay():
        return [fn(*a, **k) for fn, a, k in bound]

    return replay, (), {}


def _replay(tr: Trace, ops: list[Op]) -> tuple[Callable, tuple, dict]:
    """``(c, a, k)``: ``c(*a, **k)`` runs the ops eagerly; one op is called directly on its
    recorded arguments, several as generated straight-line code (see ``program``)."""
    if len(ops) == 1:
        return ops[0].call, ops[0].concrete_args, ops[0].concrete_kwargs
    fn, arrays = program(tr, ops)
    return fn, tuple(arrays), {}


def _close(backend: str, a: Any, b: Any) -> bool:
    try:
        xs, ys = flatten_arrays(backend, a), flatten_arrays(backend, b)
        if len(xs) != len(ys):
            return False
        for x, y in zip(xs, ys):
            x = np.asarray(ivy.to_numpy(x), dtype=np.float64)
            y = np.asarray(ivy.to_numpy(y), dtype=np.float64)
            if x.shape != y.shape or not np.allclose(x, y, rtol=1e-3, atol=1e-4):
                return False
        return True
    except Exception:
        return False


def _add_compiled(entry, backend, args, kwargs, native_program, env, stmts) -> float:
    """Compile ivy's and the native version, run each once (which compiles it), and add their
    timed statements. Returns the seconds the two first calls took."""
    if native_program is None:
        raise RuntimeError("no native version that the compiler can trace")
    agnostic = entry.agnostic
    ivy_fn, ivy_arrays = as_array_function(backend, agnostic, args, kwargs)
    native_fn, native_arrays = native_program
    if backend == "torch":
        import torch

        torch._dynamo.reset()  # compiled code is cached per code object, shared by every row
    start = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        compiled_ivy = ivy.compile_fn(ivy_fn)
        compiled_native = _compiler(backend)(native_fn)
        env["sync"](compiled_ivy(*ivy_arrays))
        env["sync"](compiled_native(*native_arrays))
    elapsed = time.perf_counter() - start
    env.update(ci=compiled_ivy, ca=ivy_arrays, cn=compiled_native, cna=native_arrays)
    stmts["compiled_ivy"] = "sync(ci(*ca))"
    stmts["compiled_native"] = "sync(cn(*cna))"
    return elapsed


def _groups(row: dict) -> None:
    """The three groups and the overheads (see the module docstring)."""
    total = row["inferred_us"] if not math.isnan(row["inferred_us"]) else row["f_us"]
    native = row["native_us"]
    primary = row["primary_us"] if not math.isnan(row["primary_us"]) else native
    ops = row["ops_us"] if not math.isnan(row["ops_us"]) else primary
    if row["native_source"] in ("native object", "traced ops (all)", "untraced") or (
        row["native_source"] == "API call" and not row["primary_matched"]
    ):
        ops = primary  # no extra ops by construction
    compilable_raw = ops - primary
    compilable = max(0.0, compilable_raw)
    eager = max(0.0, total - native - compilable)
    row.update(
        total_us=total,
        backend_us=native,
        ivy_compilable_us=compilable,
        ivy_eager_us=eager,
        eager_overhead_pct=100 * (total - native) / native,
    )
    ci, cn = row["compiled_ivy_us"], row["compiled_native_us"]
    if not (math.isnan(ci) or math.isnan(cn)):
        row["compiled_overhead_pct"] = 100 * (ci - cn) / cn
        row["compiled_source"] = "measured"
    else:
        row["compiled_overhead_pct"] = 100 * compilable_raw / native
        row["compiled_source"] = "estimated"


# ----------------------------------------------------------------------------------------------
# Discovery and the run
# ----------------------------------------------------------------------------------------------


def discover() -> tuple[list[Entry], list[dict]]:
    """Every core function and composition; the skipped ones with their reason."""
    entries: list[Entry] = []
    skipped: list[dict] = []
    registry = {
        i.name: getattr(ivy.core, i.name) for i in ivy.list_functions() if i.kind != "alias"
    }
    registry.update({i.name: getattr(ivy.core, i.target) for i in ivy.list_functions(kind="alias")})
    compositions = {i.name for i in ivy.list_functions(kind="composition")}
    for name in sorted(set(ivy.core.__all__) | set(registry)):
        fn = registry.get(name)
        kind = "composition" if name in compositions else "function"
        if fn is None:
            skipped.append(_skip("function", name, "not a dispatched function or composition"))
        elif fn.__name__ != name:
            skipped.append(_skip(kind, name, f"alias of {fn.__name__} (the same object)"))
        else:
            entries.append(Entry(name, kind, fn, f"ivy.{name}"))
    return entries, skipped


def _skip(kind: str, name: str, reason: str, backend: str = "all") -> dict:
    return {
        "kind": kind,
        "function": name,
        "backend": backend,
        "status": "skipped",
        "reason": reason,
    }


def _after_load(backend: str, threads: int) -> None:
    if threads > 0 and backend == "torch":
        import torch

        torch.set_num_threads(threads)
    if threads > 0 and backend == "tensorflow":
        import tensorflow as tf

        try:
            tf.config.threading.set_intra_op_parallelism_threads(threads)
        except RuntimeError:  # tf already initialised in this process
            pass


def run(
    functions: list[str] | None,
    backends: list[str],
    library: list[str] | None,
    cfg: Config,
    progress: bool = True,
) -> list[dict]:
    entries, skipped = discover()
    known = {e.name: e for e in entries}
    skipped_names = {s["function"]: s for s in skipped}
    if functions is not None:
        unknown = [n for n in functions if n not in known and n not in skipped_names]
        if unknown:
            raise SystemExit(
                f"unknown functions {unknown}; choose among {', '.join(sorted(known))}"
            )
        entries = [known[n] for n in functions if n in known]
        skipped = [skipped_names[n] for n in functions if n in skipped_names]
    cases = library_cases()
    chosen_cases = list(cases) if library is None else library
    for name in chosen_cases:
        if name not in cases:
            raise SystemExit(f"unknown library case {name!r}; choose among {', '.join(cases)}")
    for name in chosen_cases:
        case = cases[name]
        entries.append(Entry(case.name, "library", case.function, "g", library=case))
    rows: list[dict] = list(skipped)
    buildable: list[Entry] = []
    for entry in entries:
        if entry.library is None:
            try:
                input_spec(entry.name, entry.agnostic)
            except Unbuildable as error:
                rows.append(_skip(entry.kind, entry.name, str(error)))
                continue
        buildable.append(entry)
    tasks = [(e, b) for e in buildable for b in backends]
    bar = _progress(len(tasks), progress)
    rng = np.random.default_rng(cfg.seed)
    for entry, backend in tasks:
        bar.set_postfix_str(f"{entry.name} on {backend}", refresh=False)
        started = time.perf_counter()
        try:
            rows.append(measure(entry, backend, cfg, rng))
            rows[-1]["wall_s"] = time.perf_counter() - started
        except Exception as error:
            reason = f"{type(error).__name__}: {str(error).splitlines()[0][:160]}"
            rows.append(_skip(entry.kind, entry.name, reason, backend))
        finally:
            while ivy.current_framework() is not None:
                ivy.unset_framework()
        bar.update(1)
    bar.close()
    return rows


def _progress(total: int, enabled: bool):
    try:
        from tqdm import tqdm
    except ImportError:  # pragma: no cover - tqdm is in the [test] extra
        tqdm = None
    if tqdm is not None:
        return tqdm(
            total=total, desc="profiling", unit="call", disable=not enabled, file=sys.stderr
        )

    class Plain:
        def __init__(self):
            self.done = 0

        def set_postfix_str(self, text, refresh=False):
            self.text = text

        def update(self, n):
            self.done += n
            if enabled:
                print(f"\r[{self.done}/{total}] {self.text:60.60}", end="", file=sys.stderr)

        def close(self):
            if enabled:
                print(file=sys.stderr)

    return Plain()


# ----------------------------------------------------------------------------------------------
# Outputs
# ----------------------------------------------------------------------------------------------


def write_csv(rows: list[dict], path: Path) -> None:
    with open(path, "w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=FIELDS, extrasaction="ignore")
        writer.writeheader()
        for row in rows:
            writer.writerow({k: _cell(row.get(k, "")) for k in FIELDS})


def _cell(value: Any) -> Any:
    if isinstance(value, float):
        return "" if math.isnan(value) else f"{value:.6g}"
    return value


def averaged_groups(rows: list[dict]) -> list[tuple[str, str, dict[str, float], int]]:
    """(kind, function, mean of each group over backends, number of backends) per function."""
    by_fn: dict[tuple[str, str], list[dict]] = {}
    for row in rows:
        if row.get("status") == "ok":
            by_fn.setdefault((row["kind"], row["function"]), []).append(row)
    out = []
    for (kind, name), rs in by_fn.items():
        means = {
            "backend": statistics.fmean(r["backend_us"] for r in rs),
            "Ivy compilable": statistics.fmean(r["ivy_compilable_us"] for r in rs),
            "Ivy eager": statistics.fmean(r["ivy_eager_us"] for r in rs),
        }
        out.append((kind, name, means, len(rs)))
    order = {"function": 0, "composition": 1, "library": 2}
    out.sort(key=lambda t: (order.get(t[0], 3), -sum(t[2].values())))
    return out


def plot(rows: list[dict], path: Path, backends: list[str]) -> None:
    """The paper's figure: per function, averaged over backends, cumulative bars on a log scale
    (backend, + Ivy compilable, + Ivy eager); functions, then compositions, then library."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Patch

    data = averaged_groups(rows)
    if not data:
        return
    suffix = {"function": "", "composition": " [comp.]", "library": " [lib.]"}
    labels = [name.replace("ivy_mechanics.", "mech.") + suffix[kind] for kind, name, _, _ in data]
    fig, ax = plt.subplots(figsize=(10, max(3.5, 0.16 * len(data) + 1.8)))
    y = np.arange(len(data))[::-1]
    b = np.array([d[2]["backend"] for d in data])
    c = np.array([d[2]["Ivy compilable"] for d in data])
    e = np.array([d[2]["Ivy eager"] for d in data])
    positive = np.concatenate([b, b + c, b + c + e])
    positive = positive[positive > 0]
    left = 10 ** math.floor(math.log10(positive.min())) if positive.size else 0.1
    for top, group in ((b + c + e, "Ivy eager"), (b + c, "Ivy compilable"), (b, "backend")):
        ax.barh(y, np.maximum(top - left, 0), left=left, height=0.8, color=GROUP_COLOURS[group])
    for i in range(1, len(data)):  # a line between functions, compositions and library
        if data[i][0] != data[i - 1][0]:
            ax.axhline(y[i] + 0.5, color="black", linewidth=0.8)
    ax.set_xscale("log")
    ax.set_yticks(y)
    ax.set_yticklabels(labels, fontsize=6)
    ax.set_ylim(-0.7, len(data) - 0.3)
    ax.tick_params(axis="x", top=True, labeltop=True)
    ax.set_xlabel("time per call (us, log scale): backend, + Ivy compilable, + Ivy eager")
    ax.grid(axis="x", which="both", alpha=0.3)
    ax.set_title(
        f"ivy runtime per function, {N_ELEMENTS:,} elements on the CPU, "
        f"mean over {', '.join(backends)}",
        fontsize=9,
        pad=24,
    )
    fig.legend(
        handles=[Patch(color=GROUP_COLOURS[g], label=g) for g in GROUPS],
        loc="upper right",
        ncol=3,
        fontsize=7,
        frameon=False,
    )
    fig.tight_layout(rect=(0, 0, 1, 0.995))
    fig.savefig(path, dpi=110)
    plt.close(fig)


def summary(rows: list[dict], backends: list[str], top: int = 5) -> str:
    ok = [r for r in rows if r.get("status") == "ok"]
    lines = [
        "## Overhead of ivy per backend (core functions and compositions)",
        "",
        "Median over functions of the overhead relative to the native call(s). Eager: "
        "ivy.fn (framework inferred) vs native. Compiled: ivy.compile_fn vs the native compiler "
        "where measured, else Ivy compilable / backend (estimated).",
        "",
        "| backend | functions | median eager overhead | median compiled overhead (measured / "
        "estimated) | median noise (IQR) | same object twice | largest eager overhead |",
        "|---|---|---|---|---|---|---|",
    ]
    for backend in backends:
        rs = [r for r in ok if r["backend"] == backend and r["kind"] != "library"]
        if not rs:
            lines.append(f"| {backend} | 0 | | | | | |")
            continue
        eager = _median([r["eager_overhead_pct"] for r in rs])
        measured = [r["compiled_overhead_pct"] for r in rs if r["compiled_source"] == "measured"]
        estimated = [r["compiled_overhead_pct"] for r in rs if r["compiled_source"] != "measured"]
        compiled = (
            f"{_pct(_median(measured))} (n={len(measured)}) / "
            f"{_pct(_median(estimated))} (n={len(estimated)})"
        )
        noise = _median([r["noise_pct"] for r in rs])
        same = _median([abs(r["same_object_pct"]) for r in rs if not _nan(r["same_object_pct"])])
        worst = sorted(rs, key=lambda r: -r["eager_overhead_pct"])[:top]
        worst_text = ", ".join(
            f"{r['function']} {_pct(r['eager_overhead_pct'])} "
            f"(+{r['total_us'] - r['native_us']:.1f} us)"
            for r in worst
        )
        lines.append(
            f"| {backend} | {len(rs)} | {_pct(eager)} | {compiled} | {_pct(noise)} | "
            f"{_pct(same)} | {worst_text} |"
        )
    lines += ["", "## Largest absolute eager overhead (us per call, ivy.fn - native)", ""]
    lines += ["| backend | functions |", "|---|---|"]
    for backend in backends:
        rs = [r for r in ok if r["backend"] == backend and r["kind"] != "library"]
        worst = sorted(rs, key=lambda r: -(r["total_us"] - r["native_us"]))[:top]
        text = ", ".join(
            f"{r['function']} +{r['total_us'] - r['native_us']:.1f} us "
            f"({r['native_us']:.1f} -> {r['total_us']:.1f})"
            for r in worst
        )
        lines.append(f"| {backend} | {text} |")
    lib = [
        r
        for r in ok
        if r["kind"] in ("library", "composition") and r["native_source"] == "hand-written"
    ]
    if lib:
        lines += [
            "",
            "## Compositions and library functions against hand-written native code",
            "",
            "| function | backend | native eager us | ivy eager us | eager overhead | "
            "native compiled us | ivy compiled us | compiled overhead |",
            "|---|---|---|---|---|---|---|---|",
        ]
        for r in sorted(lib, key=lambda r: (r["kind"] != "library", r["function"], r["backend"])):
            compiled = _pct(r["compiled_overhead_pct"]) + (
                "" if r["compiled_source"] == "measured" else " (est.)"
            )
            lines.append(
                f"| {r['function']} | {r['backend']} | {r['native_us']:.1f} | "
                f"{r['total_us']:.1f} | {_pct(r['eager_overhead_pct'])} | "
                f"{_num(r['compiled_native_us'])} | {_num(r['compiled_ivy_us'])} | {compiled} |"
            )
    unmatched = sorted(
        {
            f"{r['function']} ({r['backend']})"
            for r in ok
            if r.get("native_source") == "traced ops" and not r.get("primary_matched")
        }
    )
    if unmatched:
        lines += [
            "",
            "Shims with no op named like the function (every op counted as backend): "
            + ", ".join(unmatched),
        ]
    skipped = [r for r in rows if r.get("status") == "skipped"]
    if skipped:
        lines += ["", f"## Skipped ({len(skipped)})", ""]
        for r in sorted(skipped, key=lambda r: (r["function"], r["backend"])):
            lines.append(f"- {r['function']} [{r['backend']}]: {r['reason']}")
    return "\n".join(lines) + "\n"


def _nan(v: Any) -> bool:
    return isinstance(v, float) and math.isnan(v)


def _median(values: list[float]) -> float:
    values = [v for v in values if not _nan(v)]
    return statistics.median(values) if values else float("nan")


def _pct(v: float) -> str:
    return "n/a" if _nan(v) else f"{v:+.1f}%"


def _num(v: float) -> str:
    return "n/a" if _nan(v) else f"{v:.1f}"


def main(argv: list[str] | None = None) -> list[dict]:
    parser = argparse.ArgumentParser(
        description=__doc__.splitlines()[0], formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--functions", help="comma-separated ivy functions (default: all)")
    parser.add_argument("--backends", help="comma-separated backends (default: all installed)")
    parser.add_argument("--out", default="profile_overhead_out", help="output folder")
    parser.add_argument(
        "--library",
        default=None,
        help="comma-separated library cases (default: all; 'none' for none)",
    )
    parser.add_argument("--repeats", type=int, default=7, help="samples per variant")
    parser.add_argument("--sample-ms", type=float, default=2.0, help="duration of one sample")
    parser.add_argument("--compiled", choices=("all", "compositions", "none"), default="all")
    parser.add_argument(
        "--torch-compile",
        choices=("all", "compositions", "none"),
        default="compositions",
        help="torch.compile takes seconds per function: by default only compositions and "
        "library functions",
    )
    parser.add_argument("--threads", type=int, default=1, help="intra-op threads (0: leave)")
    parser.add_argument(
        "--clock",
        choices=("cpu", "wall"),
        default="cpu",
        help="cpu: CPU time of this process (other processes on a busy machine add nothing); "
        "wall: elapsed time",
    )
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--no-progress", action="store_true")
    args = parser.parse_args(argv)

    _thread_env(args.threads)  # for frameworks not imported yet (numpy's BLAS already is)
    installed = ivy.installed_frameworks()
    backends = (args.backends or ",".join(installed)).split(",")
    missing = [b for b in backends if b not in installed]
    if missing:
        raise SystemExit(f"backends not installed: {missing}; installed: {', '.join(installed)}")
    for backend in backends:
        ivy.get_framework(f=backend)
        _after_load(backend, args.threads)
    functions = args.functions.split(",") if args.functions else None
    library = (
        None if args.library is None else [] if args.library == "none" else args.library.split(",")
    )
    cfg = Config(
        repeats=args.repeats,
        sample_s=args.sample_ms / 1000,
        compiled=args.compiled,
        torch_compile=args.torch_compile,
        seed=args.seed,
        clock=time.process_time if args.clock == "cpu" else time.perf_counter,
    )
    start = time.perf_counter()
    rows = run(functions, backends, library, cfg, progress=not args.no_progress)
    elapsed = time.perf_counter() - start
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    write_csv(rows, out / "overhead.csv")
    plot(rows, out / "overhead.png", backends)
    text = summary(rows, backends)
    text += (
        f"\n{sum(r.get('status') == 'ok' for r in rows)} rows measured in {elapsed:.0f} s "
        f"({cfg.repeats} interleaved samples of ~{cfg.sample_s * 1e3:g} ms per variant).\n"
    )
    (out / "summary.md").write_text(text)
    print(text)
    print(f"wrote {out / 'overhead.csv'}, {out / 'overhead.png'}, {out / 'summary.md'}")
    return rows


if __name__ == "__main__":
    main()
