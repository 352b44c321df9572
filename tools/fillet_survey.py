#!/usr/bin/python3
"""C2 Fillet on a handful of typical parts: what each gives (G2 blend, or OCCT's faces
kept and why), the worst continuity over its trimlines, whether the solid is valid, the
time, and the same check on OCCT's own fillet of the same edges. With --validation it also times
OCCT's validity checks on the filleted shaft-on-plate solid. With --all-edges it fillets
every edge of some parts instead (the corners filled, the fillets kept and why); with
--random N, the junctions of N random parts (bosses, holes, cones, spheres on a plate);
with --random-edges N, random sets of edges of N random blocks (corners where fillets
meet, convex and concave); with --random-machined N, of N blocks machined by holes,
pockets, slots, bosses and chamfers; with --random-shafts N, of N turned parts (steps,
tapers, grooves, bores); with --random-plates N, of N padded plates whose outlines
have rounded corners (tangent chains), holes and pockets. With --bop-times, the
processor and clock time of OCCT's BOP check on a filleted pentagonal prism and on its
plate fillings' neighbourhoods, which bopcheck's time limits allow for. With --only
TEXT, the handful of typical parts is cut down to those whose name contains TEXT (to
time them). With --turned, each random part is turned and moved to a random placement
first; with --splines, made B-splines (toNurbs) first; with --read-back, each result is
also written to a STEP file and saved in a FreeCAD document, read back from each, and
checked again (OCCT's BOP check). With --sweep R1,R2,..., every
edge alone of nine plain parts (pockets, a step, a bracket, a boss on a wall, slots,
ribs) at each radius; with --pairs too, every two edges that meet at a vertex.

usage: C2B_MODULE_DIR=build/plugin/ext /usr/bin/python3 tools/fillet_survey.py
       [--validation] [--only TEXT] [--all-edges]
       [--random N | --random-edges N | --random-machined N | --random-shafts N |
        --random-plates N [--seed S] [--turned] [--splines] [--read-back] |
        --sweep R1,R2,... [--pairs]]
       [--bop-times]
"""
import argparse
import math
import os
import pathlib
import statistics
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.append("/usr/lib/freecad-python3/lib")
sys.path.insert(0, os.environ.get("C2B_MODULE_DIR", os.path.join(HERE, "..", "build", "plugin", "ext")))
sys.path.insert(0, os.path.join(HERE, "..", "plugin", "C2Blend"))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "freecad"))
os.environ.setdefault("HOME", tempfile.mkdtemp())

import FreeCAD  # noqa: E402
import Part  # noqa: E402

import C2Blend  # noqa: E402
import shapes  # noqa: E402
from c2bwb.geometry.rollingball import RollingBallFace, midpoint, new_faces  # noqa: E402

V = FreeCAD.Vector


def curve_is(e, kind):
    try:
        return isinstance(e.Curve, kind)
    except Exception:  # curves FreeCAD cannot wrap
        return False


def names(s, pred):
    return ["Edge%d" % (i + 1) for i, e in enumerate(s.Edges) if pred(e)]


