#!/usr/bin/python3
"""Blend faces between random pairs of primaries: the G2 blend from the upper rim of
one (a cylinder, cone, sphere or torus zone, or a B-spline surface of revolution; with
a part sweep, also a plane strip) to the lower rim of another above it, tilted and
shifted at random, the whole at a random scale (1e-3, 1 or 100) and placement, some
pairs made B-splines (toNurbs, as a STEP import may give them). For each: the
continuity verdict and the face's validity, and for closed rims the solid of both
primaries, the blend and the caps (blend_solid), valid. Pairs that are not G2 and
valid, and errors, get a line each; the totals follow.

usage: C2B_MODULE_DIR=build/plugin/ext /usr/bin/python3 tools/blend_survey.py
       [--random N] [--seed S]
"""
import argparse
import math
import os
import random
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.append("/usr/lib/freecad-python3/lib")
sys.path.insert(0, os.environ.get("C2B_MODULE_DIR", os.path.join(HERE, "..", "build", "plugin", "ext")))
sys.path.insert(0, os.path.join(HERE, "..", "plugin", "C2Blend"))
os.environ.setdefault("HOME", tempfile.mkdtemp())

import FreeCAD  # noqa: E402
import Part  # noqa: E402

import C2Blend  # noqa: E402
from c2bwb.geometry.rollingball import midpoint  # noqa: E402

V = FreeCAD.Vector
KINDS = ("cylinder", "cone", "sphere zone", "torus zone", "B-spline revolution")
GOOD = "G2, valid (and the solid valid)"


def primary(rng, lower, sweep, k):
    """(kind, face) of a random primary of size about k, its axis on z from the
    origin; `lower`: its rim to blend is its top (else its bottom)."""
    kind = rng.choice(KINDS + (("plane strip",) if sweep < 360 else ()))
    r, h = k * rng.uniform(0.5, 3.0), k * rng.uniform(1.0, 4.0)
    axis = V(0, 0, 1)
    if kind == "cylinder":
        s = Part.makeCylinder(r, h, V(), axis, sweep)
    elif kind == "cone":
        s = Part.makeCone(r, r * rng.uniform(0.3, 1.7), h, V(), axis, sweep)
    elif kind == "sphere zone":
        a = rng.uniform(-60.0, 20.0)  # the latitude of the rim
        s = Part.makeSphere(r, V(), axis, -90, a, sweep) if lower else \
            Part.makeSphere(r, V(), axis, a, 90, sweep)
    elif kind == "torus zone":
        s = Part.makeTorus(r + k, k * rng.uniform(0.3, 0.9), V(), axis,
                           -90 if lower else 0, 0 if lower else 90, sweep)
    elif kind == "plane strip":
        return kind, Part.makeBox(2 * r, 0.5 * k, h, V(-r, r, 0)).Faces[2]  # y = r
    else:
        c = Part.BSplineCurve()
        c.interpolate([V(r * (1 + 0.2 * rng.uniform(-1, 1)), 0, h * i / 3) for i in range(4)])
        s = c.toShape().revolve(V(), axis, sweep)
    return kind, max(s.Faces, key=lambda f: f.Area)


def rim(face, top):
    """The face's highest (top) or lowest edge lying in a plane z = constant."""
    flat = [e for e in face.Edges if not e.Degenerated
            and e.BoundBox.ZLength < 1e-9 * face.BoundBox.DiagonalLength]
    return (max if top else min)(flat, key=lambda e: e.BoundBox.ZMin)


def pair(rng):
    """(description, face1, edge1, face2, edge2, closed) of a random pair."""
    sweep = rng.choice((360, 360, 180, 120))
    k = rng.choice((1.0, 1.0, 1e-3, 100.0))
    kind1, f1 = primary(rng, True, sweep, k)
    kind2, f2 = primary(rng, False, sweep, k)
    gap, tilt = k * rng.uniform(0.5, 4.0), rng.choice((0.0, 0.0, rng.uniform(-0.6, 0.6)))
    shift = rng.choice((0.0, k * rng.uniform(-0.5, 0.5)))
    nurbs = rng.random() < 0.3
    up = FreeCAD.Placement(V(shift, 0, f1.BoundBox.ZMax + gap),
                           FreeCAD.Rotation(V(1, 0, 0), math.degrees(tilt))).multiply(
        FreeCAD.Placement(V(0, 0, -f2.BoundBox.ZMin), FreeCAD.Rotation()))
    where = FreeCAD.Placement(V(*(k * rng.uniform(-50, 50) for _ in range(3))),
                              FreeCAD.Rotation(V(*(rng.uniform(-1, 1) for _ in range(3))),
                                               rng.uniform(0, 360)))
    faces = []
    for f, e, move in ((f1, rim(f1, True), where), (f2, rim(f2, False), where.multiply(up))):
        mid = move.multVec(midpoint(e))
        f = f.toNurbs().Faces[0] if nurbs else f.copy()
        f.Placement = move.multiply(f.Placement)
        faces += [f, min(f.Edges, key=lambda x: x.distToShape(Part.Vertex(mid))[0])]
    what = "%s -> %s, sweep %d, scale %g, gap %.3g, tilt %.2f rad, shift %.3g%s" % (
        kind1, kind2, sweep, k, gap, tilt, shift, ", B-splines" if nurbs else "")
    return (what, *faces, sweep == 360)


def survey(count, seed):
    """Blend `count` random pairs (seeded); print the failures and the totals."""
    rng = random.Random(seed)
    totals = {}
    for n in range(count):
        what, f1, e1, f2, e2, closed = pair(rng)
        t0 = time.perf_counter()
        try:
            face, rep = C2Blend.blend(f1, e1, f2, e2, report=True)
            valid = [face.isValid()]
            line = "%s, %s" % (rep["verdict"], "valid" if valid[0] else "NOT VALID")
            if closed:
                valid.append(C2Blend.blend_solid([f1, face, f2]).isValid())
                line += "; solid %s" % ("valid" if valid[1] else "NOT VALID")
            ok = rep["verdict"] == "G2" and all(valid)
            if not ok:
                line += "; worst trimline normal angle %.2g rad, curvature %.2g relative" % (
                    max(t["g1"] for t in rep["trimlines"]),
                    max(t["g2_rel"] for t in rep["trimlines"]))
            outcome = GOOD if ok else "other"
        except C2Blend.Error as ex:
            line, outcome = "error: %s" % ex, "error"
        if outcome != GOOD:
            print("%d %s: %s, %.2f s" % (n, what, line, time.perf_counter() - t0), flush=True)
        totals[outcome] = totals.get(outcome, 0) + 1
    for outcome, k in sorted(totals.items()):
        print("%4d %s" % (k, outcome))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--random", type=int, default=100, metavar="N", help="pairs (100)")
    ap.add_argument("--seed", type=int, default=1, help="of the pairs (1)")
    a = ap.parse_args()
    survey(a.random, a.seed)


if __name__ == "__main__":
    main()
