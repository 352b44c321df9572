#!/usr/bin/python3
"""Tests of c2blend-cgal-curvature (ctest label cgal).

usage: test_cgal.py TOOL WORKDIR GROUP [C2BLEND EXAMPLES]

GROUP is one of
  accuracy     sphere (both orientations), cylinder and torus against their exact
               curvatures; OFF / OBJ / binary PLY give the same estimates as ASCII PLY;
               interior / smooth / valid bookkeeping; a scale sweep 1e-6 .. 1e6
  convergence  measured order of the curvature error under uniform refinement, jet degree
               2 (required >= 1.8) and 4 (required >= 3.5), n-ring and k-nearest
  bad          malformed meshes and arguments exit with EXIT_FAILURE and the expected message
  c2blend      the C2Blend CLI's mesh of examples/thesis_eq130_131.json: per-region errors,
               and the convergence of the smooth regions under refinement

Every check prints what it compared. Exit status 0 when all checks pass.
"""

import json
import math
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import surfaces as sf  # noqa: E402

FAILURES = []


def check(ok, what):
    print("%s  %s" % ("ok  " if ok else "FAIL", what), flush=True)
    if not ok:
        FAILURES.append(what)


class Tool:
    def __init__(self, exe, work):
        self.exe, self.work = exe, work

    def path(self, name):
        return os.path.join(self.work, name)

    def run(self, mesh, *args):
        """Runs the tool with --summary and --csv; returns (summary dict, csv rows)."""
        summary, csv = self.path("summary.json"), self.path("out.csv")
        for p in (summary, csv):
            if os.path.exists(p):
                os.remove(p)
        r = subprocess.run([self.exe, mesh, "--summary", summary, "--csv", csv] + list(args),
                           capture_output=True, text=True)
        if r.returncode != 0:
            raise RuntimeError("%s %s failed (%d): %s" % (self.exe, " ".join(args), r.returncode, r.stderr))
        with open(summary) as f:
            s = json.load(f)
        rows = np.genfromtxt(csv, delimiter=",", names=True)
        return s, rows


def interior_max(summary, cls="interior", region="blend"):
    """Largest |error| of k1 and k2 over one class of one region (region 0 of the test meshes)."""
    r = summary["regions"][region][cls]
    return max(r["k1"]["max_abs"], r["k2"]["max_abs"]), max(r["k1"]["rms"], r["k2"]["rms"]), r["count"]


def order(hs, errs):
    """Least-squares slope of log(err) against log(h)."""
    return float(np.polyfit(np.log(hs), np.log(errs), 1)[0])


# ---------------------------------------------------------------------------------------

def sphere(n, flip=False, radius=1.0):
    """Band pi/4 <= theta <= 3pi/4 of a sphere, n + 1 rows and 4 n columns (square cells on
    the equator)."""
    return sf.grid_mesh(sf.SphereBand(radius), n + 1, 4 * n, flip)


def cylinder(n):
    """Radius 1, length 2: n + 1 rows, 3 n columns (cell aspect pi/3)."""
    return sf.grid_mesh(sf.Cylinder(), n + 1, 3 * n)


def torus(n):
    """R = 2, r = 1, uniform in (u, v): n x 2 n, cell aspect 1..3 (not isotropic)."""
    return sf.grid_mesh(sf.Torus(2.0, 1.0), n, 2 * n)


def torus_conformal(n):
    """R = sqrt(5), r = 1, rows uniform in the conformal coordinate: n x 2 n square cells."""
    return sf.grid_mesh(sf.Torus(math.sqrt(5.0), 1.0, conformal=True), n, 2 * n)


