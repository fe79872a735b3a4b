"""jax backend: random numbers from one module-level PRNG key.

The key lives in ``_state``; every draw takes a fresh subkey from ``_state.next_key()``, which
advances the key. Without :func:`seed`, the first draw seeds the key from the OS's entropy.

Compiled code: ``ivy.compile_fn`` (``ivy.backends.jax.compilation``) threads the key through the
jitted function as an extra input and output; while it traces, ``_state.key`` holds the traced
key, so draws inside differ from call to call and ``seed`` reproduces them. Under a plain
``jax.jit`` (or ``lax.scan`` body) the key cannot be threaded: the draws are made once, when the
code is traced, and a warning says so. Inside ``lax.scan``/``while_loop`` bodies of compiled code,
pass keys explicitly (``jax.random``) rather than drawing from ivy.
"""

from __future__ import annotations

import operator
import os
import warnings

import jax
import jax.numpy as jnp

from ivy.backends._sample_args import categorical_args, check_draw_bounds, floating_draw
from ivy.backends.jax._helpers import default_int, native_device, native_dtype

_MASK32 = 0xFFFFFFFF


def _key_from_seed(seed_value):
    """A PRNG key for a non-negative int of any size, the same whatever jax's x64 setting."""
    value = operator.index(seed_value)
    if value < 0:
        raise ValueError(f"seed: expected a non-negative integer, got {seed_value!r}.")
    key = jax.random.key(value & _MASK32)  # jax would truncate a larger seed without x64
    value >>= 32
    while value:
        key = jax.random.fold_in(key, value & _MASK32)
        value >>= 32
    return key


class _KeyState:
    """The backend's PRNG key and the one place that advances it.

    The key is held as a typed key (``key``, what draws use) or as its raw uint32 data
    (``data``, what ``ivy.compile_fn`` threads through jitted functions: jax passes raw arrays
    in and out of a jitted call about 2.5 µs faster than typed keys). Each form is made from the
    other when first asked for, and setting one discards the other.
    """

    def __init__(self):
        self._key = None
        self._data = None

    @property
    def key(self):
        if self._key is None and self._data is not None:
            self._key = _converted(jax.random.wrap_key_data, self._data)
        return self._key

    @key.setter
    def key(self, key):
        self._key, self._data = key, None

    @property
    def data(self):
        if self._data is None and self._key is not None:
            self._data = _converted(jax.random.key_data, self._key)
        return self._data

    @data.setter
    def data(self, data):
        self._key, self._data = None, data

    def saved(self):
        return self._key, self._data

    def restore(self, saved):
        self._key, self._data = saved

    def seed(self, seed_value):
        self.key = _key_from_seed(seed_value)

    def next_key(self):
        """Return a fresh subkey and advance the key."""
        if self.key is None:
            self.seed(int.from_bytes(os.urandom(8), "little"))
        key, subkey = jax.random.split(self.key)
        if isinstance(key, jax.core.Tracer) and not isinstance(self.key, jax.core.Tracer):
            # Drawing in traced code (jax.jit, lax.scan...) from the module-level key: advance it
            # now rather than store a tracer. The numbers are then fixed when the code is traced.
            warnings.warn(
                "ivy.jax random functions in traced code (jax.jit, lax.scan, ...) draw their "
                "numbers once, when the code is traced: every call of the compiled function "
                "returns the same ones. Compile with ivy.compile_fn instead of jax.jit to draw "
                "fresh numbers on every call.",
                stacklevel=3,
            )
            with jax.ensure_compile_time_eval():
                key, subkey = jax.random.split(self.key)
        self.key = key
        return subkey


def _converted(convert, value):
    """``convert(value)``, computed now when ``value`` is concrete, even while some code is being
    traced (the module's state must never hold another trace's values)."""
    if isinstance(value, jax.core.Tracer):
        return convert(value)
    with jax.ensure_compile_time_eval():
        return convert(value)


_state = _KeyState()


def seed(seed_value=0):
    _state.seed(seed_value)


def _shape(shape, *bounds):
    if shape is None:
        return jnp.broadcast_shapes(*(jnp.shape(b) for b in bounds))
    return tuple(shape) if isinstance(shape, (tuple, list)) else (operator.index(shape),)


def _placed(x, device):
    return x if device is None else jax.device_put(x, native_device(device))


def random_uniform(low=0.0, high=1.0, shape=None, *, dtype=None, device=None):
    dt = native_dtype(dtype) or jnp.float32
    floating_draw("random_uniform", "jax", dtype, jnp.issubdtype(dt, jnp.inexact))
    check_draw_bounds("random_uniform", low, high, "jax")
    out = jax.random.uniform(_state.next_key(), _shape(shape, low, high), dt, low, high)
    return _placed(out, device)


def random_normal(mean=0.0, std=1.0, shape=None, *, dtype=None, device=None):
    dt = native_dtype(dtype) or jnp.float32
    floating_draw("random_normal", "jax", dtype, jnp.issubdtype(dt, jnp.inexact))
    check_draw_bounds("random_normal", mean, std, "jax")
    out = jax.random.normal(_state.next_key(), _shape(shape, mean, std), dt)
    return _placed((mean + std * out).astype(dt), device)


def randint(low, high, shape=None, *, dtype=None, device=None):
    check_draw_bounds("randint", low, high, "jax")
    dt = native_dtype(dtype) or default_int()
    out = jax.random.randint(_state.next_key(), _shape(shape, low, high), low, high, dt)
    return _placed(out, device)


def shuffle(x, /):
    return jax.random.permutation(_state.next_key(), x)


def random_categorical(logits, /, *, num_samples=1, dtype=None):
    logits = jnp.asarray(logits)
    categorical_args(logits.shape, num_samples)
    if not jnp.issubdtype(logits.dtype, jnp.floating):
        logits = logits.astype(jnp.float32)
    shape = (num_samples, *logits.shape[:-1])  # jax puts the sample axis first
    out = jax.random.categorical(_state.next_key(), logits, axis=-1, shape=shape)
    return jnp.moveaxis(out, 0, -1).astype(native_dtype(dtype) or default_int())
