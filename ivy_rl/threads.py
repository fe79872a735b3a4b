"""Intra-op threads of a framework: :func:`ivy.set_threads`, kept here under its old name.

The setting belongs with ivy's backends (``ivy/threads.py``); ivy_rl's trainer calls it with
``--threads``. New code calls ``ivy.set_threads``.

Example:
    >>> from ivy_rl.threads import set_threads
    >>> set_threads("torch", 1)
    'torch.set_num_threads(1)'
"""

from __future__ import annotations

from ivy.threads import set_threads

__all__ = ["set_threads"]
