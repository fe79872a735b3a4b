"""numpy backend: numpy has no automatic differentiation, so the gradient functions raise.

``stop_gradient`` and ``variable`` return their input: a numpy array carries no gradient, and a
numpy array is all a numpy "variable" can be (forward passes of models work on numpy).
"""

from __future__ import annotations

from ivy.errors import UnsupportedError


def _no_autodiff(name: str) -> UnsupportedError:
    return UnsupportedError(
        f"ivy.{name} needs automatic differentiation, which the numpy backend does not have. "
        f"Use a differentiable backend: torch, jax or tensorflow (pass f='jax', convert the "
        f"inputs with ivy.asarray(x, f='jax'), or call ivy.set_framework('jax'))."
    )


def execute_with_gradients(func, xs, *, retain_grads=False):
    raise _no_autodiff("execute_with_gradients")


def execute_with_jacobian(func, x, *, batch_dims=None, retain_grads=False):
    raise _no_autodiff("execute_with_jacobian")


def stop_gradient(x, /):
    return x


def variable(x, /):
    return x
