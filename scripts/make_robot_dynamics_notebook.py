"""Write ``notebooks/robot_dynamics.ipynb`` from the cells below (run it after editing them):

    python scripts/make_robot_dynamics_notebook.py [--execute]

``--execute`` runs it once (the first cell's defaults: jax, 32 restarts, 60 + 60 swing-up and
800 reacher iterations: about 20 minutes on one core) and saves it with its outputs.

The notebook: the double pendulum's dynamics against MuJoCo, its swing-up by optimising actions
through rollouts, and a Reacher-v5 policy learned through rollouts and run in Gymnasium's MuJoCo
environment.
"""

from __future__ import annotations

from _notebooks import write_notebook  # scripts/ is on the path of `python scripts/...`

CELLS: list[tuple[str, str]] = []
CELLS.append(
    (
        "markdown",
        r"""
# Rigid-body dynamics written once: a double pendulum and a reacher learned through gradients

`ivy_robot.KinematicTree` computes MuJoCo's dynamics (mass matrix, bias, passive and actuator
forces, forward and inverse dynamics, RK4 and Euler steps) on ivy's API, so the same code
differentiates on torch, jax and tensorflow. `ivy_gym` builds Gymnasium's MuJoCo tasks on it,
step for step. This notebook:

1. checks the dynamics of Gymnasium's `inverted_double_pendulum.xml` against MuJoCo itself;
2. swings the double pendulum up from hanging down and holds it, by optimising an open-loop
   action sequence through differentiable rollouts with second-order steps
   (`ivy_gym.optimise_actions_least_squares`);
3. learns a policy for Gymnasium's `Reacher-v5` through differentiable rollouts
   (`ivy_gym.optimise_policy`), then runs it in Gymnasium's own MuJoCo environment.

Choose the backend in the first cell. The tests run this notebook with a tiny budget through the
environment variables below; the outputs stored here are those of the full budget on jax.
""".strip("\n"),
    )
)

CELLS.append(
    (
        "code",
        r"""
# Parameters: the backend (torch, jax or tensorflow: numpy has no gradients) and the budgets.
import os

BACKEND = os.environ.get("DYNAMICS_NOTEBOOK_BACKEND", "jax")
RESTARTS = int(os.environ.get("DYNAMICS_NOTEBOOK_RESTARTS", "32"))
SWING_ITERATIONS = int(os.environ.get("DYNAMICS_NOTEBOOK_SWING_ITERATIONS", "60"))  # per stage
REACHER_ITERATIONS = int(os.environ.get("DYNAMICS_NOTEBOOK_REACHER_ITERATIONS", "800"))

import matplotlib

matplotlib.use("Agg")  # headless: figures are rendered to PNG and shown with display()
""".strip("\n"),
    )
)

CELLS.append(
    (
        "code",
        r"""
import io
import pathlib
import time

import gymnasium
import matplotlib.pyplot as plt
import mujoco
import numpy as np
from IPython.display import Image, display

import ivy
import ivy_gym

if BACKEND == "jax":
    import jax

    jax.config.update("jax_enable_x64", True)  # float64 for the check against MuJoCo

xp = getattr(ivy, BACKEND)
print(f"backend: {BACKEND} | restarts: {RESTARTS} | swing-up iterations: {SWING_ITERATIONS} | "
      f"reacher iterations: {REACHER_ITERATIONS}")


def show(fig):
    # render the figure with Agg to PNG and display it (no GUI needed)
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=80, bbox_inches="tight")
    plt.close(fig)
    display(Image(buffer.getvalue()))
""".strip("\n"),
    )
)

CELLS.append(
    (
        "markdown",
        r"""
## 1. The dynamics against MuJoCo

The tree is read from Gymnasium's own `inverted_double_pendulum.xml`: a cart on a slider (a
motor of gear 500 drives it) and two hinged poles of 0.6 m. At random states, ivy's mass matrix
and forward dynamics (the accelerations `qacc` under a control) are compared with MuJoCo's
`mj_fullM` and `mj_forward` in float64.
""".strip("\n"),
    )
)

CELLS.append(
    (
        "code",
        r"""
tree = ivy_gym.inverted_double_pendulum_tree()
xml = pathlib.Path(gymnasium.__file__).parent / "envs" / "mujoco" / "assets" / "inverted_double_pendulum.xml"
model = mujoco.MjModel.from_xml_path(str(xml))
data = mujoco.MjData(model)

rng = np.random.default_rng(0)
qpos = rng.uniform([-0.5, -np.pi, -np.pi], [0.5, np.pi, np.pi], (16, 3))
qvel = rng.uniform(-3.0, 3.0, (16, 3))
ctrl = rng.uniform(-1.0, 1.0, (16, 1))

expected_qacc, expected_mass = [], []
for q, v, c in zip(qpos, qvel, ctrl):
    data.qpos[:], data.qvel[:], data.ctrl[:] = q, v, c
    mujoco.mj_forward(model, data)
    mass = np.zeros((model.nv, model.nv))
    mujoco.mj_fullM(model, data, mass)
    expected_qacc.append(data.qacc.copy())
    expected_mass.append(mass)

q, v, c = (xp.asarray(a) for a in (qpos, qvel, ctrl))
qacc = ivy.to_numpy(tree.forward_dynamics(q, v, c))
mass = ivy.to_numpy(tree.mass_matrix(q))
print(tree)
print(f"largest difference to MuJoCo over 16 states: qacc {np.abs(qacc - expected_qacc).max():.1e}, "
      f"mass matrix {np.abs(mass - expected_mass).max():.1e}")
""".strip("\n"),
    )
)

