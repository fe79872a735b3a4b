"""The constraint solver (``ivy_robot.physics.solver``): Newton on Hopper- and Ant-sized
problems, PGS on the Humanoid, compiled on jax (``jax.jit``) and torch (``torch.compile``),
against MuJoCo's own ``mj_fwdConstraint`` (C, one state at a time) in the same run.

Problems come from MuJoCo (``mj_forward`` at states with contacts and active joint limits:
Gymnasium's hopper, ant and humanoid lowered into the floor, joints pushed past their ranges,
random velocities and controls, the previous step's warm start), 256 distinct states laid out
in the static row layout a batched pipeline would have (a block of slots per row kind, sized to
the most rows of that kind in the sample, inactive slots interleaved), tiled to the batch size.
Every solve is first checked against MuJoCo (1e-9 relative), then timed after a warm-up whose
wall-clock time is reported as the compile time; the implementations of one case take turns
(benchmarks/_timing.py: interleaved, shuffled repeats) and the minimum per solve is reported.

Also measured: the compile time of one function with four solves (an RK4 step's), and with
``--unrolled K`` the torch.compile of the Newton loop unrolled to K masked iterations instead
of the solver's data-dependent loop (``ivy.torch.while_loop`` replaced, in this process only,
by a fixed loop of K steps that keeps the carry of finished elements), the alternative design.

Threads: one by default (``--threads``: XLA's and torch's intra-op pools), as MuJoCo's call
runs on one; on a shared machine XLA's pool also made some solves 100x slower (a PGS solve:
1.6 s with two threads beside other work, 13 ms with one).

Usage:
    .venv/bin/python benchmarks/solver.py [--batches 1000,4096] [--humanoid-batches 100,1000]
        [--backends jax,torch] [--repeats 5] [--threads 1] [--unrolled 8]
        [--torch-pgs-compiled] [--skip newton,four,pgs]
"""

from __future__ import annotations

import argparse
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
from ivy_robot.physics import solver as S  # noqa: E402

DISTINCT = 256


def _asset(name: str) -> str:
    import gymnasium

    folder = os.path.join(os.path.dirname(gymnasium.__file__), "envs", "mujoco", "assets")
    return os.path.join(folder, name)


def sample(name: str, count: int, seed: int = 0):
    """``count`` MuJoCo problems with constraints: (model, list of dicts, seconds per state of
    MuJoCo's ``mj_fwdConstraint``)."""
    import mujoco

    model = mujoco.MjModel.from_xml_path(_asset(name))
    model.opt.jacobian = mujoco.mjtJacobian.mjJAC_DENSE
    data = mujoco.MjData(model)
    rng = np.random.default_rng(seed)
    found, seconds = [], []
    while len(found) < count:
        mujoco.mj_resetData(model, data)
        q = model.qpos0.copy()
        for j in range(model.njnt):
            adr, kind = model.jnt_qposadr[j], model.jnt_type[j]
            if kind == 0:
                q[adr + 2] = rng.uniform(0.0, 0.5)
                quat = np.array([1.0, 0, 0, 0]) + rng.normal(size=4) * 0.3
                q[adr + 3 : adr + 7] = quat / np.linalg.norm(quat)
            elif kind in (2, 3) and model.jnt_limited[j]:
                lo, hi = model.jnt_range[j]
                q[adr] = rng.uniform(lo - 0.1 * (hi - lo), hi + 0.1 * (hi - lo))
        if model.jnt_type[0] != 0:  # planar: root z lowered
            q[1] -= rng.uniform(0.0, 0.6)
        data.qpos[:] = q
        data.qvel[:] = rng.normal(size=model.nv)
        data.ctrl[:] = rng.uniform(-1, 1, size=model.nu)
        mujoco.mj_step(model, data)  # the warm start is the previous step's
        mujoco.mj_forward(model, data)
        if not data.nefc:
            continue
        M = np.zeros((model.nv, model.nv))
        mujoco.mj_fullM(model, data, M)
        found.append(
            dict(
                M=M,
                qfrc_smooth=data.qfrc_smooth.copy(),
                qacc_smooth=data.qacc_smooth.copy(),
                J=np.array(data.efc_J).reshape(data.nefc, model.nv),
                D=data.efc_D.copy(),
                R=data.efc_R.copy(),
                aref=data.efc_aref.copy(),
                frictionloss=data.efc_frictionloss.copy(),
                kinds=S.row_kinds(data.efc_type),
                qacc_warmstart=data.qacc_warmstart.copy(),
                qacc=data.qacc.copy(),
            )
        )
        calls = 20
        seconds.append(timeit.timeit(lambda: mujoco.mj_fwdConstraint(model, data), number=calls))
        seconds[-1] /= calls
    return model, found, float(np.median(seconds))


