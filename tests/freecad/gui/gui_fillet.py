# FreeCAD GUI macro (run by run_gui.sh under Xvfb): loads the C2Blend workbench, runs
# C2 Fillet on the shaft-on-plate junction through the command and its task panel, runs
# Check continuity (curvature colour map), saves a screenshot and writes a JSON result.
import json
import os
import sys
import traceback

import FreeCAD
import FreeCADGui
from PySide import QtGui

OUT = os.environ["C2B_GUI_OUT"]
result = {"ok": False}
try:
    FreeCADGui.activateWorkbench("C2BlendWorkbench")
    sys.path.append(os.path.join(os.path.dirname(os.environ["C2B_GUI_TESTS"])))
    sys.path.append(os.environ["C2B_GUI_TESTS"])
    import shapes
    from c2bwb.commands import commands

    doc = FreeCAD.newDocument("ShaftOnPlate")
    solid, edge = shapes.shaft_on_plate()
    part = doc.addObject("Part::Feature", "ShaftPlate")
    part.Shape = solid
    doc.recompute()
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(part, edge)
    FreeCADGui.runCommand("C2Blend_Fillet")
    panel = commands.Fillet.panel
    panel.radius.setValue(2.0)
    panel.preview()
    result["preview_status"] = panel.status.text()
    assert panel.accept() is True
    fillet = doc.getObject("C2Fillet")
    result["verdict"] = fillet.Verdict
    result["valid"] = fillet.Shape.isValid()
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(fillet)
    FreeCADGui.runCommand("C2Blend_Check")
    view = FreeCADGui.ActiveDocument.ActiveView
    view.viewIsometric()
    view.fitAll()
    FreeCADGui.updateGui()
    png = os.path.join(OUT, "gui_fillet.png")
    view.saveImage(png, 1024, 768, "White")
    img = QtGui.QImage(png)
    colours, other = set(), 0
    for y in range(0, img.height(), 4):
        for x in range(0, img.width(), 4):
            c = img.pixel(x, y) & 0xFFFFFF
            colours.add(c)
            other += c != 0xFFFFFF
    result["non_white_fraction"] = other / float((img.height() // 4 + 1) * (img.width() // 4 + 1))
    result["colours"] = len(colours)
    from c2bwb.viewproviders.viewproviders import curvature_map_shown
    result["map_nodes"] = int(curvature_map_shown(fillet))
    from c2bwb.geometry import cgalcheck
    result["cgal_tool"] = cgalcheck.find_tool()
    result["ok"] = True
except Exception:
    result["error"] = traceback.format_exc()
with open(os.path.join(OUT, "gui_result.json"), "w") as f:
    json.dump(result, f, indent=1)
os._exit(0)
