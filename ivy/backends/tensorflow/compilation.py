"""tensorflow backend: compilation with ``tf.function`` (graph mode), without AutoGraph.

AutoGraph is off (``autograph=False``): Python control flow runs once at trace time, as under
``jax.jit``, so a function written with ivy behaves alike on both; branch on array values with
ivy's array functions (``ivy.where``) rather than Python ``if``.

Static arguments: ``tf.function`` treats every non-tensor argument (Python numbers, strings,
tuples of them) as static and retraces when one changes, so ``static_argnums`` and
``static_argnames`` are accepted for a uniform signature and need nothing more.

Donation: ``tf.function`` has none; ``donate_argnums`` is accepted for a uniform signature and
has no effect (the arguments stay valid, and an updated tensor is a new one).

Randomness: the backend's ``tf.random.Generator`` keeps its state in a ``tf.Variable`` that the
graph reads and advances on every call, so draws differ from call to call and ``ivy.seed``
(which resets that same variable) reproduces them.

Calling cost: ``tf.function`` spends about 15 µs of Python per argument array on every call
(it rebuilds the trace type of each argument to find the trace), which for a training step
that passes its parameters and optimizer state in and out (about 40 arrays) costs more than a
third of the step. ``compile_native`` therefore keeps its own table from a cheap key of the call
(optree's structure, each eager tensor's dtype and shape, the static values) to the trace
``tf.function`` chose, and calls that trace's flat entry point directly. A key enters the table
only after checking, at its first call, that tf itself flattens the arguments into exactly the
same tensors in the same order; calls with variables, symbolic tensors (inside another graph)
or unhashable static values always take ``tf.function``'s own path. In eager calls where no
gradient tape records, the trace's graph function is called on the flat tensors and its outputs
are packed by optree (see :class:`_Trace`); a tape that records takes ``_call_flat``, which
records the call for the gradient. This uses
``ConcreteFunction._call_flat`` and ``_inference_function``, ``function_type_utils`` and
``record.could_possibly_record``, private parts of tensorflow, imported
under a guard: where they are missing or moved, ``compile_fn`` is plain ``tf.function`` and only
the speed changes.
"""

from __future__ import annotations

import functools

import optree
import tensorflow as tf

from ivy.backends.tensorflow._helpers import EAGER_TENSOR as _EagerTensor

try:  # private: the fast path is an optimisation, never a requirement
    from tensorflow.python.eager.polymorphic_function import (
        concrete_function,
        function_type_utils,
    )

    _FAST_PATH = hasattr(concrete_function.ConcreteFunction, "_call_flat") and hasattr(
        function_type_utils, "canonicalize_function_inputs"
    )
except ImportError:  # tensorflow moved them: plain tf.function
    _FAST_PATH = False
try:  # private too: no tape is recording (then a trace's flat entry point needs no gradient)
    from tensorflow.python.eager.record import could_possibly_record as _tape_may_record
except ImportError:
    _tape_may_record = None

_MAX_FAST_TRACES = 64  # beyond this many argument signatures, tf.function's own cache serves
_UNCHECKED, _REFUSED = object(), object()


def compile_native(fn, /, *, static_argnums=None, static_argnames=None, donate_argnums=None):
    function = tf.function(fn, autograph=False)
    if not _FAST_PATH:
        return function
    return _FastCall(function)


def _call_key(leaves, treedef):
    """(key, tensors) of a call's flattened arguments, or (None, None) when the call must take
    ``tf.function``'s own path."""
    parts, tensors = [treedef], []
    for leaf in leaves:
        if type(leaf) is _EagerTensor:
            # the dtype as its enum (an int): tf.DType hashes and compares in Python, which cost
            # more than the rest of the key (the table's look-up hashes and compares each part)
            parts.append((leaf._datatype_enum(), leaf._shape_tuple()))
            tensors.append(leaf)
        elif isinstance(leaf, (tf.Tensor, tf.Variable)):
            return None, None  # symbolic tensors and variables: tf.function handles them
        else:
            parts.append((type(leaf), leaf))
    key = tuple(parts)
    try:
        hash(key)
    except TypeError:
        return None, None
    return key, tensors


