# SPDX-License-Identifier: LGPL-2.1-or-later
# C2Blend workbench, GUI part. Commands are imported lazily, when the workbench is
# activated, so FreeCAD's start-up stays fast.
import os

import c2bwb


class C2BlendWorkbench(Workbench):  # noqa: F821 (FreeCAD injects Workbench)
    """Curvature-continuous (G2) fillets and blends, with continuity reports."""

    MenuText = "C2Blend"
    ToolTip = "Curvature-continuous fillets and blends (sixth-order PDE) with continuity checks"
    Icon = os.path.join(os.path.dirname(c2bwb.__file__), "..", "resources", "icons",
                        "C2Blend_Workbench.svg")

    def Initialize(self):
        from c2bwb.commands import commands
        self.appendToolbar("C2Blend", commands.NAMES)
        self.appendMenu("C2Blend", commands.NAMES)

    def GetClassName(self):
        return "Gui::PythonWorkbench"


Gui.addWorkbench(C2BlendWorkbench())  # noqa: F821 (FreeCAD injects Gui)
