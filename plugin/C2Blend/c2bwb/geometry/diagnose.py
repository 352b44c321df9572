# SPDX-License-Identifier: LGPL-2.1-or-later
"""OCCT's rolling-ball fillet, which gives a fillet its topology (fillet.py), run safely
and, where it fails or a fillet is kept as OCCT's, explained: a radius too large for an
arc the ball must follow, the set of edges whose fillet fails, an input solid that is
not valid, and the unselected edges that would make a vertex a corner.
"""
import math

import Part

from ..errors import listing, occt_message
from . import check as ck
from . import bopcheck as bc
from .surface import frame_at_point

# the end of a kept blend's reason naming the unselected edges that would make its
# vertex a corner (_with_others: OCCT's fillet succeeds with them)
CORNER_HINT = ("; with %s selected too, the fillets meet at a corner there instead "
               "(OCCT's fillet of them succeeds)")


def rolling_ball(shape, edges, radius):
    """OCCT's rolling-ball fillet: (valid solid, None), or (None, why it failed)."""
    try:
        result = shape.makeFillet(radius, edges)
    except Exception as ex:
        return None, occt_message(ex)
    if result.isNull() or not result.isValid():
        return None, "the result is not a valid solid"
    return result, None


def _works(shape, edges, radius):
    """Whether OCCT's rolling-ball fillet of `edges` at `radius` gives a valid solid,
    tried in another process (bc.trial_fillet), where OCCT may crash; in this one
    where no such process can start."""
    tried = bc.trial_fillet(shape, edges, radius)
    if tried is None:
        return rolling_ball(shape, edges, radius)[0] is not None
    return tried[0]


def occt_crash(shape, edges, radius):
    """Why OCCT's rolling-ball fillet of `edges` at `radius` cannot be made here, when it
    crashes the process that makes it, else None: it is tried first in another
    (bc.trial_fillet), which gets the shape exactly. On a block's hole rim half under a
    boss (R = 0.001, 0.01) OCCT's fillet builder crashed (a segmentation fault), which
    closes FreeCAD."""
    tried = bc.trial_fillet(shape, edges, radius)
    if tried is None or tried[1] != bc.CRASHED:
        return None
    return ("OCCT's rolling-ball fillet of radius %g crashes on these edges (it was tried "
            "in another process, which it closed): FreeCAD's own Fillet may close FreeCAD "
            "here. A fillet of the edges one by one, or at another radius, may avoid it"
            % radius)


def invalid_input(shape, msg):
    """The message for OCCT's fillet failing (msg) on a solid that fails isValid(): no
    radius is to blame, the solid is (as one whose faces are not oriented alike, which
    BRepCheck's own messages, FreeCAD's check(), pass over as "No error": the
    finding is then bopcheck.IN_CONTEXT, which adds nothing to isValid() here)."""
    found = bc.problems(shape, bop=False)
    return ("OCCT's rolling-ball fillet failed (%s) on a solid that is not valid itself "
            "(isValid() is False%s): repair it first; Part > Check geometry shows what is "
            "wrong, and in a macro shape.fix(1e-7, 1e-7, 1e-7) mends faults such as a "
            "face oriented against the rest of its shell"
            % (msg, "; BRepCheck: %s" % found if found and found != bc.IN_CONTEXT else ""))


def rolling_ball_failure(shape, names, radius, msg, label):
    """The message for a failed rolling-ball fillet of the edges `names` ([(name,
    Part.Edge)]), with the radius nearest to `radius` that OCCT accepts on these edges:
    halving from radius down to radius / 1024, else doubling up to the shape's diagonal
    (a radius near OCCT's tolerance fails too), then 6 bisections (about 1 % from the
    limit); or the statement that no radius works, with the edges it fails on together
    (_failing_set). These fillets are tried in another process (_works), where OCCT
    may crash."""
    edges = [e for _, e in names]

    def works(r):
        return _works(shape, edges, r)

    head = "OCCT's rolling-ball fillet of radius %g failed (%s)" % (radius, msg)
    diag = shape.BoundBox.DiagonalLength
    ok = next((radius / 2 ** k for k in range(1, 11) if works(radius / 2 ** k)), None)
    if ok is not None:
        bad = 2 * ok
    else:
        ups = (radius * 2 ** k for k in range(1, 64) if radius * 2 ** k < diag)
        ok = next((r for r in ups if works(r)), None)
        if ok is None:
            return ("%s, and so does every radius from %.3g to %.3g: the rolling ball cannot "
                    "follow these edges, whatever the radius%s"
                    % (head, radius / 1024, diag, _failing_set(shape, names, radius, label)))
        bad = ok / 2
    for _ in range(6):
        mid = math.sqrt(ok * bad)
        ok, bad = (mid, bad) if works(mid) else (ok, mid)
    return ("%s; radius %g is too %s here: OCCT accepts %.3g but not %.3g on these "
            "edges" % (head, radius, "large" if ok < radius else "small", ok, bad))


