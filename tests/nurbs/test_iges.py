#!/usr/bin/python3
"""IGES export round trip (ctest iges_roundtrip, label freecad).

    /usr/bin/python3 test_iges.py path/to/iges_dump

Exit status 0 when every check passes, 1 otherwise, 77 (skipped) without FreeCAD.

For each test surface (polynomial and rational, clamped with repeated interior knots,
unclamped, degrees 2 to 5, one periodic in v, a scale sweep) the driver writes an IGES
file with c2b_iges_write_surface(). The test then

  1. checks the file's fixed-column structure (80-column records, section letters and
     sequence numbers, Terminate counts, DE pointers, no token split across records) and
     reads the Parameter Data back itself: every knot, weight and pole must equal the
     input exactly, in the entity-128 order (u index fastest);
  2. reads the file with FreeCAD (OpenCASCADE's IGES reader), takes the face's surface,
     and compares it on a 20 x 20 grid over the domain with the same surface built
     directly in FreeCAD by Part.BSplineSurface.buildFromPolesMultsKnots (an evaluator
     independent of C2Blend) and with the points C2Blend itself evaluates (driver
     --grid), to 1e-9 of the bounding-box diagonal;
  3. checks exact geometry where it exists (rational quadratic half and full cylinders,
     the full one flagged closed), the
     unit flag (a file in metres reads 1000x larger in FreeCAD's millimetres), and
  4. atomicity: a path that is a directory, a missing or read-only directory, a write
     that fails half way (file-size limit, EFBIG), bad units and NULL or empty arguments
     all fail with a message, leave no file and no temporary behind, and leave a
     pre-existing file untouched; a successful write keeps the replaced file's mode.
"""
import glob
import json
import math
import os
import pwd
import random
import re
import resource
import signal
import stat
import subprocess
import sys
import tempfile

FREECAD_LIB = "/usr/lib/freecad-python3/lib"
GRID = 20
RTOL = 1e-9

failed = 0
passed = 0


def check(what, cond, detail=""):
    global failed, passed
    print("%s %s%s" % ("ok  " if cond else "FAIL", what, (": " + detail) if detail else ""))
    if cond:
        passed += 1
    else:
        failed += 1
    return cond


def check_le(what, value, limit):
    return check(what, value <= limit, "%.3g <= %.3g" % (value, limit))


# ---- test surfaces ----------------------------------------------------------------------


def clamped(p, interior, a=0.0, b=1.0):
    return [a] * (p + 1) + list(interior) + [b] * (p + 1)


def periodic_flat(p, n, period_knots):
    """Flat knot vector (n + 2p + 1 values) of a periodic direction whose one-period
    knots (n + 1 values, first to last) are given: t[p + k] = period_knots[k], extended
    by t[i + n] = t[i] + T."""
    assert len(period_knots) == n + 1
    T = period_knots[-1] - period_knots[0]
    t = [None] * (n + 2 * p + 1)
    for k, x in enumerate(period_knots):
        t[p + k] = x
    for i in range(p - 1, -1, -1):
        t[i] = t[i + n] - T
    for i in range(n + p + 1, n + 2 * p + 1):
        t[i] = t[i - n] + T
    return t


