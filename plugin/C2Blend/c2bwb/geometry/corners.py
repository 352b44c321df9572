# SPDX-License-Identifier: LGPL-2.1-or-later
"""Corner patches where three or more fillets meet at a vertex (fillet.py).

OCCT closes such a vertex with a corner patch (a sphere where three equal fillets meet
on a box) that joins each rolling-ball face along that face's circular end section. A
PDE blend's end section is not that circle, so where a fillet at a corner is replaced
by a blend (rollingball.CornerPatch), the patch is replaced as well: the blends stop at
the sections of the ball that touches the corner's three faces, or are cut along
OCCT's end edge where it is no section (ends.py), and the hole they leave in the sewn
shell, bounded by their ends, the end sections of the fillets kept as OCCT made them
there, and faces, is filled by OCCT's plate filling
(BRepFill_Filling through FreeCAD's Surface::Filling), tangent (G1 order) to the blend,
fillet or face along each edge of the hole. The plate is an approximation: its seams
are off by about 1e-6 and turn from the neighbouring faces' tangent planes by 1e-5 to
1e-4 rad (up to 1.7e-3 on B-spline corners), which the report measures. It is never
claimed G2, and it is not G1 in this report's strict sense (1e-8 rad).
"""
import math

import FreeCAD
import Part

from . import check as ck
from .surface import angle, frame_at_point

# OCCT's plate filling, degree 5. Its approximation error varies erratically with the
# maximum degree and the number of points per edge, corner by corner: on a box's 8
# corners (R = 2, 30 points) the worst seam was 6.3e-5, 1.4e-4, 8.6e-5 and 7.9e-5 rad
# with maximum degree 10, 11, 12 and 13, each corner's best being 1e-5 to 4e-5 rad;
# FreeCAD's default (8) gave 1.6e-4 rad on one corner, and degree 3 (FreeCAD's default)
# 2.2e-3 rad. On a spline extrusion's top corners (R = 1) 30 points gave 1.1e-4 to
# 1.2e-3 rad at every degree and 40 points 2.4e-5 to 4.5e-4; at a spline block's top
# corner 30 points gave 1.8e-4 to 1.1e-3 rad, and a plate that OCCT's BOP check finds
# self-intersecting, at every degree from 6 to 14, and 40 points 5e-5 to 1.5e-4 rad
# and none. So each (maximum degree, points per edge) of TRIALS, solved once, is tried
# in turn until a seam is within GOOD_G1, keeping the best: one to three on a box's
# corners.
# The plate is solved once (Iterations 1; FreeCAD's default, 2, solves it again on the
# first one): solved twice, the spline block's corner near (0, 0, 15) turned from its
# blends by 3.8e-4 to 1.1e-3 rad over the trials, and by 4.4e-3 to 9.4e-3 rad once
# every blend's poles were changed in their 16th digit; solved once, by 3.8e-4 to
# 1.4e-3 rad either way. At the other 23 corners of seven corner tests (box, block,
# prism, brackets, revolution), each with and without that change, the best seam over
# the trials was at most 2.2e-4 rad solved twice and 1.6e-4 solved once; it changed by
# more than 1e-5 rad only at the gusset's (2.1e-4 and 2.2e-4 to 1.6e-4) and at another
# of the block's (1.1e-4 to 1.6e-4, perturbed). The BOP check's time depends on the
# plates erratically: solved once, the perturbed L bracket's plate (same trial, same
# poles count) made it take 9.5 s, not under 2 s. MaximumSegments 20 gave better seams
# still, but plates that made OCCT's BOP check of a box with 12 fillets take 10 s, not
# 4.4 s.
FILL = {"Degree": 5, "MaximumSegments": 12, "Tolerance3d": 1e-6, "TolAngular": 1e-4}
ONCE, TWICE = 1, 2  # a trial's Iterations: the plate solved once, or solved again
# Where no plate solved once is fit to keep (each bulges beyond a plane it is tangent to,
# or turns from the faces by more than MAX_SEAM), the same are solved twice: at a
# setback corner (shapes.step at R = 1), every plate solved once bulged 0.028 R to 3.4 R
# above the top face once the blends moved by 2e-13 (their turn: 3.9e-3 to 0.16 rad),
# and every plate solved twice stayed below it, turning by 1.0e-3 to 5.3e-3 rad.
# Where no plate of either kind is fit to keep, each size is solved once more through
# pins: the points of OCCT's own corner patch (the patch the filling replaces) at the
# interior nodes of a GUIDE_GRID x GUIDE_GRID grid of its parameters (those on the
# face), each moved by the hole's edges' offsets from that patch, weighted by inverse
# squared distance (Shepard's interpolation), so that the pins follow the hole where
# its edges leave OCCT's patch (the blends' end sections are no arcs). At the spline
# block's corner near (0, 0, 15) (R = 1), where every unpinned plate spanned 6.6 to 9.3
# and OCCT's patch spans 2.2 on a rim 5.4 long, the hole's edges lie up to 0.057 off
# OCCT's patch; through the 8 grid's moved pins every size gave a plate spanning 2.26,
# turning from the blends by 1.5e-3 to 2.1e-3 rad; through pins not moved, 2.28 to 2.29
# and 3.6e-3 to 8.0e-3 rad, two sizes failing; through a 6 grid's, 2.33 to 2.38 and
# 5.3e-4 to 9.0e-3 rad, one failing; through a 4 grid's, 3.0 to 3.1. At a setback
# corner OCCT's face spans only part of the hole: at shapes.tall_step's (R = 2.5) the
# plates through its pins spanned 14.4 to 15.2 and turned by 0.028 to 0.13 rad, so no
# plate is pinned there (rollingball.CornerPatch.guide is None).
UNPINNED, PINNED = False, True
GUIDE_GRID = 8
_SIZES = ((12, 30), (10, 30), (13, 30), (12, 40), (10, 40), (13, 40))
TRIALS = tuple(s + (ONCE, UNPINNED) for s in _SIZES) + \
    tuple(s + (TWICE, UNPINNED) for s in _SIZES) + tuple(s + (ONCE, PINNED) for s in _SIZES)
