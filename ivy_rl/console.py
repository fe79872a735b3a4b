"""What a training run prints: a start line, a progress bar over the whole run (with the rate,
elapsed time and estimated time left), a line while the agent compiles, a table per epoch, and a
summary at the end (the best score, the run's folder, how to play, plot and continue it).

On a terminal the bar is redrawn in place on stderr (at most ten times a second); where stderr is
a file or a pipe (a run under ``nohup``, a job's log) a progress line is written at most every
``line_seconds`` instead. Quiet, only the summary and what the user must know (an interrupted
run, a finished run resumed) are printed.

Example:
    >>> console = Console()
    >>> console.start("training PPO on CartPole-v1 with torch: 100,000 steps -> runs/ppo")
    training PPO on CartPole-v1 with torch: 100,000 steps -> runs/ppo
    >>> console.progress(5_000, 100_000, elapsed=4.2)  # the bar, on stderr
"""

from __future__ import annotations

import collections
import os
import shlex
import shutil
import sys
import threading
import time
from collections.abc import Callable, Sequence
from typing import Any, TextIO

__all__ = [
    "Console",
    "format_duration",
    "command",
    "start_line",
    "summary",
    "interrupted",
    "finished",
    "family_defaults",
]


def format_duration(seconds: float) -> str:
    """``h:mm:ss`` (``d days, h:mm:ss`` past a day).

    Example:
        >>> format_duration(3725.2)
        '1:02:05'
    """
    if seconds != seconds or seconds in (float("inf"), float("-inf")):
        return "?"
    seconds = int(round(max(seconds, 0.0)))
    days, rest = divmod(seconds, 86400)
    hours, rest = divmod(rest, 3600)
    minutes, secs = divmod(rest, 60)
    text = f"{hours}:{minutes:02d}:{secs:02d}"
    return f"{days} day{'s' if days > 1 else ''}, {text}" if days else text


def command(*words: Any) -> str:
    """A shell command line, quoting what needs it.

    Example:
        >>> command("python", "-m", "ivy_rl.play", "runs/my run")
        "python -m ivy_rl.play 'runs/my run'"
    """
    return " ".join(shlex.quote(str(w)) for w in words)