def layout(problems, batch: int):
    """The problems in a static row layout (a block per kind, inactive slots interleaved),
    tiled to ``batch``: (kinds, numpy arrays of the ConstraintProblem, warm starts, qacc)."""
    rng = np.random.default_rng(1)
    counts = [max(int(np.sum(p["kinds"] == k)) for p in problems) + 2 for k in range(3)]
    kinds = np.concatenate([np.full(c, k) for k, c in enumerate(counts)])
    n, nv = len(kinds), problems[0]["M"].shape[0]
    rows = {k: np.zeros((len(problems), n)) for k in ("D", "aref", "frictionloss")}
    rows["R"] = np.ones((len(problems), n))
    J, active = np.zeros((len(problems), n, nv)), np.zeros((len(problems), n), bool)
    for b, p in enumerate(problems):
        for k in range(3):
            mine = np.flatnonzero(p["kinds"] == k)
            slots = np.sort(rng.choice(np.flatnonzero(kinds == k), len(mine), replace=False))
            for key in rows:
                rows[key][b, slots] = p[key][mine]
            J[b, slots], active[b, slots] = p["J"][mine], True
    arrays = dict(rows, J=J, active=active)
    for key in ("M", "qfrc_smooth", "qacc_smooth", "qacc_warmstart", "qacc"):
        arrays[key] = np.stack([p[key] for p in problems])
    index = np.arange(batch) % len(problems)
    return kinds, {k: v[index] for k, v in arrays.items()}


def as_backend(arrays, backend):
    xp = getattr(ivy, backend)
    problem = S.ConstraintProblem(*[xp.asarray(arrays[k]) for k in S.ConstraintProblem._fields])
    return problem, xp.asarray(arrays["qacc_warmstart"])


def block(x):
    """Wait for an asynchronous result (jax)."""
    getattr(x, "block_until_ready", lambda: None)()
    return x


def compiled_solver(backend, kinds, options, compiled=True, solves=1):
    """One solve, or four in a row as an RK4 step has them (each warm started by the last;
    written out: torch.compile runs a whole frame eagerly where a graph break, which the
    solver's loops make, falls inside a Python loop)."""
    xp = getattr(ivy, backend)

    def one(problem, warm):
        return S.solve(xp, problem, kinds, warm, options).qacc

    def four(problem, warm):
        warm = S.solve(xp, problem, kinds, warm, options).qacc
        warm = S.solve(xp, problem, kinds, warm, options).qacc
        warm = S.solve(xp, problem, kinds, warm, options).qacc
        return S.solve(xp, problem, kinds, warm, options).qacc

    run = {1: one, 4: four}[solves]
    return ivy.compile_fn(run) if compiled else run


def first_call(fn, *args):
    start = time.perf_counter()
    out = block(fn(*args))
    return out, time.perf_counter() - start


def check(qacc, arrays, label):
    got, want = ivy.to_numpy(qacc), arrays["qacc"]
    error = np.abs(got - want).max() / max(1.0, np.abs(want).max())
    if error > 1e-9:
        raise AssertionError(f"{label}: qacc differs from MuJoCo's by {error:.1e} (relative)")
    return error


def measure(case, variants, repeats):
    """variants: label -> (fn, args). Compile, check, then interleaved timing."""
    timers, report = {}, {}
    for label, (fn, args, arrays) in variants.items():
        qacc, compile_s = first_call(fn, *args)
        error = check(qacc, arrays, f"{case} {label}")
        timers[label] = timeit.Timer(lambda fn=fn, args=args: block(fn(*args)))
        report[label] = (compile_s, error)
    samples = interleaved_samples(timers, number=1, repeats=repeats)
    for label, (compile_s, error) in report.items():
        best = min(samples[label])
        print(
            f"  {label:<28} compile {compile_s:7.2f} s   solve {best * 1e3:9.2f} ms"
            f"   error {error:.0e}"
        )
    return {label: min(samples[label]) for label in report}


def newton(args):
    for name, label in (("hopper.xml", "Hopper"), ("ant.xml", "Ant")):
        model, problems, mujoco_s = sample(name, DISTINCT)
        options = S.SolverOptions.from_mujoco(model)
        kinds, _ = layout(problems, 1)
        print(
            f"\nNewton, {label}: nv {model.nv}, {len(kinds)} row slots (active in the sample: "
            f"{min(len(p['kinds']) for p in problems)}-{max(len(p['kinds']) for p in problems)})"
            f"; MuJoCo mj_fwdConstraint {mujoco_s * 1e6:.1f} us per state"
        )
        for batch in args.batches:
            kinds, arrays = layout(problems, batch)
            print(f" batch {batch}: MuJoCo, one state at a time: {mujoco_s * batch * 1e3:.2f} ms")
            variants = {}
            for backend in args.backends:
                problem, warm = as_backend(arrays, backend)
                for compiled in (True, False) if backend == "torch" else (True,):
                    fn = compiled_solver(backend, kinds, options, compiled=compiled)
                    name = f"{backend} {'compiled' if compiled else 'eager'}"
                    variants[name] = (fn, (problem, warm), arrays)
            measure(f"{label} {batch}", variants, args.repeats)


