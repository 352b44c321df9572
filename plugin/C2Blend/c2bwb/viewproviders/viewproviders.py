# SPDX-License-Identifier: LGPL-2.1-or-later
"""View providers and the curvature colour map (GUI only)."""
import os

import FreeCAD
import FreeCADGui
from pivy import coin

from ..geometry.surface import frame_or_none, tessellation

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
        kind = type(vobj.Object.Proxy).__name__
        if kind not in ("C2Fillet", "C2BlendFaces") or mode != 0:
            return False
        if kind == "C2Fillet":
            from ..taskpanels.fillet_panel import FilletPanel as Panel
        else:
            from ..taskpanels.blendfaces_panel import BlendFacesPanel as Panel
        self.panel = Panel(obj=vobj.Object)  # macros and tests drive it
        FreeCADGui.Control.showDialog(self.panel)
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


def curvature_map(shape, quantity="kmax", deflection=None):
    """Coin node drawing shape's faces coloured by curvature at each tessellation
    vertex, from the analytic surfaces: 'kmax' (largest |principal curvature|, the
    default: it is continuous across a G2 joint and jumps across a G1 one), 'mean' or
    'gauss'. Returns (node, (lo, hi)): blue is lo, red is hi (98th percentile)."""
    deflection = deflection or shape.BoundBox.DiagonalLength * 1e-3
    coords, idx, vals = [], [], []
    for face in shape.Faces:
        pts, tris, uvs = tessellation(face, deflection)
        base = len(coords)
        for p, uv in zip(pts, uvs):
            fr = frame_or_none(face, *uv)
            k1, k2, k, h = fr.principal() if fr else (0.0, 0.0, 0.0, 0.0)
            vals.append({"kmax": max(abs(k1), abs(k2)), "mean": h, "gauss": k}[quantity])
            coords.append((p.x, p.y, p.z))
        for t in tris:
            idx.extend([base + t[0], base + t[1], base + t[2], -1])
    s = sorted(abs(v) for v in vals) or [1.0]
    hi = s[min(len(s) - 1, int(0.98 * len(s)))] or 1.0
    lo = 0.0 if quantity == "kmax" else -hi
    node = coin.SoSeparator()
    hints = coin.SoShapeHints()
    hints.vertexOrdering = coin.SoShapeHints.COUNTERCLOCKWISE
    node.addChild(hints)
    mat = coin.SoMaterial()
    mat.diffuseColor.setValues(0, len(vals), [colour((v - lo) / (hi - lo)) for v in vals])
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
    return node, (lo, hi)


MAP_NAME = "C2BlendCurvatureMap"


def show_curvature_map(obj, quantity="kmax"):
    """Show obj's curvature map in its place in the 3D view (obj is hidden while the map
    is shown; replaces a previous map); returns the colour range. The map is a view
    decoration, not part of the document."""
    hide_curvature_map(obj)
    node, rng = curvature_map(obj.Shape, quantity)
    node.setName(MAP_NAME + "_" + obj.Name)
    FreeCADGui.ActiveDocument.ActiveView.getSceneGraph().addChild(node)
    obj.ViewObject.Visibility = False
    FreeCAD.Console.PrintMessage("C2Blend: %s curvature map of %s, blue %.3g .. red %.3g "
                                 "(1/model unit)\n" % (quantity, obj.Label, rng[0], rng[1]))
    return rng


def curvature_map_shown(obj):
    """Whether obj's curvature map is in the scene."""
    sg = FreeCADGui.ActiveDocument.ActiveView.getSceneGraph()
    return any(sg.getChild(i).getName() == MAP_NAME + "_" + obj.Name
               for i in range(sg.getNumChildren()))


def hide_curvature_map(obj):
    """Remove obj's curvature map, if any, and show obj again."""
    sg = FreeCADGui.ActiveDocument.ActiveView.getSceneGraph()
    for i in reversed(range(sg.getNumChildren())):
        if sg.getChild(i).getName() == MAP_NAME + "_" + obj.Name:
            sg.removeChild(i)
            obj.ViewObject.Visibility = True
