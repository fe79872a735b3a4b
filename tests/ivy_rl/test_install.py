"""``import ivy_rl`` without Gymnasium says which extra to install (as ivy_gym's MuJoCo tasks do),
instead of a bare ModuleNotFoundError from deep inside the package."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

# None in sys.modules makes ``import gymnasium`` fail as if it were not installed
_WITHOUT_GYMNASIUM = """
import sys
sys.modules["gymnasium"] = None
try:
    import ivy_rl
except ModuleNotFoundError as error:
    print(error.name)
    print(error)
else:
    print("imported")
"""


def test_import_without_gymnasium_names_the_extra():
    out = subprocess.run(
        [sys.executable, "-c", _WITHOUT_GYMNASIUM],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=300,
        check=True,
    ).stdout.splitlines()
    assert out[0] == "gymnasium"
    assert "pip install 'ivy[rl]'" in out[1]
