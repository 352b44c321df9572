# SPDX-License-Identifier: LGPL-2.1-or-later
"""G2 fillets on solids (issue 5, MATH.md section 7).

Route: OCCT's rolling-ball fillet of the same radius gives the topology (which faces a
fillet touches, rollingball.py) and a guide. Rolling-ball faces that join each other
tangentially end to end (a tangent chain of edges, or an edge OCCT split at a seam) form
one chain. For each chain whose two sides are one face each, the exact contact of the
ball on those faces is traced (contact.py), sampled uniformly in the arc length of the
ball's centre curve, and turned into G2 cross-boundary data; the PDE blend of those
data is fitted as a B-spline face. An open chain that does not end on a plane across it
(a slanted or curved end face, or another fillet met at an angle: a mitre) is traced
past its ends and cut back by what lies there (ends.py); so is one that OCCT ends at a
corner patch along a slanted edge, no ball's section: along that edge. The faces of the
original solid that the blend touches (its two sides and its end faces) are cut anew
along the blend's boundary edges (an end face grows by the region between the corner and
the blend's end section where the fillet uncovers its surface, and a face by the region
between its corner and a corner patch's edge cutting across it), and everything is sewn
into a solid and checked (BRepCheck, and continuity along every trimline). A chain whose
side changes face (a rounded outline) has data only C1 along it: each run along one pair
of faces gets the pointwise blend, and the runs meet at junctions (solve_runs). So do
the pieces of a chain whose data are too rough because the contact crosses knot lines of
a side face (solve_chain, knots.py). Where three or more fillets meet at a vertex,
OCCT's corner patch ends their chains; when any of them is blended, the patch is
replaced by a plate filling tangent to the blends' end sections and to the end sections
of the fillets kept there (corners.py), measured and reported, never claimed G2. Where
a convex and a concave fillet meet at a vertex whose third edge is not selected, OCCT's
face between them vanishes at a point; that corner is set back along the third edge
and filled likewise, meeting the face on the third edge's other side at an angle
(setback.py). Kept as
OCCT made them, and reported as such with the reason (no G2 claim is made there): chains
whose side changes face where no blend is G2 to both faces, and chains whose exact
contact, blend, fit, cut or end face's growth cannot be built or whose blend overshoots
its faces (NotReplaced, ends.trim, Unassembled; all of them where OCCT raises an error
while they are assembled), with the fillets that meet them in a mitre, and the corner
patches where every fillet is kept.
"""
import math
import numbers
import time

import FreeCAD
import Part

from ..errors import C2BlendError, occt_message
from . import check as ck
from .bspline import fit_surface, solve_sampled
from .contact import Contact, ContactError
from . import bopcheck as bc
from . import corners as cn
from . import ends
from . import solids as sl
from . import setback as sb
from . import strips as st
from .knots import at_corner_balls, at_face_changes, side_jump, split_at_knots
from .rollingball import (TANGENT_ANGLE, RollingBallFace, chains, interior_points, joined,
                          midpoint, new_faces, off_boundary)
from .surface import (Frame, angle, face_distance, frame_at_point, leaving, mesh_area,
                      off_surface, only_c0, periods, project)
from .trimlines import ROWS, pair_rows, pointwise_shape, shape_for, spec_from_rows

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
UNCHECKED = "passes BRepCheck; BOP check skipped (preview)"  # the check line, bop=False
C0_FINDING = "GeomAbs_C0"  # the BOP check's finding on geometry that is only C0
# the BOP check's self-interference findings, which come and go on faces only C0
# (_c0_unreliable)
C0_UNRELIABLE = ("BOPAlgo SelfIntersect", "BOPAlgo OperationAborted")
ON_FACE = 10.0  # an end curve lies on its end face within this many fit tolerances
# two edges of a face's wire leaving a vertex in directions this close (rad) form a cusp
# there, whose tolerance may be raised (_tolerate_cusps) up to CUSP_REACH times the
# shorter edge's length
CUSP = 1e-3
CUSP_REACH = 0.05
CUSP_BISECTIONS = 4  # of the doubling's last step: the least tolerance found to 2^(1/16)
# the end of a kept blend's reason naming the unselected edges that would make its
# vertex a corner (_with_others: OCCT's fillet succeeds with them)
CORNER_HINT = ("; with %s selected too, the fillets meet at a corner there instead "
               "(OCCT's fillet of them succeeds)")
# a setback corner (setback.py) left unfilled, its fillets kept for their own reasons
BETWEEN = ("OCCT's face between a convex and a concave fillet at a vertex whose third "
           "edge is not selected, kept with those fillets")


class NotReplaced(Exception):
    """This chain cannot be replaced by a G2 blend; the message says why."""


class RoughData(NotReplaced):
    """The boundary data sampled along the chain converge too slowly for a G2 blend, or
    its B-spline fit cannot reach the tolerance: both happen where the data are not
    smooth along the chain (solve_chain)."""


