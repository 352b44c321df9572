# SPDX-License-Identifier: LGPL-2.1-or-later
"""A setback corner where a convex and a concave fillet meet at a vertex whose third
edge is left sharp (fillet.py, corners.py).

At a pocket's top corner with its rim edge (convex, between the top face T and a wall)
and its corner edge (concave, between that wall and the next, W) selected, and the
rim edge on W not, OCCT puts a face between the two fillets that it meets at an angle:
it runs along the top of the concave fillet and shrinks to a point P0 where that
fillet's top reaches W's rim. It cannot be otherwise: the ball rolling along the
concave fillet's top goes on along W's rim, which is not filleted, so any face tangent
to T and to the concave fillet there vanishes at P0, and a plate filling of the hole
the blends leave in its place turns from the faces around it by 0.2 to 3 rad.

So the corner is set back on W: the hole is bounded anew by
- the convex fillet's end section, where OCCT ends it (exact);
- an edge on T from that section's end Q on T to the point A of W's rim a setback s
  from P0, leaving Q along the convex fillet's trimline and meeting the rim across;
- an edge on W from A, leaving along the rim towards P0, to the point B of the
  concave fillet's trimline on W a setback s from P0, arriving along that trimline;
- the concave fillet's end, cut from the convex fillet's trimline end C on the first
  wall to B (ends.py, as a slanted end at a corner patch),
so that the hole no longer shrinks to a point: the plate filling it (corners.py) is
tangent to T and to both blends, and meets W along a crease, as T meets W along the
rim (the filling's edge order there is 0, position only). s is the fillet's radius,
at most half of either edge from P0. The edges on T and W are cubic Bezier curves in
the faces' parameters. The fillets' roles may swap: where a lower boss meets a taller
one (shapes.boss_on_boss), the lower top's rim fillet (convex) vanishes at P0 and is
cut, the fillet along the taller boss (concave) ends exact, T is the taller boss's
side, W the lower one's, and W's rim the concave edge where they meet. Q then lies
beyond that rim, and the edge on T goes round the rim's end above the lower top
before it comes down to A, its first leg as long as that takes (on_top).

The filling is an approximation, measured and reported like a corner's, never G2: on
the ten mixed-convexity vertices of the fillet surveys (tools/fillet_survey.py
--random-edges 40 --seed 5 and --random-machined 60 --seed 2) it turns from the
blends and T by 3e-4 to 3e-3 rad, and every solid passes the BOP check. It is less
fair than a three-fillet corner's: at the pocket's corner R = 1 (shapes.pocket_block)
its largest principal curvature is 9.4 (a box's corner: 3.2), where the edge on T
passes within half a radius of the concave blend's end. Tried and dropped: that edge
through the point where the ball touching W at B touches T (a quarter circle 2 R
round the concave fillet's axis on a box), or longer legs, or a setback of 1.5 to
2 R: the plate then rose 0.04 to 0.19 R above T, or OCCT's BOP check found it
self-intersecting.
"""
import FreeCAD
import Part

from .surface import frame_at_point, leaving

Vector2d = FreeCAD.Base.Vector2d

BEZIER = 1.0 / 3.0  # a Bezier leg's length, as a fraction of its chord
# the first leg of the edge on T, as a fraction of its chord, each tried in turn until
# the edge lies on the original T and passes CLEAR radii or more from its vertex
# nearest to P0 (on_top). On shapes.hole_through_pocket_wall a third of the chord
# passes it by 0.003, 0.009 and 0.015 R at R = 0.15, 0.2 and 0.1 (at 0.15 the cut left
# it on T's piece kept); the legs taken on the survey's parts pass it by 0.024 R and
# more.
FIRST_LEGS = (BEZIER, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0)
CLEAR = 0.02
ON_TOP = 16  # points inside the edge on T tested to lie on T
# the edge on T, but this fraction of its parameter range at each end (A lies on T's
# rim), must not meet T's edges: the points tested lie on T where the edge cuts across
# a corner of it between two of them (on_top)
END_SPAN = 0.01
REACH = 0.5  # the setback is at most this fraction of the edges from P0
# the reason for keeping the fillets of a setback corner left unfilled
KEPT = ("OCCT's face between a convex and a concave fillet at a vertex whose third edge "
        "is not selected, kept with those fillets")


