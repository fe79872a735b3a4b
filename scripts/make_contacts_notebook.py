"""Write ``notebooks/robot_contacts.ipynb`` from the cells below (run it after editing them):

    python scripts/make_contacts_notebook.py [--execute]

``--execute`` runs it once (the first cell's defaults: every installed backend, 100 steps of
Hopper-v5 and Ant-v5, a 10-step gradient and 15 gradient steps on jax: a few minutes on one
core, most of it jax's and tensorflow's compilations) and saves it with its outputs.

The notebook: Hopper-v5 and Ant-v5 on ``ivy_robot.physics`` (contacts, joint limits) rolled out
on every backend beside Gymnasium's own MuJoCo environments, their renderings, and a gradient
of the Hopper's return through its foot's contact with the floor against finite differences.
"""

from __future__ import annotations

from _notebooks import write_notebook  # scripts/ is on the path of `python scripts/...`

CELLS: list[tuple[str, str]] = []
CELLS.append(
    (
        "markdown",
        r"""
# Contacts written once: Hopper and Ant on every backend beside MuJoCo, and a gradient through a contact

`ivy_robot.physics` is MuJoCo's forward pipeline (kinematics, collisions with the floor, joint
limits, the constraint solver, the integrators) written once on ivy's API. `ivy_gym` builds
Gymnasium's MuJoCo locomotion tasks on it, step for step, so the same environment runs on
numpy, torch, jax and tensorflow, and differentiates on the last three. This notebook:

1. rolls Hopper-v5 and Ant-v5 out from the same seed with the same seeded random actions on
   every installed backend and in Gymnasium's own MuJoCo environment, in float64, and prints
   how far each backend's observations and rewards are from Gymnasium's;
2. renders both robots along the rollout (ivy_gym's own drawing of the geoms, beside MuJoCo's
   OpenGL rendering of Gymnasium's environment where an OpenGL context is available);
3. differentiates the Hopper's return over a few steps from a state whose foot stands on the
   floor with respect to the actions, by torch's and jax's autodiff through ivy, against
   central finite differences, and takes a few gradient steps on the actions.

The tests run this notebook with a tiny budget through the environment variables below; the
outputs stored here are those of the defaults.
""".strip("\n"),
    )
)

CELLS.append(
    (
        "code",
        r"""
# Parameters: the backends, the rollouts' length and the gradient's budget.
import os

BACKENDS = os.environ.get("CONTACTS_NOTEBOOK_BACKENDS", "numpy,torch,jax,tensorflow").split(",")
STEPS = int(os.environ.get("CONTACTS_NOTEBOOK_STEPS", "100"))  # per task and backend
GRAD_BACKENDS = os.environ.get("CONTACTS_NOTEBOOK_GRAD_BACKENDS", "torch,jax").split(",")
HORIZON = int(os.environ.get("CONTACTS_NOTEBOOK_HORIZON", "10"))  # steps the gradient spans
ITERATIONS = int(os.environ.get("CONTACTS_NOTEBOOK_ITERATIONS", "15"))  # gradient steps
SEED = 0

# tensorflow: no start-up chatter on stderr (oneDNN's notice concerns float32 kernels)
os.environ.setdefault("TF_CPP_MIN_LOG_LEVEL", "2")
os.environ.setdefault("TF_ENABLE_ONEDNN_OPTS", "0")
import warnings

warnings.filterwarnings("ignore", message=".*(Box|symmetric and normalized).*")

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
import subprocess
import sys
import tempfile
import time

import gymnasium
import matplotlib.pyplot as plt
import numpy as np
from IPython.display import Image, display

import ivy
import ivy_gym
import ivy_gym.gymnasium  # noqa: F401  (registers the ivy_gym/... ids)

BACKENDS = [b for b in BACKENDS if b in ivy.available_frameworks()]
GRAD_BACKENDS = [b for b in GRAD_BACKENDS if b in ivy.available_frameworks() and b != "numpy"]
if "jax" in BACKENDS + GRAD_BACKENDS:
    import jax

    jax.config.update("jax_enable_x64", True)  # float64, as Gymnasium's MuJoCo environments
print(f"backends: {', '.join(BACKENDS)} | steps: {STEPS} | gradient backends: "
      f"{', '.join(GRAD_BACKENDS)} | horizon: {HORIZON} | gradient steps: {ITERATIONS}")


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
## 1. Every backend beside Gymnasium's MuJoCo

Gymnasium's `Hopper-v5` and `Ant-v5` run first: reset with seed 0, then `STEPS` actions drawn
from the action space seeded with 0 (float32, as Gymnasium samples them); when an episode
terminates the environment is reset with the seed `SEED + t + 1`. Then every backend runs
ivy_gym's Gymnasium facade of the same task, `gymnasium.make("ivy_gym/<task>",
framework=backend)` (float64; jax and tensorflow compile the step once, torch and numpy run
eagerly), from the same seeds with the same actions, resetting where Gymnasium's run did.

Printed per task and backend: the largest difference of the observations and of the rewards
from Gymnasium's over the whole rollout, the first step (counted from 1) where the observations
differ by more than 1e-9, whether every termination agrees, and the time taken (compilation
included); then the largest difference of the other backends' observations from the first
backend's.
""".strip("\n"),
    )
)

