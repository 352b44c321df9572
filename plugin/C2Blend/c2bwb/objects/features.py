# SPDX-License-Identifier: LGPL-2.1-or-later
"""Parametric document objects of C2Blend (FeaturePython). Headless: no GUI imports.

The class paths are stored in saved documents: never rename this module or classes.
A failed recompute keeps the previous shape and prints the reason to the Report view.
"""
import json

import FreeCAD

from ..errors import C2BlendError
from ..geometry import blendfaces, check as ck, fillet as fl

CONTINUITIES = ["C2", "C1", "C3"]


def _shape_props(obj):
    """Shape parameters and tension of the blend-like object."""
    for name, doc in (("Gamma", "gamma: shape parameter of the sixth-order PDE"),
                      ("Eta", "eta: shape parameter of the sixth-order PDE"),
                      ("Lambda", "lambda: shape parameter of the sixth-order PDE"),
                      ("Rho", "rho: shape parameter of the sixth-order PDE"),
                      ("Tension", "scale of the cross-boundary derivatives (> 0)")):
        obj.addProperty("App::PropertyFloat", name, "Shape", doc)
        setattr(obj, name, 1.0)
    obj.addProperty("App::PropertyEnumeration", "Continuity", "Blend",
                    "C1: tangent data; C2: curvature data (G2 contact); C3: plus third")
    obj.Continuity = CONTINUITIES
    obj.Continuity = "C2"
    obj.addProperty("App::PropertyString", "Verdict", "Report", "worst continuity found")
    obj.addProperty("App::PropertyString", "Report", "Report", "continuity report (JSON)")
    obj.setEditorMode("Verdict", 1)
    obj.setEditorMode("Report", 1)


def shape_params(continuity, values):
    """The shape parameters of continuity from an object's (Gamma, Eta, Lambda, Rho): C2
    uses all four, C1's (b, c, d) are the first three, C3's (a0..a4) are the four and 1."""
    values = tuple(float(p) for p in values)
    return {"C1": values[:3], "C2": values, "C3": values + (1.0,)}[continuity]


def object_values(continuity, params_):
    """(Gamma, Eta, Lambda, Rho) storing the shape parameters of continuity (as checked
    by inputs.check_params), the inverse of shape_params. C3's five are divided by a4,
    which leaves its PDE (homogeneous in them) unchanged. Raises ValueError when a4 is 0."""
    p = tuple(float(x) for x in params_)
    if continuity == "C1":
        return p + (1.0,)
    if continuity == "C3":
        if p[4] == 0.0:
            raise ValueError("a document object stores C3's shape parameters divided by a4, "
                             "which must not be 0")
        return tuple(x / p[4] for x in p[:4])
    return p


def params(obj):
    """(continuity, shape parameters, tension) of an object (see shape_params)."""
    return (obj.Continuity, shape_params(obj.Continuity, (obj.Gamma, obj.Eta, obj.Lambda,
                                                          obj.Rho)), obj.Tension)


def _publish(obj, rep, header):
    obj.Report = json.dumps(rep, default=float)
    obj.Verdict = rep["verdict"]
    lines = [header] + ["  " + s for s in ck.format_report(rep)]
    FreeCAD.Console.PrintMessage("\n".join(lines) + "\n")


class _Proxy:
    """Proxy state is the document's properties only: nothing extra to save."""

    def dumps(self):
        return None

    def loads(self, state):
        return None

    def update(self, obj, title, compute):
        """obj.Shape (unless shape is None) and report from compute() -> (shape, report).
        On C2BlendError the previous shape is kept, the reason is printed and kept in
        last_error, and the error propagates (FreeCAD marks the object invalid)."""
        try:
            shape, rep = compute()
        except C2BlendError as ex:
            self.last_error, self.last_kind = str(ex), ex.kind
            FreeCAD.Console.PrintError("%s %s: %s (previous shape kept)\n"
                                       % (title, obj.Label, ex))
            raise
        self.last_error = ""
        if shape is not None:
            obj.Shape = shape
        _publish(obj, rep, "%s %s: %s" % (title, obj.Label, rep["verdict"]))