def parts():
    """(name, solid, edge names, radius) of each part."""
    out = []
    b = Part.makeBox(10, 10, 10)
    out.append(("box, one edge", b, ["Edge1"], 2.0))
    s, n = shapes.shaft_on_plate()
    out.append(("shaft on plate", s, [n], 2.0))
    s, n = shapes.loft()
    out.append(("loft (B-spline face) / plane", s, [n], 1.5))
    out.append(("box, 4 top edges", b, names(b, lambda e: abs(e.BoundBox.ZMin - 10) < 1e-9
                                          and abs(e.BoundBox.ZMax - 10) < 1e-9), 2.0))
    c = Part.makeCylinder(5, 10)
    out.append(("cylinder top circle", c, names(c, lambda e: curve_is(e, Part.Circle)
                                                 and abs(e.BoundBox.ZMin - 10) < 1e-9), 1.0))
    p = Part.makeBox(40, 40, 5, V(-20, -20, 0)).cut(Part.makeCylinder(5, 5))
    out.append(("hole edge in a plate", p, names(p, lambda e: curve_is(e, Part.Circle)
                                                 and abs(e.BoundBox.ZMin - 5) < 1e-9), 1.0))
    k = Part.makeCone(6, 3, 8).fuse(Part.makeBox(30, 30, 3, V(-15, -15, -3))).removeSplitter()
    out.append(("cone on a plate", k, names(k, lambda e: curve_is(e, Part.Circle)
                                            and abs(e.BoundBox.ZMin) < 1e-9
                                            and e.BoundBox.XMax < 7), 1.5))
    s, n = shapes.split_shaft_on_plate()
    out.append(("shaft of two half cylinders", s, n, 2.0))
    t, n = shapes.pipe_tee()
    out.append(("pipe tee", t, n, 1.0))
    t, n = shapes.unequal_tee()
    out.append(("pipe r = 3 on r = 6, across its seam", t, n, 0.5))
    sp = Part.makeSphere(6).cut(Part.makeBox(20, 20, 20, V(-10, -10, 2)))
    out.append(("sphere cap", sp, names(sp, lambda e: not e.Degenerated
                                        and len(sp.ancestorsOfType(e, Part.Face)) == 2
                                        and abs(e.BoundBox.ZMin - 2) < 1e-9), 1.0))
    sl = Part.makeBox(20, 10, 5).fuse(Part.makeCylinder(5, 5, V(20, 5, 0))).removeSplitter()
    out.append(("slot-like plate, long top edge", sl,
                names(sl, lambda e: curve_is(e, Part.Line) and abs(e.BoundBox.ZMin - 5) < 1e-9
                      and abs(e.BoundBox.YMax) < 1e-9), 1.0))
    cutter = Part.makeBox(60, 60, 40, V(-30, -30, 15))
    cutter.rotate(V(0, 0, 15), V(1, 0, 0), 30)
    w = Part.makeBox(10, 10, 20).cut(cutter)
    out.append(("box edge ending on a 30 degree slanted top", w,
                names(w, lambda e: e.BoundBox.XMax < 1e-9 and e.BoundBox.YMax < 1e-9
                      and e.BoundBox.ZLength > 1), 2.0))
    for bulge in ("cylinder", "sphere"):
        bx, edge = shapes.box_into(bulge)
        out.append(("box edge ending on a %s bulging out" % bulge, bx, [edge], 1.0))
    cc = Part.makeBox(30, 10, 10).cut(Part.makeCylinder(15, 10, V(40, 5, 0)))
    out.append(("box edge ending on a concave cylinder", cc,
                names(cc, lambda e: curve_is(e, Part.Line) and abs(e.BoundBox.ZMin - 10) < 1e-9
                      and abs(e.BoundBox.YMax) < 1e-9), 1.0))
    out.append(("box edge, R = 6 (over half the faces)", b, ["Edge1"], 6.0))
    lb, outer, inner = shapes.l_bracket()
    out.append(("L bracket, outer edge", lb, [outer], 2.0))
    out.append(("L bracket, inner (concave) edge", lb, [inner], 2.0))
    st, concave, convex = shapes.step()
    out.append(("step, concave and convex edges", st, [concave, convex], 2.0))
    rb, arc = shapes.ruled_block()
    out.append(("ruled B-spline face / plane (arc edge)", rb, [arc], 1.5))
    for axis in ("z", "x"):
        sb, inner = shapes.slanted_l_bracket(axis)
        out.append(("L bracket, inner edge, end tilted 20 degrees about %s" % axis, sb,
                    [inner], 2.0))
    wc, edge = shapes.wall_into_cylinder()
    out.append(("concave wall/plate edge running into a cylinder", wc, [edge], 2.0))
    for angle in (90.0, 135.0):
        lb, edges = shapes.loft_with_boss(angle)
        out.append(("boss on a loft, %g degrees from its seam" % angle, lb, edges, 1.5))
    rx, edges = shapes.rounded_box()
    out.append(("rounded box, top outline (side changes face)", rx, edges, 1.0))
    so, edges = shapes.slot_plate()
    out.append(("slot in a plate, its rim (side changes face)", so, edges, 1.0))
    for n in (24, 12):
        pl, edge = shapes.periodic_loft(n)
        out.append(("loft through %d-point periodic circles, on a plate (only G1 at its seam)"
                    % n, pl, [edge], 1.0))
    bs, edges = shapes.loft_with_boss(0.0)
    out.append(("boss on a loft, on its seam", bs, edges, 1.0))
    ol, _, edge = shapes.offset_loft()
    out.append(("loft offset by 0.5 (OffsetSurface), its bottom rim", ol, [edge], 1.0))
    et, edges = shapes.equal_tee()
    out.append(("equal pipes r = 6 in a tee (faces tangent at 2 points)", et, edges, 1.0))
    ns, edge = shapes.nurbs_sphere_through_plate(45.0)
    out.append(("toNurbs() sphere through a plate, turned 45 degrees", ns, [edge], 1.0))
    for axis in ("x", "y"):
        ns, edges = shapes.nurbs_sphere_on_its_side(axis)
        out.append(("toNurbs() sphere through a plate, turned on its side about %s" % axis,
                    ns, edges, 1.0))
    ep, edge = shapes.ellipsoid_on_plate()
    for r in (0.3, 0.8, 2.0):
        out.append(("Part Ellipsoid 6 x 3 x 3 on a plate (only C0)", ep, [edge], r))
    for scale, z, turn, r in (((1.5, 1.5, 1.5), 1.0, 0.0, 0.4),
                              ((1.5, 1.0, 1.0), 1.0, 0.0, 0.4),
                              ((1.5, 1.5, 1.5), 0.5, 30.0, 0.4),
                              ((1.5, 1.2, 1.0), 1.0, 20.0, 0.3),
                              ((1.5, 1.2, 1.0), 0.5, 20.0, 0.5)):
        tp, edges = shapes.scaled_torus_on_plate(scale, z, turn)
        out.append(("torus scaled %s by transformGeometry, at z = %g turned %g, on a plate"
                    % ("x".join("%g" % x for x in scale), z, turn), tp, edges, r))
    cl = shapes.crossing_lofts()
    out.append(("two crossing lofts of ellipses (B-spline / B-spline)", cl,
                names(cl, lambda e: len(cl.ancestorsOfType(e, Part.Face)) == 2 and all(
                    isinstance(f.Surface, Part.BSplineSurface)
                    for f in cl.ancestorsOfType(e, Part.Face))), 0.25))
    st, edges = shapes.stepped_shaft()
    out.append(("stepped shaft, the cone's two edges (a strip of cone between)", st,
                edges[3:], 0.8))
    out.append(("stepped shaft, its five circles", st, edges, 0.8))
    fb, edge = shapes.freeform_boss()
    for r in (0.5, 0.8):
        out.append(("free-form boss, its top outline (pieces meet on its side's seam)", fb,
                    [edge], r))
    cb, bores, rim = shapes.crossing_bores()
    out.append(("crossing bores r = 3 (tangent where they cross), with a rim", cb,
                bores + [rim], 0.5))
    sc, corners = shapes.square_to_circle_loft()
    out.append(("square-to-circle loft, its corner lines (tangent at the circle)", sc,
                corners, 0.5))
    for turns in (1, 1.5, 2, 2.5, 3):
        hr, edges = shapes.helical_ridge(turns)
        out.append(("helical ridge on a cylinder, %g turn(s)" % turns, hr.copy(), edges, 0.3))
    pair = Part.makeCompound([b, Part.makeBox(10, 10, 10, V(20, 0, 0))])
    out.append(("compound of two boxes, an edge of each", pair, ["Edge1", "Edge13"], 2.0))
    return out


