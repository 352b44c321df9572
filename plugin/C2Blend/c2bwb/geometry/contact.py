# SPDX-License-Identifier: LGPL-2.1-or-later
"""The exact rolling-ball contact on the true faces (MATH.md section 7).

OCCT's rolling-ball face is exact only on simple faces (a torus on a cylinder and a
plane). Elsewhere it is a B-spline approximation, C1 at its knots, and its contact
edges lie up to 2e-3 (pipe tee, R = 1) from the true contact, tangentially along the
faces. Trimlines sampled from it are neither exact nor smooth, so the blend cannot be
G2 to 1e-6. Here OCCT's face only guides; the contact itself is solved on the two
faces F1 and F2 that the ball touches.

The ball's centre c and its contact points S1(u1, v1), S2(u2, v2) satisfy

    c = S1 + g1 N1 = S2 + g2 N2,      g_i = +R or -R (the side the ball is on),
    (c - m(a)) . t0(a) = 0,

where m(a) and t0(a) are the point and unit tangent of the guide's mid-line at its
along-parameter a. Newton's method on these four equations in (u1, v1, u2, v2) gives
the contact to rounding. The centres form the spine; samples are uniform in the
spine's own arc length, which is intrinsic, so the trimlines are as smooth as the faces
whatever OCCT's approximation. The arc length is integrated by adaptive Gauss
quadrature on the guide's knot spans (the speed |dc/da| is analytic inside each span):

    |dc/da| = (m' . t0 - (c - m) . t0') / (t . t0),   t = unit spine tangent ~ N1 x N2.

On each final subinterval of the quadrature, the speed at its ten Gauss nodes (five
per half) is interpolated by a polynomial of degree 9, whose integral is the arc length
inside it: a sample's guide parameter is found on that polynomial, and the contact is
solved there once.

Where the guide is only C0 (a knot of full multiplicity, or the joint between two faces
of a chain) its plane turns and the centre jumps along the spine; the spans are joined
by the measured jump, so the samples stay uniform on the spine itself.
"""
import bisect
import math

import numpy as np

from .rollingball import Section
from .surface import Frame, angle

MAX_NEWTON = 30
NEWTON_DONE = 1e-10  # relative step after which one more Newton step is below rounding
SUB_PER_SPAN = 2  # Gauss subintervals per knot span of the guide along the fillet
MIN_SUB = 4  # ... and at least this many per section (each is halved at least once)
QUAD_REL = 1e-12  # a subinterval is halved until its halves' integrals sum to its own
# within this fraction of the section's arc length (_refine) ...
MAX_HALVINGS = 12  # ... at most this many times
# a guide's knot this close to a section's end (a fraction of the section) is its end:
# OCCT's fillet of a slot's chamfered rim put one 1 ulp before the end, and the piece
# between, of length 2e-15, looked like a ball's centre standing still
KNOT_AT_END = 1e-9
TANGENT = math.radians(1.0)  # faces closer than this to tangent: a reason Newton fails
WARM = 0.05  # start Newton from the last solution within this fraction of the section

# 5-point Gauss-Legendre nodes and weights on [0, 1]
_GL = [(0.5 - 0.5 * x, 0.5 * w) for x, w in (
    (-0.9061798459386640, 0.2369268850561891), (-0.5384693101056831, 0.4786286704993665),
    (0.0, 0.5688888888888889), (0.5384693101056831, 0.4786286704993665),
    (0.9061798459386640, 0.2369268850561891))]


class ContactError(Exception):
    """The exact contact cannot be traced (Newton failed, or the faces are parallel)."""


def _normal_frame(face, u, v, surface):
    """Point, S_u, S_v, unit normal (oriented like the face) and its u and v derivatives
    (surface.Frame; surface is face.Surface). Raises ContactError where the face is
    degenerate."""
    try:
        f = Frame(face, u, v, surface)
    except ValueError as ex:
        raise ContactError("the face is degenerate: %s" % ex) from None
    nu, nv = f.normal_derivatives()
    return f.p, f.su, f.sv, f.n, nu, nv


