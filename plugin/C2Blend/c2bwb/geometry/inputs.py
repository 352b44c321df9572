# SPDX-License-Identifier: LGPL-2.1-or-later
"""The user's input to a fillet, checked before any geometry is built (fillet.py): the
selected edges resolved on the solid, the solid itself (one closed solid), and the
radius or setback, continuity, shape parameters and tension. Every refusal is a
C2BlendError naming the object, the edge and the field.
"""
import math
import numbers

import FreeCAD
import Part

from ..errors import C2BlendError, listing
from . import check as ck
from .rollingball import TANGENT_ANGLE, midpoint
from .surface import angle, frame_at_point
from .trimlines import ROWS, shape_for


def resolve_edges(shape, edges, label, skipped=None):
    """[(name, Part.Edge)] from Part.Edge objects, 'EdgeN' names or 1-based indices, each
    between two faces that meet at an angle. Raises C2BlendError naming the offending
    element. With a list `skipped`, a seam or an edge between faces that meet
    tangentially (no corner to fillet, as OCCT's fillet ignores in a larger selection,
    such as every edge of a part with a slot) is left out instead, appended to it as
    {"where": "Label.EdgeN", "reason"}, unless every edge is such: then the first one's
    error is raised."""
    out, smooth = [], []
    for name, edge in ck.named_edges(shape, edges, label, "fillet"):
        where = "%s.%s" % (label, name)
        faces = ck.edge_faces(shape, edge)
        if len(faces) == 1 and edge.isSeam(faces[0]):
            smooth.append({"where": where, "reason": (
                "the edge is the seam of %s, where that closed face joins itself smoothly: "
                "there is no corner to fillet; leave it out of the selection"
                % ck.element_name(shape, faces[0], "Face"))})
            continue
        if len(faces) != 2:
            raise C2BlendError("the edge has %d adjacent face%s; a fillet needs exactly 2 %s"
                               % (len(faces), "" if len(faces) == 1 else "s",
                                  _why_not_two(shape, faces)), where)
        a = _normals_angle(faces, edge)
        if a < TANGENT_ANGLE:
            smooth.append({"where": where, "reason": (
                "the faces meet tangentially along the edge (their normals differ by %.1e "
                "rad): there is no corner to fillet" % a)})
            continue
        out.append((name, edge))
    if smooth and (skipped is None or not out):
        raise C2BlendError(smooth[0]["reason"], smooth[0]["where"])
    if skipped is not None:
        skipped += smooth
    return out


def _why_not_two(shape, faces):
    """Why an edge of `shape` lies on these `faces`, not two, for resolve_edges'
    message: the one solid of `shape` is not closed there (a free edge of its shell,
    as a failed Boolean can leave), or `shape` is not one solid."""
    solids = shape.Solids
    if len(faces) == 1 and len(solids) == 1 and any(faces[0].isSame(f) for f in solids[0].Faces):
        return ("(it is a free edge of the solid's shell, which is open there, so the solid "
                "is not closed and not valid: repair or rebuild it first; Part > Check "
                "geometry shows what is wrong)")
    return ("(the shape is a %s with %d solid(s); a fillet needs one closed solid)"
            % (shape.ShapeType, len(solids)))


def _normals_angle(faces, edge):
    """The angle (rad) between the normals of the two faces at edge's midpoint."""
    p = midpoint(edge)
    return angle(frame_at_point(faces[0], p).n, frame_at_point(faces[1], p).n)


def radius_for_setback(shape, edges, setback, label="Shape"):
    """The rolling-ball radius (model units) whose contacts lie `setback` (model units)
    from the edges of shape, across each: R = setback / tan(alpha / 2), alpha the angle
    between the faces' normals at the edge's midpoint. Exact where the faces are planes;
    on curved faces the contacts' distance differs by the faces' curvature. Raises
    C2BlendError naming `label` and the edges for a setback that is not a positive
    number, bad edges (resolve_edges), or edges whose angles need radii more than 1e-9
    (relative) apart: a fillet has one radius."""
    setback = positive_number(setback, "setback", label, "radius")
    radii = []
    for name, edge in resolve_edges(shape, edges, label, []):
        alpha = _normals_angle(ck.edge_faces(shape, edge), edge)
        radii.append((setback / math.tan(0.5 * alpha), "%s.%s" % (label, name)))
    lo, hi = min(radii), max(radii)
    if hi[0] - lo[0] > 1e-9 * hi[0]:
        raise C2BlendError("setback %g needs radius %.6g at %s but %.6g at %s, whose faces "
                           "meet at another angle; a fillet has one radius: give a radius, "
                           "or fillet these edges apart" % (setback, lo[0], lo[1], hi[0], hi[1]),
                           ", ".join(n for _, n in radii), "radius")
    return radii[0][0]


