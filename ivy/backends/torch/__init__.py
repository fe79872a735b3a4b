"""ivy's torch backend: ``ivy.torch``. Dtypes are torch's own (``ivy.torch.float32 is
torch.float32``); the default float dtype is float32, as on every backend."""

from ivy.backends._assemble import assemble
from ivy.backends.torch._helpers import NATIVE_DTYPES

assemble(__name__, globals(), NATIVE_DTYPES)
