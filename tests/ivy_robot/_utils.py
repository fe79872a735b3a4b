"""Test helpers for ivy_robot: MuJoCo references and each framework's own autodiff."""

from __future__ import annotations

import numpy as np

from tests.helpers import native, numpy_of


def mujoco_kinematics(model, qpos_batch):
    """``mj_kinematics`` (and ``mj_comPos``) per row: xpos, xmat, site_xpos, site_xmat."""
    import mujoco

    data = mujoco.MjData(model)
    out = {"xpos": [], "xmat": [], "site_xpos": [], "site_xmat": []}
    for q in qpos_batch:
        data.qpos[:] = q
        mujoco.mj_kinematics(model, data)
        mujoco.mj_comPos(model, data)
        out["xpos"].append(data.xpos.copy())
        out["xmat"].append(data.xmat.reshape(-1, 3, 3).copy())
        out["site_xpos"].append(data.site_xpos.copy())
        out["site_xmat"].append(data.site_xmat.reshape(-1, 3, 3).copy())
    return {k: np.stack(v) for k, v in out.items()}


def mujoco_jacobians(model, qpos_batch, kind, index, point=None):
    """``mj_jacBody`` / ``mj_jacSite`` (or ``mj_jac`` at a body-frame ``point``) per row,
    stacked as ``[jacp; jacr]`` *[batch, 6, nv]*."""
    import mujoco

    data = mujoco.MjData(model)
    out = []
    for q in qpos_batch:
        data.qpos[:] = q
        mujoco.mj_kinematics(model, data)
        mujoco.mj_comPos(model, data)
        jacp, jacr = np.zeros((3, model.nv)), np.zeros((3, model.nv))
        if kind == "site":
            mujoco.mj_jacSite(model, data, jacp, jacr, index)
        elif point is None:
            mujoco.mj_jacBody(model, data, jacp, jacr, index)
        else:
            world = data.xpos[index] + data.xmat[index].reshape(3, 3) @ point
            mujoco.mj_jac(model, data, jacp, jacr, world, index)
        out.append(np.concatenate([jacp, jacr]))
    return np.stack(out)


def autodiff_jacobian(backend, fn, x):
    """``d fn(x) / d x`` for one unbatched float64 input, by the framework's own autodiff:
    *out_shape + x.shape*."""
    if backend == "torch":
        import torch

        return torch.autograd.functional.jacobian(fn, native(x, backend)).numpy()
    if backend == "jax":
        import jax

        # jitted: one compilation instead of one per primitive
        return np.asarray(jax.jit(jax.jacfwd(fn))(native(x, backend)))
    if backend == "tensorflow":
        import tensorflow as tf

        t = native(x, backend)
        with tf.GradientTape() as tape:
            tape.watch(t)
            y = fn(t)
        return tape.jacobian(y, t).numpy()
    raise ValueError(f"{backend} has no autodiff")


def run(backend, fn, *arrays):
    """``fn`` on native arrays of ``backend`` made from numpy ``arrays``; the result as numpy."""
    return numpy_of(fn(*[native(a, backend) for a in arrays]))
