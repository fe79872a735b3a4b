"""One training step of an MLP (2 hidden layers of 256, batch 256, Adam), ivy against native.

For each differentiable backend it times, in one run, with interleaved repeats:

    ivy eager        ``Adam.training_step(loss_fn)``: ivy.MLP, ivy.mse,
                     ivy.execute_with_gradients and the functional Adam update
    ivy compiled     the same step through ``ivy.compile_fn`` (jax.jit, tf.function, torch.compile)
    ivy module step  ``Adam.module_step(model, loss_fn, compile=True)``: the compiled step bound
                     to the module, updating ``model.v`` and the optimizer state in place (on
                     tensorflow they live in tf.Variables that the graph assigns)
    native eager     the same network written in the framework itself:
                     torch: nn.Sequential + torch.optim.Adam, loss.backward();
                     jax: a params dict, jax.value_and_grad and Adam written with jax.tree.map;
                     tensorflow: tf.Variables, GradientTape and keras.optimizers.Adam
    native compiled  torch: torch.compile of the model and of optimizer.step (the PyTorch
                     recipe); jax: jax.jit of the step; tensorflow: tf.function of the step

The minimum over repeats is the estimate (interference on a shared machine only adds time);
the median is printed beside it. Ratios are ivy / native, eager to eager and compiled to
compiled (both compiled forms of ivy against the native compiled step). The target is a compiled
ratio within 1.10.

``--threads N`` limits every framework to N intra-op threads (torch.set_num_threads, tf's
threading config, XLA's CPU flags). ``--clock cpu`` measures the process's CPU time instead of
wall time: on a shared, oversubscribed machine it counts the work done and not the time spent
waiting for a core (use it with ``--threads 1``, where CPU time is the time of one core).

Usage: python benchmarks/mlp_training_step.py [--backends torch,jax,tensorflow] [--repeats 15]
       [--steps 20] [--in-features 64] [--hidden 256] [--batch 256] [--threads N] [--clock wall|cpu]
"""

from __future__ import annotations

import argparse
import os
import statistics
import time
import warnings

import numpy as np

import ivy

LR = 1e-3


def _data(n_in: int, batch: int):
    rng = np.random.default_rng(0)
    x = rng.standard_normal((batch, n_in)).astype(np.float32)
    y = np.sin(x[:, :1]) + 0.1 * x[:, 1:2]
    return x, y.astype(np.float32)


# ----------------------------------------------------------------------------------------------
# ivy: written once
# ----------------------------------------------------------------------------------------------


def ivy_steps(backend: str, x_np, y_np, hidden: int, sync):
    """(eager, compiled) zero-argument step callables that update their own state."""
    xp = getattr(ivy, backend)
    x, y = xp.asarray(x_np), xp.asarray(y_np)
    ivy.seed(0)
    model = ivy.MLP(x_np.shape[1], (hidden, hidden), 1, device="cpu", f=backend)
    opt = ivy.Adam(LR)

    def loss_fn(v, x, y):
        return ivy.mse(model(x, v=v), y)

    def runner(step):
        holder = {"v": model.v, "state": opt.init(model.v)}

        def run():
            loss, holder["v"], holder["state"] = step(holder["v"], holder["state"], x, y)
            return loss

        return run

    eager = runner(opt.training_step(loss_fn))
    compiled = runner(opt.training_step(loss_fn, compile=True))
    bound_model = ivy.MLP(x_np.shape[1], (hidden, hidden), 1, device="cpu", f=backend)
    bound_model.v = model.v
    bound_opt = ivy.Adam(LR)
    train = bound_opt.module_step(
        bound_model, lambda v, x, y: ivy.mse(bound_model(x, v=v), y), compile=True
    )
    return eager, compiled, lambda: train(x, y)


# ----------------------------------------------------------------------------------------------
# Native versions
# ----------------------------------------------------------------------------------------------