CELLS.append(
    (
        "code",
        r"""
TASKS = ("Hopper-v5", "Ant-v5")
PICKS = np.linspace(0, STEPS - 1, 5).astype(int)  # the steps drawn in section 2


def gymnasium_run(task):
    # Gymnasium's own environment: the actions, where it reset, its observations and rewards
    env = gymnasium.make(task)
    env.reset(seed=SEED)
    env.action_space.seed(SEED)
    run = {"actions": [], "obs": [], "rewards": [], "terminated": [], "contacts": []}
    for t in range(STEPS):
        action = env.action_space.sample()
        obs, reward, terminated, truncated, _ = env.step(action)
        for key, value in zip(("actions", "obs", "rewards", "terminated"),
                              (action, obs, reward, terminated)):
            run[key].append(value)
        run["contacts"].append(env.unwrapped.data.ncon)
        if terminated or truncated:
            env.reset(seed=SEED + t + 1)
    env.close()
    return {k: np.asarray(v) for k, v in run.items()}


def ivy_run(task, backend, reference):
    # the facade on ``backend``, fed Gymnasium's actions, reset where Gymnasium's run reset
    env = gymnasium.make(f"ivy_gym/{task}", framework=backend).unwrapped
    start = time.perf_counter()
    env.reset(seed=SEED)
    obs, rewards, terminated, states = [], [], [], []
    for t, action in enumerate(reference["actions"]):
        o, r, term, _, _ = env.step(action)
        obs.append(o)
        rewards.append(r)
        terminated.append(term)
        states.append(env.state.copy())  # float64 numpy, the core's layout
        if reference["terminated"][t]:
            env.reset(seed=SEED + t + 1)
    seconds = time.perf_counter() - start
    return {"obs": np.asarray(obs), "rewards": np.asarray(rewards),
            "terminated": np.asarray(terminated), "states": np.asarray(states),
            "seconds": seconds, "core": env.core}


references, runs, gaps = {}, {}, {}
for task in TASKS:
    ref = references[task] = gymnasium_run(task)
    resets = int(ref["terminated"].sum())
    print(f"{task}: {STEPS} steps in Gymnasium's MuJoCo environment, {resets} reset(s), "
          f"contacts at {int((ref['contacts'] > 0).sum())} of {STEPS} steps, observations up to "
          f"{np.abs(ref['obs']).max():.1f} in size")
    for backend in BACKENDS:
        run = runs[task, backend] = ivy_run(task, backend, ref)
        gap = gaps[task, backend] = np.abs(run["obs"] - ref["obs"]).max(axis=-1)
        reward_gap = np.abs(run["rewards"] - ref["rewards"]).max()
        above = np.flatnonzero(gap > 1e-9)
        first = f"step {above[0] + 1}" if len(above) else "none"
        agree = "agree" if np.array_equal(run["terminated"], ref["terminated"]) else "DIFFER"
        print(f"  {task} {backend:>10}: observations {gap.max():.1e}, rewards {reward_gap:.1e} | "
              f"first step above 1e-9: {first} | terminations {agree} | {run['seconds']:.1f} s")
    if len(BACKENDS) > 1:  # the backends against the first one: the same code, other arithmetic
        spread = gaps[task, "between backends"] = np.max(
            [np.abs(runs[task, b]["obs"] - runs[task, BACKENDS[0]]["obs"]).max(axis=-1)
             for b in BACKENDS[1:]], axis=0)
        print(f"  {task}: the backends against {BACKENDS[0]}: observations {spread.max():.1e}")
""".strip("\n"),
    )
)

