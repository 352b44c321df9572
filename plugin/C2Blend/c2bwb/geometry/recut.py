# SPDX-License-Identifier: LGPL-2.1-or-later
"""The original solid's faces cut anew along the blends' boundary edges (assembly.py).

A face of OCCT's result is traced back to the original face it lies on (original_face,
piece_of). An end face grows by the region between its corner and the blend's end
section where the fillet uncovers its surface, and a face by the region between its
corner and a corner patch's edge cutting across it (parts_along, grown_face). A face is
cut along the edges lying on it, keeping the pieces that no fillet consumed (cut_face).
After sewing, edge tolerances are raised to what the new pcurves need
(update_tolerances).
"""
import math

import FreeCAD
import Part

from ..errors import occt_message
from . import strips as st
from .rollingball import interior_points
from .surface import face_distance, mesh_area, off_surface, only_c0, periods


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


def piece_of(face, origs, tol):
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


def original_face(shape, face):
    """The face of the original solid `shape` that a face of OCCT's result lies on: the
    nearest to a point inside it of those whose surface holds that point (a concave
    fillet extends its end faces beyond the original ones)."""
    p = _probe(face)
    tol = 1e-7 * shape.BoundBox.DiagonalLength
    on = [g for g in shape.Faces if off_surface(g.Surface, p) <= tol] or shape.Faces
    return min(on, key=lambda g: face_distance(g, p))


def extended_surface(face, tol):
    """face's surface, or where that is a B-spline or Bezier patch lying on a plane
    within tol (a plane exported to STEP as a B-spline, a face after toNurbs()), that
    plane: the patch ends at the face's boundary, the plane goes on beyond it, as a
    face grown by a fillet's end needs (_growth, _leg_along)."""
    s = face.Surface
    if isinstance(s, (Part.BSplineSurface, Part.BezierSurface)) and s.isPlanar(tol):
        return face.findPlane(tol) or s
    return s


def extensible(face, tol):
    """face, or where its surface is a planar patch (extended_surface), the same face
    on the plane: its wires, so its edges, shared, and oriented as face. The plane may
    come the other way up, and a face on it with face's wires is then not valid: its
    reverse is taken. Where neither is valid with face's area, face itself. (OCCT's
    area of a face bounded by B-spline arcs is approximate: a 3 x 4 rectangle with a
    hole r = 1, made B-splines, has 8.8677 on the patch and 8.8720 on the plane, where
    12 - pi = 8.8584; so the areas are compared to 1e-2.)"""
    s = face.Surface
    plane = extended_surface(face, tol)
    if isinstance(s, Part.Plane) or not isinstance(plane, Part.Plane):
        return face
    p = _probe(face)
    for side in (plane, Part.Plane(plane.Position, -plane.Axis)):
        out = Part.Face(side, face.Wires)
        if out.isValid() and abs(out.Area - face.Area) <= 1e-2 * face.Area:
            if out.normalAt(*side.parameter(p)).dot(face.normalAt(*s.parameter(p))) < 0:
                out.reverse()
            return out
    return face


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
    if other is None:
        return None
    return _leg_crossing(face, other, e.hashCode(), p, corner, tol, crossings)


def _leg_crossing(face, other, key, p, corner, tol, crossings):
    """The leg (_leg) from point p to `corner` along a curve where face's surface
    crosses surface `other`, or None where p is not on `other` or on such a curve.
    crossings: a dict keeping the intersection curves under `key`, computed once."""
    if off_surface(other, p) > tol:
        return None
    if key not in crossings:
        try:
            crossings[key] = face.Surface.intersectSS(other)
        except Part.OCCError:
            crossings[key] = []
    return next((g for g in (_leg(c, p, corner, tol) for c in crossings[key])
                 if g is not None), None)