class Unassembled(Exception):
    """The original faces cannot be cut along these blends (attribute blends); the
    message says why. fillet() keeps OCCT's faces for them and assembles again."""

    def __init__(self, blends, message):
        super().__init__(message)
        self.blends = blends


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
        where = (" along %s (edge%s with one face)" % (_listed(free, 5), "" if len(free) == 1
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


def _listed(names, most=None):
    """'A, B and C' for a list of names; with `most`, the first `most` of a longer one
    then 'and N more'."""
    if most is not None and len(names) > most:
        return "%s and %d more" % (", ".join(names[:most]), len(names) - most)
    return " and ".join([", ".join(names[:-1]), names[-1]]) if len(names) > 1 else names[0]


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


def _on_face(face, p, tol):
    """True when point p lies on face (within tol)."""
    return face_distance(face, p) <= tol


def _probe(face):
    """A point inside face: the first point of a 3 x 3 grid of its parameter range that
    lies in the face, else (a face with no such point, as an L-shaped one) the centre of
    the largest triangle of its mesh, put on its surface, or, for a sliver too thin to
    mesh (OCCT's fillet at a radius within 1e-7 of a face's width), its centre of mass,
    put on its surface."""
    inside = interior_points(face, 3)
    if inside:
        return inside[0]
    pts, tris = face.tessellate(1e-2 * face.BoundBox.DiagonalLength)
    if not tris:
        return face.Surface.value(*face.Surface.parameter(face.CenterOfMass))
    tri = max(tris, key=lambda t: (pts[t[1]] - pts[t[0]]).cross(pts[t[2]] - pts[t[0]]).Length)
    c = (pts[tri[0]] + pts[tri[1]] + pts[tri[2]]) * (1.0 / 3.0)
    return face.Surface.value(*face.Surface.parameter(c))


def _piece_of(face, origs, tol):
    """Whether a face of OCCT's result is a piece of one of the original faces
    `origs`: a point inside it (_probe, else one of a 3 x 3 grid, interior_points) lies
    on one within tol. One point will not do: where a fillet ends at a concave edge,
    OCCT grows the face beyond the original (an L block's wall under the end of its
    step's fillet, R = 3.041: --random-edges 40 --seed 19 --turned, part 17), and the
    probe lay in that growth, so OCCT's face was kept beside the pieces cut anew and
    the sewing left 33 free edges."""
    near = [o for o in origs if _boxes_meet(face.BoundBox, o.BoundBox, tol)]
    if not near:
        return False
    # _probe is the grid's first point, when the grid has one
    points = interior_points(face, 3) or [_probe(face)]
    return any(_on_face(o, p, tol) for p in points for o in near)


def _original(shape, face):
    """The face of the original solid `shape` that a face of OCCT's result lies on: the
    nearest to a point inside it of those whose surface holds that point (a concave
    fillet extends its end faces beyond the original ones)."""
    p = _probe(face)
    tol = 1e-7 * shape.BoundBox.DiagonalLength
    on = [g for g in shape.Faces if off_surface(g.Surface, p) <= tol] or shape.Faces
    return min(on, key=lambda g: face_distance(g, p))


def _leg(curve, p, corner, tol):
    """The edge of `curve` from point p to point `corner` (both on it within tol; on a
    periodic curve the shorter way round), or None when p is not on the curve."""
    a, b = curve.parameter(p), curve.parameter(corner)
    if (curve.value(a) - p).Length > tol or (curve.value(b) - corner).Length > tol:
        return None
    lo, hi = min(a, b), max(a, b)
    if curve.isPeriodic() and hi - lo > 0.5 * curve.period():
        lo, hi = hi, lo + curve.period()
    return Part.Edge(curve, lo, hi)


def _leg_along(face, e, p, corner, tol, across, crossings):
    """The leg (_leg) from point p to `corner` along face's edge e, extended past its
    end where needed: along its curve, or, where that is an approximation that ends
    there (a B-spline made by a Boolean), along the intersection of face's surface with
    across(e), the surface of the face on e's other side (None where there is none),
    when p lies on that surface. crossings: a dict keeping each edge's intersection
    curves, computed once."""
    leg = _leg(e.Curve, p, corner, tol)
    if leg is not None or not isinstance(e.Curve, Part.BSplineCurve):
        return leg
    other = across(e)
    if other is None or off_surface(other, p) > tol:
        return None
    key = e.hashCode()
    if key not in crossings:
        try:
            crossings[key] = face.Surface.intersectSS(other)
        except Part.OCCError:
            crossings[key] = []
    return next((g for g in (_leg(c, p, corner, tol) for c in crossings[key])
                 if g is not None), None)


def _growth(face, edge, tol, across=lambda e: None):
    """The region by which a fillet's end extends `face`: a concave fillet adds
    material, a convex one ending on a face that bulges out (a box edge ending on a
    cylinder) uncovers some. The region lies on the face's surface, bounded by `edge`
    (the blend's end section, on that surface outside the face) and two legs from its
    ends to a vertex of the face (the corner), along the curves of the face's edges
    there, extended past them where needed (_leg_along; across(e): the surface beyond
    face's edge e, or None). Returns (region face, corner point, legs), or None when
    edge does not span such a corner or bounds no region with the legs."""
    ends = [v.Point for v in edge.Vertexes]
    if len(ends) != 2:
        return None
    spans, crossings = [], {}  # (length of the legs, corner, legs); for _leg_along
    for corner in face.Vertexes:
        at = [e for e in face.Edges
              if not e.Degenerated and any(corner.isSame(v) for v in e.Vertexes)]
        legs = [next((g for g in (_leg_along(face, e, p, corner.Point, tol, across,
                                             crossings)
                                  for e in at) if g is not None), None) for p in ends]
        if None not in legs:
            spans.append((sum(g.Length for g in legs), corner, legs))
    if not spans:
        return None
    # the nearest such corner: a far one on the same curves spans the face's other end
    # (a boss into a wall: the wall's edge, extended, passes both of the boss's sides)
    _, corner, legs = min(spans, key=lambda c: c[0])
    try:  # OCCT makes a null face where the edge and legs bound no region
        region = Part.Face(face.Surface, _loop([edge] + legs, tol))
        _validate(region)
    except (Part.OCCError, ValueError):
        return None
    uv = [g.Surface.parameter(corner.Point) for g in (region, face)]
    if region.normalAt(*uv[0]).dot(face.normalAt(*uv[1])) < 0:
        region.reverse()  # oriented like face, so the two merge into one
    return region, corner.Point, legs


def _loop(edges, tol):
    """The wire of `edges`, which follow one another round a loop, each ending within
    tol of the next: sorted by FreeCAD, or where that leaves it open, joined by OCCT
    with copies of them whose tolerance is tol (the part of an edge of OCCT's corner
    patch crossing a corner of a taller boss's side, where a lower boss meets it, ends
    3e-7 and 5e-7 from the legs along the face's edges, which FreeCAD's sorting does
    not join)."""
    wire = Part.Wire(Part.__sortEdges__(edges))
    if wire.isClosed():
        return wire
    copies = [e.copy() for e in edges]
    for e in copies:
        e.fixTolerance(tol)
    return Part.Wire(copies)


def _parts(face, edge, tol, across):
    """How face grows along an edge on its surface that does not lie on it: ([parts of
    edge on face], [(part off face, its _growth)]), or None when a part off the face
    spans no corner. The edge is one part off the face (a fillet's end section beyond
    it), or it crosses the face's boundary and is split there: an edge of OCCT's corner
    patch where two concave fillets meet a convex one cuts across the corner of the
    face between the concave ones, whose surface the convex fillet uncovers (a
    gusset's sloped edge meeting the floor, R = 1: the patch's edge on the floor cuts
    the corner of the gusset's footprint 0.02 deep). across: as _growth takes it."""
    g = _growth(face, edge, tol, across)
    if g is not None:
        return [], [(edge, g)]
    parts = face.copy().generalFuse([edge], tol)[1][1]  # a copy: see _cut_face
    on = [p for p in parts if _edge_on_face(p, face, tol)]
    off = [(p, _growth(face, p, tol, across)) for p in parts if not any(p is q for q in on)]
    if not on or any(g is None for _, g in off):
        return None
    return on, off


def _end_at(edge, corner, p, tol):
    """The edge along edge's curve from its end away from point `corner` to point p,
    which lies on that curve (within tol) before or beyond the corner, or None when
    p is off the curve or corner is not an end of edge."""
    c = edge.Curve
    s = c.parameter(p)
    if (c.value(s) - p).Length > tol:
        return None
    a, b = edge.FirstParameter, edge.LastParameter
    at_a, at_b = [(edge.valueAt(x) - corner).Length <= tol for x in (a, b)]
    if at_a == at_b:
        return None
    near, far = (a, b) if at_a else (b, a)
    if c.isPeriodic():  # the parameter of p nearest the corner's
        s += round((near - s) / c.period()) * c.period()
    return Part.Edge(c, min(s, far), max(s, far))


def _grown(face, section, whole, corner, region, legs, tol):
    """face (a piece of an original face that keeps the vertex `corner`) grown by
    `region` (_growth, whose legs run from the section's ends to the corner): its two
    edges at the corner end instead at the ends of `section` (shortened or extended
    along their curves, or left out where one ends there already: the part of an edge
    crossing the face's corner, _parts, has the face's edges at the corner as legs; or
    kept whole and continued by the leg where that runs past its end along the
    intersection with the next face, _leg_along), and `whole` joins them: the section,
    or the edge it is a part of, which then replaces the face's edges along its other
    parts (OCCT's corner patch's edge: the plate filling its hole turned from the faces
    around it by up to 5.6e-3 rad where the edge was split in three, 2.4e-4 whole). Its
    other wires are kept. Rebuilding the wire keeps the section's edge whole, where a
    Boolean fuse of face and region may split it near its ends (a G2 section leaves a
    plane as d^3, so it runs within 1e-7 of a leg there); the two are unified only
    where the rebuilt face is not valid or has the wrong area. Raises ValueError when
    the face does not have two edges at the corner, a section end is on neither their
    curves nor a leg, or the grown face's area is not the face's plus the region's."""
    face = face.copy()  # the fix below may shift the curves of its edges on its surface
    # by a period, in face too (the edges it keeps are face's): not in its neighbours
    area = face.Area
    ends = [v.Point for v in section.Vertexes]
    swap = []
    for w in face.Wires:
        at = [e for e in w.Edges
              if any((v.Point - corner).Length <= tol for v in e.Vertexes)]
        if not at:
            continue
        if len(at) != 2:
            raise ValueError("the face has %d edges at its corner (%.6g, %.6g, %.6g)"
                             % ((len(at),) + tuple(corner)))
        moved, drop, continued = [], [], False
        for p in ends:
            ending = [e for e in at if any((v.Point - p).Length <= tol for v in e.Vertexes)]
            if ending:  # an edge at the corner ends there: the region's leg
                drop += ending
                continue
            g = next(((e, g) for e, g in ((e, _end_at(e, corner, p, tol)) for e in at) if g),
                     None)
            if g is not None:  # shortened or extended along its curve
                drop.append(g[0])
                moved.append(g[1])
                continue
            leg = next((g for g in legs if any((v.Point - p).Length <= tol
                                               for v in g.Vertexes)), None)
            if leg is None:
                raise ValueError("the end section's ends are not on the curves of the "
                                 "face's two edges at its corner (%.6g, %.6g, %.6g)"
                                 % tuple(corner))
            moved.append(leg)
            continued = True
        if not continued:
            drop = list(at)  # else the edge a leg continues is kept whole
        if whole is not section:
            drop += [e for e in w.Edges if not any(e.isSame(x) for x in at) and all(
                whole.distToShape(Part.Vertex(q))[0] <= tol for q in _edge_points(e))]
        wire = _rewired(w, drop, moved + [whole])
        if wire is None:
            raise ValueError("its boundary does not close again once grown to the end "
                             "section at its corner (%.6g, %.6g, %.6g)" % tuple(corner))
        swap.append((w, wire))
    # the face itself with the wire replaced: the kept edges keep their curves on its
    # surface, which a new face on a copy of the surface would lack. The fix adds the
    # new edges' curves on the surface.
    out = face.replaceShape(swap)
    try:
        _validate(out)
        _check_growth(out, area, region, tol)
    except (ValueError, Part.OCCError):
        # the rebuild failed ("NULL shape", or a wrong area: a blind hole's wall, whose
        # domain spans more than a period round a side hole's opening, grown by a leg
        # along that opening's edge, _leg_along): face and region unified, when they
        # make one face (a Boolean fuse left the two apart once the wall had grown at
        # one end)
        fused = Part.Shell([face, region]).removeSplitter().Faces
        if len(fused) != 1:
            raise
        out = fused[0]
        _check_growth(out, area, region, tol)
    return out


def _check_growth(out, area, region, tol):
    """Raise ValueError unless face `out`'s area is a face's `area` plus the region's."""
    miss = abs(out.Area - area - region.Area)
    # OCCT's area is off by up to 9e-6 (relative) on a face with long B-spline edges (a
    # helical ridge's section by a cylinder's end plane: 2.7e-3 of 307 once grown, by
    # Green's theorem); there the grown face holds a point inside the region, and its
    # area misses by less than half the region's
    if miss > 1e-6 * (area + region.Area) and (
            miss > 0.5 * region.Area or not _on_face(out, _probe(region), tol)):
        raise ValueError("the grown face's area %.9g is not the face's %.9g plus the "
                         "region's %.9g" % (out.Area, area, region.Area))


def _edge_points(edge, fractions=(0.25, 0.5, 0.75)):
    """Points of edge at these fractions of its parameter range (by default its inner
    points: a quarter, half and three quarters)."""
    a, b = edge.FirstParameter, edge.LastParameter
    return [edge.valueAt(a + x * (b - a)) for x in fractions]


def _face_under(edge, faces, tol):
    """The one of `faces` whose surface holds the edge (at its inner points, within tol
    or 10x the edge's tolerance), the nearest to the edge where several do, or None.
    Two faces of a chain's ends may share a plane: a hole cutting a pocket's wall
    leaves two pieces of it, and the rim fillet's end sections lie one on each."""
    pts = _edge_points(edge)
    tol = max(tol, 10.0 * edge.Tolerance)
    holding = [f for f in faces if all(off_surface(f.Surface, p) <= tol for p in pts)]
    if len(holding) < 2:
        return next(iter(holding), None)
    return min(holding, key=lambda f: f.distToShape(edge)[0])


def _edge_on_face(edge, face, tol):
    """True when edge lies on face (at its inner points, within tol)."""
    return all(_on_face(face, p, tol) for p in _edge_points(edge))


def _consumed(edge, kept, tol):
    """True when no part of edge lies on `kept` (the edges of OCCT's fillet result, a
    compound), tested at its middle and at 1e-3 of its length from each end: an edge
    the fillet only shortens keeps one end's neighbourhood, or its middle if shortened
    at both, as an edge of the result. Failing those, by the result's edges
    themselves: two fillets shortening an edge from its two ends may leave a piece off
    its middle (a chamfer's end edge, 1.1 long, between fillets of the box's top edge
    and of the chamfer's lower edge at R = 0.577 kept 0.05 of it, three quarters
    along). A face of the result may hold a consumed edge's end inside it, where a
    fillet uncovers the face's corner (_parts)."""
    if any(kept.distToShape(Part.Vertex(p))[0] <= tol
           for p in _edge_points(edge, (0.5, 1e-3, 1.0 - 1e-3))):
        return False
    a = edge.BoundBox
    return not any(not r.Degenerated and _boxes_meet(a, r.BoundBox, tol) and all(
        edge.distToShape(Part.Vertex(p))[0] <= tol for p in _edge_points(r))
        for r in kept.Edges)


def _boxes_meet(a, b, tol):
    """Whether bounding boxes a and b overlap or lie within tol of each other (False
    where either is void, as an edge's box can be: BoundBox.intersect raises there)."""
    return all(lo_a - tol <= hi_b and lo_b - tol <= hi_a for lo_a, hi_a, lo_b, hi_b in (
        (a.XMin, a.XMax, b.XMin, b.XMax), (a.YMin, a.YMax, b.YMin, b.YMax),
        (a.ZMin, a.ZMax, b.ZMin, b.ZMax)))


def _cut_face(face, tools, sharp, legs, tol):
    """The pieces of an original face, cut along the edges `tools` lying on it, that do
    not touch any of the `sharp` edges the fillets consumed, except along `legs` (those
    of the regions this face or a neighbour grows by, _growth, from the corners where
    fillets end: the piece keeping such a corner keeps the part of a sharp edge along a
    leg until it grows, _grown). A face across its surface's periodic range is cut
    _rebased (and, should that fail, as it is). Where OCCT's general fuse fails, the
    cut is made again with the closed tools _restarted where they cross the face's
    seam, then half a period on, then with the tools' ends _snapped_to_seams. A face
    that winds round its surface is first cut strip by strip (_fused), and its pieces
    kept are merged again (strips.merged). A cut that makes a piece BRepCheck rejects
    is tried the next way too, and taken only where none does better: the tube of a
    helical ridge of 2.5 turns, rebased, was cut into a piece of 402.2 mm2 that is not
    valid, which OCCT's distance put on the junction's edges, so it was dropped and the
    sewing left free edges; as it is, it is cut into three valid pieces."""
    face = face.copy()  # OCCT may rewrite the pcurves of edges this face shares with
    # faces of the solid being assembled (a cylinder's seam): cut a copy
    areas = {}
    try:
        rebased = _rebased(face)
    except Exception:  # OCCT's, in several classes
        rebased = face

    def attempts():  # each remedy only where it changes a tool: the same cut fails again
        if st.needs_strips(face):
            yield face, tools, True
        for f in ((rebased, face) if rebased is not face else (face,)):
            yield f, tools, False
            for remedy in (lambda: [_restarted(e, f, tol) for e in tools],
                           lambda: [_restarted(e) for e in tools],
                           lambda: _snapped_to_seams(tools, f, tol)):
                cut = remedy()
                if any(a is not b for a, b in zip(cut, tools)):
                    yield f, cut, False

    pieces, in_strips, rejected = None, False, None
    for f, cut, in_strips in attempts():
        again = _fused(f, cut, tol, areas, in_strips)
        if not isinstance(again, str) and not all(p.isValid() for p in again):
            rejected = rejected or (again, in_strips)
            again = "OCCT's general fuse made a piece of it that BRepCheck rejects"
        if pieces is None or not isinstance(again, str):
            pieces = again  # the first failure is the one to report
        if not isinstance(again, str):
            break
    if isinstance(pieces, str) and rejected:
        pieces, in_strips = rejected  # sewing may yet mend them, as before
    if isinstance(pieces, str):
        raise ValueError(pieces)

    def touches(piece, edge):
        if piece.distToShape(edge)[0] > tol:
            return False
        return any(piece.distToShape(Part.Vertex(p))[0] <= tol
                   and all(g.distToShape(Part.Vertex(p))[0] > tol for g in legs)
                   for p in _edge_points(edge, (0.0, 1e-3, 0.25, 0.5, 0.75, 1 - 1e-3, 1.0)))

    kept = [f for f in pieces if not any(touches(f, e) for e in sharp)]
    return st.merged(kept) if in_strips else kept


def _fused(face, tools, tol, areas=None, in_strips=False):
    """The pieces of face cut along the edges `tools` by OCCT's general fuse (fuzzy value
    tol), or what went wrong (str): the fuse failed, its pieces do not make up the
    face (_amiss), or their edges do not follow a tool (within 10 tol, at its inner
    points). A closed tool must bound pieces: a scaled torus's face, rebased, was
    left whole along a closed trimline starting at its seam, which became an internal
    edge of a piece. An open tool may end inside the face. areas: as for _amiss.
    in_strips: the face, which winds round its surface (the cylinder's under a helical
    ridge of 2 or 3 turns), is cut strip by strip (strips.py): OCCT's general fuse cuts
    it wrongly as a whole."""
    try:
        parts = st.strips(face) if in_strips else [face]
    except ValueError as ex:
        return "cutting the face, which winds round its surface, into strips failed: %s" % ex
    pieces = []
    for part in parts:
        try:
            cut = part.generalFuse(tools, tol)[0].Faces if tools else [part]
        except Exception as ex:  # FreeCAD's Part and OCCT errors come in several classes
            return occt_message(ex)
        wrong = _amiss(part, cut, areas, tools)
        if wrong:
            return wrong
        pieces += cut
    edges = [e for f in pieces for e in f.Edges]
    every = Part.Compound(edges)
    bounds = Part.Compound([e for e in edges if e.Orientation in ("Forward", "Reversed")])
    for k, e in enumerate(tools):
        on = bounds if e.isClosed() else every
        if any(on.distToShape(Part.Vertex(p))[0] > 10.0 * tol for p in _edge_points(e)):
            return ("OCCT's general fuse did not cut the face along the %s of the %d "
                    "trimline edges on it" % (_ordinal(k + 1), len(tools)))
    return pieces


def _ordinal(n):
    """'1st', '2nd', '3rd', '4th', ... '11th', '12th', '13th', '21st' ..."""
    suffix = "th" if 10 <= n % 100 <= 20 else {1: "st", 2: "nd", 3: "rd"}.get(n % 10, "th")
    return "%d%s" % (n, suffix)


def _amiss(face, pieces, areas=None, tools=()):
    """What is wrong (str) with `pieces` as the pieces of face cut (_fused) along the
    edges `tools`, judged by their areas: None when they add up to the face's (they
    agree to about 1e-6; 1e-3 is allowed). Where the cause is known, it is named: a
    tool along a C0 knot line of the face's surface (_along_c0_knot), or a face that
    winds round its surface (surface.periods); else the message says where such
    losses were seen. Where OCCT's areas are not to be trusted (surface.only_c0),
    the areas of triangulations with one deflection, 2e-4 of the face's size, are
    compared instead: they agree to 1.2e-5 on the cap of a toNurbs() sphere turned on
    its side, cut along its fillet, where OCCT's areas of the pieces add up to 221.03
    of the face's 221.87. OCCT's areas are off by at most 0.9% on such faces, so a
    difference over 2% is taken as it is: the triangulations take seconds (4 s for a
    scaled torus's face above a plate, whose cut lost 94% or 3% of it before it was
    _rebased)."""
    area, whole = sum(f.Area for f in pieces), face.Area
    if 1e-3 * whole < abs(area - whole) < 2e-2 * whole and only_c0(face):
        d = 2e-4 * face.BoundBox.DiagonalLength
        if areas is None:
            areas = {}
        if id(face) not in areas:
            areas[id(face)] = mesh_area(face, d)
        area, whole = sum(mesh_area(f, d) for f in pieces), areas[id(face)]
    if area < (1.0 - 1e-3) * whole:
        return ("OCCT's general fuse lost part of the face (%.6g of %.6g)%s"
                % (area, whole, _along_c0_knot(face, tools)
                   or ", as where a trimline crosses the face's seam"))
    if area > (1.0 + 1e-3) * whole:
        turns = periods(face)
        return ("OCCT's general fuse cut the face into pieces whose areas add up to "
                "%.6g, more than its %.6g%s" % (area, whole, (
                    ": the face spans %.2g periods of its surface, winding round it (as "
                    "between the turns of a helical ridge), and OCCT's general fuse cut it "
                    "wrongly" % turns) if turns > 1.0 + 1e-9 else
                    ", as where the face winds round its surface's seam"))
    return None


def _along_c0_knot(face, tools):
    """', cutting along a knot line where its B-spline surface is only C0: the 1st of
    the 2 trimline edges on it runs along v = 6.28319 (within 3.1e-09)' when one of
    `tools` lies along an inner knot line of face's B-spline surface whose multiplicity
    is at least the degree (its points' parameters all lie within 1e-3 times the
    length of the knot vector's range from the knot); else ''. Cut along such a line,
    OCCT's general fuse loses the face beyond it: the face of a torus scaled 1.5 x 1.2
    x 1 by transformGeometry (a rational B-spline, C0 at its knots), rebased, cut along
    the iso-line at its knot v = 2 pi, keeps 30.2 of 356.0 mm2, as it does 1e-6 and
    1e-3 from it; 0.1 from it, it cuts the face in two."""
    s = face.Surface
    if not isinstance(s, Part.BSplineSurface):
        return ""
    directions = ((s.getUKnots(), s.getUMultiplicities(), s.UDegree, s.isUPeriodic()),
                  (s.getVKnots(), s.getVMultiplicities(), s.VDegree, s.isVPeriodic()))
    for i, e in enumerate(tools):
        try:
            uvs = [s.parameter(p) for p in _edge_points(e, [j / 8.0 for j in range(9)])]
        except Exception:  # noqa: BLE001 - OCCT's projection fails in several classes
            continue
        for k, (knots, mults, degree, periodic) in enumerate(directions):
            span = knots[-1] - knots[0]
            inner = range(len(knots)) if periodic else range(1, len(knots) - 1)
            for j in (j for j in inner if mults[j] >= degree):
                gaps = [abs(uv[k] - knots[j]) for uv in uvs]
                off = max(min(g % span, span - g % span) if periodic else g for g in gaps)
                if off <= 1e-3 * span:
                    which = ("the trimline edge on it" if len(tools) == 1 else
                             "the %s of the %d trimline edges on it"
                             % (_ordinal(i + 1), len(tools)))
                    return (", cutting along a knot line where its B-spline surface is only "
                            "C0: %s runs along %s = %.6g (within %.2g)"
                            % (which, "uv"[k], knots[j], off))
    return ""


def _restarted(edge, face=None, tol=0.0):
    """A closed edge on a periodic (or periodisable) curve, as a new edge on the same
    curve starting half a period on, or with face, where it crosses a seam of the
    face (it comes within 10 times tol or the seam's tolerance of it); any other edge,
    and one that crosses no seam of face, as it is. The face's pieces then meet the
    edge in one closed edge: cut along a trimline started elsewhere, the face of a
    torus scaled 1.5 x 1.2 x 1 and turned 20 degrees, its rim at R = 0.3, had pieces
    whose edges along it met at the seam, 1.2e-4 from the vertex of the blend's edge
    (the exact contact there is off the seam's curve, OCCT's fillet's by 9.5e-5), and
    sewing left it free. Half a period on: OCCT's general fuse loses
    most of a face cut along a closed trimline whose vertex lies at (or 2.6e-7 from) the
    face's seam, keeping only 8.5 of 1235 mm2 of a lofted face with a boss on its seam:
    the cut then merges the vertex with the seam's crossing. Started away from the seam,
    the trimline crosses it as any edge does, and the pieces sew to the blend's own
    edge, whose vertex is left where it is. (Cutting the offset of a lofted face there
    raised "MultiFusion failed" instead.)"""
    if not edge.isClosed():
        return edge
    c = edge.Curve.copy()
    a, b = edge.ParameterRange
    if not c.isPeriodic():
        try:
            c.setPeriodic()
        except (AttributeError, RuntimeError, ValueError):  # not a closed B-spline
            return edge
        a, b = c.FirstParameter, c.LastParameter
    h = 0.5 * (b - a)
    if face is not None:
        crossing = []  # (distance, point of edge) at each seam it crosses
        for seam in (e for e in face.Edges if e.isSeam(face)):
            d, pts, _ = edge.distToShape(seam)
            if d <= 10.0 * max(tol, seam.Tolerance):
                crossing.append((d, pts[0][0]))
        if not crossing:
            return edge
        h = c.parameter(min(crossing, key=lambda x: x[0])[1]) - a
    return c.toShape(a + h, b + h)


def _rebased(face):
    """face rebuilt on a copy of its surface whose periodic parameter ranges hold the
    face's own; the face as it is when they already do, or when its surface is no
    periodic B-spline. A torus scaled by transformGeometry is a B-spline periodic in u
    and v, and its face above a plate spans v in [5.72, 9.91], across the surface's
    range [0, 2 pi]: cut along its fillets' two trimlines, OCCT's general fuse keeps
    only the piece inside [0, 2 pi] (37.5 of 593.6 mm2). With the surface's origin
    moved to a knot inserted in the middle of the part of the period the face leaves
    out, the cut makes the three pieces. The surface is the same point set, with one
    more knot in each direction so moved."""
    s = face.Surface
    if not isinstance(s, Part.BSplineSurface):
        return face
    s = s.copy()
    lo_u, hi_u, lo_v, hi_v = face.ParameterRange
    moved = False
    for lo, hi, periodic, first, knots, insert, origin in (
            (lo_u, hi_u, s.isUPeriodic(), s.bounds()[0], s.getUKnots, s.insertUKnot,
             s.setUOrigin),
            (lo_v, hi_v, s.isVPeriodic(), s.bounds()[2], s.getVKnots, s.insertVKnot,
             s.setVOrigin)):
        period = knots()[-1] - knots()[0]
        if not periodic or hi - lo >= period or first <= lo and hi <= first + period:
            continue
        at = lo - 0.5 * (period - (hi - lo))  # the middle of the range left out
        at -= period * math.floor((at - first) / period)
        insert(at, 1, 1e-9 * period)
        origin(1 + min(range(len(knots())), key=lambda i: abs(knots()[i] - at)))
        moved = True
    if not moved:
        return face
    out = Part.Face(s, face.OuterWire)
    holes = [w for w in face.Wires if not w.isSame(face.OuterWire)]
    if holes:
        out.cutHoles(holes)
    _validate(out)  # the edges' curves on the new surface
    return out


def _rewired(wire, drop, new):
    """wire with its edges `drop`, one run of consecutive edges, replaced by the edges
    `new`, which join the two ends of the rest, or None when that makes no closed wire.
    The rest keep their order in the wire: a seam, which a wire on a periodic face runs
    along twice, is listed once by wire.Edges, and a wire sorted again from those lost
    it (a through hole's face grown at the corner where a pocket's floor meets it).
    OCCT's wire maker may still keep the seam once, depending on the edge the list
    starts with, so the cyclic order is tried from each start, with the new edges
    either way round."""
    ordered = wire.OrderedEdges
    gone = [any(e.isSame(x) for x in drop) for e in ordered]
    starts = [i for i in range(len(ordered)) if gone[i] and not gone[i - 1]]
    chain = Part.__sortEdges__(new)
    if all(gone):
        loops = [chain]
    elif len(starts) == 1:
        k = starts[0]
        kept = [e for e, g in zip(ordered[k:] + ordered[:k], gone[k:] + gone[:k]) if not g]
        loops = [kept + chain, kept + chain[::-1]]
    else:
        loops = []
    for loop in loops:
        for j in range(len(loop)):
            edges = loop[j:] + loop[:j]
            try:
                out = Part.Wire(edges)
            except Part.OCCError:
                continue
            if out.isClosed() and len(out.OrderedEdges) == len(edges):
                return out
    return None


def _validate(face):
    """face.validate(), in place: where the face is not valid, it is rebuilt with its
    edges' missing curves on its surface added. FreeCAD 0.20 rebuilds it from its outer
    wire, then adds the other wires to that without checking that the rebuild
    succeeded: where it failed (an open wire) on a face with holes, FreeCAD itself
    crashed (a segmentation fault in TopoDS_Builder::Add; a through hole's face, which
    a side hole crosses, grown where a pocket's floor edge ends on it). So each wire of
    such a face is first rebuilt alone, where a failure only raises. Raises ValueError
    when a wire bounds no face on the surface."""
    wires = face.Wires
    if len(wires) > 1 and not face.isValid():
        for k, w in enumerate(wires):
            alone = face.removeShape([x for x in wires if not x.isSame(w)])
            try:
                alone.validate()
            except Part.OCCError:
                raise ValueError("its %s wire (of %d) bounds no face on its surface"
                                 % (_ordinal(k + 1), len(wires))) from None
    face.validate()


def _snapped_to_seams(tools, face, tol):
    """The tools with their ends within tol of a seam of face moved onto it, each
    cluster of such ends to one point (the projection of its first end). A loop of
    trimline edges whose vertex lies 1e-9 before the face's seam (where the pieces of
    a fillet along a periodic extrusion's rim meet, at the knot line that is its seam)
    makes OCCT's general fuse fail ("MultiFusion failed"); on the seam, it cuts. An
    open B-spline edge (as trimlines are) becomes a clamped B-spline whose ends are
    moved by its end poles, which moves the curve by no more than its ends move; other
    edges are kept as they are."""
    seams = [e for e in face.Edges if e.isSeam(face)]
    if not seams:
        return list(tools)
    targets = []  # (end, its point on a seam)
    out = []
    for e in tools:
        if e.isClosed() or not isinstance(e.Curve, Part.BSplineCurve):
            out.append(e)
            continue
        c = e.Curve.copy()
        c.segment(*e.ParameterRange)  # clamped (a periodic curve's too): ends = end poles
        for index, end in ((1, c.StartPoint), (c.NbPoles, c.EndPoint)):
            near = next((q for p, q in targets if (p - end).Length <= tol), None)
            if near is None:
                d, pts, _ = min((s.distToShape(Part.Vertex(end)) for s in seams),
                                key=lambda r: r[0])
                if not 0.0 < d <= tol:
                    continue
                near = pts[0][0]
                targets.append((end, near))
            c.setPole(index, near)
        out.append(c.toShape())
    return out


def _samples(a, b, curves, per_span=8, n=100):
    """Parameters in [a, b] at which to compare an edge's curves: n + 1 evenly spaced,
    and per_span + 1 in each knot span of each of `curves` (the B-splines among them)
    that meets [a, b]. A pcurve's knots may cluster at one end of the edge, and its
    distance from the 3D curve peaks inside such short spans."""
    ts = {a + (b - a) * j / n for j in range(n + 1)}
    for c in curves:
        knots = c.getKnots() if hasattr(c, "getKnots") else []
        for lo, hi in zip(knots, knots[1:]):
            lo, hi = max(lo, a), min(hi, b)
            if hi > lo:
                ts.update(lo + (hi - lo) * j / per_span for j in range(per_span + 1))
    return sorted(ts)


def _update_tolerances(edges, fuzzy):
    """Raise the tolerance of each of `edges` to twice the largest distance between
    its 3D curve and its curves on the faces (what the BOP check measures, by
    optimisation), where the new pcurves made by cutting and sewing are further off
    than half the edge's tolerance. Sampled at 100 points, and at 8 per knot span of
    either curve (_samples): the distance peaks between the 129 nodes of a mitre's cut
    curve, which 101 samples missed (1.15e-7 against 4e-8 found, on a box's four top
    edges at R = 4), and inside the short spans where a toNurbs() pcurve's knots
    cluster (3.9e-7 against 9.6e-8 found, on a wall running into a cylinder).
    Then raise the tolerance of each of their vertices to twice its distance from the
    ends of the curves there (_vertex_gap), where that is at most `fuzzy`, the fuzzy
    value of the faces' cut (_cut_face): cutting a face along a closed trimline merges
    the point where the trimline crosses the face's seam with the trimline's own
    vertex when they are closer than that, and the seam's pieces then end up to that
    far from their vertex (2.8e-6 against 2e-7, where a pipe r = 3 meets one of r = 6,
    filleted at R = 0.5: BRepCheck rejected the face,
    test_blends_whose_faces_brepcheck_rejects_are_kept_as_occts). Wider gaps are no
    artefact of the cut, and the checks are left to find them (blends ending 1e-4 from
    where they should: test_blends_ending_off_the_corner_balls_are_kept_as_occts)."""
    for e in edges:
        if e.Degenerated:  # a pole: no 3D curve to compare with
            continue
        pcurves = _pcurves(e)
        worst = 0.0
        for c2, surf, place, a, b in pcurves:
            for t in _samples(a, b, (c2, e.Curve)):
                worst = max(worst, (_on(surf, place, c2.value(t)) - e.valueAt(t)).Length)
        if 2.0 * worst > e.Tolerance:
            e.fixTolerance(2.0 * worst)
        for v, gap in _vertex_gap(e, pcurves):
            if 2.0 * gap > v.Tolerance and gap <= fuzzy:
                v.fixTolerance(2.0 * gap)


def _pcurves(edge):
    """[(2D curve, surface, placement or None, first, last)] of each of edge's curves
    on the faces it bounds."""
    out = []
    for k in range(8):  # FreeCAD 0.20 returns None past the last, or raises
        try:
            c = edge.curveOnSurface(k)
        except (ValueError, RuntimeError, IndexError):
            break
        if c is None:
            break
        out.append(c)
    return out


def _on(surf, place, uv):
    """The point of surface `surf` (placed by `place` when not None) at uv."""
    q = surf.value(uv.x, uv.y)
    return place.multVec(q) if place else q


def _vertex_gap(edge, pcurves):
    """[(vertex, distance)] for the first and the last vertex of `edge`: the largest
    distance from it of the edge's 3D curve and its `pcurves` (_pcurves) at the end it
    bounds (the first vertex bounds the curve's start, the last its end)."""
    out = []
    for k, vertex in enumerate((edge.firstVertex(), edge.lastVertex())):
        gap = (edge.valueAt(edge.LastParameter if k else edge.FirstParameter)
               - vertex.Point).Length
        for c2, surf, place, a, b in pcurves:
            gap = max(gap, (_on(surf, place, c2.value(b if k else a)) - vertex.Point).Length)
        out.append((vertex, gap))
    return out


class _Touched:
    """A face of the original solid that blends touch: orig; tools: the edges lying on
    its surface that bound it anew (blend edges, kept OCCT fillets' edges, legs of
    neighbours' growth regions); inside: those lying on the face itself, or their parts
    that do (_parts); grown: an (end section, the edge it is or is a part of, corner,
    region) for each region it grows by (_growth, _grown); legs: those of its and its
    neighbours' growth regions, along which it keeps its corners (_cut_face); owners:
    the blends concerned; occt: an edge of a fillet kept as OCCT's (or of a corner
    patch) leaves it away from its corners, so only OCCT's faces can take its place."""

    def __init__(self, orig):
        self.orig, self.tools, self.inside, self.grown, self.legs = orig, [], [], [], []
        self.owners, self.occt = [], False

    @staticmethod
    def of(touched, orig, blend):
        """The entry of `touched` for face orig (added if new), with blend an owner."""
        t = next((x for x in touched if x.orig.isSame(orig)), None)
        if t is None:
            t = _Touched(orig)
            touched.append(t)
        if not any(blend is x for x in t.owners):
            t.owners.append(blend)
        return t


def assemble(shape, result, blended, fillet_faces, where, patches=(), bop=True,
             meanwhile=None):
    """The solid: the faces of `result` (OCCT's fillet of `shape`) with the replaced
    rolling-ball faces dropped, the blend faces added, and every face of `shape` that a
    blend touches (sides and ends) cut anew along the blends' boundary curves; sewn,
    with the holes left at the corner `patches` (rollingball.CornerPatch, some of whose
    fillets are blended) filled (corners.py), made a solid and checked (bopcheck.py;
    BRepCheck only when bop is False). meanwhile(solid), when given, is called with
    the first solid made while OCCT's BOP check of it runs in another process (the
    solid returned may differ, when a plate filling is remade). Returns (solid, the
    report's line on its check). Raises C2BlendError, or Unassembled for the blends at
    a corner that cannot be filled and for those to which BRepCheck's or the BOP
    check's faults belong (_rejected_faces, _bop_faulty)."""
    diag = shape.BoundBox.DiagonalLength
    tol = 1e-7 * diag
    drop = [f for b in blended for f in b.chain.faces] + [f for p in patches for f in p.faces]
    kept_fillets = [f for f in fillet_faces if not any(f.isSame(d) for d in drop)]
    faces_out = [b.face for b in blended]
    # the original faces the blends touch, with the blend's edges lying on each
    touched = []
    for b in blended:
        near = list(b.chain.sides) + [f for e in b.ends for f in e.faces
                                      if not any(f.isSame(g) for g in e.fillets)]
        for edge in b.face.Edges:
            res_face = _face_under(edge, near, ON_FACE * b.fit["tolerance"])
            if res_face is None:
                continue  # a mitre, shared with another blend
            _Touched.of(touched, _original(shape, res_face), b).tools.append(edge)
    for t in list(touched):
        # edges of OCCT fillets kept, and of corner patches, on this face bound it too;
        # a patch's where they touch it (the two setbacks where a hole cuts a pocket's
        # wall, shapes.hole_through_pocket_wall, have their edges on the wall's plane,
        # each on one of the two faces the hole leaves of it)
        touching = [e for p in patches for e in p.tools
                    if t.orig.distToShape(e)[0] <= max(tol, 10.0 * e.Tolerance)]
        t.tools += [e for e in [e for k in kept_fillets for e in k.Edges] + touching
                    if not e.Degenerated and _face_under(e, [t.orig], tol) is not None]
        t.inside += [e for e in t.tools if not any(e is x for x in t.inside)
                     and _edge_on_face(e, t.orig, tol)]

        def across(x, f=t.orig):  # the surface beyond f's edge x
            return next((g.Surface for g in shape.ancestorsOfType(x, Part.Face)
                         if not g.isSame(f)), None)
        for e in t.tools:
            if any(e is x for x in t.inside):
                continue
            parts = _parts(t.orig, e, tol, across)
            if parts is None:
                own = [b for b in t.owners if any(e.isSame(x) for x in b.face.Edges)]
                if not own:  # an edge of a fillet kept as OCCT's, or of a corner patch
                    t.occt = True  # OCCT's faces may take this one's place (below)
                    continue
                raise Unassembled(own, "an end of its blend leaves face %s of the "
                                  "original solid away from the face's corners"
                                  % ck.element_name(shape, t.orig, "Face"))
            t.inside += parts[0]
            for section, (region, corner, legs) in parts[1]:
                t.grown.append((section, e, corner, region, legs))
                t.legs += legs
                for leg in legs:  # a leg beyond the face's edges cuts the face it crosses
                    if any(_edge_on_face(leg, x, tol) for x in t.orig.Edges):
                        continue
                    other = next((f for f in shape.Faces if not f.isSame(t.orig)
                                  and _edge_on_face(leg, f, tol)), None)
                    if other is None:
                        raise Unassembled(t.owners, "the region by which its blend's end "
                                          "extends face %s is not bounded by the solid's "
                                          "faces" % ck.element_name(shape, t.orig, "Face"))
                    o = _Touched.of(touched, other, t.owners[0])
                    o.tools.append(leg)
                    o.inside.append(leg)
                    o.legs.append(leg)
    kept = Part.Compound(result.Edges)
    # a seam is no corner, whatever part of it the fillets take: the piece of a cone
    # left between two fillets holds a piece of its seam, none of which OCCT keeps
    sharp = [e for e in shape.Edges if len(ck.edge_faces(shape, e)) == 2
             and not any(e.isSame(r) for r in result.Edges) and _consumed(e, kept, tol)]
    for t in touched:
        try:
            if t.occt:
                raise ValueError("an edge of a fillet kept as OCCT's, or of a corner "
                                 "patch, leaves it away from its corners")
            pieces = _cut_face(t.orig, t.inside, sharp, t.legs, tol)
            if not pieces and _occt_pieces(result, t, drop + kept_fillets, tol):
                # every piece touches an edge the fillets consume, yet OCCT's fillet
                # keeps some of the face (a pocket's wall under a boss, next to fillets
                # kept as OCCT's there: machined seed 10, part 55)
                raise ValueError("no piece of it is kept, where OCCT's fillet keeps some")
            for section, whole, corner, region, legs in t.grown:  # the fillets' end sections
                # extend the face: at each corner, the piece keeping it grows
                k = next((i for i, f in enumerate(pieces) if any(
                    (v.Point - corner).Length <= tol for v in f.Vertexes)), None)
                if k is None:
                    raise ValueError("no piece keeps the corner (%.6g, %.6g, %.6g)"
                                     % tuple(corner))
                pieces[k] = _grown(pieces[k], section, whole, corner, region, legs, tol)
        except Exception as ex:
            pieces = _occt_pieces(result, t, drop + kept_fillets, tol)
            if pieces is None:
                raise Unassembled(t.owners, "face %s of the original solid cannot be cut "
                                  "along its blend (%s)"
                                  % (ck.element_name(shape, t.orig, "Face"),
                                     occt_message(ex))) from None
        faces_out += pieces
    for f in result.Faces:
        if any(f.isSame(d) for d in drop):
            continue
        if not any(f.isSame(k) for k in kept_fillets) and \
                _piece_of(f, [t.orig for t in touched], tol):
            continue  # replaced by the pieces cut from the original face
        faces_out.append(f)
    shells = _sewn(faces_out)
    fills = []  # _Fill per corner patch
    if patches and len(shells) == len(result.Shells):  # fill the holes the blends leave
        holed = [s for s in shells if not s.isClosed()]  # (a void's shell may have some)
        holed = holed[0] if len(holed) == 1 else Part.Compound(holed)
        try:
            loops = cn.holes(holed, patches, 0.5 * min(f.BoundBox.DiagonalLength
                                                       for p in patches for f in p.faces))
        except cn.Unfilled:
            loops = []  # a sewing gap: reported below
        fills = [_Fill(holed, p, loop, _at_corner(p, blended))
                 for p, loop in zip(patches, loops)]

    def closed():  # the solid, sewn again with the fillings as they are now
        return _closed(_sewn(faces_out + [f.face for f in fills]) if fills else shells,
                       result, where, blended, tol)
    solid = closed()
    while fills:
        # OCCT's plate filling varies erratically with its input: a filling that
        # BRepCheck rejects once sewn, or whose neighbour it rejects, is remade with the
        # next trial (a blend's face rejected where it meets a filling that changed at
        # the 16th digit of the blend's poles: test_workbench.py,
        # test_a_filling_that_breaks_the_sewn_solid_is_remade)
        redo = _rejected_fills(solid, fills)
        if not redo or not all(f.refill() for f in redo):
            break
        solid = closed()
    first = solid
    overlap = (lambda: meanwhile(first)) if meanwhile else None
    if not bop:
        problems, line = bc.problems(solid, bop=False, meanwhile=overlap), UNCHECKED
    while bop:
        # OCCT's intersection may loop on a plate filling and a blend (seen): their
        # neighbourhoods are checked alongside, and a filling where it is stuck is
        # remade with the next trial
        faces = [_patch_face(solid, f.patch) for f in fills]
        try:
            problems = bc.problems(solid, meanwhile=overlap if solid is first else None,
                                   suspects=faces)
            line = "passes BRepCheck and the BOP check"
            break
        except bc.Unfinished as ex:
            redo = [f for f, g in zip(fills, faces) if any(g.isSame(x) for x in ex.stuck)]
            if not redo or not all(f.refill() for f in redo):
                problems = bc.problems(solid, bop=False)
                line = ("passes BRepCheck, but %s (%s): Boolean operations on this solid "
                        "may not finish either" % (ex, _unfinished_why(redo, faces, solid)))
                break
            solid = closed()
    orig = _input_problems(shape) if problems else None
    # an input that fails the BOP check for C0 geometry only does not stop the faults
    # that are new being looked for around the blends: they are the fillet's
    c0_input = orig is not None and _input_only_c0(shape, orig)
    unreliable = _c0_unreliable(solid) if orig and C0_FINDING in orig and bop and \
        _unreliable_count(problems) else []
    inherited = _inherited(problems, orig, solid, unreliable) if problems else None
    if inherited:
        problems, line = None, inherited
    blocks = orig if not c0_input else None
    rejected = _rejected_faces(solid, blended, fills, shape) if problems else []
    if rejected:
        # FreeCAD's message then lists its faces' own statuses ("No error"), not those
        # in their context that failed
        problems = "BRepCheck rejects %s" % ", ".join(name for name, _ in rejected)
        # blame the blends and fillings rejected themselves, else those next to a
        # rejected face (a face cut along several blends would blame them all)
        own = [near for name, near in rejected if not name.startswith("face ")]
        at = [b for b in blended if any(b is x for near in own or [n for _, n in rejected]
                                        for x in near)]
        if at and not blocks:
            raise Unassembled(at, "the solid sewn with its blend is not valid: %s"
                              % problems)
    elif problems and bop and not blocks:
        # BRepCheck passes: the BOP check's findings (which name no face) are looked
        # for around each blend and filling, but for the C0 faces of a C0 input and
        # the self-interference findings of the faces where they are unreliable
        def ignore(near, finding):
            return c0_input and (finding.endswith(C0_FINDING) or (
                finding.endswith(C0_UNRELIABLE)
                and any(f.isSame(u) for f in near.Faces for u, _ in unreliable)))
        at = _bop_faulty(solid, blended, fills, ignore)
        if at:
            raise Unassembled(at, "OCCT's BOP check of the solid sewn with its blend "
                              "finds, around it: %s" % problems)
        line = _as_occt_fillet(problems, solid, result)
        if line:
            problems = None
    if problems:
        msg = ("the filleted solid is not valid after sewing (BRepCheck and BOP check: %s)"
               % problems)
        if orig:
            msg += ("; the input solid already fails that check (%s), so repair or "
                    "rebuild it first" % orig)
        raise C2BlendError(msg, where, "validity")
    return solid, line


def _occt_pieces(result, touched, skip, tol):
    """The faces of `result` (OCCT's fillet) that lie on touched.orig, a face the blends
    touch, none of `skip` (the rolling-ball faces replaced, and OCCT's fillets kept):
    they take that face's place when it cannot be cut, if every edge bounding it anew
    (touched.tools) lies on their edges. A blend's trimline is the exact contact, which
    OCCT's fillet has too where its face is a cylinder or a torus (between planes, or a
    plane and a coaxial cylinder or cone), so there a face that only blends' sides
    touch is OCCT's own where its cut fails; elsewhere the edges' test refuses it. The
    case: a block's top face, cut along one edge's blend and the fillets kept where a
    pocket's convex rim and concave corner meet (OCCT's face between them, a
    mixed-convexity vertex), had no piece keeping the pocket's corner. Where a blend
    ends on the face, its end section is not OCCT's: None."""
    faces = [f for f in result.Faces if not any(f.isSame(x) for x in skip)
             and _piece_of(f, [touched.orig], tol)]
    if not faces:
        return None
    edges = Part.Compound([e for f in faces for e in f.Edges])
    if all(edges.distToShape(Part.Vertex(p))[0] <= tol for e in touched.tools
           for p in _edge_points(e, (0.0, 0.25, 0.5, 0.75, 1.0))):
        return faces
    return None


def _rejected_faces(solid, blended, fills, shape=None):
    """The faces of `solid` that BRepCheck rejects (in their own context: edges and
    pcurves that do not fit their surface, wires that do not close), each as (what it
    is, for messages: 'the blend face of ...', 'the plate filling of ...' or 'face
    FaceN of the filleted solid', followed by ', on FaceM of the input' where `shape`,
    the input solid, is given, since the filleted solid is not returned then; the
    blends of `blended` it belongs to: the blend whose face it is, those ending at the
    corner it fills, or those sharing an edge with it)."""
    out = []
    mine = [(b, _find_face(solid, b)) for b in blended]
    for f in solid.Faces:
        if f.isValid():
            continue
        own = next((b for b, g in mine if g.isSame(f)), None)
        fill = next((x for x in fills if _patch_face(solid, x.patch).isSame(f)), None)
        if own is not None:
            out.append(("the blend face of %s" % own.where, [own]))
        elif fill is not None:
            out.append(("the plate filling of the %s" % fill.patch.where(),
                        _at_corner(fill.patch, blended)))
        else:
            on = "" if shape is None else ", on %s of the input" % ck.element_name(
                shape, _original(shape, f), "Face")
            out.append(("face %s of the filleted solid%s" % (ck.element_name(solid, f, "Face"),
                                                            on),
                        [b for b, g in mine
                         if any(e.isSame(x) for e in g.Edges for x in f.Edges)]))
    return out


def _rejected_fills(solid, fills):
    """The fillings of `fills` whose face in `solid` shares an edge with a face that
    BRepCheck rejects, or is one (a face shares all its edges with itself)."""
    edges = [e for f in solid.Faces if not f.isValid() for e in f.Edges]
    return [x for x in fills if edges and any(
        e.isSame(d) for e in _patch_face(solid, x.patch).Edges for d in edges)]


def _bop_faulty(solid, blended, fills, ignore=None):
    """The blends of `blended` in whose neighbourhood in `solid` (the blend face, or
    the plate filling at its corner, with the faces next to it) OCCT's BOP check finds
    something wrong (bopcheck.faulty), but for findings that ignore(neighbourhood,
    finding) passes."""
    faces = [_find_face(solid, b) for b in blended]
    fill_faces = [_patch_face(solid, f.patch) for f in fills]
    bad = bc.faulty(solid, faces + fill_faces, bc.NEAR_LIMIT, ignore)
    at = [b for b, g in zip(blended, faces) if any(g.isSame(x) for x in bad)]
    for f, g in zip(fills, fill_faces):
        if any(g.isSame(x) for x in bad):
            at += [b for b in _at_corner(f.patch, blended) if not any(b is x for x in at)]
    return at


def _inherited(problems, orig, solid, unreliable=()):
    """The report's line when the BOP check's only findings (`problems`) are faces or
    edges whose geometry is only C0 (GeomAbs_C0), the input solid has such geometry
    too (`orig`, its findings: B-spline faces with knots of full multiplicity, as after
    toNurbs()) and BRepCheck passes: those are the input's faces, cut anew but the
    same surfaces, not a defect of the fillet. Self-interference findings count as
    such too, up to as many as the faces `unreliable` (_c0_unreliable) have alone.
    None otherwise."""
    if not orig or C0_FINDING not in orig or bc.problems(solid, bop=False):
        return None
    flaky = _unreliable_count(problems)
    if not _only_c0(problems, (C0_FINDING,) + C0_UNRELIABLE) or \
            flaky > sum(n for _, n in unreliable):
        return None
    c0 = "; ".join(f for f in problems.split("; ") if C0_FINDING in f)
    line = ("passes BRepCheck; the BOP check finds geometry that is only C0 (%s), as in "
            "the input solid (%s)" % (c0, orig))
    if flaky:
        line += ("; its self-interference test also reports %s on %s, only C0 like the "
                 "input's face, whose edges do not interfere and whose boundary BRepCheck "
                 "accepts: on faces only C0 that test is unreliable (it reports the same "
                 "on plane cuts of such faces)"
                 % ("; ".join(f for f in problems.split("; ") if C0_FINDING not in f),
                    ", ".join("face %s" % ck.element_name(solid, f, "Face")
                              for f, _ in unreliable)))
    return line + ": Boolean operations on those faces may fail"


def _as_occt_fillet(problems, solid, result):
    """The report's line when BRepCheck passes on `solid` and the BOP check's findings
    (`problems`, none of them around a blend or plate filling: _bop_faulty) are no
    more, of each kind, than on OCCT's own fillet `result` of the same edges, which
    FreeCAD's Fillet returns: they lie in what the solid keeps of OCCT's fillet (tiny
    edges and self-intersecting vertices where two arcs of crossing slots are filleted
    at R = 0.03, shapes.three_slots), and that fillet would have them too. None
    otherwise, and when OCCT's fillet passes or its check does not finish."""
    if bc.problems(solid, bop=False) is not None:
        return None
    try:
        occt = bc.problems(result)
    except bc.Unfinished:
        return None
    if occt is None:
        return None
    theirs = _counts(occt)
    if any(n > theirs.get(f, 0) for f, n in _counts(problems).items()):
        return None
    return ("passes BRepCheck; the BOP check finds %s, as it does on OCCT's own fillet of "
            "these edges (FreeCAD's Fillet gives the same: %s), and none of it around a "
            "blend or plate filling (each checked with the faces next to it): Boolean "
            "operations on it may fail" % (problems, occt))


def _counts(findings):
    """{finding: count} of a problems line (bopcheck.problems)."""
    out = {}
    for f in findings.split("; "):
        text, _, n = f.rpartition(" (")
        if text and n.endswith(")") and n[:-1].isdigit():
            out[text] = out.get(text, 0) + int(n[:-1])
        else:
            out[f] = out.get(f, 0) + 1
    return out


def _unreliable_count(findings):
    """How many of the findings of a problems line are self-interference findings
    (C0_UNRELIABLE)."""
    return sum(n for f, n in _counts(findings).items() if f.endswith(C0_UNRELIABLE))


def _only_c0(findings, kinds=(C0_FINDING,)):
    """True when every finding of a problems line (bopcheck.problems) is on geometry
    that is only C0 (or, with `kinds`, ends with one of those)."""
    return all(f.endswith(tuple(kinds)) for f in _counts(findings))


def _input_only_c0(shape, findings):
    """True when the BOP check's `findings` on `shape` (a problems line) are geometry
    only C0 and, no more often than _c0_unreliable finds it on shape's faces, self-
    interference on faces only C0 (a toNurbs() sphere through a plate gets it)."""
    if C0_FINDING not in findings or \
            not _only_c0(findings, C0_UNRELIABLE + (C0_FINDING,)):
        return False
    flaky = _unreliable_count(findings)
    return not flaky or flaky <= sum(n for _, n in _c0_unreliable(shape))


def _c0_unreliable(solid):
    """[(face, count)]: the B-spline faces of `solid` on which, checked alone, the BOP
    check finds geometry that is only C0 and self-interference (C0_UNRELIABLE, count
    such findings) but nothing else, whose edges checked together show no
    interference, and which BRepCheck accepts (it tests the boundary's self-
    intersection in the face's parameters). On such faces OCCT 7.6's
    self-interference test is unreliable: the surface of FreeCAD's Part Ellipsoid
    (6 x 3 x 3, a rational B-spline with double knots) cut by the plane z = c with
    OCCT's own Boolean gets SelfIntersect at c = -2, 0, 2 and 2.5 and nothing at -1,
    0.2 to 1.5; a toNurbs() sphere r = 5 about z = 7 gets it at 5.5 to 9 and not at
    3 to 5.2 (tests/freecad: test_a_part_ellipsoid_on_a_plate_is_g2 and the test
    before it). A region bounded by a plane section cannot intersect itself."""
    out = []
    for f in solid.Faces:
        if not only_c0(f):  # no other face gets GeomAbs_C0: not worth a check
            continue
        try:
            found = bc.problems(f, bc.NEAR_LIMIT)
            if found is None or C0_FINDING not in found or \
                    not _only_c0(found, C0_UNRELIABLE + (C0_FINDING,)):
                continue
            count = _unreliable_count(found)
            edges = bc.problems(Part.Compound(f.Edges), bc.NEAR_LIMIT)
        except bc.Unfinished:
            continue
        if count and (edges is None or _only_c0(edges)) and f.isValid():
            out.append((f, count))
    return out


class _Fill:
    """The plate filling (face) of a corner patch's hole (edges loop of the open
    shell), with the trials tried (corners.fill). Raises Unassembled for
    `blends`, those ending there, when the hole cannot be filled."""

    def __init__(self, shell, patch, loop, blends):
        self.shell, self.patch, self.loop = shell, patch, loop
        self.tried, self.face, self.error = [], None, None
        if not self.refill():
            raise Unassembled(blends, "the %s cannot be replaced: %s"
                              % (patch.where(), self.error))

    def refill(self):
        """Fill again with the trials not yet tried; False when none is left or none
        gives a face (error says why)."""
        left = [t for t in cn.TRIALS if t not in self.tried]
        if not left:
            return False
        try:
            self.face, trial = cn.fill(self.shell, self.loop, self.patch.guide, left,
                                       self.patch.creases)
        except cn.Unfilled as ex:
            self.error = str(ex)
            return False
        self.tried.append(trial)
        return True


def _closed(shells, result, where, blended, fuzzy):
    """The solid bounded by the closed shells of `shells`, as many as `result` (OCCT's
    fillet) has: the outer one facing outwards, those of voids inwards, with the
    tolerance of each edge not in `result` (OCCT's fillet) raised to its pcurves'
    deviation, and of its vertices to the gaps up to `fuzzy` (the faces' cut's) that
    the cut leaves there (_update_tolerances). A sewing that left free edges raises
    Unassembled for the blends (of `blended`) those edges touch, which are then kept as
    OCCT's, or C2BlendError when they touch none."""
    if len(shells) != len(result.Shells) or not all(s.isClosed() for s in shells):
        free = [e for s in shells for e in s.Edges
                if len(s.ancestorsOfType(e, Part.Face)) == 1
                and not e.isSeam(s.ancestorsOfType(e, Part.Face)[0])]
        sewn = Part.Compound(shells)

        def unsewn(b):  # left out of every shell, or next to a free edge
            tol = ON_FACE * b.fit["tolerance"]
            return sewn.isNull() or sewn.distToShape(Part.Vertex(b.probe))[0] > tol or \
                any(b.face.distToShape(e)[0] <= tol for e in free)
        at = [b for b in blended if unsewn(b)]
        if at:
            raise Unassembled(at, "sewing its blend to the faces it meets left %d free "
                              "edge(s) (gaps wider than the sewing tolerance), or the "
                              "blend outside the shell" % len(free))
        raise C2BlendError("sewing the blend faces to the solid failed: %d shell(s), %d free "
                           "edge(s) left (gaps wider than the sewing tolerance)"
                           % (len(shells), len(free)), where, "sewing")
    solids = [_outwards(s) for s in shells]
    solid = max(solids, key=lambda s: s.Volume)  # the outer shell's, around every void
    if len(solids) > 1:
        solid = Part.makeSolid(Part.Compound(
            [solid.Shells[0]] + [s.Shells[0].reversed() for s in solids if s is not solid]))
    # every edge that cutting or sewing made anew (those of OCCT's result are as they
    # were): the blends' edges, and an original face's other edges, rebuilt by the cut
    # (a cylinder's second hole opening kept 1.5e-7 against its pcurve's 2e-7)
    old = {e.hashCode() for e in result.Edges}
    _update_tolerances([e for e in solid.Edges if e.hashCode() not in old], fuzzy)
    _tolerate_cusps(solid, {v.hashCode() for v in result.Vertexes})
    return solid


def _outwards(shell):
    """The solid that the closed `shell` bounds, its faces pointing outwards."""
    solid = Part.Solid(shell)
    if solid.Orientation == "Reversed" or solid.Volume < 0:
        # the sewn faces point inwards and Part.Solid only flagged the solid reversed
        # around them; OCCT's fillet and chamfer of such a solid give an inside-out,
        # invalid one. Reverse the faces themselves instead.
        solid = Part.Solid(Part.Shell([f.reversed() for f in shell.Faces]))
    return solid


def _tolerances(shape):
    """{"vertex": the largest tolerance of shape's vertices, "edge": of its edges}."""
    return {"vertex": max(v.Tolerance for v in shape.Vertexes),
            "edge": max(e.Tolerance for e in shape.Edges)}


def _tolerate_cusps(solid, keep=frozenset()):
    """Raise the tolerance of the vertices at the cusps (_cusps) of each face of `solid`
    that BRepCheck rejects, together, doubling from 1e-6 until it passes, then bisecting
    the last step for the least that does (CUSP_BISECTIONS), each up to CUSP_REACH times
    the shorter of its two edges (else they are left as they were).
    Vertices whose hashCode is in `keep` (OCCT's result's, which it shares with the
    input) are left alone: the input is not modified.
    A concave fillet's end section in the face it ends on is tangent there to that
    face's edge along the other side, and the face it grows meets itself at that point
    at a cusp. A G2 blend's section leaves that edge as d^3 (a G1 one as d^2), so it runs
    within the edges' tolerance of it for a while, and BRepCheck takes the wire for
    self-intersecting unless the vertex's tolerance covers that stretch. Where the face
    cuts the fillet at a shallow angle, the section is stretched and the stretch long:
    the top and bottom faces of the 3-turn helical ridge's cylinder, where the junction
    climbs at 0.064 (pitch 4 on a circumference of 62.8), need 2.5e-3 (R = 0.3; OCCT's
    own G1 fillet there has 1.1e-4 to 1.3e-4; the doubling alone gave 4.1e-3)."""
    if solid.isValid():
        return
    for f in solid.Faces:
        if f.isValid():
            continue
        cusps = [(v, cap) for v, cap in _cusps(f) if v.hashCode() not in keep]
        start = [v.Tolerance for v, _ in cusps]

        def passes(t):  # with the cusps' tolerances t (within their caps), or as they were
            for (v, cap), t0 in zip(cusps, start):
                v.fixTolerance(max(min(t, cap), t0))
            return f.isValid()
        t = 1e-6
        while cusps and not f.isValid() and any(t < cap for _, cap in cusps):
            t *= 2.0
            if passes(t):  # the least that passes, to 2^(1/16), between t / 2 and t
                lo = 0.5 * t
                for _ in range(CUSP_BISECTIONS):
                    mid = math.sqrt(lo * t)
                    lo, t = (lo, mid) if passes(mid) else (mid, t)
                passes(t)
        if not f.isValid():
            passes(0.0)


def _cusps(face):
    """[(vertex, largest tolerance allowed there)] for each vertex of face's wires where
    two consecutive edges leave it in directions within CUSP of each other."""
    out = []
    for w in face.Wires:
        es = [e for e in w.OrderedEdges if not e.Degenerated]
        for a, b in zip(es, es[1:] + es[:1]):
            shared = [v for v in a.Vertexes if any(v.isSame(x) for x in b.Vertexes)]
            if len(shared) != 1 or a.isSame(b):
                continue
            v = shared[0]
            try:
                da, db = leaving(a, v.Point), leaving(b, v.Point)
            except Exception:  # noqa: BLE001 - OCCT's: no tangent there, no cusp found
                continue
            if da.getAngle(db) < CUSP:
                out.append((v, CUSP_REACH * min(a.Length, b.Length)))
    return out


def _sewn(faces):
    """The shells of `faces` sewn together."""
    sewn = Part.Compound(faces)
    sewn.sewShape()
    return sewn.Shells if sewn.ShapeType != "Shell" else [sewn]


def _at_corner(patch, blended):
    """The blends of `blended` that replace fillets ending at the corner patch."""
    return [b for b in blended if any(b.source is c for c in patch.chains)]


def _corner_check(solid, patch, scales):
    """The continuity between the filling at a corner patch and the faces around it
    (check.check_edge along each of its edges): the worst of each measure, with the
    verdict by the report's criteria (scales: check.compare's)."""
    face = _patch_face(solid, patch)
    edges = [e for e in face.Edges if not e.Degenerated]
    creased = [e for e in edges if any(cn.on_edge(e, c) for c in patch.creases)]
    rs = [ck.check_edge(solid, e, scales=scales) for e in edges
          if not any(e is c for c in creased)]
    out = {"where": patch.where(), "face": ck.element_name(solid, face, "Face"),
           "edges": len(rs), "g0": max(r["g0"] for r in rs),
           "g1": max(r["g1"] for r in rs), "g2_rel": max(r["g2_rel"] for r in rs),
           "verdict": min((r["verdict"] for r in rs), key=ck.RANK.get)}
    if creased:  # where it meets a face at an angle, as OCCT's patch or the rim does
        wall = [f for f in solid.ancestorsOfType(creased[0], Part.Face) if not f.isSame(face)]
        out["crease"] = {"edges": len(creased), "face": ck.element_name(solid, wall[0], "Face")
                         if wall else None, "setback": patch.setback is not None}
    return out


def _patch_face(solid, patch):
    """The face of `solid` that fills the hole at the corner patch: the face nearest to
    a point of the patch (of its first face) near its centre."""
    face = patch.faces[0]
    return _nearest_face(solid, face.Surface.value(*face.Surface.parameter(face.CenterOfMass)))


def _nearest_face(solid, point):
    """The face of solid nearest to point (on or next to it): among the faces whose
    bounding box, grown by a millionth of the solid's, holds the point (all faces if
    none does), which spares the distance to most faces of a large solid."""
    grow = 1e-6 * solid.BoundBox.DiagonalLength
    near = []
    for f in solid.Faces:
        box = f.BoundBox  # a copy
        box.enlarge(grow)
        if box.isInside(point):
            near.append(f)
    vertex = Part.Vertex(point)
    return min(near or solid.Faces, key=lambda f: f.distToShape(vertex)[0])


def _unfinished_why(stuck, faces, solid):
    """Why the BOP check of `solid`, with plate fillings `faces`, did not finish, as far as
    is known: the fillings `stuck` (each tried with every trial) where the check of
    their neighbourhood does not finish either; where there are none, but fillings, the
    check of each one's neighbourhood finished (bopcheck._watched checks them all), so
    the whole is slow, or loops elsewhere. A prism with 15 edges filleted at R = 1.954
    and 10 corners filled (tools/fillet_survey.py --random-edges 40 --seed 19 --turned,
    part 36) took 53 s of processor time to pass, its fillings' neighbourhoods 2 to
    10 s each."""
    if stuck:
        return ("it loops on faces tangent along an edge, at the %s, with every plate "
                "filling tried" % ", ".join(f.patch.where() for f in stuck))
    if faces:
        return ("the neighbourhood of each of its %d plate filling(s) passes it within "
                "%.0f s: it is slow on this solid's %d faces, or loops on two faces tangent "
                "along an edge elsewhere" % (len(faces), bc.NEAR_LIMIT, len(solid.Faces)))
    return "it loops on faces tangent along an edge, or is slow on this solid"


def _occt_result_check(shape, result, bop=True):
    """The report's line on a solid returned as OCCT's fillet made it (every chain kept):
    isValid() holds (_rolling_ball), but OCCT's own fillet is not checked further, and
    can fail the BOP argument check that C2Blend's own solids pass (not run when bop is
    False)."""
    if not bop:
        return "OCCT's rolling-ball solid, unchanged: passes isValid(); BOP check skipped"
    try:
        problems = bc.problems(result)
    except bc.Unfinished as ex:
        return ("OCCT's rolling-ball solid, unchanged: it passes isValid(), but %s"
                % ex)
    if problems is None:
        return "OCCT's rolling-ball solid, unchanged: passes BRepCheck and the BOP check"
    orig = _input_problems(shape)
    return ("OCCT's rolling-ball solid, unchanged (FreeCAD's Fillet gives the same): it "
            "passes isValid(), but the BOP check finds: %s%s; Boolean operations on it "
            "may fail" % (problems, "" if orig is None else " (in the input solid: %s)" % orig))


def _input_problems(shape):
    """What the BOP check finds wrong with the input solid (bopcheck.problems), None
    also when the check does not finish."""
    try:
        return bc.problems(shape)
    except bc.Unfinished:
        return None


def _selected(names, chains_):
    """{id(chain): [(name, edge)] of the selected edges it fillets}: each edge goes to
    the chain whose faces are nearest to the edge's midpoint."""
    out = {}
    for n, e in names:
        mid = Part.Vertex(midpoint(e))
        c = min(chains_, key=lambda c: min(f.distToShape(mid)[0] for f in c.faces))
        out.setdefault(id(c), []).append((n, e))
    return out


def _tangent_ends(shape, label, edges):
    """'; ...' naming each end of `edges` [(name, edge)] of shape where its two faces
    become tangent (normals within TANGENT_ANGLE), as where two equal cylinders meet in a
    tee: the rolling ball's fillet shrinks to a point there, which OCCT's faces follow
    and which tells why they do not chain up; '' where none does."""
    out = []
    for n, e in edges:
        faces = ck.edge_faces(shape, e)
        if len(faces) != 2:
            continue
        for v in e.Vertexes:
            a = angle(frame_at_point(faces[0], v.Point).n, frame_at_point(faces[1], v.Point).n)
            if a < TANGENT_ANGLE or math.pi - a < TANGENT_ANGLE:
                out.append("%s.%s at (%.4g, %.4g, %.4g)" % ((label, n) + tuple(v.Point)))
    if not out:
        return ""
    return ("; the two faces become tangent at %s, where the rolling ball's fillet shrinks "
            "to a point: a blend needs two trimlines apart" % ", ".join(out))


def _measure(solid, blended, corners):
    """The continuity measures of a filleted solid for the report: {"trimlines",
    "mitres", "junctions", "corner_patches": [check per trimline, shared edge or filled
    corner patch (rollingball.CornerPatch of `corners`)]}; blended: the blends in it."""
    faces = [(b, _find_face(solid, b)) for b in blended]
    scales = {}  # each face's curvature scale, sampled once for all the checks
    return {"trimlines": _trimline_checks(solid, faces, scales),
            "mitres": _shared_edge_checks(solid, faces, False, scales),
            "junctions": _shared_edge_checks(solid, faces, True, scales),
            "corner_patches": [_corner_check(solid, p, scales) for p in corners]
            if blended else []}


def _trimline_checks(solid, faces, scales):
    """Continuity of the solid across both trimlines of each blend face, at 101 points
    per trimline, evaluated on the blend at known parameters and projected onto the
    neighbouring face of the solid. faces: [(Blended, its face in solid)]; scales:
    check.compare's."""
    out = []
    diag = solid.BoundBox.DiagonalLength
    for b, face in faces:
        for side in (0.0, 1.0):
            v_range = ends.side_range(b, side)
            if v_range is None:
                continue  # the face does not reach this side
            pts = ck.trimline_points(b.surface, side, v_range=v_range)
            probe = Part.Vertex(pts[len(pts) // 2][0])
            nbrs = [f for e in face.Edges for f in ck.edge_faces(solid, e)
                    if not f.isSame(face) and e.distToShape(probe)[0] < 1e-6 * diag]
            if not nbrs:
                raise C2BlendError("the blend face is not joined to a face along u = %g"
                                   % side, b.where, "sewing")
            r = ck.compare(face, nbrs[0], pts, diag, scales=scales)
            r["edge"] = ck.element_name(solid, _edge_near(face, probe), "Edge")
            r["faces"] = [ck.element_name(solid, face, "Face"),
                          ck.element_name(solid, nbrs[0], "Face")]
            r["blend"] = b.where
            r["blend_face"] = r["faces"][0]
            out.append(r)
    return out


def _shared_edge_checks(solid, faces, junctions, scales):
    """Continuity across the edges where two blends meet: at an angle (mitres, junctions
    False), creases by construction, as where OCCT's fillets meet there; or where two
    runs of one chain meet (junctions True), G1 as the side faces are there, with the
    jump of a side face's own curvature there (knots.side_jump, relative:
    side_curvature_jump), which no blend can follow. Reported,
    not counted in the verdict, which is about the trimlines, except a junction whose
    blends meet at a crease (normals more than check.TOL_G1 apart; solve_runs accepts
    up to JUNCTION_TURN). faces: [(Blended, its face in solid)]; scales:
    check.compare's."""
    out = []
    for i, (b, f) in enumerate(faces):
        for o, g in faces[i + 1:]:
            if _consecutive(b, o) != junctions:
                continue
            for e in f.Edges:
                if any(e.isSame(x) for x in g.Edges):
                    r = ck.check_edge(solid, e, scales=scales)
                    r["edge"] = ck.element_name(solid, e, "Edge")
                    r["faces"] = [ck.element_name(solid, f, "Face"),
                                  ck.element_name(solid, g, "Face")]
                    r["blends"] = [b.where, o.where]
                    if junctions:
                        r["side_curvature_jump"] = side_jump(
                            [v.Point for v in e.Vertexes],
                            list(b.chain.sides) + list(o.chain.sides))
                    out.append(r)
    return out


def _consecutive(a, b):
    """Whether blends a and b are runs of one chain that follow one another along it
    (solve_runs: the last run and the first of a closed chain too, Blended.ring; a
    run's own chain attribute is the run, never closed), and so meet at a junction.
    The first and last runs of a chain that is not closed can also share an edge: at a
    sharp corner of the outline that the chain runs round (a plate's top edge, its
    corners rounded but one), where they meet at a mitre as two chains do."""
    group = a.group
    if group is None or group is not b.group:
        return False
    i, j = sorted(next(k for k, x in enumerate(group) if x is y) for y in (a, b))
    return j - i == 1 or (a.ring and (i, j) == (0, len(group) - 1))


def _edge_near(face, vertex):
    return min(face.Edges, key=lambda e: e.distToShape(vertex)[0])


def _occt_face_at(label, face):
    """'Label, OCCT's face at (x, y, z)': a face of OCCT's fillet that no selected edge
    is nearest to (such as the face between two fillets at a vertex), for messages."""
    p = face.CenterOfMass
    return "%s, OCCT's face at (%.4g, %.4g, %.4g)" % (label, p.x, p.y, p.z)


def _find_face(solid, b):
    """The face of solid made from blend b (sewing keeps the surface, not the face)."""
    return _nearest_face(solid, b.probe)


def _rolling_ball(shape, edges, radius):
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
        return _rolling_ball(shape, edges, radius)[0] is not None
    return tried[0]


def _occt_crash(shape, edges, radius):
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


def _invalid_input(shape, msg):
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


def _rolling_ball_failure(shape, names, radius, msg, label):
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
            % (_listed(listed), ", where they meet at %s" % " and ".join(
                "(%.4g, %.4g, %.4g)" % tuple(v.Point) for v in meet) if meet else "", radius,
               "any %d of them" % (len(rest) - 1) if len(rest) > 2 else "either alone",
               _with_others(shape, [e for _, e in names], meet, radius,
                            "; with %s selected too, it succeeds")))


def _with_others(shape, edges, vertices, radius, phrase):
    """phrase % 'the edge from (x, y, z) to (x, y, z) and ...' for the edges of `shape`
    between two faces that end at any of `vertices` and are not among `edges`, where
    OCCT's fillet at `radius` succeeds with them added to `edges`; '' where there are
    none or it fails. The edges are named by their ends: on a compound, the names of
    the edges of one solid are not the user's."""
    others = []
    for v in vertices:
        for e in shape.ancestorsOfType(v, Part.Edge):
            if not e.Degenerated and len(ck.edge_faces(shape, e)) == 2 and \
                    not any(e.isSame(x) for x in edges + others):
                others.append(e)
    if not others or not _works(shape, edges + others, radius):
        return ""
    return phrase % " and ".join(
        "the edge from (%.4g, %.4g, %.4g) to (%.4g, %.4g, %.4g)"
        % (tuple(e.Vertexes[0].Point) + tuple(e.Vertexes[-1].Point)) for e in others)


TIGHT_POINTS = 9  # per edge, where _tight_arc compares the ball's offset and the curvature


def _tight_arc(shape, result, face, radius):
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


def _vertex_hint(shape, names, face, radius):
    """CORNER_HINT for OCCT's face between two fillets at a vertex, naming the edges
    there not among `names` ([(name, Part.Edge)]) with which OCCT's fillet succeeds
    (_with_others), at the solid's vertex nearest to `face` (the one it stands for);
    '' where there are none."""
    v = min(shape.Vertexes, key=lambda x: face.distToShape(x)[0])
    return _with_others(shape, [e for _, e in names], [v], radius, CORNER_HINT)


def _corner_hint(shape, names, own, radius, memo):
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


def fillet(shape, edges, radius, continuity="C2", shape_params=(1.0, 1.0, 1.0, 1.0),
           tension=1.0, label="Shape", tol_rel=1e-8, samples=32, max_samples=1024,
           bop=True):
    """G2 (C2 data) fillet of `edges` of solid `shape` at `radius` (model units).

    edges: Part.Edge objects of shape, 'EdgeN' names or 1-based indices.
    continuity: 'C1', 'C2' or 'C3' (rows of cross-boundary data matched).
    shape_params: (gamma, eta, lambda, rho) for C2, (b, c, d) for C1, (a0..a4) for C3;
    all ones (the default) fits any continuity. tension scales the cross derivatives.
    tol_rel: B-spline fit tolerance relative to each blend's bounding-box diagonal. The
    fit's error in the normal must stay well below the G1 criterion (1e-8 rad): at 1e-7
    the pipe tee's normal angle was 7e-9 rad, at 1e-8 it is 3e-10.
    bop: run OCCT's BOP check on the result (False for a preview: it is half the time
    of a many-edge fillet, and can take its limit, bopcheck.LIMIT; BRepCheck still runs).
    Returns (Part.Solid, report dict). Raises C2BlendError naming `label` and the edge.
    Seams and edges between tangent faces among other edges are left out, as OCCT's
    fillet does, and listed in the report's "skipped_edges" with the reason.
    On a compound of solids, each solid with selected edges is filleted on its own, as
    OCCT's fillet does (solids.py): the result is then a Part.Compound, and the report
    also lists the solids filleted ("solids").
    The input shape is not modified.
    """
    t0 = time.perf_counter()
    radius, shape_params, tension = check_params(radius, continuity, shape_params, tension,
                                                 label)
    skipped = []  # seams and edges between tangent faces in a larger selection
    names = resolve_edges(shape, edges, label, skipped)

    def one(solid, names):
        return _fillet_solid(solid, names, radius, continuity, shape_params, tension, label,
                             tol_rel, samples, max_samples, bop)

    several = sl.separate(shape)
    if several:
        result, report = sl.fillet_each(several, names, label, one, check_solid)
    else:
        check_solid(shape, label)
        result, report = one(shape, names)
    report["skipped_edges"] = skipped
    report["seconds"] = time.perf_counter() - t0
    return result, report


def _fillet_solid(shape, names, radius, continuity, shape_params, tension, label, tol_rel,
                  samples, max_samples, bop):
    """fillet() of the edges `names` ([(name, Part.Edge of shape)]) of the closed solid
    `shape`, with the parameters checked (check_params): (solid, report without
    "skipped_edges")."""
    t0 = time.perf_counter()
    # OCCT's fillet shares faces and edges with its input, and what follows writes to
    # some of them (a tessellation sets a face's Checked flag): work on a copy
    own = [ck.element_name(shape, edge, "Edge") for _, edge in names]  # the solid's names
    shape = shape.copy()
    names = [(n, shape.getElement(o)) for (n, _), o in zip(names, own)]
    where_all = ", ".join("%s.%s" % (label, n) for n, _ in names)
    selected = [e for _, e in names]
    crash = _occt_crash(shape, selected, radius)
    if crash:
        raise C2BlendError(crash, where_all, "radius")
    result, msg = _rolling_ball(shape, selected, radius)
    if result is None and not shape.isValid():
        raise C2BlendError(_invalid_input(shape, msg), label)
    if result is None:
        raise C2BlendError(_rolling_ball_failure(shape, names, radius, msg, label), where_all,
                           "radius")
    t_occt = time.perf_counter() - t0
    fillet_faces = new_faces(shape, result)
    if not fillet_faces:
        raise C2BlendError("radius %g is too small: OCCT's fillet of it cannot be told "
                           "apart from the faces it joins (it lies within %.2g of them, 10 "
                           "times their tolerance); use a larger radius"
                           % (radius, max(off_boundary(f) for f in result.Faces)),
                           where_all, "radius")
    blended, kept = [], []
    rbfs = [RollingBallFace(result, f, fillet_faces) for f in fillet_faces]
    for r in rbfs:  # OCCT's face between a convex and a concave fillet: set back
        if r.between:
            try:
                r.setback = sb.Setback(result, r.face, fillet_faces, radius,
                                       lambda f: _original(shape, f))
            except (ValueError, Part.OCCError) as ex:
                r.corner += " (it cannot be set back: %s)%s" % (
                    ex, _tight_arc(shape, result, r.face, radius))
                continue
            r.patch, r.corner = True, None
    all_chains, patches = chains(rbfs)
    selected = _selected(names, all_chains)
    for chain in all_chains:
        edges = selected.get(id(chain), [])
        where = ", ".join("%s.%s" % (label, n) for n, _ in edges) or \
            _occt_face_at(label, chain.faces[0])
        if chain.corner:
            reason = chain.corner + _tangent_ends(shape, label, edges)
            if any(m.between for m in chain.members):
                reason += _vertex_hint(shape, names, chain.faces[0], radius)
            kept.append({"where": where, "reason": reason})
            continue
        try:
            new = solve_chain(chain, radius, where, continuity, shape_params, tension,
                              tol_rel, samples, max_samples, fillet_faces)
        except NotReplaced as ex:
            kept.append({"where": where, "reason": str(ex)})
            continue
        for b in new:
            b.source = chain
        blended += new
    t_solve = None
    measured = {}  # the solid whose continuity was measured, and the measures

    def measure(solid):
        t = time.perf_counter()
        try:
            checks = _measure(solid, blended, filled)
        except Exception:  # noqa: BLE001 - measured again once the solid is checked,
            return  # whose findings then explain it first
        measured.update(solid=solid, checks=checks, seconds=time.perf_counter() - t)

    hints = {}  # for _corner_hint
    while True:  # a blend that cannot be cut back or cut into its faces is kept as OCCT's
        filled = joined([p for p in patches if _at_corner(p, blended)], all_chains)
        failed = ends.trim(blended, lambda f: _original(shape, f))
        if not failed:
            t_solve = t_solve or time.perf_counter()
            try:
                if blended:
                    solid, solid_check = assemble(shape, result, blended, fillet_faces,
                                                  where_all, filled, bop, measure)
                else:
                    solid = result.Solids[0] if len(result.Solids) == 1 else result
                    solid_check = _occt_result_check(shape, solid, bop)
                break
            except Unassembled as ex:
                failed = [(b, str(ex)) for b in ex.blends]
            except Part.OCCError as ex:  # not foreseen: OCCT's solid stands, and says why
                failed = [(b, "OCCT failed while the blends were assembled into the solid "
                           "(%s)" % occt_message(ex)) for b in blended]
        drop = []
        for b, reason in failed:
            if not any(b is x for x in drop):  # with the other runs of its chain, once
                kept.append({"where": b.where, "reason": reason + _corner_hint(
                    shape, names, selected.get(id(b.source), []), radius, hints)})
                drop += b.group or [b]
        blended = [b for b in blended if not any(b is x for x in drop)]
    t_assemble = time.perf_counter()
    overlapped = measured.get("seconds", 0.0) if measured.get("solid") is solid else 0.0
    if not overlapped:  # not measured while the BOP check ran
        measured.update(solid=solid, checks=_measure(solid, blended, filled))
        measured["seconds"] = time.perf_counter() - t_assemble
    checks, corner_checks = measured["checks"]["trimlines"], measured["checks"]["corner_patches"]
    for p in patches:  # not filled: OCCT's corner patch, or its face between two fillets
        if not any(r is x for q in filled for x in q.rbfs for r in p.rbfs):
            kept.append({"where": p.where(), "reason": "OCCT's corner patch, kept with the "
                         "fillets that meet there" if p.setback is None else
                         BETWEEN + _vertex_hint(shape, names, p.faces[0], radius)})
    report = {
        "continuity": continuity, "radius": radius, "shape_params": list(shape_params),
        "tension": tension,
        "blends": [{"where": b.where, "samples": b.samples, "data_error": b.data_rel,
                    "fit_deviation": b.fit["deviation"], "fit_tolerance": b.fit["tolerance"],
                    "poles": list(b.fit["poles"].shape[:2]),
                    "closed": b.chain.closed, "pointwise": b.group is not None}
                   for b in blended],
        "kept_occt_faces": kept,
        "solid_check": solid_check,
        **measured["checks"],
        "volume": solid.Volume, "occt_volume": result.Volume,
        "tolerance": {**_tolerances(solid), **{"occt_" + k: x for k, x
                                               in _tolerances(result).items()}},
        "seconds": time.perf_counter() - t0, "occt_seconds": t_occt,
        # the continuity check overlaps OCCT's BOP check (in another process): the
        # stages count that time once, in continuity_check
        "stage_seconds": {"occt_fillet": t_occt, "trimlines_solve_fit": t_solve - t0 - t_occt,
                          "sew_and_brepcheck": t_assemble - t_solve - overlapped,
                          "continuity_check": measured["seconds"]},
    }
    creased = [j for j in measured["checks"]["junctions"] if j["g1"] > ck.TOL_G1]
    report["verdict"] = min([c["verdict"] for c in checks + corner_checks + creased]
                            + (["G1"] if kept else []),
                            key=ck.RANK.get) if (checks or kept) else "none"
    return solid, report
