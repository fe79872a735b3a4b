"""torch backend: gradients with ``torch.autograd.grad``, which returns them and never
accumulates into ``.grad``: two calls give the same gradients, and parameters stay untouched.

Each leaf of ``xs`` is differentiated through a fresh leaf tensor (``x.detach()
.requires_grad_()``), so the graph of a previous computation is neither reused nor freed. With
``retain_grads=True`` a leaf that already requires grad is used as it is and the graph is kept
(``create_graph=True``), so the results can be differentiated again (second order).
"""

from __future__ import annotations

import torch

from ivy.nest import flatten_nest, map_nest, unflatten_nest


def _input(x, retain_grads):
    """The tensor to differentiate with respect to, in place of the leaf ``x``."""
    if not isinstance(x, torch.Tensor):
        x = torch.as_tensor(x)
    if retain_grads and x.requires_grad:
        return x
    return x.detach().requires_grad_(True)


def _split(out, name):
    """(loss, aux) of a function's output: a tuple's first element is the loss."""
    if isinstance(out, tuple):
        if not out:
            raise ValueError(f"{name}: the function returned an empty tuple; return the loss.")
        return out[0], out[1:]
    return out, ()


def _detach(nest):
    return map_nest(lambda a: a.detach() if isinstance(a, torch.Tensor) else a, nest)


def _grads(y, inputs, retain_grads, keep_graph=False):
    """Gradients of ``y`` with respect to each of ``inputs``; zeros where ``y`` does not depend."""
    if not y.requires_grad:
        return [torch.zeros_like(x) for x in inputs]
    return list(
        torch.autograd.grad(
            y,
            inputs,
            retain_graph=retain_grads or keep_graph,
            create_graph=retain_grads,
            allow_unused=True,
            materialize_grads=True,
        )
    )


def execute_with_gradients(func, xs, *, retain_grads=False):
    leaves, spec = flatten_nest(xs)
    inputs = [_input(x, retain_grads) for x in leaves]
    with torch.enable_grad():
        loss, aux = _split(func(unflatten_nest(spec, inputs)), "execute_with_gradients")
    if not isinstance(loss, torch.Tensor):
        loss = torch.as_tensor(loss)
    if loss.dim() != 0:
        raise ValueError(
            f"execute_with_gradients: the loss must be a scalar (shape ()), got shape "
            f"{tuple(loss.shape)}; reduce it first, e.g. with ivy.mean or ivy.sum."
        )
    grads = unflatten_nest(spec, _grads(loss, inputs, retain_grads))
    if not retain_grads:
        loss, aux = loss.detach(), _detach(aux)
    return (loss, grads, *aux)


def execute_with_jacobian(func, x, *, batch_dims=None, retain_grads=False):
    x = _input(x, retain_grads)
    nb = x.dim() - 1 if batch_dims is None else batch_dims
    nb = max(nb, 0)
    with torch.enable_grad():
        y = func(x)
    if tuple(y.shape[:nb]) != tuple(x.shape[:nb]):
        raise ValueError(
            f"execute_with_jacobian: with {nb} batch dims the output's leading shape "
            f"{tuple(y.shape[:nb])} must equal the input's {tuple(x.shape[:nb])}."
        )
    out_event = tuple(y.shape[nb:])
    # Batch elements are independent, so the sum over the batch has the per-element Jacobians
    # as its gradients: one backward pass per output component.
    summed = (y.sum(dim=tuple(range(nb))) if nb else y).reshape(-1)
    m = summed.numel()
    rows = [_grads(summed[i], [x], retain_grads, keep_graph=i < m - 1)[0] for i in range(m)]
    jac = torch.stack(rows, 0) if rows else x.new_zeros((0, *x.shape))
    jac = jac.reshape(*out_event, *x.shape)
    n_out = len(out_event)
    perm = [*range(n_out, n_out + nb), *range(n_out), *range(n_out + nb, jac.dim())]
    jac = jac.permute(perm)
    if not retain_grads:
        y, jac = y.detach(), jac.detach()
    return y, jac


def stop_gradient(x, /):
    return x.detach()


def variable(x, /):
    if not isinstance(x, torch.Tensor):
        x = torch.as_tensor(x)
    return x.detach().requires_grad_(True)
