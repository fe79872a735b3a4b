"""jax backend: compilation with ``jax.jit``, threading the backend's PRNG key through.

The jitted function takes the backend's PRNG key (``ivy.backends.jax.random``; as its raw uint32
data, which jax passes through a jitted call faster than a typed key) as an extra input
and returns the advanced key as an extra output, which is written back to the key state after
the call. While jax traces the function, the key state holds the traced key, so every ivy random
function inside draws from it. Draws therefore differ from call to call (they are not constants
frozen at trace time), ``ivy.seed(n)`` reproduces them, and a function that draws nothing just
passes its key through. Compiled functions may call each other (the key is threaded through).

Called inside someone else's trace (a plain ``jax.jit`` around a compiled function), the key
cannot be written back: its draws are then fixed when that outer code is traced, with the
warning of ``ivy.backends.jax.random``, as for any draw under a plain ``jax.jit``.

``static_argnums`` and ``static_argnames`` refer to ``fn``'s parameters, as in ``jax.jit``; each
completes the other through ``fn``'s signature, so a static argument may be passed by position
or by name.

``donate_argnums`` (positions of ``fn``'s parameters, as in ``jax.jit``; jax finds their names
through the signature, so a donated argument may be passed by name too) lets XLA reuse those
arguments' buffers for outputs of the same shape and dtype: an array updated with
``ivy.put_rows`` or ``.at[...].set`` and returned is then written in place instead of copied.
jax deletes the donated arrays at the call (``arr.is_deleted()``); reading one afterwards
raises. The PRNG key is never donated.
"""

from __future__ import annotations

import functools
import inspect
import operator

import jax

from ivy.backends.jax import random as _random

_Tracer = jax.core.Tracer


def _static_args(sig, static_argnums, static_argnames):
    """jax.jit's static arguments of the traced function (whose first argument is the key).

    Positions and names complete each other through ``fn``'s signature ``sig``, so a static
    argument is static whether it is passed by position or by name.
    """
    nums = (static_argnums,) if isinstance(static_argnums, int) else (static_argnums or ())
    names = (static_argnames,) if isinstance(static_argnames, str) else (static_argnames or ())
    nums, names = [operator.index(i) for i in nums], list(names)
    if sig is not None:
        params = list(sig.parameters.values())
        positional = [p for p in params if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
        if not any(p.kind is p.VAR_POSITIONAL for p in params):
            nums = [i + len(positional) if i < 0 else i for i in nums]
        for i, p in enumerate(positional):
            if i in nums and p.kind is p.POSITIONAL_OR_KEYWORD and p.name not in names:
                names.append(p.name)
            if p.name in names and i not in nums:
                nums.append(i)
    shifted = tuple(i + 1 if i >= 0 else i for i in nums)
    return shifted or None, tuple(names) or None


def _committed_like(key, arguments):
    """``key`` placed where the first committed array among ``arguments`` lives.

    jax.jit compiles once per committed/uncommitted pattern of its inputs, and its outputs are
    committed when any input is. A fresh key (``ivy.seed``) is uncommitted; passed next to
    committed arrays (parameters placed with ``device=``), it would come back committed and the
    second call would compile the function again. Committing it up front, like its neighbours,
    gives one compilation; next to uncommitted arrays only, it stays uncommitted, as they do.
    """
    for leaf in jax.tree_util.tree_leaves(arguments):
        if isinstance(leaf, jax.Array) and not isinstance(leaf, _Tracer) and leaf.committed:
            return jax.device_put(key, leaf.sharding)
    return key


def _donated(sig, donate_argnums):
    """jax.jit's ``donate_argnums`` for the traced function (whose first argument is the key):
    ``fn``'s positions shifted by one, negative ones counted from the end of ``fn``'s
    positional parameters."""
    nums = (donate_argnums,) if isinstance(donate_argnums, int) else (donate_argnums or ())
    nums = [operator.index(i) for i in nums]
    if any(i < 0 for i in nums):
        params = [] if sig is None else list(sig.parameters.values())
        if sig is not None and not any(p.kind is p.VAR_POSITIONAL for p in params):
            count = sum(p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD) for p in params)
            nums = [i + count if i < 0 else i for i in nums]
        if any(i < 0 for i in nums):
            raise ValueError(
                f"compile_fn: donate_argnums {donate_argnums!r} counts back past this "
                f"function's positional parameters (or its signature has none to count)."
            )
    return tuple(i + 1 for i in nums)


def compile_native(fn, /, *, static_argnums=None, static_argnames=None, donate_argnums=None):
    state = _random._state

    traced = {"draws": True}  # whether the traced function draws random numbers

    def with_key(key_data, /, *args, **kwargs):
        saved = state.saved()
        # traced: draws inside the function come from the key passed in
        state.key = jax.random.wrap_key_data(key_data)
        start = state.key
        try:
            out = fn(*args, **kwargs)
            traced["draws"] = state.key is not start  # a draw replaces the key (next_key)
            return out, jax.random.key_data(state.key)
        finally:
            state.restore(saved)

    try:
        sig = inspect.signature(fn)
    except (TypeError, ValueError):
        sig = None
    else:  # jax reads parameter names and kinds from the signature
        key = inspect.Parameter("_ivy_prng_key", inspect.Parameter.POSITIONAL_ONLY)
        with_key.__signature__ = sig.replace(parameters=[key, *sig.parameters.values()])
    nums, names = _static_args(sig, static_argnums, static_argnames)
    donated = _donated(sig, donate_argnums)
    jitted = jax.jit(with_key, static_argnums=nums, static_argnames=names, donate_argnums=donated)

    @functools.wraps(fn)
    def compiled(*args, **kwargs):
        if state.data is None:  # never seeded: next_key seeds from the OS's entropy (concretely,
            with jax.ensure_compile_time_eval():  # also when called inside a user's jax.jit)
                state.next_key()
        data = state.data
        if not isinstance(data, _Tracer) and not data.committed:
            data = _committed_like(data, (args, kwargs))
        out, new_data = jitted(data, *args, **kwargs)
        if isinstance(new_data, _Tracer) and not isinstance(data, _Tracer):
            if traced["draws"]:  # under an outer trace: advance the key concretely (and warn)
                state.next_key()
        else:
            state.data = new_data
        return out

    compiled.jitted = jitted  # the jax.jit object: (key data, *args) -> (out, new key data)
    return compiled
