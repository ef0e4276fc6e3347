"""What the Python tests share: the built dem (DEM, set by ctest), the source tree, a short scene."""
import os
import pathlib

import pytest

SOURCE = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def dem():
    path = os.environ.get("DEM", str(SOURCE / "build" / "bin" / "dem"))
    assert os.access(path, os.X_OK), f"no dem at {path} (set DEM)"
    return path


@pytest.fixture(scope="session")
def source():
    return SOURCE
