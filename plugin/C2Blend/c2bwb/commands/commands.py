# SPDX-License-Identifier: LGPL-2.1-or-later
"""Workbench commands (GUI only). Selection problems are reported in a message box
and the Report view, naming the object and sub-element; the document is not touched."""
import os

import FreeCAD
import FreeCADGui
from PySide import QtGui

from ..errors import C2BlendError
from ..objects import animate, features, make
from ..viewproviders.viewproviders import ICONS, show_curvature_map

NAMES = ["C2Blend_Fillet", "C2Blend_BlendFaces", "C2Blend_Check", "C2Blend_Animate"]


def _fail(title, ex):
    FreeCAD.Console.PrintError("%s: %s\n" % (title, ex))
    if FreeCADGui.getMainWindow().isVisible():
        QtGui.QMessageBox.warning(FreeCADGui.getMainWindow(), title, str(ex))


class _Command:
    """Resources from ICON, MENU and TIP; active when a document is open."""

    ICON = MENU = TIP = ""

    def GetResources(self):
        return {"Pixmap": os.path.join(ICONS, self.ICON), "MenuText": self.MENU,
                "ToolTip": self.TIP}

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None


def _edges_of_selection():
    """(object, [edge names]) from the selection; faces etc. are refused by name."""
    sel = FreeCADGui.Selection.getSelectionEx()
    if len(sel) != 1:
        raise C2BlendError("select edges of exactly one object, a solid or a compound of solids "
                           "(%d objects selected)" % len(sel))
    s = sel[0]
    bad = [n for n in s.SubElementNames if not n.startswith("Edge")]
    if bad:
        raise C2BlendError("%s is not an edge; select only edges" % bad[0],
                           "%s.%s" % (s.Object.Label, bad[0]))
    if not s.SubElementNames:
        raise C2BlendError("no edges selected", s.Object.Label)
    return s.Object, list(s.SubElementNames)


class Fillet(_Command):
    """C2 Fillet: G2 fillet of the selected edges, with a task panel."""

    ICON, MENU = "C2Blend_Fillet.svg", "C2 Fillet"
    TIP = "Curvature-continuous (G2) fillet of the selected edges"
    panel = None  # the open task panel (macros and tests drive it)

    def Activated(self):
        try:
            base, edges = _edges_of_selection()
        except C2BlendError as ex:
            return _fail("C2 Fillet", ex)
        from ..taskpanels.fillet_panel import FilletPanel
        Fillet.panel = FilletPanel(base=base, edges=edges)
        FreeCADGui.Control.showDialog(Fillet.panel)


class BlendFaces(_Command):
    """C2 Blend faces: blend face between (face, edge) picked on one object and on
    another, with a task panel (parameters, one solid or not)."""

    ICON, MENU = "C2Blend_BlendFaces.svg", "C2 Blend faces"
    TIP = ("G2 blend between an edge of a face and an edge of another face: pick face and "
           "edge on the first object, then on the second")
    panel = None  # the open task panel (macros and tests drive it)

    def Activated(self):
        sides = []
        for s in FreeCADGui.Selection.getSelectionEx():
            names = list(s.SubElementNames)
            if not names:
                sides.append((s.Object, []))
            while names:
                pair, names = names[:2], names[2:]
                sides.append((s.Object, pair))
        try:
            if len(sides) != 2:
                picked = ", ".join("%s.%s" % (o.Label, "+".join(p) or "(whole object)")
                                   for o, p in sides) or "nothing"
                raise C2BlendError("pick a face and one of its edges on each of two sides "
                                   "(selected: %s)" % picked)
            features.blend_side(sides[0], "Edge1")
            features.blend_side(sides[1], "Edge2")
        except C2BlendError as ex:
            return _fail("C2 Blend faces", ex)
        from ..taskpanels.blendfaces_panel import BlendFacesPanel
        BlendFaces.panel = BlendFacesPanel(*sides)
        FreeCADGui.Control.showDialog(BlendFaces.panel)