def occt_check(shape, edges, r):
    """The continuity check on OCCT's own fillet of the same edges, across its contact
    edges: 'verdict, angle, jump' (worst over the edges)."""
    res = shape.makeFillet(r, [shape.getElement(e) for e in edges])
    ff = new_faces(shape, res)
    contacts = [e for f in ff for e, _ in RollingBallFace(res, f, ff).contacts]
    if not contacts:
        return "no contact edges"
    rep = C2Blend.check(res, contacts)
    return "%s, %.1e rad, %.2g rel" % (rep["verdict"], max(x["g1"] for x in rep["edges"]),
                                       max(x["g2_rel"] for x in rep["edges"]))


def survey(only=""):
    print("| part | edges | R | verdict | valid | blends | kept | worst angle (rad) | worst "
          "jump (rel) | samples | data error | ms | kept because | OCCT's fillet: check |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name, shape, edges, r in parts():
        if only not in name:
            continue
        t0 = time.perf_counter()
        try:
            solid, rep = C2Blend.fillet_report(shape, edges, r)
        except C2Blend.Error as ex:
            print("| %s | %d | %g | error |%s %s | |" % (name, len(edges), r, " |" * 8, ex))
            continue
        ms = 1e3 * (time.perf_counter() - t0)
        why = sorted({k["reason"] for k in rep["kept_occt_faces"]})
        tl, bl = rep["trimlines"], rep["blends"]
        worst = ("%.1e | %.1e" % (max(t["g1"] for t in tl), max(t["g2_rel"] for t in tl))
                 if tl else " | ")
        data = ("%s | %.1e" % ("/".join(str(b["samples"]) for b in bl),
                               max(b["data_error"] for b in bl)) if bl else " | ")
        print("| %s | %d | %g | %s | %s | %d | %d | %s | %s | %.0f | %s | %s |"
              % (name, len(edges), r, rep["verdict"], solid.isValid(), len(bl),
                 len(rep["kept_occt_faces"]), worst, data, ms, "; ".join(why),
                 occt_check(shape, edges, r)))


def first(x):
    """The solid of what a shapes.* function returns: x, or its first item."""
    return x[0] if isinstance(x, tuple) else x


def all_edge_parts():
    """(name, solid, radius) of each part whose every edge is filleted."""
    out = [("box 10", Part.makeBox(10, 10, 10), 2.0),
           ("box 20 x 20 x 10 with a hole", Part.makeBox(20, 20, 10).cut(
               Part.makeCylinder(3, 10, V(10, 10, 0))), 1.0),
           ("box 20 x 20 x 10 (a BOP check loop at one corner)", Part.makeBox(20, 20, 10),
            0.5),
           ("box 20 x 20 x 10, shelled 1.5 thick, open at its top", shapes.open_box(), 0.5)]
    for name, make, radii in (("spline prism", shapes.spline_prism, (1.0,)),
                              ("spline extrusion", shapes.spline_extrusion, (1.0,)),
                              ("wavy B-spline top block", shapes.wavy_top_block, (1.0,)),
                              ("partial revolution", shapes.partial_revolution, (0.5, 1.0, 2.0)),
                              ("gusset bracket", shapes.gusset_bracket, (0.5, 1.0))):
        out += [(name, first(make()), r) for r in radii]
    return out


def all_edges():
    print("| part | R | edges | verdict | valid | blends | kept | corners filled | worst corner "
          "seam (rad) | solid | s | kept because |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name, shape, r in all_edge_parts():
        edges = shapes.every_edge(shape)
        t0 = time.perf_counter()
        try:
            solid, rep = C2Blend.fillet_report(shape, edges, r)
        except C2Blend.Error as ex:
            print("| %s | %g | %d | error |%s %s |" % (name, r, len(edges), " |" * 7, ex))
            continue
        kept = [k for k in rep["kept_occt_faces"] if not k["where"].startswith("corner")]
        corners = rep["corner_patches"]
        why = sorted({k["reason"] for k in kept})
        print("| %s | %g | %d | %s | %s | %d | %d | %d | %s | %s | %.1f | %s |"
              % (name, r, len(edges), rep["verdict"], solid.isValid(), len(rep["blends"]),
                 len(kept), len(corners),
                 "%.1e" % max(c["g1"] for c in corners) if corners else "",
                 rep["solid_check"], time.perf_counter() - t0, "; ".join(why)))


def random_part(rng):
    """(kind, solid, names of the junction edges, radius): a 40 x 40 x 6 plate with a
    boss, hole, tilted boss, cone, sphere or turned box of random size and place."""
    plate = Part.makeBox(40, 40, 6, V(-20, -20, -6))
    kind = rng.choice(["boss", "hole", "tilted boss", "cone boss", "sphere bump", "box boss"])
    r, x, y = rng.uniform(2, 8), rng.uniform(-8, 8), rng.uniform(-8, 8)
    if kind == "boss":
        tool = Part.makeCylinder(r, 10, V(x, y, -1))
    elif kind == "hole":
        tool = Part.makeCylinder(r, 20, V(x, y, -10))
    elif kind == "tilted boss":
        tool = Part.makeCylinder(r, 12, V(x, y, -3),
                                 V(rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), 1))
    elif kind == "cone boss":
        tool = Part.makeCone(r, r * rng.uniform(0.2, 0.9), 10, V(x, y, -1))
    elif kind == "sphere bump":
        tool = Part.makeSphere(r, V(x, y, rng.uniform(-0.8 * r, 0.5 * r)))
    else:
        tool = Part.makeBox(r, 1.3 * r, 5, V(x, y, -1))
        tool.rotate(V(x, y, 0), V(0, 0, 1), rng.uniform(0, 90))
    s = (plate.cut(tool) if kind == "hole" else plate.fuse(tool)).removeSplitter()
    radius = rng.choice([0.3, 0.7, 1.0, 1.5, 2.5])

    def junction(e):  # on the tool and on the plate's top (a hole: inside the plate)
        faces = s.ancestorsOfType(e, Part.Face)
        if len(faces) != 2 or e.Degenerated or any(e.isSeam(f) for f in faces) or \
                tool.distToShape(e)[0] > 1e-6:
            return False
        return abs(e.BoundBox.ZMax) < 1e-6 if kind != "hole" else e.BoundBox.ZMin > -6 + 1e-6
    return kind, s, names(s, junction), radius


def random_block(rng):
    """(kind, solid, names of a random set of its edges, radius): a box, an L block, a
    regular prism, a step or a box with a round boss, of random size, with 1 to all of
    its edges selected, at R = 3 to 20 % of its smallest extent."""
    a, b, c = rng.uniform(5, 20), rng.uniform(5, 20), rng.uniform(5, 20)
    kind = rng.choice(["box", "L block", "prism", "step", "box with a boss"])
    if kind == "box":
        s = Part.makeBox(a, b, c)
    elif kind == "L block":
        s = Part.makeBox(a, b, c).fuse(Part.makeBox(0.4 * a, b, 2 * c)).removeSplitter()
    elif kind == "prism":
        n = rng.choice([3, 5, 6, 8])
        pts = [V(a * math.cos(2 * math.pi * k / n), a * math.sin(2 * math.pi * k / n), 0)
               for k in range(n + 1)]
        s = Part.Face(Part.makePolygon(pts)).extrude(V(0, 0, c))
    elif kind == "step":
        s = Part.makeBox(a, b, c).fuse(Part.makeBox(0.5 * a, b, 0.5 * c, V(a, 0, 0)))
        s = s.removeSplitter()
    else:
        s = Part.makeBox(a, b, c).fuse(Part.makeCylinder(0.25 * min(a, b), c,
                                                         V(0.5 * a, 0.5 * b, c)))
        s = s.removeSplitter()
    edges = names(s, lambda e: not e.Degenerated
                  and not any(e.isSeam(f) for f in s.ancestorsOfType(e, Part.Face)))
    chosen = rng.sample(edges, rng.randint(1, len(edges)))
    box = s.BoundBox
    r = round(rng.uniform(0.03, 0.2) * min(box.XLength, box.YLength, box.ZLength), 3)
    return kind, s, sorted(chosen, key=lambda e: int(e[4:])), r


def random_machined(rng):
    """(kind, solid, names of a random set of its edges, radius): a block machined by 1 to
    3 features (a through or blind hole, a pocket, a slot, a boss, a side hole or a
    chamfered top edge) of random size and place, with 1 to 6 of its edges selected, at
    R = 3 to 15 % of the smallest feature."""
    a, b, c = rng.uniform(20, 40), rng.uniform(20, 40), rng.uniform(6, 15)
    s = Part.makeBox(a, b, c)
    kinds, sizes = [], [c]
    for _ in range(rng.randint(1, 3)):
        kind = rng.choice(["through hole", "blind hole", "pocket", "slot", "boss",
                           "side hole", "chamfer"])
        r = rng.uniform(1.5, 0.2 * min(a, b))
        x, y = rng.uniform(r + 2, a - r - 2), rng.uniform(r + 2, b - r - 2)
        if kind == "through hole":
            s = s.cut(Part.makeCylinder(r, c + 2, V(x, y, -1)))
        elif kind == "blind hole":
            depth = rng.uniform(0.3, 0.7) * c
            s = s.cut(Part.makeCylinder(r, depth + 1, V(x, y, c - depth)))
            sizes.append(depth)
        elif kind == "pocket":
            depth = rng.uniform(0.3, 0.7) * c
            s = s.cut(Part.makeBox(2 * r, 1.5 * r, depth + 1, V(x - r, y - 0.75 * r, c - depth)))
            sizes.append(depth)
        elif kind == "slot":
            w, length = 0.5 * r, rng.uniform(0.5, 1.5) * r
            depth = rng.uniform(0.3, 0.7) * c
            tool = Part.makeBox(length, 2 * w, depth + 1, V(x - 0.5 * length, y - w, c - depth))
            for end in (-0.5, 0.5):
                tool = tool.fuse(Part.makeCylinder(w, depth + 1,
                                                   V(x + end * length, y, c - depth)))
            s = s.cut(tool)
            sizes += [depth, w]
        elif kind == "boss":
            height = rng.uniform(0.3, 1.0) * c
            s = s.fuse(Part.makeCylinder(r, height, V(x, y, c)))
            sizes.append(height)
        elif kind == "side hole":
            r = min(r, 0.3 * c)
            s = s.cut(Part.makeCylinder(r, a + 2, V(-1, y, 0.5 * c), V(1, 0, 0)))
        else:
            tops = [e for e in s.Edges if e.BoundBox.ZMin > c - 1e-6 and
                    isinstance(e.Curve, Part.Line)]
            if not tops:
                continue
            try:
                s = s.makeChamfer(rng.uniform(0.5, 2.0), [rng.choice(tops)])
            except Part.OCCError:
                continue
        s = s.removeSplitter()
        kinds.append(kind)
        sizes.append(r)
    edges = names(s, lambda e: not e.Degenerated
                  and not any(e.isSeam(f) for f in s.ancestorsOfType(e, Part.Face)))
    chosen = rng.sample(edges, rng.randint(1, min(6, len(edges))))
    r = round(rng.uniform(0.03, 0.15) * min(sizes), 3)
    return " + ".join(kinds) or "block", s, sorted(chosen, key=lambda e: int(e[4:])), r


def random_shaft(rng):
    """(kind, solid, names of a random set of its circular edges, radius): a turned part,
    its profile revolved about z: 2 to 5 steps of random radius and length, each
    shoulder square or tapered (a cone), some steps grooved (a square groove), and maybe
    bored through, with 1 to 6 of its edges selected, at R = 3 to 15 % of its smallest
    feature (step, shoulder, groove or wall)."""
    steps = rng.randint(2, 5)
    bore = rng.uniform(1.0, 2.5) if rng.random() < 0.3 else 0.0
    radii = [rng.uniform(bore + 3, 15) for _ in range(steps)]
    for k in range(1, steps):  # shoulders at least 1 high
        if abs(radii[k] - radii[k - 1]) < 1:
            radii[k] = radii[k - 1] + (1.5 if radii[k - 1] < 12 else -1.5)
    kinds, sizes, z = ["%d steps" % steps], [min(radii) - bore], 0.0
    pts = [(bore, 0.0), (radii[0], 0.0)]
    for k, r in enumerate(radii):
        length = rng.uniform(4, 15)
        sizes.append(length)
        if rng.random() < 0.3 and length > 6:  # a square groove in the middle of the step
            w, d = rng.uniform(1, 0.4 * length), rng.uniform(0.5, 0.3 * (r - bore))
            z0 = z + 0.5 * (length - w)
            pts += [(r, z0), (r - d, z0), (r - d, z0 + w), (r, z0 + w)]
            kinds.append("groove")
            sizes += [w, d]
        z += length
        pts.append((r, z))
        if k + 1 < steps:
            nxt = radii[k + 1]
            if rng.random() < 0.3:  # a tapered shoulder
                taper = rng.uniform(1, 4)
                pts.append((nxt, z + taper))
                z += taper
                kinds.append("taper")
            else:
                pts.append((nxt, z))
            sizes.append(abs(nxt - r))
    pts.append((bore, z))
    if bore:
        kinds.append("bore")
    wire = Part.makePolygon([V(x, 0, y) for x, y in pts] + [V(pts[0][0], 0, pts[0][1])])
    s = Part.Face(wire).revolve(V(0, 0, 0), V(0, 0, 1), 360).removeSplitter()
    edges = names(s, lambda e: not e.Degenerated and isinstance(e.Curve, Part.Circle)
                  and not any(e.isSeam(f) for f in s.ancestorsOfType(e, Part.Face)))
    chosen = rng.sample(edges, rng.randint(1, min(6, len(edges))))
    r = round(rng.uniform(0.03, 0.15) * min(sizes), 3)
    return " + ".join(kinds), s, sorted(chosen, key=lambda e: int(e[4:])), r


def random_plate(rng):
    """(kind, solid, names of a random set of its edges, radius): a plate as sketched and
    padded: an L, T, U or rectangular outline, some of its corners rounded (cylinders
    tangent to the sides, so that the outline's edges form tangent chains), maybe with a
    hole and a pocket with rounded corners, with 1 to 6 of its edges selected, at R = 5 to
    30 % of the plate's thickness."""
    a, b, c = rng.uniform(20, 40), rng.uniform(20, 40), rng.uniform(3, 10)
    kind = rng.choice(["rectangle", "L", "T", "U"])
    w = rng.uniform(0.3, 0.45)  # the arms' width, as a share of the outline's
    outline = {"rectangle": [(0, 0), (a, 0), (a, b), (0, b)],
               "L": [(0, 0), (a, 0), (a, w * b), (w * a, w * b), (w * a, b), (0, b)],
               "T": [(0, 0), (a, 0), (a, w * b), ((0.5 + w / 2) * a, w * b),
                     ((0.5 + w / 2) * a, b), ((0.5 - w / 2) * a, b),
                     ((0.5 - w / 2) * a, w * b), (0, w * b)],
               "U": [(0, 0), (a, 0), (a, b), ((1 - w) * a, b), ((1 - w) * a, w * b),
                     (w * a, w * b), (w * a, b), (0, b)]}[kind]
    s = Part.Face(Part.makePolygon([V(x, y, 0) for x, y in outline + outline[:1]]))
    s = s.extrude(V(0, 0, c))
    kinds, arm = [kind + " plate"], min(a, b) * (w if kind != "rectangle" else 1)
    corners = [e for e in s.Edges if e.BoundBox.ZLength > 1e-9 and rng.random() < 0.6]
    rounding = rng.uniform(0.1, 0.3) * arm
    if corners:
        try:
            s = s.makeFillet(rounding, corners)
            kinds.append("%d corners rounded" % len(corners))
        except Part.OCCError:  # as a sketch's corner too tight for the rounding
            pass
    if rng.random() < 0.5:  # a hole through the plate's first arm
        r = rng.uniform(1, 0.2 * arm)
        s = s.cut(Part.makeCylinder(r, c + 2, V(0.5 * arm, 0.5 * arm, -1)))
        kinds.append("hole")
    if rng.random() < 0.5:  # a pocket with rounded corners near the outline's (a, 0) corner
        pw, ph, depth = rng.uniform(0.2, 0.4) * arm, rng.uniform(0.2, 0.4) * arm, \
            rng.uniform(0.3, 0.7) * c
        tool = Part.makeBox(pw, ph, depth + 1, V(a - 0.5 * arm - pw / 2,
                                                 0.5 * arm - ph / 2, c - depth))
        tool = tool.makeFillet(rng.uniform(0.1, 0.45) * min(pw, ph),
                               [e for e in tool.Edges if e.BoundBox.ZLength > 1e-9])
        s = s.cut(tool)
        kinds.append("pocket")
    s = s.removeSplitter().Solids[0]
    edges = names(s, lambda e: not e.Degenerated
                  and not any(e.isSeam(f) for f in s.ancestorsOfType(e, Part.Face)))
    chosen = rng.sample(edges, rng.randint(1, min(6, len(edges))))
    r = round(rng.uniform(0.05, 0.3) * c, 3)
    return " + ".join(kinds), s, sorted(chosen, key=lambda e: int(e[4:])), r


def turned(make):
    """make, its part then turned about a random axis by a random angle and moved up to
    1000 away (its Placement), as a part placed in an assembly is."""
    def made(rng):
        kind, s, edges, r = make(rng)
        axis = V(rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1))
        s = s.copy()
        s.Placement = FreeCAD.Placement(V(*(rng.uniform(-1000, 1000) for _ in range(3))),
                                        FreeCAD.Rotation(axis, rng.uniform(0, 360)))
        return kind + " (turned)", s, edges, r
    return made


