"""The parts of the workbench tests, built with Part (no files), a document
fingerprint for checking that failed operations leave documents unchanged, and a
sewing fault to inject."""
import hashlib
import math

import FreeCAD
import Part

V = FreeCAD.Vector


def box():
    """10 x 10 x 10 box."""
    return Part.makeBox(10, 10, 10)


def shaft_on_plate(k=1.0):
    """Cylinder r = 5, h = 20 fused on a 40 x 40 x 5 plate, all lengths times k; returns
    (solid, junction edge name)."""
    plate = Part.makeBox(40 * k, 40 * k, 5 * k, V(-20 * k, -20 * k, -5 * k))
    s = plate.fuse(Part.makeCylinder(5 * k, 20 * k)).removeSplitter()
    for i, e in enumerate(s.Edges):
        if isinstance(e.Curve, Part.Circle) and abs(e.Curve.Center.z) < 1e-9 * k \
                and abs(e.Curve.Radius - 5 * k) < 1e-9 * k:
            return s, "Edge%d" % (i + 1)
    raise AssertionError("no junction edge")


def split_shaft_on_plate():
    """shaft_on_plate with the shaft made of two half cylinders: the junction circle is
    two edges, so OCCT's fillet is two rolling-ball faces joined end to end (a closed
    tangent chain). Returns (solid, [names of the two junction edges])."""
    plate = Part.makeBox(40, 40, 5, V(-20, -20, -5))
    half = Part.makeCylinder(5, 20, V(0, 0, 0), V(0, 0, 1), 180)
    shaft = half.fuse(half.rotated(V(0, 0, 0), V(0, 0, 1), 180)).removeSplitter()
    s = plate.fuse(shaft)
    names = ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
             if isinstance(e.Curve, Part.Circle) and abs(e.Curve.Center.z) < 1e-9
             and abs(e.Curve.Radius - 5) < 1e-9]
    assert len(names) == 2, names
    return s, names


def pipe_tee():
    """A pipe r = 3 along x joining a pipe r = 5 along z; returns (solid, names of the
    two edges of their intersection curve, which OCCT splits at the seams)."""
    s = Part.makeCylinder(5, 40, V(0, 0, -20)).fuse(
        Part.makeCylinder(3, 20, V(0, 0, 0), V(1, 0, 0))).removeSplitter()
    names = ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
             if len(s.ancestorsOfType(e, Part.Face)) == 2 and e.BoundBox.XMin > 2
             and e.BoundBox.XMax < 6 and isinstance(e.Curve, Part.BSplineCurve)]
    assert len(names) == 2, names
    return s, names


def unequal_tee():
    """A pipe r = 3 along z, from the axis up, on a pipe r = 6 along y (y = -15..15); the
    big pipe's seam runs along its top (x = 0, z = 6), through the junction. Returns
    (solid, names of the edges of their intersection curve)."""
    s = Part.makeCylinder(6, 30, V(0, -15, 0), V(0, 1, 0)).fuse(
        Part.makeCylinder(3, 12)).removeSplitter()
    names = ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
             if len(s.ancestorsOfType(e, Part.Face)) == 2 and e.BoundBox.ZMin > 5
             and e.BoundBox.ZMax < 6 + 1e-9 and not e.isSeam(s.ancestorsOfType(e, Part.Face)[0])]
    assert len(names) == 3, names
    return s, names


def loft():
    """Lofted solid (B-spline side face) through circles r = 10, 6, 8 at z = 0, 10, 20;
    returns (solid, name of the top edge between the B-spline face and the top plane)."""
    ws = [Part.Wire(Part.makeCircle(r, V(0, 0, z))) for r, z in ((10, 0), (6, 10), (8, 20))]
    s = Part.makeLoft(ws, True, False)
    for i, e in enumerate(s.Edges):
        if abs(e.Vertexes[0].Point.z - 20) < 1e-9:
            return s, "Edge%d" % (i + 1)
    raise AssertionError("no top edge")


def offset_loft():
    """loft() offset outwards by 0.5 (makeOffsetShape, intersection joins): an
    OffsetSurface side face between planes at z = -0.5 and 20.5. Returns (solid, the
    original loft's side face, name of the bottom edge)."""
    lo = loft()[0]
    s = lo.makeOffsetShape(0.5, 1e-6, join=2)
    side = next(f for f in lo.Faces if isinstance(f.Surface, Part.BSplineSurface))
    return s, side, _edge_named(s, lambda e: e.BoundBox.ZMax < -0.5 + 1e-6)


def stepped_shaft():
    """A turned part: the profile (0, 0) (10, 0) (10, 3) (6, 3) (6, 8) (8, 10) (0, 10) in
    the xz plane revolved about z: a collar r = 10, a shank r = 6, then a cone at 45
    degrees out to a top disk r = 8. Returns (solid, names of its 5 circular edges
    between two faces, from the bottom up: z = 0, 3 (r = 10), 3 (r = 6), 8 and 10)."""
    pts = [(0, 0), (10, 0), (10, 3), (6, 3), (6, 8), (8, 10), (0, 10), (0, 0)]
    s = Part.Face(Part.makePolygon([V(x, 0, z) for x, z in pts])).revolve(V(), V(0, 0, 1),
                                                                         360)
    circles = [(e.BoundBox.ZMin, e.BoundBox.XLength, "Edge%d" % (i + 1))
               for i, e in enumerate(s.Edges) if isinstance(e.Curve, Part.Circle)
               and len(s.ancestorsOfType(e, Part.Face)) == 2]
    return s, [n for _, _, n in sorted(circles)]


def misoriented_box():
    """A 10-box made a solid from its faces with the first one reversed: a face oriented
    against the rest of its shell, so the solid fails isValid() (FreeCAD's check()
    says "No error"); shape.fix(1e-7, 1e-7, 1e-7) mends it."""
    fs = Part.makeBox(10, 10, 10).Faces
    return Part.Solid(Part.Shell([fs[0].reversed()] + fs[1:]))


def loft_tube():
    """Lofted solid through circles r = 3, 4, 3 at z = -15, 0, 15; returns (solid, name
    of the top edge). OCCT makes the side one polynomial patch (degree 14 around), whose
    seam is G2 but not G3: the contact's data converge slowly at first (1.3x from 32 to
    64 samples), then as n^-2."""
    ws = [Part.Wire(Part.makeCircle(r, V(0, 0, z))) for r, z in ((3, -15), (4, 0), (3, 15))]
    s = Part.makeLoft(ws, True)
    for i, e in enumerate(s.Edges):
        if e.BoundBox.ZMin > 15 - 1e-9 and len(s.ancestorsOfType(e, Part.Face)) == 2:
            return s, "Edge%d" % (i + 1)
    raise AssertionError("no top edge")


def l_bracket():
    """An L-shaped profile in the xz plane (legs 40 long, 5 thick) extruded 30 along y;
    returns (solid, name of the outer corner edge at x = z = 0, name of the inner corner
    edge at x = z = 5)."""
    s = Part.Face(Part.makePolygon([V(0, 0, 0), V(40, 0, 0), V(40, 0, 5), V(5, 0, 5),
                                    V(5, 0, 40), V(0, 0, 40), V(0, 0, 0)])).extrude(V(0, 30, 0))
    names = []
    for x in (0, 5):
        names += ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
                  if max(abs(e.BoundBox.XMin - x), abs(e.BoundBox.XMax - x),
                         abs(e.BoundBox.ZMin - x), abs(e.BoundBox.ZMax - x)) < 1e-9]
    assert len(names) == 2, names
    return (s, *names)


def slanted_l_bracket(axis):
    """The l_bracket with its end y = 30 replaced by a plane tilted 20 degrees about the
    z axis (y = 30 - x tan 20) or the x axis (y = 30 - z tan 20) through (0, 30, 0);
    returns (solid, name of the inner corner edge at x = z = 5)."""
    s, _, _ = l_bracket()
    cutter = Part.makeBox(200, 100, 200, V(-100, 30, -100))
    cutter.rotate(V(0, 30, 0), V(0, 0, 1) if axis == "z" else V(-1, 0, 0), -20)
    s = s.cut(cutter)
    names = ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
             if max(abs(e.BoundBox.XMin - 5), abs(e.BoundBox.XMax - 5),
                    abs(e.BoundBox.ZMin - 5), abs(e.BoundBox.ZMax - 5)) < 1e-9]
    assert len(names) == 1, names
    return s, names[0]


def wall_into_cylinder():
    """A 40 x 30 x 5 plate with a 5 mm wall (x in [0, 5], 20 high) along y, ending in a
    cylinder r = 6 (axis x = 5, y = 30, from z = 5 to 25); returns (solid, name of the
    concave edge at x = z = 5 between the wall and the plate, which runs into the
    cylinder)."""
    s = Part.makeBox(40, 30, 5).fuse(Part.makeBox(5, 30, 20, V(0, 0, 5))).fuse(
        Part.makeCylinder(6, 20, V(5, 30, 5))).removeSplitter()
    names = ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
             if max(abs(e.BoundBox.XMin - 5), abs(e.BoundBox.XMax - 5),
                    abs(e.BoundBox.ZMin - 5), abs(e.BoundBox.ZMax - 5)) < 1e-9
             and e.BoundBox.YLength > 1]
    assert len(names) == 1, names
    return s, names[0]


def boss_into_wall():
    """A 20 x 20 x 20 box fused with a cylinder r = 6, h = 20 on axis x = 20, y = 10
    (half of it stands out of the box's face x = 20); returns (solid, names of the two
    concave edges where the cylinder meets that face, at y = 4 and y = 16)."""
    s = Part.makeBox(20, 20, 20).fuse(Part.makeCylinder(6, 20, V(20, 10, 0))).removeSplitter()
    names = ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
             if abs(e.BoundBox.XMin - 20) < 1e-9 and abs(e.BoundBox.XMax - 20) < 1e-9
             and e.BoundBox.ZLength > 19 and 1 < e.BoundBox.YMin < 19]
    assert len(names) == 2, names
    return s, names


def flush_rib():
    """A 60 x 40 x 8 plate with a rib (x in [28, 32], y in [26, 40], 14 high) flush with
    its side y = 40. Returns (solid, [name of the plate's top edge at y = 40 from x = 0
    to 28, name of the rib's foot at x = 28]): a convex and a concave edge meeting at
    the vertex (28, 40, 8), whose third edge (the rib's) is not filleted."""
    s = Part.makeBox(60, 40, 8).fuse(Part.makeBox(4, 14, 14, V(28, 26, 8))).removeSplitter()
    at = [i for i, e in enumerate(s.Edges)
          if any((v.Point - V(28, 40, 8)).Length < 1e-9 for v in e.Vertexes)]
    top = [i for i in at if s.Edges[i].BoundBox.XMin < 1e-9]
    foot = [i for i in at if s.Edges[i].BoundBox.YLength > 1 and s.Edges[i].BoundBox.ZLength < 1e-9]
    assert len(top) == len(foot) == 1, (top, foot)
    return s, ["Edge%d" % (top[0] + 1), "Edge%d" % (foot[0] + 1)]