GOOD_G1 = 2e-5  # rad
# rad: a plate turning further from the faces around its hole does not fill it (at a
# corner where blends end 1e-4 from a fillet kept as OCCT's, one folded over, 2 rad,
# and the solid, valid, lost 200 mm3); the worst kept corner seen is 1.7e-3 rad (the
# gusset bracket at R = 0.5)
MAX_SEAM = 1e-2
# no filling of a corner's hole spans more than a hemisphere whose rim is as long as the
# hole's edges, P^2 / (2 pi) (an octant of a sphere spans 0.07 P^2, a flat disc 0.08 P^2):
# at a 4-sided hole of perimeter 17.6 (shapes.tall_step, R = 2.5), where OCCT's corner
# patch spans 8.1, the 12 trials' plates spanned 189 to 240, the best turning from the
# faces along its seams by 4.9e-3 rad (within MAX_SEAM); it cut through a blend and the
# bottom face, and the sewn solid failed the BOP check;
# at the spline block's corner near (0, 0, 15) (R = 1, a 52 degree wedge) they
# spanned 6.6 to 9.3 against a hemisphere's 4.6 on its rim and OCCT's patch's 2.2, rising
# 0.64 above the top face while their seams met the blends within 1.4e-3 rad
MAX_AREA = 1.0 / (2.0 * math.pi)  # times the perimeter squared
# no filling of a corner's hole where OCCT's corner patch lies along the hole (no
# setback) spans more than GUIDE_AREA times that patch: at the partial revolution's
# corners at R = 2 (shapes.partial_revolution), plates at two mirrored corners spanned
# 3.5 and 8.9 where OCCT's patches span 3.45, and at a third 9.3 where OCCT's spans
# 2.98, all within a hemisphere on their rims; the plates kept there since span 1.02
# to 1.04 times OCCT's patch
GUIDE_AREA = 1.5
# no filling that rises beyond a plane face it is tangent to (by more than twice its
# seams' gap) is kept where it rises by more than MAX_BULGE times the hole's size (its
# edges' box diagonal): at a setback corner where the top face wraps 270 degrees round
# the vertex left sharp (shapes.chamfered_pocket), every trial rose 0.03 R to 1 R above
# the top face (7e-3 to 0.21 of the hole's size, R = 0.171 and 0.45). Of the 183
# corners filled in three surveys (tools/fillet_survey.py --random-edges 40 --seed 59
# --turned, --random-machined 40 --seed 2, --random-edges 40 --seed 5), one had trials
# that rise (by 2e-6 to 0.051, its hole 3.36 across), and one that does not was kept
MAX_BULGE = 1e-3
SEAM_POINTS = 21  # per edge, where a filling's seams are measured
BULGE_GRID = 16  # intervals per parameter where a filling's bulge is measured