def _growth(face, edge, tol, across=lambda e: None, meeting=lambda v: []):
    """The region by which a fillet's end extends `face`: a concave fillet adds
    material, a convex one ending on a face that bulges out (a box edge ending on a
    cylinder) uncovers some. The region lies on the face's surface, bounded by `edge`
    (the blend's end section, on that surface outside the face) and two legs from its
    ends to a vertex of the face (the corner), along the curves of the face's edges
    there, extended past them where needed (_leg_along; across(e): the surface beyond
    face's edge e, or None); where no corner has two such legs, one of them may run
    along the surface of another face of the solid at the corner (_leg_meeting;
    meeting(v): [(key, surface)] of those at face's vertex v). Returns (region face,
    corner point, legs), or None when edge does not span such a corner or bounds no
    region with the legs."""
    ends = [v.Point for v in edge.Vertexes]
    if len(ends) != 2:
        return None
    crossings = {}  # for _leg_along and _leg_meeting
    tried = []  # (corner, [its leg from each end along the face's edges, or None])
    for corner in face.Vertexes:
        at = [e for e in face.Edges
              if not e.Degenerated and any(corner.isSame(v) for v in e.Vertexes)]
        tried.append((corner, [next((g for g in (_leg_along(face, e, p, corner.Point, tol,
                                                            across, crossings)
                                                 for e in at) if g is not None), None)
                               for p in ends]))
    spans = [(sum(g.Length for g in legs), corner, legs) for corner, legs in tried
             if None not in legs]  # (length of the legs, corner, legs)
    if not spans:  # one leg, missing, may run along another face at the corner
        for corner, legs in tried:
            if legs.count(None) == 1:
                k = legs.index(None)
                legs[k] = _leg_meeting(face, ends[k], corner, tol, meeting, crossings)
                if legs[k] is not None:
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


def _leg_meeting(face, p, corner, tol, meeting, crossings):
    """The leg (_leg) from point p to vertex `corner` of face along the intersection of
    face's surface with that of another face of the solid at the corner (meeting) on
    which p lies, else None. A convex pocket rim's fillet that ends where a boss's
    base, level with the top, crosses the rim ends on the boss's cylinder, below the
    base: its end section reaches the pocket's wall straight below the vertex where
    the cylinder touches the wall, which meets the cylinder at that vertex only
    (--random-machined 40 --seed 75 --turned, part 2). crossings: as _leg_crossing
    takes it."""
    return next((g for g in (_leg_crossing(face, other, key, p, corner.Point, tol, crossings)
                             for key, other in meeting(corner)) if g is not None), None)


def parts_along(face, edge, tol, across, meeting=lambda v: []):
    """How face grows along an edge on its surface that does not lie on it: ([parts of
    edge on face], [(part off face, its _growth)]), or None when a part off the face
    spans no corner. The edge is one part off the face (a fillet's end section beyond
    it), or it crosses the face's boundary and is split there: an edge of OCCT's corner
    patch where two concave fillets meet a convex one cuts across the corner of the
    face between the concave ones, whose surface the convex fillet uncovers (a
    gusset's sloped edge meeting the floor, R = 1: the patch's edge on the floor cuts
    the corner of the gusset's footprint 0.02 deep). across, meeting: as _growth takes
    them."""
    g = _growth(face, edge, tol, across, meeting)
    if g is not None:
        return [], [(edge, g)]
    parts = face.copy().generalFuse([edge], tol)[1][1]  # a copy: see cut_face
    on = [p for p in parts if edge_on_face(p, face, tol)]
    off = [(p, _growth(face, p, tol, across, meeting)) for p in parts
           if not any(p is q for q in on)]
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


def grown_face(face, section, whole, corner, region, legs, tol):
    """_grown, and where that fails on a face placed away from its own frame (a part
    with a Placement: its faces carry it as their location), _grown on the face in its
    own frame, its result placed back. OCCT's rebuild of a located face may fail where
    the same face in its own frame is rebuilt: a blind hole's wall, which a side hole
    crosses, grown at the ends of the floor's fillet along the side hole, on a part
    turned and moved 1150 from the origin, was not valid and its fix gave a NULL shape
    (--random-machined 40 --seed 54 --turned, part 33; shapes.turned_hole_floor_block).
    Raises as _grown does."""
    try:
        return _grown(face, section, whole, corner, region, legs, tol)
    except (ValueError, Part.OCCError):
        if face.Placement.isIdentity():
            raise
    place = face.Placement
    back = place.inverse()

    def own(x):  # x in the face's own frame
        y = x.copy()
        y.transformShape(back.toMatrix())
        return y
    bare = face.copy()
    bare.Placement = FreeCAD.Placement()
    cut = own(section)
    out = _grown(bare, cut, cut if whole is section else own(whole), back.multVec(corner),
                 own(region), [own(g) for g in legs], tol)
    out.Placement = place
    return out