def torch_steps(x_np, y_np, hidden: int, sync):
    import torch

    x, y = torch.from_numpy(x_np), torch.from_numpy(y_np)

    def build():
        torch.manual_seed(0)
        model = torch.nn.Sequential(
            torch.nn.Linear(x_np.shape[1], hidden),
            torch.nn.ReLU(),
            torch.nn.Linear(hidden, hidden),
            torch.nn.ReLU(),
            torch.nn.Linear(hidden, 1),
        )
        return model, torch.optim.Adam(model.parameters(), lr=LR)

    model, opt = build()

    def eager():
        opt.zero_grad(set_to_none=True)
        loss = torch.nn.functional.mse_loss(model(x), y)
        loss.backward()
        opt.step()
        return loss

    c_model, c_opt = build()
    forward = torch.compile(c_model)

    @torch.compile
    def opt_step():
        c_opt.step()

    def compiled():
        c_opt.zero_grad(set_to_none=True)
        loss = torch.nn.functional.mse_loss(forward(x), y)
        loss.backward()
        opt_step()
        return loss

    return eager, compiled


def jax_steps(x_np, y_np, hidden: int, sync):
    import jax
    import jax.numpy as jnp

    cpu = jax.devices("cpu")[0]
    x, y = jax.device_put(jnp.asarray(x_np), cpu), jax.device_put(jnp.asarray(y_np), cpu)
    key = jax.random.key(0)
    sizes = [x_np.shape[1], hidden, hidden, 1]
    params = {}
    for i, (n_in, n_out) in enumerate(zip(sizes[:-1], sizes[1:])):
        key, sub = jax.random.split(key)
        limit = (6.0 / (n_in + n_out)) ** 0.5
        w = jax.random.uniform(sub, (n_out, n_in), jnp.float32, -limit, limit)
        params[str(i)] = {"w": w, "b": jnp.zeros(n_out, jnp.float32)}
    params = jax.device_put(params, cpu)

    def forward(p, x):
        h = jax.nn.relu(x @ p["0"]["w"].T + p["0"]["b"])
        h = jax.nn.relu(h @ p["1"]["w"].T + p["1"]["b"])
        return h @ p["2"]["w"].T + p["2"]["b"]

    def loss_fn(p, x, y):
        return jnp.mean((forward(p, x) - y) ** 2)

    def step(p, m, n, t, x, y):
        loss, g = jax.value_and_grad(loss_fn)(p, x, y)
        t = t + 1
        b1, b2, eps = 0.9, 0.999, 1e-8
        m = jax.tree.map(lambda m, g: b1 * m + (1 - b1) * g, m, g)
        n = jax.tree.map(lambda n, g: b2 * n + (1 - b2) * g * g, n, g)
        step_size = LR / (1 - b1**t)
        bc2 = jnp.sqrt(1 - b2**t)
        p = jax.tree.map(lambda p, m, n: p - step_size * m / (jnp.sqrt(n) / bc2 + eps), p, m, n)
        return loss, p, m, n, t

    def runner(fn):
        zeros = jax.tree.map(jnp.zeros_like, params)
        state = {"p": params, "m": zeros, "n": zeros, "t": jax.device_put(jnp.float32(0), cpu)}

        def run():
            loss, state["p"], state["m"], state["n"], state["t"] = fn(
                state["p"], state["m"], state["n"], state["t"], x, y
            )
            return loss

        return run

    return runner(step), runner(jax.jit(step))


def tensorflow_steps(x_np, y_np, hidden: int, sync):
    import keras
    import tensorflow as tf

    x, y = tf.constant(x_np), tf.constant(y_np)

    def build():
        tf.random.set_seed(0)
        sizes = [x_np.shape[1], hidden, hidden, 1]
        variables = []
        for n_in, n_out in zip(sizes[:-1], sizes[1:]):
            limit = (6.0 / (n_in + n_out)) ** 0.5
            variables.append(tf.Variable(tf.random.uniform((n_in, n_out), -limit, limit)))
            variables.append(tf.Variable(tf.zeros(n_out)))
        return variables, keras.optimizers.Adam(LR)

    def make(variables, opt):
        w0, b0, w1, b1, w2, b2 = variables

        def step():
            with tf.GradientTape() as tape:
                h = tf.nn.relu(x @ w0 + b0)
                h = tf.nn.relu(h @ w1 + b1)
                loss = tf.reduce_mean(tf.square(h @ w2 + b2 - y))
            grads = tape.gradient(loss, variables)
            opt.apply_gradients(zip(grads, variables))
            return loss

        return step

    eager = make(*build())
    compiled = tf.function(make(*build()))
    return eager, compiled


NATIVE = {"torch": torch_steps, "jax": jax_steps, "tensorflow": tensorflow_steps}


