# SPDX-License-Identifier: LGPL-2.1-or-later
"""C2Blend scripting API: curvature-continuous (G2) fillets and blends for macros.

    import C2Blend
    solid = C2Blend.fillet(shape, ["Edge10"], 2.0)                  # Part.Solid
    solid, report = C2Blend.fillet_report(shape, ["Edge10"], 2.0)   # Part.Solid, dict
    radius = C2Blend.radius_for_setback(shape, ["Edge10"], 1.5)     # model units
    face = C2Blend.blend(face1, edge1, face2, edge2)                # Part.Face
    face, report = C2Blend.blend(face1, edge1, face2, edge2, report=True)
    report = C2Blend.check(shape, ["Edge3"])                        # dict

Every function leaves its inputs unchanged and raises C2Blend.Error, whose message
names the object (the `label` or `labels` given, "Shape" by default) and the edge, when
the operation cannot be done. Reports state, for every
trimline, the worst position gap (g0), normal angle (g1, rad) and cross-direction
normal-curvature jump (g2, absolute and relative) over 101 samples, and a verdict.
"""
from c2bwb.errors import C2BlendError as Error
from c2bwb.geometry import blendfaces as _blendfaces
from c2bwb.geometry import check as _check
from c2bwb.geometry import fillet as _fillet
from c2bwb.geometry import inputs as _inputs

__all__ = ["Error", "fillet", "fillet_report", "radius_for_setback", "blend", "blend_solid",
           "check", "format_report"]


def fillet_report(shape, edges, radius, continuity="C2", shape_params=(1, 1, 1, 1),
                  tension=1.0, label="Shape"):
    """Fillet edges of shape with the PDE blend; returns (Part.Solid, report dict).

    shape: one solid, or a compound of solids (each with selected edges is filleted on
    its own, as OCCT's makeFillet does; the result is then a Part.Compound of them in
    their order, then any wires, edges and vertices beside them, and the report names
    the compound's edges and faces).
    edges: Part.Edge objects of shape, names ('Edge3') or 1-based indices (a single one
    stands for a list of one; an edge given twice is filleted once).
    radius: rolling-ball radius (model units) fixing the trimlines.
    continuity: 'C1', 'C2' (G2 contact, default) or 'C3'.
    shape_params: (gamma, eta, lambda, rho) for C2, (b, c, d) for C1, (a0..a4) for C3;
    tension scales the cross derivatives. label: the shape's name in error messages.
    """
    return _fillet.fillet(shape, edges, radius, continuity, shape_params, tension, label)


def fillet(shape, edges, radius, continuity="C2", shape_params=(1, 1, 1, 1), tension=1.0,
           label="Shape"):
    """Fillet edges of shape; returns the filleted Part.Solid, or Part.Compound for a
    compound of solids (see fillet_report)."""
    return fillet_report(shape, edges, radius, continuity, shape_params, tension, label)[0]


def radius_for_setback(shape, edges, setback, label="Shape"):
    """The radius whose fillet of edges lies `setback` from each edge, across it (exact
    between planes: R = setback / tan(alpha / 2), alpha the angle between the faces'
    normals); edges needing different radii raise C2Blend.Error."""
    return _inputs.radius_for_setback(shape, edges, setback, label)


def blend(face1, edge1, face2, edge2, continuity="C2", shape_params=(1, 1, 1, 1),
          tension=1.0, report=False, labels=("Face1", "Face2")):
    """G2 blend face from edge1 of face1 to edge2 of face2 (possibly different solids).

    Returns a Part.Face, or (Part.Face, report dict) with report=True. labels: the two
    sides' names in error messages and the report, e.g. ("Cylinder.Face1", "Tube.Face3").
    """
    face, rep = _blendfaces.blend(face1, edge1, face2, edge2, continuity, shape_params,
                                  tension, names=labels)
    return (face, rep) if report else face


def blend_solid(faces, where="blend"):
    """One solid from primary faces plus blend faces, with planar caps where needed."""
    return _blendfaces.close_solid(faces, where)


def check(shape, edges, samples=101, label="Shape"):
    """Continuity report (G0/G1/G2) across edges of shape, e.g. of OCCT's own fillets.
    edges: Part.Edge objects, names ('Edge3') or 1-based indices, each between two faces.
    samples: points per edge (at least 1)."""
    return _check.check(shape, edges, samples, label)


def format_report(report):
    """Report lines (str) for the Report view or a terminal."""
    return "\n".join(_check.format_report(report))