def _grown(face, section, whole, corner, region, legs, tol):
    """face (a piece of an original face that keeps the vertex `corner`) grown by
    `region` (_growth, whose legs run from the section's ends to the corner): its two
    edges at the corner end instead at the ends of `section` (shortened or extended
    along their curves, or left out where one ends there already: the part of an edge
    crossing the face's corner, parts_along, has the face's edges at the corner as legs; or
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
            # shortened or extended along its curve: the one p lies on, where both
            # edges at the corner are arcs of one curve (a boss's foot circle, split
            # where it crosses a pocket's rim: --random-machined 40 --seed 75
            # --turned, part 2), else the one whose curve holds p
            cut = [(e, g) for e, g in ((e, _end_at(e, corner, p, tol)) for e in at) if g]
            g = next((x for x in cut if x[0].distToShape(Part.Vertex(p))[0] <= tol),
                     cut[0] if cut else None)
            if g is not None:
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
                whole.distToShape(Part.Vertex(q))[0] <= tol for q in edge_points(e))]
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
        _check_growth(out, face, area, region, tol)
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
        _check_growth(out, face, area, region, tol)
    return out


def _check_growth(out, face, area, region, tol):
    """Raise ValueError unless face `out`'s area is the area of `face` (`area`, OCCT's)
    plus the region's."""
    miss = abs(out.Area - area - region.Area)
    # OCCT's area is off by up to 9e-6 (relative) on a face with long B-spline edges (a
    # helical ridge's section by a cylinder's end plane: 2.7e-3 of 307 once grown, by
    # Green's theorem); there the grown face holds a point inside the region, and its
    # area misses by less than half the region's
    if miss <= 1e-6 * (area + region.Area) or (
            miss <= 0.5 * region.Area and _on_face(out, _probe(region), tol)):
        return
    if isinstance(out.Surface, Part.Plane):
        # on a plane bounded by B-spline arcs (a boss's top made B-splines, grown on
        # its plane: extensible) OCCT's area was off by 0.47 % (119.2502, where
        # Green's theorem and the triangulation give 119.8084): the triangulations'
        # areas, exact on a plane but for the chords of curved edges, decide
        d = 1e-5 * out.BoundBox.DiagonalLength
        miss = abs(mesh_area(out, d) - mesh_area(face, d) - mesh_area(region, d))
        if miss <= 0.5 * region.Area and _on_face(out, _probe(region), tol):
            return
    raise ValueError("the grown face's area %.9g is not the face's %.9g plus the "
                     "region's %.9g" % (out.Area, area, region.Area))


def edge_points(edge, fractions=(0.25, 0.5, 0.75)):
    """Points of edge at these fractions of its parameter range (by default its inner
    points: a quarter, half and three quarters)."""
    a, b = edge.FirstParameter, edge.LastParameter
    return [edge.valueAt(a + x * (b - a)) for x in fractions]


def face_under(edge, faces, tol):
    """The one of `faces` whose surface holds the edge (at its inner points, within tol
    or 10x the edge's tolerance), the nearest to the edge where several do, or None.
    Two faces of a chain's ends may share a plane: a hole cutting a pocket's wall
    leaves two pieces of it, and the rim fillet's end sections lie one on each."""
    pts = edge_points(edge)
    tol = max(tol, 10.0 * edge.Tolerance)
    holding = [f for f in faces if all(off_surface(f.Surface, p) <= tol for p in pts)]
    if len(holding) < 2:
        return next(iter(holding), None)
    return min(holding, key=lambda f: f.distToShape(edge)[0])


def edge_on_face(edge, face, tol):
    """True when edge lies on face (at its inner points, within tol)."""
    return all(_on_face(face, p, tol) for p in edge_points(edge))