def splines(make):
    """make, its part then made B-splines (toNurbs: every face a B-spline surface, as
    some STEP exports are), its edges found again by their midpoints."""
    def made(rng):
        kind, s, edges, r = make(rng)
        ns = s.toNurbs()
        found = []
        for name in edges:
            mid = Part.Vertex(midpoint(s.getElement(name)))
            found.append("Edge%d" % (1 + min(range(len(ns.Edges)),
                                             key=lambda k: ns.Edges[k].distToShape(mid)[0])))
        return kind + " (B-splines)", ns, found, r
    return made


def random_survey(count, seed, make=random_part, read_back=False):
    """Fillet `count` random parts (make(rng), seeded): lists those where a trimline is
    not G2, a fillet is kept as OCCT's, the solid is not valid or does not pass the
    BOP check, and the errors (as where OCCT's own fillet fails), then the totals. With
    read_back, each result is also read back from a STEP file and a FreeCAD document
    (read_back_faults), and the outcome says what the check finds beyond the result's
    own findings."""
    import random
    rng = random.Random(seed)
    totals = {}
    for k in range(count):
        kind, s, edges, r = make(rng)
        if len(s.Solids) != 1 or not edges:
            outcome = "skipped (no single solid, or no edge)"
        else:
            outcome = tried("%d %s" % (k, kind), s, edges, r, read_back)
        totals[outcome] = totals.get(outcome, 0) + 1
    print_totals(totals)