def four_solves(args):
    model, problems, _ = sample("hopper.xml", DISTINCT)
    options = S.SolverOptions.from_mujoco(model)
    kinds, arrays = layout(problems, args.batches[0])
    batch = arrays["M"].shape[0]
    print(f"\nCompile time of one function with four Newton solves (Hopper, batch {batch})")
    for backend in args.backends:
        if backend == "torch":  # dynamo forgets the solver's frames compiled above
            import torch

            torch._dynamo.reset()
        problem, warm = as_backend(arrays, backend)
        _, seconds = first_call(compiled_solver(backend, kinds, options, solves=4), problem, warm)
        print(f"  {backend:<10} {seconds:7.2f} s")
    if args.unrolled and "torch" in args.backends:
        unrolled_torch(args, kinds, arrays, options)


def unrolled_torch(args, kinds, arrays, options):
    """torch.compile of the Newton loop unrolled to K masked iterations (the alternative to the
    solver's data-dependent loop, which breaks torch's graph once per iteration)."""
    import torch

    xp = ivy.torch
    original = xp.while_loop

    def unrolled(cond_fun, body_fun, init_val, *, maximum_iterations=None):
        val = init_val
        for _ in range(args.unrolled):
            go = cond_fun(val)
            new = body_fun(val)
            val = type(val)(torch.where(go, n, o) for n, o in zip(new, val))
        return val

    problem, warm = as_backend(arrays, "torch")
    try:
        xp.while_loop = unrolled
        torch._dynamo.reset()
        print(f"  torch, Newton unrolled to {args.unrolled} iterations (no graph break):")
        for solves in (1, 4):
            fn = compiled_solver("torch", kinds, options, solves=solves)
            _, seconds = first_call(fn, problem, warm)
            print(f"    {solves} solve(s): compile {seconds:7.2f} s")
    finally:
        xp.while_loop = original


def pgs(args):
    model, problems, mujoco_s = sample("humanoid.xml", DISTINCT)
    options = S.SolverOptions.from_mujoco(model)
    kinds, _ = layout(problems, 1)
    print(
        f"\nPGS, Humanoid: nv {model.nv}, {len(kinds)} row slots (active in the sample: "
        f"{min(len(p['kinds']) for p in problems)}-{max(len(p['kinds']) for p in problems)}), "
        f"{options.iterations} iterations; MuJoCo mj_fwdConstraint {mujoco_s * 1e6:.1f} us "
        f"per state"
    )
    for batch in args.humanoid_batches:
        kinds, arrays = layout(problems, batch)
        print(f" batch {batch}: MuJoCo, one state at a time: {mujoco_s * batch * 1e3:.2f} ms")
        variants = {}
        for backend in args.backends:
            problem, warm = as_backend(arrays, backend)
            loops = ivy.framework_handler.capabilities(backend).compiled_loops
            compiled = loops or args.torch_pgs_compiled
            label = f"{backend} {'compiled' if compiled else 'eager'}"
            fn = compiled_solver(backend, kinds, options, compiled=compiled)
            variants[label] = (fn, (problem, warm), arrays)
        measure(f"Humanoid {batch}", variants, max(2, args.repeats // 2))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--batches", default="1000,4096")
    parser.add_argument("--humanoid-batches", default="100,1000")
    parser.add_argument("--backends", default="jax,torch")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--unrolled", type=int, default=0)
    parser.add_argument("--torch-pgs-compiled", action="store_true")
    parser.add_argument("--skip", default="", help="comma-separated: newton,four,pgs")
    parser.add_argument("--threads", type=int, default=1, help="intra-op threads (0: default)")
    args = parser.parse_args()
    if args.threads:
        flags = "--xla_cpu_multi_thread_eigen=false intra_op_parallelism_threads=1"
        if args.threads == 1 and "jax" not in sys.modules:
            os.environ["XLA_FLAGS"] = (os.environ.get("XLA_FLAGS", "") + " " + flags).strip()
        if "torch" in args.backends.split(","):
            import torch

            torch.set_num_threads(args.threads)
    args.batches = [int(b) for b in args.batches.split(",")]
    args.humanoid_batches = [int(b) for b in args.humanoid_batches.split(",")]
    args.backends = [b for b in args.backends.split(",") if b]
    if "jax" in args.backends:
        import jax

        jax.config.update("jax_enable_x64", True)
    warnings.filterwarnings("ignore")
    skip = set(args.skip.split(","))
    threads = args.threads or "default"
    print(f"float64, CPU, {os.cpu_count()} cores, {threads} thread(s); backends {args.backends}")
    if "newton" not in skip:
        newton(args)
    if "four" not in skip:
        four_solves(args)
    if "pgs" not in skip:
        pgs(args)


if __name__ == "__main__":
    main()