def _failing_set(shape, names, radius, label):
    """Where OCCT's fillet of the edges `names` ([(name, Part.Edge)]) fails at `radius`,
    for messages: '. It fails on L.EdgeA alone' or '. It fails on L.EdgeA, L.EdgeB and
    L.EdgeC together, where they meet at (x, y, z) and ..., though it succeeds at radius
    R on any 2 of them', then, where OCCT's fillet succeeds with the other edges at those
    vertices added (_with_others), '; with the edge from ... selected too, it succeeds'
    ('' for a single edge). Each edge is left out in turn, for good
    where the fillet of the rest still fails (a few milliseconds per fillet), so that
    the fillet succeeds without any one of those that remain. On an L block, a concave
    edge and the two convex edges rising from its ends fail together at every radius,
    and any two of them succeed."""
    if len(names) == 1:
        return ""
    rest = list(names)
    for item in names:
        fewer = [x for x in rest if x is not item]
        if fewer and not _works(shape, [e for _, e in fewer], radius):
            rest = fewer
    listed = ["%s.%s" % (label, n) for n, _ in rest]
    if len(rest) == 1:
        return ". It fails on %s alone" % listed[0]
    meet = []
    for i, (_, e) in enumerate(rest):
        for v in e.Vertexes:
            if any(v.isSame(w) for _, g in rest[i + 1:] for w in g.Vertexes) and \
                    not any(v.isSame(m) for m in meet):
                meet.append(v)
    return (". It fails on %s together%s, though it succeeds at radius %g on %s%s"
            % (listing(listed), ", where they meet at %s" % " and ".join(
                "(%.4g, %.4g, %.4g)" % tuple(v.Point) for v in meet) if meet else "", radius,
               "any %d of them" % (len(rest) - 1) if len(rest) > 2 else "either alone",
               _with_others(shape, [e for _, e in names], meet, radius,
                            "; with %s selected too, it succeeds")))


def _with_others(shape, edges, vertices, radius, phrase):
    """phrase % 'the edge from (x, y, z) to (x, y, z) and ...' for the edges of `shape`
    between two faces that end at any of `vertices` and are not among `edges`, where
    OCCT's fillet at `radius` succeeds with them added to `edges`; '' where there are
    none or it fails. The edges are named by their ends (_by_points): on a compound,
    the names of the edges of one solid are not the user's."""
    others = []
    for v in vertices:
        for e in shape.ancestorsOfType(v, Part.Edge):
            if not e.Degenerated and len(ck.edge_faces(shape, e)) == 2 and \
                    not any(e.isSame(x) for x in edges + others):
                others.append(e)
    if not others or not _works(shape, edges + others, radius):
        return ""
    return phrase % " and ".join(_by_points(shape, e) for e in others)


def _by_points(shape, edge):
    """'the edge from (x, y, z) to (x, y, z)', naming an edge of `shape` by its ends, with
    ' through (x, y, z)', its middle, where its ends do not tell it from every other
    edge: a closed edge, or another edge between the same vertices (on a blind hole's
    floor that a side hole cuts, the floor's edge on the side hole and the arc of the
    hole's wall join the same two points)."""
    ends = [v.Point for v in (edge.Vertexes[0], edge.Vertexes[-1])]
    out = "the edge from (%.4g, %.4g, %.4g) to (%.4g, %.4g, %.4g)" % (
        tuple(ends[0]) + tuple(ends[1]))
    twins = [e for e in shape.Edges if not e.isSame(edge) and not e.Degenerated and
             all(any(v.isSame(w) for w in e.Vertexes) for v in edge.Vertexes)]
    if twins or edge.Vertexes[0].isSame(edge.Vertexes[-1]):
        a, b = edge.ParameterRange
        out += " through (%.4g, %.4g, %.4g)" % tuple(edge.valueAt(0.5 * (a + b)))
    return out


TIGHT_POINTS = 9  # per edge, where tight_arc compares the ball's offset and the curvature