GOOD = "G2 at every trimline, nothing kept as OCCT's, valid, passes the BOP check"


def tried(what, s, edges, r, read_back=False):
    """The outcome of C2 Fillet of `edges` of s at radius r: GOOD, "other" or "error";
    prints a line saying what, unless GOOD within 10 s. With read_back, the outcome also
    names each form (STEP, FCStd) read back from which the solid has findings it has not
    (read_back_faults), and whether OCCT's own fillet of the same edges has them in the
    same forms; a line says what they are."""
    try:
        t0 = time.perf_counter()
        solid, rep = C2Blend.fillet_report(s, edges, r)
        seconds = time.perf_counter() - t0
    except C2Blend.Error as ex:
        print("%s, %d edge(s), R=%g: error: %s" % (what, len(edges), r, ex))
        return "error"
    kept = [x for x in rep["kept_occt_faces"] if not x["where"].startswith("corner patch")]
    ok = all(t["verdict"] == "G2" for t in rep["trimlines"]) and not kept and \
        solid.isValid() and rep["solid_check"] == "passes BRepCheck and the BOP check"
    corners = rep["corner_patches"]
    seam = " (%d corners filled, seams within %.1e rad)" % (
        len(corners), max(c["g1"] for c in corners)) if corners else ""
    if not ok or seconds > 10:
        print("%s, %d edge(s), R=%g: %s%s, %s, %.1f s; %s"
              % (what, len(edges), r, rep["verdict"], seam, rep["solid_check"], seconds,
                 "; ".join(sorted({x["reason"] for x in kept}))))
    outcome = GOOD if ok else "other"
    if read_back:
        faults = read_back_faults(solid)
        theirs = read_back_faults(s.makeFillet(r, [s.getElement(e) if isinstance(e, str)
                                                   else e for e in edges])) if faults else []
        for form, found in faults:
            print("%s, %d edge(s), R=%g (%d corners filled, %d seams; the report's "
                  "exchange line: %d edges, OCCT's %d): read back from %s: %s; OCCT's own "
                  "fillet: %s"
                  % (what, len(edges), r, len(corners), sum(c["edges"] for c in corners),
                     rep["exchange"]["edges"], rep["exchange"]["occt_edges"], form, found,
                     dict(theirs).get(form, "no new findings")))
        outcome += "; read back: no new findings" if not faults else \
            "; read back from %s: new findings%s" % (
                " and ".join(form for form, _ in faults),
                ", as from OCCT's own fillet" if [f for f, _ in faults] == [f for f, _ in theirs]
                else ", not all from OCCT's own fillet")
    return outcome


