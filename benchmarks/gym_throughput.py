"""ivy_gym's throughput against Gymnasium's vectorised CartPole and gymnax, in one run.

1. CartPole steps per second, random actions, autoreset, batch 1, 64, 1024 and 16384:

   gymnasium vector    ``gymnasium.make_vec("CartPole-v1", vectorization_mode=
                       "vector_entry_point")``: Gymnasium's own numpy CartPoleVectorEnv, stepped in a
                       Python loop with pre-drawn actions
   ivy numpy facade    the same loop on ``gymnasium.make_vec("ivy_gym/CartPole-v1", ...,
                       framework="numpy")`` (ivy_gym's native VectorEnv)
   ivy <backend> scan  ``ivy_gym.rollout(..., autoreset=True)`` over 100 steps of pre-drawn
                       actions: eager on numpy; compiled (``ivy.compile_fn``) on jax, tensorflow
                       and torch (torch.compile unrolls the loop: ~1 min to compile per size)
   gymnax jax          ``jax.jit`` of a ``lax.scan`` over 100 steps of ``vmap(env.step)`` with
                       random actions (gymnax steps reset themselves), the usual gymnax recipe

2. Forward and backward: the gradient of the return of 200 steps of 64 Pendulums with respect to
   the actions, eager and compiled, per backend (torch compiled is left out: torch.compile of 200
   unrolled steps with their backward takes several minutes).

3. With ``--device`` (e.g. ``gpu:0``): ivy_gym CartPole and Pendulum on jax on that device against
   gymnax on the same device (``--device-batches``, the issue's 65,536 and 1,048,576 on a GPU),
   and a torch section: ``ivy.compile_fn`` of ``ivy_gym.rollout`` over Pendulum (on CUDA
   ``torch.compile(..., mode="reduce-overhead")``, for CUDA graphs: ``ivy.compile_fn`` has no
   ``mode``), against the same loop written in plain torch here (``torch_pendulum_loop``),
   eager and compiled the same way (``--torch-batches``, 4,096 and more). Every array is created on
   the device (``env.reset(device=...)``, ``ivy.asarray(device=...)``). ``--device-only`` skips
   sections 1 and 2.

The variants of each batch size take turns (interleaved repeats, ``benchmarks/_timing.py``) and the
median is reported; ratios are against Gymnasium (numpy) and gymnax (jax), from the same run.

gymnax is a benchmark-only peer. Installed alone it would replace Gymnasium 1.4 with 1.3, so:
``pip install --no-deps gymnax && pip install flax chex seaborn`` (which leave numpy, jax, torch,
tensorflow and gymnasium as they are). Without it the gymnax rows are skipped.

Usage: python benchmarks/gym_throughput.py [--backends numpy,jax,tensorflow,torch]
       [--batches 1,64,1024,16384] [--steps 100] [--repeats 7] [--no-torch-compile]
       [--clock wall|cpu] [--device gpu:0 [--device-only] [--device-batches 65536,1048576]
       [--torch-batches 4096,65536]]
"""

from __future__ import annotations

import argparse
import sys
import time
import timeit
import warnings
from pathlib import Path

import numpy as np

import ivy
import ivy_gym
import ivy_gym.gymnasium  # noqa: F401  (registers the ivy_gym/... ids)

sys.path.insert(0, str(Path(__file__).parent))
from _timing import calls_per_sample, interleaved_samples, median  # noqa: E402

warnings.filterwarnings("ignore")


def _block(out):
    for leaf in ivy.nest.nest_leaves(out):
        if hasattr(leaf, "block_until_ready"):
            leaf.block_until_ready()
        elif hasattr(leaf, "numpy"):
            np.asarray(leaf.detach() if hasattr(leaf, "detach") else leaf)
    return out


def gymnasium_vector(env_id, n, steps, **kwargs):
    """A Python loop of ``steps`` vector steps with pre-drawn actions."""
    import gymnasium

    envs = gymnasium.make_vec(env_id, num_envs=n, vectorization_mode="vector_entry_point", **kwargs)
    envs.reset(seed=0)
    actions = np.random.default_rng(0).integers(0, 2, size=(steps, n))

    def run():
        for a in actions:
            out = envs.step(a)
        return out[0]

    return run


def _native_device(backend, device):
    """``device`` ('cpu', 'gpu:0') in the framework's own spelling, for the peers."""
    kind, _, index = device.partition(":")
    if backend == "torch":
        return "cpu" if kind == "cpu" else f"cuda:{index or 0}"
    import jax

    return jax.devices("cpu" if kind == "cpu" else "gpu")[int(index or 0)]


