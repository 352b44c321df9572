# SPDX-License-Identifier: LGPL-2.1-or-later
"""How an open blend ends (fillet.py).

Each end of an open fillet chain is one of:
- exact: a single planar face across the fillet (its normal along the guide's tangent
  there). The ball's section at the end lies in that plane, and so does the blend's end
  section (its first or last v): the blend stops there as computed.
- trimmed: anything else. A slanted or curved end face, or another fillet met at an
  angle (a mitre, as where two fillets on a box's top edges meet above a sharp vertical
  edge). The contact is traced EXTEND radii past OCCT's end, on the faces' underlying
  surfaces (contact.py), and the blend is cut back by what lies there: the end face's
  surface, or the other fillet's blend, itself extended. One general fuse cuts all such
  blends together, so two blends meeting at a mitre share the edge they are cut along.
- a junction: where one run of a chain whose side changes face meets the next
  (rollingball.Run). Both blends end at the ball's section there, which is exact.
- a corner: where the chain meets a corner patch (rollingball.CornerPatch). Where three
  fillets meet, one ball touches the three faces, and each fillet ends at its section:
  the blend stops at that ball's exact section (knots.at_corner_balls; OCCT's end
  section is that ball's only on analytic faces), and corners.py fills the hole the
  blends leave around the patch. Where OCCT's end edge at the patch is no ball's
  section (at the foot of a gusset's sloped edge, where a convex fillet meets two
  concave ones, the convex one ends along a slanted curve from one concave fillet's
  trimline to the other's), that end is trimmed, along a cut through OCCT's end edge
  (_slant_tool). At a setback corner (setback.py) the concave fillet's end is trimmed
  likewise, along the setback's edge in place of OCCT's; the convex one is exact.
"""
import math

import numpy as np
import Part

from ..errors import occt_message
from .rollingball import interior_points
from .surface import angle, frame_at_point, off_surface

EXTEND = 1.0  # radii traced past a trimmed end
ACROSS = 1e-9  # rad: an exact end plane's normal is this close to the guide's tangent
ON_TRIMLINE = 1e-7  # |u - side| of a blend edge's ends on a trimline (u in [0, 1])
CUT_NODES = 128  # intervals in u of a cut curve's interpolation (REFINE times as many
REFINE = 4  # where it strays from the surfaces by more than CUT_TOL: cut_edge)
CUT_TOL = 1e-8  # a cut curve lies on both surfaces within this, relative to the blend
MAX_NEWTON = 30
NEWTON_DONE = 1e-14  # relative residual or step at which a cut point is converged
# ... or the residual within this of the coordinates' size: the trimlines' crossing at
# a mitre of an L block placed 850 from the origin stalls at 1.6e-11, 86 ulp of it
ROUNDING = 256 * 2.0 ** -52
# OCCT's end edge at a corner patch is a ball's section unless it leaves the plane
# across the guide at the end by more than SLANT times its length (the gusset's sloped
# edges at R = 1: 0.75; sections: 1e-7)
SLANT = 1e-3
RULING = 0.5  # radii along the fillet's normals, each way, of the tool cutting a slant
SLANT_NODES = 16  # intervals along OCCT's slanted end edge of that tool's rulings


class ChainEnd:
    """One end of an open chain: at 0 (the start of its sections, the blend's first v) or
    1 (the end, last v); faces: OCCT's faces met there; fillets: those of them that are
    rolling-ball faces (mitres); edges: [(OCCT's end edge, the face it meets there)];
    across: True when the end is exact (see the module); junction: True where a run of
    a chain meets the next run (rollingball.Run): exact, with no face there; corner:
    True where it meets a corner patch: exact unless slanted, the patch replaced by a
    filling; ball:
    at a corner, the third face (of OCCT's result) that the ball ending the fillet
    touches besides the chain's two sides, or None where there is not exactly one or the
    end is slanted; slant: at a corner, OCCT's end edge there where it is no ball's
    section (the end is then trimmed along it: tool, _slant_tool), else None."""

    def __init__(self, at, junction=False):
        self.at, self.faces, self.fillets, self.edges = at, [], [], []
        self.across = self.junction = junction
        self.corner, self.ball, self.slant, self.tool = False, None, None, None

    def edges_on(self, face):
        """OCCT's end edges where the fillet meets `face`."""
        return [e for e, f in self.edges if f.isSame(face)]


