"""pytest configuration of the workbench tests (headless FreeCAD, real OCCT).

Paths: FreeCAD's library (freecad-python3), the workbench (plugin/C2Blend) and the
built c2blend module (C2B_MODULE_DIR, set by ctest). HOME is a temporary folder so no
user configuration is left behind.
"""
import os
import sys
import tempfile

os.environ["HOME"] = tempfile.mkdtemp(prefix="c2b_fc_home_")
HERE = os.path.dirname(os.path.abspath(__file__))
for p in ("/usr/lib/freecad-python3/lib", os.path.join(HERE, "..", "..", "plugin", "C2Blend"),
          os.environ.get("C2B_MODULE_DIR", "")):
    if p and p not in sys.path:
        sys.path.append(p)

import FreeCAD  # noqa: E402,F401  (FreeCAD must be imported before Part)
