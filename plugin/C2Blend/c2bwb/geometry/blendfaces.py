# SPDX-License-Identifier: LGPL-2.1-or-later
"""A G2 blend face between an edge of one face and an edge of another (possibly of
different solids), e.g. two coaxial cylinders with a gap (thesis eqs. 130-131).

Correspondence: both trimlines are parametrised by normalised arc length; closed
trimlines are aligned (start of the second at the point nearest the start of the
first) and oriented alike, open ones are matched end to end.
"""
import math
import time

import Part

from ..errors import C2BlendError, occt_message
from . import check as ck
from .bspline import fit_surface, solve_sampled
from .inputs import check_params
from .solve import DATA_REL
from .surface import frame_at_point
from .trimlines import ROWS, pair_rows, spec_from_rows


class Trimline:
    """An edge of a face, traversed by normalised arc length from a start parameter."""

    def __init__(self, face, edge, where):
        if not any(edge.isSame(e) for e in face.Edges):
            raise C2BlendError("the edge is not an edge of the selected face", where)
        self.face, self.edge, self.where = face, edge, where
        self.closed = edge.isClosed()
        self.length = edge.Length
        if self.length <= 1e-9:
            raise C2BlendError("the edge has zero length", where)
        self.start, self.sense = 0.0, 1.0
        mine = next(e for e in face.Edges if e.isSame(edge))
        if mine.isSeam(face):
            raise C2BlendError("the edge is the face's seam, where the surface closes on "
                               "itself; select an edge bounding the face", where)
        # the edge's sense in the face taken forward; the face lies to its left
        self.forward = (mine.Orientation == "Forward") == (face.Orientation != "Reversed")
        self.pcurve = face.curveOnSurface(edge)

    def param(self, s):
        """Edge parameter at normalised arc length s in [0, 1] from the start, to 1e-12 of
        the edge's length: FreeCAD's default tolerance, 1e-7 model units, moved the
        samples along a B-spline edge 4 thousandths long by up to 2e-5 of it, unevenly,
        and the blend turned from its faces by 7e-8 rad."""
        a = (self.start + self.sense * s) % 1.0 if self.closed else (
            s if self.sense > 0 else 1.0 - s)
        if self.closed and a == 0.0 and s > 0.5:
            a = 1.0
        return self.edge.getParameterByLength(a * self.length, 1e-12 * self.length)

    def outward(self, frame, tangent, t):
        """Unit tangent of the face at the frame's point (the edge's point at parameter
        t), perpendicular to the edge, pointing out of the face across the edge. A face
        lies to the left of its edges' curves in its parameter plane, each run in the
        edge's sense in the face taken forward (OCCT's convention), so the side is read
        from the edge's curve on the face, exactly. (A domain test, isPartOfDomain,
        classifies against polygons of those curves: a point 2.4e-6 beyond the rim of
        a disc of radius 3.8e-3 made a B-spline, where the rim touches the patch's
        border, was held inside on both sides, and the direction flipped there.)"""
        d = frame.n.cross(tangent)
        d.normalize()
        a, b = frame.coords(d)
        c2d, lo, hi = self.pcurve
        e = self.edge
        g = c2d.tangent(lo + (t - e.FirstParameter) / (e.LastParameter - e.FirstParameter)
                        * (hi - lo))
        right = a * g.y - b * g.x  # (a, b) . (g.y, -g.x): towards the right of the curve
        return d if (right > 0.0) == self.forward else -d


def align(t1, t2):
    """Make t2 run like t1: same start point (closed) or matching ends (open)."""
    if t1.closed != t2.closed:
        raise C2BlendError("one trimline is closed and the other open", t2.where)
    p0 = t1.edge.valueAt(t1.param(0.0))
    if t2.closed:
        t2.start = _fraction(t2.edge, p0)
        ta = t1.edge.tangentAt(t1.param(0.0))
        tb = t2.edge.tangentAt(t2.param(0.0))
        if ta.dot(tb) < 0:
            t2.sense = -1.0
    else:
        e = t2.edge
        if (e.valueAt(e.FirstParameter) - p0).Length > (e.valueAt(e.LastParameter) - p0).Length:
            t2.sense = -1.0


def _fraction(edge, p):
    """Normalised arc length of the point of `edge` nearest p."""
    t = edge.Curve.parameter(p)
    t = min(max(t, edge.FirstParameter), edge.LastParameter)
    piece = edge.Curve.toShape(edge.FirstParameter, t) if t > edge.FirstParameter else None
    return (piece.Length / edge.Length) if piece is not None else 0.0