CELLS.append(
    (
        "markdown",
        r"""
The difference of the observations from Gymnasium's at every step, per backend (a grey
vertical line: Gymnasium's episode ended there and both restart from the same seeded reset),
and, in grey, the largest difference between the backends. The backends lie on top of each
other: they run the same code, and differ from one another by the rounding of their arithmetic,
which the contacts amplify as they amplify the difference from MuJoCo, from a smaller start.
""".strip("\n"),
    )
)

CELLS.append(
    (
        "code",
        r"""
fig, axes = plt.subplots(1, len(TASKS), figsize=(11, 3.2), sharey=True)
styles = {"numpy": "-", "torch": "--", "jax": "-.", "tensorflow": ":"}
steps = np.arange(1, STEPS + 1)
for ax, task in zip(axes, TASKS):
    for backend in BACKENDS:
        ax.semilogy(steps, np.maximum(gaps[task, backend], 1e-17), styles.get(backend, "-"),
                    label=backend)
    if (task, "between backends") in gaps:
        ax.semilogy(steps, np.maximum(gaps[task, "between backends"], 1e-17), color="0.5",
                    linewidth=0.8, label="between backends")
    for t in np.flatnonzero(references[task]["terminated"]):
        ax.axvline(t + 1, color="0.7", linewidth=0.8)  # Gymnasium reset after this step
    ax.axhline(1e-9, color="k", linestyle=":", linewidth=0.8)
    ax.set_title(f"{task}: largest |observation - Gymnasium's|")
    ax.set_xlabel("step")
axes[0].legend(fontsize=8)
show(fig)
""".strip("\n"),
    )
)

CELLS.append(
    (
        "markdown",
        r"""
## 2. Renderings

Five steps of each rollout, drawn by the environments' own renderer (`env.core.render`:
ivy_gym projects the model's capsules, spheres and boxes onto a side view for the Hopper and a
top view for the Ant, with numpy and no OpenGL) from the first backend's states. Below them,
MuJoCo's OpenGL rendering of Gymnasium's environment at the same steps (its tracking camera),
where a headless OpenGL context (EGL) is available: in a child process that replays
Gymnasium's run, because loading EGL beside tensorflow crashes tensorflow.
""".strip("\n"),
    )
)

CELLS.append(
    (
        "code",
        r"""
# Gymnasium's run replayed in a child process (the same seeds and actions), rendered by MuJoCo
MUJOCO_RENDER = '''
import os, sys
os.environ["MUJOCO_GL"] = "egl"
import gymnasium, numpy as np
task, path = sys.argv[1], sys.argv[2]
run = np.load(path)
env = gymnasium.make(task, render_mode="rgb_array", width=240, height=240)
env.reset(seed=int(run["seed"]))
frames = []
for t, action in enumerate(run["actions"]):
    env.step(action)
    if t in run["picks"]:
        frames.append(env.render())
    if run["terminated"][t]:
        env.reset(seed=int(run["seed"]) + t + 1)
np.save(path + ".frames.npy", np.stack(frames))
'''


def mujoco_frames(task):
    # MuJoCo's frames of Gymnasium's run at PICKS, or None where it cannot render here
    ref = references[task]
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "run.npz")
        np.savez(path, seed=SEED, picks=PICKS, actions=ref["actions"],
                 terminated=ref["terminated"])
        child = subprocess.run([sys.executable, "-c", MUJOCO_RENDER, task, path],
                               capture_output=True, text=True, timeout=300)
        if child.returncode != 0:
            last = (child.stderr.strip().splitlines() or ["no message"])[-1]
            print(f"{task}: MuJoCo's OpenGL rendering is unavailable here ({last})")
            return None
        return np.load(path + ".frames.npy")


for task in TASKS:
    run = runs[task, BACKENDS[0]]
    rows = [("ivy_gym", [run["core"].render(run["states"][t], width=240, height=240)
                         for t in PICKS])]
    theirs = mujoco_frames(task)
    if theirs is not None:
        rows.append(("MuJoCo (Gymnasium)", list(theirs)))
    fig, axes = plt.subplots(len(rows), len(PICKS), figsize=(2.2 * len(PICKS), 2.3 * len(rows)),
                             squeeze=False)
    for r, (name, frames) in enumerate(rows):
        for c, (t, frame) in enumerate(zip(PICKS, frames)):
            axes[r, c].imshow(frame)
            axes[r, c].set_xticks([]), axes[r, c].set_yticks([])
            axes[0, c].set_title(f"step {t + 1}", fontsize=9)
        axes[r, 0].set_ylabel(name, fontsize=9)
    fig.suptitle(f"{task} ({BACKENDS[0]} states)", y=1.02)
    show(fig)
""".strip("\n"),
    )
)

