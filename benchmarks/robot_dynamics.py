"""Forward dynamics and a full step of Gymnasium's Hopper: ivy_robot's KinematicTree dynamics,
compiled on jax and torch, against MuJoCo on the CPU (``mujoco.rollout``: ``mj_step`` looped in C
over the batch; a Python loop of ``mj_forward`` for forward dynamics) and, where it imports,
MJX (``jax.vmap`` of ``mjx.forward`` / ``mjx.step``, jitted), measured in the same run.

The Hopper (Gymnasium's ``hopper.xml``: 6 dofs, 3 motors, RK4, h = 0.002 s) starts from random
states lifted above the floor (no contacts: MuJoCo still runs its collision detection, which
ivy_robot does not have). Every implementation is first checked against MuJoCo (1e-9 on qacc
and the stepped state), then timed after a warm-up that compiles (the compile time, wall clock,
is reported). The implementations of one batch size take turns (benchmarks/_timing.py:
interleaved, shuffled repeats); the minimum per call and per state is reported, with the ratio
to MuJoCo's (< 1: faster).

MJX is not a dependency of the project: point ``--mjx-path`` at a folder where ``mujoco-mjx``
(and its requirements ``etils``, ``trimesh``) are installed, e.g. ``pip install --no-deps
--target /tmp/mjxpkg mujoco-mjx etils trimesh``; it is appended to ``sys.path``.

Usage:
    .venv/bin/python benchmarks/robot_dynamics.py [--batches 1,1000,100000] [--repeats 5]
        [--backends jax,torch] [--torch-threads 1] [--clock wall|cpu] [--mjx-path DIR]
"""

from __future__ import annotations

import argparse
import importlib.util
import os
import sys
import time
import timeit
import warnings

import numpy as np

_HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [_HERE, os.path.join(_HERE, "..")]

from _timing import interleaved_samples  # noqa: E402

import ivy  # noqa: E402
import ivy_robot  # noqa: E402


def hopper_path() -> str:
    import gymnasium

    folder = os.path.join(os.path.dirname(gymnasium.__file__), "envs", "mujoco", "assets")
    return os.path.join(folder, "hopper.xml")


def random_states(model, batch, rng):
    """Lifted hopper states inside the joint ranges, random velocities and controls, kept where
    MuJoCo finds no contact (the folded leg can touch the torso) and no constraint."""
    import mujoco

    data = mujoco.MjData(model)
    kept = []
    while len(kept) < batch:
        q = model.qpos0.copy()
        for j in range(model.njnt):
            if model.jnt_limited[j]:
                lo, hi = model.jnt_range[j]
                q[model.jnt_qposadr[j]] = rng.uniform(lo + 0.2 * (hi - lo), hi - 0.2 * (hi - lo))
        q[1] = 2.0  # rootz: above the floor
        data.qpos[:] = q
        mujoco.mj_forward(model, data)
        if data.ncon == 0 and data.nefc == 0:
            kept.append(q)
    v = rng.normal(scale=0.5, size=(batch, model.nv))
    u = rng.uniform(-1.0, 1.0, size=(batch, model.nu))
    return np.stack(kept), v, u


def mujoco_reference(model, q, v, u):
    """MuJoCo's qacc and next state; the step with contacts and limits disabled, since a step
    from a constraint-free state may reach one (the Hopper's foot can touch its torso)."""
    import mujoco

    smooth = mujoco.MjModel.from_xml_path(hopper_path())
    for bit in (mujoco.mjtDisableBit.mjDSBL_CONTACT, mujoco.mjtDisableBit.mjDSBL_LIMIT):
        smooth.opt.disableflags |= int(bit)
    data, smooth_data = mujoco.MjData(model), mujoco.MjData(smooth)
    qacc, nxt = [], []
    for qi, vi, ui in zip(q, v, u):
        data.qpos[:], data.qvel[:], data.ctrl[:] = qi, vi, ui
        mujoco.mj_forward(model, data)
        assert data.ncon == 0 and data.nefc == 0, "a state with contacts or limits"
        qacc.append(data.qacc.copy())
        smooth_data.qpos[:], smooth_data.qvel[:], smooth_data.ctrl[:] = qi, vi, ui
        mujoco.mj_step(smooth, smooth_data)
        nxt.append(np.concatenate([smooth_data.qpos, smooth_data.qvel]))
    return np.stack(qacc), np.stack(nxt)


def mujoco_runs(model, q, v, u):
    import mujoco
    from mujoco import rollout

    data = mujoco.MjData(model)
    spec = mujoco.mjtState.mjSTATE_FULLPHYSICS
    states = np.zeros((len(q), mujoco.mj_stateSize(model, spec)))
    for k, (qi, vi) in enumerate(zip(q, v)):
        data.qpos[:], data.qvel[:] = qi, vi
        mujoco.mj_getState(model, data, states[k], spec)
    control = u[:, None, :]
    out = np.zeros((len(q), 1, states.shape[1]))

    def forward_loop():
        for qi, vi, ui in zip(q, v, u):
            data.qpos[:], data.qvel[:], data.ctrl[:] = qi, vi, ui
            mujoco.mj_forward(model, data)
        return data.qacc

    def step_rollout():
        return rollout.rollout(model, data, states, control, nstep=1, state=out)

    return {
        "MuJoCo mj_forward (Python loop)": forward_loop,
        "MuJoCo rollout (C loop)": step_rollout,
    }


