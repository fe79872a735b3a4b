"""A step of Gymnasium's Hopper and Ant with contacts: ivy_robot.physics (MuJoCo's pipeline
written once), compiled on jax and torch, against MuJoCo on the CPU (``mujoco.rollout``:
``mj_step`` looped in C over the batch, one thread) and, where it imports, MJX (``jax.vmap`` of
``mjx.step``, jitted), with the same physics on every side: collision detection, contacts, joint
limits and the Newton solver, measured in the same run.

The states come from MuJoCo itself: each starts at the model's reference pose with Gymnasium's
reset noise and runs 100 to 300 steps of random controls, so the robots stand, fall and lie on
their floor with their contacts and limits active as in training (the full state, the solver's
warm start included, is MuJoCo's ``mjSTATE_INTEGRATION``). Every implementation is first checked
against ``mujoco.rollout``'s next state (1e-8), then timed after a warm-up that compiles (its
wall time is reported). The implementations of one batch size take turns (benchmarks/_timing.py:
interleaved, shuffled repeats); the minimum per call and per state is reported, with the ratio
to MuJoCo's (< 1: faster). ``--memory`` runs each compiled step again in a fresh process and
reports its peak resident memory above the same process at batch 1.

Threads: one intra-op thread by default (``--threads``: XLA's pool and torch's), as MuJoCo's
call runs on one; on a shared machine XLA's pool also made solves up to 100x slower. A torch
step that inductor cannot compile is an error here (``ivy.compile_fn`` would run it eagerly,
with a warning, and its eager time would be reported as compiled). The torch step is compiled
as users compile it: ``ivy.compile_fn`` (which switches on dynamo's ``capture_scalar_outputs``
for its calls: inductor reads the RK4 scan's step with ``.item()``).

MJX is not a dependency of the project: point ``--mjx-path`` at a folder where ``mujoco-mjx``
(and its requirements ``etils``, ``trimesh``) are installed, e.g. ``pip install --no-deps
--target /tmp/mjxpkg mujoco-mjx etils trimesh``; it is appended to ``sys.path``.

Usage:
    .venv/bin/python benchmarks/robot_dynamics.py [--models hopper,ant] [--batches 1000,4096]
        [--repeats 5] [--backends jax,torch] [--threads 1] [--mjx-path DIR] [--memory]
"""

from __future__ import annotations

import argparse
import importlib.util
import os
import subprocess
import sys
import time
import timeit
import warnings

import numpy as np

_HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [_HERE, os.path.join(_HERE, "..")]

from _timing import interleaved_samples  # noqa: E402

import ivy  # noqa: E402
from ivy_robot import physics  # noqa: E402


def model_path(name: str) -> str:
    import gymnasium

    folder = os.path.join(os.path.dirname(gymnasium.__file__), "envs", "mujoco", "assets")
    return os.path.join(folder, f"{name}.xml")


def sample_states(model, batch: int, rng):
    """``(qpos, qvel, qacc_warmstart, ctrl, states)``: ``batch`` states reached by MuJoCo from
    noisy reference poses under random controls (``mujoco.rollout``, then one last ``mj_step``
    each for its warm start), their MuJoCo states (``mjSTATE_FULLPHYSICS``) and a control."""
    import mujoco
    from mujoco import rollout

    spec = mujoco.mjtState.mjSTATE_FULLPHYSICS
    data = mujoco.MjData(model)
    size = mujoco.mj_stateSize(model, spec)
    start = np.zeros((batch, size))
    for k in range(batch):
        mujoco.mj_resetData(model, data)
        data.qpos[:] = model.qpos0 + rng.uniform(-0.1, 0.1, size=model.nq)
        data.qvel[:] = 0.1 * rng.normal(size=model.nv)
        mujoco.mj_getState(model, data, start[k], spec)
    steps = int(rng.integers(100, 300))
    low, high = model.actuator_ctrlrange.T
    controls = rng.uniform(low, high, size=(batch, steps, model.nu))
    states, _ = rollout.rollout(model, data, start, controls)
    qpos, qvel = np.zeros((batch, model.nq)), np.zeros((batch, model.nv))
    warm, final = np.zeros((batch, model.nv)), np.zeros((batch, size))
    for k in range(batch):
        mujoco.mj_setState(model, data, states[k, -1], spec)
        data.ctrl[:] = rng.uniform(low, high)
        mujoco.mj_step(model, data)  # the warm start of the next step, as training carries it
        qpos[k], qvel[k], warm[k] = data.qpos, data.qvel, data.qacc_warmstart
        mujoco.mj_getState(model, data, final[k], spec)
    ctrl = rng.uniform(low, high, size=(batch, model.nu))
    return qpos, qvel, warm, ctrl, final


