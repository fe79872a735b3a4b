"""Runtime overhead of ivy's abstraction per function and backend, in the paper's three groups
(backend, Ivy compilable, Ivy eager), measured by direct timing against the native call.

Usage:
    python scripts/profile_overhead.py [--functions sin,clip,lstm_update] [--out DIR]
        [--backends numpy,torch,jax,tensorflow] [--repeats 7] [--sample-ms 2] [--top 30] [--clock cpu|wall]

Times are the CPU time of this process (``time.process_time``; ``--clock wall`` for elapsed time)
with one intra-op thread per framework: on a busy shared machine elapsed time mostly measures the
other processes, while the CPU time of a single-threaded call is what the call costs. Each figure
is the minimum over interleaved samples (interference only ever adds time).

Every function the core lists (``ivy.list_functions()``: dispatched, by hand and compositions;
aliases and functions that take functions are skipped) runs on every selected backend with inputs
of about 10,000 elements (``scripts/_profile_inputs.py``). Three calls are timed, interleaved
sample by sample (``benchmarks/_timing.py``, ``--repeats`` samples each):

- ``total``: ``ivy.fn(...)``, the framework inferred from the inputs (``f=`` where none has one);
- ``ivy.<b>.fn``: the backend namespace's function, which the dispatch calls;
- ``native``: the framework's own function of the same name (``numpy.sin``, ``torch.clamp`` for
  ``clip``, ``tf.math.sin``...) on the same arguments, where there is one that gives the same
  result; else none.

The groups partition ``total``, each a measured difference (clipped at 0; the CSV keeps the
signed values):

- backend = ``native`` (where there is none: ``ivy.<b>.fn``, and the row says
  ``attribution=none``: what the backend function adds around the framework is then not split
  out, rather than guessed by tracing);
- Ivy compilable = ``ivy.<b>.fn - native``: the work of ivy's backend function beyond the native
  call (a cast, a transpose), which compiling keeps;
- Ivy eager = ``total - ivy.<b>.fn``: dispatch (type inference, the namespace lookup), which
  compiling removes.

jax dispatches asynchronously: each jax call is followed by ``block_until_ready``. Outputs in
``--out`` (default ``profile_overhead_out``): ``overhead.csv``, ``overhead.png`` (per backend, the
functions with the largest overhead as stacked bars of the three groups, log scale) and
``summary.md``.
"""

from __future__ import annotations

import argparse
import csv
import inspect
import math
import os
import statistics
import sys
import time
import timeit
import warnings
from pathlib import Path
from typing import Any


def _one_thread() -> None:
    """One intra-op thread per framework, through the variables they read when they load."""
    for var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
        os.environ.setdefault(var, "1")
    os.environ.setdefault("TF_NUM_INTRAOP_THREADS", "1")
    os.environ.setdefault("TF_NUM_INTEROP_THREADS", "1")
    flags = os.environ.get("XLA_FLAGS", "")
    if "intra_op_parallelism_threads" not in flags:
        os.environ["XLA_FLAGS"] = (
            f"{flags} --xla_cpu_multi_thread_eigen=false intra_op_parallelism_threads=1"
        ).strip()


if __name__ == "__main__":  # before numpy (BLAS) and the frameworks are imported
    _one_thread()

_HERE = Path(__file__).resolve().parent
for _path in (_HERE, _HERE.parent / "benchmarks", _HERE.parent):
    if str(_path) not in sys.path:
        sys.path.insert(0, str(_path))

import numpy as np  # noqa: E402
from _profile_inputs import Unbuildable, input_spec, materialize  # noqa: E402
from _timing import calls_per_sample, interleaved_samples  # noqa: E402

import ivy  # noqa: E402

COLUMNS = [
    "function",
    "kind",
    "backend",
    "total_us",
    "backend_fn_us",
    "native_us",
    "backend_us",
    "ivy_compilable_us",
    "ivy_eager_us",
    "eager_overhead_pct",
    "attribution",
    "native",
    "skipped",
]
# ivy name -> the framework's name where it differs
SYNONYMS = {
    "torch": {"clip": "clamp", "concat": "cat", "permute_dims": "permute", "pow": "pow"},
    "tensorflow": {"clip": "clip_by_value", "concat": "concat", "sum": "reduce_sum"},
}
HIGHER_ORDER = {"fn", "func", "function", "loss_fn", "body_fun", "cond_fun", "true_fun"}


def _native_modules(backend: str) -> list:
    if backend == "numpy":
        return [np, np.linalg, np.fft]
    if backend == "torch":
        import torch

        return [torch, torch.linalg, torch.fft, torch.nn.functional]
    if backend == "jax":
        import jax
        import jax.numpy as jnp

        return [jnp, jnp.linalg, jnp.fft, jax.nn]
    if backend == "tensorflow":
        import tensorflow as tf

        return [tf.math, tf, tf.linalg, tf.nn, tf.signal]
    return []