class Unfilled(Exception):
    """A hole left by blends around a corner patch cannot be filled; the message says
    why."""


def holes(shell, patches, tol):
    """The free edges of the sewn shell (those with one face), each assigned to the
    patch (rollingball.CornerPatch, at least one) nearest to it: [[edge, ...] per patch]. Raises
    Unfilled when a free edge is farther than tol from every patch: the hole is a
    sewing gap, not a corner."""
    out = [[] for _ in patches]
    for e in shell.Edges:
        faces = shell.ancestorsOfType(e, Part.Face)
        if len(faces) != 1 or e.isSeam(faces[0]) or e.Degenerated:
            continue
        mid = Part.Vertex(e.valueAt(0.5 * (e.FirstParameter + e.LastParameter)))
        d = [p.region.distToShape(mid)[0] for p in patches]
        k = min(range(len(patches)), key=d.__getitem__)
        if d[k] > tol:
            raise Unfilled("the sewn faces leave a gap away from every corner patch")
        out[k].append(e)
    return out


def fill(shell, edges, guide, trials=TRIALS, creases=()):
    """(face, trial): the face filling the hole bounded by `edges` (free edges of
    `shell`), tangent to each edge's face in the shell (OCCT's plate, FILL), with each
    (maximum degree, points per edge, iterations, pinned) of `trials` tried until a seam
    is within GOOD_G1, the best kept, those solved twice only where none solved once is
    fit to keep, and those pinned to the `guide` face (OCCT's corner patch, or None: no
    pinned trial) only where none of the others is (TRIALS). A filling that rises
    beyond a plane it is tangent to by more than twice its seams' gap ranks after every
    one that does not, and is not kept where it rises by more than MAX_BULGE of the
    hole's size; one that spans more than MAX_AREA, or GUIDE_AREA times the
    guide, is never kept, and its seams are not measured. Through the edges on
    `creases` (edges) only, not tangent there (rollingball.CornerPatch.creases: a
    setback corner's edge on the face whose rim stays sharp, setback.py, or where
    OCCT's patch meets a face at an angle).
    Built in a hidden temporary document, which is closed again; the active document
    is left as it was. Raises Unfilled."""
    edges = _in_order(edges)
    orders = [0 if any(on_edge(e, c) for c in creases) else 1 for e in edges]
    doc = FreeCAD.newDocument("C2BlendCorner", hidden=True, temp=True)
    try:
        holder = doc.addObject("Part::Feature", "Shell")
        holder.Shape = shell
        names, faces = [], []
        for e in edges:
            k = next(i for i, x in enumerate(shell.Edges) if x.isSame(e))
            f = shell.ancestorsOfType(e, Part.Face)[0]
            j = next(i for i, x in enumerate(shell.Faces) if x.isSame(f))
            names.append((holder, "Edge%d" % (k + 1)))
            faces.append("Face%d" % (j + 1))
        tangent = [e for e, k in zip(edges, orders) if k]
        pinned = None  # the pins' vertices, made for the first pinned trial
        planes = _planes(shell, tangent, edges)
        size = Part.Compound(edges).BoundBox.DiagonalLength
        most = (MAX_AREA * sum(e.Length for e in edges) ** 2, "a hemisphere on the hole's rim")
        if guide is not None and GUIDE_AREA * guide.Area < most[0]:
            most = (GUIDE_AREA * guide.Area, "%g times OCCT's corner patch" % GUIDE_AREA)
        # ((too large, bulges: 0 no, 1 within MAX_BULGE, 2 more, worst seam angle), face,
        # trial)
        best, areas, rises = None, [], []
        for trial in trials:
            if trial[3] and guide is None:
                continue
            if best is not None and _kind(trial) > _kind(best[2]) and \
                    not any(best[0][:2]) and best[0][2] <= MAX_SEAM:
                break  # a filling of an earlier kind is fit to keep
            filling = doc.addObject("Surface::Filling", "Fill")
            for key, value in FILL.items():
                setattr(filling, key, value)
            filling.MaximumDegree, filling.PointsOnCurve, filling.Iterations = trial[:3]
            if trial[3]:
                if pinned is None:
                    pins = doc.addObject("Part::Feature", "Pins")
                    pins.Shape = Part.Compound([Part.Vertex(p) for p in _pins(guide, edges)])
                    pinned = [(pins, "Vertex%d" % (i + 1))
                              for i in range(len(pins.Shape.Vertexes))]
                filling.Points = pinned
            filling.BoundaryEdges = names
            filling.BoundaryFaces = faces
            filling.BoundaryOrder = orders  # 1: tangent to the edge's face
            filling.recompute()
            result = filling.Shape
            if result.isNull() or len(result.Faces) != 1 or not result.isValid():
                continue
            face = result.Faces[0].copy()
            areas.append(face.Area)
            if areas[-1] > most[0]:  # never kept, so not measured (slow on such a plate)
                rank = (True, 2, math.inf)
            else:
                turn, gap = _seam(face, shell, tangent)
                rises.append(_bulge(face, planes))
                rank = (False, 0 if rises[-1] <= 2.0 * gap + 1e-7 * size else
                        1 if rises[-1] <= MAX_BULGE * size else 2, turn)
            if best is None or rank < best[0]:
                best = (rank, face, trial)
            if not any(rank[:2]) and rank[2] <= GOOD_G1:
                break
        if best is None:
            raise Unfilled("OCCT's plate filling of its %d-sided hole failed" % len(edges))
        if best[0][0]:
            raise Unfilled("OCCT's plate filling of its %d-sided hole spans %.3g to %.3g "
                           "over %d trials, more than %s (%.3g): it does not fill the hole"
                           % (len(edges), min(areas), max(areas), len(areas), most[1],
                              most[0]))
        if best[0][2] > MAX_SEAM:
            raise Unfilled("OCCT's plate filling of its %d-sided hole turns from the faces "
                           "around it by %.2g rad at best" % (len(edges), best[0][2]))
        if best[0][1] == 2:
            raise Unfilled("OCCT's plate filling of its %d-sided hole rises %.2g to %.2g "
                           "(%.2g to %.2g of the hole's size) above a plane face it is "
                           "tangent to over %d trials: it would bump out of the solid"
                           % (len(edges), min(rises), max(rises), min(rises) / size,
                              max(rises) / size, len(rises)))
        return best[1:]
    finally:
        FreeCAD.closeDocument(doc.Name)