class Console:
    """The run's console.

    Args:
        quiet: print only the summary and the messages a user must see (interruptions).
        stdout, stderr: streams (default: ``sys.stdout`` and ``sys.stderr`` when written).
        line_seconds: seconds between progress lines where stderr is not a terminal.
        compile_seconds: how long a call runs, with the agent's compilations growing, before
            the console says that it compiles.

    Example:
        >>> Console(quiet=True).summary(["finished: 1,000 steps in 0:00:02"])
        finished: 1,000 steps in 0:00:02
    """

    def __init__(
        self,
        *,
        quiet: bool = False,
        stdout: TextIO | None = None,
        stderr: TextIO | None = None,
        line_seconds: float = 30.0,
        compile_seconds: float = 2.0,
    ) -> None:
        self.quiet = quiet
        self._stdout, self._stderr = stdout, stderr
        self.line_seconds = line_seconds
        self.compile_seconds = compile_seconds
        self._bar_shown = False
        self._last_draw = -float("inf")
        self._samples: collections.deque = collections.deque()
        self._lock = threading.RLock()
        self._watch: threading.Thread | None = None
        self._stop = threading.Event()
        self._tick = (time.monotonic(), 0)  # (when the loop last ticked, compilations then)
        self._compiling_since: float | None = None
        self._last_progress: tuple[int, int, float] | None = None

    # streams, looked up when written (so that redirections made later are followed)
    @property
    def stdout(self) -> TextIO:
        return self._stdout or sys.stdout

    @property
    def stderr(self) -> TextIO:
        return self._stderr or sys.stderr

    @property
    def tty(self) -> bool:
        isatty = getattr(self.stderr, "isatty", None)
        try:
            return bool(isatty and isatty())
        except ValueError:  # a closed stream
            return False

    # ------------------------------------------------------------------------------------------

    def _clear_bar(self) -> None:
        if self._bar_shown:
            self.stderr.write("\r\033[K")
            self.stderr.flush()
            self._bar_shown = False

    def print(self, text: str, *, always: bool = False, error: bool = False) -> None:
        """Print lines (on stdout; ``error``: on stderr), above the progress bar; nothing when
        quiet unless ``always``."""
        if self.quiet and not always:
            return
        with self._lock:
            self._clear_bar()
            stream = self.stderr if error else self.stdout
            stream.write(text.rstrip("\n") + "\n")
            stream.flush()
            if self._last_progress is not None and self.tty and not self.quiet:
                self._draw(*self._last_progress)

    def start(self, text: str) -> None:
        """The start line: what trains where, and where the run is written."""
        self.print(text)

    def progress(self, steps: int, max_steps: int, *, elapsed: float, force: bool = False) -> None:
        """Update the progress bar: ``steps`` of ``max_steps`` done, ``elapsed`` seconds of the
        run so far (earlier sessions of a resumed run included)."""
        now = time.monotonic()
        self._samples.append((now, steps))
        while len(self._samples) > 2 and now - self._samples[1][0] > 30.0:
            self._samples.popleft()  # the rate over the last half minute
        self._last_progress = (steps, max_steps, elapsed)
        if self.quiet:
            return
        interval = 0.1 if self.tty else self.line_seconds
        if not force and now - self._last_draw < interval:
            return
        with self._lock:
            self._draw(steps, max_steps, elapsed)

    def rate(self) -> float | None:
        """Steps per second over the last half minute (None before two measurements)."""
        if len(self._samples) < 2:
            return None
        (t0, s0), (t1, s1) = self._samples[0], self._samples[-1]
        return (s1 - s0) / (t1 - t0) if t1 > t0 and s1 > s0 else None

    def bar(self, steps: int, max_steps: int, elapsed: float, width: int = 30) -> str:
        """The progress line: percent, bar, steps, rate, elapsed time and time left.

        Example:
            >>> Console().bar(5_000, 20_000, 12.0)  # no rate measured yet
            ' 25% [#######-----------------------] 5,000/20,000 steps | - steps/s | elapsed 0:00:12 | left ?'
        """
        done = min(steps / max(max_steps, 1), 1.0)
        filled = int(width * done)
        rate = self.rate()
        speed = f"{rate:,.0f} steps/s" if rate else "- steps/s"
        left = format_duration((max_steps - steps) / rate) if rate else "?"
        return (
            f"{100 * done:3.0f}% [{'#' * filled}{'-' * (width - filled)}] "
            f"{steps:,}/{max_steps:,} steps | {speed} | elapsed {format_duration(elapsed)} | "
            f"left {left}"
        )

    def _draw(self, steps: int, max_steps: int, elapsed: float) -> None:
        self._last_draw = time.monotonic()
        line = self.bar(steps, max_steps, elapsed)
        if self.tty:
            # one line of the terminal (a wrapped line is not redrawn in place): a narrower bar,
            # then the line cut
            columns = shutil.get_terminal_size((100, 24)).columns - 1
            if len(line) > columns:
                width = max(30 - (len(line) - columns), 10)
                line = self.bar(steps, max_steps, elapsed, width=width)[:columns]
            self.stderr.write("\r\033[K" + line)
            self._bar_shown = True
        else:
            self.stderr.write(line + "\n")
        self.stderr.flush()

    def table(self, row: dict[str, Any]) -> None:
        """An epoch's row as a table (means; no std, min and max)."""
        keys = [k for k in row if not k.endswith(("/std", "/min", "/max"))]
        if not keys:
            return
        width = max(len(k) for k in keys)
        line = "-" * (width + 16)
        lines = [line, *(f"| {k:<{width}} | {_format(row[k]):>10} |" for k in keys), line]
        self.print("\n".join(lines))

    def summary(self, lines: list[str]) -> None:
        """The end of the run: printed even when quiet."""
        self.print("\n".join(lines), always=True)

    # ------------------------------------------------------------------------------------------
    # Compilation
    # ------------------------------------------------------------------------------------------

    def watch_compiles(self, compiles: Callable[[], int], what: str) -> None:
        """Watch a long call: when the loop has not ticked (:meth:`tick`) for
        ``compile_seconds`` and ``compiles()`` grew meanwhile, say that ``what`` compiles (the
        agent's compiled functions count a compilation when they meet a new signature, before
        compiling); when the loop ticks again, say how long it took."""
        if self.quiet or self._watch is not None:
            return
        self._compiles, self._what = compiles, what
        self._tick = (time.monotonic(), self._count())
        self._watch = threading.Thread(target=self._watching, name="ivy_rl-console", daemon=True)
        self._watch.start()

    def _count(self) -> int:
        try:
            return int(self._compiles())
        except Exception:  # read while the loop changes it: try again later
            return -1

    def tick(self) -> None:
        """The training loop is between calls (cheap: call it every step)."""
        if self._watch is None:
            return
        now = time.monotonic()
        if self._compiling_since is not None:
            with self._lock:
                took = now - self._compiling_since
                self._compiling_since = None
                self._samples.clear()  # the rate from here on, without the compilation
                self.print(f"compiled in {format_duration(took)}", error=True)
        self._tick = (now, self._count())

    def _watching(self) -> None:
        while not self._stop.wait(min(0.25, max(self.compile_seconds / 4, 0.005))):
            since, before = self._tick
            if self._compiling_since is not None or time.monotonic() - since < self.compile_seconds:
                continue
            now = self._count()
            if before >= 0 and now > before:
                with self._lock:
                    if self._tick[0] != since:  # the loop went on meanwhile
                        continue
                    self._compiling_since = since
                    self.print(
                        f"compiling {self._what} (its first calls compile; this can take a "
                        "few minutes on torch) ...",
                        error=True,
                    )

    def close(self) -> None:
        """Stop watching, and end the progress bar's line."""
        self._stop.set()
        if self._watch is not None:
            self._watch.join(timeout=1.0)
            self._watch = None
        with self._lock:
            self._clear_bar()
            self._last_progress = None  # what is printed next is not redrawn under a bar