def tangent_rib():
    """A 60 x 40 x 8 plate with a boss (r = 8 at x = 30, y = 20, 20 high) and a rib
    (x in [28, 32], y in [28, 40], 14 high) whose face y = 28 touches the boss along a
    line: valid by isValid(), but OCCT's BOP check finds it self-intersecting. Returns
    (solid, name of the plate's vertical edge at x = y = 0)."""
    s = Part.makeBox(60, 40, 8).fuse(Part.makeCylinder(8, 20, V(30, 20, 8))).fuse(
        Part.makeBox(4, 12, 14, V(28, 28, 8))).removeSplitter().Solids[0]
    names = ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
             if e.BoundBox.XMax < 1e-9 and e.BoundBox.YMax < 1e-9]
    assert len(names) == 1, names
    return s, names[0]


def box_into(bulge):
    """A 20 x 10 x 10 box fused with a cylinder r = 8 (axis x = 20, y = 5, z in [0, 10])
    or a sphere r = 8 (centre (20, 5, 5)) bulging out of its front; returns (solid, name
    of the top front edge y = 0, z = 10, which ends on the bulge)."""
    other = Part.makeCylinder(8, 10, V(20, 5, 0)) if bulge == "cylinder" \
        else Part.makeSphere(8, V(20, 5, 5))
    s = Part.makeBox(20, 10, 10).fuse(other).removeSplitter()
    names = ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges) if not e.Degenerated
             and abs(e.BoundBox.ZMin - 10) < 1e-9 and abs(e.BoundBox.ZMax - 10) < 1e-9
             and abs(e.BoundBox.YMax) < 1e-9]
    assert len(names) == 1, names
    return s, names[0]


def hex_prism():
    """A regular hexagonal prism, circumradius 10 (sides 10), 20 high, its vertices at
    angles k 60 degrees; returns (solid, names of its six top edges)."""
    import math
    pts = [V(10 * math.cos(math.pi * k / 3), 10 * math.sin(math.pi * k / 3), 0)
           for k in range(6)]
    s = Part.Face(Part.makePolygon(pts + [pts[0]])).extrude(V(0, 0, 20))
    names = ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
             if abs(e.BoundBox.ZMin - 20) < 1e-9 and abs(e.BoundBox.ZMax - 20) < 1e-9]
    assert len(names) == 6, names
    return s, names


def step():
    """A 30 x 20 x 10 block with a 15 x 20 x 10 block on its left half; returns (solid,
    name of the concave edge at x = 15, z = 10, name of the convex edge at x = 15,
    z = 20), both along y."""
    s = Part.makeBox(30, 20, 10).fuse(Part.makeBox(15, 20, 10, V(0, 0, 10))).removeSplitter()
    names = ["Edge%d" % (i + 1) for z in (10, 20) for i, e in enumerate(s.Edges)
             if max(abs(e.BoundBox.XMin - 15), abs(e.BoundBox.XMax - 15),
                    abs(e.BoundBox.ZMin - z), abs(e.BoundBox.ZMax - z)) < 1e-9]
    assert len(names) == 2, names
    return (s, *names)


def ruled_block():
    """A block whose front face is ruled (a degree-8 B-spline from OCCT) between the line
    (0, 0, 0)-(20, 0, 0) and an arc through (10, -4, 10) ending at (0, 0, 10) and
    (20, 0, 10), closed by the planes z = 0, z = 10, y = 20, x = 0 and x = 20; returns
    (solid, name of the arc edge between the ruled face and the top)."""
    a = Part.makeLine(V(0, 0, 0), V(20, 0, 0))
    arc = Part.Arc(V(0, 0, 10), V(10, -4, 10), V(20, 0, 10)).toShape()

    def quad(*p):
        return Part.Face(Part.makePolygon(list(p) + [p[0]]))
    top = Part.Face(Part.Wire([arc, Part.makeLine(V(20, 0, 10), V(20, 20, 10)),
                               Part.makeLine(V(20, 20, 10), V(0, 20, 10)),
                               Part.makeLine(V(0, 20, 10), V(0, 0, 10))]))
    shell = Part.Shell([Part.makeRuledSurface(a, arc), top,
                        quad(V(0, 0, 0), V(20, 0, 0), V(20, 20, 0), V(0, 20, 0)),
                        quad(V(0, 20, 0), V(20, 20, 0), V(20, 20, 10), V(0, 20, 10)),
                        quad(V(0, 0, 0), V(0, 20, 0), V(0, 20, 10), V(0, 0, 10)),
                        quad(V(20, 0, 0), V(20, 20, 0), V(20, 20, 10), V(20, 0, 10))])
    shell.sewShape()
    s = Part.Solid(shell)
    names = ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
             if abs(e.BoundBox.ZMin - 10) < 1e-9 and abs(e.BoundBox.ZMax - 10) < 1e-9
             and e.BoundBox.YMin < -1]
    assert len(names) == 1, names
    return s, names[0]


def loft_with_boss(angle):
    """A loft from a circle r = 10 at z = 0 to a 12 x 8 ellipse at z = 20 (one B-spline
    side face, its seam at angle 0), with a cylinder r = 3 along the horizontal
    direction `angle` (degrees) from (0, 0, 10); returns (solid, names of the two edges
    of the junction curve)."""
    import math
    body = Part.makeLoft([Part.Wire(Part.makeCircle(10)),
                          Part.Wire(Part.Ellipse(V(0, 0, 20), 12, 8).toShape())], True, False)
    d = V(math.cos(math.radians(angle)), math.sin(math.radians(angle)), 0)
    s = body.fuse(Part.makeCylinder(3, 20, V(0, 0, 10), d)).removeSplitter()
    names = ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
             if len({f.hashCode() for f in s.ancestorsOfType(e, Part.Face)}) == 2
             and 5 < e.BoundBox.ZMin and e.BoundBox.ZMax < 15 and e.BoundBox.ZLength > 1e-6
             and 6 < (e.BoundBox.Center - V(0, 0, 10)).Length < 15
             and e.BoundBox.DiagonalLength < 9]
    assert len(names) == 2, names
    return s, names


def gusset_bracket():
    """l_bracket with a triangular gusset 4 thick in its inner corner; returns (solid,
    names of the gusset's two sloped edges)."""
    s = l_bracket()[0]
    g = Part.Face(Part.makePolygon([V(5, 13, 5), V(25, 13, 5), V(5, 13, 25), V(5, 13, 5)]))
    s = s.fuse(g.extrude(V(0, 4, 0))).removeSplitter()
    names = ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges) if isinstance(e.Curve, Part.Line)
             and e.BoundBox.XLength > 5 and e.BoundBox.ZLength > 5 and e.BoundBox.YLength < 1e-9]
    assert len(names) == 2, names
    return s, names


def cross_hole():
    """Cylinder r = 10 along z with a hole r = 3 through it along x; returns (solid,
    names of the edges of the opening at x > 0, of the opening at x < 0)."""
    s = Part.makeCylinder(10, 40, V(0, 0, -20)).cut(
        Part.makeCylinder(3, 40, V(-20, 0, 0), V(1, 0, 0))).removeSplitter()
    side = [["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
             if isinstance(e.Curve, Part.BSplineCurve) and k * e.BoundBox.Center.x > 5]
            for k in (1, -1)]
    assert side[0] and side[1], side  # OCCT splits the +x opening at the seam
    return (s, *side)


def spline_block():
    """A block whose front face is extruded from an open interpolating B-spline through
    (0, 0), (10, 3), (20, -2), (30, 0), 20 deep and 15 high; returns (solid, name of the
    spline's top edge)."""
    bs = Part.BSplineCurve()
    bs.interpolate([V(0, 0, 0), V(10, 3, 0), V(20, -2, 0), V(30, 0, 0)])
    w = Part.Wire([bs.toShape(), Part.makeLine(V(30, 0, 0), V(30, 20, 0)),
                   Part.makeLine(V(30, 20, 0), V(0, 20, 0)), Part.makeLine(V(0, 20, 0), V(0, 0, 0))])
    s = Part.Face(w).extrude(V(0, 0, 15))
    names = ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
             if isinstance(e.Curve, Part.BSplineCurve) and abs(e.BoundBox.ZMin - 15) < 1e-9]
    assert len(names) == 1, names
    return s, names[0]


def spline_prism():
    """A block whose front wall is extruded from a cubic spline interpolating 7 points of
    y = 3 sin(x / 5), x = 0, 5, ..., 30 (C2 at its 5 interior knots), 20 deep and 15
    high. Returns (solid, name of the spline's top edge, the spline at z = 0)."""
    bs = Part.BSplineCurve()
    pts = [V(5.0 * k, 3.0 * math.sin(k), 0) for k in range(7)]
    bs.interpolate(pts)
    w = Part.Wire([bs.toShape(), Part.makeLine(pts[-1], V(30, 20, 0)),
                   Part.makeLine(V(30, 20, 0), V(0, 20, 0)), Part.makeLine(V(0, 20, 0), pts[0])])
    s = Part.Face(w).extrude(V(0, 0, 15))
    names = ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
             if isinstance(e.Curve, Part.BSplineCurve) and abs(e.BoundBox.ZMin - 15) < 1e-9]
    assert len(names) == 1, names
    return s, names[0], bs


def spline_extrusion():
    """A profile closed by an interpolated B-spline arch, extruded 20 along y: its top
    is a surface of extrusion of the spline, meeting the two end planes and the two
    side planes. Returns (solid, names of the top face's four edges)."""
    arch = Part.BSplineCurve()
    arch.interpolate([V(30, 0, 10), V(22, 0, 16), V(12, 0, 13), V(0, 0, 18)])
    wire = Part.Wire([Part.LineSegment(V(0, 0, 0), V(30, 0, 0)).toShape(),
                      Part.LineSegment(V(30, 0, 0), V(30, 0, 10)).toShape(), arch.toShape(),
                      Part.LineSegment(V(0, 0, 18), V(0, 0, 0)).toShape()])
    s = Part.Face(wire).extrude(V(0, 20, 0))
    top = next(f for f in s.Faces if not f.Surface.isPlanar())
    return s, ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
               if any(e.isSame(x) for x in top.Edges)]