def _guide(chain, at):
    """Point and along-tangent of the guide's mid-line at the start (0) or end (1)."""
    sec = chain.sections[0] if at == 0 else chain.sections[-1]
    a = sec.a_start if at == 0 else sec.a_end
    return sec.rbf.point(a, sec.cm), sec.rbf.derivative(a, sec.cm, True)


def chain_ends(chain, fillet_faces, radius):
    """[ChainEnd at the start, ChainEnd at the end] of an open chain of rolling-ball
    faces of `radius`, [] if closed."""
    if chain.closed:
        return []
    out = [ChainEnd(0, chain.junctions[0]), ChainEnd(1, chain.junctions[1])]
    guide = [_guide(chain, at) for at in (0, 1)]

    def nearest(edge):  # the end an end edge belongs to: never a junction
        if out[0].junction != out[1].junction:  # a run with one of the chain's ends
            return out[1] if out[0].junction else out[0]
        d = [edge.distToShape(Part.Vertex(m))[0] for m, _ in guide]
        return out[0 if d[0] <= d[1] else 1]

    for edge, nb in chain.ends:
        end = nearest(edge)
        end.edges.append((edge, nb))
        if not any(nb.isSame(f) for f in end.faces):
            end.faces.append(nb)
            if any(nb.isSame(f) for f in fillet_faces):
                end.fillets.append(nb)
    for edge, patch in chain.corners:
        end = nearest(edge)
        end.corner = True
        if patch.setback is not None:  # cut along its slanted end, or exact
            for face, slant in patch.setback.slants:
                if any(face.isSame(f) for f in chain.faces) and \
                        any(edge.isSame(e) for e in face.Edges):
                    end.slant, end.tool = slant, _slant_tool(slant, face, radius)
            continue
        m, t = guide[end.at]
        off = max(abs((p - m).dot(t)) for p in edge.discretize(9)) / t.Length
        if off > SLANT * edge.Length:
            end.slant = edge
            end.tool = _slant_tool(edge, next(f for f in chain.faces if any(
                edge.isSame(e) for e in f.Edges)), radius)
            continue
        sides = chain.sections[-end.at].sides
        third = [f for f in patch.touches if not any(f.isSame(s) for s in sides)]
        end.ball = third[0] if len(third) == 1 else None
    for end in out:
        m, t = guide[end.at]
        if end.slant is not None:
            end.across = False
        elif end.corner and not end.faces:
            end.across = True
        elif not end.junction and len(end.faces) == 1 and not end.fillets \
                and end.faces[0].Surface.isPlanar():
            n = frame_at_point(end.faces[0], m).n
            end.across = min(angle(n, t), angle(n, -t)) <= ACROSS
    return out


def extension(ends, radius):
    """(start, end): the lengths to trace the contact past each end."""
    out = [0.0, 0.0]
    for end in ends:
        if not end.across:
            out[end.at] = EXTEND * radius
    return tuple(out)


def _tool(face):
    """A face on the surface of `face`, three times its parameter spans where the
    surface allows (one period at most, within a bounded surface's bounds), so that a
    blend extended past it is cut across its whole width."""
    s = face.Surface
    r, bounds = face.ParameterRange, s.bounds()
    periods = (s.UPeriod() if s.isUPeriodic() else None,
               s.VPeriod() if s.isVPeriodic() else None)
    box = []
    for k in (0, 1):
        lo, hi = r[2 * k], r[2 * k + 1]
        lo, hi = lo - (hi - lo), hi + (hi - lo)
        if periods[k] is not None:
            mid, half = 0.5 * (lo + hi), 0.5 * min(hi - lo, periods[k])
            lo, hi = mid - half, mid + half
        else:
            lo, hi = max(lo, bounds[2 * k]), min(hi, bounds[2 * k + 1])
        box += [lo, hi]
    return s.toShape(*box)


def _slant_tool(edge, face, radius):
    """A face through OCCT's end `edge` of its rolling-ball `face` of `radius`, ruled
    along the face's normals (RULING radii each way, at SLANT_NODES + 1 points of the
    edge): it crosses a blend close to the rolling ball there, and meets the blend's
    trimlines at the edge's ends, where the rulings lie along the side faces' normals
    (the rolling ball is tangent to them there) and the trimlines in those faces."""
    a, b = edge.FirstParameter, edge.LastParameter
    ts = [k / SLANT_NODES for k in range(SLANT_NODES + 1)]
    on = [edge.valueAt(a + (b - a) * t) for t in ts]
    normals = [frame_at_point(face, p).n for p in on]
    sides = []
    for sign in (-1.0, 1.0):
        c = Part.BSplineCurve()
        c.interpolate(Points=[p + n * (sign * RULING * radius) for p, n in zip(on, normals)],
                      Parameters=ts)
        sides.append(c.toShape())
    return Part.makeRuledSurface(*sides)


