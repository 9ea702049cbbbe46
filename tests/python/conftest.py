"""The Python module's tests (ctest -L python): the module from the build tree (PYTHONPATH), the
starter files from SWEEP_SWP_DIR, and pytest's own pytester to run the snapshot fixture's users."""
import os
import shutil
from pathlib import Path

import pytest

pytest_plugins = ["pytester"]

SWP = Path(os.environ.get("SWEEP_SWP_DIR", Path(__file__).resolve().parents[2] / "swp"))


@pytest.fixture
def wineglass(tmp_path):
    """A copy of the starter file swp/wineglass.swp in a fresh folder."""
    path = tmp_path / "wineglass.swp"
    shutil.copy(SWP / "wineglass.swp", path)
    return path