def ivy_scan(backend, n, steps, compile, env_name="CartPole", device=None):
    env = getattr(ivy_gym, env_name)()
    state = env.reset((n,), f=backend, device=device)
    signs = np.where(np.random.default_rng(0).uniform(size=(steps, n, 1)) > 0.5, 1.0, -1.0)
    actions = ivy.asarray(signs.astype(np.float32), f=backend, device=device)

    def run(state, actions):
        traj = ivy_gym.rollout(env, state, actions, autoreset=True)
        return traj.final_state, ivy.sum(traj.rewards)

    if compile:
        run = ivy.compile_fn(run, f=backend)
    return lambda: run(state, actions)


def gymnax_scan(n, steps, env_id="CartPole-v1", device=None):
    try:
        import gymnax
        import jax
    except ImportError:
        return None
    with jax.default_device(_native_device("jax", device or "cpu")):
        return _gymnax_run(gymnax, jax, n, steps, env_id)


def _gymnax_run(gymnax, jax, n, steps, env_id):
    env, params = gymnax.make(env_id)
    discrete = env_id == "CartPole-v1"
    vstep = jax.vmap(env.step, in_axes=(0, 0, 0, None))
    _, state = jax.vmap(env.reset, in_axes=(0, None))(
        jax.random.split(jax.random.key(0), n), params
    )

    @jax.jit
    def run(key, state):
        def body(carry, _):
            key, state = carry
            key, k_act, k_step = jax.random.split(key, 3)
            if discrete:
                actions = jax.random.randint(k_act, (n,), 0, 2)
            else:
                actions = jax.random.uniform(k_act, (n,), minval=-2.0, maxval=2.0)
            out = vstep(jax.random.split(k_step, n), state, actions, params)
            state, reward = out[1], out[2]  # (obs, state, reward, terminated, truncated, info)
            return (key, state), reward

        (_, state), rewards = jax.lax.scan(body, (key, state), None, length=steps)
        return state, rewards.sum()

    key = jax.random.key(1)
    return lambda: run(key, state)


def torch_pendulum_inputs(n, steps, device):
    """The initial states and pre-drawn actions that both torch variants run from."""
    state = ivy_gym.Pendulum().reset((n,), f="torch", device=device)
    signs = np.where(np.random.default_rng(0).uniform(size=(steps, n, 1)) > 0.5, 1.0, -1.0)
    return state, ivy.asarray(signs.astype(np.float32), f="torch", device=device)


def torch_pendulum_loop(state, actions, compile_mode):
    """Pendulum written in plain torch: the same dynamics and rewards as ivy_gym.Pendulum
    (Gymnasium's), a Python loop over the actions, on their device; compiled with
    ``torch.compile(mode=compile_mode)`` unless ``compile_mode`` is False."""
    import torch

    g, m, length, dt, max_speed, max_torque = 10.0, 1.0, 1.0, 0.05, 8.0, 2.0

    def run(state, actions):
        th, thdot = state[..., 0], state[..., 1]
        total = torch.zeros((), device=state.device)
        for t in range(actions.shape[0]):
            u = torch.clamp(actions[t, :, 0], -max_torque, max_torque)
            wrapped = torch.remainder(th + torch.pi, 2 * torch.pi) - torch.pi
            total = total - (wrapped**2 + 0.1 * thdot**2 + 0.001 * u**2).sum()
            acc = 3 * g / (2 * length) * torch.sin(th) + 3.0 / (m * length**2) * u
            thdot = torch.clamp(thdot + acc * dt, -max_speed, max_speed)
            th = th + thdot * dt
        return torch.stack([th, thdot], -1), total

    if compile_mode is not False:
        run = torch.compile(run, mode=compile_mode)
    return lambda: run(state, actions)


def ivy_torch_pendulum(state, actions, compile_mode):
    """``ivy_gym.rollout`` of Pendulum on torch, compiled: ``ivy.compile_fn`` on the CPU, and
    ``torch.compile(mode=compile_mode)`` when a mode is asked for (CUDA graphs)."""
    import torch

    env = ivy_gym.Pendulum()

    def run(state, actions):
        traj = ivy_gym.rollout(env, state, actions)
        return traj.final_state, ivy.sum(traj.rewards)

    if compile_mode is None:
        run = ivy.compile_fn(run, f="torch")
    else:
        run = torch.compile(run, mode=compile_mode)
    return lambda: run(state, actions)


def _torch_sync(out):
    import torch

    if torch.cuda.is_available():
        torch.cuda.synchronize()
    return out


