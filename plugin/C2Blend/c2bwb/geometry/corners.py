# SPDX-License-Identifier: LGPL-2.1-or-later
"""Corner patches where three or more fillets meet at a vertex (fillet.py).

OCCT closes such a vertex with a corner patch (a sphere where three equal fillets meet
on a box) that joins each rolling-ball face along that face's circular end section. A
PDE blend's end section is not that circle, so where every fillet at a corner is
replaced by a blend (rollingball.CornerPatch), the patch is replaced as well: the blends
stop at the ball's sections (ends.py) and the hole they leave in the sewn shell is
filled by OCCT's plate filling (BRepFill_Filling through FreeCAD's Surface::Filling),
tangent (G1 order) to the blend and face along each edge of the hole. The plate is an
approximation: its seams are off by about 1e-6 and turn from the neighbouring faces'
tangent planes by 1e-5 to 1e-4 rad, which the report measures. It is never claimed
G2, and it is not G1 in this report's strict sense (1e-8 rad).
"""
import FreeCAD
import Part

from . import check as ck

# OCCT's plate filling, degree 5 with 30 points per edge. Its approximation error
# varies erratically with the maximum degree, corner by corner: on a box's 8 corners
# (R = 2) the worst seam was 6.3e-5, 1.4e-4, 8.6e-5 and 7.9e-5 rad with maximum degree
# 10, 11, 12 and 13, each corner's best being 1e-5 to 4e-5 rad; FreeCAD's default (8)
# gave 1.6e-4 rad on one corner, and degree 3 (FreeCAD's default) 2.2e-3 rad. So each
# maximum degree of MAX_DEGREES is tried until a seam is within GOOD_G1, keeping the
# best.
FILL = {"Degree": 5, "PointsOnCurve": 30, "MaximumSegments": 12, "Iterations": 2,
        "Tolerance3d": 1e-6, "TolAngular": 1e-4}
MAX_DEGREES = (12, 10, 13)
GOOD_G1 = 2e-5  # rad
SEAM_POINTS = 21  # per edge, where a filling's seams are measured


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
        d = [p.face.distToShape(mid)[0] for p in patches]
        k = min(range(len(patches)), key=d.__getitem__)
        if d[k] > tol:
            raise Unfilled("the sewn faces leave a gap away from every corner patch")
        out[k].append(e)
    return out


def fill(shell, edges, degrees=MAX_DEGREES):
    """(face, maximum degree): the face filling the hole bounded by `edges` (free edges
    of `shell`), tangent to each edge's face in the shell (OCCT's plate, FILL), with
    each of `degrees` tried as its maximum degree until a seam is within GOOD_G1, the
    best kept. Built in a hidden temporary document, which is closed again; the active
    document is left as it was. Raises Unfilled."""
    edges = _in_order(edges)
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
        best = None  # (worst seam angle, face, degree)
        scales = {}  # the shell faces' curvature scales, shared by the degrees tried
        for degree in degrees:
            filling = doc.addObject("Surface::Filling", "Fill")
            for key, value in FILL.items():
                setattr(filling, key, value)
            filling.MaximumDegree = degree
            filling.BoundaryEdges = names
            filling.BoundaryFaces = faces
            filling.BoundaryOrder = [1] * len(names)  # G1: tangent to each face
            filling.recompute()
            result = filling.Shape
            if result.isNull() or len(result.Faces) != 1 or not result.isValid():
                continue
            face = result.Faces[0].copy()
            turn = _seam_angle(face, shell, edges, scales)
            if best is None or turn < best[0]:
                best = (turn, face, degree)
            if turn <= GOOD_G1:
                break
        if best is None:
            raise Unfilled("OCCT's plate filling of its %d-sided hole failed" % len(edges))
        return best[1:]
    finally:
        FreeCAD.closeDocument(doc.Name)


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


def _seam_angle(face, shell, edges, scales=None):
    """The largest angle (rad) between the normals of a filling `face` and of the
    shell's faces along `edges`, at SEAM_POINTS per edge (scales: check.compare's)."""
    diag = shell.BoundBox.DiagonalLength
    worst = 0.0
    for e in edges:
        pts = [(e.valueAt(t), e.tangentAt(t), None)
               for t in ck.sample_params(e, SEAM_POINTS)]
        r = ck.compare(face, shell.ancestorsOfType(e, Part.Face)[0], pts, diag,
                       oriented=False, scales=scales)
        worst = max(worst, r["g1"])
    return worst