def tight_arc(shape, result, face, radius):
    """Where OCCT's fillet (`result`) vanishes into a face between fillets (`face`)
    because an edge of `shape` near it, which the fillet runs along (it is not an edge
    of the result), curves tighter than the rolling ball can follow:
    '; along EdgeN, which curves at radius rho toward the rolling ball, ...' naming the
    edge whose ball centre runs furthest past its centre of curvature, with the largest
    radius that follows it; '' where none does. At a point p of an edge with outward
    normals n1 and n2, the ball touching both faces has its centre at c = p + t b, with
    b the unit bisector, -(n1 + n2) at a convex edge (into the solid) and n1 + n2 at a
    concave one (out of it), and t = 2 R / |n1 + n2|. Its offset toward the edge's
    centre of curvature, h, grows with R; where h reaches the radius of curvature rho,
    the centres' path has a cusp, as an inward offset of a circle by more than its
    radius, and no fillet follows the edge there (a plate's outline rounded at
    r = 1.367, its bottom edge at R = 1.668: tools/fillet_survey.py --random-plates 40
    --seed 1, part 37)."""
    worst = None  # (h / rho, name, rho, largest radius that follows)
    for k, e in enumerate(shape.Edges):
        faces = shape.ancestorsOfType(e, Part.Face)
        if len(faces) != 2 or e.Degenerated or e.Length == 0.0 or \
                any(e.isSame(x) for x in result.Edges) or \
                e.distToShape(face)[0] > 2.0 * radius:
            continue
        for t in ck.sample_params(e, TIGHT_POINTS):
            try:
                kappa = e.curvatureAt(t)
                if kappa <= 0.0:
                    continue
                p, centre, tangent = e.valueAt(t), e.centerOfCurvatureAt(t), e.tangentAt(t)
            except Part.OCCError:  # no curvature or tangent defined there
                continue
            n1, n2 = frame_at_point(faces[0], p).n, frame_at_point(faces[1], p).n
            n = n1 + n2
            if n.Length < 1e-9:
                continue
            # into the first face, across the edge: the edge is convex where that
            # face falls away behind the second's tangent plane
            d = n1.cross(tangent) * (1e-4 * radius)
            if faces[0].distToShape(Part.Vertex(p - d))[0] < \
                    faces[0].distToShape(Part.Vertex(p + d))[0]:
                d = -d
            b = n * ((-1.0 if d.dot(n2) < 0.0 else 1.0) / n.Length)
            inward = centre - p
            h = (b * (2.0 * radius / n.Length)).dot(inward) / inward.Length
            rho = 1.0 / kappa
            if h >= rho and (worst is None or h / rho > worst[0]):
                worst = (h / rho, "Edge%d" % (k + 1), rho, radius * rho / h)
    if worst is None:
        return ""
    return ("; along %s, which curves at radius %.4g toward the rolling ball, the ball's "
            "centre would run %.3g times that radius in, past its centre of curvature, so "
            "no fillet of this radius follows it there: a radius below %.4g does"
            % (worst[1], worst[2], worst[0], worst[3]))


def vertex_hint(shape, names, face, radius):
    """CORNER_HINT for OCCT's face between two fillets at a vertex, naming the edges
    there not among `names` ([(name, Part.Edge)]) with which OCCT's fillet succeeds
    (_with_others), at the solid's vertex nearest to `face` (the one it stands for);
    '' where there are none."""
    v = min(shape.Vertexes, key=lambda x: face.distToShape(x)[0])
    return _with_others(shape, [e for _, e in names], [v], radius, CORNER_HINT)


def corner_hint(shape, names, own, radius, memo):
    """For a blend kept as OCCT's: where its selected edges `own` ([(name, Part.Edge)])
    end at a vertex where another selected edge (of `names`) ends too, and edges there
    are not selected, with which OCCT's fillet succeeds (_with_others): '; with the
    edge from ... selected too, the fillets meet at a corner there instead (OCCT's
    fillet of them succeeds)'; else ''. Whether C2Blend then fills that corner is not
    tried (a whole fillet more). Where a hole's rim (convex) meets a pocket's floor
    edge (concave) at the pocket's wall, the vertex's third edge, the hole's wall on the
    pocket's wall, is convex: the rim's blend cannot be cut back there (its cut curve
    leaves the surfaces), and with that edge selected the three meet at a corner, which
    C2Blend fills (shapes.hole_through_pocket_wall). memo: {vertices: hint}, so that
    the blends ending at the same vertices try OCCT's fillet once."""
    others = [e for _, e in names if not any(e.isSame(o) for _, o in own)]
    at = []
    for _, e in own:
        for v in e.Vertexes:
            if any(v.isSame(w) for g in others for w in g.Vertexes) and \
                    not any(v.isSame(x) for x in at):
                at.append(v)
    if not at:
        return ""
    key = tuple(sorted(v.hashCode() for v in at))
    if key not in memo:
        memo[key] = _with_others(shape, [e for _, e in names], at, radius, CORNER_HINT)
    return memo[key]