CELLS.append(
    (
        "markdown",
        r"""
## 2. Swinging the double pendulum up

`InvertedDoublePendulum(swing_up=True)` starts hanging down (with Gymnasium's reset noise) and
never terminates. The cart must stay within the slider's range (where the model is faithful: the
slider's limit is outside the tree's scope). A step is 0.05 s (five RK4 steps of 0.01 s, as
Gymnasium's).

Adam on the return through the rollout (`ivy_gym.optimise_actions`) does not solve this task:
the return's gradient vanishes at the hanging state and explodes once the poles whirl
(`docs/ivy_gym.md` lists what was tried). Second-order steps do.
`ivy_gym.optimise_actions_least_squares` takes Levenberg-Marquardt steps on a least-squares
objective of the rollout, each from the Jacobian of its residuals through the rollout, from
`RESTARTS` hanging states at once, each its own optimisation. In two stages:

1. reach: 40 actions (2 s) for the residuals of the last state alone
   (`env.swing_up_residuals(traj, hold=1)`: the poles upright and still, the cart centred);
2. hold: those actions extended by 10 zero actions, optimised again for the residuals of the
   last 10 states (0.5 s held upright).

A restart counts as solved when, replayed, both poles stay within 18 degrees of upright over the
last 10 steps and the cart within 1 m of the centre throughout.
""".strip("\n"),
    )
)

CELLS.append(
    (
        "code",
        r"""
env = ivy_gym.InvertedDoublePendulum(swing_up=True)
REACH, HOLD = 40, 10  # steps of 0.05 s


def tip_heights(states):
    return 0.6 * np.cos(states[..., 1]) + 0.6 * np.cos(states[..., 1] + states[..., 2])


start = time.perf_counter()
reach = ivy_gym.optimise_actions_least_squares(
    env, REACH, SWING_ITERATIONS, lambda traj: env.swing_up_residuals(traj, hold=1),
    batch_shape=(RESTARTS,), seed=0, f=BACKEND,
)
logits = ivy.to_numpy(reach.variables)
logits = np.concatenate([logits, np.zeros((HOLD, *logits.shape[1:]), logits.dtype)])
swing = ivy_gym.optimise_actions_least_squares(
    env, REACH + HOLD, SWING_ITERATIONS, lambda traj: env.swing_up_residuals(traj, hold=HOLD),
    initial_state=reach.initial_state, initial_logits=logits, f=BACKEND,
)
seconds = time.perf_counter() - start
trajectory = ivy_gym.rollout(env, swing.initial_state, swing.actions)
states = np.asarray(ivy.to_numpy(trajectory.states), np.float64)  # (steps, restarts, 6)
tips = tip_heights(states)
last = states[-HOLD:]
upright = (np.cos(last[..., 1]) > 0.95) & (np.cos(last[..., 1] + last[..., 2]) > 0.95)
solved = upright.all(axis=0) & (np.abs(states[..., 0]).max(axis=0) < 1.0)
best = int(np.argmin(swing.costs))
print(f"{2 * SWING_ITERATIONS} Levenberg-Marquardt iterations in {seconds:.0f} s, compilation "
      f"included; lowest final cost {swing.costs[best]:.3f}")
print(f"best restart: lowest tip over the last {HOLD} steps {tips[-HOLD:, best].min():.2f} m "
      f"(upright: 1.2 m), cart within {np.abs(states[:, best, 0]).max():.2f} m of the centre")
print(f"solved: {int(solved.sum())} of {RESTARTS} restarts")
""".strip("\n"),
    )
)

CELLS.append(
    (
        "markdown",
        r"""
The tip's height and the cart's position over time for every restart: solved ones in blue, the
others in grey.
""".strip("\n"),
    )
)

CELLS.append(
    (
        "code",
        r"""
time_s = np.arange(1, REACH + HOLD + 1) * 0.05
fig, (left, right) = plt.subplots(1, 2, figsize=(11, 3.2))
for ax, values, label in ((left, tips, "tip height (m)"), (right, states[..., 0], "cart x (m)")):
    ax.plot(time_s, values[:, ~solved], color="0.8", linewidth=0.8)
    ax.plot(time_s, values[:, solved], color="tab:blue", linewidth=1.5)
    ax.axvspan(REACH * 0.05, (REACH + HOLD) * 0.05, color="tab:green", alpha=0.1)
    ax.set_xlabel("time (s)")
    ax.set_ylabel(label)
left.axhline(1.2, color="k", linestyle=":", linewidth=1)
left.set_title("tip height; the held window shaded")
right.set_title("cart position")
show(fig)
""".strip("\n"),
    )
)