def make_surfaces():
    rnd = random.Random(20240611)
    out = []

    # bicubic polynomial, clamped, a double interior knot in u
    ku = clamped(3, [0.3, 0.3, 0.7])
    kv = clamped(3, [0.5])
    nu, nv = len(ku) - 4, len(kv) - 4
    poles = [[[i * 1.5, j * 2.0, math.sin(i) * math.cos(0.7 * j) * 3.0, 1.0] for j in range(nv)]
             for i in range(nu)]
    out.append(("bicubic_polynomial", {"degree": [3, 3], "knots_u": ku, "knots_v": kv,
                                       "poles": poles, "periodic": [False, False]}))

    # rational quadratic half cylinder of radius 2: exact circle arcs in u, a line in v
    R = 2.0
    h = math.sqrt(0.5)
    arc = [(R, 0, 1.0), (R, R, h), (0, R, 1.0), (-R, R, h), (-R, 0, 1.0)]
    poles = [[[x, y, z, w] for z in (0.0, 1.5, 3.0)] for (x, y, w) in arc]
    out.append(("rational_half_cylinder", {"degree": [2, 2],
                                           "knots_u": clamped(2, [0.5, 0.5]),
                                           "knots_v": clamped(2, []),
                                           "poles": poles, "periodic": [False, False]}))

    # rational quadratic full cylinder of radius 2, clamped: closed in u (PROP1 = 1)
    sq = [(R, 0, 1.0), (R, R, h), (0, R, 1.0), (-R, R, h), (-R, 0, 1.0), (-R, -R, h),
          (0, -R, 1.0), (R, -R, h), (R, 0, 1.0)]
    poles = [[[x, y, z, w] for z in (-1.0, 2.0)] for (x, y, w) in sq]
    out.append(("rational_full_cylinder", {"degree": [2, 1],
                                           "knots_u": clamped(2, [0.25, 0.25, 0.5, 0.5,
                                                                  0.75, 0.75]),
                                           "knots_v": clamped(1, []),
                                           "poles": poles, "periodic": [False, False]}))

    # degree 4 x 5 rational, random weights, non-unit domains, repeated interior knots
    ku = clamped(4, [0.25, 0.5, 0.5], 0.0, 1.0)
    kv = clamped(5, [0.2, 0.2, 1.1], -1.0, 2.0)
    nu, nv = len(ku) - 5, len(kv) - 6
    poles = [[[i + rnd.uniform(-0.2, 0.2), 0.7 * j + rnd.uniform(-0.2, 0.2),
               rnd.uniform(-1, 1), rnd.uniform(0.5, 2.0)] for j in range(nv)]
             for i in range(nu)]
    out.append(("rational_deg4x5", {"degree": [4, 5], "knots_u": ku, "knots_v": kv,
                                    "poles": poles, "periodic": [False, False]}))

    # periodic in v: degree 2 x 3, rational, non-uniform periodic knots (a bumpy torus band)
    p, q, nv = 2, 3, 7
    ku = clamped(2, [1.0], 0.0, 2.0)
    nu = len(ku) - 3
    kv = periodic_flat(q, nv, [0.0, 0.5, 1.5, 2.0, 3.0, 3.25, 3.5, 4.0])
    poles = []
    for i in range(nu):
        row = []
        for j in range(nv):
            a = 2 * math.pi * j / nv
            r = 5.0 + math.cos(math.pi * i / (nu - 1)) + rnd.uniform(-0.3, 0.3)
            row.append([r * math.cos(a), r * math.sin(a), math.sin(math.pi * i / (nu - 1)),
                        rnd.uniform(0.6, 1.6)])
        poles.append(row)
    out.append(("periodic_v_rational", {"degree": [p, q], "knots_u": ku, "knots_v": kv,
                                        "poles": poles, "periodic": [False, True]}))

    # quintic in u with an unclamped uniform knot vector, quadratic clamped in v
    p, q = 5, 2
    nu = 7
    ku = [float(k) for k in range(nu + p + 1)]
    kv = clamped(2, [0.4])
    nv = len(kv) - 3
    poles = [[[0.5 * i, j + 0.1 * i, rnd.uniform(-1, 1), 1.0] for j in range(nv)]
             for i in range(nu)]
    out.append(("unclamped_quintic", {"degree": [p, q], "knots_u": ku, "knots_v": kv,
                                      "poles": poles, "periodic": [False, False]}))

    # scale sweep of the rational degree-4x5 surface
    base = out[3][1]
    for scale in (1e-6, 1e6):
        s = json.loads(json.dumps(base))
        for row in s["poles"]:
            for pt in row:
                pt[0] *= scale
                pt[1] *= scale
                pt[2] *= scale
        out.append(("rational_deg4x5_scale_%g" % scale, s))
    return out


def domain(surf):
    dom = []
    for d, key in ((0, "knots_u"), (1, "knots_v")):
        t = surf[key]
        p = surf["degree"][d]
        n = len(surf["poles"]) if d == 0 else len(surf["poles"][0])
        if surf["periodic"][d]:
            dom += [t[p], t[n + p]]
        else:
            dom += [t[p], t[n]]
    return dom


def unwrapped(surf):
    """Pole net (nu' x nv' of [x, y, z, w]) with periodic directions unwrapped."""
    P = surf["poles"]
    nu, nv = len(P), len(P[0])
    p, q = surf["degree"]
    mu = nu + (p if surf["periodic"][0] else 0)
    mv = nv + (q if surf["periodic"][1] else 0)
    return [[P[i % nu][j % nv] for j in range(mv)] for i in range(mu)]