def blend(face1, edge1, face2, edge2, continuity="C2", shape_params=(1.0, 1.0, 1.0, 1.0),
          tension=1.0, samples=32, max_samples=1024, tol_rel=1e-8, names=("Face1", "Face2")):
    """G2 blend face from edge1 of face1 (u = 0) to edge2 of face2 (u = 1).

    tol_rel: the B-spline fit's tolerance relative to the blend's size, as for a fillet
    (fillet.fillet): at 1e-7 the fit alone turned the normal of a blend between
    cylinders tilted 0.5 rad by 6.7e-8 rad, over G1's 1e-8; at 1e-8, 1.9e-9.
    Returns (Part.Face, report dict). Raises C2BlendError naming the faces/edges.
    """
    t0 = time.perf_counter()
    if isinstance(names, str) or not (isinstance(names, (tuple, list)) and len(names) == 2
                                      and all(isinstance(x, str) for x in names)):
        raise C2BlendError("labels must be two names, one per face, as ('Cylinder.Face1', "
                           "'Tube.Face3'); got %r" % (names,), "blend")
    names = tuple(names)
    for face, edge, name in ((face1, edge1, names[0]), (face2, edge2, names[1])):
        if not isinstance(face, Part.Face) or not isinstance(edge, Part.Edge):
            raise C2BlendError("a Part.Face and one of its Part.Edge objects are needed, got "
                               "%s and %s" % (type(face).__name__, type(edge).__name__), name)
    _, shape_params, tension = check_params(1.0, continuity, shape_params, tension, names[0])
    t1, t2 = Trimline(face1, edge1, names[0]), Trimline(face2, edge2, names[1])
    align(t1, t2)
    where = "%s -> %s" % names
    nrows = ROWS[continuity]

    def rows_at(n):
        def pair(s):
            a, b = t1.param(s), t2.param(s)
            p1, p2 = edge1.valueAt(a), edge2.valueAt(b)
            g1, g2 = edge1.tangentAt(a), edge2.tangentAt(b)
            f1, f2 = frame_at_point(face1, p1), frame_at_point(face2, p2)
            return f1, g1, t1.outward(f1, g1, a), f2, g2, t2.outward(f2, g2, b)
        fractions = (k / n if t1.closed else k / (n - 1) for k in range(n))
        return pair_rows((pair(s) for s in fractions), nrows, tension, where)

    kernel, n, err = solve_sampled(
        rows_at,
        lambda r0, r1: spec_from_rows(r0, r1, continuity, shape_params, t1.closed,
                                      "blend " + where),
        where, samples, max_samples, DATA_REL, math.inf)
    surface, fit = fit_surface(kernel, tol_rel, where)
    face = Part.Face(surface)
    v0, v1 = surface.bounds()[2:4]
    diag = face.BoundBox.DiagonalLength
    reps = []
    for side, prim in ((0.0, face1), (1.0, face2)):
        r = ck.compare(face, prim, ck.trimline_points(surface, side), diag, oriented=False)
        r["trimline"] = "u=%g (%s)" % (side, names[int(side)])
        reps.append(r)
    report = {"continuity": continuity, "shape_params": list(shape_params), "tension": tension,
              "samples": n, "data_error": err, "fit_deviation": fit["deviation"],
              "fit_tolerance": fit["tolerance"], "poles": list(fit["poles"].shape[:2]),
              "trimlines": reps, "seconds": time.perf_counter() - t0,
              "verdict": min((r["verdict"] for r in reps), key=ck.RANK.get)}
    return face, report


def close_solid(faces, where):
    """One solid from faces (primaries + blend), capping planar free boundaries.
    Raises C2BlendError when faces are not Part.Face objects or no closed shell results."""
    try:
        given = list(faces)
    except TypeError:
        given = None
    if not given or not all(isinstance(f, Part.Face) for f in given):
        kinds = sorted({type(f).__name__ for f in given}) if given else None
        raise C2BlendError("a list of Part.Face objects is needed (the primaries' faces "
                           "and the blend), got %s" % (
                               "a list of %s" % " and ".join(kinds) if kinds else
                               "an empty list" if given == [] else type(faces).__name__),
                           where)
    faces = given
    sewn = Part.Compound(faces)
    sewn.sewShape()
    shell = sewn if sewn.ShapeType == "Shell" else Part.Shell(sewn.Faces)
    free = []
    for e in shell.Edges:
        owners = shell.ancestorsOfType(e, Part.Face)
        # a sphere's or cone's pole is a degenerate edge of one face, not a boundary
        if len(owners) == 1 and not e.isSeam(owners[0]) and not e.Degenerated:
            free.append(e)
    caps = []
    for w in Part.sortEdges(free) if free else []:
        wire = Part.Wire(w)
        try:
            caps.append(Part.Face(wire))
        except Exception as ex:
            c = wire.BoundBox.Center
            why = "it is not closed" if not wire.isClosed() else "it is not planar" \
                if wire.findPlane() is None else "OCCT: " + occt_message(ex)
            raise C2BlendError("cannot cap the free boundary of %d edge(s) around (%.4g, "
                               "%.4g, %.4g) with a plane face (%s): cap it yourself, or "
                               "pass faces that close it" % (len(w), c.x, c.y, c.z, why),
                               where, "sewing") from None
    sewn = Part.Compound(list(shell.Faces) + caps)
    sewn.sewShape()
    shells = sewn.Shells if sewn.ShapeType != "Shell" else [sewn]
    if len(shells) != 1 or not shells[0].isClosed():
        raise C2BlendError("the primaries, the blend and the caps do not close into one "
                           "solid", where, "sewing")
    solid = Part.Solid(shells[0])
    if solid.Volume < 0:
        solid.reverse()
    if not solid.isValid():
        raise C2BlendError("the closed solid is not valid", where, "validity")
    return solid