class Setback:
    """The setback corner replacing OCCT's face `face` (a RollingBallFace with between
    set) between a convex and a concave fillet of `radius` in `result` (OCCT's fillet;
    fillet_faces: its rolling-ball faces; original(f): the face of the original solid
    that a face f of `result` lies on).

    Attributes: tools, the edges on T and W that bound the faces anew; creases, [the
    edge on W] (the filling meets W there at an angle); slants, [(the concave fillet's
    rolling-ball face, its end edge C to B, by which its blend is cut)] (the convex
    fillet ends exact); kept, the reason its fillets are kept when the corner is not
    filled. Raises ValueError, saying why, where OCCT's face is not such a
    corner (its edges are not one on a face, one on each fillet and at most one
    degenerate) or the setback edges cannot be made."""

    def __init__(self, result, face, fillet_faces, radius, original):
        on_face, on_fillet, pinch = [], [], None
        for e in face.Edges:
            if e.Degenerated:
                pinch = e.Vertexes[0]
                continue
            nbrs = [f for f in result.ancestorsOfType(e, Part.Face) if not f.isSame(face)]
            if len(nbrs) != 1:
                raise ValueError("an edge of it has %d neighbours" % len(nbrs))
            fillet = any(nbrs[0].isSame(f) for f in fillet_faces)
            (on_fillet if fillet else on_face).append((e, nbrs[0]))
        if len(on_face) != 1 or len(on_fillet) != 2:
            raise ValueError("it has %d edges on faces and %d on fillets, not 1 and 2"
                             % (len(on_face), len(on_fillet)))
        (t_edge, top), = on_face
        if pinch is None:  # the vertex where the edge on T meets a fillet's
            pinch = _shared(t_edge, *[e for e, _ in on_fillet])
        concave = [(e, f) for e, f in on_fillet if _has(e, pinch)]
        convex = [(e, f) for e, f in on_fillet if not _has(e, pinch)]
        if len(concave) != 1 or len(convex) != 1:
            raise ValueError("its vertex where the fillets vanish is not on one of them")
        (c_edge, c_face), (v_edge, v_face) = concave[0], convex[0]
        q = _shared(v_edge, t_edge).Point
        c = _shared(v_edge, c_edge).Point
        walls = [f for f in result.ancestorsOfType(pinch, Part.Face)
                 if not f.isSame(face) and not f.isSame(top)
                 and not any(f.isSame(g) for g in fillet_faces)]
        if len(walls) != 1:
            raise ValueError("%d faces besides the top and the fillets meet at its "
                             "vanishing point, not 1" % len(walls))
        wall = walls[0]
        rim = _between(result, top, wall, pinch)
        trimline = _between(result, c_face, wall, pinch)
        a, rim_out = _along(rim, pinch, min(radius, REACH * rim.Length))
        b, trim_out = _along(trimline, pinch, min(radius, REACH * trimline.Length))
        # across the rim at A, pointing out of T: T lies on its other side
        across = frame_at_point(top, a).n.cross(rim_out)
        eps = 1e-3 * radius
        if top.distToShape(Part.Vertex(a + across * eps))[0] < \
                top.distToShape(Part.Vertex(a - across * eps))[0]:
            across = -across
        v_out = -leaving(_trimline_at(result, v_face, top, q), q)  # on past Q
        self.tools = [on_top(top, original(top), q, v_out, a, across, pinch.Point,
                              CLEAR * radius),
                      bezier(wall, a, -rim_out, b, trim_out)]
        self.creases = [self.tools[1]]
        self.slants = [(c_face, bezier(c_face, c, None, b, None))]
        self.kept = KEPT


def _has(edge, vertex):
    return any(v.isSame(vertex) for v in edge.Vertexes)


def _shared(a, *others):
    """The vertex of edge a that one of `others` has too."""
    for v in a.Vertexes:
        if any(_has(o, v) for o in others):
            return v
    raise ValueError("its edges do not meet")


def _between(result, f, g, vertex):
    """The edge of `result` between faces f and g that ends at `vertex`."""
    for e in result.ancestorsOfType(vertex, Part.Edge):
        faces = result.ancestorsOfType(e, Part.Face)
        if not e.Degenerated and any(x.isSame(f) for x in faces) and \
                any(x.isSame(g) for x in faces):
            return e
    raise ValueError("no edge between the faces ends at its vanishing point")


def _along(edge, vertex, s):
    """(point of `edge` at arc length s from its end `vertex`, the edge's unit tangent
    there pointing away from that end)."""
    first = (edge.valueAt(edge.FirstParameter) - vertex.Point).Length <= \
        (edge.valueAt(edge.LastParameter) - vertex.Point).Length
    t = edge.getParameterByLength(s if first else edge.Length - s)
    d = edge.tangentAt(t)
    return edge.valueAt(t), (d if first else -d)