def grid_params(dom):
    return [(dom[0] + (dom[1] - dom[0]) * i / (GRID - 1),
             dom[2] + (dom[3] - dom[2]) * j / (GRID - 1))
            for i in range(GRID) for j in range(GRID)]


def bbox_diag(surf):
    pts = [pt for row in surf["poles"] for pt in row]
    lo = [min(pt[c] for pt in pts) for c in range(3)]
    hi = [max(pt[c] for pt in pts) for c in range(3)]
    return math.sqrt(sum((h - l) ** 2 for l, h in zip(lo, hi)))


# ---- IGES structure --------------------------------------------------------------------


def split_tokens(data, what):
    """Tokens of one record's data (Hollerith-aware). Each token ends with ',' or ';',
    and the record must end right after a delimiter (then only blanks)."""
    toks = []
    k = 0
    data = data.rstrip(" ")
    while k < len(data):
        m = re.match(r"(\d+)H", data[k:])
        if m:
            n = int(m.group(1))
            start = k + len(m.group(0))
            body = data[start:start + n]
            if len(body) < n:
                raise ValueError("%s: Hollerith string split across records" % what)
            k = start + n
            toks.append(("S", body))
        else:
            end = k
            while end < len(data) and data[end] not in ",;":
                end += 1
            toks.append(("V", data[k:end]))
            k = end
        if k >= len(data) or data[k] not in ",;":
            raise ValueError("%s: record ends inside a token: %r" % (what, data))
        k += 1
    return toks


def read_iges_structure(path):
    with open(path, "rb") as f:
        raw = f.read()
    text = raw.decode("ascii")
    lines = text.split("\n")
    check("file ends with a newline", lines[-1] == "")
    lines = lines[:-1]
    check("every record has 80 columns",
          all(len(l) == 80 for l in lines), "%d records" % len(lines))
    letters = "".join(l[72] for l in lines)
    check("sections in order S G D P T", re.fullmatch(r"S+G+D+P+T", letters) is not None,
          re.sub(r"(.)\1*", lambda m: m.group(1) + str(len(m.group(0))), letters))
    sect = {}
    for l in lines:
        sect.setdefault(l[72], []).append(l)
    for c, ls in sect.items():
        seq = [int(l[73:80]) for l in ls]
        check("section %s numbered 1..%d" % (c, len(ls)), seq == list(range(1, len(ls) + 1)))
    t = sect["T"][0]
    want = "S%7dG%7dD%7dP%7d" % (len(sect["S"]), len(sect["G"]), len(sect["D"]), len(sect["P"]))
    check("Terminate counts", t[:32] == want, repr(t[:32]))

    g = []
    for l in sect["G"]:
        g += split_tokens(l[:72], "global")
    d1, d2 = sect["D"]
    f1 = [d1[8 * k:8 * k + 8] for k in range(9)]
    f2 = [d2[8 * k:8 * k + 8] for k in range(9)]
    check("DE entity type 128", int(f1[0]) == 128 and int(f2[0]) == 128)
    check("DE parameter pointer 1", int(f1[1]) == 1)
    check("DE parameter record count", int(f2[3]) == len(sect["P"]),
          "%s vs %d" % (f2[3].strip(), len(sect["P"])))
    check("DE form 0", int(f2[4]) == 0)
    check("P records point at DE 1, column 65 blank",
          all(l[64] == " " and l[65:72] == "      1" for l in sect["P"]))
    ptoks = []
    for l in sect["P"]:
        ptoks += split_tokens(l[:64], "parameter")
    check("parameter data ends with ';'", sect["P"][-1][:64].rstrip().endswith(";"))
    return g, [v for (_, v) in ptoks]