class C2Fillet(_Proxy):
    """G2 fillet of edges of a solid: Base = (object, [edge names])."""

    def __init__(self, obj):
        obj.addProperty("App::PropertyLinkSub", "Base", "Fillet", "solid and its edges")
        obj.addProperty("App::PropertyLength", "Radius", "Fillet",
                        "rolling-ball radius that fixes the trimlines")
        obj.Radius = 1.0
        _shape_props(obj)
        obj.Proxy = self

    def execute(self, obj):
        base, subs = obj.Base
        cont, sp, tension = params(obj)
        self.update(obj, "C2 Fillet", lambda: fl.fillet(
            base.Shape, list(subs), float(obj.Radius), cont, sp, tension, base.Label))


class C2BlendFaces(_Proxy):
    """G2 blend face between Edge1 = (object, [FaceN, EdgeM]) and Edge2 likewise."""

    def __init__(self, obj):
        obj.addProperty("App::PropertyLinkSub", "Edge1", "Blend", "first face and its edge")
        obj.addProperty("App::PropertyLinkSub", "Edge2", "Blend", "second face and its edge")
        obj.addProperty("App::PropertyBool", "MakeSolid", "Blend",
                        "one solid: the primaries' faces, the blend and planar caps")
        _shape_props(obj)
        obj.Proxy = self

    def execute(self, obj):
        self.update(obj, "C2 Blend", lambda: blend_faces(
            obj.Edge1, obj.Edge2, *params(obj), make_solid=obj.MakeSolid))


def blend_side(link, which):
    """(face, edge, 'Label.FaceN+EdgeM') of one side of a blend, link = (object,
    ['FaceN', 'EdgeM']). Raises C2BlendError naming the side (which) and the object."""
    o, subs = link
    subs = list(subs)
    faces = [s for s in subs if s.startswith("Face")]
    edges = [s for s in subs if s.startswith("Edge")]
    where = "%s.%s" % (o.Label, "+".join(subs))
    if len(faces) != 1 or len(edges) != 1 or len(subs) != 2:
        raise C2BlendError("%s needs one face and one of its edges, got %s"
                           % (which, subs), where)
    n = {"Face": len(o.Shape.Faces), "Edge": len(o.Shape.Edges)}
    for name in subs:
        kind, k = name[:4], name[4:]
        if not k.isdigit() or not 1 <= int(k) <= n[kind]:
            raise C2BlendError("no such %s: %s (%s has %d %ss)"
                               % (kind.lower(), name, o.Label, n[kind], kind.lower()), where)
    face, edge = o.Shape.getElement(faces[0]), o.Shape.getElement(edges[0])
    blendfaces.Trimline(face, edge, where)  # the edge is the face's and not degenerate
    return face, edge, where


def blend_faces(side1, side2, continuity, shape_params, tension, make_solid=False):
    """(shape, report) of a C2BlendFaces object: the blend face from side1 to side2
    (blend_side), or with make_solid one solid of the two faces, the blend and planar
    caps. Raises C2BlendError naming the sides."""
    f1, e1, w1 = blend_side(side1, "Edge1")
    f2, e2, w2 = blend_side(side2, "Edge2")
    face, rep = blendfaces.blend(f1, e1, f2, e2, continuity, shape_params, tension,
                                 names=(w1, w2))
    shape = blendfaces.close_solid([f1, face, f2], "%s -> %s" % (w1, w2)) \
        if make_solid else face
    for r in rep["trimlines"]:
        r.setdefault("edge", r["trimline"])
        r.setdefault("faces", [])
    return shape, rep


class C2Check(_Proxy):
    """Continuity report across edges: Target = (object, [edge names])."""

    def __init__(self, obj):
        obj.addProperty("App::PropertyLinkSub", "Target", "Check", "shape and its edges")
        obj.addProperty("App::PropertyInteger", "Samples", "Check", "points per edge")
        obj.Samples = 101
        obj.addProperty("App::PropertyString", "Verdict", "Report", "worst continuity found")
        obj.addProperty("App::PropertyString", "Report", "Report", "continuity report (JSON)")
        obj.Proxy = self

    def execute(self, obj):
        o, subs = obj.Target
        self.update(obj, "C2 Check", lambda: (None, ck.check(o.Shape, list(subs), obj.Samples,
                                                             o.Label)))


class C2Clock(_Proxy):
    """A Time property for animations; bind primaries to it with expressions,
    e.g. Cylinder.Radius = 1 + 0.2 * Clock.Time."""

    def __init__(self, obj):
        obj.addProperty("App::PropertyFloat", "Time", "Animation", "time parameter t")
        obj.Proxy = self

    def execute(self, obj):
        return None