def _format(value: Any) -> str:
    if isinstance(value, float):
        if value != 0 and (abs(value) >= 1e6 or abs(value) < 1e-3):
            return f"{value:.3e}"
        return f"{value:.4g}"
    if isinstance(value, int):
        return f"{value:,}" if abs(value) >= 10_000 else str(value)
    return str(value)


# ----------------------------------------------------------------------------------------------
# What the trainer says
# ----------------------------------------------------------------------------------------------


def start_line(
    agent: str,
    environment: str,
    *,
    framework: str,
    dtype: str,
    device: Any,
    compiled: bool,
    steps: int,
    workers: int,
    seed: int,
    out: str | None,
    resumed_at: int | None = None,
    checkpoint: str | None = None,
) -> str:
    """The first line of a run: what trains where, for how long, and where it is written.

    Example:
        >>> start_line("SAC", "Pendulum-v1", framework="jax", dtype="float32", device="cpu",
        ...            compiled=True, steps=20_000, workers=1, seed=0, out="runs/sac")
        'training SAC on Pendulum-v1 with jax (float32, cpu, compiled): 20,000 steps, 1 worker, seed 0 -> runs/sac'
    """
    where = f"{framework} ({dtype}, {device}, {'compiled' if compiled else 'eager'})"
    folder = f" -> {out}" if out is not None else " (no out folder: nothing is saved)"
    if resumed_at is not None:
        name = os.path.relpath(checkpoint, out) if checkpoint and out else checkpoint
        return (
            f"resuming {agent} on {environment} with {where} from step {resumed_at:,} "
            f"({name}) to {steps:,} steps{folder}"
        )
    return (
        f"training {agent} on {environment} with {where}: {steps:,} steps, {workers} "
        f"worker{'s' if workers > 1 else ''}, seed {seed}{folder}"
    )


