# SPDX-License-Identifier: LGPL-2.1-or-later
"""A corner where fillets run along an edge that curves tighter than their radius
(diagnose.tight_arc), set back so that a filling replaces OCCT's face there
(fillet.py, corners.py).

A box 20 x 14 x 6 whose vertical edges are rounded at rho = 1.4, its top edge filleted
at R = 1.75: the rolling ball cannot follow a rounded corner, as its centre would run
past the arc's centre of curvature. OCCT ends the fillets of the two sides at a mitre,
where they cross, and puts a face between them that shrinks to a point (the pinch) on
the top face T. That face meets both fillets and the rounded corner's face at an
angle, by up to 0.019 rad. The same happens on a pocket's floor whose corners are
rounded tighter than the floor's fillet. Cut along OCCT's mitre, the blends leave a
hole that no tangent filling closes well: where the mitre meets the wall, the blend is
G2 to the plane wall (no normal curvature there), while the rounded corner's face
beyond curves at 1 / rho along the hole's edge, so no filling's twist matches both.
The best plate turned from the faces by 0.012 rad at the box's corners.

So each fillet is set back. Its blend is cut along an edge of OCCT's face from the
mitre's end P on the wall to a point Q of the trimline on T, SETBACK radii beyond the
mitre's end there. The edge leaves P and reaches Q across the fillet, along its
sections, where the blend is G2 to the plane faces and the filling's corners are
compatible. With the edge arriving at Q along its chord, the hole had a thin wedge at
Q, and the plates turned by up to 9.8e-3 rad. The hole is then bounded by:
- the two cut ends of the blends (ends.py, as slanted ends at a corner patch);
- OCCT's edges on the rounded corner's face, where its face between meets it;
- on T, an edge from one Q to the other (setback.on_top: a cubic Bezier curve in T's
  parameters), leaving each Q along its trimline toward the pinch, with legs as long
  as Q's distance to the pinch.
The filling is tangent to the faces all round, with no crease. With legs of a third
of the chord (as setback.py's first try), every plate rose about 4e-3 above T, where
T's edge turns sharply near the pinch; with a first leg of 0.1 or 0.2 of the chord,
0.03 or 0.014. With the legs reaching the pinch, the plates stay below T, and the box's
four corners turn from the faces by 3.5e-5 to 3.0e-4 rad (setbacks of 0.5 to 1.5 R
alike). The setback is at most REACH of the trimline on T, so that a fillet along a
short wall between two such corners keeps a part (a pocket's 1.3 wall at R = 1.229,
tools/fillet_survey.py --random-plates 40 --seed 64, part 14: with half, the two cuts
crossed).
"""
import Part

from . import setback as sb

SETBACK = 1.0  # radii, along the trimline on top from the mitre's end
REACH = 1.0 / 3.0  # the setback is at most this fraction of the trimline on top
# the reason for keeping the fillets of such a corner left unfilled (then the arc's words)
KEPT = ("OCCT's face between fillets that cannot follow an edge curving tighter than "
        "their radius, kept with them")