def mujoco_run(model, states, warm, ctrl):
    """One ``mj_step`` per state, looped in C (``mujoco.rollout``, one thread)."""
    import mujoco
    from mujoco import rollout

    data = mujoco.MjData(model)
    control = ctrl[:, None, :]
    out = np.zeros((len(states), 1, states.shape[1]))

    def step():
        return rollout.rollout(
            model, data, states, control, nstep=1, state=out, initial_warmstart=warm
        )[0]

    return step


def mujoco_next(model, states, warm, ctrl):
    import mujoco
    from mujoco import rollout

    data = mujoco.MjData(model)
    nxt, _ = rollout.rollout(model, data, states, ctrl[:, None, :], initial_warmstart=warm)
    spec = mujoco.mjtState.mjSTATE_FULLPHYSICS
    qpos = np.zeros((len(states), model.nq))
    qvel = np.zeros((len(states), model.nv))
    for k in range(len(states)):
        mujoco.mj_setState(model, data, nxt[k, -1], spec)
        qpos[k], qvel[k] = data.qpos, data.qvel
    return np.concatenate([qpos, qvel], axis=-1)


def ivy_step(model, backend):
    xp = getattr(ivy, backend)

    def step(qpos, qvel, warm, ctrl):
        data = physics.step(xp, model, physics.make_data(xp, model, qpos, qvel, ctrl, None, warm))
        return xp.concat([data.qpos, data.qvel], axis=-1)

    return ivy.compile_fn(step)


def mjx_step(mjmodel):
    import jax
    from mujoco import mjx

    mx = mjx.put_model(mjmodel)
    base = mjx.make_data(mx)

    def one(q, v, w, u):
        d = mjx.step(mx, base.replace(qpos=q, qvel=v, qacc_warmstart=w, ctrl=u))
        return jax.numpy.concatenate([d.qpos, d.qvel])

    return jax.jit(jax.vmap(one))


def _sync(out):
    return out.block_until_ready() if hasattr(out, "block_until_ready") else out


