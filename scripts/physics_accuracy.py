"""How closely ``ivy_robot.physics`` follows MuJoCo on Gymnasium's models, as a table.

    python scripts/physics_accuracy.py [--steps 1000] [--backend numpy] [--models hopper,ant]

For each model, MuJoCo runs ``--steps`` steps from ``qpos0`` plus Gymnasium-sized reset noise
under uniformly random controls (the robots fall, land, walk into their limits); every state on
that trajectory, with MuJoCo's warm start, is then given to ivy in one batch:

- ``qacc``: ivy's ``forward`` against ``mj_forward``'s, largest absolute difference and largest
  relative to the state's largest entry;
- ``step``: ivy's ``step`` against ``mj_step``'s ``qpos``, ``qvel`` and ``qacc_warmstart``;
- ``free run``: ivy's own trajectory from the same start under the same controls, each step from
  its own last state (the warm start carried as MuJoCo carries it): the largest difference of
  ``qpos`` from MuJoCo's over the first 100 steps and over all, and the first step where it
  exceeds 1e-6. Contacts make
  the dynamics chaotic: rounding apart at one step grows, as between two MuJoCo builds.

The states counted as "with contacts" have at least one active contact in ``mj_forward``;
"at limits" at least one joint-limit row.
"""

from __future__ import annotations

import argparse
import os

import numpy as np

MODELS = ("hopper", "walker2d_v5", "half_cheetah", "ant", "swimmer", "humanoid", "reacher",
          "inverted_pendulum", "inverted_double_pendulum")  # fmt: skip


def _trajectory(mjm, steps, rng):
    """MuJoCo's trajectory under random controls: the states (with warm starts) and the
    results of ``mj_forward`` and ``mj_step`` at each."""
    import mujoco

    d = mujoco.MjData(mjm)
    d.qpos[:] = mjm.qpos0 + rng.uniform(-0.1, 0.1, mjm.nq)
    d.qvel[:] = 0.1 * rng.standard_normal(mjm.nv)
    lo, hi = mjm.actuator_ctrlrange.T
    keys = ("qpos", "qvel", "ctrl", "warm", "qacc", "qpos1", "qvel1", "warm1", "contacts",
            "limits")  # fmt: skip
    out = {k: [] for k in keys}
    for _ in range(steps):
        d.ctrl[:] = rng.uniform(lo, hi)
        state = (d.qpos.copy(), d.qvel.copy(), d.ctrl.copy(), d.qacc_warmstart.copy())
        mujoco.mj_forward(mjm, d)
        types = np.asarray(d.efc_type[: d.nefc])
        limits = int(np.sum(types == int(mujoco.mjtConstraint.mjCNSTR_LIMIT_JOINT)))
        contacts = int(np.sum(d.contact.exclude[: d.ncon] == 0)) if d.ncon else 0
        qacc = d.qacc.copy()
        d.qacc_warmstart[:] = state[3]  # mj_forward wrote it: the step starts where it did
        mujoco.mj_step(mjm, d)
        for k, x in zip(keys, (*state, qacc, d.qpos.copy(), d.qvel.copy(),
                               d.qacc_warmstart.copy(), contacts, limits)):  # fmt: skip
            out[k].append(x)
    return {k: np.asarray(v) for k, v in out.items()}


def _gap(got, want):
    """Largest absolute difference, and largest relative to each state's largest entry."""
    got, want = np.asarray(got, np.float64), np.asarray(want, np.float64)
    diff = np.abs(got - want)
    scale = np.maximum(np.abs(want).max(axis=-1, keepdims=True), 1.0)
    return float(diff.max()), float((diff / scale).max())


def measure(name, steps, xp, seed=0):
    import mujoco

    from ivy_robot import physics

    path = os.path.join(_assets(), f"{name}.xml")
    mjm = mujoco.MjModel.from_xml_path(path)
    model = physics.read_model(mjm)
    rng = np.random.default_rng(seed)
    ref = _trajectory(mjm, steps, rng)
    data = physics.make_data(xp, model, ref["qpos"], ref["qvel"], ref["ctrl"],
                             qacc_warmstart=ref["warm"])  # fmt: skip
    forward, step = physics.forward, physics.step  # (compiled once per model on jax)
    after = step(xp, model, data)
    qacc = forward(xp, model, data).qacc
    row = {
        "model": name,
        "solver": "PGS" if int(mjm.opt.solver) == int(mujoco.mjtSolver.mjSOL_PGS) else "Newton",
        "states": steps,
        "with contacts": int(np.sum(ref["contacts"] > 0)),
        "at limits": int(np.sum(ref["limits"] > 0)),
        "qacc": _gap(_np(qacc), ref["qacc"]),
        "step": max(
            _gap(_np(after.qpos), ref["qpos1"]),
            _gap(_np(after.qvel), ref["qvel1"]),
            _gap(_np(after.qacc_warmstart), ref["warm1"]),
        ),
    }
    state = physics.make_data(xp, model, ref["qpos"][0], ref["qvel"][0], ref["ctrl"][0],
                              qacc_warmstart=ref["warm"][0])  # fmt: skip
    apart, first = [], None
    for t in range(steps):
        state = step(xp, model, state.replace(ctrl=xp.asarray(ref["ctrl"][t])))
        gap = float(np.abs(_np(state.qpos) - ref["qpos1"][t]).max())
        apart.append(gap)
        if first is None and gap > 1e-6:
            first = t + 1
    row["free run"] = (max(apart[:100]), max(apart), first)
    return row


def _np(x):
    import ivy

    return np.asarray(ivy.to_numpy(x))


def _assets():
    import gymnasium

    return os.path.join(os.path.dirname(gymnasium.__file__), "envs", "mujoco", "assets")


def table(rows):
    lines = [
        "| model | solver | states (with contacts, at limits) | qacc abs | qacc rel | step abs "
        "| step rel | free run: qpos, 100 steps | all steps | first step beyond 1e-6 |",
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for r in rows:
        lines.append(
            f"| {r['model']} | {r['solver']} | {r['states']} ({r['with contacts']}, "
            f"{r['at limits']}) | {r['qacc'][0]:.0e} | {r['qacc'][1]:.0e} | {r['step'][0]:.0e} "
            f"| {r['step'][1]:.0e} | {r['free run'][0]:.0e} | {r['free run'][1]:.0e} | {r['free run'][2] or 'none'} |"
        )
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--steps", type=int, default=1000)
    parser.add_argument("--backend", default="numpy")
    parser.add_argument("--models", default=",".join(MODELS))
    args = parser.parse_args()
    import ivy

    if args.backend == "jax":
        import jax

        jax.config.update("jax_enable_x64", True)
    xp = getattr(ivy, args.backend)
    rows = []
    for name in args.models.split(","):
        rows.append(measure(name, args.steps, xp))
        print(table(rows[-1:]).splitlines()[-1], flush=True)
    print()
    print(table(rows))


if __name__ == "__main__":
    main()