class Turn:
    """The setback replacing OCCT's face `face` between two fillets of `radius` in
    `result` (OCCT's fillet; rbfs: its rollingball.RollingBallFaces; original(f): the
    face of the original solid that a face f of `result` lies on), where they follow
    an edge curving tighter than the radius.

    Attributes (as setback.Setback's): tools, the edges bounding the faces around the
    hole anew; creases, [] (the filling is tangent all round); slants, [(rolling-ball
    face, the edge along which its blend is cut)]; kept, the reason its fillets are kept
    when the corner is not filled, ending with `arc` (diagnose.tight_arc's words).
    Raises ValueError, saying why, where OCCT's face does not meet exactly two fillets
    replaced by blends that touch one face in common, or the edges cannot be made."""

    def __init__(self, result, face, rbfs, radius, original, arc):
        fillets, others = [], []
        for e in face.Edges:
            if e.Degenerated:
                continue
            nbrs = [f for f in result.ancestorsOfType(e, Part.Face) if not f.isSame(face)]
            if len(nbrs) != 1:
                raise ValueError("an edge of it has %d neighbours" % len(nbrs))
            rbf = next((r for r in rbfs if r.face.isSame(nbrs[0])), None)
            (others if rbf is None else fillets).append((e, rbf))
        if len(fillets) != 2 or any(r.corner for _, r in fillets):
            raise ValueError("it meets %d fillets, not 2 replaced by blends" % len(fillets))
        (ea, a), (eb, b) = fillets
        tops = [f for _, f in a.contacts if any(f.isSame(g) for _, g in b.contacts)]
        if len(tops) != 1:
            raise ValueError("its fillets touch %d faces in common, not 1" % len(tops))
        top = tops[0]
        (sa, qa, da), (sb_, qb, db) = [_cut(r, e, top, radius) for e, r in ((ea, a), (eb, b))]
        pinch = min((v.Point for v in face.Vertexes),
                    key=lambda p: (p - qa).Length + (p - qb).Length)
        chord = (qb - qa).Length
        if chord <= 1e-9 * radius:
            raise ValueError("its fillets' cuts reach the face they share at one point")
        legs = [((pinch - qa).Length / chord, (pinch - qb).Length / chord)]
        self.tools = [sb.on_top(top, original(top), qa, da, qb, -db, pinch,
                                 sb.CLEAR * radius, legs)] + [e for e, _ in others]
        self.creases = []
        self.slants = [(a.face, sa), (b.face, sb_)]
        self.kept = KEPT + arc


def _cut(rbf, mitre, top, radius):
    """(the edge along which the blend replacing the rolling-ball face `rbf` is cut, its
    end Q on `top`, the unit tangent there of the trimline on top pointing toward
    OCCT's `mitre` edge on the face). The edge runs on the face from the mitre's end P
    on the other face (the wall) to Q, SETBACK radii (at most REACH of the trimline on
    top) beyond the mitre's end on top, leaving P and reaching Q across the fillet.
    Raises ValueError where the fillet has no length or width there."""
    lo, hi = rbf.range
    at = [(rbf.along_of(v.Point), v.Point) for v in mitre.Vertexes]
    mid = sum(a for a, _ in at) / len(at)
    near_lo = abs(mid - lo) < abs(hi - mid)
    (c_top, c_wall) = [c for _, c in sorted(
        zip(rbf.contacts, rbf.across), key=lambda x: not x[0][1].isSame(top))]
    # the mitre's ends: P on the wall, and the one on top
    (a_p, p), (a_top, _) = sorted(at, key=lambda x: (rbf.point(x[0], c_wall) - x[1]).Length)
    # the trimline on top runs from a_top to its other end, a_end
    e_top = next(e for (e, f) in rbf.contacts if f.isSame(top))
    a_end = (max if near_lo else min)(rbf.along_of(v.Point) for v in e_top.Vertexes)
    speed = rbf.derivative(a_top, c_top, True).Length
    if speed <= 0.0:
        raise ValueError("a fillet's surface has no length along its trimline there")
    step = min(SETBACK * radius / speed, REACH * abs(a_end - a_top))
    a_q = a_top + step if near_lo else a_top - step
    q = rbf.point(a_q, c_top)
    sign = 1.0 if c_top > c_wall else -1.0
    leave, arrive = [rbf.derivative(a, c, False) * sign for a, c in ((a_p, c_wall), (a_q, c_top))]
    if min(leave.Length, arrive.Length) <= 0.0:
        raise ValueError("a fillet's surface has no width across at its cut")
    leave.normalize()
    arrive.normalize()
    cut = sb.bezier(rbf.face, p, leave, q, arrive)
    d = rbf.derivative(a_q, c_top, True)
    if d.Length <= 0.0:
        raise ValueError("a fillet's surface has no length along its trimline there")
    d.normalize()
    return cut, q, d * (-1.0 if near_lo else 1.0)