def knot_wall_block(offset=0.4):
    """A 30 x 20 x 15 block whose front wall is a surface of extrusion of a cubic spline
    through y = 3 sin(x / 5) at x = -5 + offset, offset, 5 + offset, ..., 35 + offset,
    cut by the block's side planes x = 0 and 30: the wall's knot lines lie `offset` in
    from the sides, within the mitres of a top-outline fillet of radius above offset.
    Returns (solid, names of the top face's 4 edges)."""
    pts = [V(x + offset, 3.0 * math.sin((x + offset) / 5.0), 0) for x in range(-5, 40, 5)]
    bs = Part.BSplineCurve()
    bs.interpolate(pts)
    a, b = pts[0].x, pts[-1].x
    w = Part.Wire([bs.toShape(), Part.makeLine(pts[-1], V(b, 20, 0)),
                   Part.makeLine(V(b, 20, 0), V(a, 20, 0)), Part.makeLine(V(a, 20, 0), pts[0])])
    s = Part.Face(w).extrude(V(0, 0, 15)).common(Part.makeBox(30, 30, 15, V(0, -5, 0)))
    s = s.removeSplitter()
    return s, _edges_at(s, 15.0)


def partial_revolution():
    """A profile with an interpolated cubic B-spline side, revolved 270 degrees about z:
    the surface of revolution is only C2 across its 3 knot lines, which a fillet along
    the profile's edge crosses obliquely. Returns (solid, name of that edge)."""
    side = Part.BSplineCurve()
    side.interpolate([V(10, 0, 0), V(12, 0, 5), V(8, 0, 12), V(9, 0, 18), V(6, 0, 25)])
    w = Part.Wire([Part.LineSegment(V(3, 0, 0), V(10, 0, 0)).toShape(), side.toShape(),
                   Part.LineSegment(V(6, 0, 25), V(3, 0, 25)).toShape(),
                   Part.LineSegment(V(3, 0, 25), V(3, 0, 0)).toShape()])
    s = Part.Face(w).revolve(V(0, 0, 0), V(0, 0, 1), 270)
    rev = next(f for f in s.Faces if "Revolution" in type(f.Surface).__name__)
    names = ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
             if any(e.isSame(x) for x in rev.Edges) and not isinstance(e.Curve, Part.Circle)]
    return s, names[0]


def every_edge(s):
    """Names of the edges of s that a fillet can take: all but degenerate edges and the
    seams of closed faces."""
    return ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges) if not e.Degenerated
            and not any(e.isSeam(f) for f in s.ancestorsOfType(e, Part.Face))]


def _edge_named(s, pred):
    """The name ("EdgeN") of the first edge e of s for which pred(e) holds."""
    return next("Edge%d" % (i + 1) for i, e in enumerate(s.Edges) if pred(e))


def _edges_at(s, z):
    """Names of the edges of s lying in the plane z (no vertical extent)."""
    return ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
            if abs(e.BoundBox.ZMin - z) < 1e-9 and e.BoundBox.ZLength < 1e-9]


def rounded_box(tilt=0.0):
    """A 20 x 20 x 10 box whose four vertical edges are rounded (OCCT's fillet, r = 3):
    its top outline runs along planes and cylinders. tilt (degrees): the top is cut
    instead by a plane through z = 8 tilted about x. Returns (solid, names of the top
    face's edges)."""
    b = Part.makeBox(20, 20, 10)
    s = b.makeFillet(3.0, [e for e in b.Edges if e.BoundBox.ZLength > 1])
    if not tilt:
        names = _edges_at(s, 10.0)
        assert len(names) == 8, names
        return s, names
    cutter = Part.makeBox(60, 60, 40, V(-20, -20, 8))
    cutter.rotate(V(0, 0, 8), V(1, 0, 0), tilt)
    s = s.cut(cutter)
    top = max(s.Faces, key=lambda f: f.CenterOfMass.z)
    return s, ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
               if any(e.isSame(x) for x in top.Edges)]


def pentagonal_prism():
    """A regular pentagonal prism, circumradius 17.576 and 15.975 high, with 11 of its 15
    edges selected at R = 0.863 (five corners, plate fillings whose neighbourhoods take
    OCCT's BOP check seconds of processor time: bopcheck.NEAR_LIMIT). Returns (solid,
    edge names, radius)."""
    pts = [V(17.576 * math.cos(0.4 * math.pi * k), 17.576 * math.sin(0.4 * math.pi * k), 0)
           for k in range(6)]
    s = Part.Face(Part.makePolygon(pts)).extrude(V(0, 0, 15.975))
    return s, ["Edge%d" % k for k in (1, 2, 3, 4, 6, 7, 8, 11, 13, 14, 15)], 0.863


def rounded_hexagon():
    """A regular hexagonal prism (circumradius 10, height 10) whose six vertical edges
    are rounded (OCCT's fillet, r = 2): its top outline runs along planes and 60 degree
    arcs. Returns (solid, names of the top face's edges)."""
    pts = [V(10 * math.cos(math.pi * k / 3), 10 * math.sin(math.pi * k / 3), 0)
           for k in range(6)]
    s = Part.Face(Part.makePolygon(pts + pts[:1])).extrude(V(0, 0, 10))
    s = s.makeFillet(2.0, [e for e in s.Edges if e.BoundBox.ZLength > 1])
    names = _edges_at(s, 10.0)
    assert len(names) == 12, names
    return s, names


def ruled_rounded_loft():
    """A ruled loft from a 20 x 14 rectangle with corners rounded at r = 3 (z = 0) to a
    16 x 10 one rounded at r = 2 (z = 10). Returns (solid, names of the top face's
    edges)."""
    def outline(w, h, r, z):
        x, y = w / 2 - r, h / 2 - r
        centres = [V(x, -y, z), V(x, y, z), V(-x, y, z), V(-x, -y, z)]
        segs = []
        for k, c in enumerate(centres):
            a = math.pi / 2 * (k - 1)
            segs.append(Part.ArcOfCircle(Part.Circle(c, V(0, 0, 1), r), a, a + math.pi / 2)
                        .toShape())
            d = centres[(k + 1) % 4]
            segs.append(Part.LineSegment(c + V(math.cos(a + math.pi / 2) * r,
                                               math.sin(a + math.pi / 2) * r, 0),
                                         d + V(math.cos(a + math.pi / 2) * r,
                                               math.sin(a + math.pi / 2) * r, 0)).toShape())
        return Part.Wire(segs)
    s = Part.makeLoft([outline(20, 14, 3, 0), outline(16, 10, 2, 10)], True, True)
    names = _edges_at(s, 10.0)
    assert len(names) == 8, names
    return s, names


def rounded_pocket():
    """A 40 x 20 x 6 block with a pocket 3 deep: a 16 x 10 rectangle from (12, 5) whose
    corners are rounded at r = 2.5 (OCCT's fillet). Returns (solid, names of the pocket's
    rim edges on the top face)."""
    p = Part.makeBox(16, 10, 10, V(12, 5, 3))
    p = p.makeFillet(2.5, [e for e in p.Edges if e.BoundBox.ZLength > 1])
    s = Part.makeBox(40, 20, 6).cut(p).removeSplitter()
    names = [n for n in _edges_at(s, 6.0)
             if 1 < s.getElement(n).BoundBox.XMin and s.getElement(n).BoundBox.XMax < 39]
    assert len(names) == 8, names
    return s, names


def pocket_into_hole():
    """A 40 x 35 x 9 block with a through hole r = 3 at (30, 22) and a pocket 4 deep,
    x from 22 to 31 and y from 16 to 24, whose floor edge at y = 24 runs into the hole.
    Returns (solid, name of that floor edge)."""
    s = Part.makeBox(40, 35, 9).cut(Part.makeCylinder(3, 11, V(30, 22, -1)))
    s = s.cut(Part.makeBox(9, 8, 5, V(22, 16, 5))).removeSplitter()
    return s, _edge_named(s, lambda e: isinstance(e.Curve, Part.Line)
                          and e.BoundBox.ZLength < 1e-9 and e.BoundBox.XLength > 1
                          and abs(e.BoundBox.ZMin - 5) < 1e-9
                          and abs(e.BoundBox.YMin - 24) < 1e-9)


def chamfered_box(c=0.78):
    """A 30 x 34 x 14 box whose top edge at y = 34 is chamfered by c. Returns (solid,
    name of the top edge at x = 0, name of the chamfer's lower edge, on the face
    y = 34)."""
    b = Part.makeBox(30, 34, 14)
    s = b.makeChamfer(c, [e for e in b.Edges if e.BoundBox.ZMin > 13.9
                          and e.BoundBox.YMin > 33.9])
    return (s, _edge_named(s, lambda e: e.BoundBox.XMax < 1e-9 and e.BoundBox.ZMin > 13.9
                           and e.BoundBox.YLength > 10),
            _edge_named(s, lambda e: abs(e.BoundBox.ZMax - 14 + c) < 1e-9
                        and e.BoundBox.ZLength < 1e-9 and e.BoundBox.XLength > 10
                        and e.BoundBox.YMin > 33.9))


def chamfered_pocket(c=1.2):
    """A 24 x 28 x 14 block with a pocket x from 4 to 12, y from 5 to 11, its floor at
    z = 6, whose rim edge at x = 4 is chamfered by c (as machined seed 60's part 5,
    turned). Returns (solid, name of the top edge at y = 5 over the chamfer, from
    (4 - c, 5, 14) to (4, 5, 14), name of the chamfer's edge on the pocket's end wall
    y = 5, from (4 - c, 5, 14) to (4, 5, 14 - c)). Both meet at (4 - c, 5, 14) with the
    chamfer's top edge, convex, 135 degrees."""
    b = Part.makeBox(24, 28, 14).cut(Part.makeBox(8, 6, 9, V(4, 5, 6))).removeSplitter()
    s = b.makeChamfer(c, [b.getElement(_edge_named(
        b, lambda e: abs(e.BoundBox.XMin - 4) < 1e-9 and e.BoundBox.XLength < 1e-9
        and e.BoundBox.ZMin > 14 - 1e-9))])

    def on_end_wall(e):
        return abs(e.BoundBox.YMin - 5) < 1e-9 and e.BoundBox.YLength < 1e-9 \
            and abs(e.BoundBox.XMin - 4 + c) < 1e-9 and abs(e.BoundBox.XMax - 4) < 1e-9
    return (s, _edge_named(s, lambda e: on_end_wall(e) and e.BoundBox.ZLength < 1e-9),
            _edge_named(s, lambda e: on_end_wall(e) and e.BoundBox.ZLength > c - 1e-9))