def read_back_faults(solid):
    """[(form, findings)]: each form ("STEP", "FCStd") that `solid`, written to a STEP
    file (exportStep) or saved in a FreeCAD document and read back, fails the validity
    checks in: isValid(), or a kind of finding of the BOP check (bopcheck.problems) that
    the solid itself has not, with the findings. OCCT's check lists a curve off its face
    once per (edge, face) pair, so an edge off both its faces counts twice: the findings
    end with how many distinct edges of the shape read back have curves further apart
    (recut.pcurve_gap, sampled) than their tolerance."""
    from c2bwb.geometry import bopcheck as bc
    from c2bwb.geometry import recut
    def checked(shape):  # the findings, or why the check did not finish
        try:
            return bc.problems(shape)
        except bc.Unfinished as ex:
            return "the check did not finish: %s" % ex
    def kinds(found):
        return {x.split(" (")[0] for x in found.split("; ")} if found else set()
    own = kinds(checked(solid))
    out = []
    with tempfile.TemporaryDirectory() as folder:
        forms = [(form, shapes.read_back(solid, form, pathlib.Path(folder)))
                 for form in ("STEP", "FCStd")]
    for form, shape in forms:
        found = checked(shape)
        if not shape.isValid() or kinds(found) - own:
            apart = sum(recut.pcurve_gap(e) > e.Tolerance for e in shape.Edges
                        if not e.Degenerated)
            out.append((form, ("not valid; " if not shape.isValid() else "") + str(found)
                        + " [%d distinct edge(s) whose curves lie further apart than their "
                        "tolerance]" % apart))
    return out


