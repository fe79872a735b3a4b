"""What the commands (``train``, ``play``, ``plot``) share: one-line errors, the checks of a
framework, a dtype and a device, and a run folder's ``config.json``."""

from __future__ import annotations

import json
import os
import re
import sys
from collections.abc import Callable
from typing import Any

import ivy

__all__ = ["command_line", "check_framework", "check_device", "read_config", "enable_float64"]

# errors a user can fix from the command line: printed as one line, exit status 2
USER_ERRORS = (ValueError, TypeError, FileNotFoundError, ImportError, ivy.errors.IvyError)


def command_line(main: Callable[[list[str] | None], Any], argv: list[str] | None = None) -> None:
    """Run a command's ``main``; an error the user can fix is printed as ``error: ...`` on one
    line, with exit status 2 (as argparse does for malformed arguments); Ctrl-C exits with
    status 130 and no traceback."""
    try:
        main(argv)
    except USER_ERRORS as error:
        message = " ".join(str(error).split())
        print(f"error: {message}", file=sys.stderr)
        raise SystemExit(2) from None
    except KeyboardInterrupt as interrupt:
        # Ctrl-C: no traceback; a run the trainer stopped has said where it saved and how to
        # resume (its TrainingInterrupted is ``reported``)
        if not getattr(interrupt, "reported", False):
            print("interrupted", file=sys.stderr)
        raise SystemExit(130) from None


def check_framework(framework: str, dtype: str = "float32") -> None:
    """Raise when ``framework`` is unknown or cannot compute in ``dtype`` (no framework is
    imported)."""
    capabilities = ivy.framework_handler.capabilities(framework)
    if dtype not in ("float32", "float64"):
        raise ValueError(f"--dtype must be float32 or float64, got {dtype!r}")
    if dtype == "float64" and not capabilities.float64:
        raise ValueError(f"--framework {framework} has no float64; use --dtype float32")


def check_device(device: str | None, framework: str) -> None:
    """Raise when ``device`` is not ``'<kind>'`` or ``'<kind>:<index>'`` of a kind the framework
    places arrays on (``cpu``, ``gpu``...)."""
    if device is None:
        return
    match = re.fullmatch(r"([a-z]+)(?::(\d+))?", str(device))
    kinds = ivy.framework_handler.capabilities(framework).devices
    if match is None or match.group(1) not in kinds:
        choices = ", ".join(f"'{k}'" if k == "cpu" else f"'{k}:0'" for k in kinds)
        raise ValueError(
            f"--device {device!r} is not a device of {framework}; choose one of {choices}"
        )


def enable_float64(framework: str, dtype: str) -> None:
    """Make 64-bit floats available where the framework holds them only on request.

    Asks the backend's namespace whether it can hold float64 now (jax only does so in its
    64-bit mode, which must be switched on before any computation); switches the mode on
    where it cannot.
    """
    if dtype != "float64":
        return
    xp = ivy.get_framework(f=framework)
    if "float64" in xp.__array_namespace_info__().dtypes(kind="real floating"):
        return
    import jax  # the only framework whose 64-bit types come and go

    jax.config.update("jax_enable_x64", True)


def read_config(run: str) -> dict[str, Any]:
    """The ``config.json`` of a run folder, with one-line errors for a missing folder, a folder
    that is not a run, and a damaged file."""
    if not os.path.isdir(run):
        raise FileNotFoundError(f"no run folder {run!r}: it does not exist")
    path = os.path.join(run, "config.json")
    if not os.path.exists(path):
        raise FileNotFoundError(
            f"{run!r} is not a run folder: it has no config.json (python -m ivy_rl.train "
            "--out <folder> writes one)"
        )
    try:
        with open(path) as fh:
            config = json.load(fh)
    except (json.JSONDecodeError, UnicodeDecodeError) as error:
        raise ValueError(f"{path} is not valid JSON ({error})") from None
    if not isinstance(config, dict):
        raise ValueError(f"{path} does not hold a JSON object")
    return config