def _newton(f, x, scale, what):
    """Newton (least squares when overdetermined) on f(x) -> (point, its residual
    Vector, [column Vectors]) from x, until the residual is rounding (NEWTON_DONE x
    scale, or ROUNDING x the point's largest coordinate, for a part placed far from the
    origin) or the step is (near a tangency the Jacobian is nearly singular, so the
    parameters jitter by more than the residual). Returns x. Raises ValueError naming
    `what`, also when the iterates run off to where the surfaces give no finite values
    (far outside their domains): numpy's least squares would fail there with a
    SystemError."""
    for _ in range(MAX_NEWTON):
        p, d, cols = f(x)
        if d.Length <= max(NEWTON_DONE * scale, ROUNDING * max(abs(p.x), abs(p.y), abs(p.z))):
            return x
        jac = np.array([[c.x for c in cols], [c.y for c in cols], [c.z for c in cols]])
        if not (np.isfinite(jac).all() and math.isfinite(d.Length)):
            raise ValueError("Newton's method for %s diverged" % what)
        dx = np.linalg.lstsq(jac, [-d.x, -d.y, -d.z], rcond=None)[0]
        x = [a + b for a, b in zip(x, dx)]
        if max(abs(q) for q in dx) <= NEWTON_DONE * (1.0 + max(abs(q) for q in x)):
            return x
    raise ValueError("Newton's method for %s did not converge" % what)


def _gap(p, q, *cols):
    """(p, p - q, cols): a point on one surface, its residual from one on the other, and
    the residual's derivatives, as _newton takes them."""
    return p, p - q, cols


def cut_edge(surface, scale, tool_face, near, touch=None):
    """The curve where a blend `surface` (u across, v along) crosses the surface T of
    `tool_face`, as an edge (scale: the blend's size, for Newton's stopping test): at
    CUT_NODES + 1 values of u, Newton's method on S(u, v) = T(s, t) for (v, s, t),
    marching across. It starts at the point of the edges `near` (OCCT's fillet edges
    where the rolling ball met the tool, close to the cut) nearest to the start side.
    The points are interpolated by a C2 B-spline in u. touch: None, or (u side, tool's
    u side) where the two surfaces are tangent (a mitre's end on the face both blends
    touch); that end is where the two trimlines cross (Newton on S(u side, v) =
    T(tool side, t)). Where the curve strays from the surfaces by more than CUT_TOL
    (relative to scale) between the nodes, it is marched again with REFINE times as
    many (a pocket rim's fillet at R = 0.75 ending on a boss's cylinder, whose cut runs
    steeply in u near one end: 1.4e-6 off at 128 intervals, shapes.boss_over_pocket_rim).
    Returns (edge, largest distance of the curve from either surface between the
    nodes). Raises ValueError saying why it cannot."""
    tool = tool_face.Surface
    start, x = _start(surface, tool, near, touch)
    for count in (CUT_NODES, REFINE * CUT_NODES):
        sol = _march(surface, tool, _nodes(start, 1.0 - start, count), x, scale, touch)
        made = _curve(surface, tool, sol)
        if made[1] <= CUT_TOL * scale:
            break
    return made