def end_gap(tools, vertices, tol):
    """The widest gap between the ends of two of `tools` (edges lying on one face) that
    stand for one vertex of OCCT's fillet: more than tol apart, both within the
    tolerance of one of `vertices` (its result's), neither on another tool; 0.0 where
    there are none. OCCT's fillet may end two fillets at one point of a face, its corner
    patch touching the face there only; the blends end where their own exact contacts
    reach the face, apart by up to OCCT's tolerance there, and a cut along them within
    tol is not closed: the face keeps the strip the fillets consume, and the sewing
    leaves free edges. Seen on a blind hole's wall where a side hole crosses its floor,
    with the floor's edge on the wall and the side hole's edges on the wall and on the
    floor filleted (shapes.side_hole_through_hole_floor): ends 2.05e-5 apart, within
    OCCT's vertex tolerance there, 8.4e-5. A short edge joining them instead is shorter
    than its vertices' tolerance, which OCCT's BOP check rejects (TooSmallEdge)."""
    ends = [(e, v.Point, {k for k, w in enumerate(vertices)
                          if (w.Point - v.Point).Length <= w.Tolerance})
            for e in tools for v in (e.Vertexes[0], e.Vertexes[-1])]

    def free(e, p):
        return not any(x is not e and x.distToShape(Part.Vertex(p))[0] <= tol for x in tools)
    gap = 0.0
    for k, (e, p, at) in enumerate(ends):
        for f, q, also in ends[k + 1:]:
            if f is not e and at & also and (p - q).Length > max(tol, gap) and \
                    free(e, p) and free(f, q):
                gap = (p - q).Length
    return gap


def is_consumed(edge, kept, tol):
    """True when no part of edge lies on `kept` (the edges of OCCT's fillet result, a
    compound), tested at its middle and at 1e-3 of its length from each end: an edge
    the fillet only shortens keeps one end's neighbourhood, or its middle if shortened
    at both, as an edge of the result. Failing those, by the result's edges
    themselves: two fillets shortening an edge from its two ends may leave a piece off
    its middle (a chamfer's end edge, 1.1 long, between fillets of the box's top edge
    and of the chamfer's lower edge at R = 0.577 kept 0.05 of it, three quarters
    along). A face of the result may hold a consumed edge's end inside it, where a
    fillet uncovers the face's corner (parts_along)."""
    if any(kept.distToShape(Part.Vertex(p))[0] <= tol
           for p in edge_points(edge, (0.5, 1e-3, 1.0 - 1e-3))):
        return False
    a = edge.BoundBox
    return not any(not r.Degenerated and _boxes_meet(a, r.BoundBox, tol) and all(
        edge.distToShape(Part.Vertex(p))[0] <= tol for p in edge_points(r))
        for r in kept.Edges)


def _boxes_meet(a, b, tol):
    """Whether bounding boxes a and b overlap or lie within tol of each other (False
    where either is void, as an edge's box can be: BoundBox.intersect raises there)."""
    return all(lo_a - tol <= hi_b and lo_b - tol <= hi_a for lo_a, hi_a, lo_b, hi_b in (
        (a.XMin, a.XMax, b.XMin, b.XMax), (a.YMin, a.YMax, b.YMin, b.YMax),
        (a.ZMin, a.ZMax, b.ZMin, b.ZMax)))