def check_global(name, g, unit_flag, unit_name, surf):
    vals = [v for (_, v) in g]
    check(name + ": global delimiters", vals[0] == "," and vals[1] == ";")
    check(name + ": global system id", vals[4] == "C2Blend", vals[4])
    check(name + ": global integer bits/precision",
          [int(x) for x in vals[6:11]] == [32, 38, 6, 308, 15])
    check(name + ": global unit flag and name",
          int(vals[13]) == unit_flag and vals[14] == unit_name, "%s %s" % (vals[13], vals[14]))
    check(name + ": global date", re.fullmatch(r"\d{8}\.\d{6}", vals[17]) is not None, vals[17])
    maxc = max(abs(c) for row in surf["poles"] for pt in row for c in pt[:3])
    check(name + ": global max coordinate", float(vals[19]) == maxc, vals[19])
    check(name + ": global version flag 11 (5.3)", int(vals[22]) == 11)
    check(name + ": global has 25 fields", len(vals) == 25, str(len(vals)))


def closed_flags(surf):
    """Periodic directions are closed; so is a clamped direction whose first and last pole
    rows coincide."""
    P = surf["poles"]
    flags = []
    for d, key in ((0, "knots_u"), (1, "knots_v")):
        p, t = surf["degree"][d], surf[key]
        if surf["periodic"][d]:
            flags.append(1)
            continue
        is_clamped = len(set(t[:p + 1])) == 1 and len(set(t[-p - 1:])) == 1
        first = P[0] if d == 0 else [row[0] for row in P]
        last = P[-1] if d == 0 else [row[-1] for row in P]
        flags.append(1 if is_clamped and first == last else 0)
    return flags


def check_parameters(name, toks, surf):
    p, q = surf["degree"]
    net = unwrapped(surf)
    mu, mv = len(net), len(net[0])
    ws = [net[i][j][3] for i in range(mu) for j in range(mv)]
    head = [int(x) for x in toks[:10]]
    per = [1 if x else 0 for x in surf["periodic"]]
    check(name + ": K1 K2 M1 M2", head[:5] == [128, mu - 1, mv - 1, p, q], str(head[:5]))
    check(name + ": PROP3 polynomial flag", head[7] == (1 if len(set(ws)) == 1 else 0))
    check(name + ": PROP4 PROP5 periodic flags", head[8:10] == per, str(head[8:10]))
    check(name + ": PROP1 PROP2 closed flags", head[5:7] == closed_flags(surf), str(head[5:7]))
    want = [float(x) for x in surf["knots_u"]] + [float(x) for x in surf["knots_v"]]
    want += [net[i][j][3] for j in range(mv) for i in range(mu)]
    for j in range(mv):
        for i in range(mu):
            want += net[i][j][:3]
    want += domain(surf)
    got_txt = toks[10:]
    check(name + ": number of parameters", len(got_txt) == len(want),
          "%d vs %d" % (len(got_txt), len(want)))
    reals_ok = all(("." in x) for x in got_txt)
    check(name + ": every real has a decimal point", reals_ok)
    got = [float(x.replace("D", "E")) for x in got_txt]
    bad = [k for k, (a, b) in enumerate(zip(got, want)) if a != b]
    check(name + ": knots, weights (u fastest), poles, range read back exactly",
          not bad and len(got) == len(want),
          "first mismatch at %d" % bad[0] if bad else "%d values" % len(got))


# ---- FreeCAD ----------------------------------------------------------------------------


def mults_knots(t, lo, hi):
    """Distinct knots and multiplicities of flat vector t[lo..hi] (inclusive)."""
    ks, ms = [], []
    for x in t[lo:hi + 1]:
        if ks and x == ks[-1]:
            ms[-1] += 1
        else:
            ks.append(x)
            ms.append(1)
    return ks, ms


def freecad_direct(Part, V, surf):
    """The surface built directly in FreeCAD from the spec (periodic as periodic)."""
    P = surf["poles"]
    nu, nv = len(P), len(P[0])
    p, q = surf["degree"]
    args = []
    for d, (key, n, deg) in enumerate((("knots_u", nu, p), ("knots_v", nv, q))):
        t = surf[key]
        if surf["periodic"][d]:
            ks, ms = mults_knots(t, deg, n + deg)
        else:
            ks, ms = mults_knots(t, 0, len(t) - 1)
        args.append((ks, ms))
    s = Part.BSplineSurface()
    s.buildFromPolesMultsKnots([[V(*pt[:3]) for pt in row] for row in P],
                               args[0][1], args[1][1], args[0][0], args[1][0],
                               bool(surf["periodic"][0]), bool(surf["periodic"][1]), p, q,
                               [[pt[3] for pt in row] for row in P])
    return s