def cut_across_junction(a, va, b, vb, scale, tool_face, near, touch=None):
    """A cut curve (cut_edge) that crosses from blend surface `a` into `b` where two runs
    of a chain meet (a's section at v = va is b's at v = vb): where a knot line of a side
    face lies within a mitre, the last run is little more than the part traced past
    OCCT's end, and the mitre curve starts on it and ends on the run before it. It is
    marched across a until it leaves a's range at va; the point where it crosses the
    junction section is solved for (Newton on S_a(u, va) = T(s, t) for (u, s, t)), and
    each part is marched again from there with CUT_NODES intervals. Returns [(edge,
    off, (u, v) inside the part of a on the start's side of the curve) on a, (edge,
    off, None) on b]. Raises ValueError when the curve does not cross the junction or
    cannot be traced."""
    tool = tool_face.Surface
    start, x = _start(a, tool, near, touch)
    lo, hi = a.bounds()[2:4]
    beyond = (lambda v: v < va) if abs(va - lo) < abs(va - hi) else (lambda v: v > va)
    us = _nodes(start, 1.0 - start)
    try:
        sol = _march(a, tool, us, x, scale, None, stop=lambda q: beyond(q[1]))
    except ValueError:
        sol = []
    if not sol or not beyond(sol[-1][1]) or len(sol) < 2:
        raise ValueError("the cut curve does not cross into the next run")
    u0, _, s0, t0 = sol[-2]
    uj, sj, tj = _newton(lambda y: _gap(a.value(y[0], va), tool.value(y[1], y[2]),
                                        a.getDN(y[0], va, 1, 0), -tool.getDN(y[1], y[2], 1, 0),
                                        -tool.getDN(y[1], y[2], 0, 1)),
                         [u0, s0, t0], scale, "the cut curve's crossing of the junction")
    part_a = _march(a, tool, _nodes(start, uj), x, scale, None)
    part_b = _march(b, tool, _nodes(uj, 1.0 - start), [vb, sj, tj], scale, touch)
    # a's part kept: the curved triangle between the curve, the junction and the
    # trimline at the start; its centroid in (u, v)
    inside = ((2.0 * start + uj) / 3.0, (part_a[0][1] + 2.0 * va) / 3.0)
    return [_curve(a, tool, part_a) + (inside,), _curve(b, tool, part_b) + (None,)]


def _nodes(u0, u1, count=CUT_NODES):
    """count + 1 values of u from u0 to u1 (both exact)."""
    return [u0 + (u1 - u0) * k / count for k in range(count)] + [u1]


def _start(surface, tool, near, touch):
    """(start side u, [v, s, t] to start Newton from) of a cut curve (cut_edge): it
    starts on the side away from a mitre's touching side, at the point of the edges
    `near` nearest to that side."""
    guesses = [surface.parameter(p) for e in near for p in e.discretize(Number=8)]
    if not guesses:
        raise ValueError("OCCT's fillet has no edge there to start from")
    start = 0.0 if touch is not None and touch[0] == 1.0 else 1.0
    g = min(guesses, key=lambda q: abs(q[0] - start))
    return start, [g[1]] + list(tool.parameter(surface.value(start, g[1])))


def _march(surface, tool, us, x, scale, touch, stop=None):
    """[(u, v, s, t)] of the cut curve of `surface` and `tool` at each of `us` in turn,
    each point by Newton's method from the previous (x: [v, s, t] to start from), the
    last at the trimlines' crossing where `touch` says so (cut_edge); it ends early at
    the first point for which stop(point) holds. Raises ValueError."""
    sol = []
    for u in us:
        if touch is not None and u == touch[0]:
            side = touch[1]
            v, t = _newton(lambda y: _gap(surface.value(u, y[0]), tool.value(side, y[1]),
                                          surface.getDN(u, y[0], 0, 1),
                                          -tool.getDN(side, y[1], 0, 1)),
                           [x[0], x[2]], scale, "the trimlines' crossing")
            sol.append((u, v, side, t))
            break
        x = _newton(lambda y: _gap(surface.value(u, y[0]), tool.value(y[1], y[2]),
                                   surface.getDN(u, y[0], 0, 1), -tool.getDN(y[1], y[2], 1, 0),
                                   -tool.getDN(y[1], y[2], 0, 1)), x, scale, "the cut curve")
        sol.append((u, *x))
        if stop is not None and stop(sol[-1]):
            break
    return sol


def _curve(surface, tool, sol):
    """(edge, off): the C2 B-spline in u through the cut points `sol` (_march) on
    `surface`, and its largest distance from either surface midway between nodes."""
    sol = sorted(sol)
    curve = Part.BSplineCurve()
    curve.interpolate(Points=[surface.value(q[0], q[1]) for q in sol],
                      Parameters=[q[0] for q in sol])
    off = 0.0
    for q0, q1 in zip(sol, sol[1:]):  # midway, projected from the nodes' mean parameters
        m = [0.5 * (a + b) for a, b in zip(q0, q1)]
        p = curve.value(m[0])
        off = max(off, off_surface(surface, p, m[:2]), off_surface(tool, p, m[2:]))
    return curve.toShape(), off