def device_section(args, clock):
    """ivy_gym on ``args.device``: jax against gymnax, torch compiled against plain torch."""
    device, steps = args.device, args.steps
    batches = [int(b) for b in args.device_batches.split(",")]
    print(f"\nOn {device}: steps per second (millions), {steps}-step runs, random actions")
    backends = args.backends.split(",")
    envs = (("CartPole", "CartPole-v1"), ("Pendulum", "Pendulum-v1")) if "jax" in backends else ()
    for env_name, env_id in envs:
        rows: dict[str, list[float]] = {}
        for n in batches:
            variants = {
                "ivy jax scan (compiled)": ivy_scan("jax", n, steps, True, env_name, device)
            }
            gymnax = gymnax_scan(n, steps, env_id, device)
            if gymnax is not None:
                variants["gymnax jax (jit+vmap+scan)"] = gymnax
            for name, seconds in _interleaved(variants, args.repeats, clock, 0.05).items():
                rows.setdefault(name, []).append(n * steps / seconds)
        print(f"{env_name:<32}" + "".join(f"{'N=' + str(n):>12}" for n in batches))
        for name, values in rows.items():
            print(f"{name:<32}" + "".join(f"{v / 1e6:12.3f}" for v in values))
        if "gymnax jax (jit+vmap+scan)" in rows:
            ours, theirs = rows["ivy jax scan (compiled)"], rows["gymnax jax (jit+vmap+scan)"]
            print(
                f"{'ivy jax / gymnax':<32}"
                + "".join(f"{a / b:12.2f}" for a, b in zip(ours, theirs))
            )
        else:
            print("(gymnax is not installed: no peer row)")
    if args.no_torch_compile or "torch" not in backends:
        return
    import torch

    if device == "cpu":  # one thread, as the CPU sections of benchmarks/ do: steadier when shared
        torch.set_num_threads(1)

    mode = "reduce-overhead" if device.startswith("gpu") else None
    tsteps = args.torch_steps
    batches = [int(b) for b in args.torch_batches.split(",")]
    rows = {}
    for n in batches:
        torch._dynamo.reset()
        state, actions = torch_pendulum_inputs(n, tsteps, device)
        variants = {
            "ivy torch rollout (compiled)": ivy_torch_pendulum(state, actions, mode),
            "plain torch loop (eager)": torch_pendulum_loop(state, actions, False),
            "plain torch loop (compiled)": torch_pendulum_loop(state, actions, mode),
        }
        ours = variants["ivy torch rollout (compiled)"]()[1]
        theirs = variants["plain torch loop (eager)"]()[1]
        np.testing.assert_allclose(float(ours), float(theirs), rtol=1e-3)
        timed = {k: (lambda fn=fn: _torch_sync(fn())) for k, fn in variants.items()}
        for name, seconds in _interleaved(timed, args.repeats, clock, 0.05).items():
            rows.setdefault(name, []).append(n * tsteps / seconds)
    compiler = "torch.compile(mode='reduce-overhead')" if mode else "ivy.compile_fn"
    print(f"\nPendulum on torch, {device}, {tsteps}-step runs, {compiler}: steps/s (millions)")
    print(f"{'variant':<32}" + "".join(f"{'N=' + str(n):>12}" for n in batches))
    for name, values in rows.items():
        print(f"{name:<32}" + "".join(f"{v / 1e6:12.3f}" for v in values))
    ours = rows["ivy torch rollout (compiled)"]
    for peer in ("plain torch loop (eager)", "plain torch loop (compiled)"):
        label = "ivy / " + peer.replace("plain torch loop", "plain")
        print(f"{label:<32}" + "".join(f"{a / b:12.2f}" for a, b in zip(ours, rows[peer])))


def pendulum_gradient(backend, compile, steps=200, batch=64):
    env = ivy_gym.Pendulum()
    state = env.reset((batch,), f=backend)
    actions = ivy.asarray(np.zeros((steps, batch, 1), np.float32), f=backend)

    def value_and_grad(actions):
        def loss(actions):
            return -ivy.mean(ivy.sum(ivy_gym.rollout(env, state, actions).rewards, axis=0))

        return ivy.execute_with_gradients(loss, actions)

    if compile:
        value_and_grad = ivy.compile_fn(value_and_grad, f=backend)
    return lambda: value_and_grad(actions)


