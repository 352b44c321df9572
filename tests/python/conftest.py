"""pytest configuration of the c2blend module tests.

- The `freecad` marker selects the tests that need FreeCAD (ctest python_module_freecad).
- The `freecad` fixture imports FreeCAD and Part from Debian's freecad-python3 with HOME
  set to a temporary directory (FreeCAD writes its user configuration there). It skips
  when FreeCAD is missing, unless C2B_REQUIRE_FREECAD=1 (as ctest sets), then it fails.
"""
import os
import sys
import tempfile

import pytest

FREECAD_LIB = "/usr/lib/freecad-python3/lib"


def pytest_configure(config):
    config.addinivalue_line("markers", "freecad: needs FreeCAD (Part) from freecad-python3")


@pytest.fixture(scope="session")
def freecad():
    """(FreeCAD, Part) modules."""
    os.environ["HOME"] = tempfile.mkdtemp(prefix="c2b_pytest_home_")
    if FREECAD_LIB not in sys.path:
        sys.path.append(FREECAD_LIB)
    try:
        import FreeCAD  # noqa: F401
        import Part
    except ImportError as e:
        if os.environ.get("C2B_REQUIRE_FREECAD") == "1":
            pytest.fail("FreeCAD is required but does not import: %s" % e)
        pytest.skip("FreeCAD does not import: %s" % e)
    return FreeCAD, Part