def _extended(sections, extend):
    """The chain's sections, the first started extend[0] earlier and the last ended
    extend[1] later (lengths along the guide's mid-line, converted to guide parameter
    by its speed at the end)."""
    out = list(sections)
    for i, length in ((0, extend[0]), (-1, extend[1])):
        if length <= 0.0:
            continue
        sec = out[i]
        a = sec.a_start if i == 0 else sec.a_end
        da = length / sec.rbf.derivative(a, sec.cm, True).Length
        if (sec.a_end > sec.a_start) == (i == 0):
            da = -da
        out[i] = Section(sec.rbf, sec.a_start + (da if i == 0 else 0.0),
                          sec.a_end + (da if i != 0 else 0.0), sec.c1, sec.c2, sec.sides)
    return out


class _Piece:
    """A stretch of one section between knots of its guide: k (the section), nodes
    [(a, spine arc length from the piece's start)] at its Gauss subintervals' ends,
    arcs [the arc length from the start of a final subinterval of the quadrature, a
    numpy series in a, or None where the speed is not finite], one per interval
    between nodes (a subinterval's serves its two halves), length, and start (arc
    length from the chain's start, set by Contact._join)."""

    def __init__(self, k, nodes, arcs):
        self.k, self.nodes, self.arcs, self.length = k, nodes, arcs, nodes[-1][1]
        self.start, self.c_end, self.t_end = 0.0, None, None