def _kind(trial):
    """0, 1 or 2: a trial solved once, solved twice, or pinned (TRIALS' order)."""
    return 2 if trial[3] else (1 if trial[2] == TWICE else 0)


def _pins(face, edges):
    """The points of `face` at the interior nodes of a GUIDE_GRID x GUIDE_GRID grid of
    its parameters that lie on it, each moved by the offsets of the hole's `edges` from
    the face (at SEAM_POINTS per edge, from the nearest point of the face), weighted by
    the inverse square of the distance to that nearest point."""
    rim = [e.valueAt(t) for e in edges for t in ck.sample_params(e, SEAM_POINTS)]
    near = [face.distToShape(Part.Vertex(q))[1][0][0] for q in rim]
    u0, u1, v0, v1 = face.ParameterRange
    grid = [(u0 + (u1 - u0) * i / GUIDE_GRID, v0 + (v1 - v0) * j / GUIDE_GRID)
            for i in range(1, GUIDE_GRID) for j in range(1, GUIDE_GRID)]
    out = []
    for p in (face.Surface.value(u, v) for u, v in grid if face.isPartOfDomain(u, v)):
        weights = [1.0 / max((p - r).Length, 1e-12) ** 2 for r in near]
        move = FreeCAD.Vector()
        for w, q, r in zip(weights, rim, near):
            move += (q - r) * w
        out.append(p + move * (1.0 / sum(weights)))
    return out


