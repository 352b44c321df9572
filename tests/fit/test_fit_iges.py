#!/usr/bin/python3
"""End to end through an independent reader: `c2blend fit --iges`, read back with
OpenCASCADE (FreeCAD's Part.read), then compare with the analytic blend (`c2blend eval`):
 - positions at 400 random (u, v) within the deviation the fit reported;
 - S, S_u, S_uu at u = 0 and 1 (OCCT's getDN) against the blend's own derivatives,
   within the end-row residuals the fit reported.
Usage: test_fit_iges.py C2BLEND EXAMPLES_DIR"""
import json, math, os, random, subprocess, sys, tempfile

tmp = tempfile.mkdtemp(prefix="c2b_fit_iges_")
os.environ["HOME"] = tmp  # FreeCAD writes its user configuration under HOME
sys.path.append("/usr/lib/freecad-python3/lib")
import FreeCAD  # noqa: E402
import Part  # noqa: E402

c2b, examples = sys.argv[1], sys.argv[2]
failed = 0


def check(what, ok, detail):
    global failed
    print(("ok   " if ok else "FAIL ") + what + ": " + detail)
    failed += not ok


def eval_points(spec, pts, derivs=False):
    text = "\n".join("%.17g %.17g" % p for p in pts) + "\n"
    args = [c2b, "eval", spec, "--points", "-"] + (["--derivs"] if derivs else [])
    out = subprocess.run(args, input=text, capture_output=True, text=True, check=True).stdout
    rows = [list(map(float, l.split(","))) for l in out.strip().split("\n")[1:]]
    return rows


for name in ["thesis_eq127_129", "nurbs_cubic_quartic", "thesis_eq130_131"]:
    spec = os.path.join(examples, name + ".json")
    out_json, out_igs = os.path.join(tmp, name + ".json"), os.path.join(tmp, name + ".igs")
    r = subprocess.run([c2b, "fit", spec, "-o", out_json, "--iges", out_igs],
                       capture_output=True, text=True)
    check(name + ": fit with --iges", r.returncode == 0, r.stderr.strip())
    if r.returncode:
        continue
    fit = json.load(open(out_json))
    shape = Part.read(out_igs)
    faces = shape.Faces
    check(name + ": IGES read back as one face", len(faces) == 1, "%d faces" % len(faces))
    surf = faces[0].Surface
    if not isinstance(surf, Part.BSplineSurface):
        surf = surf.toBSpline()
    u0, u1, v0, v1 = surf.bounds()
    vr = json.load(open(spec)).get("v_range", [0, 1])
    check(name + ": parameter ranges kept", abs(u0) < 1e-12 and abs(u1 - 1) < 1e-12 and
          abs(v0 - vr[0]) < 1e-12 and abs(v1 - vr[1]) < 1e-12, str((u0, u1, v0, v1)))
    rnd = random.Random(7)
    pts = [(rnd.random(), vr[0] + (vr[1] - vr[0]) * rnd.random()) for _ in range(400)]
    ana = eval_points(spec, pts)
    worst = 0.0
    for (u, v), row in zip(pts, ana):
        p = surf.value(u, v)
        worst = max(worst, ((p.x - row[2]) ** 2 + (p.y - row[3]) ** 2 + (p.z - row[4]) ** 2) ** 0.5)
    # The reported deviation is a sampled maximum: other points may exceed it a little,
    # the tolerance never.
    check(name + ": OCCT points vs analytic blend within the tolerance and 1.25x the reported deviation",
          worst <= fit["tolerance"] and worst <= 1.25 * fit["deviation"] + 1e-12,
          "max %.3g, reported %.3g, tolerance %.3g" % (worst, fit["deviation"], fit["tolerance"]))
    # End rows: S, S_u, S_uu at u = 0, 1 by OCCT vs the blend's derivatives.
    vs = [vr[0] + (vr[1] - vr[0]) * (i + 0.29) / 61 for i in range(61)]
    for side in (0, 1):
        rows = eval_points(spec, [(side, v) for v in vs], derivs=True)
        for k, (col, key) in enumerate([(2, "S"), (5, "S_u"), (11, "S_uu")]):
            worst = 0.0
            for v, row in zip(vs, rows):
                d = surf.value(side, v) if k == 0 else surf.getDN(side, v, k, 0)
                worst = max(worst, ((d.x - row[col]) ** 2 + (d.y - row[col + 1]) ** 2 +
                                    (d.z - row[col + 2]) ** 2) ** 0.5)
            rep = fit["residuals"]["u%d" % side][key]
            check("%s: u=%d %s by OCCT within 1.25x the reported (sampled) end-row residual" % (name, side, key),
                  worst <= rep * 1.25 + 1e-12 * fit["bbox_diagonal"],
                  "max %.3g, reported %.3g (%.2g of the bbox diagonal)" % (worst, rep, worst / fit["bbox_diagonal"]))
        # Normals along the trimline: OCCT's (from the IGES surface) vs the blend's
        # (S_u x S_v), within the reported tilt, which the fit holds under 0.3 tol_rel.
        worst = 0.0
        for v, row in zip(vs, rows):
            su, sv = FreeCAD.Vector(*row[5:8]), FreeCAD.Vector(*row[8:11])
            nb = su.cross(sv)
            nf = surf.getDN(side, v, 1, 0).cross(surf.getDN(side, v, 0, 1))
            # atan2 of |cross| and dot: Vector.getAngle is an arc cosine, which cannot
            # resolve angles below about 1.5e-8 rad
            worst = max(worst, math.atan2(nb.cross(nf).Length, nb.dot(nf)))
        rep = fit["tilt"]["u%d" % side]
        check("%s: u=%d normals by OCCT within 1.25x the reported tilt and 0.3 tol_rel" % (name, side),
              worst <= 1.25 * rep + 1e-12 and worst <= 0.3 * fit["tolerance_rel"] + 1e-11,
              "max %.3g rad, reported %.3g" % (worst, rep))

print("%d failed" % failed)
sys.exit(1 if failed else 0)
