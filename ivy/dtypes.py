"""Dtype names shared by every backend. In the framework-agnostic ``ivy`` namespace a dtype is its
name; each backend namespace maps the same names to the framework's own dtype objects."""

__all__ = [
    "bool",
    "int8",
    "int16",
    "int32",
    "int64",
    "uint8",
    "uint16",
    "uint32",
    "uint64",
    "float16",
    "float32",
    "float64",
    "complex64",
    "complex128",
]

DTYPE_NAMES = tuple(__all__)

bool = "bool"  # noqa: A001 - the Array API name
int8 = "int8"
int16 = "int16"
int32 = "int32"
int64 = "int64"
uint8 = "uint8"
uint16 = "uint16"
uint32 = "uint32"
uint64 = "uint64"
float16 = "float16"
float32 = "float32"
float64 = "float64"
complex64 = "complex64"
complex128 = "complex128"

DEFAULT_FLOAT = "float32"
DEFAULT_INT = "int64"
DEFAULT_COMPLEX = "complex64"