def on_edge(e, other):
    """Whether edge e lies along `other` (its middle and quarter points within 1e-7 of
    the size of e's box, plus 1e-9): a piece of it, after a cut or sewing."""
    tol = 1e-7 * e.BoundBox.DiagonalLength + 1e-9
    a, b = e.FirstParameter, e.LastParameter
    return all(other.distToShape(Part.Vertex(e.valueAt(a + (b - a) * k)))[0] <= tol
               for k in (0.25, 0.5, 0.75))


def _in_order(edges):
    """The hole's edges in the order they follow one another around it (each shares a
    vertex with the next), as OCCT's filling requires: the shell lists them in its own
    order, which is not the hole's at a corner where fillets of both kinds meet. Raises
    Unfilled when they do not form one closed loop."""
    rest, out = list(edges[1:]), [edges[0]]
    end = edges[0].Vertexes[-1]
    while rest:
        k = next((i for i, e in enumerate(rest)
                  if any(end.isSame(v) for v in e.Vertexes)), None)
        if k is None:
            raise Unfilled("the %d edges around the hole do not form one loop" % len(edges))
        e = rest.pop(k)
        end = next((v for v in e.Vertexes if not end.isSame(v)), end)
        out.append(e)
    if not any(end.isSame(v) for v in edges[0].Vertexes):
        raise Unfilled("the %d edges around the hole do not form one loop" % len(edges))
    return out


def _seam(face, shell, edges):
    """(angle, gap): the largest angle (rad) between the normals of a filling `face` and
    of the shell's faces along `edges`, and the largest distance between the edges and
    the filling, at SEAM_POINTS per edge, with the filling turned once for all to face
    the shell's way (where its normal agrees with the shell's over most of the seam): a
    plate folded over along part of its seam is then about pi off there, where a
    point-by-point choice of side would hide it."""
    pairs, gap = [], 0.0
    for e in edges:
        f = shell.ancestorsOfType(e, Part.Face)[0]
        ga = gb = None  # each projection starts from the previous point's, along the edge
        for t in ck.sample_params(e, SEAM_POINTS):
            p = e.valueAt(t)
            a, b = frame_at_point(face, p, ga), frame_at_point(f, p, gb)
            ga, gb = (a.u, a.v), (b.u, b.v)
            pairs.append((a.n, b.n))
            gap = max(gap, (a.p - p).Length)
    side = 1.0 if sum(a.dot(b) for a, b in pairs) >= 0.0 else -1.0
    return max(angle(a * side, b) for a, b in pairs), gap


def _planes(shell, tangent, edges):
    """[(point, normal)] of the planar faces of the shell along the `tangent` edges of a
    hole bounded by `edges`, each normal pointing away from the hole: to the side of the
    plane opposite the hole's edges that leave it (the edges of a hole lie on one side of
    a plane that its filling is tangent to, or on it)."""
    out = []
    for e in tangent:
        f = shell.ancestorsOfType(e, Part.Face)[0]
        if not f.Surface.isPlanar() or any(f.isSame(g) for g, _, _ in out):
            continue
        p = e.valueAt(e.FirstParameter)
        n = f.Surface.normal(*f.Surface.parameter(p))
        off = sum((x.valueAt(x.FirstParameter + (x.LastParameter - x.FirstParameter) * k) - p)
                  .dot(n) for x in edges for k in (0.25, 0.5, 0.75))
        out.append((f, p, -n if off > 0.0 else n))
    return [(p, n) for _, p, n in out]


def _bulge(face, planes):
    """How far (model units, 0 if not at all) a filling `face` rises beyond the planes
    (_planes) it should stay behind, at the points of a BULGE_GRID x BULGE_GRID grid
    of its parameters that lie on it. Only the points that rise are tested to lie on
    the face, highest first (the test costs far more than the point: 0.37 s a filling
    for the whole grid)."""
    if not planes:
        return 0.0
    u0, u1, v0, v1 = face.ParameterRange
    grid = [(u0 + (u1 - u0) * i / BULGE_GRID, v0 + (v1 - v0) * j / BULGE_GRID)
            for i in range(BULGE_GRID + 1) for j in range(BULGE_GRID + 1)]
    rises = sorted(((max((face.Surface.value(u, v) - p).dot(n) for p, n in planes), u, v)
                    for u, v in grid), reverse=True)
    return next((max(h, 0.0) for h, u, v in rises if h <= 0.0 or face.isPartOfDomain(u, v)),
                0.0)