class _FastCall:
    """A ``tf.function`` that skips its per-call argument matching once a call's signature has
    been seen (see the module's docstring)."""

    def __init__(self, function):
        self._function = function
        self._traces: dict = {}
        functools.update_wrapper(self, function.python_function)

    def __call__(self, *args, **kwargs):
        leaves, treedef = optree.tree_flatten((args, kwargs))
        key, tensors = _call_key(leaves, treedef)
        if key is None:
            return self._function(*args, **kwargs)
        trace = self._traces.get(key, _UNCHECKED)
        if trace is _UNCHECKED:
            out = self._function(*args, **kwargs)
            if len(self._traces) < _MAX_FAST_TRACES:
                self._traces[key] = self._checked_trace(args, kwargs, tensors)
            return out
        if trace is _REFUSED:
            return self._function(*args, **kwargs)
        if trace.direct is not None and not _tape_may_record() and tf.executing_eagerly():
            if trace.out_spec is not None:
                flat = trace.direct(*tensors, *trace.captured)
                return optree.tree_unflatten(trace.out_spec, flat)
            if not trace.out_checked:
                return trace.first_direct_call(tensors)
        return trace.concrete._call_flat(tensors, trace.captured)

    def _checked_trace(self, args, kwargs, tensors):
        """The trace tf.function chose for these arguments, if tf flattens them into exactly
        ``tensors``; otherwise _REFUSED."""
        concrete = self._function.get_concrete_function(*args, **kwargs)
        try:
            bound = function_type_utils.canonicalize_function_inputs(
                args, kwargs, concrete.function_type
            )
            flat = concrete.function_type.unpack_inputs(bound)
        except Exception:  # noqa: BLE001 - any surprise means: use tf.function's path
            return _REFUSED
        if len(flat) != len(tensors) or any(a is not b for a, b in zip(flat, tensors)):
            return _REFUSED
        return _Trace(concrete)

    def get_concrete_function(self, *args, **kwargs):
        return self._function.get_concrete_function(*args, **kwargs)

    @property
    def python_function(self):
        return self._function.python_function

    def __get__(self, obj, objtype=None):
        return self if obj is None else functools.partial(self, obj)


class _Trace:
    """A trace that ``tf.function`` chose, and, in eager calls where no gradient tape records,
    its graph function's flat entry point with the outputs packed by optree (tf's own packing,
    ``function_type.pack_output``, rebuilds the output nest in Python, about a third of the
    Python cost of a call that returns a training step's parameters and state). The packing is
    checked once: at the first such call, tf packs the outputs and optree must find exactly the
    same tensors in the same order in the result; otherwise every call takes ``_call_flat``."""

    __slots__ = ("concrete", "captured", "direct", "out_spec", "out_checked")

    def __init__(self, concrete):
        self.concrete = concrete
        self.captured = list(concrete.captured_inputs)
        atomic = getattr(concrete, "_inference_function", None)
        usable = (
            _tape_may_record is not None
            and hasattr(atomic, "call_flat")
            and hasattr(getattr(concrete, "function_type", None), "pack_output")
        )
        self.direct = atomic.call_flat if usable else None
        self.out_spec = None
        self.out_checked = False

    def first_direct_call(self, tensors):
        """One call through the flat entry point, packed by tf; it checks optree's packing."""
        self.out_checked = True
        flat = self.direct(*tensors, *self.captured)
        out = self.concrete.function_type.pack_output(flat)
        leaves, spec = optree.tree_flatten(out)
        if len(leaves) == len(flat) and all(a is b for a, b in zip(leaves, flat)):
            self.out_spec = spec
        return out