CELLS.append(
    (
        "markdown",
        r"""
## 3. A gradient through a contact

The start: Gymnasium's Hopper-v5 after its reset with seed 0 and ten seeded random actions,
where MuJoCo reports the foot on the floor. From there the objective is the return (forward
velocity + healthy reward - control cost, summed) of `HORIZON` steps of 8 ms under an action
sequence, as a function of the actions `(HORIZON, 3)`, starting from zeros. Its gradient is
taken by `ivy.value_and_grad` through `ivy_gym.rollout` on each differentiable backend (jax:
compiled with `ivy.compile_fn`), and compared with central finite differences of every action
component (step 1e-6) computed on numpy. The contacts along the way are MuJoCo's, counted in
Gymnasium's environment replaying the same actions.
""".strip("\n"),
    )
)

CELLS.append(
    (
        "code",
        r"""
def gymnasium_at_start():
    # Gymnasium's Hopper after its reset and ten seeded random actions: the foot on the floor
    env = gymnasium.make("Hopper-v5").unwrapped
    env.reset(seed=SEED)
    env.action_space.seed(SEED)
    for _ in range(10):
        env.step(env.action_space.sample())
    return env


def gymnasium_return(actions):
    # the return of ``actions`` from the start in Gymnasium's MuJoCo Hopper, and its contacts
    env = gymnasium_at_start()
    total, contacts = 0.0, []
    for action in actions:
        _, reward, terminated, _, _ = env.step(action)
        total += reward
        contacts.append(env.data.ncon)
        if terminated:
            break
    return total, contacts


env = gymnasium_at_start()
names = [f"{env.model.geom(c.geom1).name}-{env.model.geom(c.geom2).name}" for c in env.data.contact]
start_state = np.concatenate([env.data.qpos, env.data.qvel])  # the Hopper's state: [qpos, qvel]
print(f"start: rootz {start_state[1]:.3f} m, contacts in MuJoCo: {', '.join(names)}")
hopper = ivy_gym.Hopper()


def objective(actions):
    # the return of HORIZON steps from the start, in the actions' framework
    xp = ivy.get_framework(actions)
    trajectory = ivy_gym.rollout(hopper, xp.asarray(start_state), actions)
    return xp.sum(trajectory.rewards)


actions0 = np.zeros((HORIZON, 3))
value_and_grads = {}
for backend in GRAD_BACKENDS:
    fn = ivy.value_and_grad(objective)
    if backend == "jax":
        fn = ivy.compile_fn(fn, f="jax")
    value_and_grads[backend] = fn

analytic = {}
for backend, fn in value_and_grads.items():
    start = time.perf_counter()
    value, grad = fn(ivy.get_framework(f=backend).asarray(actions0))
    analytic[backend] = np.asarray(ivy.to_numpy(grad), np.float64)
    print(f"{backend:>6}: return {float(ivy.to_numpy(value)):.12f}, gradient in "
          f"{time.perf_counter() - start:.1f} s (compilation included)")

start = time.perf_counter()
h = 1e-6
numeric = np.zeros_like(actions0)
for index in np.ndindex(actions0.shape):
    step = np.zeros_like(actions0)
    step[index] = h
    numeric[index] = (float(objective(actions0 + step)) - float(objective(actions0 - step))) / (2 * h)
reference_return, contacts = gymnasium_return(actions0)
print(f"central differences on numpy: {2 * actions0.size} rollouts in "
      f"{time.perf_counter() - start:.1f} s")
print(f"Gymnasium's MuJoCo Hopper: return {reference_return:.12f}; contacts at each step: "
      f"{' '.join(map(str, contacts))}")
print()
print("d return / d action, first three steps (thigh, leg, foot):")
print("  finite differences " + " ".join(f"{g:+.6f}" for g in numeric[:3].ravel()))
for backend, grad in analytic.items():
    print(f"  {backend:>18} " + " ".join(f"{g:+.6f}" for g in grad[:3].ravel()))
for backend, grad in analytic.items():
    error = np.linalg.norm(grad - numeric) / np.linalg.norm(numeric)
    print(f"{backend} against finite differences: relative error {error:.1e} "
          f"(gradient norm {np.linalg.norm(numeric):.3f})")
""".strip("\n"),
    )
)