def ivy_runs(tree, backend, q, v, u, want_qacc, want_next, compile_times):
    xp = getattr(ivy, backend)
    x = [xp.asarray(a) for a in (q, v, u)]
    sync = (lambda out: out.block_until_ready()) if backend == "jax" else (lambda out: out)

    def step(qpos, qvel, ctrl):
        qpos1, qvel1 = tree.step(qpos, qvel, ctrl)
        return xp.concat([qpos1, qvel1], axis=-1)

    runs = {}
    for label, fn, want in (
        ("forward dynamics", tree.forward_dynamics, want_qacc),
        ("step", step, want_next),
    ):
        compiled = ivy.compile_fn(fn)
        start = time.perf_counter()
        got = sync(compiled(*x))
        compile_times[f"ivy {backend} {label}"] = time.perf_counter() - start
        got = ivy.to_numpy(got)
        np.testing.assert_allclose(got[: len(want)], want, rtol=1e-9, atol=1e-9, err_msg=label)
        runs[f"ivy {backend} compiled: {label}"] = lambda c=compiled: sync(c(*x))
    return runs


def mjx_runs(model, q, v, u, want_qacc, want_next, compile_times):
    import jax
    from mujoco import mjx

    mx = mjx.put_model(model)
    base = mjx.make_data(mx)

    def make(qi, vi, ui):
        return base.replace(qpos=qi, qvel=vi, ctrl=ui)

    forward = jax.jit(jax.vmap(lambda a, b, c: mjx.forward(mx, make(a, b, c)).qacc))
    step = jax.jit(
        jax.vmap(
            lambda a, b, c: (lambda d: jax.numpy.concatenate([d.qpos, d.qvel]))(
                mjx.step(mx, make(a, b, c))
            )
        )
    )
    x = [jax.numpy.asarray(a) for a in (q, v, u)]
    runs = {}
    for label, fn, want in (("forward dynamics", forward, want_qacc), ("step", step, want_next)):
        start = time.perf_counter()
        got = np.asarray(fn(*x).block_until_ready())
        compile_times[f"MJX {label}"] = time.perf_counter() - start
        error = float(np.abs(got[: len(want)] - want).max())
        compile_times[f"MJX {label} max |error| vs MuJoCo"] = error
        runs[f"MJX (jax.vmap, jit): {label}"] = lambda f=fn: f(*x).block_until_ready()
    return runs


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--batches", default="1,1000,100000")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--backends", default="jax,torch")
    parser.add_argument("--torch-threads", type=int, default=1)
    parser.add_argument("--clock", choices=("wall", "cpu"), default="wall")
    parser.add_argument("--mjx-path", default=None)
    args = parser.parse_args()
    if args.mjx_path:  # before mujoco is imported: mujoco.mjx is found on the path then
        sys.path.append(args.mjx_path)
    import mujoco

    backends = [b for b in args.backends.split(",") if importlib.util.find_spec(b)]
    if "jax" in backends or args.mjx_path:
        import jax

        jax.config.update("jax_enable_x64", True)
    if "torch" in backends:
        import torch

        torch.set_num_threads(args.torch_threads)
    use_mjx = False
    if args.mjx_path:
        try:
            from mujoco import mjx  # noqa: F401

            use_mjx = True
        except ImportError as err:
            print(f"MJX does not import ({err}): its rows are left out\n")
    warnings.filterwarnings("ignore")
    model = mujoco.MjModel.from_xml_path(hopper_path())
    tree = ivy_robot.KinematicTree.from_mjcf(model)
    rng = np.random.default_rng(0)
    clock = time.perf_counter if args.clock == "wall" else time.process_time
    print(
        f"Gymnasium Hopper (nq={model.nq}, nv={model.nv}, nu={model.nu}, {tree.integrator}, "
        f"h={tree.timestep}), float64; torch threads: {args.torch_threads}; clock: "
        f"{args.clock}; load average: {os.getloadavg()[0]:.1f}"
    )
    for batch in (int(b) for b in args.batches.split(",")):
        q, v, u = random_states(model, batch, rng)
        check = min(batch, 50)
        want_qacc, want_next = mujoco_reference(model, q[:check], v[:check], u[:check])
        compile_times = {}
        runs = mujoco_runs(model, q, v, u)
        for backend in backends:
            runs.update(ivy_runs(tree, backend, q, v, u, want_qacc, want_next, compile_times))
        if use_mjx:
            runs.update(mjx_runs(model, q, v, u, want_qacc, want_next, compile_times))
        for fn in runs.values():  # warm-up
            fn(), fn()
        number = max(1, min(50, int(1e4 // batch)))
        repeats = args.repeats if batch < 100000 else max(3, args.repeats // 2)
        samples = interleaved_samples(
            {name: timeit.Timer(fn, timer=clock) for name, fn in runs.items()}, number, repeats
        )
        best = {name: min(s) for name, s in samples.items()}
        mj_forward = best["MuJoCo mj_forward (Python loop)"]
        mj_step = best["MuJoCo rollout (C loop)"]
        print(f"\nbatch {batch:,}: {number} calls per sample, {repeats} samples (minimum)")
        print(f"{'implementation':44s} {'per call':>12s} {'per state':>12s} {'/ MuJoCo':>9s}")
        for name, t in best.items():
            ref = mj_step if ("step" in name or "rollout" in name) else mj_forward
            print(f"{name:44s} {t * 1e6:10.1f}us {t / batch * 1e6:10.3f}us {t / ref:9.2f}")
        for name, t in compile_times.items():
            print(f"  first call (compile) {name}: {t:.3g}" + ("" if "error" in name else " s"))


if __name__ == "__main__":
    main()
