# SPDX-License-Identifier: LGPL-2.1-or-later
"""A fillet chain's G2 blend (fillet.py): the ball's exact contact on the chain's two
faces (contact.py), sampled into cross-boundary rows (trimlines.py), the PDE blend of
those rows, and its B-spline fit (bspline.py). A chain whose sides change face, or whose
data are too rough across knot lines of a side face, is blended in runs that meet at
junctions (solve_runs, knots.py). A chain that cannot be blended raises NotReplaced,
saying why; fillet() then keeps OCCT's face for it.
"""
import math

import Part

from ..errors import C2BlendError
from . import check as ck
from .bspline import fit_surface, solve_sampled
from .contact import Contact, ContactError
from . import corners as cn
from . import ends
from .knots import at_corner_balls, at_face_changes, side_jump, split_at_knots
from .surface import Frame, angle, off_surface, project
from .trimlines import ROWS, pair_rows, pointwise_shape, spec_from_rows

DATA_REL = 1e-8  # target relative truncation error of the sampled boundary data
# the targets, in turn, for the runs at a junction where their blends meet at a crease
# (solve_runs)
JUNCTION_DATA_REL = (1e-9, 1e-10)
# rad: runs whose blends still meet at a crease after that finer sampling (where a
# face only C2 across a knot line is crossed obliquely by the contact) stay blended up
# to this crease, and such a junction counts in the verdict. OCCT's face there is no
# better: along a partial revolution's profile edge (R = 1) it meets the B-spline face
# at up to 7.4e-6 rad (3.2e-5 at R = 2; OCCT's normals at 201 points), where the
# blends are G2 to it and meet at 5e-7 to 2.6e-6 rad (6.8e-5 at R = 2, where OCCT's
# face is kept). The bound is the plate fillings' target at corners.
JUNCTION_TURN = cn.GOOD_G1
DATA_KEEP = 1e-6  # above this the boundary data are too rough for G2: keep OCCT's face
SLOW_CENTRE = 0.25  # the ball's centre slower than this times its contacts: say why
ON_FACE = 10.0  # an end curve lies on its end face within this many fit tolerances


class NotReplaced(Exception):
    """This chain cannot be replaced by a G2 blend; the message says why."""


class RoughData(NotReplaced):
    """The boundary data sampled along the chain converge too slowly for a G2 blend, or
    its B-spline fit cannot reach the tolerance: both happen where the data are not
    smooth along the chain (solve_chain)."""


def sample_rows(chain, contact, n, nrows, tension, where):
    """Cross-boundary rows at n corresponding points of the exact contact of a chain."""
    return pair_rows(contact.pairs(n), nrows, tension, where)


