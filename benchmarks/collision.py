"""Collision detection of Gymnasium's Ant and Humanoid: ``ivy_robot.physics.collision.collide``
compiled on jax (``jax.jit``) and torch (``torch.compile``), against MuJoCo's own collision
detection on the CPU (``mj_kinematics`` + ``mj_collision`` in a Python loop over the batch),
measured in the same run.

The states touch the floor: random joint angles inside their ranges, the root turned about the
vertical (the Ant upright, a little tilted; the Humanoid lying down), the root lowered until its lowest geom sinks 0 to 6 cm into the
floor, so that many contacts are found (and the limbs touch each other). Every implementation
is first checked against MuJoCo on the first 32 states (the active candidates, in order, are
``d.contact``'s constraint contacts; distances within 1e-9), then timed after the warm-up call
that compiles: its wall clock is the compile time. For torch, the compile time of a trivial
function in the same run is reported too (the fixed cost of inductor's C++ toolchain, paid
once per compiled graph), so the share of collision detection can be read off.

The implementations of one model take turns (benchmarks/_timing.py: interleaved, shuffled
repeats); the median per call is reported, per state and as a ratio to MuJoCo's (< 1: faster).

Usage:
    .venv/bin/python benchmarks/collision.py [--batch 4096] [--repeats 5]
        [--backends jax,torch] [--models ant,humanoid] [--torch-threads N]
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

from _timing import interleaved_samples, median, relative_spread  # noqa: E402

import ivy  # noqa: E402
from ivy_robot.physics import collision as C  # noqa: E402

CHECKED = 32  # states checked against MuJoCo


def model_path(name: str) -> str:
    import gymnasium

    folder = os.path.join(os.path.dirname(gymnasium.__file__), "envs", "mujoco", "assets")
    return os.path.join(folder, f"{name}.xml")


def _quat(axis, angle) -> np.ndarray:
    axis = np.asarray(axis, np.float64)
    half = angle / 2
    return np.concatenate([[np.cos(half)], np.sin(half) * axis / np.linalg.norm(axis)])


def _mul(q1, q2) -> np.ndarray:
    w1, x1, y1, z1 = q1
    w2, x2, y2, z2 = q2
    return np.array(
        [
            w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
            w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
            w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
            w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
        ]
    )


def _lowest(model, data, geom) -> float:
    """A geom's lowest point (z)."""
    kind, size = model.geom_type[geom], model.geom_size[geom]
    along = data.geom_xmat[geom].reshape(3, 3)[2]  # the world z axis in the geom's frame
    z = data.geom_xpos[geom][2]
    if kind == C.SPHERE:
        return z - size[0]
    if kind == C.CAPSULE:
        return z - size[0] - size[1] * abs(along[2])
    if kind == C.CYLINDER:
        return z - size[0] * np.sqrt(max(0.0, 1 - along[2] ** 2)) - size[1] * abs(along[2])
    return z - np.abs(along) @ size


def touching_states(model, batch: int, rng, lying: bool) -> np.ndarray:
    """Random joint angles in range, the root turned at random about the vertical and tilted
    a little (lying: on its side), then lowered so that its lowest geom sinks 0 to 6 cm into
    the floor."""
    import mujoco

    data = mujoco.MjData(model)
    movers = [g for g in range(model.ngeom) if model.geom_bodyid[g] and model.geom_type[g]]
    free = [j for j in range(model.njnt) if model.jnt_type[j] == 0][0]
    root = model.jnt_qposadr[free]
    q = np.tile(model.qpos0, (batch, 1))
    for i in range(batch):
        for j in range(model.njnt):
            if model.jnt_type[j] == 3 and model.jnt_limited[j]:
                q[i, model.jnt_qposadr[j]] = rng.uniform(*model.jnt_range[j])
        yaw = _quat([0, 0, 1], rng.uniform(0, 2 * np.pi))
        if lying:
            quat = _mul(yaw, _quat([0, 1, 0], 1.5))
        else:  # upright, a little tilted
            quat = _mul(yaw, _quat(rng.normal(size=3), rng.uniform(0, 0.3)))
        q[i, root + 3 : root + 7] = quat / np.linalg.norm(quat)
        q[i, root : root + 2] = rng.normal(size=2)
        data.qpos[:] = q[i]
        mujoco.mj_kinematics(model, data)
        q[i, root + 2] += rng.uniform(-0.06, 0.0) - min(_lowest(model, data, g) for g in movers)
    return q


def mujoco_poses_and_contacts(model, qpos):
    """Geom poses of every state; MuJoCo's contacts of the first CHECKED states."""
    import mujoco

    data = mujoco.MjData(model)
    xpos, xmat, contacts = [], [], []
    for i, q in enumerate(qpos):
        data.qpos[:] = q
        if i < CHECKED:
            mujoco.mj_forward(model, data)
            contacts.append(
                [(tuple(c.geom), c.dist, c.efc_address >= 0) for c in data.contact[: data.ncon]]
            )
        else:
            mujoco.mj_kinematics(model, data)
        xpos.append(np.array(data.geom_xpos))
        xmat.append(np.array(data.geom_xmat).reshape(-1, 3, 3))
    return np.array(xpos), np.array(xmat), contacts


