# SPDX-License-Identifier: LGPL-2.1-or-later
"""Create C2Blend objects in a document. On failure the document is left as it was:
the selection and parameters are checked before anything is added; the object is then
added in one undo transaction, and if its first recompute fails the transaction is
aborted and the object removed (documents made by scripts and freecadcmd have UndoMode
0, where aborting undoes nothing)."""
import FreeCAD

from ..errors import C2BlendError
from . import features

if FreeCAD.GuiUp:
    from ..viewproviders.viewproviders import ViewProviderC2
else:
    ViewProviderC2 = None


def _add(doc, type_name, name, proxy_cls, setup):
    before = {o.Name for o in doc.Objects}
    doc.openTransaction("C2Blend: add " + name)
    try:
        obj = doc.addObject(type_name, name)
        proxy_cls(obj)
        setup(obj)
        if ViewProviderC2 is not None:
            ViewProviderC2(obj.ViewObject)
        doc.recompute()
        if "Invalid" in obj.State:
            why = getattr(obj.Proxy, "last_error", "") or ", ".join(obj.State)
            raise C2BlendError(why, "", getattr(obj.Proxy, "last_kind", "numeric"))
    except Exception:
        doc.abortTransaction()
        for o in reversed(doc.Objects):  # what aborting left (UndoMode 0)
            if o.Name not in before:
                doc.removeObject(o.Name)
        doc.recompute()
        raise
    doc.commitTransaction()
    return obj


def set_params(obj, continuity, shape_params, tension):
    """Store continuity, its shape parameters (as inputs.check_params returns them) and
    tension in obj's properties (features.object_values). Raises ValueError for a C3
    a4 of 0."""
    obj.Continuity = continuity
    obj.Gamma, obj.Eta, obj.Lambda, obj.Rho = features.object_values(continuity, shape_params)
    obj.Tension = float(tension)


def _checked_params(radius, continuity, shape_params, tension, label):
    """The shape parameters of continuity, checked with the radius and tension; raises
    C2BlendError naming label."""
    from ..geometry import inputs
    sp = inputs.check_params(radius, continuity, shape_params, tension, label)[1]
    try:
        features.object_values(continuity, sp)
    except ValueError as ex:
        raise C2BlendError("shape_params: %s" % ex, label) from None
    return sp


def make_fillet(base, edges, radius, continuity="C2", shape_params=(1, 1, 1, 1), tension=1.0):
    """A C2Fillet object filleting edges (names like 'Edge3', 1-based indices or Part.Edge
    objects, or one of them) of document object base. The selection and parameters are
    validated before the document is touched; any later failure aborts the
    transaction, so the document is left as it was."""
    from ..geometry import check as ck, inputs
    sp = _checked_params(radius, continuity, shape_params, tension, base.Label)
    inputs.resolve_edges(base.Shape, edges, base.Label, [])  # at least one edge to fillet
    # the whole selection is kept: a recompute reports the edges it leaves out
    names = [n for n, _ in ck.named_edges(base.Shape, edges, base.Label, "fillet")]

    def setup(obj):
        obj.Base = (base, names)
        obj.Radius = float(radius)
        set_params(obj, continuity, sp, tension)
    obj = _add(base.Document, "Part::FeaturePython", "C2Fillet", features.C2Fillet, setup)
    if FreeCAD.GuiUp:
        base.ViewObject.Visibility = False
    return obj


def make_blend(side1, side2, continuity="C2", shape_params=(1, 1, 1, 1), tension=1.0,
               make_solid=False):
    """A C2BlendFaces object blending side1 to side2, each (object, ['FaceN', 'EdgeM']);
    with make_solid its shape is one solid (features.blend_faces). The sides and
    parameters are validated before the document is touched; any later failure aborts
    the transaction, so the document is left as it was."""
    sp = _checked_params(1.0, continuity, shape_params, tension, side1[0].Label)
    features.blend_side(side1, "Edge1")
    features.blend_side(side2, "Edge2")

    def setup(obj):
        obj.Edge1, obj.Edge2 = side1, side2
        obj.MakeSolid = bool(make_solid)
        set_params(obj, continuity, sp, tension)
    return _add(side1[0].Document, "Part::FeaturePython", "C2Blend", features.C2BlendFaces,
                setup)


def make_check(target, edges, samples=101):
    """A C2Check object reporting continuity across edges of target (as for
    make_fillet)."""
    from ..geometry import check as ck
    names = [n for n, _ in ck.named_edges(target.Shape, edges, target.Label, "check")]

    def setup(obj):
        obj.Target = (target, names)
        obj.Samples = samples
    return _add(target.Document, "App::FeaturePython", "C2Check", features.C2Check, setup)


def make_clock(doc, time=0.0):
    """A C2Clock object holding the animation time."""
    def setup(obj):
        obj.Time = float(time)
    return _add(doc, "App::FeaturePython", "Clock", features.C2Clock, setup)
