"""Forward kinematics of a 7-DOF arm: ivy_robot's KinematicTree on every installed backend
(eager and compiled) against a loop of MuJoCo's ``mj_kinematics`` and against
pytorch_kinematics on torch, measured in the same run.

The arm is ivy_robot's Panda (``ivy_robot.panda_mjcf()``: 10 bodies, 7 hinges), in float64. For
each batch size (default 1, 1,000 and 100,000 configurations) every implementation computes the
world poses of all bodies; each result is first checked against ``mj_kinematics`` (1e-10; 1e-6
for pytorch_kinematics, whose frames are built from float32 values). After a warm-up (which also
compiles: jax.jit, tf.function, torch.compile), the implementations of one batch size take turns
(benchmarks/_timing.py: interleaved, shuffled repeats). The minimum over the repeats is reported,
per call and per configuration, with the ratio to the ``mj_kinematics`` loop and to
pytorch_kinematics (< 1: faster).

pytorch_kinematics is a benchmark-only dependency: ``.venv/bin/pip install pytorch_kinematics``
(it does not change torch). Its MJCF reader keys MuJoCo's joint types by enum, which MuJoCo 4's
joint views no longer match; this script patches that table at run time (``_patch_pk``), nothing
on disk. Without it the pytorch_kinematics rows are left out and the run says so.

torch runs single-threaded by default (``--torch-threads``), like MuJoCo's loop, and so that a
shared machine's load disturbs it less. ``--clock cpu`` times with the process's CPU time
(``time.process_time``, all threads) instead of the wall clock: on a loaded machine it leaves
out the time the process waits for a core.

``--device gpu:0`` puts every backend's configurations on that device (``xp.asarray(...,
device=...)``; ``forward_kinematics`` follows its input) and pytorch_kinematics' chain too; on jax
MuJoCo's MJX (``mujoco.mjx``, ``jax.vmap`` of ``mjx.kinematics`` under ``jax.jit``) joins as a peer
where it installs. numpy and the ``mj_kinematics`` loop stay on the CPU; on batches over 10,000
the loop runs over the first 10,000 configurations and its per-call time is scaled to the batch
(marked ``*``). The issue's GPU size: ``--device gpu:0 --batches 1000000 --backends torch,jax``.

Usage:
    .venv/bin/python benchmarks/robot_kinematics.py [--batches 1,1000,100000] [--repeats 7]
        [--backends numpy,torch,jax,tensorflow] [--torch-threads 1] [--clock wall|cpu]
        [--device cpu|gpu:0]
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

XML = ivy_robot.panda_mjcf()


def _mujoco_reference(qpos):
    import mujoco

    model = mujoco.MjModel.from_xml_string(XML)
    data = mujoco.MjData(model)
    out = np.zeros((len(qpos), model.nbody, 3))
    for k, q in enumerate(qpos):
        data.qpos[:] = q
        mujoco.mj_kinematics(model, data)
        out[k] = data.xpos
    return out


def _mujoco_loop():
    import mujoco

    model = mujoco.MjModel.from_xml_string(XML)
    data = mujoco.MjData(model)

    def run(qpos):
        for q in qpos:
            data.qpos[:] = q
            mujoco.mj_kinematics(model, data)
        return data.xpos

    return run


def _patch_pk(pk):
    """MuJoCo 4's joint views give numpy ints that pytorch_kinematics' enum-keyed table misses."""
    table = pk.mjcf.JOINT_TYPE_MAP
    pk.mjcf.JOINT_TYPE_MAP = {int(k): v for k, v in table.items()}


def _torch_device(device):
    kind, _, index = device.partition(":")
    return "cpu" if kind == "cpu" else f"cuda:{index or 0}"


def _pytorch_kinematics(device="cpu"):
    if importlib.util.find_spec("pytorch_kinematics") is None:
        return None
    import pytorch_kinematics as pk
    import torch

    _patch_pk(pk)
    chain = pk.build_chain_from_mjcf(XML).to(dtype=torch.float64, device=_torch_device(device))
    names = chain.get_frame_names(exclude_fixed=False)

    def run(q):
        return chain.forward_kinematics(q)

    return run, names


def _mjx(device):
    """MuJoCo's MJX forward kinematics, vmapped and jitted on ``device``; None if missing."""
    if importlib.util.find_spec("mujoco") is None or importlib.util.find_spec("mujoco.mjx") is None:
        return None
    import jax
    import mujoco
    from mujoco import mjx

    kind, _, index = device.partition(":")
    dev = jax.devices("cpu" if kind == "cpu" else "gpu")[int(index or 0)]
    model = jax.device_put(mjx.put_model(mujoco.MjModel.from_xml_string(XML)), dev)
    data = jax.device_put(mjx.make_data(model), dev)

    @jax.jit
    def run(qpos):
        return jax.vmap(lambda q: mjx.kinematics(model, data.replace(qpos=q)).xpos)(qpos)

    return lambda qpos: run(jax.device_put(qpos, dev)), lambda qpos: jax.device_put(qpos, dev)


def _sync(backend):
    if backend == "jax":
        return lambda out: out.block_until_ready()
    if backend == "torch":
        import torch

        if torch.cuda.is_available():
            return lambda out: (torch.cuda.synchronize(), out)[1]
    return lambda out: out


LOOP_CAP = 10_000


