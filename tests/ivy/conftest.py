"""The core's tests also run on the opt-in backends (see ``tests/conftest.py``).

A test parametrized with a dtype that a backend's library does not have (float16 on
array_api_strict, which follows the standard) is skipped there, by the capability table.
"""

from __future__ import annotations

import pytest

from tests.conftest import BACKENDS, capable

IVY_OPT_IN_BACKENDS = ("array_api_strict",)

# Known gaps of the array_api_strict backend, by test id: where ivy allows more than the standard
# (and array_api_strict refuses it), or a rule the standard leaves open. Each is a strict xfail,
# so a fix shows as XPASS and must remove it here; the cross-backend agreement of issue 17 is
# where they close.
KNOWN_STRICT_GAPS: dict[str, str] = {
    "test_boolean_products_are_any_of_the_ands[array_api_strict]": "the standard's matmul, tensordot and vecdot refuse booleans",
    "test_can_cast_from_an_array[array_api_strict]": "dtype rules: float16 and mixed kinds (the standard leaves them open)",
    "test_can_cast_within_kinds_on_every_backend[array_api_strict]": "dtype rules: float16 and mixed kinds (the standard leaves them open)",
    "test_clip_by_global_norm[array_api_strict-clipped]": "a composition mixes a Python float with a 0-d array of another dtype",
    "test_clip_by_global_norm[array_api_strict-within]": "a composition mixes a Python float with a 0-d array of another dtype",
    "test_compiled_equals_eager[array_api_strict]": "compile_fn of a library without a compiler",
    "test_cross[array_api_strict]": "the standard's cross takes 3-vectors only; ivy's takes 2-vectors too",
    "test_diff[array_api_strict]": "the standard's diff refuses bool",
    "test_global_framework_answers_with_its_dtypes[array_api_strict]": "dtype rules on a dtype the library lacks (float16)",
    "test_integer_products_keep_their_dtype[array_api_strict-int32]": "the standard's matmul/vecdot refuse integers",
    "test_integer_products_keep_their_dtype[array_api_strict-int64]": "the standard's matmul/vecdot refuse integers",
    "test_isdtype_kinds[array_api_strict]": "isdtype of a dtype the library lacks (float16)",
    "test_matrix_power_of_integers_stays_integer[array_api_strict]": "the standard's matrix_power takes floating matrices only",
    "test_one_dimensional_transforms[array_api_strict-irfft]": "the standard's irfft takes complex input only",
    "test_result_type_follows_the_table_on_every_backend[array_api_strict]": "dtype rules: mixed kinds and Python scalars (the standard leaves them open)",
    "test_result_type_is_the_dtype_the_backend_computes[array_api_strict-float32-float64]": "dtype rules: mixed kinds and Python scalars (the standard leaves them open)",
    "test_result_type_is_the_dtype_the_backend_computes[array_api_strict-int32-float32]": "dtype rules: mixed kinds and Python scalars (the standard leaves them open)",
    "test_result_type_is_the_dtype_the_backend_computes[array_api_strict-int8-int16]": "dtype rules: mixed kinds and Python scalars (the standard leaves them open)",
    "test_result_type_is_the_dtype_the_backend_computes[array_api_strict-uint8-int8]": "dtype rules: mixed kinds and Python scalars (the standard leaves them open)",
    "test_result_type_with_python_scalars[array_api_strict]": "dtype rules: mixed kinds and Python scalars (the standard leaves them open)",
    "test_scan_of_no_steps_returns_empty_outputs[array_api_strict]": "the standard's zeros takes no positional dtype",
    "test_trace[array_api_strict--1-int8]": "the standard's trace refuses bool and promotes integers differently",
    "test_trace[array_api_strict--1-uint8]": "the standard's trace refuses bool and promotes integers differently",
    "test_trace[array_api_strict-0-bool]": "the standard's trace refuses bool and promotes integers differently",
    "test_trace[array_api_strict-0-float32]": "the standard's trace refuses bool and promotes integers differently",
    "test_trace[array_api_strict-0-int32]": "the standard's trace refuses bool and promotes integers differently",
    "test_trace[array_api_strict-1-float64]": "the standard's trace refuses bool and promotes integers differently",
    "test_trace[array_api_strict-1-int64]": "the standard's trace refuses bool and promotes integers differently",
    "test_vecdot[array_api_strict-complex64-((3, 2), (3, 2), 0)0]": "the standard's vecdot takes a negative axis only",
    "test_vecdot[array_api_strict-complex64-((3, 2), (3, 2), 0)1]": "the standard's vecdot takes a negative axis only",
}