def _blend_of(face, blends, near=()):
    """Index in `blends` of the blend replacing the rolling-ball face `face`, or None.
    Where several do (the runs of a chain cut at knot lines share OCCT's face), the one
    nearest to the edges `near`, the end edges of the caller's blend on that face (the
    first was taken: at the wavy-top block's corner x = 0, the run at x = 40)."""
    ks = [k for k, b in enumerate(blends) if any(face.isSame(g) for g in b.chain.faces)]
    if len(ks) > 1 and near:
        return min(ks, key=lambda k: min(blends[k].full_face.distToShape(e)[0] for e in near))
    return ks[0] if ks else None


def _touch(b, partner):
    """(u side of b, u side of partner) on the face both blends touch at a mitre, or
    None when they share no face."""
    for i, f in enumerate(b.chain.sides):
        for j, g in enumerate(partner.chain.sides):
            if f.isSame(g):
                return float(i), float(j)
    return None


def _mitre_cut(b, partner, near, tol):
    """(edge, off) of cut_edge where blends b and partner meet at a mitre (near: OCCT's
    edges where b's fillet met the partner's). It marches across b; where the mitre
    curve leaves the partner's width before crossing b's (the narrower of two fillets
    meeting at a vertex, as at a wedge's ridge end), that march runs off the partner
    and the curve is off its surface (or Newton's method fails): it then marches across
    the partner instead, from OCCT's edges where the partner met b. Raises ValueError
    when neither way gives a curve."""
    try:
        first = cut_edge(b.surface, b.surface_diag, partner.full_face, near,
                         _touch(b, partner))
    except ValueError as ex:
        first, why = None, ex
    if first is not None and first[1] <= tol:
        return first
    back = [x for e in partner.ends for g in e.faces if _blend_of(g, [b]) == 0
            for x in e.edges_on(g)]
    try:
        other = cut_edge(partner.surface, partner.surface_diag, b.full_face, back,
                         _touch(partner, b))
    except ValueError:
        if first is None:
            raise why from None
        return first
    return other if first is None else min(first, other, key=lambda c: c[1])


def _mitre_cuts(b, partner, near, tol):
    """[(edge, off, [the blends it cuts])] where blends b and partner meet at a mitre
    (near: OCCT's edges where b's fillet met the partner's): one edge (_mitre_cut), or,
    where one of them is the run of a chain at its end and the mitre crosses into the
    run before it (a knot line within the mitre), an edge on each run
    (cut_across_junction); that run's probe is then moved into what is kept of it.
    Raises ValueError."""
    try:
        edge, off = _mitre_cut(b, partner, near, tol)
        if off <= tol:
            return [(edge, off, [b, partner])]
        why = ValueError("its cut curve is %.1e off the surfaces" % off)
    except ValueError as ex:
        why = ex
    for run, other in ((b, partner), (partner, b)):
        step = _next_run(run)
        if step is None:
            continue
        nxt, v_run, v_nxt = step
        try:
            (ea, oa, inside), (eb, ob, _) = cut_across_junction(
                run.surface, v_run, nxt.surface, v_nxt, run.surface_diag, other.full_face,
                near, _touch(run, other))
        except ValueError:
            continue
        if max(oa, ob) > tol:
            continue
        run.probe, run.one_side = run.surface.value(*inside), True
        return [(ea, oa, [run, other]), (eb, ob, [nxt, other])]
    raise why


def _next_run(run):
    """(the run before or after `run` across its junction, run's v there, that run's v
    there) where run is the first or last run of a chain (solve.solve_runs: group in
    order), else None."""
    if not run.group:
        return None
    junctions = [e for e in run.ends if e.junction]
    if len(junctions) != 1:
        return None
    at = junctions[0].at
    k = next(i for i, x in enumerate(run.group) if x is run) + (1 if at else -1)
    if not 0 <= k < len(run.group):
        return None
    nxt = run.group[k]
    return nxt, run.surface.bounds()[2 + at], nxt.surface.bounds()[3 - at]


