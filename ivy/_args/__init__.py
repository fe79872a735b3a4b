"""Argument rules that both the core and the backends apply (axes, convolution and pooling
arguments). They sit below both layers: they import nothing of ivy but its errors."""