def read_face_surface(Part, path):
    shape = Part.read(path)
    faces = shape.Faces
    if len(faces) != 1:
        return None, None
    face = faces[0]
    s = face.Surface
    if s.TypeId != "Part::GeomBSplineSurface":
        s = face.toNurbs().Faces[0].Surface
    return face, s


def max_dist(a, b):
    return max(math.sqrt(sum((x - y) ** 2 for x, y in zip(p, r))) for p, r in zip(a, b))


def roundtrip(Part, V, dump, tmp, name, surf):
    src = os.path.join(tmp, name + ".json")
    out = os.path.join(tmp, name + ".igs")
    with open(src, "w") as f:
        json.dump(surf, f)
    r = subprocess.run([dump, src, out, "--grid", str(GRID)], capture_output=True, text=True)
    if not check(name + ": driver succeeds", r.returncode == 0, r.stderr.strip()):
        return
    check(name + ": no temporary left", not glob.glob(out + ".tmp-*"))
    g, toks = read_iges_structure(out)
    check_global(name, g, 2, "MM", surf)
    check_parameters(name, toks, surf)

    dom = domain(surf)
    uv = grid_params(dom)
    diag = bbox_diag(surf)
    tol = RTOL * diag
    face, s = read_face_surface(Part, out)
    if not check(name + ": FreeCAD reads one face", s is not None):
        return
    b = s.bounds()
    check(name + ": read surface keeps the parameter range",
          all(abs(x - y) <= 1e-12 * max(1.0, abs(y)) for x, y in zip(b, dom)),
          "%s vs %s" % (list(b), dom))
    check(name + ": face parameter range",
          all(abs(x - y) <= 1e-12 * max(1.0, abs(y)) for x, y in zip(face.ParameterRange, dom)))
    read_pts = [tuple(s.value(u, v)) for (u, v) in uv]
    direct = freecad_direct(Part, V, surf)
    direct_pts = [tuple(direct.value(u, v)) for (u, v) in uv]
    c2b_pts = [tuple(x) for x in json.loads(r.stdout)["points"]]
    check_le(name + ": IGES read vs FreeCAD direct, max distance / bbox diag",
             max_dist(read_pts, direct_pts) / diag, RTOL)
    check_le(name + ": IGES read vs C2Blend evaluation, max distance / bbox diag",
             max_dist(read_pts, c2b_pts) / diag, RTOL)
    check_le(name + ": FreeCAD direct vs C2Blend evaluation, max distance / bbox diag",
             max_dist(direct_pts, c2b_pts) / diag, RTOL)
    # off-grid check between the two FreeCAD surfaces
    rnd = random.Random(7)
    extra = [(rnd.uniform(dom[0], dom[1]), rnd.uniform(dom[2], dom[3])) for _ in range(200)]
    e = max_dist([tuple(s.value(u, v)) for u, v in extra],
                 [tuple(direct.value(u, v)) for u, v in extra]) / diag
    check_le(name + ": IGES read vs FreeCAD direct at 200 random (u, v)", e, RTOL)
    if surf["periodic"][1]:
        # OpenCASCADE honours PROP5 and folds the repeated poles back
        check(name + ": FreeCAD reads v as periodic with the distinct poles",
              s.isVPeriodic() and s.NbVPoles == len(surf["poles"][0]),
              "periodic %s, %d poles" % (s.isVPeriodic(), s.NbVPoles))
    if name in ("rational_half_cylinder", "rational_full_cylinder"):
        err = max(abs(math.hypot(p[0], p[1]) - 2.0) for p in read_pts)
        check_le(name + ": read points lie on the radius-2 cylinder (abs)", err, tol)


# ---- atomicity --------------------------------------------------------------------------


def run_dump(dump, src, out, *extra, preexec=None):
    return subprocess.run([dump, src, out] + list(extra), capture_output=True, text=True,
                          preexec_fn=preexec)


def no_leftovers(path):
    return not glob.glob(glob.escape(path) + ".tmp-*")