def pocket_block():
    """A 40 x 20 x 7 block with a pocket 5 deep, x from 15 to 23 and y from 10 to 17.
    Returns (solid, name of the block's top edge at y = 0, name of the pocket's rim edge
    at y = 17, name of the pocket's corner edge at (23, 17))."""
    s = Part.makeBox(40, 20, 7).cut(Part.makeBox(8, 7, 6, V(15, 10, 2))).removeSplitter()
    return (s, _edge_named(s, lambda e: e.BoundBox.YMax < 1e-9
                           and e.BoundBox.ZMin > 7 - 1e-9 and e.BoundBox.XLength > 39),
            _edge_named(s, lambda e: abs(e.BoundBox.YMin - 17) < 1e-9
                        and e.BoundBox.ZMin > 7 - 1e-9 and e.BoundBox.XLength > 7),
            _edge_named(s, lambda e: abs(e.BoundBox.XMin - 23) < 1e-9
                        and abs(e.BoundBox.YMin - 17) < 1e-9 and e.BoundBox.ZLength > 4))


def boss_over_hole():
    """A 25 x 24 x 10 block with a through hole r = 1.8 at (9, 9) and a boss r = 2, 5
    high, at (11, 7) on its top, over part of the hole. Returns (solid, name of the
    hole's rim arc, 2.807 long, between the top face and the hole), on which OCCT's
    fillet crashes (a segmentation fault) at R = 0.001 to 0.5 and fails at 3e-4."""
    s = Part.makeBox(25, 24, 10).cut(Part.makeCylinder(1.8, 12, V(9, 9, -1)))
    s = s.fuse(Part.makeCylinder(2, 5, V(11, 7, 10))).removeSplitter()
    return s, _edge_named(s, lambda e: isinstance(e.Curve, Part.Circle)
                          and abs(e.Curve.Radius - 1.8) < 1e-9
                          and abs(e.BoundBox.ZMin - 10) < 1e-9
                          and abs(e.Length - 2.807) < 1e-3)


def side_hole_through_blind_hole():
    """A 30 x 30 x 10 block with a blind hole r = 3 at (15, 15), its floor at z = 4,
    and a side hole r = 1.5 along x, its axis at y = 15.5, z = 4.5, which crosses the
    hole half a radius above the floor and cuts a trough in it. Returns (solid, names
    of the floor's two straight edges along the trough, at y = 15.5 -+ sqrt 2, from
    wall to wall), convex edges that end where the side hole opens the hole's wall."""
    s = Part.makeBox(30, 30, 10).cut(Part.makeCylinder(3, 7, V(15, 15, 4)))
    s = s.cut(Part.makeCylinder(1.5, 32, V(-1, 15.5, 4.5), V(1, 0, 0))).removeSplitter()
    return s, ["Edge%d" % (i + 1) for i, e in sorted(
        enumerate(s.Edges), key=lambda q: q[1].BoundBox.YMin)
        if isinstance(e.Curve, Part.Line) and abs(e.BoundBox.ZMin - 4) < 1e-9
        and abs(e.BoundBox.ZMax - 4) < 1e-9 and e.BoundBox.XLength > 1]


def hole_through_pocket_wall():
    """A 20 x 30 x 9 block with a 6 x 10 pocket 3 deep (floor z = 6, its wall y = 15
    from x = 3 to 9) and a blind hole r = 2.5 at (6, 15.5) down to z = 3, which cuts
    through that wall: the hole's rim on the floor (convex) meets the floor's edges
    along the wall (concave) at x = 6 -+ sqrt(2.5^2 - 0.5^2), y = 15, z = 6, where the
    hole's wall meets the pocket's wall along a vertical (convex) edge up to z = 9 (the
    shape of --random-machined 60 --seed 2, part 54). Returns (solid, names of the rim's
    two arcs and the floor's two edges along the wall, names of the two vertical
    edges)."""
    s = Part.makeBox(20, 30, 9)
    s = s.cut(Part.makeBox(6, 10, 4, V(3, 15, 6)))
    s = s.cut(Part.makeCylinder(2.5, 7, V(6, 15.5, 3))).removeSplitter()

    def flat(e):
        return abs(e.BoundBox.ZMin - 6) < 1e-9 and e.BoundBox.ZLength < 1e-9

    def on_wall(e):
        return abs(e.BoundBox.YMin - 15) < 1e-9 and e.BoundBox.YLength < 1e-9

    names = ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges) if flat(e) and (
        isinstance(e.Curve, Part.Circle) or isinstance(e.Curve, Part.Line) and on_wall(e))]
    x = (6 - math.sqrt(6.0), 6 + math.sqrt(6.0))
    vertical = ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
                if on_wall(e) and e.BoundBox.ZLength > 2.9
                and min(abs(e.BoundBox.XMin - c) for c in x) < 1e-9]
    return s, names, vertical


def side_hole_through_hole_floor():
    """A 34.362 x 37.006 x 9.497 block with a blind hole r = 5.937 about (18.905,
    10.745) down to its floor z = 5.229, crossed by a side hole r = 2.676 along x (axis
    y = 12.246, z = 4.749) that cuts the floor along two lines (y = 12.246 -+ 2.633)
    and the hole's wall on both sides (--random-machined 40 --seed 51, part 19, without
    its other side hole). At (x0, 9.613, 5.229), x0 = 13.077 and 24.733, the floor's line
    on the side hole (convex), the side hole's edge on the wall (convex) and the floor's
    arc on the wall (concave) meet: the line and that arc join the same two vertices.
    Returns (solid, names of the floor's line at y = 9.613 and of the side hole's edges
    on the wall that end at its ends, name of the floor's arc at y < 9.613)."""
    s = Part.makeBox(34.362, 37.006, 9.497)
    s = s.cut(Part.makeCylinder(5.937, 5.268, V(18.905, 10.745, 5.229)))
    s = s.cut(Part.makeCylinder(2.676, 36.362, V(-1, 12.246, 4.749), V(1, 0, 0)))
    s = s.removeSplitter()

    def named(test):
        return ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges) if test(e)]

    def floor(e):
        return abs(e.BoundBox.ZMax - 5.229) < 1e-6 and e.BoundBox.ZLength < 1e-6 and \
            e.BoundBox.YMax < 9.62
    line = named(lambda e: floor(e) and isinstance(e.Curve, Part.Line))
    arc = named(lambda e: floor(e) and isinstance(e.Curve, Part.Circle))
    ends = [v.Point for v in s.getElement(line[0]).Vertexes]
    walls = named(lambda e: isinstance(e.Curve, Part.BSplineCurve) and any(
        (v.Point - p).Length < 1e-6 for v in e.Vertexes for p in ends))
    return s, line + walls, arc[0]


def turned_hole_floor_block():
    """A 38.06 x 35.07 x 13.32 block with a side hole r = 3.802 along x (axis y = 26.18,
    z = 6.658) and a blind hole r = 5.512 about (29.51, 24.96) down to its floor z =
    4.477, which the side hole crosses, turned about (0.219, 0.734, -0.643) by 218.1
    degrees and moved to (-259.4, -535.0, 982.9) by its Placement (--random-machined 40
    --seed 54 --turned, part 33, to full precision). Returns (solid, name of the floor's
    line on the side hole at y = 23.07, radius 0.127)."""
    s = Part.makeBox(38.05940311331791, 35.07499794225333, 13.316386457894428)
    s = s.cut(Part.makeCylinder(3.8021169907633783, 40.05940311331791,
                                V(-1, 26.18362183404797, 6.658193228947214),
                                V(1, 0, 0))).removeSplitter()
    s = s.cut(Part.makeCylinder(5.511969257421023, 9.839043552279286,
                                V(29.51268829178503, 24.96434737619817,
                                  4.477342905615142))).removeSplitter()
    (line,) = ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
               if isinstance(e.Curve, Part.Line) and e.BoundBox.ZLength < 1e-9
               and abs(e.BoundBox.ZMin - 4.477342905615142) < 1e-9
               and abs(e.BoundBox.YMin - 23.07) < 1e-2]
    s.Placement = FreeCAD.Placement(
        V(-259.4225708561537, -535.0202060088602, 982.8992516527635),
        FreeCAD.Rotation(0.20709089991077514, 0.69351845133145, -0.6079429237305805,
                         -0.32642138153449224))
    return s, line, 0.127


def slot_in_side_hole():
    """A 21.48 x 23.73 x 7.285 block with a pocket 4.202 x 3.152 down to z = 3.254, a slot
    3.468 wide down to z = 2.685 (its round ends r = 1.734 about x = 10.68 and 13.33, y =
    12.66) and a side hole r = 2.185 along x (axis y = 14.52, z = 3.642), which the slot
    cuts near the top of the hole, at its seam (--random-machined 40 --seed 54 --turned,
    part 35, unturned, to full precision). Returns (solid, names of the edges where the
    slot's ends meet the side hole from (10.68, 14.39, 5.82) and from (15.07, 12.66,
    4.80))."""
    s = Part.makeBox(21.48377281256226, 23.731317680041048, 7.28472017365125)
    s = s.cut(Part.makeBox(4.202086032796315, 3.1515645245972363, 5.03080466723819,
                           V(7.062276327200802, 9.695799037562308, 3.25391550641306)))
    s = s.removeSplitter()
    w, depth, y, z = 1.7340959123676538, 5.599872179936716, 12.660553822122019, \
        2.684847993714534
    tool = Part.makeBox(2.64987974774975, 2 * w, depth, V(10.682027303855419, y - w, z))
    for x in (10.682027303855419, 13.33190705160517):
        tool = tool.fuse(Part.makeCylinder(w, depth, V(x, y, z)))
    s = s.cut(tool).removeSplitter()
    s = s.cut(Part.makeCylinder(2.1854160520953747, 23.48377281256226,
                                V(-1, 14.515970497725384, 3.642360086825625),
                                V(1, 0, 0))).removeSplitter()
    starts = [V(10.682, 14.395, 5.824), V(15.066, 12.661, 4.797)]
    return s, ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
               if isinstance(e.Curve, Part.BSplineCurve)
               and any((e.Vertexes[0].Point - p).Length < 1e-2 for p in starts)]