def _sync(backend: str):
    if backend == "jax":
        import jax

        return jax.block_until_ready
    if backend == "tensorflow":
        return lambda loss: loss.numpy()
    return lambda loss: float(loss)


# ----------------------------------------------------------------------------------------------
# Timing
# ----------------------------------------------------------------------------------------------

VARIANTS = ("ivy eager", "native eager", "ivy compiled", "ivy module step", "native compiled")


def measure(backend: str, args) -> dict[str, tuple[float, float]]:
    """(min, median) seconds per step of each variant, repeats interleaved."""
    clock = time.process_time if args.clock == "cpu" else time.perf_counter
    x, y = _data(args.in_features, args.batch)
    sync = _sync(backend)
    ivy_eager, ivy_compiled, ivy_module = ivy_steps(backend, x, y, args.hidden, sync)
    native_eager, native_compiled = NATIVE[backend](x, y, args.hidden, sync)
    runs = {
        "ivy eager": ivy_eager,
        "native eager": native_eager,
        "ivy compiled": ivy_compiled,
        "ivy module step": ivy_module,
        "native compiled": native_compiled,
    }
    for run in runs.values():  # compile and warm up
        for _ in range(3):
            sync(run())
    samples: dict[str, list[float]] = {v: [] for v in VARIANTS}
    for _ in range(args.repeats):
        for variant in VARIANTS:
            run = runs[variant]
            start = clock()
            for _ in range(args.steps):
                loss = run()
            sync(loss)
            samples[variant].append((clock() - start) / args.steps)
    return {v: (min(s), statistics.median(s)) for v, s in samples.items()}


def limit_threads(n: int) -> None:
    """At most ``n`` intra-op threads in every framework (call before any framework runs)."""
    os.environ["XLA_FLAGS"] = (
        os.environ.get("XLA_FLAGS", "")
        + f" --xla_cpu_multi_thread_eigen={'true' if n > 1 else 'false'}"
        + f" intra_op_parallelism_threads={n}"
    )
    try:
        import torch

        torch.set_num_threads(n)
        torch.set_num_interop_threads(n)
    except ImportError:
        pass
    try:
        import tensorflow as tf

        tf.config.threading.set_intra_op_parallelism_threads(n)
        tf.config.threading.set_inter_op_parallelism_threads(n)
    except ImportError:
        pass


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--backends", default=None)
    parser.add_argument("--repeats", type=int, default=15)
    parser.add_argument("--steps", type=int, default=20)
    parser.add_argument("--in-features", type=int, default=64)
    parser.add_argument("--hidden", type=int, default=256)
    parser.add_argument("--batch", type=int, default=256)
    parser.add_argument("--threads", type=int, default=None)
    parser.add_argument("--clock", choices=("wall", "cpu"), default="wall")
    args = parser.parse_args()
    if args.threads:
        limit_threads(args.threads)
    installed = [b for b in ivy.installed_frameworks() if b in NATIVE]
    backends = args.backends.split(",") if args.backends else installed
    warnings.filterwarnings("ignore")
    threads = f"{args.threads} thread(s)" if args.threads else "default threads"
    print(
        f"MLP {args.in_features}-{args.hidden}-{args.hidden}-1, batch {args.batch}, Adam, "
        f"{threads}; ms of {args.clock} time per training step, min (median) of "
        f"{args.repeats} x {args.steps} steps\n"
    )
    header = (
        f"{'backend':<11}{'ivy eager':>17}{'native eager':>17}{'ratio':>7}"
        f"{'ivy compiled':>17}{'ivy module step':>17}{'native compiled':>17}{'ratios':>12}"
    )
    print(header)
    print("-" * len(header))
    for backend in backends:
        r = measure(backend, args)

        def cell(v, r=r):
            return f"{r[v][0] * 1e3:7.3f} ({r[v][1] * 1e3:6.3f})"

        def ratio(a, b, r=r):
            return r[a][0] / r[b][0]

        print(
            f"{backend:<11}{cell('ivy eager'):>17}{cell('native eager'):>17}"
            f"{ratio('ivy eager', 'native eager'):7.2f}{cell('ivy compiled'):>17}"
            f"{cell('ivy module step'):>17}{cell('native compiled'):>17}"
            f"{ratio('ivy compiled', 'native compiled'):6.2f}"
            f"{ratio('ivy module step', 'native compiled'):6.2f}",
            flush=True,
        )


if __name__ == "__main__":
    main()