def check_solid(shape, label):
    """Raise C2BlendError naming `label` unless shape is one closed solid, not inside out.
    (A compound of solids that share no face or edge is filleted solid by solid, each
    checked here: solids.py.)"""
    solids = [] if shape.isNull() else shape.Solids
    if len(solids) != 1 or len(shape.Faces) != len(solids[0].Faces):
        loose = len(shape.Faces) - sum(len(s.Faces) for s in solids)
        if len(solids) > 1 and loose <= 0:
            raise C2BlendError("the shape is a %s of %d solids that share faces or edges "
                               "(as a CompSolid's do), so a fillet of one would change "
                               "another: make one solid of them (Part > Boolean > Union), "
                               "or separate them (Part > Compound > Explode compound) and "
                               "fillet each" % (shape.ShapeType, len(solids)), label)
        if not solids and loose and all(s.isClosed() for s in shape.Shells) and \
                len(shape.Shells) == 1 and len(shape.Shells[0].Faces) == loose:
            advice = ("; its faces close up: make them a solid first (Part > Convert to "
                      "solid, or Part.Solid(shell) in a macro)")
        elif loose:
            advice = ("; faces with free edges bound no volume: close the shell first "
                      "(Part > Shape builder)")
        else:
            advice = ""
        raise C2BlendError("the shape is a %s with %d solid(s) and %d face(s) outside "
                           "them; a fillet needs one closed solid%s"
                           % ("null shape" if shape.isNull() else shape.ShapeType,
                              len(solids), loose, advice), label)
    if not all(sh.isClosed() for sh in solids[0].Shells):
        free = [ck.element_name(shape, e, "Edge") for e in _free_edges(solids[0])]
        where = (" along %s (edge%s with one face)" % (listing(free, 5), "" if len(free) == 1
                                                       else "s")) if free else ""
        raise C2BlendError("the solid is not closed: its shell is open%s, so it is not valid: "
                           "repair or rebuild it first; Part > Check geometry shows what is "
                           "wrong" % where, label)
    if solids[0].Volume < 0:
        raise C2BlendError("the solid is inside out: its faces point inwards (volume %.6g); "
                           "reverse it first (shape.reversed())" % solids[0].Volume, label)


def _free_edges(solid):
    """The edges of `solid` that bound one face only (not seams or degenerated edges):
    where its shell is open."""
    out = []
    for e in solid.Edges:
        faces = solid.ancestorsOfType(e, Part.Face)
        if not e.Degenerated and len(faces) == 1 and not e.isSeam(faces[0]):
            out.append(e)
    return out


def positive_number(x, what, label, field=None):
    """float(x) for a finite positive real number x (not a bool or a string), or the
    value of a FreeCAD Quantity (in FreeCAD's internal units: mm for a length, as a
    PropertyLength gives); raises C2BlendError naming `label`, `what` (the parameter)
    and x otherwise."""
    if isinstance(x, FreeCAD.Units.Quantity):
        x = x.Value
    if isinstance(x, bool) or not isinstance(x, numbers.Real) or not (
            math.isfinite(x) and x > 0):
        raise C2BlendError("%s must be a positive number, got %r" % (what, x), label, field)
    return float(x)


def check_params(radius, continuity, shape_params, tension, label):
    """Validate the parameters; raise C2BlendError naming the bad one. Returns
    (radius, shape parameters for the continuity (see trimlines.shape_for), tension),
    as floats."""
    radius = positive_number(radius, "radius", label, "radius")
    if not (isinstance(continuity, str) and continuity in ROWS):
        raise C2BlendError("continuity must be C1, C2 or C3, got %r" % (continuity,), label)
    try:
        shape = shape_for(continuity, shape_params)
    except (TypeError, ValueError) as ex:
        raise C2BlendError("shape_params: %s" % ex, label) from None
    return radius, shape, positive_number(tension, "tension", label)