CELLS.append(
    (
        "code",
        r"""
frames = ivy_gym.render_trajectory(env, trajectory.states[:, best], width=160, height=140)
picks = np.linspace(0, len(frames) - 1, 8).astype(int)
fig, axes = plt.subplots(1, len(picks), figsize=(2 * len(picks), 2))
for ax, k in zip(axes, picks):
    ax.imshow(frames[k])
    ax.set_title(f"{(k + 1) * 0.05:.2f} s", fontsize=8)
    ax.axis("off")
show(fig)
""".strip("\n"),
    )
)

CELLS.append(
    (
        "markdown",
        r"""
## 3. A reacher policy learned through gradients

`ivy_gym.ReacherMuJoCo` is Gymnasium's `Reacher-v5` (the same observations, rewards and seeded
resets, to 1e-8 in float64). A 64-64 MLP policy (tanh) is optimised with Adam through rollouts
of the whole 50-step episode: at each iteration a fresh batch of 64 initial states (arm and
target drawn as Gymnasium draws them) and minus the mean return as the loss. Then the policy
drives Gymnasium's own MuJoCo environment, `gymnasium.make("Reacher-v5")`, for 20 seeded
episodes, against uniformly random actions. A return is about -43 for random actions and about
-4 for a policy that reaches the target and stays there.
""".strip("\n"),
    )
)

CELLS.append(
    (
        "code",
        r"""
reacher = ivy_gym.ReacherMuJoCo()
ivy.seed(0, f=BACKEND)
policy = ivy.MLP(reacher.observation_dim, (64, 64), reacher.action_dim, activation="tanh",
                 output_activation="tanh", f=BACKEND)
start = time.perf_counter()
learned = ivy_gym.optimise_policy(
    reacher, policy, 50, REACHER_ITERATIONS, batch_size=64, lr=3e-3, max_grad_norm=10.0, seed=0
)
policy.v = learned.variables
print(f"mean return over 64 episodes: {learned.returns[0]:.2f} -> {learned.final_return:.2f} in "
      f"{REACHER_ITERATIONS} iterations, {time.perf_counter() - start:.0f} s")

mujoco_env = gymnasium.make("Reacher-v5")
episodes = {"learned policy": [], "random actions": []}
for seed in range(20):
    for name in episodes:
        obs, _ = mujoco_env.reset(seed=seed)
        mujoco_env.action_space.seed(seed)
        total, done = 0.0, False
        while not done:
            if name == "learned policy":
                action = ivy.to_numpy(policy(xp.asarray(obs.astype(np.float32)))).astype(np.float32)
            else:
                action = mujoco_env.action_space.sample()
            obs, reward, terminated, truncated, _ = mujoco_env.step(action)
            total += reward
            done = terminated or truncated
        episodes[name].append(total)
for name, totals in episodes.items():
    print(f"Gymnasium Reacher-v5 (MuJoCo), {name}: return {np.mean(totals):.2f} +- "
          f"{np.std(totals):.2f} over 20 episodes")
""".strip("\n"),
    )
)

CELLS.append(
    (
        "code",
        r"""
fig, ax = plt.subplots(figsize=(5, 3))
ax.plot(learned.returns)
ax.set_xlabel("iteration")
ax.set_ylabel("mean return of the batch")
ax.set_title("Reacher-v5 policy through differentiable rollouts")
show(fig)
""".strip("\n"),
    )
)

CELLS.append(
    (
        "markdown",
        r"""
## What this shows

- The dynamics equal MuJoCo's to rounding (section 1), so a trajectory or a policy optimised on
  them transfers to MuJoCo: the reacher's policy, learned only through ivy's gradients, scores in
  Gymnasium's MuJoCo environment what it scored in training.
- The gradient of a whole episode is informative where the task is smooth: the reacher learns
  from 64 episodes per iteration, with no value function and no exploration noise.
- The double pendulum's swing-up is the hard case for gradients. Adam on the return fails: its
  gradient vanishes at the hanging state and explodes once the poles whirl. Levenberg-Marquardt
  steps on the distance to the upright state, each from the Jacobian of the whole rollout, swing
  the poles up and hold them from a share of the random restarts; the open-loop actions hold
  them for half a second only (the upright state is unstable), and a policy that swings up and
  balances from any start is future work.
""".strip("\n"),
    )
)


if __name__ == "__main__":
    write_notebook(CELLS, "robot_dynamics.ipynb", __doc__.splitlines()[0])