class Contact:
    """Exact contact of a ball of radius R rolling on a FilletChain's two sides.

    pairs(n) gives n samples uniform in the spine's arc length, as
    trimlines.pair_rows takes them. extend: (start, end), lengths (model units, along
    the guide's mid-line) by which an open chain is traced past its ends, on the
    faces' underlying surfaces (ends.py trims the blend back). arc_length: False for a
    caller that only solves at guide parameters it chooses (solve()): the spine's arc
    length (pieces, length, starts), which pairs() and at_length() need, is then not
    integrated. Raises ContactError where it cannot."""

    def __init__(self, chain, radius, extend=(0.0, 0.0), arc_length=True):
        self.chain, self.radius = chain, radius
        self.f1, self.f2 = chain.sides
        self.s1, self.s2 = self.f1.Surface, self.f2.Surface
        self.sections = _extended(chain.sections, extend)
        self.signs = None
        self.solved = [([], []) for _ in self.sections]  # per section: sorted a, solutions
        self.cache = {}  # arc length -> contact, shared by pairs(n) and pairs(2n)
        # (ratio, point): the least ratio of the ball's centre's speed to its faster
        # contact point's, near 0 where the radius nears a face's curvature radius
        # (1 - R / rho on a wall of radius of curvature rho), and where it was seen
        self.slowest = (math.inf, None)
        if arc_length:
            self.pieces = [p for k in range(len(self.sections)) for p in self._pieces(k)]
            self.length = self._join(self.pieces, chain.closed)
            self.starts = [p.start for p in self.pieces]

    def _guess(self, sec, a):
        q1, q2 = sec.rbf.point(a, sec.c1), sec.rbf.point(a, sec.c2)
        return list(self.s1.parameter(q1)) + list(self.s2.parameter(q2))

    def _warm(self, k, a):
        """Newton's start at guide parameter a: the solution at the nearest parameter
        solved before, if within WARM of the section, else OCCT's contact points."""
        sec, (keys, xs) = self.sections[k], self.solved[k]
        i = bisect.bisect_left(keys, a)
        near = [j for j in (i - 1, i) if 0 <= j < len(keys)]
        if near:
            j = min(near, key=lambda q: abs(keys[q] - a))
            if abs(keys[j] - a) <= WARM * abs(sec.a_end - sec.a_start):
                return list(xs[j])
        return self._guess(sec, a)

    def _signs(self, x):
        """(g1, g2): the ball's side of each face, from OCCT's contact points x."""
        p1, _, _, n1, _, _ = _normal_frame(self.f1, x[0], x[1], self.s1)
        p2, _, _, n2, _, _ = _normal_frame(self.f2, x[2], x[3], self.s2)
        r = self.radius
        return min(((a * r, b * r) for a in (1, -1) for b in (1, -1)),
                   key=lambda g: ((p1 + n1 * g[0]) - (p2 + n2 * g[1])).Length)

    def solve(self, k, a):
        """The contact in section k at guide parameter a: (p1, p2, c, t, speed, x) with
        t the unit spine tangent (oriented like the section), speed = |dc/da| signed so
        that arc length grows along the section, and x = (u1, v1, u2, v2)."""
        sec = self.sections[k]
        r, s = sec.rbf, sec.rbf.surface
        m, d1 = r.point(a, sec.cm), r.derivative(a, sec.cm, True)
        d2 = s.getDN(a, sec.cm, 2, 0) if r.along == 0 else s.getDN(sec.cm, a, 0, 2)
        dl = d1.Length
        t0 = d1 * (1.0 / dl)
        t0p = (d2 - t0 * t0.dot(d2)) * (1.0 / dl)
        p1, p2, c, t, x = self._newton(self._warm(k, a), m, t0)
        keys, xs = self.solved[k]
        i = bisect.bisect_left(keys, a)
        keys.insert(i, a)
        xs.insert(i, x)
        speed = (d1.dot(t0) - (c - m).dot(t0p)) / t.dot(t0)
        return p1, p2, c, t, (speed if sec.a_end >= sec.a_start else -speed), x

    def _newton(self, x, m, t0):
        """The contact whose ball centre c lies in the plane (c - m) . t0 = 0, by
        Newton's method from x = (u1, v1, u2, v2): (p1, p2, c, t, x), t the unit spine
        tangent oriented like t0."""
        if self.signs is None:
            self.signs = self._signs(x)
        start = x
        g1, g2 = self.signs
        for _ in range(MAX_NEWTON):
            p1, s1u, s1v, n1, n1u, n1v = _normal_frame(self.f1, x[0], x[1], self.s1)
            p2, s2u, s2v, n2, n2u, n2v = _normal_frame(self.f2, x[2], x[3], self.s2)
            c = p1 + n1 * g1
            d = c - (p2 + n2 * g2)
            cols = (s1u + n1u * g1, s1v + n1v * g1, -(s2u + n2u * g2), -(s2v + n2v * g2))
            jac = np.array([[q.x for q in cols], [q.y for q in cols], [q.z for q in cols],
                            [cols[0].dot(t0), cols[1].dot(t0), 0.0, 0.0]])
            try:
                dx = np.linalg.solve(jac, [-d.x, -d.y, -d.z, -(c - m).dot(t0)])
            except np.linalg.LinAlgError:
                raise ContactError("the rolling-ball contact is singular near (%.6g, %.6g, "
                                   "%.6g)" % (m.x, m.y, m.z)) from None
            x = [x[i] + dx[i] for i in range(4)]
            if max(abs(q) for q in dx) <= NEWTON_DONE * (1.0 + max(abs(q) for q in x)):
                break  # quadratic convergence: the error left is ~ step^2
        else:
            raise ContactError("Newton's method for the exact rolling-ball contact did not "
                               "converge near (%.6g, %.6g, %.6g)%s"
                               % (m.x, m.y, m.z, self._tangent_words(start)))
        p1, _, _, n1, _, _ = _normal_frame(self.f1, x[0], x[1], self.s1)
        p2 = self.s2.value(x[2], x[3])
        c = p1 + n1 * g1
        t = (p1 - c).cross(p2 - c)
        if t.Length <= 1e-12 * self.radius ** 2:
            raise ContactError("the faces are parallel at the contact near (%.6g, %.6g, %.6g)"
                               % (c.x, c.y, c.z))
        t.normalize()
        return p1, p2, c, (-t if t.dot(t0) < 0.0 else t), x

    def _tangent_words(self, x):
        """Why Newton's method may fail at contact parameters x (OCCT's contact, or a
        solution nearby): ", where the faces are within A degrees of tangent, ..." when
        their normals there differ by less than TANGENT, else ""."""
        try:
            n1 = _normal_frame(self.f1, x[0], x[1], self.s1)[3]
            n2 = _normal_frame(self.f2, x[2], x[3], self.s2)[3]
        except ContactError:
            return ""
        turn = angle(n1, n2)
        if turn >= TANGENT:
            return ""
        return (", where the faces are within %.2g degrees of tangent: there a ball "
                "touching both has no single contact, and no blend runs up to the tangent "
                "joint" % math.degrees(turn))

    def _gauss(self, k, a0, a1):
        """Spine arc length from guide parameter a0 to a1 in section k (Gauss), and
        [(a, speed)] at the Gauss nodes; notes the slowest the centre moves (slowest)."""
        nodes = [(a, self.solve(k, a)) for a in (a0 + (a1 - a0) * x for x, _ in _GL)]
        for (_, x), (_, y) in zip(nodes, nodes[1:]):
            # the ball's centre against its faster contact point, between two nodes
            moved = max((y[0] - x[0]).Length, (y[1] - x[1]).Length)
            if moved > 0.0 and (y[2] - x[2]).Length < self.slowest[0] * moved:
                self.slowest = ((y[2] - x[2]).Length / moved, (x[2] + y[2]) * 0.5)
        speeds = [(a, sol[4]) for a, sol in nodes]
        return (a1 - a0) * sum(w * v for (_, w), (_, v) in zip(_GL, speeds)), speeds

    def _pieces(self, k):
        """Section k cut at the interior knots of its guide: [Piece]. OCCT's fillet
        surfaces are only C0 or C1 at some knots (degree 14, multiplicity 14 on a boss
        on a loft), where the guide's section plane turns: the ball's centre then jumps
        along the spine (by 1.7e-6 there), so arc length is integrated per piece and
        the pieces are joined by their measured gaps (_join)."""
        sec = self.sections[k]
        s = sec.rbf.surface
        knots = getattr(s, "getUKnots" if sec.rbf.along == 0 else "getVKnots", list)()
        lo, hi = sorted((sec.a_start, sec.a_end))
        near = KNOT_AT_END * (hi - lo)
        spans = sorted(set([lo, hi] + [q for q in knots if lo + near < q < hi - near]))
        per = max(SUB_PER_SPAN, -(-MIN_SUB // (len(spans) - 1)))
        spans = list(zip(spans, spans[1:]))
        if sec.a_end < sec.a_start:
            spans = [(b, a) for a, b in reversed(spans)]
        subs = [[(a + (b - a) * i / per, a + (b - a) * (i + 1) / per) for i in range(per)]
                for a, b in spans]
        wholes = [[self._gauss(k, a0, a1)[0] for a0, a1 in row] for row in subs]
        tol = QUAD_REL * sum(abs(w) for row in wholes for w in row)
        out = []
        for (a, _), row, row_wholes in zip(spans, subs, wholes):
            nodes, arcs = [(a, 0.0)], []
            for (a0, a1), whole in zip(row, row_wholes):
                self._refine(k, a0, a1, whole, nodes, arcs, tol, 0)
            out.append(_Piece(k, nodes, arcs))
        return out

    def _refine(self, k, a0, a1, whole, nodes, arcs, tol, depth):
        """Append the arc-length nodes of [a0, a1] (whole: its Gauss integral) to nodes,
        halving it until the halves' integrals sum to whole within tol (a length), and
        the arc length inside each final subinterval to arcs (see _Piece). Inside a
        knot span the speed is analytic, but OCCT's guides vary fast near clustered
        knots (a degree-14 face whose spans shrink to 1e-3 of the fillet at one end): a
        fixed rule misplaced a sample by 1e-7 there, and the data lost 3 digits."""
        m = 0.5 * (a0 + a1)
        (left, at_left), (right, at_right) = self._gauss(k, a0, m), self._gauss(k, m, a1)
        if depth >= MAX_HALVINGS or abs(left + right - whole) <= tol:
            # degree 9 through the ten nodes: each half's Gauss rule integrates it
            # exactly, so its integral passes through the nodes' arc lengths (the mean
            # speed where the subinterval is a few units of rounding wide, or none,
            # and its nodes coincide: a jump of the speed halved MAX_HALVINGS times, a
            # section of zero length)
            a, v = zip(*(at_left + at_right))
            if not all(math.isfinite(q) for q in v):
                arc = None  # where the centre stops (_at_length says so)
            elif len(set(a)) == len(a):
                arc = np.polynomial.Chebyshev.fit(a, v, 9, domain=sorted((a0, a1)))
                arc = arc.integ(lbnd=a0)
            else:
                mean = sum(v) / len(v)
                arc = np.polynomial.Polynomial([-mean * a0, mean])
            nodes.append((m, nodes[-1][1] + left))
            nodes.append((a1, nodes[-1][1] + right))
            arcs += [arc, arc]
            return
        self._refine(k, a0, m, left, nodes, arcs, tol, depth + 1)
        self._refine(k, m, a1, right, nodes, arcs, tol, depth + 1)

    def _end(self, piece, at_end):
        """(c, t): the ball's centre and spine tangent at the start or end of a piece,
        from its own side of a knot (evaluated 1e-7 of the span inside, moved back
        along the spine by speed times that offset)."""
        (a0, _), (a1, _) = piece.nodes[0], piece.nodes[-1]
        end, inward = (a1, a0 - a1) if at_end else (a0, a1 - a0)
        _, _, c, t, speed, _ = self.solve(piece.k, end + 1e-7 * inward)
        return c + t * ((1e-7 if at_end else -1e-7) * abs(inward) * speed), t

    def _join(self, pieces, closed):
        """Set each piece's start (spine arc length) and return the whole length (a
        closed spine's up to where it returns to its start): a piece starts where the
        previous one ends plus the gap (c_start - c_end) . t_end between them, which
        OCCT's faces leave at knots and between the faces of a chain and a closed face's
        ends. A sample that falls in a gap (a positive one) is solved in the plane
        across the spine at that arc length (at_length)."""
        acc = 0.0
        for i, piece in enumerate(pieces):
            piece.start = acc
            acc += piece.length
            if i + 1 < len(pieces) or closed:
                piece.c_end, piece.t_end = self._end(piece, True)
                c_next, _ = self._end(pieces[(i + 1) % len(pieces)], False)
                acc += (c_next - piece.c_end).dot(piece.t_end)
        return acc

    def at_length(self, s):
        """The contact at spine arc length s from the chain's start (see _pieces)."""
        if s not in self.cache:
            self.cache[s] = self._at_length(s)
        return self.cache[s]

    def _at_length(self, s):
        i = max(bisect.bisect_right(self.starts, s) - 1, 0)
        piece = self.pieces[i]
        if s > piece.start + piece.length and i + 1 < len(self.pieces) + self.chain.closed:
            # in the gap after this piece: in the plane across the spine at s
            m = piece.c_end + piece.t_end * (s - piece.start - piece.length)
            x = self._warm(piece.k, piece.nodes[-1][0])
            return self._newton(x, m, piece.t_end)
        k, s = piece.k, min(max(s - piece.start, 0.0), piece.length)
        lengths = [q[1] for q in piece.nodes]
        j = min(max(bisect.bisect_right(lengths, s) - 1, 0), len(lengths) - 2)
        (a0, l0), (a1, l1) = piece.nodes[j], piece.nodes[j + 1]
        arc = piece.arcs[j]
        if not l1 > l0 or arc is None:  # the centre stands still: a cusp of its curve
            c = self.solve(k, a0)[2]
            raise ContactError("the rolling ball's centre stops near (%.6g, %.6g, %.6g): the "
                               "radius is about a face's curvature radius there, where its "
                               "offset has a cusp; a smaller radius avoids it"
                               % (c.x, c.y, c.z))
        base = l0 - arc(a0)  # arc length where this final subinterval starts
        speed = arc.deriv()
        a = a0 + (a1 - a0) * (s - l0) / (l1 - l0)
        for _ in range(MAX_NEWTON):  # on the polynomial: no contact solved
            step = (base + arc(a) - s) / speed(a)
            a = min(max(a - step, min(a0, a1)), max(a0, a1))
            if abs(step) <= NEWTON_DONE * (1.0 + abs(a)):
                break
        p1, p2, c, t, _, x = self.solve(k, a)
        return p1, p2, c, t, x

    def pairs(self, n):
        """n samples uniform in spine arc length (the end point excluded on a closed
        chain): (frame1, t, p2 - p1, frame2, t, p1 - p2) each, with the sides' frames
        at the contact points, as trimlines.pair_rows takes them. The cross direction on
        each face is then t x N, in the ball's plane."""
        span = self.length / (n if self.chain.closed else n - 1)
        out = []
        for j in range(n):
            p1, p2, _, t, x = self.at_length(min(j * span, self.length))
            out.append((Frame(self.f1, x[0], x[1], self.s1), t, p2 - p1,
                        Frame(self.f2, x[2], x[3], self.s2), t, p1 - p2))
        return out