def cut_face(face, tools, sharp, legs, tol):
    """The pieces of an original face, cut along the edges `tools` lying on it, that do
    not touch any of the `sharp` edges the fillets consumed, except along `legs` (those
    of the regions this face or a neighbour grows by, _growth, from the corners where
    fillets end: the piece keeping such a corner keeps the part of a sharp edge along a
    leg until it grows, grown_face). A face across its surface's periodic range is cut
    _rebased (and, should that fail, as it is). Where OCCT's general fuse fails, the
    cut is made again with the closed tools _restarted where they cross the face's
    seam, then half a period on, then with the tools' ends _snapped_to_seams. A face
    that winds round its surface is first cut strip by strip (_fused), and its pieces
    kept are merged again (strips.merged). A cut that makes a piece BRepCheck rejects
    is tried the next way too, and taken only where none does better: the tube of a
    helical ridge of 2.5 turns, rebased, was cut into a piece of 402.2 mm2 that is not
    valid, which OCCT's distance put on the junction's edges, so it was dropped and the
    sewing left free edges; as it is, it is cut into three valid pieces. Pieces that
    meet along an edge no tool runs along (the face's seam) are one region of the
    surface, kept or dropped together."""
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
                   for p in edge_points(edge, (0.0, 1e-3, 0.25, 0.5, 0.75, 1 - 1e-3, 1.0)))

    gone = [any(touches(f, e) for e in sharp) for f in pieces]
    # pieces that meet along an edge no tool runs along (the face's seam; the pieces of
    # different strips share no edge) are one region of the surface, kept or dropped
    # together: the strip a fillet consumes on a side hole's wall, where its trimline
    # crosses the wall's seam, was cut in two by the seam, and the sliver beyond it,
    # which touches no sharp edge, was kept (shapes.slot_in_side_hole)
    links = [(i, j) for i, a in enumerate(pieces) for j, b in enumerate(pieces[:i])
             if any(not e.Degenerated and not _along_tool(e, tools, tol) for e in a.Edges
                    if any(e.isSame(x) for x in b.Edges))]
    while True:
        spread = [(i, j) for i, j in links if gone[i] != gone[j]]
        if not spread:
            break
        for i, j in spread:
            gone[i] = gone[j] = True
    kept = [f for f, g in zip(pieces, gone) if not g]
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
        if any(on.distToShape(Part.Vertex(p))[0] > 10.0 * tol for p in edge_points(e)):
            return ("OCCT's general fuse did not cut the face along the %s of the %d "
                    "trimline edges on it" % (_ordinal(k + 1), len(tools)))
    return pieces


def _along_tool(edge, tools, tol):
    """Whether edge runs along one of `tools` (at its inner points, within 10 tol)."""
    return any(all(t.distToShape(Part.Vertex(p))[0] <= 10.0 * tol for p in edge_points(edge))
               for t in tools)


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
            uvs = [s.parameter(p) for p in edge_points(e, [j / 8.0 for j in range(9)])]
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


def update_tolerances(edges, fuzzy):
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
    value of the faces' cut (cut_face): cutting a face along a closed trimline merges
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
        worst = pcurve_gap(e, pcurves)
        if 2.0 * worst > e.Tolerance:
            e.fixTolerance(2.0 * worst)
        for v, gap in _vertex_gap(e, pcurves):
            if 2.0 * gap > v.Tolerance and gap <= fuzzy:
                v.fixTolerance(2.0 * gap)


def pcurve_gap(edge, pcurves=None):
    """The largest distance between edge's 3D curve and its curves on the faces it
    bounds (`pcurves`, _pcurves(edge) when None), in model units, sampled as
    update_tolerances says (_samples). The edge must have a 3D curve."""
    worst = 0.0
    for c2, surf, place, a, b in _pcurves(edge) if pcurves is None else pcurves:
        for t in _samples(a, b, (c2, edge.Curve)):
            worst = max(worst, (_on(surf, place, c2.value(t)) - edge.valueAt(t)).Length)
    return worst


# model units: OCCT's least tolerance (Precision::Confusion()). A STEP file keeps no
# tolerances; OCCT's reader gives each edge the deviation it samples between its curves,
# at least this, and its BOP check's finer search can exceed that where the curves lie
# further apart (a plate filling's seams, about 1e-6 off its blends: corners.py).
EXCHANGE_GAP = 1e-7


def curve_gaps(shape):
    """{"edges": how many of shape's edges have curves further apart than EXCHANGE_GAP
    (pcurve_gap), "gap": the largest pcurve_gap of its edges (model units)}: the edges
    OCCT's BOP check may find off their faces in the shape read back from a STEP file.
    Degenerated edges (poles) have no 3D curve and are left out."""
    gaps = [pcurve_gap(e) for e in shape.Edges if not e.Degenerated]
    return {"edges": sum(g > EXCHANGE_GAP for g in gaps), "gap": max(gaps, default=0.0)}


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
