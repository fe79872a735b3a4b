"""torch backend: compilation with ``torch.compile`` (TorchDynamo and the inductor backend).

Static arguments: dynamo guards on every non-tensor argument and recompiles when one changes, so
Python values are always static; ``static_argnums`` and ``static_argnames`` are accepted for a
uniform signature and need nothing more.

Donation: ``torch.compile`` has none (torch writes in place by itself, where code asks for it);
``donate_argnums`` is accepted for a uniform signature and has no effect.

Randomness: inductor draws compiled random numbers from a seed it takes from torch's global
generator on every call, so draws differ from call to call and ``ivy.seed`` (``torch
.manual_seed``) reproduces them (the compiled numbers differ from eager ones for the same seed).

Gradients: by default dynamo does not trace ``torch.autograd.grad`` (what
``ivy.execute_with_gradients`` uses); it splits the graph there, once per differentiated leaf.
The compiled function therefore runs with dynamo's ``trace_autograd_ops`` switched on for the
duration of each call: the forward pass, the gradients and the optimizer update of a training
step become one graph, about 25% faster than the split one. The flag is global, so it is saved
and restored under a lock: the first of the compiled calls running at once (in any thread)
saves it and switches it on, the last one to finish restores it, and other ``torch.compile``
users in the process find it as they left it once no ivy-compiled call runs.

Scalars read inside the graph: inductor lowers a ``scan`` whose body holds a ``while_loop``
(both kept as loops: see ``control_flow.py``; a physics step's RK4 stages around its solver)
to a loop that reads its step count with ``.item()``. dynamo refuses that read unless its
``capture_scalar_outputs`` is on, and the whole function then fell back to eager mode (with the
fallback's warning). It is switched on for each call with ``trace_autograd_ops``, in the same
way.

Fallback: where ``torch.compile`` cannot run (dynamo unsupported on this Python or platform, or
the inductor backend fails to build, e.g. without a C++ compiler), the function runs eagerly
instead, with one warning; its results are the same, only slower.
"""

from __future__ import annotations

import functools
import threading
import warnings

import torch

_flag_lock = threading.Lock()
_flag_state = {"calls": 0, "saved": None}  # ivy-compiled calls running now, the user's values
#: dynamo's settings that each ivy-compiled call switches on while it runs (see above)
_FLAGS = ("trace_autograd_ops", "capture_scalar_outputs")


def _warn_fallback(reason: str) -> None:
    warnings.warn(
        f"torch.compile cannot run here ({reason}); ivy.compile_fn runs the function eagerly "
        f"instead, with the same results.",
        RuntimeWarning,
        stacklevel=4,
    )


def compile_native(fn, /, *, static_argnums=None, static_argnames=None, donate_argnums=None):
    if not torch._dynamo.is_dynamo_supported():
        _warn_fallback("TorchDynamo does not support this Python or platform")
        return fn
    current = [torch.compile(fn)]
    config = torch._dynamo.config

    @functools.wraps(fn)
    def compiled(*args, **kwargs):
        # Read when dynamo traces, which happens inside the call (first call, recompiles).
        with _flag_lock:
            if _flag_state["calls"] == 0:
                _flag_state["saved"] = {name: getattr(config, name) for name in _FLAGS}
                for name in _FLAGS:
                    setattr(config, name, True)
            _flag_state["calls"] += 1
        try:
            return current[0](*args, **kwargs)
        except torch._dynamo.exc.BackendCompilerFailed as error:
            if current[0] is fn:
                raise
            _warn_fallback(f"{type(error.inner_exception).__name__}: {error.inner_exception}")
            current[0] = fn
            return fn(*args, **kwargs)
        finally:
            with _flag_lock:
                _flag_state["calls"] -= 1
                if _flag_state["calls"] == 0:
                    for name, value in _flag_state["saved"].items():
                        setattr(config, name, value)

    compiled.__wrapped__ = fn
    return compiled