def slot_over_side_hole():
    """A 31.6 x 29.1 x 13.6 block with a side hole r = 4.068 along x (axis y = 12.85,
    z = 6.780) and a slot 4.515 wide from above down to z = 6.357, its round ends
    (r = 2.257) about x = 5.894 and 9.549, y = 18.28: the hole cuts the slot's wall and
    floor (--random-machined 40 --seed 7, part 4, to full precision: OCCT fillets its
    edges at 0.099 but not at 0.1). Returns (solid, names of the edge where the hole
    meets the slot's end at x = 5.894 and of the slot floor's arc there, which meet
    at (4.115, 16.89, 6.357), where the hole meets the floor along the third edge)."""
    s = Part.makeBox(31.597904085649844, 29.1241066260283, 13.5597100246129)
    s = s.cut(Part.makeCylinder(4.067913007383861, 34, V(-1, 12.847240266552994,
                                                         6.779855012306436), V(1, 0, 0)))
    w, y, z = 2.257291199751672, 18.282549356832277, 6.357083697888904
    x0, x1 = 5.894030395964995, 9.549069608462295
    tool = Part.makeBox(x1 - x0, 2 * w, 8, V(x0, y - w, z))
    for x in (x0, x1):
        tool = tool.fuse(Part.makeCylinder(w, 8, V(x, y, z)))
    s = s.cut(tool).removeSplitter()

    def at_end(e):  # round the slot's end x = x0, from its floor up
        b = e.BoundBox
        return x0 - w - 1e-6 < b.XMin and b.XMax < x0 + 1e-6 and abs(b.ZMin - z) < 1e-6
    wall = _edge_named(s, lambda e: at_end(e) and isinstance(e.Curve, Part.BSplineCurve))
    floor = _edge_named(s, lambda e: at_end(e) and e.BoundBox.ZLength < 1e-9
                        and isinstance(e.Curve, Part.Circle))
    return s, [wall, floor]


def slot_over_small_side_hole():
    """A 20.35 x 22.44 x 9.585 block with a side hole r = 1.659 along x (axis y = 3.896,
    z = 4.792) and a slot 2.007 wide from above down to z = 3.303, its round ends
    (r = 1.003) about x = 11.25 and 13.74, y = 5.762: the hole's top cuts the slot's
    floor along its wall y = 4.758 (--random-machined 40 --seed 32, part 15, to full
    precision). Returns (solid, names of the survey's five edges: two of the block's
    edges along x, the two arcs of the slot's top rim at x = 13.74 and the floor's edge
    along the wall y = 6.765)."""
    a, b, c = 20.34531230117065, 22.438509267776546, 9.584813914057033
    s = Part.makeBox(a, b, c)
    s = s.cut(Part.makeCylinder(1.6594453930759276, a + 2, V(-1, 3.896151899087102, 0.5 * c),
                                V(1, 0, 0))).removeSplitter()
    r, x, y = 2.0066402816239566, 12.494046446775219, 5.76173793857972
    w, length, depth = 0.5 * r, 1.2403038884568724 * r, 0.6554171206845746 * c
    tool = Part.makeBox(length, 2 * w, depth + 1, V(x - 0.5 * length, y - w, c - depth))
    for end in (-0.5, 0.5):
        tool = tool.fuse(Part.makeCylinder(w, depth + 1, V(x + end * length, y, c - depth)))
    s = s.cut(tool).removeSplitter()

    def along_x(e, y_, z_):
        return e.BoundBox.XLength > 0.5 * a and all(
            abs(v.Point.y - y_) < 1e-9 and abs(v.Point.z - z_) < 1e-9 for v in e.Vertexes)
    rim = ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges) if isinstance(e.Curve, Part.Circle)
           and e.BoundBox.ZMin > c - 1e-9 and e.BoundBox.XMin > x + 0.5 * length - 1e-9]
    floor = _edge_named(s, lambda e: isinstance(e.Curve, Part.Line)
                        and abs(e.BoundBox.ZMax - (c - depth)) < 1e-9 and e.BoundBox.ZLength < 1e-9
                        and abs(e.BoundBox.YMin - (y + w)) < 1e-9)
    return s, [_edge_named(s, lambda e: along_x(e, 0.0, 0.0)),
               _edge_named(s, lambda e: along_x(e, b, c))] + rim + [floor]


def hole_through_pocket_floor():
    """A 25.01 x 28.26 x 8.343 plate, two of its vertical edges rounded (r = 5.091), with
    a pocket 5.875 x 8.785 and 3.402 deep, its corners rounded (r = 1.964), and a hole
    r = 1.954 through the pocket's floor, both centred at (12.50, 12.50): the hole's
    rim on the floor passes 0.98 and 0.38 from the pocket's walls (--random-plates 40
    --seed 44, part 29, to full precision). Returns (solid, name of that rim)."""
    a, b, c = 25.007401728513678, 28.257246894802996, 8.342694275357296
    s = Part.Face(Part.makePolygon([V(0, 0, 0), V(a, 0, 0), V(a, b, 0), V(0, b, 0),
                                    V(0, 0, 0)])).extrude(V(0, 0, c))
    vertical = [e for e in s.Edges if e.BoundBox.ZLength > 1e-9]
    s = s.makeFillet(0.2035777383090373 * a, vertical[1:3])
    s = s.cut(Part.makeCylinder(1.9542422686483332, c + 2, V(0.5 * a, 0.5 * a, -1)))
    pw, ph, depth = 0.23491425227427115 * a, 0.35130438450183815 * a, 0.4077883511331306 * c
    tool = Part.makeBox(pw, ph, depth + 1, V(0.5 * a - pw / 2, 0.5 * a - ph / 2, c - depth))
    tool = tool.makeFillet(0.3343024155602733 * min(pw, ph),
                           [e for e in tool.Edges if e.BoundBox.ZLength > 1e-9])
    s = s.cut(tool).removeSplitter().Solids[0]
    rim = _edge_named(s, lambda e: isinstance(e.Curve, Part.Circle) and e.Closed
                      and abs(e.Curve.Radius - 1.9542422686483332) < 1e-9
                      and abs(e.BoundBox.ZMin - (c - depth)) < 1e-9)
    return s, rim


def boss_on_boss(lower=(5.0, 15.0, 20.0, 2.0), taller=(5.0, 21.0, 20.0, 4.0)):
    """A 40 x 40 x 3 plate with two overlapping cylindrical bosses on it, each (radius,
    x, y, height): the lower boss's top is a crescent, bounded by its rim (convex) and
    by the taller boss's side (concave), which meet at the crescent's two tips, where
    the bosses' sides meet along a vertical (concave) edge from the plate up to the
    lower top. Returns (solid, names of the lower top's two edges)."""
    s = Part.makeBox(40, 40, 3)
    for r, x, y, h in (lower, taller):
        s = s.fuse(Part.makeCylinder(r, h, V(x, y, 3)))
    s = s.removeSplitter()
    z = 3 + lower[3]
    return s, ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
               if abs(e.BoundBox.ZMin - z) < 1e-9 and e.BoundBox.ZLength < 1e-9]


def pocket_under_boss():
    """A 38.57 x 33.63 x 14.36 block with a boss r = 4.822 at (28.51, 19.31), 8.808 high,
    and a pocket 10.56 x 7.918 from z = 8.362 up to 1 above the block's top, which
    tunnels under the boss (its ceiling z = 15.36 lies inside the boss), to full
    precision (--random-machined 60 --seed 10, part 55). Returns (solid, names of the
    block's top edge at y = 0, the edge where the boss's side meets the pocket's wall
    y = 15.96, and the edge where that wall meets the ceiling)."""
    s = Part.makeBox(38.56981841968583, 33.6263458995889, 14.355130813464195)
    s = s.fuse(Part.makeCylinder(4.821921287641795, 23.163005723336127 - 14.355130813464195,
                                 V(28.510317115667146, 19.30623028832621, 14.355130813464195)))
    x0, x1 = 23.992102897819763, 34.548945963575406
    y0, y1 = 15.961342472322428, 23.878974771639164
    z0, z1 = 8.361584618555145, 15.355130813464195
    s = s.cut(Part.makeBox(x1 - x0, y1 - y0, z1 - z0, V(x0, y0, z0))).removeSplitter()

    def flat(e, y, z):
        b = e.BoundBox
        return abs(b.YMin - y) < 1e-9 and b.YLength < 1e-9 and abs(b.ZMin - z) < 1e-9
    front = _edge_named(s, lambda e: flat(e, 0.0, 14.355130813464195) and e.BoundBox.ZLength < 1e-9)
    side = _edge_named(s, lambda e: flat(e, y0, 14.355130813464195) and e.BoundBox.ZLength > 0.5
                       and e.BoundBox.XMin < 28.5)  # the boss's side at x = 25.04
    ceiling = _edge_named(s, lambda e: flat(e, y0, z1) and e.BoundBox.ZLength < 1e-9)
    return s, [front, side, ceiling]


def chamfered_slot():
    """A 24 x 27.31 x 10.57 block, its front top edge chamfered 0.8975, with a slot
    (half-width w = 1.114, ends at x = 14.32 and 16.75, y = 14.37, 5.398 deep) whose
    rim is chamfered 0.922 all round (a cone at each end), to full precision
    (--random-machined 60 --seed 18, part 1). Its Edge11 and Edge14 are the straight
    and arc edges of the rim's chamfer at the slot's end x = 16.75, on the slot's
    wall z = 9.648."""
    a, b, c = 24.004514177862657, 27.310714062384243, 10.569673343128155
    s = Part.makeBox(a, b, c)
    front = _edge_named(s, lambda e: e.BoundBox.ZMin > c - 1e-9 and e.BoundBox.YMax < 1e-9)
    s = s.makeChamfer(0.8974937424808322, [s.getElement(front)]).removeSplitter()
    x, y, w = 15.533548673039009, 14.369925940686885, 0.5 * 2.227652787179352
    length, depth = 1.0934625608712991 * 2.227652787179352, 0.5106943108801498 * c
    tool = Part.makeBox(length, 2 * w, depth + 1, V(x - 0.5 * length, y - w, c - depth))
    for end in (-0.5, 0.5):
        tool = tool.fuse(Part.makeCylinder(w, depth + 1, V(x + end * length, y, c - depth)))
    s = s.cut(tool).removeSplitter()
    rim = _edge_named(s, lambda e: isinstance(e.Curve, Part.Line) and e.BoundBox.ZMin > c - 1e-9
                      and e.BoundBox.YLength < 1e-9 and abs(e.BoundBox.YMin - y - w) < 1e-9)
    return s.makeChamfer(0.9219901838608635, [s.getElement(rim)]).removeSplitter()


def tall_l_block():
    """An L block: a 16.73 x 16.17 x 17.66 box and a 0.4 x 16.73 wide column on it up
    to twice that height (--random-edges 40 --seed 19 --turned, part 17, unturned, to
    full precision). Returns (solid, names of its 18 edges but the column's back
    vertical edge at x = 0.4 a, y = b and the step's concave edge at x = 0.4 a, z = c),
    and (a, b, c)."""
    a, b, c = 16.729006889705023, 16.1675909252352, 0.5 * 35.31673327448374
    s = Part.makeBox(a, b, c).fuse(Part.makeBox(0.4 * a, b, 2 * c)).removeSplitter()

    def left_out(e):
        bb = e.BoundBox
        return abs(bb.XMin - 0.4 * a) < 1e-9 and bb.XLength < 1e-9 and (
            (abs(bb.YMin - b) < 1e-9 and bb.YLength < 1e-9 and bb.ZMin > c - 1e-9) or
            (bb.ZLength < 1e-9 and abs(bb.ZMin - c) < 1e-9))
    names = ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges) if not left_out(e)]
    return s, names, (a, b, c)


