"""The trainer's logger: one row per epoch in ``log.csv``, and the same scalars in TensorBoard
when asked. It prints nothing: the run's console (the epoch's table, the progress bar, the
summary) is :class:`ivy_rl.console.Console`'s.

Values stored during an epoch are averaged when the epoch ends; values stored with
``stats=True`` (episode scores...) are summarised as ``key/mean``, ``key/std``, ``key/min`` and
``key/max``. When a new column appears (an agent's first losses), ``log.csv`` is rewritten with
the new header.

Example:
    >>> log = Logger("runs/ppo")
    >>> log.store("train/episode_score", 21.0, stats=True)
    >>> log.store("train/episode_score", 25.0, stats=True)
    >>> row = log.dump({"train/steps": 1000})          # a row of log.csv
    >>> row["train/episode_score/mean"], row["train/episode_score/max"]
    (23.0, 25.0)
"""

from __future__ import annotations

import csv
import math
import os
import time
import warnings
from typing import Any

import numpy as np

__all__ = ["Logger", "read_log"]


class Logger:
    """Writes ``<out>/log.csv`` and optionally TensorBoard events (it prints nothing).

    Args:
        out: the run's folder (None: nothing is written to disk).
        tensorboard: also write TensorBoard events to ``<out>/tensorboard``.

    Example:
        >>> log = Logger("runs/a2c", tensorboard=True)
    """

    def __init__(self, out: str | None = None, *, tensorboard: bool = False):
        self.out = out
        self.columns: list[str] = []
        self.rows: list[dict[str, Any]] = []
        self._values: dict[str, list[float]] = {}
        self._stats: set[str] = set()
        self._writer = None
        self.warnings: list[str] = []
        if out is not None:
            os.makedirs(out, exist_ok=True)
            if tensorboard:
                self._writer = _TensorBoard(os.path.join(out, "tensorboard"))

    @property
    def path(self) -> str | None:
        return None if self.out is None else os.path.join(self.out, "log.csv")

    def store(self, key: str, value: Any, *, stats: bool = False) -> None:
        """Add a value (a number or an array, flattened) to the epoch's values of ``key``."""
        values = np.asarray(value, dtype=np.float64).ravel()
        self._values.setdefault(key, []).extend(values.tolist())
        if stats:
            self._stats.add(key)

    def warning(self, message: str) -> None:
        """Report a problem of the run (kept in ``self.warnings``, and a ``RuntimeWarning``)."""
        self.warnings.append(message)
        warnings.warn(message, RuntimeWarning, stacklevel=2)

    def dump(self, fixed: dict[str, Any]) -> dict[str, Any]:
        """End the epoch: summarise the stored values with ``fixed`` scalars into one row,
        write it, and start a new epoch.

        Returns:
            The row.
        """
        row: dict[str, Any] = dict(fixed)
        for key, values in sorted(self._values.items()):
            if not values:
                continue
            if key in self._stats:
                array = np.asarray(values)
                row[f"{key}/mean"] = float(array.mean())
                row[f"{key}/std"] = float(array.std())
                row[f"{key}/min"] = float(array.min())
                row[f"{key}/max"] = float(array.max())
            else:
                row[key] = float(np.mean(values))
        self._values, self._stats = {}, set()
        self.rows.append(row)
        new_columns = [k for k in row if k not in self.columns]
        self.columns.extend(new_columns)
        if self.path is not None:
            if new_columns or len(self.rows) == 1:
                self._rewrite()
            else:
                with open(self.path, "a", newline="") as fh:
                    csv.DictWriter(fh, self.columns).writerow(row)
        if self._writer is not None:
            step = int(row.get("train/steps", len(self.rows)))
            self._writer.scalars(step, {k: v for k, v in row.items() if _is_number(v)})
        return row

    def _rewrite(self) -> None:
        with open(self.path, "w", newline="") as fh:
            writer = csv.DictWriter(fh, self.columns)
            writer.writeheader()
            writer.writerows(self.rows)

    def restore(self, epochs: int) -> None:
        """Keep the first ``epochs`` rows of an existing ``log.csv`` (resuming a run)."""
        if self.path is None or not os.path.exists(self.path):
            if epochs:
                raise FileNotFoundError(f"cannot resume: {self.path} is missing")
            return
        self.rows = read_log(self.path)[:epochs]
        self.columns = []
        for row in self.rows:
            self.columns.extend(k for k in row if k not in self.columns)
        self._rewrite()

    def pending(self) -> dict[str, Any]:
        """The values stored in the epoch so far (a checkpoint taken within an epoch keeps
        them): ``{'values': {key: [...]}, 'stats': [keys]}``."""
        return {
            "values": {k: list(v) for k, v in self._values.items()},
            "stats": sorted(self._stats),
        }

    def restore_pending(self, pending: dict[str, Any] | None) -> None:
        """Continue an epoch with the values of :meth:`pending`."""
        pending = pending or {}
        self._values = {k: [float(x) for x in v] for k, v in pending.get("values", {}).items()}
        self._stats = set(pending.get("stats", ()))

    def close(self) -> None:
        if self._writer is not None:
            self._writer.close()


def _is_number(value: Any) -> bool:
    return isinstance(value, (int, float)) and math.isfinite(value)


def read_log(path: str) -> list[dict[str, Any]]:
    """The rows of a ``log.csv`` as dicts of numbers: ints where a cell holds an integer (the
    counters), floats elsewhere; empty cells are left out. Written back, a row reads the same.

    Example:
        >>> log = Logger("runs/ppo")
        >>> log.store("test/episode_score", 200.0, stats=True)
        >>> row = log.dump({"train/steps": 1000})
        >>> rows = read_log("runs/ppo/log.csv")
        >>> rows[-1]["train/steps"], rows[-1]["test/episode_score/mean"]
        (1000, 200.0)
    """
    with open(path, newline="") as fh:
        rows = []
        for raw in csv.DictReader(fh):
            rows.append({k: _number(v) for k, v in raw.items() if v not in ("", None)})
    return rows


def _number(text: str) -> int | float:
    try:
        return int(text)
    except ValueError:
        return float(text)


class _TensorBoard:
    """Scalars as TensorBoard event files, written with the ``tensorboard`` package's record
    writer and protocol buffers (neither tensorflow nor torch is imported)."""

    def __init__(self, folder: str) -> None:
        try:
            from tensorboard.compat.proto.event_pb2 import Event
            from tensorboard.compat.proto.summary_pb2 import Summary
            from tensorboard.summary.writer.record_writer import RecordWriter
        except ImportError as error:
            raise ImportError(
                "--tensorboard needs the 'tensorboard' package: pip install 'ivy[rl]'"
            ) from error
        import socket

        os.makedirs(folder, exist_ok=True)
        name = f"events.out.tfevents.{int(time.time())}.{socket.gethostname()}.{os.getpid()}"
        self._file = open(os.path.join(folder, name), "wb")  # noqa: SIM115 - closed in close()
        self._records = RecordWriter(self._file)
        self._event, self._summary = Event, Summary
        self._write(Event(wall_time=time.time(), file_version="brain.Event:2"))

    def _write(self, event) -> None:
        self._records.write(event.SerializeToString())
        self._file.flush()

    def scalars(self, step: int, values: dict[str, float]) -> None:
        summary = self._summary(
            value=[self._summary.Value(tag=k, simple_value=float(v)) for k, v in values.items()]
        )
        self._write(self._event(wall_time=time.time(), step=step, summary=summary))

    def close(self) -> None:
        self._file.close()