def atomicity(dump, tmp, surf):
    src = os.path.join(tmp, "atomic.json")
    with open(src, "w") as f:
        json.dump(surf, f)

    # argument errors (NULL surface, NULL or empty path) return C2B_ERR_ARG
    r = subprocess.run([dump, "--check-args", src], capture_output=True, text=True)
    lines = r.stdout.strip().splitlines()
    check("argument errors: NULL surface, NULL path, empty path give C2B_ERR_ARG",
          r.returncode == 0 and len(lines) == 3
          and all("invalid argument: iges:" in l for l in lines), " | ".join(lines))

    # path is a directory: rename fails, the temporary is removed
    d = os.path.join(tmp, "is_a_dir")
    os.mkdir(d)
    r = run_dump(dump, src, d)
    check("path is a directory: driver fails", r.returncode == 1, r.stderr.strip())
    check("path is a directory: message names the path and the I/O error",
          "i/o error" in r.stderr and d in r.stderr and "Is a directory" in r.stderr,
          r.stderr.strip())
    check("path is a directory: still an empty directory",
          os.path.isdir(d) and not os.listdir(d))
    check("path is a directory: no temporary left", no_leftovers(d))

    # missing directory
    m = os.path.join(tmp, "missing", "out.igs")
    r = run_dump(dump, src, m)
    check("missing directory: driver fails with the path",
          r.returncode == 1 and "i/o error" in r.stderr and m in r.stderr and "No such file" in r.stderr, r.stderr.strip())
    check("missing directory: nothing created", not os.path.exists(os.path.dirname(m)))

    # read-only directory with a pre-existing file. Root ignores permissions, so as root
    # the driver runs as the unprivileged user "nobody".
    ro = os.path.join(tmp, "readonly")
    os.mkdir(ro)
    target = os.path.join(ro, "keep.igs")
    with open(target, "w") as f:
        f.write("precious\n")
    os.chmod(ro, 0o555)
    preexec = None
    if os.geteuid() == 0:
        try:
            nobody = pwd.getpwnam("nobody")
            uid, gid = nobody.pw_uid, nobody.pw_gid
        except KeyError:
            uid = gid = 65534

        def preexec():
            os.setgid(gid)
            os.setuid(uid)
        os.chmod(tmp, 0o755)  # let the unprivileged driver reach its input
    try:
        before = os.stat(target)
        try:
            r = run_dump(dump, src, target, preexec=preexec)
        except (OSError, subprocess.SubprocessError) as e:
            r = None
            print("skip read-only directory: cannot run the driver unprivileged (%s)" % e)
        if r is not None and r.returncode not in (0, 1):
            print("skip read-only directory: driver did not run unprivileged: %s"
                  % r.stderr.strip())
        elif r is not None:
            check("read-only directory: driver fails",
                  r.returncode == 1 and "i/o error" in r.stderr and target in r.stderr
                  and "Permission denied" in r.stderr, r.stderr.strip())
            check("read-only directory: existing file untouched",
                  open(target).read() == "precious\n"
                  and os.stat(target).st_mtime_ns == before.st_mtime_ns)
            check("read-only directory: no temporary left", sorted(os.listdir(ro)) == ["keep.igs"])
    finally:
        os.chmod(ro, 0o755)
        os.chmod(tmp, 0o700)

    # a write that fails half way: file-size limit (EFBIG; works for root too)
    target = os.path.join(tmp, "keep2.igs")
    with open(target, "w") as f:
        f.write("precious\n")
    os.chmod(target, 0o640)
    before = os.stat(target)

    def limit():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (1000, 1000))

    r = run_dump(dump, src, target, preexec=limit)
    check("write fails half way (EFBIG): driver fails with the I/O error",
          r.returncode == 1 and "i/o error" in r.stderr and "File too large" in r.stderr and target in r.stderr,
          r.stderr.strip())
    check("write fails half way: existing file untouched",
          open(target).read() == "precious\n"
          and os.stat(target).st_mtime_ns == before.st_mtime_ns)
    check("write fails half way: no temporary left", no_leftovers(target))

    # unknown units: rejected before any file is touched
    r = run_dump(dump, src, target, "--units", "furlong")
    check("unknown units: driver fails naming the field",
          r.returncode == 1 and "invalid argument" in r.stderr and "units" in r.stderr and "furlong" in r.stderr, r.stderr.strip())
    check("unknown units: existing file untouched", open(target).read() == "precious\n")
    check("unknown units: no temporary left", no_leftovers(target))

    # success over an existing file: replaced, mode kept, no temporary
    r = run_dump(dump, src, target)
    check("replace existing file: driver succeeds", r.returncode == 0, r.stderr.strip())
    with open(target) as f:
        first = f.readline()
    check("replace existing file: content is IGES", len(first) == 81 and first[72] == "S")
    check("replace existing file: mode 0640 kept",
          stat.S_IMODE(os.stat(target).st_mode) == 0o640,
          oct(stat.S_IMODE(os.stat(target).st_mode)))
    check("replace existing file: no temporary left", no_leftovers(target))

    # a new file gets 0644
    fresh = os.path.join(tmp, "fresh.igs")
    r = run_dump(dump, src, fresh)
    check("new file: mode 0644", r.returncode == 0
          and stat.S_IMODE(os.stat(fresh).st_mode) == 0o644)