def _trimline_at(result, fillet, top, q):
    """The rolling-ball face `fillet`'s contact edge on the face `top` that ends at q."""
    for e in fillet.Edges:
        faces = result.ancestorsOfType(e, Part.Face)
        if any(f.isSame(top) for f in faces) and \
                min((v.Point - q).Length for v in e.Vertexes) <= 1e-7 * (1.0 + q.Length):
            return e
    raise ValueError("the convex fillet has no edge on the top face at its end")


def on_top(top, whole, q, d0, a, d1, p0, clear, legs=None):
    """The edge on T (`top`, OCCT's face; `whole`, the original solid's, which is cut
    along it) from Q to A (bezier, leaving Q along d0 and arriving at A along d1), its
    first leg the shortest of FIRST_LEGS for which it lies on the original face and
    passes `clear` (model units) or more from that face's vertex V nearest to P0
    (`p0`), where the edges the fillets consume end: V must lie in the hole, not on
    the piece of T kept. Where Q lies close to W's rim (at the tip of a crescent where
    a lower boss meets a taller one, T being the taller one's side and W the lower
    one's), a short leg turns down too soon and crosses T's edge along the lower
    boss's top (OCCT's face grows past it), and a long one hooks back too far for the
    filling: at a tip of shapes.boss_on_boss (R = 0.204), legs of 0.7, 0.8, 0.9 and
    1.2 times the chord gave an edge off the face, a filling within 4e-3 rad, one
    within 0.013 rad and a folded one. Where a hole cuts a pocket's wall
    (shapes.hole_through_pocket_wall, R = 0.15), a third of the chord passed 5e-4
    from V, which the cut then left on T's piece, and that piece was dropped. Raises
    ValueError when no leg does. The edge's inner part (but END_SPAN at each end) must
    not meet that face's edges either: where T wraps 270 degrees round V (the top of a
    pocket's end wall over a chamfer, shapes.chamfered_pocket), a leg of 0.7 of the
    chord cut across V's corner between two of the points tested, off T, and V was left
    on T's piece. `legs`, when given, are the (first, last) legs (fractions of the
    chord) tried in place of FIRST_LEGS' first legs, each with a last leg of BEZIER."""
    tol = max(e.Tolerance for e in whole.Edges)
    corner = Part.Vertex(min((v.Point for v in whole.Vertexes), key=lambda p: (p - p0).Length))
    bounds = Part.Compound(whole.Edges)
    for first, last in legs or [(f, BEZIER) for f in FIRST_LEGS]:
        edge = bezier(top, q, d0, a, d1, first, last)
        t0, t1 = edge.FirstParameter, edge.LastParameter
        inner = Part.Edge(edge.Curve, t0 + END_SPAN * (t1 - t0), t1 - END_SPAN * (t1 - t0))
        if all(whole.isInside(edge.valueAt(t0 + (t1 - t0) * k / (ON_TOP + 1)), tol, True)
               for k in range(1, ON_TOP + 1)) and edge.distToShape(corner)[0] >= clear \
                and inner.distToShape(bounds)[0] > tol:
            return edge
    raise ValueError("its edge on the top face leaves that face, or passes its corner, "
                     "whatever its legs")


def bezier(face, p0, d0, p1, d1, first=BEZIER, last=BEZIER):
    """An edge on face's surface from point p0 to p1 (on it): a cubic Bezier curve in its
    parameters whose legs, `first` and `last` times the chord long, leave p0 along d0
    and arrive at p1 along d1 (unit 3D tangent vectors, or None: along the chord in the
    parameters, the short way round a periodic surface). Raises ValueError when it
    misses p0 or p1."""
    surface = face.Surface
    f0, f1 = frame_at_point(face, p0), frame_at_point(face, p1)
    uv0, uv1 = Vector2d(f0.u, f0.v), Vector2d(f1.u, f1.v)
    if surface.isUPeriodic():
        uv1.x += round((uv0.x - uv1.x) / surface.UPeriod()) * surface.UPeriod()
    if surface.isVPeriodic():
        uv1.y += round((uv0.y - uv1.y) / surface.VPeriod()) * surface.VPeriod()
    chord = (p1 - p0).Length

    def step(frame, d, fraction):
        if d is None:
            return (uv1 - uv0) * fraction
        du, dv = frame.coords(d)
        return Vector2d(du, dv) * (fraction * chord)
    curve = Part.Geom2d.BezierCurve2d()
    curve.setPoles([uv0, uv0 + step(f0, d0, first), uv1 - step(f1, d1, last), uv1])
    edge = curve.toShape(surface)
    ends = [edge.valueAt(edge.FirstParameter), edge.valueAt(edge.LastParameter)]
    if (ends[0] - p0).Length + (ends[1] - p1).Length > 1e-6 * (1.0 + BEZIER * chord):
        raise ValueError("a setback edge does not reach its ends")
    return edge
