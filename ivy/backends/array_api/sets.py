"""Sets, written once against ``xp``: ``isin`` by broadcast comparison (array_api_strict 2.6's
own ``isin`` ignores ``invert`` and refuses floats)."""

from __future__ import annotations

from ivy.backends.array_api._unbound import xp


def isin(x1, x2, /, *, invert=False):
    found = xp.any(xp.equal(xp.expand_dims(x1, axis=-1), xp.reshape(x2, (-1,))), axis=-1)
    return xp.logical_not(found) if invert else found
