"""jax backend: control flow with ``jax.lax.scan``, ``fori_loop``, ``while_loop`` and ``cond``
when traced, Python loops when eager.

Loops on concrete values, outside any jax transformation, are the Python loops of
``ivy/core/control_flow.py``: an eager ``lax.scan`` traces and compiles its body with XLA at every
call (the body is a new closure each time), about 0.3 s for a 100-step loop where the Python loop
takes 20 ms. Loops that jax stages out (under ``ivy.compile_fn``/``jax.jit``, or inside the body
of another ``lax`` loop) or whose carry or inputs are traced (``jax.grad``, ``jax.vmap``, e.g.
``ivy.execute_with_gradients`` of a rollout) use ``jax.lax``: differentiating a Python loop
eagerly costs about 0.3 ms per operation. A loop with a concrete carry and inputs whose body
closes over traced values (under an eager ``jax.grad``) stays a Python loop: correct, slower.
``cond`` branches in Python whenever its predicate is concrete.

``while_loop`` with ``maximum_iterations`` runs as a ``lax.scan`` of that many steps whose
steps after the end do nothing (a ``lax.cond``), so that it is reverse-differentiable;
``lax.while_loop`` itself is not.
"""

from __future__ import annotations

import jax
import jax.numpy as jnp

from ivy.backends.jax import random as _random
from ivy.backends.jax.creation import asarray
from ivy.core.control_flow import (
    LoopOps,
    python_cond,
    python_fori_loop,
    python_scan,
    python_while_loop,
)
from ivy.nest import nest_leaves

_Tracer = jax.core.Tracer
_state = _random._state


def _unstack(a):
    return [a[i] for i in range(a.shape[0])]


_OPS = LoopOps(
    unstack=_unstack, stack=jnp.stack, zeros=jnp.zeros, asarray=asarray, native=jax.Array
)


def _staged() -> bool:
    """Whether jax is staging code out now (``jax.jit``, a ``lax`` loop's body): there, even a
    constant made now is a tracer (about 40 us eagerly)."""
    return isinstance(jax.lax.full((), 0, jnp.int32), _Tracer)


def _use_lax(*nests) -> bool:
    """Whether a loop runs as ``jax.lax``: when jax stages code out, or when the carry or the
    inputs are traced (``jax.grad``, ``jax.vmap`` called eagerly: differentiating a Python loop
    eagerly costs ~0.3 ms per operation, 3 s for 200 steps of a pendulum, where ``lax.scan``
    compiles once per call)."""
    return any(isinstance(leaf, _Tracer) for leaf in nest_leaves(nests)) or _staged()


def _key_data():
    """The key state's raw data, seeding it first if it was never seeded (concretely: seeding
    while jax traces would store a tracer in the module's state)."""
    if _state.data is None:
        with jax.ensure_compile_time_eval():
            _state.next_key()
    return _state.data


class _Threaded:
    """Runs user functions with the key state set to a key traced through a loop or branch,
    and records whether any of them drew from it."""

    def __init__(self):
        self.drew = False

    def call(self, key, fn, *args):
        """``fn(*args)`` with the key state holding ``key``; returns (key after, result)."""
        saved = _state.saved()
        _state.data = key
        try:
            out = fn(*args)
            new_key = _state.data
        finally:
            _state.restore(saved)
        if new_key is not key:
            self.drew = True
        return new_key, out

    def store(self, key_before, key_after):
        """Write the advanced key back to the state after the loop, if a body drew."""
        if not self.drew:
            return
        if isinstance(key_after, _Tracer) and not isinstance(key_before, _Tracer):
            _state.next_key()  # inside an outer trace: advance concretely (and warn)
        else:
            _state.data = key_after


def scan(fn, init, xs=None, length=None, unroll=1, *, pure=False):
    if not _use_lax(init, xs):
        return python_scan(_OPS, fn, init, xs, length, unroll)
    threaded = _Threaded()

    def body(carry, x):
        key, c = carry
        key, (c, y) = threaded.call(key, fn, c, x)
        return (key, c), y

    key0 = _key_data()
    (key, carry), ys = jax.lax.scan(body, (key0, init), xs, length=length, unroll=unroll)
    threaded.store(key0, key)
    return carry, ys


def fori_loop(lower, upper, body_fun, init_val, *, pure=False):
    if not _use_lax(init_val, lower, upper):
        return python_fori_loop(_OPS, lower, upper, body_fun, init_val)
    threaded = _Threaded()

    def body(i, carry):
        key, val = carry
        return threaded.call(key, body_fun, i, val)

    key0 = _key_data()
    key, val = jax.lax.fori_loop(lower, upper, body, (key0, init_val))
    threaded.store(key0, key)
    return val


def while_loop(cond_fun, body_fun, init_val, *, maximum_iterations=None, pure=False):
    if not _use_lax(init_val):
        return python_while_loop(_OPS, cond_fun, body_fun, init_val, maximum_iterations)
    threaded = _Threaded()

    def keep_going(carry):
        key, val = carry
        return _predicate(threaded.call(key, cond_fun, val)[1])

    def body(carry):
        key, val = carry
        return threaded.call(key, body_fun, val)

    key0 = _key_data()
    if maximum_iterations is None:
        key, val = jax.lax.while_loop(keep_going, body, (key0, init_val))
    else:

        def step(carry, _):
            running, key, val = carry
            running = jnp.logical_and(running, keep_going((key, val)))
            key, val = jax.lax.cond(running, body, lambda kv: kv, (key, val))
            return (running, key, val), None

        start = (jnp.asarray(True), key0, init_val)
        (_, key, val), _ = jax.lax.scan(step, start, None, length=int(maximum_iterations))
    threaded.store(key0, key)
    return val


def _predicate(pred):
    pred = jnp.asarray(pred)
    if pred.shape != ():
        raise ValueError(
            f"ivy.while_loop: the predicate must be a scalar (shape ()), got shape {pred.shape}; "
            f"reduce it with ivy.all or ivy.any."
        )
    return pred.astype(bool)


def cond(pred, true_fun, false_fun, *operands):
    if not isinstance(pred, _Tracer):
        return python_cond(pred, true_fun, false_fun, *operands)
    threaded = _Threaded()

    def branch(fn):
        def run(key, ops):
            return threaded.call(key, fn, *ops)

        return run

    pred = jnp.asarray(pred)
    if pred.shape != ():
        raise ValueError(
            f"ivy.cond: the predicate must be a scalar (shape ()), got shape {pred.shape}; "
            f"reduce it with ivy.all or ivy.any."
        )
    key0 = _key_data()
    key, out = jax.lax.cond(pred, branch(true_fun), branch(false_fun), key0, operands)
    threaded.store(key0, key)
    return out
