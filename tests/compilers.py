"""Each framework's own compiler, keyed by backend, for the tests that run ivy inside it (not
through ``ivy.compile_fn``): a backend with a fast graph compiler (``fast_graph`` in
``tests/conftest.py``) adds its row here, and those tests run on it.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence


def _jax_jit(fn: Callable, unknown_batch_of: Sequence | None) -> Callable:
    import jax

    return jax.jit(fn)  # shapes are always static under jax.jit


def _tf_function(fn: Callable, unknown_batch_of: Sequence | None) -> Callable:
    import tensorflow as tf

    if unknown_batch_of is None:
        return tf.function(fn)
    specs = [tf.TensorSpec([None, *a.shape[1:]], tf.as_dtype(a.dtype)) for a in unknown_batch_of]
    return tf.function(fn, input_signature=specs, autograph=False)  # no Python control flow


NATIVE_COMPILERS: dict[str, Callable[[Callable, Sequence | None], Callable]] = {
    "jax": _jax_jit,
    "tensorflow": _tf_function,
}


def native_compile(backend: str, fn: Callable, *, unknown_batch_of: Sequence | None = None):
    """``fn`` compiled by ``backend``'s own compiler (``jax.jit``, ``tf.function``).

    Args:
        unknown_batch_of: example arguments (numpy arrays) whose leading axis the compiled
            function takes as unknown until run time, where the compiler has such a notion
            (tensorflow's ``input_signature``).
    """
    return NATIVE_COMPILERS[backend](fn, unknown_batch_of)


def _torch_graph_counter() -> Callable[[], tuple[int, dict]]:
    import torch._dynamo

    counters = torch._dynamo.utils.counters
    counters.clear()
    return lambda: (counters["stats"]["unique_graphs"], dict(counters["graph_break"]))


#: Compilers that report what they compiled: backend -> a function that starts counting and
#: returns ``report() -> (graphs compiled since, graph breaks since)``. A compiler that traces
#: Python once per graph (``jax.jit``, ``tf.function``) is counted by the test itself, with a
#: side effect in the traced function; dynamo replays such side effects at every call.
GRAPH_COUNTERS: dict[str, Callable[[], Callable[[], tuple[int, dict]]]] = {
    "torch": _torch_graph_counter,
}
