# SPDX-License-Identifier: LGPL-2.1-or-later
"""Where the faces a fillet runs along lose smoothness: the knot lines of their surfaces,
and the points where the exact contact crosses them.

A cubic B-spline is only C2 at its knots: its third derivative jumps there, and so do
the boundary data sampled along a contact that crosses a knot line. The v-series of a
whole chain then converge only algebraically. On a prism whose side is a cubic
interpolating spline through 7 points, 1024 samples leave 4e-6 (relative), too rough for
a G2 blend. Between two crossings the data are analytic. So a chain whose data are too
rough is cut at the crossings into runs, as a chain whose side changes face is
(rollingball.Run), and each run gets the pointwise blend (solve.solve_runs).

Where a side changes face, the runs must end where the exact contact crosses the edge
between the two faces, not at OCCT's split between its fillet faces: on B-spline walls
OCCT splits 1e-2 away from it, and the two runs' end sections would not meet
(at_face_changes). Likewise, where three fillets meet at a corner, each ends where the
exact ball also touches the corner's third face (at_corner_balls).
"""
import math

import Part

from .contact import Contact
from .rollingball import Run, Section
from .surface import frame_at_point

MAX_ROOT = 60  # iterations of the bracketed root finder (each halves the bracket at worst)


def knot_lines(surface):
    """([u knots], [v knots], (u period, v period)): the parameters of surface's knot
    lines inside its range, where it may be less smooth than elsewhere (a B-spline
    surface's own knots; the knots of the B-spline curve that an extrusion sweeps in u
    or a revolution in v), and its periods (None if not periodic). A periodic spline's
    first knot is a knot line too, and so is the seam of a spline closed but not
    periodic in a direction, whose period is then its range: its ends meet at a
    clamped knot, across which it may be only G1 (a loft through closed curves from
    FreeCAD 0.20's periodic interpolate, whose first knot is double: around a loft
    through such circles of 24 points, radius 4 to 5.5, the curvature jumps from 0.193
    to 0.173 at its seam)."""
    def lines(knots, periodic, closed):
        if periodic or closed:
            return list(knots[:-1]), None if periodic else knots[-1] - knots[0]
        return list(knots[1:-1]), None

    periods = [surface.UPeriod() if surface.isUPeriodic() else None,
               surface.VPeriod() if surface.isVPeriodic() else None]
    if isinstance(surface, Part.BSplineSurface):
        (ku, pu), (kv, pv) = (lines(surface.getUKnots(), surface.isUPeriodic(),
                                    surface.isUClosed()),
                              lines(surface.getVKnots(), surface.isVPeriodic(),
                                    surface.isVClosed()))
        return ku, kv, (periods[0] or pu, periods[1] or pv)
    basis = getattr(surface, "BasisCurve", None)
    if isinstance(basis, Part.BSplineCurve):
        k, p = lines(basis.getKnots(), basis.isPeriodic(), basis.isClosed())
        if isinstance(surface, Part.SurfaceOfExtrusion):
            return k, [], (periods[0] or p, periods[1])
        if isinstance(surface, Part.SurfaceOfRevolution):
            return [], k, (periods[0], periods[1] or p)
    return [], [], tuple(periods)


def curvature_jump(face, p, near=1e-7):
    """The largest jump of the principal curvatures of face's surface across a knot line
    or seam (knot_lines) passing within `near` (times its period or range) of point p on
    it, compared at that distance on either side, relative to the largest of them or to
    1 / the face's diagonal; 0.0 where none passes. Where it exceeds the
    finite-difference noise (about 1e-7 across a cubic's simple knot), the face itself
    is only G1 there (a double knot of a cubic), and no fillet along it can be G2 to it
    on both sides of p."""
    s = face.Surface
    uv = list(s.parameter(p))
    ku, kv, periods = knot_lines(s)
    bounds = s.bounds()
    floor = 1.0 / face.BoundBox.DiagonalLength
    worst = 0.0
    for q, knots in enumerate((ku, kv)):
        period, lo = periods[q], bounds[2 * q]
        eps = near * (period or (bounds[2 * q + 1] - lo))
        for k in knots:
            d = uv[q] - k - (period * round((uv[q] - k) / period) if period else 0.0)
            if abs(d) > eps:
                continue
            sides = []
            for x in (k - eps, k + eps):
                if period and x < lo:  # a seam: its other side is a period on
                    x += period
                at = list(uv)
                at[q] = x
                sides.append([s.curvature(at[0], at[1], kind) for kind in ("Min", "Max")])
            scale = max(floor, *(abs(x) for side in sides for x in side))
            worst = max(worst, *(abs(a - b) / scale for a, b in zip(*sides)))
    return worst


