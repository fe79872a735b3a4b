"""What a shared module uses before the assembly binds it to a backend: ``xp`` and the helpers.

Static tools and editors read these names; the assembly replaces every one of them in the bound
copies (``ivy.backends._assemble.bind_shared``), so none of these bodies ever runs in a backend.
"""

from __future__ import annotations

from typing import Any

xp: Any = None  # the backend's native Array API namespace


def _unbound(name: str):
    def fn(*args: Any, **kwargs: Any) -> Any:
        raise RuntimeError(f"{name} of the shared layer runs only bound to a backend")

    fn.__name__ = name
    return fn


native_dtype = _unbound("native_dtype")  # dtype name or object -> native dtype; None stays None
native_device = _unbound("native_device")  # 'cpu', 'gpu:0' -> native device; None stays None
as_inexact = _unbound("as_inexact")  # integer and bool arrays -> float32; others as they are
backend_name: str = "<unbound>"  # the name the backend is registered under
backend_ns: Any = (
    None  # the ivy namespace being assembled (``ivy.numpy``...), for its own functions
)
dtype_name = _unbound("dtype_name")  # native dtype -> ivy's name ('float32')
device_name = _unbound("device_name")  # native device -> ivy's name ('cpu', 'gpu:0')
native_dtypes: dict = {}  # ivy dtype name -> the native dtype
array_types: tuple = ()  # the types of the native arrays
concrete = _unbound("concrete")  # array -> whether its values are known (not traced by jax.jit)
