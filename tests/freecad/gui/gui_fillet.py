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
    # bad selections through the commands: each says why (the modal warning is
    # recorded here instead of waiting for a click) and nothing changes in the document
    warnings = []
    QtGui.QMessageBox.warning = staticmethod(lambda parent, title, text: warnings.append(text))
    before = shapes.document_state(doc)
    for bad in (["Face1"], ["Vertex1"], []):
        FreeCADGui.Selection.clearSelection()
        for sub in bad:
            FreeCADGui.Selection.addSelection(part, sub)
        if not bad:
            FreeCADGui.Selection.addSelection(part)
        for cmd in ("C2Blend_Fillet", "C2Blend_BlendFaces", "C2Blend_Check"):
            FreeCADGui.runCommand(cmd)
    FreeCADGui.Control.closeDialog()
    # Blend faces with an edge that is not the picked face's: refused before its panel
    sh = part.Shape
    stray = next(i for i, e in enumerate(sh.Edges)
                 if not any(e.isSame(x) for x in sh.Faces[0].Edges))
    FreeCADGui.Selection.clearSelection()
    for sub in ("Face1", "Edge%d" % (stray + 1), "Face2", "Edge%d" % (
            next(i for i, e in enumerate(sh.Edges) if e.isSame(sh.Faces[1].Edges[0])) + 1)):
        FreeCADGui.Selection.addSelection(part, sub)
    FreeCADGui.runCommand("C2Blend_BlendFaces")
    result["blend_panel_opened"] = commands.BlendFaces.panel is not None
    result["stray_edge"] = "ShaftPlate.Face1+Edge%d" % (stray + 1)
    result["warnings"] = warnings
    result["bad_selections_unchanged"] = before == shapes.document_state(doc)
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(part, edge)
    FreeCADGui.runCommand("C2Blend_Fillet")
    panel = commands.Fillet.panel
    panel.radius.setValue(2.0)
    panel.preview()
    result["preview_status"] = panel.status.toPlainText()
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
    # Check continuity on an edge selection: one trimline of the fillet (a C2Check)
    trim = json.loads(fillet.Report)["trimlines"][0]["edge"]
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(fillet, trim)
    FreeCADGui.runCommand("C2Blend_Check")
    check = doc.getObject("C2Check")
    result["edge_check"] = [trim, check.Verdict if check else None]
    # C2 Blend faces through the command (face + edge picked on each cylinder), driven
    # by a Clock; then Animate writes 10 PNG frames (the folder dialog is answered here)
    from c2bwb.objects import make
    doc2 = FreeCAD.newDocument("Cylinders")
    clock = make.make_clock(doc2)
    a = doc2.addObject("Part::Cylinder", "A")
    a.Height = 2.0
    a.setExpression("Radius", "1 + 0.3 * Clock.Time")
    b = doc2.addObject("Part::Cylinder", "B")
    b.Radius, b.Height = 0.8, 2.0
    b.Placement.Base = FreeCAD.Vector(0, 0, 3)
    doc2.recompute()
    FreeCADGui.Selection.clearSelection()
    for obj, z in ((a, 2.0), (b, 3.0)):
        FreeCADGui.Selection.addSelection(obj, "Face1")
        FreeCADGui.Selection.addSelection(obj, "Edge%d" % (shapes.circle_edge(obj.Shape, z) + 1))
    FreeCADGui.runCommand("C2Blend_BlendFaces")
    # its panel: the preview, then one solid chosen before OK
    bpanel = commands.BlendFaces.panel
    bpanel.timer.stop()
    bpanel.preview()
    result["blend_preview"] = bpanel.status.toPlainText()
    result["blend_preview_drawn"] = bpanel.preview_node is not None
    bpanel.solid.setChecked(True)
    bpanel.timer.stop()
    bpanel.preview()
    result["blend_solid_preview"] = bpanel.status.toPlainText()
    FreeCADGui.ActiveDocument.ActiveView.viewIsometric()
    FreeCADGui.SendMsgToActiveView("ViewFit")
    FreeCADGui.updateGui()
    FreeCADGui.getMainWindow().grab().save(os.path.join(OUT, "gui_blend_panel.png"))
    FreeCADGui.ActiveDocument.ActiveView.saveImage(os.path.join(OUT, "gui_blend_preview.png"),
                                                   800, 600, "White")
    result["blend_accepted"] = bpanel.accept()
    blend = doc2.getObject("C2Blend")
    result["blend_verdict"] = blend.Verdict if blend else None
    result["blend_solid"] = [blend.MakeSolid, blend.Shape.ShapeType, blend.Shape.isValid(),
                             len(blend.Shape.Faces)] if blend else None
    # editing it (double click): C1 and the face only, through the same panel
    FreeCADGui.ActiveDocument.setEdit(blend.Name)
    bedit = blend.ViewObject.Proxy.panel
    bedit.timer.stop()
    result["blend_edit_values"] = [bedit.solid.isChecked(), bedit.cont.currentText()]
    bedit.cont.setCurrentIndex(1)
    bedit.solid.setChecked(False)
    bedit.timer.stop()
    result["blend_edit_accepted"] = bedit.accept()
    result["blend_edited"] = [blend.MakeSolid, blend.Continuity, blend.Verdict,
                              blend.Shape.ShapeType]
    # back to C2 and one solid for the animation
    blend.Continuity, blend.MakeSolid = "C2", True
    doc2.recompute()
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(clock)
    FreeCADGui.Selection.addSelection(blend)
    frames = os.path.join(OUT, "frames")
    os.makedirs(frames, exist_ok=True)
    QtGui.QFileDialog.getExistingDirectory = staticmethod(lambda *args, **kw: frames)
    FreeCADGui.ActiveDocument.ActiveView.viewIsometric()
    FreeCADGui.SendMsgToActiveView("ViewFit")
    FreeCADGui.runCommand("C2Blend_Animate")
    pngs = sorted(p for p in os.listdir(frames) if p.endswith(".png"))
    result["png_frames"] = len(pngs)
    result["png_sizes_ok"] = all(os.path.getsize(os.path.join(frames, p)) > 1000 for p in pngs)
    # editing the shaft's fillet: the panel keeps values its sliders cannot show exactly
    from c2bwb.taskpanels.fillet_panel import FilletPanel
    fillet.Tension, fillet.Gamma = 1.37, 2.5
    doc.recompute()
    edit = FilletPanel(obj=fillet)
    edit.timer.stop()
    result["edit_parameters"] = edit.parameters()
    # the slider moves the value in its box; a value typed in the box is kept exactly
    # (the tension slider cannot show 1.0) and moves the slider; the box takes negative
    # shape parameters, which the log-scale slider cannot
    edit.sliders["Tension"].setValue(500)
    result["slid_tension"] = edit.spins["Tension"].value()
    edit.spins["Tension"].setValue(1.0)
    edit.spins["Rho"].setValue(-0.5)
    result["typed"] = [edit.parameters()[3], edit.sliders["Tension"].value(),
                       edit.parameters()[2][3], edit.sliders["Rho"].value()]
    # C1 through the panel: its (b, c, d) are Gamma, Eta, Lambda
    edit.spins["Rho"].setValue(1.0)
    edit.cont.setCurrentIndex(1)
    result["c1_parameters"] = edit.fillet_parameters()
    edit.timer.stop()
    result["c1_accepted"] = edit.accept()
    result["c1_object"] = [fillet.Continuity, fillet.Verdict, "Invalid" in fillet.State]
    # a failed edit (a radius too large for the plate) says why and keeps the object
    volume = fillet.Shape.Volume
    QtGui.QMessageBox.critical = staticmethod(lambda parent, title, text: warnings.append(text))
    edit = FilletPanel(obj=fillet)
    edit.timer.stop()
    edit.radius.setValue(50.0)
    result["too_large_accepted"] = edit.accept()
    FreeCADGui.Control.closeDialog()
    result["too_large_message"] = warnings[-1]
    result["too_large_kept"] = [fillet.Radius.Value, fillet.Shape.Volume == volume,
                                "Invalid" in fillet.State]
    # all 12 edges of a box through the command and its panel, left at its defaults but
    # for the size, given as a setback:
    # 12 blends and 8 plate-filled corners (this froze FreeCAD in OCCT's BOP check at
    # tension 1.0008, where the panel's tension slider rounded 1.0)
    doc3 = FreeCAD.newDocument("BoxCorners")
    box = doc3.addObject("Part::Box", "Box")
    doc3.recompute()
    FreeCADGui.Selection.clearSelection()
    for i in range(12):
        FreeCADGui.Selection.addSelection(box, "Edge%d" % (i + 1))
    FreeCADGui.runCommand("C2Blend_Fillet")
    panel = commands.Fillet.panel
    panel.size.setCurrentIndex(1)  # a setback of 2 on edges at 90 degrees: radius 2
    panel.radius.setValue(2.0)
    result["box_parameters"] = panel.parameters()
    assert panel.accept() is True
    rounded = doc3.getObject("C2Fillet")
    result["box_radius"] = rounded.Radius.Value
    report = json.loads(rounded.Report)
    result["box_blends"] = len(report["blends"])
    result["box_corners"] = len(report["corner_patches"])
    result["box_valid"] = rounded.Shape.isValid()
    result["box_solid_check"] = report["solid_check"]
    FreeCADGui.ActiveDocument.ActiveView.viewIsometric()
    FreeCADGui.SendMsgToActiveView("ViewFit")
    FreeCADGui.updateGui()
    FreeCADGui.ActiveDocument.ActiveView.saveImage(os.path.join(OUT, "gui_box_corners.png"),
                                                   1024, 768, "White")
    result["ok"] = True
except Exception:
    result["error"] = traceback.format_exc()
with open(os.path.join(OUT, "gui_result.json"), "w") as f:
    json.dump(result, f, indent=1)
os._exit(0)