class Check(_Command):
    """C2 Check: continuity report of a C2Blend result or of selected edges."""

    ICON, MENU = "C2Blend_Check.svg", "Check continuity"
    TIP = ("G0/G1/G2 report across the selected edges (or of a C2Blend result), a curvature "
           "colour map, and the CGAL cross-check when the tool is installed")

    def Activated(self):
        sel = FreeCADGui.Selection.getSelectionEx()
        try:
            if len(sel) != 1:
                raise C2BlendError("select one C2Blend object or edges of one object")
            s = sel[0]
            if s.SubElementNames:
                bad = [n for n in s.SubElementNames if not n.startswith("Edge")]
                if bad:
                    raise C2BlendError("%s is not an edge" % bad[0],
                                       "%s.%s" % (s.Object.Label, bad[0]))
                check = make.make_check(s.Object, list(s.SubElementNames))
                _cgal_cross_check(check)
            elif hasattr(s.Object, "Report") and s.Object.Report:
                FreeCAD.Console.PrintMessage("%s: %s\n" % (s.Object.Label, s.Object.Verdict))
                _cgal_cross_check(s.Object)
            else:
                raise C2BlendError("select edges, or a C2Fillet/C2Blend object",
                                   s.Object.Label)
            show_curvature_map(s.Object)
        except C2BlendError as ex:
            _fail("Check continuity", ex)


def _cgal_cross_check(obj):
    """CGAL jet-fitting estimate against the analytic curvature, printed to the Report
    view (skipped, with a note, when the tool is not installed): of the blend faces of a
    C2Fillet or C2Blend result (the faces across their trimlines compared as a second
    region), or of the faces on both sides of a C2Check's edges."""
    import json
    from ..geometry import cgalcheck
    rep = json.loads(obj.Report)
    if "trimlines" in rep:
        shape = obj.Shape
        names = sorted({r["blend_face"] for r in rep["trimlines"] if "blend_face" in r})
        others = sorted({r["faces"][1] for r in rep["trimlines"]}) if names else []
    else:
        shape = obj.Target[0].Shape
        names, others = sorted({f for r in rep["edges"] for f in r["faces"]}), []
    if not names:
        return
    summary = cgalcheck.cross_check(shape, [shape.getElement(n) for n in names],
                                    [shape.getElement(n) for n in others])
    if summary is None:
        FreeCAD.Console.PrintMessage("  CGAL cross-check skipped: %s not found\n" % cgalcheck.TOOL)
    elif "error" in summary:
        FreeCAD.Console.PrintWarning("  CGAL cross-check failed: %s\n" % summary["error"])
    else:
        for name, reg in summary["regions"].items():
            sm = reg["smooth"]
            if sm["count"]:
                what = ("%s faces" % name) if "trimlines" in rep else ", ".join(names)
                FreeCAD.Console.PrintMessage(
                    "  CGAL jet fit vs analytic, %s (%d vertices): mean |dk1| %.3g, "
                    "mean |dk2| %.3g, max %.3g\n"
                    % (what, sm["count"], sm["k1"]["mean_abs"], sm["k2"]["mean_abs"],
                       max(sm["k1"]["max_abs"], sm["k2"]["max_abs"])))


class Animate(_Command):
    """Animate: step the Time of a C2Clock and check the selected blends per frame."""

    ICON, MENU = "C2Blend_Animate.svg", "Animate"
    TIP = ("Select a Clock (or a spreadsheet with a cell named Time or time) and C2Blend "
           "objects; steps the time 0..1 in 10 frames, checks continuity and saves PNG "
           "frames")

    def Activated(self):
        objs = [s.Object for s in FreeCADGui.Selection.getSelectionEx()]
        clocks = [o for o in objs if animate.clock_property(o)]
        targets = [o for o in objs if "Report" in o.PropertiesList and o not in clocks]
        try:
            if len(clocks) != 1 or not targets:
                raise C2BlendError("select one clock (a Clock, or a spreadsheet with a cell "
                                   "named %s) and the C2Blend objects to check (selected: %s)"
                                   % (", ".join(animate.TIME_ALIASES[:-1]) + " or "
                                      + animate.TIME_ALIASES[-1],
                                      ", ".join(o.Label for o in objs) or "nothing"))
            out = QtGui.QFileDialog.getExistingDirectory(None, "Folder for PNG frames")
            if not out:
                return
            FreeCADGui.Selection.clearSelection()  # no selection highlight in the frames
            view = FreeCADGui.ActiveDocument.ActiveView
            frames = animate.animate(FreeCAD.ActiveDocument, clocks[0],
                                     [k / 9.0 for k in range(10)], targets, out, "brep",
                                     animate.clock_property(clocks[0]),
                                     snapshot=lambda p: animate.save_view_png(view, p))
            for f in frames:
                FreeCAD.Console.PrintMessage("t = %.3f: %s\n" % (f["t"], f["verdicts"]))
        except C2BlendError as ex:
            _fail("Animate", ex)


for _name, _cmd in zip(NAMES, (Fillet(), BlendFaces(), Check(), Animate())):
    FreeCADGui.addCommand(_name, _cmd)