def measure(args, name, batch, backends, use_mjx):
    import mujoco

    mjmodel = mujoco.MjModel.from_xml_path(model_path(name))
    model = physics.read_model(mjmodel)
    rng = np.random.default_rng(batch)
    q, v, w, u, states = sample_states(mjmodel, batch, rng)
    want = mujoco_next(mjmodel, states, w, u)
    runs = {"MuJoCo rollout (C loop, 1 thread)": mujoco_run(mjmodel, states, w, u)}
    compile_times, errors = {}, {}
    for backend in backends:
        xp = getattr(ivy, backend)
        x = [xp.asarray(a) for a in (q, v, w, u)]
        compiled = ivy_step(model, backend)
        start = time.perf_counter()
        got = ivy.to_numpy(_sync(compiled(*x)))
        compile_times[f"ivy {backend}"] = time.perf_counter() - start
        errors[f"ivy {backend}"] = float(np.abs(got - want).max())
        np.testing.assert_allclose(got, want, rtol=1e-8, atol=1e-8, err_msg=backend)
        runs[f"ivy {backend} compiled"] = lambda c=compiled, x=x: _sync(c(*x))
    if use_mjx:
        import jax.numpy as jnp

        fn = mjx_step(mjmodel)
        x = [jnp.asarray(a) for a in (q, v, w, u)]
        start = time.perf_counter()
        got = np.asarray(_sync(fn(*x)))
        compile_times["MJX"] = time.perf_counter() - start
        errors["MJX"] = float(np.abs(got - want).max())
        runs["MJX (vmap, jit)"] = lambda f=fn, x=x: _sync(f(*x))
    for fn in runs.values():  # warm-up
        fn(), fn()
    number = max(1, min(20, int(2e3 // batch)))
    samples = interleaved_samples(
        {k: timeit.Timer(fn) for k, fn in runs.items()}, number, args.repeats
    )
    best = {k: min(s) for k, s in samples.items()}
    reference = best["MuJoCo rollout (C loop, 1 thread)"]
    print(f"\n{name}, batch {batch:,}: {number} calls per sample, {args.repeats} samples (min)")
    print(f"{'implementation':36s} {'per call':>12s} {'per state':>12s} {'/ MuJoCo':>9s}")
    for k, t in best.items():
        print(f"{k:36s} {t * 1e3:10.2f}ms {t / batch * 1e6:10.2f}us {t / reference:9.2f}")
    for k, t in compile_times.items():
        print(f"  first call (trace and compile) {k}: {t:.1f} s; max |error| {errors[k]:.1e}")


def memory(args, name, backend, batch):
    """Peak resident memory (MB) of a process that compiles and runs the step once."""
    root = os.path.join(_HERE, "..")
    code = (
        f"import sys, resource; sys.path[:0] = [{_HERE!r}, {root!r}]; "
        f"import robot_dynamics as b; b._memory_child({name!r}, {backend!r}, {batch}, "
        f"{args.threads}); print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    if out.returncode:
        raise RuntimeError(out.stderr[-2000:])
    return int(out.stdout.strip().splitlines()[-1]) / 1024


def _memory_child(name, backend, batch, threads=1):
    import mujoco

    _set_threads(threads, [backend])

    if backend == "jax":
        import jax

        jax.config.update("jax_enable_x64", True)
    _warnings()
    mjmodel = mujoco.MjModel.from_xml_path(model_path(name))
    model = physics.read_model(mjmodel)
    xp = getattr(ivy, backend)
    x = [
        xp.asarray(np.tile(a, (batch, 1)))
        for a in (mjmodel.qpos0, np.zeros(mjmodel.nv), np.zeros(mjmodel.nv), np.zeros(mjmodel.nu))
    ]
    compiled = ivy_step(model, backend)
    for _ in range(2):
        _sync(compiled(*x))


def _set_threads(threads: int, backends) -> None:
    """``threads`` intra-op threads (0: the libraries' defaults) for each of ``backends``
    (:func:`ivy.set_threads`: XLA's flags, set before jax starts, and torch's pool)."""
    for name in backends:
        if threads and importlib.util.find_spec(name):
            ivy.set_threads(name, threads)


def _warnings():
    warnings.filterwarnings("ignore")
    warnings.filterwarnings("error", message="torch.compile cannot run")  # no eager fallback


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--models", default="hopper,ant")
    parser.add_argument("--batches", default="1000,4096")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--backends", default="jax,torch")
    parser.add_argument("--threads", type=int, default=1, help="intra-op threads (0: default)")
    parser.add_argument("--mjx-path", default=None)
    parser.add_argument("--memory", action="store_true")
    args = parser.parse_args()
    if args.mjx_path:  # before mujoco is imported: mujoco.mjx is found on the path then
        sys.path.append(args.mjx_path)
    backends = [b for b in args.backends.split(",") if importlib.util.find_spec(b)]
    _set_threads(args.threads, {*backends, *(["jax"] if args.mjx_path else [])})
    if "jax" in backends or args.mjx_path:
        import jax

        jax.config.update("jax_enable_x64", True)
    use_mjx = False
    if args.mjx_path:
        try:
            from mujoco import mjx  # noqa: F401

            use_mjx = True
        except ImportError as err:
            print(f"MJX does not import ({err}): its rows are left out\n")
    _warnings()
    print(
        f"float64; intra-op threads: {args.threads or 'default'}; load average "
        f"{os.getloadavg()[0]:.1f}; {os.cpu_count()} cores"
    )
    for name in args.models.split(","):
        for batch in (int(b) for b in args.batches.split(",")):
            measure(args, name, batch, backends, use_mjx)
        if args.memory:
            largest = max(int(b) for b in args.batches.split(","))
            for backend in backends:
                base = memory(args, name, backend, 1)
                peak = memory(args, name, backend, largest)
                print(f"  peak memory, {name} {backend} batch {largest:,}: {peak:.0f} MB "
                      f"({peak - base:+.0f} MB over batch 1)")  # fmt: skip


if __name__ == "__main__":
    main()
