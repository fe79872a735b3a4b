"""The conversions of model constants that ``constant`` keeps (see ``ivy.constant``).

A numpy array converted outside any trace is kept per (array, dtype, device, key) while the
array lives, so that an eager loop converts (and copies to an accelerator) each constant once.
Inside a trace the backends convert without the cache: what a trace makes belongs to it, and a
look-up in a table would make ``torch.compile`` guard on the array's identity.
"""

from __future__ import annotations

import weakref
from collections.abc import Callable
from typing import Any

__all__ = ["ConstantCache"]


class ConstantCache:
    """Converted numpy arrays, forgotten when the array is garbage-collected."""

    def __init__(self) -> None:
        self._converted: dict[tuple, Any] = {}

    def get(
        self,
        value: Any,
        key: tuple,
        convert: Callable[[Any], Any],
        keep: Callable[[Any], bool] | None = None,
    ) -> Any:
        """``convert(value)``, made once per ``(value, *key)`` while ``value`` lives (not kept
        where ``keep(result)`` is False: a tracer)."""
        full = (id(value), *key)
        found = self._converted.get(full)
        if found is None:
            found = convert(value)
            if found is value or getattr(found, "base", None) is not None:
                return found  # value itself or a view of it: nothing to keep, and no cycle
            if keep is not None and not keep(found):
                return found
            self._converted[full] = found
            weakref.finalize(value, self._converted.pop, full, None)
        return found

    def __len__(self) -> int:
        return len(self._converted)