def summary(
    rows: Sequence[dict[str, Any]],
    *,
    steps: int | None,
    max_steps: int,
    elapsed: float,
    rate: float | None,
    test_episodes: int,
    out: str | None,
) -> list[str]:
    """The end of a run: steps and time (when it trained: ``steps``), the best and last test
    scores of ``rows`` (the log), the folder and the commands that play, plot and continue it."""
    lines = []
    if steps is not None:
        speed = f" ({rate:,.0f} steps/s)" if rate else ""
        lines.append(f"finished: {steps:,} steps in {format_duration(elapsed)}{speed}")
    scores = [
        (r["test/episode_score/mean"], r.get("train/steps", 0))
        for r in rows
        if r.get("test/episode_score/mean") is not None
    ]
    if scores:
        best, at = max(scores, key=lambda pair: pair[0])
        plural = "s" if test_episodes > 1 else ""
        lines.append(
            f"test score: best {best:.2f} at step {int(at):,}, last {scores[-1][0]:.2f} "
            f"(mean of {test_episodes} episode{plural})"
        )
    if out is not None:
        best = ["--best"] if os.path.isdir(os.path.join(out, "best")) else []
        curves = os.path.join(out, "curves.png")
        lines += [
            f"run folder: {out}",
            f"  play:   {command('python', '-m', 'ivy_rl.play', out, *best)}",
            f"  plot:   {command('python', '-m', 'ivy_rl.plot', out, '--out', curves)}",
            "  go on:  "
            + command(
                "python", "-m", "ivy_rl.train", "--out", out, "--resume", "--steps", 2 * max_steps
            ),
        ]
    return lines


def interrupted(
    steps: int, max_steps: int, out: str | None, saved: str | None, last: str | None
) -> str:
    """What Ctrl-C stopped: where, what was saved (``saved``; else the ``last`` checkpoint), and
    how to resume."""
    text = f"interrupted at step {steps:,} of {max_steps:,}"
    if saved is not None:
        text += f": saved {saved}"
    elif out is not None:
        text += ", not saved" + (
            f" (the last checkpoint is {os.path.basename(last)})" if last else ""
        )
    if out is not None and (saved or last):
        text += "\nresume with: " + command(
            "python", "-m", "ivy_rl.train", "--out", out, "--resume"
        )
    return text


def finished(out: str, max_steps: int, steps: int, checkpoint: str) -> str:
    """A finished run resumed: nothing to train, and how to go on."""
    return (
        f"the run in {out} has done its {max_steps:,} steps (its last checkpoint, "
        f"{os.path.basename(checkpoint)}, is at step {steps:,}): nothing to train; to go on, "
        f"resume with --steps above {steps:,}"
    )


def family_defaults(agent: str, environment: Any, given: Sequence[str] = ()) -> list[str]:
    """Where the defaults of the environment's task family (what the command line and
    ``make(agent, environment=...)`` use, :mod:`ivy_rl.agents.defaults`) differ from the agent
    class's own (``SAC()``'s), the settings in ``given`` (the user's) left out: a few lines
    under the start line, none where they agree.

    Example:
        >>> for line in family_defaults("SAC", "Pendulum-v1", given=["hidden_sizes"]):
        ...     print(line)
        defaults of the classic_continuous family where they differ from SAC()'s:
          batch_size 128 (SAC(): 256)
          every setting: python -m ivy_rl.agents.defaults SAC Pendulum-v1
    """
    from ivy_rl.agents import make
    from ivy_rl.agents.defaults import settings_table, task_family

    name = make.resolve(agent)
    rows = [
        row
        for row in settings_table(name, environment)
        if row["name"] not in given and row["differs"]
    ]
    if not rows:
        return []
    shown = [
        f"{row['name']} {_shown(row['family_default'])} ({name}(): {_shown(row['agent_default'])})"
        for row in rows
    ]
    lines, line = [], ""
    width = 96
    for item in shown:
        if line and len(line) + len(item) + 2 > width:
            lines.append(line + ",")
            line = ""
        line = f"{line}, {item}" if line else item
    lines.append(line)
    return [
        f"defaults of the {task_family(environment)} family where they differ from {name}()'s:",
        *(f"  {line}" for line in lines),
        "  every setting: " + command("python", "-m", "ivy_rl.agents.defaults", name, environment),
    ]


def _shown(value: Any) -> str:
    return str(tuple(value) if isinstance(value, list) else value)
