# SPDX-License-Identifier: LGPL-2.1-or-later
"""C2Blend workbench package: geometry (headless), objects, and GUI parts."""
# FreeCAD 0.20's Part library ends the interpreter with a segmentation fault when it is
# loaded before FreeCAD's own (`import Part` first, outside FreeCAD), and the geometry
# modules import Part: FreeCAD is loaded first, so that `import C2Blend` may come first
# in a script (test_workbench.py, test_c2blend_may_be_a_scripts_first_import)
import FreeCAD  # noqa: F401
