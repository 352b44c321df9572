# SPDX-License-Identifier: LGPL-2.1-or-later
# C2Blend workbench, GUI part. Commands are imported lazily, when the workbench is
# activated, so FreeCAD's start-up stays fast. FreeCAD executes this file with separate
# global and local namespaces, so names are imported where they are used.


class C2BlendWorkbench(Workbench):  # noqa: F821 (FreeCAD injects Workbench)
    """Curvature-continuous (G2) fillets and blends, with continuity reports."""

    import os as _os
    import c2bwb as _pkg
    MenuText = "C2Blend"
    ToolTip = "Curvature-continuous fillets and blends (sixth-order PDE) with continuity checks"
    Icon = _os.path.join(_os.path.dirname(_pkg.__file__), "..", "resources", "icons",
                         "C2Blend_Workbench.svg")

    def Initialize(self):
        from c2bwb.commands import commands
        self.appendToolbar("C2Blend", commands.NAMES)
        self.appendMenu("C2Blend", commands.NAMES)

    def GetClassName(self):
        return "Gui::PythonWorkbench"


Gui.addWorkbench(C2BlendWorkbench())  # noqa: F821 (FreeCAD injects Gui)