def installed_backends(names: str, torch_threads: int) -> list[str]:
    """The installed backends among ``names`` (comma-separated), set up for these benchmarks:
    jax in float64, torch with ``torch_threads`` threads."""
    backends = [b for b in names.split(",") if importlib.util.find_spec(b)]
    if "jax" in backends:
        import jax

        jax.config.update("jax_enable_x64", True)
    if "torch" in backends:
        import torch

        torch.set_num_threads(torch_threads)
    return backends


def build(backends, batch, rng, device="cpu"):
    """name -> (function of no argument, scale of its time to the batch), all on the same
    configurations, each checked against ``mj_kinematics`` first."""
    tree = ivy_robot.KinematicTree.from_mjcf(XML)
    qpos = rng.uniform(tree.qpos_lower, tree.qpos_upper, size=(batch, tree.nq))
    want = _mujoco_reference(qpos[: min(batch, 200)])
    runs = {}
    for backend in backends:
        xp = getattr(ivy, backend)
        where = "cpu" if backend == "numpy" else device
        x, sync = xp.asarray(qpos, device=where), _sync(backend)
        fns = {f"{backend} eager": tree.forward_kinematics}
        if backend != "numpy":
            fns[f"{backend} compiled"] = ivy.compile_fn(tree.forward_kinematics)
        for name, fn in fns.items():
            got = ivy.to_numpy(fn(x))[: len(want), :, :3, 3]
            np.testing.assert_allclose(got, want, atol=1e-10, err_msg=name)
            runs[name] = (lambda fn=fn, x=x, sync=sync: sync(fn(x)), 1.0)
    loop, looped = _mujoco_loop(), qpos[:LOOP_CAP]
    runs["mj_kinematics loop"] = (lambda: loop(looped), batch / len(looped))
    pk = _pytorch_kinematics(device) if "torch" in backends else None
    if pk is not None:
        import torch

        run, names = pk
        tq, sync = torch.tensor(qpos, device=_torch_device(device)), _sync("torch")
        frames = run(tq)
        got = np.stack(
            [
                frames[n].get_matrix()[: len(want)].cpu().numpy()[:, :3, 3]
                for n in tree.body_names[2:]
            ],
            1,
        )
        np.testing.assert_allclose(got, want[:, 2:], atol=1e-6, err_msg="pk")
        runs["pytorch_kinematics (torch)"] = (lambda: sync(run(tq)), 1.0)
    mjx_fk = _mjx(device) if "jax" in backends else None
    if mjx_fk is not None:
        run, put = mjx_fk
        jq = put(qpos)
        got = np.asarray(run(jq))[: len(want)]
        # MJX computes in float32 unless jax's x64 reaches its model: a float32 tolerance
        np.testing.assert_allclose(got, want, atol=1e-5, err_msg="mjx")
        runs["MJX (jax)"] = (lambda: run(jq).block_until_ready(), 1.0)
    return runs


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--batches", default="1,1000,100000")
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--backends", default="numpy,torch,jax,tensorflow")
    parser.add_argument("--torch-threads", type=int, default=1)
    parser.add_argument("--clock", choices=("wall", "cpu"), default="wall")
    parser.add_argument("--device", default="cpu", help="'cpu' or 'gpu:0' (CUDA)")
    args = parser.parse_args()
    backends = installed_backends(args.backends, args.torch_threads)
    if "torch" in backends and importlib.util.find_spec("pytorch_kinematics") is None:
        print("pytorch_kinematics is not installed: its rows are left out "
              "(pip install pytorch_kinematics)\n")  # fmt: skip
    warnings.filterwarnings("ignore", category=UserWarning)
    rng = np.random.default_rng(0)
    clock = time.perf_counter if args.clock == "wall" else time.process_time
    print(
        f"Panda FK (10 bodies, 7 hinges), float64; torch threads: {args.torch_threads}; "
        f"clock: {args.clock}; device: {args.device}; load average: {os.getloadavg()[0]:.1f}"
    )
    for batch in (int(b) for b in args.batches.split(",")):
        runs = build(backends, batch, rng, args.device)
        scale = {name: s for name, (_, s) in runs.items()}
        runs = {name: fn for name, (fn, _) in runs.items()}
        for fn in runs.values():  # warm-up: compilation, caches
            fn(), fn()
        number = max(1, min(100, int(2e4 // batch)))
        repeats = args.repeats if batch < 100000 else max(3, args.repeats // 2)
        samples = interleaved_samples(
            {name: timeit.Timer(fn, timer=clock) for name, fn in runs.items()}, number, repeats
        )
        best = {name: min(v) * scale[name] for name, v in samples.items()}
        mj = best["mj_kinematics loop"]
        pk = best.get("pytorch_kinematics (torch)")
        print(f"\nbatch {batch:,}: {number} calls per sample, {repeats} samples (minimum)")
        head = f"{'implementation':28s} {'per call':>12s} {'per config':>12s} {'/ mj loop':>10s}"
        print(head + (f" {'/ pk':>8s}" if pk else ""))
        for name, t in best.items():
            name = name + ("*" if scale[name] != 1.0 else "")
            line = f"{name:28s} {t * 1e6:10.1f}us {t / batch * 1e6:10.3f}us {t / mj:10.2f}"
            print(line + (f" {t / pk:8.2f}" if pk else ""))


if __name__ == "__main__":
    main()