def group_accuracy(tool):
    n = 64
    ply = tool.path("sphere.ply")
    m = sphere(n)
    sf.write_ply(ply, m)
    s, rows = tool.run(ply, "--degree", "4", "--rings", "2")
    e, _, cnt = interior_max(s)
    check(e < 1e-5, "sphere R=1 outward normals, degree 4, 2-ring, n=%d: interior max |k - (-1)| = %.2e < 1e-5" % (n, e))
    check(np.all(np.abs(rows["k1_est"] + 1) < 0.05) and np.all(np.abs(rows["k2_est"] + 1) < 0.05),
          "sphere: every vertex, the border included, within 0.05 of -1 (max dev %.2e)"
          % np.max(np.abs(np.r_[rows["k1_est"], rows["k2_est"]] + 1)))
    check(np.all(rows["k1_est"] >= rows["k2_est"]), "sphere: k1 >= k2 at every vertex")
    expect = (n + 1 - 6) * 4 * n
    check(cnt == expect and s["interior_vertices"] == expect,
          "sphere: interior (no border point in the 2-ring) = %d vertices, expected %d" % (cnt, expect))
    a, _, acnt = interior_max(s, "all")
    check(acnt == len(m.xyz) and a >= e, "sphere: 'all' has %d vertices and max error %.2e >= interior %.2e"
          % (acnt, a, e))
    check(s["border_vertices"] == 2 * 4 * n, "sphere: %d border vertices, expected %d" % (s["border_vertices"], 8 * n))
    check(s["condition_number"]["max"] < 1e6, "sphere: condition number max %.3g reported" % s["condition_number"]["max"])
    base = rows

    s, rows = tool.run(ply, "--degree", "4", "--monge", "4", "--rings", "2")
    d = max(np.max(np.abs(rows["k1_est"] - base["k1_est"])), np.max(np.abs(rows["k2_est"] - base["k2_est"])))
    check(d == 0 and s["monge_degree"] == 4, "sphere: --monge 4 gives the same k1, k2 as --monge 2 (diff %.1e)" % d)

    s, rows = tool.run(ply, "--degree", "2", "--rings", "1")
    e, _, _ = interior_max(s)
    check(e < 1e-3, "sphere degree 2, 1-ring: interior max error %.2e < 1e-3" % e)
    for deg, rings, tol in (("3", "2", 5e-3), ("6", "3", 1e-5)):
        s, rows = tool.run(ply, "--degree", deg, "--rings", rings)
        e, _, _ = interior_max(s)
        check(e < tol, "sphere degree %s, %s-ring: interior max error %.2e < %g" % (deg, rings, e, tol))

    # The opposite orientation: normals and faces flipped, k1 = k2 = +1.
    plyf = tool.path("sphere_in.ply")
    sf.write_ply(plyf, sphere(n, flip=True))
    s, rows = tool.run(plyf, "--degree", "4", "--rings", "2")
    e, _, _ = interior_max(s)
    check(e < 1e-5 and np.all(rows["k1_est"] > 0.95), "sphere inward normals: k = +1, interior max error %.2e" % e)

    # OFF (no normals: area-weighted face normals; no analytic data), OBJ with and without
    # vn, binary PLY: the same points, so the same estimates.
    for name, write in (("sphere.off", sf.write_off), ("sphere_vn.obj", sf.write_obj),
                        ("sphere.obj", lambda p, mm: sf.write_obj(p, mm, normals=False)),
                        ("sphere_bin.ply", lambda p, mm: sf.write_ply(p, mm, binary=True)),
                        ("sphere_bin_be.ply", lambda p, mm: sf.write_ply(p, mm, binary=True, big_endian=True)),
                        ("sphere_xyz.ply", lambda p, mm: sf.write_ply(p, mm, analytic=False, normals=False))):
        path = tool.path(name)
        write(path, m)
        s2, rows2 = tool.run(path, "--degree", "4", "--rings", "2")
        d = max(np.max(np.abs(rows2["k1_est"] - base["k1_est"])), np.max(np.abs(rows2["k2_est"] - base["k2_est"])))
        check(d < 1e-12, "%s: estimates equal the ASCII PLY's (max diff %.1e), analytic=%s"
              % (name, d, s2["analytic"]))

    # Cylinder (k1 = 1, k2 = 0) and torus.
    for label, mesh, tol2, tol4 in (("cylinder n=64", cylinder(64), 1e-3, 1e-5),
                                    ("torus R=2 r=1 n=64", torus(64), 1e-2, 1e-3)):
        path = tool.path("acc.ply")
        sf.write_ply(path, mesh)
        for deg, rings, tol in (("2", "1", tol2), ("4", "2", tol4)):
            s, rows = tool.run(path, "--degree", deg, "--rings", rings)
            e, rms, _ = interior_max(s)
            check(e < tol, "%s, degree %s, %s-ring: interior max error %.2e (rms %.2e) < %g"
                  % (label, deg, rings, e, rms, tol))

    # valid == 0 vertices are excluded; regions: 'smooth' drops fits straddling a region
    # boundary.
    nvert = len(m.xyz)
    valid = np.ones(nvert, dtype=np.uint8)
    valid[::7] = 0
    region = np.zeros(nvert, dtype=np.uint8)
    region[(n // 2) * 4 * n:] = 1
    path = tool.path("regions.ply")
    sf.write_ply(path, m, region=region, valid=valid)
    s, rows = tool.run(path, "--degree", "4", "--rings", "2")
    excl = int(np.sum(valid == 0))
    check(s["invalid_vertices_excluded"] == excl, "valid == 0: %d vertices excluded, expected %d"
          % (s["invalid_vertices_excluded"], excl))
    check(np.all(np.isnan(rows["err1"][valid == 0])) and not np.any(np.isnan(rows["err1"][valid == 1])),
          "valid == 0: err1 is nan exactly there")
    cnt_all = s["regions"]["blend"]["all"]["count"] + s["regions"]["primary1"]["all"]["count"]
    check(cnt_all == nvert - excl, "regions: blend + primary1 counts %d = valid vertices %d" % (cnt_all, nvert - excl))
    rows_int = np.arange(nvert) // (4 * n)
    smooth = (rows_int >= 3) & (rows_int <= n - 3) & (np.abs(rows_int - (n // 2 - 0.5)) > 2)
    check(s["smooth_vertices"] == int(np.sum(smooth)), "regions: %d smooth vertices (2-ring in one region, off the "
          "border), expected %d" % (s["smooth_vertices"], int(np.sum(smooth))))

    # Scale sweep: relative errors do not depend on the model scale.
    ref = None
    for scale in (1e-6, 1.0, 1e6):
        path = tool.path("scaled.ply")
        sf.write_ply(path, sphere(32).scaled(scale))
        s, _ = tool.run(path, "--degree", "4", "--rings", "2")
        rel = interior_max(s)[0] * scale
        ref = rel if scale == 1.0 else ref
        check(rel < 1e-4, "scale %g: relative interior max error %.6e" % (scale, rel))
    for scale in (1e-6, 1e6):
        path = tool.path("scaled.ply")
        sf.write_ply(path, sphere(32).scaled(scale))
        s, _ = tool.run(path, "--degree", "4", "--rings", "2")
        rel = interior_max(s)[0] * scale
        check(abs(rel - ref) <= 1e-6 * ref, "scale %g: relative error %.10e equals scale 1's %.10e to 1e-6"
              % (scale, rel, ref))

    left = [f for f in os.listdir(tool.work) if ".tmp" in f]
    check(not left, "no temporary output files left behind (%s)" % left)


# ---------------------------------------------------------------------------------------

CONFIGS = {
    "d2-ring1": ("2", ["--rings", "1"], 1.8),
    "d4-ring2": ("4", ["--rings", "2"], 3.5),
    "d2-k24": ("2", ["--k", "24"], 1.8),
    "d4-k24": ("4", ["--k", "24"], 3.5),
}

# surface, generator, levels for degree 2, levels for degree 4, configurations asserted,
# configurations only reported
STUDIES = [
    ("sphere band", sphere, [8, 16, 32, 64], [8, 16, 32, 64], ["d2-ring1", "d4-ring2", "d2-k24", "d4-k24"], []),
    ("cylinder", cylinder, [8, 16, 32, 64], [8, 16, 32, 64], ["d2-ring1", "d4-ring2", "d2-k24", "d4-k24"], []),
    ("torus uniform", torus, [16, 32, 64, 128], [32, 64, 128], ["d2-ring1", "d4-ring2"], ["d2-k24", "d4-k24"]),
    ("torus conformal", torus_conformal, [16, 32, 64, 128], [32, 64, 128],
     ["d2-ring1", "d4-ring2", "d2-k24", "d4-k24"], []),
]


def group_convergence(tool):
    print("error = max over interior vertices of |k1 - k1_exact| and |k2 - k2_exact|; h = 1/n")
    table = []
    for label, gen, lev2, lev4, asserted, reported in STUDIES:
        results = {c: ([], [], []) for c in asserted + reported}
        for n in sorted(set(lev2) | set(lev4)):
            path = tool.path("conv.ply")
            sf.write_ply(path, gen(n))
            for c in results:
                deg, args, _ = CONFIGS[c]
                if n not in (lev2 if deg == "2" else lev4):
                    continue
                s, _ = tool.run(path, "--degree", deg, *args)
                e, rms, _ = interior_max(s)
                results[c][0].append(1.0 / n)
                results[c][1].append(e)
                results[c][2].append(rms)
        for c, (hs, es, rs) in results.items():
            deg, args, need = CONFIGS[c]
            p, prms = order(hs, es), order(hs, rs)
            levels = "n=" + ",".join(str(int(round(1 / h))) for h in hs)
            errs = " ".join("%.2e" % x for x in es)
            table.append((label, c, levels, errs, p, prms))
            if c in asserted:
                check(p >= need, "%-15s %-8s %-16s max err %s: order %.2f (rms %.2f) >= %.1f"
                      % (label, c, levels, errs, p, prms, need))
            else:
                print("info  %-15s %-8s %-16s max err %s: order %.2f (rms %.2f), not asserted: the k-nearest "
                      "set of an anisotropic grid is not symmetric" % (label, c, levels, errs, p, prms))


# ---------------------------------------------------------------------------------------

def write(path, text):
    with open(path, "w") as f:
        f.write(text)


def group_bad(tool):
    w = tool.path
    tri2 = "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 2\n"
    cases = [
        ("empty file", "empty.off", "", [], "empty.off: empty file"),
        ("OFF with no vertices", "novert.off", "OFF\n0 0 0\n", [], "empty mesh: 0 vertices"),
        ("PLY with no vertices", "novert.ply",
         "ply\nformat ascii 1.0\nelement vertex 0\nproperty double x\nproperty double y\nproperty double z\n"
         "element face 0\nproperty list uchar int vertex_indices\nend_header\n", [], "empty mesh"),
        ("vertices but no faces", "nofaces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", [], "no faces"),
        ("non-manifold edge", "nonmanifold.off",
         "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n", [],
         "non-manifold edge (0, 1) shared by 3 faces: 0 (line 8), 1 (line 9), 2 (line 10)"),
        ("non-manifold vertex", "pinch.off",
         "OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 0 3 4\n", [],
         "vertex 0: non-manifold vertex"),
        ("inconsistent orientation", "orient.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 2 3\n", [],
         "inconsistent orientation"),
        ("NaN coordinate", "nan.off", "OFF\n4 2 0\n0 0 0\n1 0 0\nnan 1 0\n1 1 0\n3 0 1 2\n3 1 3 2\n", [],
         "nan.off, line 5: vertex 2: non-finite vertex coordinate x = nan"),
        ("Inf coordinate (PLY)", "inf.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
         "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 inf 0\n0 1 0\n3 0 1 2\n",
         [], "inf.ply, line 11: vertex 1: non-finite vertex coordinate y = inf"),
        ("index out of range (OFF)", "range.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 7 2\n", [],
         "range.off, line 8: face 1: vertex index 7 out of range (the mesh has 4 vertices)"),
        ("negative index (PLY)", "range.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
         "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n",
         [], "range.ply, line 13: face 0: vertex index -1 out of range"),
        ("index out of range (OBJ)", "range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", [],
         "range.obj, line 4: face 0: vertex index 3 out of range"),
        ("face with 2 vertices", "short.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", [],
         "face 0: 2 vertices; a face needs at least 3"),
        ("truncated OFF", "trunc.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n", [], "unexpected end of file in vertex 2 of 4"),
        ("too few points for degree 4 (rings)", "small.off", tri2, ["--degree", "4"],
         "small.off, line 3: vertex 0: too few neighbours: 4 points within 4 rings (the vertex included; "
         "--rings 2 grown by up to 2); a degree-4 jet needs at least 15"),
        ("too few points for degree 2 (k nearest)", "small2.off", tri2, ["--degree", "2", "--k", "5"],
         "vertex 0: too few neighbours: 4 points"),
        ("--k too small for the degree", "small3.off", tri2, ["--degree", "4", "--k", "10"],
         "--k 10 gives 11 points with the query; a degree-4 jet needs at least 15"),
        ("monge above jet degree", "m.off", tri2, ["--degree", "2", "--monge", "4"], "--monge 4 exceeds the jet degree 2"),
        ("--k with --rings", "m2.off", tri2, ["--k", "24", "--rings", "2"], "--k and --rings exclude each other"),
        ("bad degree", "m3.off", tri2, ["--degree", "9"], "--degree needs an integer in [2, 6]"),
        ("unknown option", "m4.off", tri2, ["--frobnicate"], "unknown option --frobnicate"),
        ("bad extension", "mesh.stl", "solid\n", [], "the extension must be .off, .ply or .obj"),
        ("bad PLY header", "hdr.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty quad x\nend_header\n", [],
         "hdr.ply, line 4: bad property declaration"),
        ("NaN analytic curvature", "nank.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
         "property double k1\nproperty double k2\nelement face 1\nproperty list uchar int vertex_indices\n"
         "end_header\n0 0 0 0 0\n1 0 0 nan 0\n0 1 0 0 0\n3 0 1 2\n", [],
         "nank.ply, line 13: vertex 1: non-finite analytic curvature k1 = nan"),
        ("list length out of range in the vertex element (PLY)", "listlen.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
         "property list int double extra\nelement face 1\nproperty list uchar int vertex_indices\n"
         "end_header\n0 0 0 0\n1 0 0 -5e108\n0 1 0 0\n3 0 1 2\n", [],
         "listlen.ply, line 12: vertex 1: bad list length -5e+108"),
        ("non-integer list length in an element not used (PLY)", "skiplen.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
         "element face 1\nproperty list uchar int vertex_indices\nelement edge 1\n"
         "property list int int vertices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n2.5 0 1\n", [],
         "skiplen.ply, line 16: edge 0: bad list length 2.5"),
        ("PLY values missing", "few.ply",
         "ply\nformat ascii 1.0\nelement vertex 2\nproperty double x\nproperty double y\nproperty double z\n"
         "element face 0\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0\n", [],
         "few.ply, line 11: vertex 1: fewer values than the header declares"),
    ]
    for label, name, text, args, fragment in cases:
        path = w(name)
        write(path, text)
        csv = w("bad_out.csv")
        if os.path.exists(csv):
            os.remove(csv)
        r = subprocess.run([tool.exe, path, "--csv", csv] + args, capture_output=True, text=True)
        ok = r.returncode == 1 and fragment in r.stderr and r.stdout == "" and not os.path.exists(csv)
        check(ok, "%s: exit %d, stderr %r contains %r, stdout empty, no CSV" % (label, r.returncode,
                                                                             r.stderr.strip(), fragment))
    # Truncated binary PLY.
    m = sphere(4)
    path = w("trunc_bin.ply")
    sf.write_ply(path, m, binary=True)
    with open(path, "rb") as f:
        data = f.read()
    with open(path, "wb") as f:
        f.write(data[:-10])
    r = subprocess.run([tool.exe, path], capture_output=True, text=True)
    check(r.returncode == 1 and "binary data end early in face" in r.stderr,
          "truncated binary PLY: exit %d, %r" % (r.returncode, r.stderr.strip()))
    r = subprocess.run([tool.exe, w("does_not_exist.ply")], capture_output=True, text=True)
    check(r.returncode == 1 and "does_not_exist.ply: cannot open" in r.stderr,
          "missing file: exit %d, %r" % (r.returncode, r.stderr.strip()))


# ---------------------------------------------------------------------------------------

def group_c2blend(tool, c2blend, examples):
    spec = os.path.join(examples, "thesis_eq130_131.json")

    def mesh(n):
        out = tool.path("c2b_%d.ply" % n)
        subprocess.run([c2blend, "mesh", spec, "--n", str(n), "--with-primaries", "0.2", "-o", out], check=True,
                       capture_output=True)
        return out

    m64 = mesh(64)
    _, rows = tool.run(m64)
    for reg, k in ((1, 1.0), (2, 1.25)):
        sel = rows["region"] == reg
        check(np.allclose(rows["k1_exact"][sel], k, atol=1e-12) and np.allclose(rows["k2_exact"][sel], 0, atol=1e-12),
              "c2blend n=64: primary %d carries the exact cylinder curvature (%g, 0)" % (reg, k))
    print("c2blend mesh examples/thesis_eq130_131.json --n 64 --with-primaries 0.2")
    print("%-9s %-9s %-8s %6s %10s %10s %10s %10s" % ("config", "region", "class", "count", "k1 max", "k1 mean",
                                                       "k2 max", "k2 mean"))
    for deg, args in (("2", ["--rings", "2"]), ("2", ["--rings", "1"]), ("4", ["--rings", "2"])):
        s, _ = tool.run(m64, "--degree", deg, *args)
        cfg = "d%s-r%s" % (deg, args[1])
        for reg, r in s["regions"].items():
            for cls in ("all", "interior", "smooth"):
                c = r[cls]
                print("%-9s %-9s %-8s %6d %10.3e %10.3e %10.3e %10.3e" % (cfg, reg, cls, c["count"],
                      c["k1"]["max_abs"], c["k1"]["mean_abs"], c["k2"]["max_abs"], c["k2"]["mean_abs"]))
        if deg == "4":
            for reg in ("primary1", "primary2"):
                e = s["regions"][reg]["smooth"]
                check(e["k1"]["max_abs"] < 1e-4 and e["k2"]["max_abs"] < 1e-9,
                      "c2blend n=64 degree 4: %s (exact cylinder) smooth |k1 err| %.2e < 1e-4, |k2 err| %.2e < 1e-9"
                      % (reg, e["k1"]["max_abs"], e["k2"]["max_abs"]))
            e = s["regions"]["blend"]["smooth"]
            check(max(e["k1"]["max_abs"], e["k2"]["max_abs"]) < 0.1,
                  "c2blend n=64 degree 4: blend smooth max error %.2e < 0.1 (k1 up to %.2f)"
                  % (max(e["k1"]["max_abs"], e["k2"]["max_abs"]), s["estimates"]["k1_max"]))

    # Refinement: the analytic curvature of the blend and the CGAL estimate converge to each
    # other at the estimator's order, away from borders and trimlines.
    levels = [64, 128, 256]
    paths = [mesh(n) for n in levels]
    for deg, args, need in (("2", ["--rings", "1"], 1.8), ("4", ["--rings", "2"], 3.5)):
        errs = {"blend": [], "primary1": []}
        for p in paths:
            s, _ = tool.run(p, "--degree", deg, *args)
            for reg in errs:
                e = s["regions"][reg]["smooth"]
                errs[reg].append(max(e["k1"]["max_abs"], e["k2"]["max_abs"]))
        hs = [1.0 / n for n in levels]
        for reg, es in errs.items():
            p = order(hs, es)
            check(p >= need, "c2blend %s degree %s %s-ring, n=%s: smooth max err %s, order %.2f >= %.1f"
                  % (reg, deg, args[1], ",".join(map(str, levels)), " ".join("%.2e" % x for x in es), p, need))


def main(argv):
    if len(argv) < 4:
        print(__doc__)
        return 2
    tool = Tool(argv[1], argv[2])
    os.makedirs(tool.work, exist_ok=True)
    group = argv[3]
    if group == "accuracy":
        group_accuracy(tool)
    elif group == "convergence":
        group_convergence(tool)
    elif group == "bad":
        group_bad(tool)
    elif group == "c2blend":
        if len(argv) < 6 or not os.access(argv[4], os.X_OK):
            print("c2blend CLI not available: skipped")
            return 77
        group_c2blend(tool, argv[4], argv[5])
    else:
        print("unknown group %s" % group)
        return 2
    if FAILURES:
        print("%d check(s) failed" % len(FAILURES))
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