def units_check(Part, dump, tmp, surf):
    """A file in metres (or inches) reads scaled into FreeCAD's millimetres."""
    src = os.path.join(tmp, "units.json")
    with open(src, "w") as f:
        json.dump(surf, f)
    ref = os.path.join(tmp, "units_mm.igs")
    run_dump(dump, src, ref)
    _, s_mm = read_face_surface(Part, ref)
    dom = domain(surf)
    uv = grid_params(dom)
    diag = bbox_diag(surf)
    for name, flag, factor in (("M", 6, 1000.0), ("in", 1, 25.4), ("CM", 10, 10.0)):
        out = os.path.join(tmp, "units_%s.igs" % name)
        r = run_dump(dump, src, out, "--units", name)
        if not check("units %s: driver succeeds" % name, r.returncode == 0, r.stderr.strip()):
            continue
        g, _ = read_iges_structure(out)
        check_global("units " + name, g, flag, name.upper(), surf)
        _, s = read_face_surface(Part, out)
        e = max(math.sqrt(sum((a - factor * b) ** 2
                              for a, b in zip(s.value(u, v), s_mm.value(u, v))))
                for u, v in uv) / (factor * diag)
        check_le("units %s: FreeCAD reads coordinates x %g" % (name, factor), e, RTOL)


def odd_file_name(Part, dump, tmp, surf):
    """Delimiters, non-ASCII bytes and a long name in the Global file-name field."""
    src = os.path.join(tmp, "odd.json")
    with open(src, "w") as f:
        json.dump(surf, f)
    base = "we,ird;n\u00e4me H " + "x" * 80 + ".igs"
    out = os.path.join(tmp, base)
    r = run_dump(dump, src, out)
    if not check("odd file name: driver succeeds", r.returncode == 0, r.stderr.strip()):
        return
    try:
        g, _ = read_iges_structure(out)
    except ValueError as e:
        check("odd file name: global section parses record by record", False, str(e))
        return
    vals = [v for (_, v) in g]
    want = base.encode("utf-8").decode("ascii", "replace").replace("\ufffd", "_")[:68]
    check("odd file name: file name field sanitised and cut to one record",
          vals[3] == want, repr(vals[3]))
    check("odd file name: product id is the name without extension",
          vals[2] == want, repr(vals[2]))  # the name is longer than a record
    _, s = read_face_surface(Part, out)
    check("odd file name: FreeCAD reads the surface", s is not None)


def main():
    if len(sys.argv) != 2:
        print("usage: test_iges.py path/to/iges_dump")
        return 2
    dump = os.path.abspath(sys.argv[1])
    with tempfile.TemporaryDirectory(prefix="c2b_iges_") as tmp:
        home = os.path.join(tmp, "home")
        os.mkdir(home)
        os.environ["HOME"] = home
        sys.path.append(FREECAD_LIB)
        try:
            import FreeCAD  # noqa: F401  (needs HOME set first)
            import Part
            from FreeCAD import Vector as V
        except ImportError as e:
            print("skip: FreeCAD cannot be imported (%s)" % e)
            return 77

        surfaces = make_surfaces()
        for name, surf in surfaces:
            roundtrip(Part, V, dump, tmp, name, surf)
        units_check(Part, dump, tmp, surfaces[0][1])
        odd_file_name(Part, dump, tmp, surfaces[1][1])
        atomicity(dump, tmp, surfaces[3][1])

    print("test_iges: %d passed, %d failed" % (passed, failed))
    return 1 if failed or not passed else 0


if __name__ == "__main__":
    sys.exit(main())