def mitred_step():
    """A step: a 19.76 x 12.22 x 14.42 box and half of it beside it, half as high, to
    full precision (--random-edges 20 --seed 90, part 10). Returns (solid, names of 13
    of its 18 edges in their order in the solid, which changes OCCT's fillet: among
    them the lower step's front edge and the front vertical edge below its end, whose
    fillets meet at a mitre), and (a, b, c)."""
    a, b, c = 19.76169051810392, 12.216377377779633, 14.423724133689285
    s = Part.makeBox(a, b, c).fuse(Part.makeBox(0.5 * a, b, 0.5 * c, V(a, 0, 0)))
    s = s.removeSplitter()

    def at(x, y, z):  # the straight edge at these coordinates, the one running along None
        def found(e):
            bb = e.BoundBox
            return all(v is None or (abs(lo - v) < 1e-9 and hi - lo < 1e-9)
                       for v, lo, hi in ((x, bb.XMin, bb.XMax), (y, bb.YMin, bb.YMax),
                                         (z, bb.ZMin, bb.ZMax)))
        return found
    wheres = [(a, None, 0.5 * c), (a, b, None), (a, None, c), (0.0, 0.0, None),
              (0.0, None, c), (0.0, b, None), (0.0, None, 0.0), (None, 0.0, c),
              (a, 0.0, None), (None, 0.0, 0.5 * c), (1.5 * a, 0.0, None),
              (1.5 * a, None, 0.0), (None, b, 0.0)]
    return s, sorted((_edge_named(s, at(*w)) for w in wheres), key=lambda n: int(n[4:])), \
        (a, b, c)


def box_with_void():
    """A 20 x 20 x 10 box with a closed 6 x 6 x 4 void from (7, 7, 3) (a solid of two
    shells, as a pocket closed by a boss fused over it makes: --random-machined 60
    --seed 13, part 9). Returns (solid, names of the box's top edge at y = 0 and of the
    void's top edge at y = 7)."""
    s = Part.makeBox(20, 20, 10).cut(Part.makeBox(6, 6, 4, V(7, 7, 3)))

    def flat(e, y, z):
        b = e.BoundBox
        return b.YLength < 1e-9 and b.ZLength < 1e-9 and abs(b.YMin - y) < 1e-9 and \
            abs(b.ZMin - z) < 1e-9
    return s, [_edge_named(s, lambda e: flat(e, 0.0, 10.0)),
               _edge_named(s, lambda e: flat(e, 7.0, 7.0))]


def placed_l_block():
    """An L block (a 12.12 x 14.86 x 15.00 box and a 4.85 wide upright on it, 30.0 high)
    turned about (0.84, -0.33, -0.44) by 239 degrees and placed at (638, -851, 374),
    to full precision (--random-edges 40 --seed 12 --turned, part 0). Returns (solid,
    names of the 13 edges that part selects)."""
    a, b, c = 12.11856018032822, 14.86208753985883, 14.996157066872572
    s = Part.makeBox(a, b, c).fuse(Part.makeBox(0.4 * a, b, 2 * c)).removeSplitter()
    s.Placement = FreeCAD.Placement(
        V(637.6402556841608, -850.7807327282451, 373.89100818708334),
        FreeCAD.Rotation(0.7290864496804582, -0.2883754381594327, -0.38102510941685774,
                         -0.489992266829357))
    return s, ["Edge%d" % k for k in (1, 4, 5, 6, 8, 9, 10, 11, 12, 13, 15, 16, 18)]


def two_bosses_and_a_hole():
    """A 25.62 x 33.03 x 6.472 block with a boss r = 4.838 at (11.94, 21.99), 2.643 high,
    a blind hole r = 3.166 at (10.87, 27.27), 3.422 deep, cut through the boss's foot
    up to z = 7.472, and a boss r = 4.465 at (18.47, 18.51), 5.662 high, which meets
    the first (a part of the random machined survey, --random-machined 60 --seed 2
    --turned, number 33). Returns (solid, names of the 6 edges selected there: the
    second boss's foot arc and top rim, the hole's short rim arc on the top face, the
    first boss's top rim arc, the vertical edge where the hole cuts the first boss, and
    the block's vertical edge at x = 0, y = 33.03)."""
    c = 6.472
    s = Part.makeBox(25.62, 33.03, c)
    s = s.fuse(Part.makeCylinder(4.838, 0.4084 * c, V(11.94, 21.99, c))).removeSplitter()
    s = s.cut(Part.makeCylinder(3.166, 0.5287 * c + 1, V(10.87, 27.27, 0.4713 * c)))
    s = s.removeSplitter().fuse(Part.makeCylinder(4.465, 0.8749 * c, V(18.47, 18.51, c)))
    s = s.removeSplitter()

    def arc(radius, z, length=None):
        return lambda e: (isinstance(e.Curve, Part.Circle) and abs(e.Curve.Radius - radius)
                          < 1e-6 and abs(e.BoundBox.ZMax - z) < 1e-6
                          and (length is None or abs(e.Length - length) < 0.1))

    def vertical(x, y):
        return lambda e: (isinstance(e.Curve, Part.Line) and e.BoundBox.ZLength > 0.5
                          and abs(e.BoundBox.XMin - x) < 1e-3 and abs(e.BoundBox.YMin - y) < 1e-3)
    return s, [_edge_named(s, p) for p in (
        arc(4.465, c, 8.79), arc(4.465, 0.8749 * c + c), arc(3.166, c, 0.87),
        arc(4.838, 0.4084 * c + c), vertical(8.401, 25.288), vertical(0.0, 33.03))]


def as_nurbs(s, names):
    """(s.toNurbs() as a solid, the names of its edges at the given edges of s)."""
    points = [s.getElement(n).valueAt(0.63 * s.getElement(n).FirstParameter
                                      + 0.37 * s.getElement(n).LastParameter) for n in names]
    ns = s.toNurbs().Solids[0]
    return ns, [min(("Edge%d" % (i + 1) for i in range(len(ns.Edges))),
                    key=lambda n: ns.getElement(n).distToShape(Part.Vertex(p))[0])
                for p in points]


def slot_plate():
    """A 40 x 20 x 5 plate with a through slot: a stadium of half-width 4 whose centre
    line runs from (12, 10) to (28, 10). Returns (solid, names of the slot's edges on
    the top face)."""
    cutter = Part.makeCylinder(4, 7, V(12, 10, -1)).fuse(
        [Part.makeCylinder(4, 7, V(28, 10, -1)), Part.makeBox(16, 8, 7, V(12, 6, -1))])
    s = Part.makeBox(40, 20, 5).cut(cutter.removeSplitter()).removeSplitter()
    names = [n for n in _edges_at(s, 5.0)
             if 1 < s.getElement(n).BoundBox.XMin and s.getElement(n).BoundBox.XMax < 39]
    assert names
    return s, names


def revolved_spline(k=1.0):
    """A part of revolution, 25 high, whose side is a B-spline profile (radius 10 at the
    bottom, 6 at the top), scaled by k. Returns (solid, names of its bottom and top rims:
    circles between the B-spline side and the planar ends)."""
    bs = Part.BSplineCurve()
    bs.interpolate([V(10, 0, 0), V(12, 0, 5), V(8, 0, 12), V(9, 0, 18), V(6, 0, 25)])
    w = Part.Wire([Part.LineSegment(V(0, 0, 0), V(10, 0, 0)).toShape(), bs.toShape(),
                   Part.LineSegment(V(6, 0, 25), V(0, 0, 25)).toShape(),
                   Part.LineSegment(V(0, 0, 25), V(0, 0, 0)).toShape()])
    s = Part.Face(w).revolve(V(0, 0, 0), V(0, 0, 1), 360)
    s.scale(k)
    names = [circle_edge(s, 0.0), circle_edge(s, 25.0 * k)]
    return s, ["Edge%d" % (i + 1) for i in names]


def elliptic_boss():
    """An elliptic boss (semi-axes 12 and 6, 10 high) on a 50 x 40 x 5 plate. Returns
    (solid, name of the boss's top edge)."""
    plate = Part.makeBox(50, 40, 5, V(-25, -20, -5))
    boss = Part.Face(Part.Wire(Part.Ellipse(V(0, 0, 0), 12, 6).toShape())).extrude(V(0, 0, 10))
    s = plate.fuse(boss).removeSplitter()
    return s, _edge_named(s, lambda e: abs(e.BoundBox.ZMin - 10) < 1e-6
                          and abs(e.BoundBox.ZMax - 10) < 1e-6)


def freeform_boss():
    """A boss 8 high on a 50 x 40 x 5 plate, its outline a periodic cubic B-spline
    through 12 points (smallest radius of curvature 1.075). Returns (solid, name of its
    top edge)."""
    pts = [V(12 * math.cos(t) * (1 + 0.15 * math.cos(3 * t)),
             8 * math.sin(t) * (1 + 0.1 * math.sin(2 * t)), 0)
           for t in [2 * math.pi * k / 12 for k in range(12)]]
    c = Part.BSplineCurve()
    c.interpolate(pts, PeriodicFlag=True)
    boss = Part.Face(Part.Wire(c.toShape())).extrude(V(0, 0, 8))
    s = Part.makeBox(50, 40, 5, V(-25, -20, -5)).fuse(boss).removeSplitter()
    return s, _edge_named(s, lambda e: isinstance(e.Curve, Part.BSplineCurve)
                          and abs(e.BoundBox.ZMin - 8) < 1e-6)


def periodic_loft(n=24):
    """A loft through six circles of n points (radius 4 + 1.5 sin(z / 3) at z = 2, 4, ...,
    12), each interpolated by FreeCAD 0.20's periodic interpolate, which makes its first
    knot double: the loft's B-spline face is clamped and closed in u, and only G1 across
    its seam u = 0. The loft stands on a 40 x 40 x 5 plate. Returns (solid, name of the
    junction edge), the face's seam meeting that edge at its vertex."""
    ws = []
    for z in range(2, 13, 2):
        r = 4 + 1.5 * math.sin(z / 3.0)
        c = Part.BSplineCurve()
        c.interpolate([V(r * math.cos(2 * math.pi * k / n), r * math.sin(2 * math.pi * k / n),
                         z) for k in range(n)], PeriodicFlag=True)
        ws.append(Part.Wire(c.toShape()))
    s = Part.makeBox(40, 40, 5, V(-20, -20, 0)).fuse(Part.makeLoft(ws, True)).removeSplitter()
    return s, _edge_named(s, lambda e: abs(e.BoundBox.ZMin - 5) < 1e-6
                          and abs(e.BoundBox.ZMax - 5) < 1e-6 and abs(e.BoundBox.XMax) < 7)


