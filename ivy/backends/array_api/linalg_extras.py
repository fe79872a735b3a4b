"""Linear algebra beyond the Array API extension, written once: ``einsum`` where the library
has it (numpy, jax; not in the standard, so other libraries take it from the host bridge)."""

from __future__ import annotations

NATIVE = {"einsum": "einsum"}
