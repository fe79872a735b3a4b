"""The shared layer: functions written once against an Array API namespace ``xp``, bound per
backend (numpy, jax, and any library registered with :func:`ivy.register_framework`).

Each module here has the name of a core group and holds that group's functions, written with
``xp`` (the native namespace: ``numpy``, ``jax.numpy``, ``array_api_strict``...) and the backend's
helpers (``native_dtype``, ``native_device``, ``as_inexact``, see ``_unbound.py``). The assembly
(``ivy/backends/_assemble.py``) binds them: each function becomes the same code with ``xp`` and
the helpers replaced by the backend's, so a bound function costs what the same function written in
the backend would, and ``inspect.getsource`` shows this file. A module's ``NATIVE`` table names the
functions that are the native ones as they are (``add`` is ``xp.add``).

A backend package keeps, in a module of the group's name, only what differs for it: a module of
``ivy/backends/jax/`` defining ``matrix_rank`` wins over this layer's ``matrix_rank`` on jax.

What a library lacks beyond the standard (``einsum``, ``gather_nd``, convolutions, random
numbers...) a registered backend takes from the host bridge (``_host.py``): those functions run on
numpy and come back through DLPack. That keeps any Array API library complete from its first
registration; a faster native version is one function in the shared layer or the backend.
"""