def side_jump(points, sides):
    """The largest curvature_jump of the side faces at points of the trimlines, each
    taken on the side face nearest to it."""
    return max(curvature_jump(min(sides, key=lambda f: f.distToShape(Part.Vertex(p))[0]), p)
               for p in points)


def _crossed(x0, x1, knots, period):
    """The knots (shifted by whole periods) strictly between parameters x0 and x1."""
    lo, hi = min(x0, x1), max(x0, x1)
    out = []
    for k in knots:
        if period:
            k += period * ((lo - k) // period + 1)  # the first copy above lo
        if lo < k < hi:
            out.append(k)
    return out


def _on_knot(x, knots, period, near):
    """True when parameter x lies within near of a knot (or of its copy a whole number
    of periods away)."""
    return any(abs(x - k - (period * round((x - k) / period) if period else 0.0)) <= near
               for k in knots)


def _root(f, a0, a1):
    """a in [a0, a1] with f(a) = 0, where f(a0) and f(a1) differ in sign: the Illinois
    variant of the false position, to rounding."""
    f0, f1 = f(a0), f(a1)
    side = 0
    for _ in range(MAX_ROOT):
        a = (a0 * f1 - a1 * f0) / (f1 - f0)
        if not min(a0, a1) < a < max(a0, a1):
            a = 0.5 * (a0 + a1)
        fa = f(a)
        if fa == 0.0 or abs(a1 - a0) <= 4e-16 * (1.0 + abs(a)):
            return a
        if (fa > 0) == (f1 > 0):
            a1, f1 = a, fa
            if side == 1:
                f0 *= 0.5
            side = 1
        else:
            a0, f0 = a, fa
            if side == -1:
                f1 *= 0.5
            side = -1
    return a


def crossings(contact, k):
    """(on, cuts): whether the exact contact at the start of section k of contact lies
    on a knot line of either side face (a closed face's seam may), and the guide
    parameters inside the section at which it crosses one, in the section's direction.
    The cuts are found between the parameters Contact already solved (its arc-length
    nodes, several per knot span of the guide), each to rounding by a bracketed root
    finder on the contact parameter minus the knot."""
    sec = contact.sections[k]
    x_start = contact.solve(k, sec.a_start)[5]
    contact.solve(k, sec.a_end)
    keys, xs = contact.solved[k]
    pts = list(zip(keys, xs))
    out, on = [], False
    for side, face in enumerate((contact.f1, contact.f2)):
        lines = knot_lines(face.Surface)
        for j in (0, 1):
            knots, period = lines[j], lines[2][j]
            if not knots:
                continue
            q = 2 * side + j
            near = 1e-9 * (period or max(knots) - min(knots) or 1.0)
            on = on or _on_knot(x_start[q], knots, period, near)
            for (a0, x0), (a1, x1) in zip(pts, pts[1:]):
                if period and abs(x1[q] - x0[q]) > 0.5 * period:
                    continue  # a projection a period away, not a crossing
                for kn in _crossed(x0[q], x1[q], knots, period):
                    # the contact parameter's copy near x0 (a periodic one may differ
                    # by a period from call to call)
                    def f(a, q=q, kn=kn, ref=x0[q]):
                        x = contact.solve(k, a)[5][q]
                        if period:
                            x += period * round((ref - x) / period)
                        return x - kn
                    out.append(_root(f, a0, a1))
    out.sort(reverse=sec.a_end < sec.a_start)
    lo, hi = sorted((sec.a_start, sec.a_end))
    tol = 1e-9 * (hi - lo)
    cuts = []
    for a in out:  # a contact through a knot of both faces at once: one cut
        if lo + tol < a < hi - tol and all(abs(a - b) > tol for b in cuts):
            cuts.append(a)
    return on, cuts


MAX_SHIFT = 0.5  # a junction moves by at most this fraction of its runs' end sections
BALL_GAP = 1e-2  # OCCT's corner ball is this close (times R) to the exact one, or unrelated


def _secant(f, a0, a1):
    """a with f(a) = 0 by the secant method from a0 and a1 (no bracket: the root may lie
    outside the guide's range), to 1e-12 relative (f, an exact contact solved by
    Newton's method, is noisy at rounding); None if it does not converge."""
    f0, f1 = f(a0), f(a1)
    for _ in range(MAX_ROOT):
        if f1 == f0:
            return a1 if f1 == 0.0 else None
        a0, a1, f0 = a1, a1 - f1 * (a1 - a0) / (f1 - f0), f1
        if abs(a1 - a0) <= 1e-12 * (1.0 + abs(a1)):
            return a1
        f1 = f(a1)
    return None


def _shared_edge(f, g, near):
    """The edge of face f that face g shares with it nearest to the point near, or None."""
    common = [e for e in f.Edges if any(e.isSame(x) for x in g.Edges)]
    return min(common, key=lambda e: e.distToShape(near)[0], default=None)


def _end_where(run, at_end, radius, f, near=math.inf):
    """The guide parameter of the section of run at its end (at_end) or start at which
    f(exact contact: p1, p2, c, t) is 0, by the secant method from OCCT's end, or None
    when not found within MAX_SHIFT of that section, or when |f| at OCCT's end exceeds
    near (a length, like f)."""
    sec = run.sections[-1 if at_end else 0]
    contact = Contact(Run([sec], (True, True), ends=[], corners=[]), radius, arc_length=False)
    a0 = sec.a_end if at_end else sec.a_start
    span = sec.a_end - sec.a_start
    g = lambda a: f(*contact.solve(0, a)[:4])  # noqa: E731
    if abs(g(a0)) > near:
        return None
    a = _secant(g, a0, a0 - 1e-3 * span if at_end else a0 + 1e-3 * span)
    if a is None or abs(a - a0) > MAX_SHIFT * abs(span):
        return None
    return a


def _crossing(run, at_end, side, edge, radius):
    """The guide parameter of the section of run at its end (at_end) or start at which
    the exact contact on side `side` crosses edge (the edge's curve, extended), or None.
    The offset of the contact from that curve along the spine changes sign there."""
    curve = edge.Curve

    def offset(p1, p2, c, t):
        p = (p1, p2)[side]
        return (p - curve.value(curve.parameter(p))).dot(t)

    return _end_where(run, at_end, radius, offset)


def _ball_gap(face):
    """g(p1, p2, c, t): the signed distance of a ball centre c from the surface of
    `face` (along its normal, oriented like the face)."""
    def gap(p1, p2, c, t):
        f = frame_at_point(face, c)
        return (c - f.p).dot(f.n)

    return gap


def at_corner_balls(run, at_ends, radius):
    """run (a chain or Run) with each end at a corner patch where three fillets meet
    (ends.ChainEnd.ball set) moved to where the exact ball also touches the third face:
    the ball that ends all three fillets, so that their blends' end sections meet at
    its contact points. OCCT's corner lies there on analytic faces but 1e-4 away on a
    B-spline wall (R = 1), which left a hole with a 1e-4 edge that OCCT's plate filling
    could not fill. An end stays where it is when OCCT's end ball is more than
    BALL_GAP * radius from touching the third face (a corner where convex and concave
    edges meet: no ball touches the three faces there; one found anyway lay 0.35 mm
    along a boss's rim at R = 1 and left the blends unsewable), or when that ball is
    not found within MAX_SHIFT of its section. Raises contact.ContactError."""
    for end in at_ends:
        if end.ball is None:
            continue
        gap = _ball_gap(end.ball)
        a = _end_where(run, end.at == 1, radius, lambda *x: abs(gap(*x)) - radius,
                       near=BALL_GAP * radius)
        if a is not None:
            run = _moved(run, -end.at, a)
    return run


def at_face_changes(runs, closed, radius):
    """The runs of a chain whose side changes face, with each junction where a side
    changes face moved to where the exact contact on that side crosses the edge between
    the two faces: both runs' end sections are then the same ball, touching both faces
    there. OCCT's split between its fillet faces (where the runs end) lies on that edge
    for analytic faces but up to 1e-2 away on B-spline faces. A junction stays where it
    is when the faces share no edge, or when the crossing is not found within
    MAX_SHIFT of the end sections. Returns [Run]. Raises contact.ContactError."""
    runs = list(runs)
    pairs = list(zip(range(len(runs)), range(1, len(runs)))) + \
        ([(len(runs) - 1, 0)] if closed and len(runs) > 1 else [])
    for i, j in pairs:
        a, b = runs[i], runs[j]
        side = next((s for s in (0, 1) if not a.sides[s].isSame(b.sides[s])), None)
        if side is None:
            continue  # a cut at a knot line: the side stays on its face
        sec = a.sections[-1]
        near = Part.Vertex(sec.rbf.point(sec.a_end, (sec.c1, sec.c2)[side]))
        edge = _shared_edge(a.sides[side], b.sides[side], near)
        if edge is None:
            continue
        end, start = _crossing(a, True, side, edge, radius), _crossing(b, False, side, edge,
                                                                        radius)
        if end is None or start is None:
            continue
        runs[i] = _moved(a, -1, end)
        runs[j] = _moved(b, 0, start)
    return runs


def _moved(run, k, a):
    """run with the end (k = -1) or start (k = 0) of its end section moved to guide
    parameter a."""
    sec = run.sections[k]
    bounds = (sec.a_start, a) if k == -1 else (a, sec.a_end)
    secs = list(run.sections)
    secs[k] = Section(sec.rbf, *bounds, sec.c1, sec.c2, sec.sides)
    return Run(secs, run.junctions, ends=run.ends, corners=run.corners)


def split_at_knots(chain, radius):
    """The runs of chain (chain.runs, or the whole chain) cut where the exact contact
    crosses a knot line of a side face: [Run] in order, each with its junctions and, at
    the chain's ends, the chain's end edges (and those at corner patches); None when the
    contact crosses none. A closed chain's runs start at a cut. Raises
    contact.ContactError."""
    parts = chain.runs or [chain]
    items = []  # (Section, True where a junction precedes it)
    ends, corners = [], []  # the parts' end edges, and those at corner patches
    cut = False
    for p in parts:
        contact = Contact(p, radius)
        ends += p.ends
        corners += p.corners
        for k, sec in enumerate(p.sections):
            on, cuts = crossings(contact, k)
            bounds = [sec.a_start] + cuts + [sec.a_end]
            first = not chain.closed and p is parts[0] and k == 0  # the chain's start
            # a run of a chain whose side changes face starts here
            run_start = k == 0 and bool(chain.runs)
            cut = cut or bool(cuts) or on and not first
            for i in range(len(bounds) - 1):
                # a junction before it: at a cut, at a knot line, or where a run starts
                junction = i > 0 or not first and (on or run_start)
                items.append((Section(sec.rbf, bounds[i], bounds[i + 1], sec.c1, sec.c2,
                                      sec.sides), junction))
    if not cut:
        return None
    if chain.closed:  # start at a cut or side change: every run then ends at junctions
        first = next(i for i, (_, j) in enumerate(items) if j)
        items = items[first:] + items[:first]
    groups = []
    for sec, junction in items:
        if junction or not groups:
            groups.append([])
        groups[-1].append(sec)
    n = len(groups)
    runs = [Run(g, (chain.closed or i > 0, chain.closed or i + 1 < n), ends=[], corners=[])
            for i, g in enumerate(groups)]
    if not chain.closed:  # the chain's own end edges: at the first run's start or the last's end
        start = runs[0].sections[0]
        stop = runs[-1].sections[-1]
        p0 = Part.Vertex(start.rbf.point(start.a_start, start.cm))
        p1 = Part.Vertex(stop.rbf.point(stop.a_end, stop.cm))
        for edges, attr in ((ends, "ends"), (corners, "corners")):
            for e, nb in edges:
                near = runs[0] if e.distToShape(p0)[0] <= e.distToShape(p1)[0] else runs[-1]
                getattr(near, attr).append((e, nb))
    return runs