def equal_tee():
    """A pipe r = 6 standing on the axis of another r = 6 (axis y, 30 long): the junction
    is two half-ellipses, split into 4 edges, that meet at (-6, 0, 0) and (6, 0, 0), where
    the two cylinders have the same normal (along x). Returns (solid, names of the 4
    junction edges)."""
    big = Part.makeCylinder(6, 30, V(0, -15, 0), V(0, 1, 0))
    s = big.fuse(Part.makeCylinder(6, 12)).removeSplitter()
    return s, ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
               if len(s.ancestorsOfType(e, Part.Face)) == 2 and e.BoundBox.ZMin > -1e-9
               and 1 < e.BoundBox.ZMax < 6 + 1e-6
               and not any(e.isSeam(f) for f in s.ancestorsOfType(e, Part.Face))]


def crossing_bores():
    """A 20 x 20 x 20 box bored through by two holes r = 3 along x and y, their axes
    crossing at the centre (10, 10, 10): the bores meet in two half-ellipses each way
    (6 edges), tangent to each other at (10, 10, 7) and (10, 10, 13). Returns (solid,
    names of the 6 bore-to-bore edges, name of the x bore's rim on the face x = 0)."""
    s = Part.makeBox(20, 20, 20).cut(Part.makeCylinder(3, 40, V(10, -10, 10), V(0, 1, 0))) \
        .cut(Part.makeCylinder(3, 40, V(-10, 10, 10), V(1, 0, 0)))
    bores = ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
             if len({f.hashCode() for f in s.ancestorsOfType(e, Part.Face)}) == 2
             and all(isinstance(f.Surface, Part.Cylinder)
                     for f in s.ancestorsOfType(e, Part.Face))]
    rim = _edge_named(s, lambda e: isinstance(e.Curve, Part.Circle)
                      and e.BoundBox.XMax < 1e-9)
    assert len(bores) == 6, bores
    return s, bores, rim


def square_to_circle_loft():
    """A ruled loft from a 10 x 10 square at z = 0 to a circle r = 4 at z = 12: its
    B-spline faces meet at an angle along the square's corner lines, tangent where
    those lines reach the circle (at 45, 135, 225 and 315 degrees); a fifth edge,
    tangent all along, runs to the circle's seam and splits one side in two. Returns
    (solid, names of the four corner lines)."""
    square = Part.makePolygon([V(-5, -5, 0), V(5, -5, 0), V(5, 5, 0), V(-5, 5, 0),
                               V(-5, -5, 0)])
    s = Part.makeLoft([square, Part.Wire(Part.makeCircle(4, V(0, 0, 12)))], True, True)
    top = [max(e.Vertexes, key=lambda v: v.Point.z).Point for e in s.Edges]
    return s, ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
               if e.BoundBox.ZLength > 11 and abs(abs(top[i].x) - abs(top[i].y)) < 1e-6]


def helical_ridge(turns=3):
    """A circle r = 0.8 swept along a helix (radius 10, pitch 4, `turns` turns) and fused
    with a cylinder r = 10 as high: a ridge half sunk in it, its B-spline face meeting
    the cylinder along helical edges that wind round the cylinder's seam. Returns
    (solid, names of those junction edges)."""
    helix = Part.Wire(Part.makeHelix(4, 4 * turns, 10))
    ridge = helix.makePipeShell([Part.Wire(Part.makeCircle(0.8, V(10, 0, 0), V(0, 1, 0)))],
                                True, True)
    s = Part.makeCylinder(10, 4 * turns).fuse(ridge).removeSplitter()
    kinds = [{type(f.Surface) for f in s.ancestorsOfType(e, Part.Face)} for e in s.Edges]
    return s, ["Edge%d" % (i + 1) for i, k in enumerate(kinds)
               if k == {Part.Cylinder, Part.BSplineSurface}]


def nurbs_sphere_through_plate(turn):
    """A sphere r = 5 centred at (0, 0, 7), converted by toNurbs() (a rational B-spline,
    only C0 at its knots: the BOP check flags it) and turned by `turn` degrees about the
    z axis, fused through a 40 x 40 x 5 plate. Returns (solid, name of the junction
    circle at z = 5)."""
    sphere = Part.Solid(Part.Shell(Part.makeSphere(5, V(0, 0, 7)).Faces[0].toNurbs().Faces))
    sphere.rotate(V(0, 0, 7), V(0, 0, 1), turn)
    s = Part.makeBox(40, 40, 5, V(-20, -20, 0)).fuse(sphere).removeSplitter()
    return s, _edge_named(s, lambda e: abs(e.BoundBox.ZMin - 5) < 1e-6
                          and abs(e.BoundBox.ZMax - 5) < 1e-6 and 5 < e.BoundBox.XLength < 12)


def nurbs_sphere_on_its_side(axis="y"):
    """nurbs_sphere_through_plate, but the sphere turned by 90 degrees about the x or y
    `axis` (its poles at z = 7). About x, the BOP check finds a self-intersection on
    this input besides its C0 geometry. Returns (solid,
    names of the junction edges at z = 5: two about y, where the junction crosses the
    sphere's seam, one about x)."""
    sphere = Part.Solid(Part.Shell(Part.makeSphere(5, V(0, 0, 7)).Faces[0].toNurbs().Faces))
    sphere.rotate(V(0, 0, 7), V(1, 0, 0) if axis == "x" else V(0, 1, 0), 90)
    s = Part.makeBox(40, 40, 5, V(-20, -20, 0)).fuse(sphere).removeSplitter()
    return s, ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
               if abs(e.BoundBox.ZMin - 5) < 1e-6 and abs(e.BoundBox.ZMax - 5) < 1e-6
               and 5 < e.BoundBox.XLength < 12]


def ellipsoid_on_plate():
    """FreeCAD's Part Ellipsoid primitive, 6 along x, 3 along y and z (a rational
    B-spline with double knots, only C0 to the BOP check), fused on a 30 x 30 x 3 plate
    below z = 0. Returns (solid, name of the junction at z = 0)."""
    doc = FreeCAD.newDocument("EllipsoidOnPlate")
    try:
        e = doc.addObject("Part::Ellipsoid", "Ellipsoid")
        e.Radius1, e.Radius2, e.Radius3 = 3, 6, 3
        doc.recompute()
        ell = e.Shape.copy()
    finally:
        FreeCAD.closeDocument(doc.Name)
    s = ell.fuse(Part.makeBox(30, 30, 3, V(-15, -15, -3))).removeSplitter()
    return s, _edge_named(s, lambda x: abs(x.BoundBox.ZMin) < 1e-6
                          and abs(x.BoundBox.ZMax) < 1e-6 and abs(x.BoundBox.XLength - 12) < 1)


def crossing_lofts():
    """A loft through 6 x 4, 5 x 3.5 and 6 x 4 ellipses at z = 0, 6 and 12, and one
    through ellipses of 0.4 that size from z = -4 to 16, turned to lie along y through
    (0, 0, 6): their junction runs between two B-spline faces."""
    def loft(k, z0, z1):
        return Part.makeLoft([Part.Wire(Part.Ellipse(V(0, 0, z), a * k, b * k).toShape())
                              for z, (a, b) in ((z0, (6, 4)), (0.5 * (z0 + z1), (5, 3.5)),
                                                (z1, (6, 4)))], True, False)
    cross = loft(0.4, -4, 16)
    cross.rotate(V(0, 0, 6), V(1, 0, 0), 90)
    return loft(1.0, 0, 12).fuse(cross).removeSplitter()


def open_box():
    """A 20 x 20 x 10 box shelled 1.5 thick (makeThickness), open at its top."""
    b = Part.makeBox(20, 20, 10)
    return b.makeThickness([f for f in b.Faces if abs(f.CenterOfMass.z - 10) < 1e-9], -1.5,
                           1e-6)


def wavy_top_block():
    """A 40 x 30 x 20 block whose top is cut by a cubic B-spline surface interpolated
    over a 5 mm grid from x = -5 to 45, z = 15 + 2 sin(x / 6): its knot lines run every
    5 mm in x, two of them on the block's sides x = 0 and x = 40. Returns (solid, name of
    the top's front edge, at y = 0)."""
    pts = [[V(x, y, 15 + 2 * math.sin(x / 6.0)) for y in range(-5, 36, 5)]
           for x in range(-5, 46, 5)]
    top = Part.BSplineSurface()
    top.interpolate(pts)
    s = Part.makeBox(40, 30, 20).cut(top.toShape().extrude(V(0, 0, 20))).removeSplitter()
    return s, _edge_named(s, lambda e: abs(e.BoundBox.YMax) < 1e-6 and e.BoundBox.ZMin > 10
                          and e.BoundBox.XLength > 30)


def circle_edge(shape, z):
    """Index (0-based) of the circular edge of shape at height z."""
    for i, e in enumerate(shape.Edges):
        if isinstance(e.Curve, Part.Circle) and abs(e.Curve.Center.z - z) < 1e-9 * max(1.0, abs(z)):
            return i
    raise AssertionError("no circle at z = %g" % z)


def document_state(doc):
    """Per object: name, label, state, BREP hash and volume of its shape (if any)."""
    out = []
    for o in doc.Objects:
        sh = getattr(o, "Shape", None)
        out.append((o.Name, o.Label, tuple(o.State),
                    hashlib.sha1(sh.exportBrepToString().encode()).hexdigest() if sh else None,
                    round(sh.Volume, 9) if sh and sh.Solids else None))
    return out


def losing_far_face(sewn, shape, edge):
    """A stand-in for the fillet's sewing function `sewn` (assembly._sewn) that first loses
    the face of `shape` farthest from `edge`: the shell then has free edges that touch
    no blend, so the sewing fails."""
    far = max(shape.Faces, key=lambda f: f.distToShape(edge)[0]).CenterOfMass

    def lose(faces):
        lost = min(faces, key=lambda f: f.distToShape(Part.Vertex(far))[0])
        return sewn([f for f in faces if f is not lost])

    return lose