class Blended:
    """A rolling-ball chain (or a run of one: rollingball.Run) replaced by a PDE blend:
    surface, fit and data facts; ends: its ends (ends.ChainEnd); full_face: the whole
    surface; face: the part of it in the solid (full_face cut back at trimmed ends, see
    ends.trim); probe: a point inside face; group: None for a whole chain's blend, or
    the pointwise blends of all runs of its chain (solve_runs), which are kept or
    replaced together; ring: True when that chain is closed (its last run meets its
    first); source: the FilletChain it replaces (or a run or piece of),
    which fillet() sets, for the corner patches that chain ends at; one_side: True when
    its face reaches one trimline only (ends.cut_across_junction)."""

    def __init__(self, chain, ends, where, surface, fit, samples, data_rel):
        self.chain, self.ends, self.where, self.surface, self.fit = chain, ends, where, surface, fit
        self.samples, self.data_rel, self.group, self.source = samples, data_rel, None, None
        self.ring = self.one_side = False
        self.full_face = self.face = Part.Face(surface)
        self.surface_diag = self.full_face.BoundBox.DiagonalLength
        sec = chain.sections[len(chain.sections) // 2]
        mid = sec.rbf.point(0.5 * (sec.a_start + sec.a_end), sec.cm)
        u0, u1, v0, v1 = surface.bounds()
        self.probe = surface.value(0.5 * (u0 + u1), surface.parameter(mid)[1])


def _slow_centre(contact):
    """Why the data may be rough, for RoughData's message: where the ball's centre
    moves at less than SLOW_CENTRE times its contacts' speed (Contact.slowest), the
    radius nears a face's curvature radius, and the centre's curve bends sharply
    there; else ""."""
    ratio, c = contact.slowest
    if not ratio < SLOW_CENTRE:
        return ""
    return ("; the rolling ball's centre nearly stops near (%.6g, %.6g, %.6g), moving at "
            "%.2g times its contacts' speed: the radius is close to a face's curvature "
            "radius there, and a smaller radius avoids it" % (c.x, c.y, c.z, ratio))


def solve_face(chain, radius, where, continuity, shape_params, tension, tol_rel, samples,
               max_samples, fillet_faces, target=DATA_REL, smooth=False):
    """The PDE blend replacing one rolling-ball chain or run (see bspline.solve_sampled),
    from the exact contact of the ball of `radius`, traced past the ends that are
    trimmed (ends.py), its data sampled to `target` (relative); smooth: the contact
    crosses no knot line or edge of its faces, so its data are analytic. Raises
    NotReplaced saying why it cannot."""
    nrows = ROWS[continuity]
    at_ends = ends.chain_ends(chain, fillet_faces, radius)
    try:
        chain = at_corner_balls(chain, at_ends, radius)
        contact = Contact(chain, radius, ends.extension(at_ends, radius))
        blend, n, err = solve_sampled(
            lambda k: sample_rows(chain, contact, k, nrows, tension, where),
            lambda r0, r1: spec_from_rows(r0, r1, continuity, shape_params, chain.closed,
                                          "fillet " + where),
            where, samples, max_samples, target, DATA_KEEP, smooth)
    except ContactError as ex:
        raise NotReplaced(str(ex)) from None
    if err > DATA_KEEP:
        raise RoughData("the boundary data sampled along the exact contact converge only "
                        "to %.1e (relative) with %d samples, too rough for an exact G2 "
                        "blend%s" % (err, n, _slow_centre(contact)))
    try:
        surface, fit = fit_surface(blend, tol_rel, where)
    except C2BlendError as ex:  # the B-spline fit's limits, not the user's input
        raise RoughData(ex.message) from None
    over = overshoot(surface, chain.sides, contact.signs)
    if over > ON_FACE * fit["tolerance"]:
        raise NotReplaced("the blend overshoots: it crosses the surface of a face it joins by "
                          "%.3g (model units), cutting into the part or bulging out of it; a "
                          "lower tension (here %g) or other shape parameters keep it inside "
                          "the corner" % (over, tension))
    b = Blended(chain, at_ends, where, surface, fit, n, err)
    v_ends = surface.bounds()[2:4]
    for end in at_ends:
        if end.across and end.faces:  # an end face across it, not a junction or corner
            gap = max(off_surface(end.faces[0].Surface, surface.value(u / 8.0, v_ends[end.at]))
                      for u in range(9))
            if gap > ON_FACE * fit["tolerance"]:
                raise NotReplaced("the blend's end section leaves the end face by %.1e"
                                  % gap)
    return b


def solve_chain(chain, radius, where, continuity, shape_params, tension, tol_rel, samples,
                max_samples, fillet_faces):
    """The blends replacing a chain: one PDE blend (solve_face), or one pointwise blend
    per run where the side changes face (solve_runs). Where the data are too rough
    because the contact crosses knot lines of a side face, the chain (or its runs) is
    cut there (knots.split_at_knots) and each piece gets the pointwise blend. Returns
    [Blended]. Raises NotReplaced saying why the chain cannot be replaced."""
    try:
        if chain.runs:
            return solve_runs(chain.runs, chain.closed, radius, where, continuity, tension,
                              tol_rel, samples, max_samples, fillet_faces)
        return [solve_face(chain, radius, where, continuity, shape_params, tension, tol_rel,
                           samples, max_samples, fillet_faces)]
    except RoughData as rough:
        try:
            runs = split_at_knots(chain, radius)
        except ContactError as ex:
            raise NotReplaced("%s; %s" % (rough, ex)) from None
        if runs is None:
            raise
        try:
            return solve_runs(runs, chain.closed, radius, where, continuity, tension,
                              tol_rel, samples, max_samples, fillet_faces, smooth=True)
        except NotReplaced as ex:
            raise NotReplaced("%s; cut into %d pieces where the contact crosses knot lines "
                              "of its faces, %s" % (rough, len(runs), ex)) from None


def solve_runs(runs, closed, radius, where, continuity, tension, tol_rel, samples,
               max_samples, fillet_faces, smooth=False):
    """The blends of a chain's runs (rollingball.Run), one per run: where the side changes
    face or the contact crosses a knot line of a face. The boundary data there are only
    C1 or C2 along the chain (a face's curvature, or its derivative, jumps), which no
    v-coupled PDE blend reproduces (its series stall, and blends of the runs solved apart
    do not meet). Each run takes the pointwise blend (trimlines.pointwise_shape), whose
    section at a junction depends on the data there only: the runs meet wherever both
    sides give the same data there. Where a side changes face, the runs first end where
    the exact contact crosses the edge between its faces (knots.at_face_changes). They
    do not meet where the faces' normal curvatures across the fillet differ (a side
    face's edge crossing the trimline obliquely): no surface is G2 to both there. The
    runs at a junction where their blends meet at a crease are sampled again to the
    lower targets of JUNCTION_DATA_REL; a crease left (a knot line crossed obliquely)
    is accepted up to JUNCTION_TURN, and the report measures it. closed: the last run
    meets the first. smooth: the runs are cut at every knot line the contact crosses
    (knots.split_at_knots), so that each one's data are analytic. Returns [Blended],
    each with group set. Raises NotReplaced saying why the chain cannot be replaced."""
    shape = pointwise_shape(continuity)
    try:
        runs = at_face_changes(runs, closed, radius)
    except ContactError as ex:
        raise NotReplaced(str(ex)) from None

    def solved(run, target=DATA_REL, start=samples):
        return solve_face(run, radius, where, continuity, shape, tension, tol_rel, start,
                          max_samples, fillet_faces, target, smooth)

    blends = [solved(r) for r in runs]
    pairs = list(zip(range(len(runs)), list(range(1, len(runs))) + ([0] if closed else [])))
    # a blend's S_v at its ends comes from the series of its sampled data, whose
    # derivative there is less accurate than the data: runs meeting at a crease are
    # sampled again to lower targets, from the number of samples reached (a box's
    # vertical C2 fillets, then its top outline: 1.9e-7 rad at 1e-8, 3.9e-9 to 6.7e-9 at
    # 1e-9, 0.8e-9 to 2.5e-9 at 1e-10)
    def junction(i, j):  # (gap, turn, gap at the trimlines, the gaps' tolerance)
        a, b = blends[i], blends[j]
        return _junction(a.surface, b.surface) + (
            ON_FACE * max(a.fit["tolerance"], b.fit["tolerance"]),)

    for target in JUNCTION_DATA_REL:
        creased = {k for i, j in pairs for gap, turn, _, tol in [junction(i, j)]
                   if turn > ck.TOL_G1 and gap <= tol for k in (i, j)}
        for k in sorted(creased):
            # sampled again from the count reached, if it can still double (at
            # max_samples the same samples would give the same blend)
            if blends[k].data_rel > target and 2 * blends[k].samples <= max_samples:
                blends[k] = solved(runs[k], target, blends[k].samples)
    for i, j in pairs:
        gap, turn, ends_gap, tol = junction(i, j)
        if ends_gap > tol:
            raise NotReplaced("where a side changes face, the runs' end sections lie "
                              "%.1e apart on the trimlines: the exact contact's crossing "
                              "of the edge between the side's faces was not found, and "
                              "OCCT splits its fillet away from it" % ends_gap)
        if gap > tol:
            raise NotReplaced("where a side changes face or crosses a knot line, the faces' "
                              "curvatures across the fillet differ, so no blend is G2 to "
                              "both there (the blends of the two runs would be %.1e apart)"
                              % gap)
        if turn > JUNCTION_TURN:
            sa, va = blends[i].surface, blends[i].surface.bounds()[3]
            jump = side_jump([sa.value(0.0, va), sa.value(1.0, va)],
                             list(runs[i].sides) + list(runs[j].sides))
            why = (ck.side_jump_words(jump) if jump > ck.SIDE_JUMP else
                   "a face's normal curvature across the fillet changes its rate along it "
                   "there (as on a face only C2 across a knot line that the contact crosses "
                   "obliquely), which two blends, each smooth up to the junction, cannot "
                   "follow")
            raise NotReplaced("where a side changes face or crosses a knot line, the blends "
                              "of the two runs would meet at a crease of %.1e rad (at most "
                              "%.0e is accepted), which sampling their data finer (toward "
                              "%.0e) did not remove: %s"
                              % (turn, JUNCTION_TURN, JUNCTION_DATA_REL[-1], why))
    for b in blends:
        b.group, b.ring = blends, closed
    return blends


JUNCTION_U = 16  # intervals in u at which two runs' blends are compared at a junction


def _junction(sa, sb):
    """(largest distance, largest normal angle, largest distance at the trimlines, u = 0
    and 1) between the end section of surface sa (its last v) and the start section of
    sb (its first v), at JUNCTION_U + 1 values of u."""
    va, vb = sa.bounds()[3], sb.bounds()[2]
    gap = turn = ends_gap = 0.0
    for i in range(JUNCTION_U + 1):
        u = i / JUNCTION_U
        d = (sa.value(u, va) - sb.value(u, vb)).Length
        gap = max(gap, d)
        if i in (0, JUNCTION_U):
            ends_gap = max(ends_gap, d)
        turn = max(turn, angle(sa.normal(u, va), sb.normal(u, vb)))
    return gap, turn, ends_gap


OVER_V, OVER_U = 16, 12  # samples along and across (the half next to each face)


def overshoot(surface, sides, signs):
    """How far (model units, 0 if not at all) the blend `surface` crosses to the wrong
    side of the surfaces of its side faces (sides[0] at u = 0, sides[1] at u = 1): it
    should stay on the rolling ball's side of each (signs: contact.Contact.signs).
    Measured at OVER_V values of v, marching from each trimline to u = 1/2 (projections
    start from the previous point's). A point beyond a bounded surface's edge (in the
    part traced past a chain's end, cut off later) has no foot point on it: OCCT's
    projection returns the nearest boundary point instead, which measures nothing, so
    such points are skipped."""
    u0, u1, v0, v1 = surface.bounds()
    worst = 0.0
    for k, (face, g) in enumerate(zip(sides, signs)):
        for i in range(OVER_V):
            v = v0 + (v1 - v0) * (i + 0.5) / OVER_V
            guess = None
            for j in range(1, OVER_U + 1):
                x = 0.5 * j / OVER_U
                p = surface.value(x if k == 0 else 1.0 - x, v)
                guess = project(face.Surface, p, guess)
                f = Frame(face, *guess)
                d = p - f.p
                off = d.dot(f.n)
                if (d - f.n * off).Length <= 1e-3 * d.Length:  # a foot point
                    worst = max(worst, -math.copysign(1.0, g) * off)
    return worst
