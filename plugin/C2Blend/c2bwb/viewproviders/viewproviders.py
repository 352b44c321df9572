# SPDX-License-Identifier: LGPL-2.1-or-later
"""View providers and the curvature colour map (GUI only)."""
import os

import FreeCAD
import FreeCADGui
from pivy import coin

from ..geometry.surface import Frame

ICONS = os.path.join(os.path.dirname(__file__), "..", "..", "resources", "icons")


class ViewProviderC2:
    """Icon and edit mode of C2Blend objects; the shape is drawn by Part."""

    def __init__(self, vobj):
        vobj.Proxy = self

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        kind = type(self.Object.Proxy).__name__ if hasattr(self, "Object") else ""
        name = {"C2Fillet": "Fillet", "C2BlendFaces": "BlendFaces",
                "C2Check": "Check", "C2Clock": "Animate"}.get(kind, "Workbench")
        return os.path.join(ICONS, "C2Blend_%s.svg" % name)

    def setEdit(self, vobj, mode=0):
        if type(vobj.Object.Proxy).__name__ != "C2Fillet" or mode != 0:
            return False
        from ..taskpanels.fillet_panel import FilletPanel
        FreeCADGui.Control.showDialog(FilletPanel(obj=vobj.Object))
        return True

    def unsetEdit(self, vobj, mode=0):
        FreeCADGui.Control.closeDialog()
        return True

    def dumps(self):
        return None

    def loads(self, state):
        return None


def colour(x):
    """Blue (0) - green (0.5) - red (1) ramp."""
    x = min(max(x, 0.0), 1.0)
    return (max(0.0, 2 * x - 1), 1.0 - abs(2 * x - 1), max(0.0, 1 - 2 * x))


def curvature_map(shape, quantity="mean", deflection=None):
    """Coin node drawing shape's faces coloured by curvature at each tessellation
    vertex (mean H, gaussian K, k1 or k2 from the analytic surfaces). Returns
    (node, (lo, hi)) with the colour range used (symmetric percentiles)."""
    deflection = deflection or shape.BoundBox.DiagonalLength * 1e-3
    coords, idx, vals = [], [], []
    pick = {"k1": 0, "k2": 1, "gauss": 2, "mean": 3}[quantity]
    for face in shape.Faces:
        pts, tris = face.tessellate(deflection)
        base = len(coords)
        for p in pts:
            u, v = face.Surface.parameter(p)
            try:
                vals.append(Frame(face, u, v).principal()[pick])
            except ValueError:
                vals.append(0.0)
            coords.append((p.x, p.y, p.z))
        for t in tris:
            idx.extend([base + t[0], base + t[1], base + t[2], -1])
    s = sorted(abs(v) for v in vals) or [1.0]
    hi = s[min(len(s) - 1, int(0.98 * len(s)))] or 1.0
    node = coin.SoSeparator()
    hints = coin.SoShapeHints()
    hints.vertexOrdering = coin.SoShapeHints.COUNTERCLOCKWISE
    node.addChild(hints)
    offset = coin.SoPolygonOffset()
    node.addChild(offset)
    mat = coin.SoMaterial()
    mat.diffuseColor.setValues(0, len(vals), [colour(0.5 + 0.5 * v / hi) for v in vals])
    node.addChild(mat)
    bind = coin.SoMaterialBinding()
    bind.value = coin.SoMaterialBinding.PER_VERTEX_INDEXED
    node.addChild(bind)
    c = coin.SoCoordinate3()
    c.point.setValues(0, len(coords), coords)
    node.addChild(c)
    fs = coin.SoIndexedFaceSet()
    fs.coordIndex.setValues(0, len(idx), idx)
    fs.materialIndex.setValues(0, len(idx), idx)
    node.addChild(fs)
    return node, (-hi, hi)


def show_curvature_map(obj, quantity="mean"):
    """Overlay obj's curvature map in the 3D view (replacing a previous one); returns
    the colour range. The map is a view decoration, not part of the document."""
    hide_curvature_map(obj)
    node, rng = curvature_map(obj.Shape, quantity)
    node.setName("C2BlendCurvatureMap")
    obj.ViewObject.RootNode.addChild(node)
    FreeCAD.Console.PrintMessage("C2Blend: %s curvature map of %s, blue %.3g .. red %.3g\n"
                                 % (quantity, obj.Label, rng[0], rng[1]))
    return rng


def hide_curvature_map(obj):
    """Remove the curvature map overlay of obj, if any."""
    root = obj.ViewObject.RootNode
    for i in reversed(range(root.getNumChildren())):
        if root.getChild(i).getName() == "C2BlendCurvatureMap":
            root.removeChild(i)