def _interleaved(variants, repeats, clock=time.perf_counter, target_s=None):
    """Median seconds per call of each variant, the variants taking turns (shared drift); with
    ``target_s``, each sample repeats the calls for about that long (the fastest variant's)."""
    timers = {}
    for _ in range(2):  # warm up (and compile) all, twice: torch.compile guards on ivy's cache
        for fn in variants.values():  # of array types, which the other variants fill
            _block(fn())
    for name, fn in variants.items():
        timers[name] = timeit.Timer(lambda fn=fn: _block(fn()), timer=clock)
    number = 1
    if target_s is not None:
        number = min(calls_per_sample(t, target_s) for t in timers.values())
    samples = interleaved_samples(timers, number, repeats)
    return {name: median(values) for name, values in samples.items()}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--backends", default="numpy,jax,tensorflow,torch")
    parser.add_argument("--batches", default="1,64,1024,16384")
    parser.add_argument("--steps", type=int, default=100)
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--no-torch-compile", action="store_true")
    parser.add_argument(
        "--clock",
        choices=("wall", "cpu"),
        default="wall",
        help="cpu: this process's CPU time (steadier on a loaded machine; the multi-threaded "
        "backends count the time of all their threads)",
    )
    parser.add_argument("--device", default="cpu", help="'cpu' or 'gpu:0' (CUDA), section 3")
    parser.add_argument("--device-only", action="store_true", help="only section 3")
    parser.add_argument("--device-batches", default="1024,4096", help="section 3, jax")
    parser.add_argument("--torch-batches", default="1024,4096", help="section 3, torch")
    parser.add_argument("--torch-steps", type=int, default=50, help="section 3, torch")
    args = parser.parse_args()
    clock = time.process_time if args.clock == "cpu" else time.perf_counter
    backends = args.backends.split(",")
    batches = [int(b) for b in args.batches.split(",")]
    steps = args.steps
    if args.device_only:
        device_section(args, clock)
        return

    rows: dict[str, list[float]] = {}
    for n in batches:
        variants = {"gymnasium vector (numpy)": gymnasium_vector("CartPole-v1", n, steps)}
        if "numpy" in backends:
            variants["ivy numpy facade"] = gymnasium_vector(
                "ivy_gym/CartPole-v1", n, steps, framework="numpy"
            )
            variants["ivy numpy scan (eager)"] = ivy_scan("numpy", n, steps, False)
        for backend in ("jax", "tensorflow", "torch"):
            if backend in backends and not (backend == "torch" and args.no_torch_compile):
                variants[f"ivy {backend} scan (compiled)"] = ivy_scan(backend, n, steps, True)
        if "jax" in backends:
            gymnax = gymnax_scan(n, steps)
            if gymnax is not None:
                variants["gymnax jax (jit+vmap+scan)"] = gymnax
        for name, seconds in _interleaved(variants, args.repeats, clock).items():
            rows.setdefault(name, []).append(n * steps / seconds)

    print(f"CartPole steps per second (millions), random actions, autoreset, {steps}-step runs")
    print(f"{'variant':<32}" + "".join(f"{'N=' + str(n):>10}" for n in batches))
    for name, values in rows.items():
        print(f"{name:<32}" + "".join(f"{v / 1e6:10.3f}" for v in values))
    base = rows["gymnasium vector (numpy)"]
    for name in ("ivy numpy facade", "ivy numpy scan (eager)"):
        if name in rows:
            ratios = "".join(f"{a / b:10.2f}" for a, b in zip(rows[name], base))
            print(f"{name + ' / gymnasium':<32}{ratios}")
    if "gymnax jax (jit+vmap+scan)" in rows and "ivy jax scan (compiled)" in rows:
        ours, theirs = rows["ivy jax scan (compiled)"], rows["gymnax jax (jit+vmap+scan)"]
        print(f"{'ivy jax / gymnax':<32}" + "".join(f"{a / b:10.2f}" for a, b in zip(ours, theirs)))

    print("\nForward + backward through 200 steps of 64 Pendulums (ms per gradient)")
    print(f"{'backend':<12}{'eager':>10}{'compiled':>10}")
    for backend in backends:
        if backend == "numpy":
            continue
        variants = {"eager": pendulum_gradient(backend, False)}
        if backend != "torch":
            variants["compiled"] = pendulum_gradient(backend, True)
        times = _interleaved(variants, args.repeats, clock)
        compiled = f"{times['compiled'] * 1e3:10.2f}" if "compiled" in times else f"{'-':>10}"
        print(f"{backend:<12}{times['eager'] * 1e3:10.2f}{compiled}")
    if args.device != "cpu":
        device_section(args, clock)


if __name__ == "__main__":
    main()