def print_totals(totals):
    """Each outcome of `totals` ({outcome: count}) with its count, a line each."""
    for outcome, n in sorted(totals.items()):
        print("%4d %s" % (n, outcome))


def plain_parts():
    """(name, solid) of nine plain parts: pockets, a step, a bracket, a boss on a wall,
    slots, crossing ribs."""
    out = [(name, first(make())) for name, make in (
        ("open pocket", shapes.open_pocket), ("pocket block", shapes.pocket_block),
        ("step", shapes.step), ("L bracket", shapes.l_bracket),
        ("slot plate", shapes.slot_plate), ("boss into wall", shapes.boss_into_wall))]
    return out + [
        ("through slot", Part.makeBox(30, 20, 8).cut(Part.makeBox(6, 30, 5, V(12, -5, 3)))),
        ("blind slot", Part.makeBox(30, 20, 8).cut(Part.makeBox(6, 15, 5, V(12, -5, 3)))),
        ("crossing ribs", Part.makeBox(30, 30, 3).fuse(Part.makeBox(30, 3, 8, V(0, 13, 0)))
         .fuse(Part.makeBox(3, 30, 8, V(13, 0, 0))).removeSplitter())]


def sweep(radii, pairs):
    """C2 Fillet of every edge alone of the plain parts (plain_parts) at each of
    `radii`, or with pairs, of every two edges that meet at a vertex: lists the runs
    that are not GOOD or take over 10 s, then the totals."""
    totals = {}
    for name, s in plain_parts():
        names = ["Edge%d" % (i + 1) for i in range(len(s.Edges))]
        if pairs:
            at = [[i for i, e in enumerate(s.Edges) if any(v.isSame(w) for w in e.Vertexes)]
                  for v in s.Vertexes]
            selections = sorted({(i, j) for edges in at for i in edges for j in edges if i < j})
        else:
            selections = [(i,) for i in range(len(s.Edges))]
        for sel in selections:
            for r in radii:
                outcome = tried("%s %s" % (name, "+".join(names[i] for i in sel)), s,
                                [names[i] for i in sel], r)
                totals[outcome] = totals.get(outcome, 0) + 1
    print_totals(totals)