def native_function(name: str, backend: str):
    """The framework's own function for ``name`` (by name or a synonym), or None."""
    wanted = SYNONYMS.get(backend, {}).get(name, name)
    for module in _native_modules(backend):
        fn = getattr(module, wanted, None)
        if callable(fn) and not inspect.isclass(fn):
            return fn
    return None


def _sync(backend: str):
    if backend == "jax":
        import jax

        return jax.block_until_ready
    return lambda out: out


def _same(a: Any, b: Any) -> bool:
    try:
        x, y = np.asarray(ivy.to_numpy(a)), np.asarray(ivy.to_numpy(b))
    except Exception:  # noqa: BLE001 - a tuple, a namedtuple, a dtype...: not compared
        return False
    return x.shape == y.shape and np.allclose(x, y, rtol=1e-4, atol=1e-5, equal_nan=True)


CLOCKS = {"cpu": time.process_time, "wall": time.perf_counter}


def measure(
    name: str, kind: str, backend: str, args, kwargs, repeats: int, sample_s: float, clock="cpu"
):
    """One row: the three timings and the groups (see the module's docstring)."""
    ns = getattr(ivy, backend)
    agnostic, backend_fn = getattr(ivy, name), getattr(ns, name)
    has_array = _has_array(args, kwargs)
    sync = _sync(backend)
    calls = {
        "total": (lambda: sync(agnostic(*args, **kwargs)))
        if has_array
        else (lambda: sync(agnostic(*args, f=backend, **kwargs))),
        "backend_fn": lambda: sync(backend_fn(*args, **kwargs)),
    }
    expected = calls["backend_fn"]()
    native = native_function(name, backend)
    if native is not None and native is not backend_fn:
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                ok = _same(sync(native(*args, **kwargs)), expected)
        except Exception:  # noqa: BLE001 - other arguments: no native reference
            ok = False
        if ok:
            calls["native"] = lambda: sync(native(*args, **kwargs))
        else:
            native = None
    elif native is backend_fn:
        calls["native"] = calls["backend_fn"]  # the namespace exports the native object
    timers = {k: timeit.Timer(v, timer=CLOCKS[clock]) for k, v in calls.items()}
    number = calls_per_sample(timers["backend_fn"], target_s=sample_s)
    samples = interleaved_samples(timers, number, repeats)
    t = {k: min(v) * 1e6 for k, v in samples.items()}
    native_us = t.get("native", math.nan)
    base = t["backend_fn"] if math.isnan(native_us) else native_us
    return {
        "function": name,
        "kind": kind,
        "backend": backend,
        "total_us": t["total"],
        "backend_fn_us": t["backend_fn"],
        "native_us": native_us,
        "backend_us": base,
        "ivy_compilable_us": max(t["backend_fn"] - base, 0.0),
        "ivy_eager_us": max(t["total"] - t["backend_fn"], 0.0),
        "eager_overhead_pct": 100.0 * (t["total"] - base) / base,
        "attribution": "direct" if "native" in calls else "none",
        "native": "" if "native" not in calls else getattr(native or backend_fn, "__name__", ""),
        "skipped": "",
    }


def _has_array(args, kwargs) -> bool:
    leaves = [*args, *kwargs.values()]
    while leaves:
        v = leaves.pop()
        if isinstance(v, (list, tuple)):
            leaves.extend(v)
        elif hasattr(v, "shape") and hasattr(v, "dtype"):
            return True
    return False


def functions(selected: list[str] | None) -> list[tuple[str, str, str]]:
    """(name, kind, reason to skip or '') for the core's functions."""
    out = []
    for info in ivy.list_functions():
        if selected and info.name not in selected:
            continue
        if info.kind == "alias":
            out.append((info.name, info.kind, f"alias of {info.target}"))
            continue
        params = inspect.signature(getattr(ivy.core, info.name)).parameters
        if HIGHER_ORDER & set(params):
            out.append((info.name, info.kind, "takes a function: not timed per call"))
            continue
        out.append((info.name, info.kind, ""))
    return out


def run(names, backends, repeats=7, sample_s=0.002, progress=True, clock="cpu") -> list[dict]:
    rows = []
    rng = np.random.default_rng(0)
    for name, kind, reason in functions(names):
        for backend in backends:
            row = {c: "" for c in COLUMNS} | {"function": name, "kind": kind, "backend": backend}
            if reason:
                rows.append(row | {"skipped": reason})
                continue
            try:
                specs, kwspecs = input_spec(name, getattr(ivy.core, name))
                ns = getattr(ivy, backend)
                args = materialize(specs, ns, rng)
                kwargs = materialize(kwspecs, ns, rng)
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")
                    rows.append(
                        measure(name, kind, backend, args, kwargs, repeats, sample_s, clock)
                    )
            except Unbuildable as err:
                rows.append(row | {"skipped": str(err)})
            except Exception as err:  # noqa: BLE001 - listed, with the reason
                rows.append(row | {"skipped": f"{type(err).__name__}: {err}"[:200]})
            if progress:
                print(f"\r{name:>30} {backend:<12}", end="", file=sys.stderr, flush=True)
    if progress:
        print(file=sys.stderr)
    return rows