CELLS.append(
    (
        "markdown",
        r"""
A simple use: Adam ascent on the actions (learning rate 0.1, the actions clipped to the action
box `[-1, 1]`) with the last gradient backend, then the optimised actions replayed in
Gymnasium's own MuJoCo Hopper from the same start.
""".strip("\n"),
    )
)

CELLS.append(
    (
        "code",
        r"""
backend = GRAD_BACKENDS[-1]
xp, fn = ivy.get_framework(f=backend), value_and_grads[backend]
actions = actions0.copy()
first_moment, second_moment, returns = np.zeros_like(actions), np.zeros_like(actions), []
start = time.perf_counter()
for k in range(1, ITERATIONS + 1):
    value, grad = fn(xp.asarray(actions))
    grad = np.asarray(ivy.to_numpy(grad), np.float64)
    returns.append(float(ivy.to_numpy(value)))
    first_moment = 0.9 * first_moment + 0.1 * grad
    second_moment = 0.999 * second_moment + 0.001 * grad**2
    ascent = (first_moment / (1 - 0.9**k)) / (np.sqrt(second_moment / (1 - 0.999**k)) + 1e-8)
    actions = np.clip(actions + 0.1 * ascent, -1.0, 1.0)
value, _ = fn(xp.asarray(actions))
returns.append(float(ivy.to_numpy(value)))
replayed, contacts = gymnasium_return(actions)
print(f"{ITERATIONS} gradient steps on {backend} in {time.perf_counter() - start:.1f} s: return "
      f"{returns[0]:.4f} -> {returns[-1]:.4f}")
print(f"the optimised actions in Gymnasium's MuJoCo Hopper: return {replayed:.4f} "
      f"(difference {abs(replayed - returns[-1]):.1e}); contacts at each step: "
      f"{' '.join(map(str, contacts))}")

fig, (left, right) = plt.subplots(1, 2, figsize=(11, 3.2))
steps = np.arange(HORIZON)
for j, name in enumerate(("thigh", "leg", "foot")):
    left.plot(steps, numeric[:, j], "o", color=f"C{j}", markersize=7, fillstyle="none",
              label=f"{name}: finite differences")
    for backend, grad in analytic.items():
        left.plot(steps, grad[:, j], "x" if backend == "jax" else "+", color=f"C{j}",
                  label=f"{name}: {backend}")
left.set_xlabel("step of the action")
left.set_ylabel("d return / d action")
left.set_title("gradient through the foot's contact")
left.legend(fontsize=7, ncol=3, loc="upper right")
right.plot(returns, "o-")
right.set_xlabel("gradient step")
right.set_ylabel(f"return of {HORIZON} steps")
right.set_title(f"Adam on the actions ({backend})")
show(fig)
""".strip("\n"),
    )
)

CELLS.append(
    (
        "markdown",
        r"""
## What this shows

- The same physics code runs on numpy, torch, jax and tensorflow and follows MuJoCo's
  `mj_step` in Gymnasium's environments: the Hopper to rounding (about 1e-14) over the whole
  rollout, most of it with its foot on the floor; the Ant to about 1e-10 from its first
  contacts (four legs striking the floor at once, under RK4). From there the Ant's trajectory
  parts from Gymnasium's, by about ten every few steps of contact, past 1e-9 after a dozen steps
  and to about 1e-4 after a hundred: contact dynamics amplify any difference, and the backends'
  own rounding differences (from about 1e-15) grow the same way.
- The gradient of a rollout through contacts is exact: torch's and jax's autodiff agree with
  central finite differences to the accuracy of the differences themselves (about 1e-9), over
  steps where the foot's contacts come and go (one, then two). Finite differences are valid
  there because no contact appears or vanishes within their small perturbation; a gradient
  says nothing about what a larger change of the actions would make or break.
- That gradient is useful: a few ascent steps on the actions raise the return, and the
  optimised actions earn the same return in Gymnasium's MuJoCo Hopper, to rounding.
""".strip("\n"),
    )
)


if __name__ == "__main__":
    write_notebook(CELLS, "robot_contacts.ipynb", __doc__.splitlines()[0])