def scaled_torus_on_plate(scale=(1.5, 1.5, 1.5), z=1.0, turn=0.0):
    """A torus (radii 5 and 2, centred at (0, 0, z), turned by `turn` degrees about its
    axis) scaled by `scale` with transformGeometry, which makes it a rational B-spline
    periodic in both directions, only C0 at its knots; fused on a 40 x 40 x 3 plate
    below z = 0. Its face above the plate spans, in the tube's direction, parameters
    across the surface's periodic range (v in [5.72, 9.91] of [0, 2 pi] for the
    default). Returns (solid, names of the two junctions at z = 0, outer first)."""
    t = Part.makeTorus(5, 2, V(0, 0, z))
    t.rotate(V(0, 0, z), V(0, 0, 1), turn)
    m = FreeCAD.Matrix()
    m.scale(*scale)
    plate = Part.makeBox(40, 40, 3, V(-20, -20, -3))
    s = plate.fuse(t.transformGeometry(m)).removeSplitter()
    rims = sorted((e for e in s.Edges if abs(e.BoundBox.ZMin) < 1e-6
                   and abs(e.BoundBox.ZMax) < 1e-6 and 1 < e.BoundBox.XLength < 30),
                  key=lambda e: -e.Length)
    return s, ["Edge%d" % (i + 1) for r in rims
               for i, e in enumerate(s.Edges) if e.isSame(r)]


def box_rounded_but_one_corner():
    """A 20 x 20 x 6 box whose vertical edges are rounded at r = 3 (OCCT), but the one at
    (0, 0), as a padded sketch of a rectangle with three corners rounded; and the name of
    its top edge along y = 0. Its top outline is one tangent chain of 4 lines and 3 arcs,
    whose two ends meet at the sharp corner (0, 0, 6)."""
    s = Part.makeBox(20, 20, 6)
    s = s.makeFillet(3.0, [e for e in s.Edges if e.BoundBox.ZLength > 1
                           and (e.BoundBox.XMin > 1e-9 or e.BoundBox.YMin > 1e-9)])
    return s, _edge_named(s, lambda e: e.BoundBox.ZMin > 6 - 1e-9 and e.BoundBox.YMax < 1e-9)


def pocket_with_rounded_corners():
    """A 30 x 30 x 10 block with a 10 x 8 pocket 5 deep, its vertical corners rounded at
    r = 1 (a milled pocket); and the names of the pocket floor's 8 edges (4 lines, 4
    arcs of radius 1), one tangent chain."""
    tool = Part.makeBox(10, 8, 6, V(10, 10, 5))
    tool = tool.makeFillet(1.0, [e for e in tool.Edges if e.BoundBox.ZLength > 1])
    s = Part.makeBox(30, 30, 10).cut(tool).removeSplitter().Solids[0]
    return s, _edges_at(s, 5)


def small_pocket_with_rounded_corners():
    """A 12 x 12 x 6 block with a 4.4 x 3.8 pocket 2.7 deep, its vertical corners rounded
    at r = 1.136 (the floor's straight edges 2.128 and 1.528 long), as the pocket of
    tools/fillet_survey.py --random-plates 40 --seed 64, part 14; and the names of the
    pocket floor's 8 edges, one tangent chain."""
    tool = Part.makeBox(4.4, 3.8, 4, V(4, 4, 3.3))
    tool = tool.makeFillet(1.136, [e for e in tool.Edges if e.BoundBox.ZLength > 1])
    s = Part.makeBox(12, 12, 6).cut(tool).removeSplitter().Solids[0]
    return s, _edges_at(s, 3.3)


def open_pocket():
    """A 20 x 20 x 10 block with a 10 x 10 pocket 6 deep, x and y from 5 to 15; and the
    name of the pocket's rim edge at x = 5, between the top and the wall x = 5, whose
    ends meet the walls y = 5 and y = 15 at concave corners."""
    s = Part.makeBox(20, 20, 10).cut(Part.makeBox(10, 10, 6, V(5, 5, 4))).removeSplitter()
    return s, _edge_named(s, lambda e: e.BoundBox.ZMin > 10 - 1e-9
                          and e.BoundBox.XLength < 1e-9 and abs(e.BoundBox.XMin - 5) < 1e-9)


def boss_over_pocket_rim():
    """A 32 x 34 x 13 block with a pocket x 2.4 to 9.9, y 6.5 to 12.1, 8.4 deep, and a
    boss of radius 4.25 and height 10.7 on the top, centred at (6.45, 12.15): its base
    overhangs the pocket, its foot circle crossing the rim x = 9.9 at y = 9.67 and x =
    2.4 at y = 10.86 (after --random-machined 40 --seed 75 --turned, part 2, in round
    figures). Returns (solid, the rim edge of the wall x = 9.9 with the top, convex,
    ending at the circle, and the edge of the wall x = 2.4 with the boss's base,
    concave, ending at the circle)."""
    s = Part.makeBox(32, 34, 13).cut(Part.makeBox(7.5, 5.6, 8.4, V(2.4, 6.5, 4.6)))
    s = s.fuse(Part.makeCylinder(4.25, 10.7, V(6.45, 12.15, 13))).removeSplitter()

    def at(x, under):  # the edge on the wall x at the top, under the boss's base or not
        return _edge_named(s, lambda e: e.BoundBox.ZMin > 13 - 1e-9 and e.BoundBox.XLength
                           < 1e-9 and abs(e.BoundBox.XMin - x) < 1e-9
                           and (e.BoundBox.YMin > 10.5) == under)
    return s, at(9.9, False), at(2.4, True)


def three_slots():
    """A 39.24 x 39.62 x 9.757 block with three slots of rounded ends (half-widths 3.547,
    3.569 and 0.7777; the rounded ends of the first two overlap), to full precision
    (--random-machined 40 --seed 24, part 19). Its Edge41 and Edge56 are arcs of the
    second slot's floor where the first one crosses it, a convex and a concave edge
    meeting at a vertex; OCCT's fillet of them at R = 0.03 passes isValid() but fails
    its own BOP check (12 tiny edges, 12 self-intersecting vertices, 2 curves off their
    faces)."""
    a, b, c = 39.2359917278954, 39.62043672760976, 9.75710061866642
    s = Part.makeBox(a, b, c)
    for r, x, y, k, f in ((7.093420698406275, 15.044503806939238, 24.8208131338423,
                           1.0999193534611202, 0.4735498618840003),
                          (7.137447887877721, 28.354941432989456, 29.97343347750087,
                           1.3243236838912922, 0.3379318708744775),
                          (1.5553725497957327, 27.8557426162698, 8.149058598359808,
                           1.0761853962136145, 0.6681804501210956)):
        w, length, depth = 0.5 * r, k * r, f * c
        tool = Part.makeBox(length, 2 * w, depth + 1, V(x - 0.5 * length, y - w, c - depth))
        for end in (-0.5, 0.5):
            tool = tool.fuse(Part.makeCylinder(w, depth + 1, V(x + end * length, y, c - depth)))
        s = s.cut(tool).removeSplitter()
    return s


def tall_step():
    """A 10.58 x 16.44 x 15.81 block with a block half as wide and half as tall beside
    it (x from 10.58 to 15.87), to full precision (--random-edges 40 --seed 31 --turned,
    part 17, unturned), and the names of its ten edges that part fillets at R = 2.5: the
    tall block's top edges along y at x = 0 and x = 10.58 and along x at y = 0, its
    edges at x = 0 and y = 16.44 (vertical) and along y on the bottom, the step's
    riser's edge at y = 0 (vertical, convex) and the step's two edges along y (concave
    at x = 10.58, convex at x = 15.87), the low block's vertical edge at x = 15.87,
    y = 0, and the bottom edge along x at y = 16.44. The riser's edge and the concave
    one meet at (10.58, 0, 7.90), whose third edge (along x at y = 0) is not
    selected."""
    a, b, c = 10.577757879704462, 16.43748006088694, 15.809080168923774
    s = Part.makeBox(a, b, c).fuse(Part.makeBox(0.5 * a, b, 0.5 * c, V(a, 0, 0)))
    s = s.removeSplitter()
    return s, ["Edge2", "Edge3", "Edge4", "Edge6", "Edge7", "Edge8", "Edge10", "Edge12",
               "Edge14", "Edge18"]


def rounded_plate(r=0.3):
    """A 20 x 20 x 6 plate whose four vertical edges are rounded at r (OCCT), and the name
    of its top edge along y = 0: its top outline is one tangent chain of 4 lines and 4
    arcs of radius r."""
    s = Part.makeBox(20, 20, 6)
    s = s.makeFillet(r, [e for e in s.Edges if e.BoundBox.ZLength > 1])
    return s, _edge_named(s, lambda e: e.BoundBox.ZMin > 6 - 1e-9 and e.BoundBox.YMax < 1e-9
                          and e.BoundBox.XLength > 1)


def off_curve_block():
    """A 25.32 x 25.40 x 13.81 block with a through hole (r = 2.906) and a slot, to full
    precision, made B-splines (--random-machined 40 --seed 96 --splines, part 38). The
    top face's edge curves lie off it between BRepCheck's samples: BRepCheck passes,
    OCCT's BOP check finds BOPAlgo_InvalidCurveOnSurface on that face, alone too.
    Returns (solid, its top face's name, the name of its bottom edge at x = 0)."""
    a, b, c = 25.319119937043713, 25.40040128168709, 13.806562350778957
    s = Part.makeBox(a, b, c)
    s = s.cut(Part.makeCylinder(2.906233942372771, c + 2,
                                V(10.417930020442586, 8.822345820829911, -1))).removeSplitter()
    r, x, y = 4.325544314073051, 12.007681635950414, 7.636227622914863
    w, length, depth = 0.5 * r, 0.8175662529621524 * r, 0.6743093050570319 * c
    tool = Part.makeBox(length, 2 * w, depth + 1, V(x - 0.5 * length, y - w, c - depth))
    for end in (-0.5, 0.5):
        tool = tool.fuse(Part.makeCylinder(w, depth + 1, V(x + end * length, y, c - depth)))
    s = s.cut(tool).removeSplitter().toNurbs()
    s = s.Solids[0] if s.ShapeType != "Solid" else s
    top = next(k for k, f in enumerate(s.Faces) if f.BoundBox.ZLength < 1e-9
               and abs(f.BoundBox.ZMin - c) < 1e-9)
    edge = _edge_named(s, lambda e: e.BoundBox.XLength < 1e-9 and e.BoundBox.XMin < 1e-9
                       and e.BoundBox.ZLength < 1e-9 and e.BoundBox.ZMin < 1e-9)
    return s, "Face%d" % (top + 1), edge


def read_back(shape, form, folder):
    """shape saved in a FreeCAD document and opened again (form "FCStd"), or written to
    a STEP or BREP file (exportStep, exportBrep) and read back (Part.read), in the
    pathlib folder `folder`."""
    path = str(folder / ("read_back." + form.lower()))
    if form != "FCStd":
        (shape.exportStep if form == "STEP" else shape.exportBrep)(path)
        return Part.read(path)
    doc = FreeCAD.newDocument("ReadBack")
    doc.addObject("Part::Feature", "Result").Shape = shape
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    doc = FreeCAD.openDocument(path)
    out = doc.getObject("Result").Shape.copy()
    FreeCAD.closeDocument(doc.Name)
    return out