# Known gaps of the frameworks' own gradients, by test id (strict xfails, as above).
KNOWN_TENSORFLOW_GAPS: dict[str, str] = {
    f"test_gradient_of_det_is_the_adjugate[tensorflow-{case}]": "tf's det gradient inverts the "
    "matrix and raises for a singular one (ivy's own, through tf.custom_gradient, made every eager "
    "det call 8 times slower and lost second derivatives)"
    for case in ("rank 1", "zero")
}
KNOWN_TENSORFLOW_GAPS["test_det_of_a_singular_matrix_keeps_its_gradient[tensorflow]"] = (
    KNOWN_TENSORFLOW_GAPS["test_gradient_of_det_is_the_adjugate[tensorflow-zero]"]
)

# backend -> its known gaps (a new backend adds its own table).
KNOWN_GAPS = {"array_api_strict": KNOWN_STRICT_GAPS, "tensorflow": KNOWN_TENSORFLOW_GAPS}


_64_BIT = ("float64", "complex128", "int64", "uint64")
# Tests of the 64-bit dtypes themselves (they make or name int64, uint64, float64 or complex128
# arrays, or expect int64 as the default integer), which jax cannot hold while its 64-bit types
# are off: there ivy refuses them by name (UnsupportedError, UnavailableDtypeError), as
# tests/ivy/core/test_data_type.py checks.
_OF_64_BIT_DTYPES = frozenset(
    "test_asarray_from_python_objects_uses_default_dtypes test_meshgrid_with_f_and_no_arrays "
    "test_python_ints_beyond_int64_with_dtype_uint64 test_astype_keeps_the_shape_of_0d_and_empty_arrays "
    "test_astype_with_copy_false test_result_type_follows_the_table_on_every_backend "
    "test_can_cast_within_kinds_on_every_backend test_can_cast_from_an_array "
    "test_can_cast_never_crosses_kinds test_can_cast_never_narrows_nor_drops_the_imaginary_part "
    "test_isdtype_kinds test_isdtype_tuples_and_dtypes".split()
)


def _is_64_bit(value) -> bool:
    """A test parameter naming a 64-bit dtype (alone or in a tuple), which jax cannot make while
    its 64-bit types are off (``--jax-x64 off``)."""
    if isinstance(value, str):
        return value in _64_BIT
    if isinstance(value, (tuple, list)):
        return any(_is_64_bit(v) for v in value)
    if isinstance(value, dict):
        return any(_is_64_bit(v) for v in value.values())
    return False


def pytest_collection_modifyitems(config, items):
    for item in items:
        params = getattr(getattr(item, "callspec", None), "params", {})
        backend = params.get("backend")
        if backend not in BACKENDS:
            continue
        if not BACKENDS[backend]["float16"] and any(
            isinstance(v, str) and v == "float16" for v in params.values()
        ):
            item.add_marker(pytest.mark.skip(reason=f"{backend} has no float16"))
        if not capable(backend, "float64") and (
            any(_is_64_bit(v) for v in params.values()) or item.originalname in _OF_64_BIT_DTYPES
        ):
            item.add_marker(pytest.mark.skip(reason=f"{backend} runs without 64-bit types"))
        reason = KNOWN_GAPS.get(backend, {}).get(item.name)
        if reason:
            item.add_marker(pytest.mark.xfail(reason=reason, strict=True))