def median_ms(f, n=5):
    ts = []
    for _ in range(n):
        t0 = time.perf_counter()
        f()
        ts.append(time.perf_counter() - t0)
    return 1e3 * statistics.median(ts)


def validation():
    s, edge = shapes.shaft_on_plate()
    solid, _ = C2Blend.fillet_report(s, [edge], 2.0)
    blend = next(f for f in solid.Faces if isinstance(f.Surface, Part.BSplineSurface))
    nbrs = [f for f in solid.Faces if not f.isSame(blend)
            and any(e.isSame(x) for e in f.Edges for x in blend.Edges)]
    local = Part.Compound([blend] + nbrs)
    print("validity checks on the filleted shaft on plate (median of 5, ms):")
    print("  isValid()                       %8.2f" % median_ms(solid.isValid))
    print("  check(False)  (BRepCheck)       %8.2f" % median_ms(lambda: solid.check(False)))
    print("  check(True)   (+ BOP analysis)  %8.2f" % median_ms(lambda: solid.check(True)))
    print("  check(True) on the blend and its %d neighbours only %8.2f"
          % (len(nbrs), median_ms(lambda: local.check(True))))


def bop_times():
    """OCCT's BOP check (check(True)) in this process on the pentagonal prism filleted
    (shapes.pentagonal_prism) and on the neighbourhood of each of its plate fillings
    (bopcheck._neighbourhood): processor time (user and system, all threads: OCCT
    checks on several) and time on the clock."""
    import resource
    from c2bwb.geometry import bopcheck

    def timed(shape):
        r0, t0 = resource.getrusage(resource.RUSAGE_SELF), time.perf_counter()
        try:
            shape.check(True)
        except Exception:  # noqa: BLE001 - OCCT's findings; only the time matters here
            pass
        r1 = resource.getrusage(resource.RUSAGE_SELF)
        return (r1.ru_utime + r1.ru_stime - r0.ru_utime - r0.ru_stime,
                time.perf_counter() - t0)

    s, edges, r = shapes.pentagonal_prism()
    solid, rep = C2Blend.fillet_report(s, edges, r)
    print("OCCT's BOP check on the pentagonal prism, %d edges filleted at R = %g "
          "(processor s, clock s):" % (len(edges), r))
    print("  the whole solid: %.1f, %.1f" % timed(solid))
    for c in rep["corner_patches"]:
        near = bopcheck._neighbourhood(solid, solid.getElement(c["face"]))
        print("  the neighbourhood of the plate filling at the %s: %.1f, %.1f"
              % (c["where"], *timed(near)))
    print("limits (processor s): whole %g, neighbourhood %g"
          % (bopcheck.LIMIT, bopcheck.NEAR_LIMIT))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--validation", action="store_true", help="also time OCCT's validity checks")
    ap.add_argument("--only", default="", metavar="TEXT",
                    help="only the typical parts whose name contains TEXT")
    ap.add_argument("--all-edges", action="store_true",
                    help="fillet every edge of some parts instead")
    ap.add_argument("--random", type=int, metavar="N",
                    help="instead, fillet the junctions of N random parts")
    ap.add_argument("--random-edges", type=int, metavar="N",
                    help="instead, fillet random sets of edges of N random blocks")
    ap.add_argument("--random-machined", type=int, metavar="N",
                    help="instead, fillet random sets of edges of N random machined blocks")
    ap.add_argument("--random-shafts", type=int, metavar="N",
                    help="instead, fillet random sets of circular edges of N random turned "
                    "parts")
    ap.add_argument("--random-plates", type=int, metavar="N",
                    help="instead, fillet random sets of edges of N random padded plates")
    ap.add_argument("--seed", type=int, default=2, help="of the random parts (2)")
    ap.add_argument("--turned", action="store_true",
                    help="each random part turned and moved to a random placement")
    ap.add_argument("--splines", action="store_true",
                    help="each random part made B-splines (toNurbs) first")
    ap.add_argument("--read-back", action="store_true",
                    help="each random part's result also written to STEP and to a FreeCAD "
                    "document, read back and checked again")
    ap.add_argument("--sweep", metavar="R1,R2,...",
                    help="instead, fillet every edge alone of nine plain parts at each radius")
    ap.add_argument("--pairs", action="store_true",
                    help="with --sweep, every two edges that meet at a vertex instead")
    ap.add_argument("--bop-times", action="store_true",
                    help="instead, time OCCT's BOP check on a filleted pentagonal prism")
    a = ap.parse_args()
    def place(make):
        make = splines(make) if a.splines else make
        return turned(make) if a.turned else make
    for count, make in ((a.random, random_part), (a.random_edges, random_block),
                        (a.random_machined, random_machined), (a.random_shafts, random_shaft),
                        (a.random_plates, random_plate)):
        if count:
            random_survey(count, a.seed, place(make), a.read_back)
            return
    if a.sweep:
        sweep([float(r) for r in a.sweep.split(",")], a.pairs)
        return
    if a.bop_times:
        bop_times()
        return
    if a.all_edges:
        all_edges()
        return
    survey(a.only)
    if a.validation:
        validation()


if __name__ == "__main__":
    main()