def trim(blends, original_face):
    """Cut every blend with a trimmed end back: each extended face (b.full_face) is cut
    along its section with the tools of its trimmed ends (the end faces' surfaces, via
    original_face(result face) -> face of the original solid; a mitre partner's
    extended face, whose section is computed once and shared; the tool through OCCT's
    slanted end edge at a corner patch). Sets b.face to the piece holding b.probe.
    Returns [(blend, reason)] for blends that cannot be cut, or whose extension
    survives; blends whose mitre partner is not among `blends` are returned too."""
    todo = [b for b in blends if any(not e.across for e in b.ends)]
    failed = [(b, "it meets another fillet at an angle, and that fillet is kept as OCCT "
               "made it") for b in todo
              if any(_blend_of(f, todo) is None for e in b.ends for f in e.fillets)]
    if failed:
        return failed
    cuts = {id(b): [] for b in todo}
    cut = list(todo)  # and the runs next to a run whose mitre crosses into them
    for i, b in enumerate(todo):
        tol = CUT_TOL * b.surface_diag
        for e in b.ends:
            if e.across:
                continue
            for f in e.faces + [None] * (e.slant is not None):  # None: the slant
                k = None if f is None else _blend_of(f, todo, e.edges_on(f))
                if k is not None and k < i:
                    continue  # a mitre's edge is made once, by the first of its blends
                partner = None if k is None else todo[k]
                try:
                    if f is None:
                        made = [cut_edge(b.surface, b.surface_diag, e.tool, [e.slant])
                                + ([b],)]
                    elif partner is None:
                        made = [cut_edge(b.surface, b.surface_diag,
                                         _tool(original_face(f)), e.edges_on(f)) + ([b],)]
                    else:
                        made = _mitre_cuts(b, partner, e.edges_on(f), tol)
                    off = max(m[1] for m in made)
                    if off > tol:
                        raise ValueError("its cut curve is %.1e off the surfaces" % off)
                except ValueError as ex:
                    failed.append((b, "its blend, traced %g radii past OCCT's end, cannot "
                                   "be cut back to the %s there: %s"
                                   % (EXTEND, "fillet" if partner else "end face" if f
                                      else "slanted end of OCCT's fillet at its corner "
                                      "patch", ex)))
                    continue
                for edge, off, owners in made:
                    edge.fixTolerance(max(2.0 * off, 1e-7 * b.surface_diag))
                    for x in owners:
                        cuts.setdefault(id(x), []).append(edge)
                        if not any(x is y for y in cut):
                            cut.append(x)
    for b in cut:
        if any(b is x for x, _ in failed):
            continue
        try:
            pieces = b.full_face.generalFuse(cuts[id(b)])[0].Faces
        except Exception as ex:  # OCCT's general fuse failed on this blend
            failed.append((b, "cutting its blend along the curves at its ends failed (OCCT's "
                           "general fuse of the blend face with those curves reports: %s)"
                           % occt_message(ex)))
            continue
        tol = CUT_TOL * b.surface_diag
        keep = [p for p in pieces if p.distToShape(Part.Vertex(b.probe))[0] <= tol]
        v0, v1 = b.surface.bounds()[2:4]
        beyond = [Part.Vertex(b.surface.value(0.5, v1 if e.at else v0))
                  for e in b.ends if not e.across]  # in the parts cut off
        if len(keep) != 1 or any(keep[0].distToShape(m)[0] <= tol for m in beyond):
            # the probe, OCCT's face's middle, lies beyond a cut taking most of a short
            # fillet (a setback's slant 0.28 along one 0.55 long): the one piece holding
            # no end traced past, if there is one, probed at a point inside it
            keep = [p for p in pieces if all(p.distToShape(m)[0] > tol for m in beyond)]
            inside = interior_points(keep[0]) if len(keep) == 1 else []
            if not inside:
                failed.append((b, "its blend, traced %g radii past OCCT's end, is not cut "
                               "off by the face or fillet there" % EXTEND))
                continue
            b.probe = inside[0]
        b.face = keep[0]
    return failed


def side_range(b, side):
    """(v0, v1): the v-range of the blend's face along its trimline u = side; None where
    the face does not reach that side (b.one_side: what is kept of a chain's last run
    whose mitre crosses into the run before it, cut_across_junction)."""
    if b.face is b.full_face:
        return tuple(b.surface.bounds()[2:4])
    vs = []
    for e in b.face.Edges:  # the ends of each edge's curve on the blend's surface
        c2d, a, z = b.face.curveOnSurface(e)
        uv = [c2d.value(a), c2d.value(z)]
        if all(abs(q.x - side) <= ON_TRIMLINE for q in uv):
            vs += [q.y for q in uv]
    if vs:
        return min(vs), max(vs)
    return None if b.one_side else tuple(b.surface.bounds()[2:4])