def write_csv(rows: list[dict], path: Path) -> None:
    with path.open("w", newline="") as fh:
        writer = csv.DictWriter(fh, COLUMNS)
        writer.writeheader()
        for row in rows:
            writer.writerow(
                {k: (f"{v:.3f}" if isinstance(v, float) else v) for k, v in row.items()}
            )


def _timed(rows: list[dict]) -> list[dict]:
    return [r for r in rows if not r["skipped"]]


def bar_limits(totals) -> tuple[float, float]:
    """The x-range of a log-scaled axis of bars with these totals (us): every bar visible, the
    shortest ending well inside the axis (matplotlib's own limits, set by the bars' stacked
    segments, could start above a short bar and hide it: jax's ``sin`` at 27 us)."""
    positive = [t for t in totals if t > 0] or [1.0]
    return min(positive) / 2.0, max(positive) * 1.5


def plot(rows: list[dict], path: Path, backends: list[str], top: int = 30) -> list[tuple]:
    """Draw the figure to ``path``; return each backend's x-limits (for the tests)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(backends), figsize=(5 * len(backends), 0.25 * top + 2))
    axes = np.atleast_1d(axes)
    colours = {"backend": "#4c72b0", "ivy_compilable": "#dd8452", "ivy_eager": "#c44e52"}
    limits = []
    for ax, backend in zip(axes, backends):
        mine = [r for r in _timed(rows) if r["backend"] == backend]
        mine.sort(key=lambda r: r["ivy_compilable_us"] + r["ivy_eager_us"], reverse=True)
        mine = mine[:top][::-1]
        y = np.arange(len(mine))
        left = np.zeros(len(mine))
        for group, colour in colours.items():
            width = np.array([r[f"{group}_us"] for r in mine])
            ax.barh(y, width, left=left, color=colour, label=group.replace("_", " "))
            left += width
        ax.set_yticks(
            y, [r["function"] + ("" if r["attribution"] == "direct" else " *") for r in mine]
        )
        ax.set_xscale("log")
        ax.set_xlim(*bar_limits(left))
        limits.append(ax.get_xlim())
        ax.set_xlabel("time per call (us), cumulative")
        ax.set_title(f"{backend} (* no native reference)")
    axes[0].legend(loc="lower right")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return limits


def summary(rows: list[dict], backends: list[str], top: int = 5) -> str:
    lines = ["# Runtime overhead of ivy per function", ""]
    lines += [
        "| backend | functions timed | with a native reference | median eager overhead "
        "(direct) | median Ivy eager (us) | median Ivy compilable (us, direct) |",
        "|---|---|---|---|---|---|",
    ]
    for backend in backends:
        mine = [r for r in _timed(rows) if r["backend"] == backend]
        direct = [r for r in mine if r["attribution"] == "direct"]
        med = lambda vals: statistics.median(vals) if vals else math.nan  # noqa: E731
        lines.append(
            f"| {backend} | {len(mine)} | {len(direct)} | "
            f"{med([r['eager_overhead_pct'] for r in direct]):.1f}% | "
            f"{med([r['ivy_eager_us'] for r in mine]):.2f} | "
            f"{med([r['ivy_compilable_us'] for r in direct]):.2f} |"
        )
    lines += ["", f"Largest overheads (Ivy compilable + Ivy eager), top {top} per backend:", ""]
    for backend in backends:
        mine = sorted(
            (r for r in _timed(rows) if r["backend"] == backend),
            key=lambda r: r["ivy_compilable_us"] + r["ivy_eager_us"],
            reverse=True,
        )[:top]
        cells = ", ".join(
            f"{r['function']} +{r['ivy_compilable_us'] + r['ivy_eager_us']:.1f} us "
            f"({r['backend_us']:.1f} us native, {r['attribution']})"
            for r in mine
        )
        lines.append(f"- {backend}: {cells}")
    skipped = sorted({(r["function"], r["skipped"]) for r in rows if r["skipped"]})
    lines += ["", f"Skipped: {len(skipped)} (function, reason) pairs, listed in the CSV."]
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> list[dict]:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--functions", default="")
    parser.add_argument("--backends", default=",".join(ivy.installed_frameworks()))
    parser.add_argument("--out", default="profile_overhead_out")
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--sample-ms", type=float, default=2.0)
    parser.add_argument("--top", type=int, default=30)
    parser.add_argument("--clock", choices=sorted(CLOCKS), default="cpu")
    parser.add_argument("--quiet", action="store_true")
    args = parser.parse_args(argv)
    names = [n for n in args.functions.split(",") if n] or None
    backends = [b for b in args.backends.split(",") if b]
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    rows = run(names, backends, args.repeats, args.sample_ms / 1e3, not args.quiet, args.clock)
    write_csv(rows, out / "overhead.csv")
    plot(rows, out / "overhead.png", backends, args.top)
    text = summary(rows, backends)
    (out / "summary.md").write_text(text)
    if not args.quiet:
        print(text)
    return rows


if __name__ == "__main__":
    main()