def check(table, got, contacts) -> None:
    """The active candidates, in order, are MuJoCo's constraint contacts (geoms, distances)."""
    dist, active = (np.asarray(ivy.to_numpy(a)) for a in (got.dist, got.active))
    for i, reference in enumerate(contacts):
        want = [(g, d) for g, d, on in reference if on]
        rows = np.flatnonzero(active[i])
        have = [((int(table.geom1[r]), int(table.geom2[r])), dist[i, r]) for r in rows]
        assert [g for g, _ in have] == [g for g, _ in want], f"state {i}: geoms differ"
        assert np.allclose([d for _, d in have], [d for _, d in want], atol=1e-9), f"state {i}"


def mujoco_run(model, qpos):
    """MuJoCo's collision detection over the batch (with the kinematics it needs)."""
    import mujoco

    data = mujoco.MjData(model)

    def run():
        for q in qpos:
            data.qpos[:] = q
            mujoco.mj_kinematics(model, data)
            mujoco.mj_collision(model, data)

    return run


def ivy_run(backend, table, xpos, xmat, contacts, compile_times, label):
    """The compiled collide on ``backend``, checked; its compile time recorded."""
    xp = getattr(ivy, backend)
    pos, mat = xp.asarray(xpos), xp.asarray(xmat)

    def contacts_of(p, m):
        return tuple(C.collide(xp, table, p, m))

    def sync(out):
        if backend == "jax":
            for a in out:
                a.block_until_ready()
        return out

    compiled = ivy.compile_fn(contacts_of)
    start = time.perf_counter()
    got = C.Contacts(*sync(compiled(pos, mat)))
    compile_times[f"{label} ivy {backend}"] = time.perf_counter() - start
    check(table, got, contacts)
    return lambda: sync(compiled(pos, mat))


def trivial_torch_compile() -> float:
    """inductor's fixed cost: the compile time of a one-line function, same shapes' scale."""
    import torch

    x = torch.rand(4096, 14, 3, dtype=torch.float64)
    fn = torch.compile(lambda a: (a * 2 + 1).sum(-1))
    start = time.perf_counter()
    fn(x)
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--batch", type=int, default=4096)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--backends", default="jax,torch")
    parser.add_argument("--models", default="ant,humanoid")
    parser.add_argument("--torch-threads", type=int, default=None)
    args = parser.parse_args()
    import mujoco

    backends = [b for b in args.backends.split(",") if importlib.util.find_spec(b)]
    if "jax" in backends:
        import jax

        jax.config.update("jax_enable_x64", True)
    if "torch" in backends and args.torch_threads:
        import torch

        torch.set_num_threads(args.torch_threads)
    warnings.filterwarnings("ignore", category=UserWarning)
    compile_times: dict[str, float] = {}
    if "torch" in backends:
        compile_times["torch.compile of a trivial function (inductor's fixed cost)"] = (
            trivial_torch_compile()
        )
    rng = np.random.default_rng(0)
    rows = []
    for name in args.models.split(","):
        model = mujoco.MjModel.from_xml_path(model_path(name))
        table = C.read_contact_table(model)
        qpos = touching_states(model, args.batch, rng, lying=name.startswith("humanoid"))
        xpos, xmat, contacts = mujoco_poses_and_contacts(model, qpos)
        found = sum(len(c) for c in contacts) / len(contacts)
        print(
            f"{name}: {table.ncon} candidate contacts in {len(table.kinds)} pair kinds; "
            f"MuJoCo finds {found:.1f} contacts a state (first {CHECKED} states)"
        )
        runs = {"MuJoCo (mj_kinematics + mj_collision, Python loop)": mujoco_run(model, qpos)}
        for backend in backends:
            runs[f"ivy {backend} compiled"] = ivy_run(
                backend, table, xpos, xmat, contacts, compile_times, name
            )
        timers = {k: timeit.Timer(f) for k, f in runs.items()}
        samples = interleaved_samples(timers, number=1, repeats=args.repeats)
        reference = median(samples[next(iter(runs))])
        for k, values in samples.items():
            t = median(values)
            rows.append(
                f"| {name} | {k} | {args.batch} | {t * 1e3:.1f} ms | "
                f"{t / args.batch * 1e9:.0f} ns | {t / reference:.3f} | "
                f"{relative_spread(values):.2f} |"
            )
    print()
    print("| model | implementation | batch | per call | per state | vs MuJoCo | spread |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    print("\n".join(rows))
    print()
    print("| compile (first call, wall clock) | seconds |")
    print("| --- | --- |")
    for k, v in compile_times.items():
        print(f"| {k} | {v:.1f} |")


if __name__ == "__main__":
    main()
