#!/usr/bin/python3
"""Cross-check of the NURBS evaluator against OpenCASCADE (ctest nurbs_occt, label freecad).

    /usr/bin/python3 test_occt.py path/to/nurbs_dump

Random NURBS surfaces (degrees 1..5 in each direction, clamped knot vectors with repeated
interior knots, rational with weights in [0.5, 2] and non-rational, some periodic in u, in
v or in both, coordinates scaled from 1e-3 to 1e3; parameters include the domain corners
and, for periodic directions, values outside the domain) and random curves are built
both as c2b_nurbs JSON, evaluated by nurbs_dump (every SKL[a][b], a, b <= 3), and as
Part.BSplineSurface / Part.BSplineCurve objects in FreeCAD 0.20, evaluated by OCCT
(value, getDN). Both are also compared with an exact reference (60-digit decimal
evaluation of the same knots and poles from the textbook recursions).

Errors are relative to the largest exact norm of each derivative over the sample, floored
at its natural size max|pole| (p / h_u)^a (q / h_v)^b (h: mean knot span), the scale of
the rounding error that any evaluation carries; the floor only matters for derivatives
that (nearly) vanish, e.g. d^3/dv^3 of a quadratic raised to degree 5. A derivative passes
when it agrees with OCCT to 1e-12, or with the exact value to 1e-12, or is no farther from
the exact value than twice OCCT's error.

Knot insertion and degree elevation: nurbs_dump applies them, OCCT does its own
(insertUKnot/insertVKnot/insertKnot, increaseDegree); the knot vectors must be equal and
the poles and weights agree to 1e-12 relative (non-periodic objects, whose representation
is unique), and the modified objects are evaluated and compared as above. (That the shape
does not change is tested in test_nurbs.c.)

Prints a table of the largest errors; exit 0 when everything passes, 1 on a mismatch, 77
(skip) when FreeCAD is not available.
"""
import atexit
import json
import os
from decimal import Decimal, localcontext
from math import comb
import random
import shutil
import subprocess
import sys
import tempfile

TOL = 1e-12
N_SURF = 24
N_CURVE = 20
N_PARAM = 50
ORDER = 3

_home = tempfile.mkdtemp(prefix="c2b_occt_home_")
os.environ["HOME"] = _home  # FreeCAD writes its user configuration under HOME
atexit.register(shutil.rmtree, _home, True)
sys.path.append("/usr/lib/freecad-python3/lib")
try:
    import FreeCAD  # noqa: E402
    import Part  # noqa: E402
except ImportError as exc:  # pragma: no cover
    print("FreeCAD is not available (%s): skipped" % exc)
    sys.exit(77)

V = FreeCAD.Vector


def knot_data(rng, p, n, a, length, periodic):
    """Distinct knots, multiplicities (OCCT form) and the flat vector (c2b_nurbs form)."""
    if not periodic:
        interior = n - p - 1
        mults = []
        while sum(mults) < interior:
            m = rng.randint(2, p) if (p > 1 and rng.random() < 0.35) else 1
            mults.append(min(m, interior - sum(mults)))
        k = len(mults)
        while True:
            vals = sorted(rng.uniform(0.0, 1.0) for _ in range(k))
            pts = [0.0] + vals + [1.0]
            if all(pts[i + 1] - pts[i] > 0.3 / (k + 1) for i in range(k + 1)):
                break
        knots = [a + length * x for x in pts]
        knots[-1] = a + length
        mults = [p + 1] + mults + [p + 1]
        flat = [x for x, m in zip(knots, mults) for _ in range(m)]
        return knots, mults, flat
    # periodic: sum of the multiplicities of knots[0..k-1] is n, first = last = 1
    mults = [1]
    while sum(mults) < n:
        m = rng.randint(2, p) if (p > 1 and rng.random() < 0.3) else 1
        mults.append(min(m, n - sum(mults)))
    k = len(mults)
    while True:
        vals = sorted(rng.uniform(0.0, 1.0) for _ in range(k - 1))
        pts = [0.0] + vals + [1.0]
        if all(pts[i + 1] - pts[i] > 0.3 / k for i in range(k)):
            break
    knots = [a + length * x for x in pts]
    knots[-1] = a + length
    mults = mults + [1]
    period = [x for x, m in zip(knots[:-1], mults[:-1]) for _ in range(m)]
    assert len(period) == n
    flat = [period[i % n] + length * (i // n) for i in range(-p, n + p + 1)]
    return knots, mults, flat


def random_surface(rng, idx):
    p, q = rng.randint(1, 5), rng.randint(1, 5)
    per = [idx % 4 == 1, idx % 4 == 2]
    if idx % 8 == 3:
        per = [True, True]
    nu = p + 1 + rng.randint(0, 6) + (p if per[0] else 0)
    nv = q + 1 + rng.randint(0, 6) + (q if per[1] else 0)
    rational = idx % 3 != 0
    scale = [1e-3, 1.0, 1e3][idx % 3]
    ku = knot_data(rng, p, nu, rng.uniform(-2, 2), rng.uniform(0.5, 3), per[0])
    kv = knot_data(rng, q, nv, rng.uniform(-2, 2), rng.uniform(0.5, 3), per[1])
    poles = [[[scale * (i + rng.uniform(-0.4, 0.4)), scale * (j + rng.uniform(-0.4, 0.4)),
               scale * rng.uniform(-1, 1), rng.uniform(0.5, 2.0) if rational else 1.0]
              for j in range(nv)] for i in range(nu)]
    return dict(p=p, q=q, nu=nu, nv=nv, per=per, ku=ku, kv=kv, poles=poles, rational=rational)


def occt_surface(s):
    b = Part.BSplineSurface()
    poles = [[V(*P[:3]) for P in row] for row in s["poles"]]
    weights = [[P[3] for P in row] for row in s["poles"]]
    b.buildFromPolesMultsKnots(poles, s["ku"][1], s["kv"][1], s["ku"][0], s["kv"][0],
                               s["per"][0], s["per"][1], s["p"], s["q"], weights)
    return b


def c2b_surface(s):
    return {"degree": [s["p"], s["q"]], "knots_u": s["ku"][2], "knots_v": s["kv"][2],
            "poles": s["poles"], "periodic": s["per"]}


def run_dump(exe, data):
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(data, f)
        name = f.name
    try:
        r = subprocess.run([exe, name], capture_output=True, text=True)
    finally:
        os.unlink(name)
    if r.returncode != 0:
        raise RuntimeError("nurbs_dump failed: " + r.stderr.strip())
    return json.loads(r.stdout)


def vnorm(x):
    return (x[0] ** 2 + x[1] ** 2 + x[2] ** 2) ** 0.5


def exact_table(obj, params, du, dv):
    """SKL[a][b] (a <= du, b <= dv) of a c2b_nurbs JSON object (surface, or curve with
    dv = 0) in 60-digit decimal arithmetic (exact for our purpose: the inputs, doubles,
    convert exactly), from the textbook definitions: the Cox-de Boor recursion,
    N'_{i,d} = d (N_{i,d-1} / (U_{i+d} - U_i) - N_{i+1,d-1} / (U_{i+d+1} - U_{i+1})),
    and the Leibniz rule for S = A / w. Returns [{(a, b): (x, y, z)}] as floats."""
    with localcontext() as ctx:
        ctx.prec = 60
        return _exact_table(obj, params, du, dv)


def _exact_table(obj, params, du, dv):
    curve = "knots" in obj
    if curve:
        dirs = [(obj["degree"], obj["knots"], obj["periodic"])]
        poles = [[P] for P in obj["poles"]]
    else:
        dirs = [(obj["degree"][0], obj["knots_u"], obj["periodic"][0]),
                (obj["degree"][1], obj["knots_v"], obj["periodic"][1])]
        poles = obj["poles"]
    nd = [len(poles), len(poles[0])]
    U = [[Decimal(x) for x in k] for _, k, _ in dirs]
    hom = [[[Decimal(P[0]) * Decimal(P[3]), Decimal(P[1]) * Decimal(P[3]),
             Decimal(P[2]) * Decimal(P[3]), Decimal(P[3])] for P in row] for row in poles]
    orders = [du, dv]

    def basis(di, t):
        p, _, per = dirs[di]
        K = U[di]
        nw = len(K) - p - 1
        a, b = K[p], K[nw]
        if per:
            t = a + (t - a) % (b - a)
            if t < a:
                t += b - a
        t = min(max(t, a), b)
        if t >= b:
            span = nw - 1
            while K[span] == K[span + 1]:
                span -= 1
        else:
            span = p
            while K[span + 1] <= t:
                span += 1
        memo = {}

        def N(i, d, m):
            key = (i, d, m)
            if key in memo:
                return memo[key]
            if d == 0:
                r = Decimal(int(i == span and m == 0))
            elif m == 0:
                r = Decimal(0)
                if K[i + d] > K[i]:
                    r += (t - K[i]) / (K[i + d] - K[i]) * N(i, d - 1, 0)
                if K[i + d + 1] > K[i + 1]:
                    r += (K[i + d + 1] - t) / (K[i + d + 1] - K[i + 1]) * N(i + 1, d - 1, 0)
            else:
                r = Decimal(0)
                if K[i + d] > K[i]:
                    r += d * N(i, d - 1, m - 1) / (K[i + d] - K[i])
                if K[i + d + 1] > K[i + 1]:
                    r -= d * N(i + 1, d - 1, m - 1) / (K[i + d + 1] - K[i + 1])
            memo[key] = r
            return r
        idx = list(range(span - p, span + 1))
        return idx, [[N(i, p, m) for i in idx] for m in range(orders[di] + 1)]

    out = []
    for prm in params:
        if curve:
            iu, Nu = basis(0, Decimal(prm))
            iv, Nv = [0], [[Decimal(1)]] + [[Decimal(0)]] * dv
        else:
            iu, Nu = basis(0, Decimal(prm[0]))
            iv, Nv = basis(1, Decimal(prm[1]))
        A = {}
        for a in range(du + 1):
            for b in range(dv + 1):
                acc = [Decimal(0)] * 4
                for r, i in enumerate(iu):
                    if Nu[a][r] == 0:
                        continue
                    for c, j in enumerate(iv):
                        f = Nu[a][r] * Nv[b][c]
                        if f:
                            P = hom[i % nd[0]][j % nd[1]]
                            for x in range(4):
                                acc[x] += f * P[x]
                A[(a, b)] = acc
        S = {}
        for a in range(du + 1):
            for b in range(dv + 1):
                v = list(A[(a, b)][:3])
                for i in range(a + 1):
                    for j in range(b + 1):
                        if i == 0 and j == 0:
                            continue
                        f = comb(a, i) * comb(b, j) * A[(i, j)][3]
                        for x in range(3):
                            v[x] -= f * S[(a - i, b - j)][x]
                S[(a, b)] = [x / A[(0, 0)][3] for x in v]
        out.append({k: tuple(float(x) for x in v) for k, v in S.items()})
    return out


def occt_to_c2b(occ, curve):
    """The c2b_nurbs JSON form of an OCCT B-spline (flat knot vectors as in knot_data)."""
    def flat(knots, mults, p, per):
        if not per:
            return occt_flat(knots, mults)
        period = [x for x, m in zip(knots[:-1], mults[:-1]) for _ in range(m)]
        n, T = len(period), knots[-1] - knots[0]
        return [period[i % n] + T * (i // n) for i in range(-p, n + p + 1)]
    if curve:
        W = occ.getWeights()
        return {"degree": occ.Degree, "periodic": occ.isPeriodic(),
                "knots": flat(occ.getKnots(), occ.getMultiplicities(), occ.Degree, occ.isPeriodic()),
                "poles": [[P.x, P.y, P.z, w] for P, w in zip(occ.getPoles(), W)]}
    W = occ.getWeights()
    return {"degree": [occ.UDegree, occ.VDegree], "periodic": [occ.isUPeriodic(), occ.isVPeriodic()],
            "knots_u": flat(occ.getUKnots(), occ.getUMultiplicities(), occ.UDegree, occ.isUPeriodic()),
            "knots_v": flat(occ.getVKnots(), occ.getVMultiplicities(), occ.VDegree, occ.isVPeriodic()),
            "poles": [[[P.x, P.y, P.z, w] for P, w in zip(row, wrow)]
                      for row, wrow in zip(occ.getPoles(), W)]}


class Stats:
    def __init__(self):
        self.worst = {}   # (kind, a, b) -> [vs OCCT, ours vs exact, OCCT vs exact]
        self.fail = []
        self.other = {}

    def add(self, key, rel, what):
        """A plain check: rel <= TOL."""
        self.other[key] = max(self.other.get(key, 0.0), rel)
        if not rel <= TOL:
            self.fail.append("%s: relative error %.3g" % (what, rel))

    def add_table(self, key, d, eo, ex, what):
        w = self.worst.setdefault(key, [0.0, 0.0, 0.0])
        for i, x in enumerate((d, eo, ex)):
            w[i] = max(w[i], x)
        # pass: agrees with OCCT, or is as close to the exact value (or at least about as
        # close as OCCT)
        if not (d <= TOL or eo <= TOL or eo <= 2 * ex):
            self.fail.append("%s: vs OCCT %.3g, vs exact %.3g (OCCT vs exact %.3g)" % (what, d, eo, ex))


def natural_size(obj, a, b):
    """max |pole coordinate| (p / h_u)^a (q / h_v)^b of a c2b_nurbs JSON object, h the mean
    length of the non-empty knot spans in the domain: the size of a typical a, b-th
    derivative of a spline with such poles, and over eps the rounding error that any
    evaluation of it carries."""
    if "knots" in obj:
        dirs = [(obj["degree"], obj["knots"], a)]
        coords = [abs(x) for P in obj["poles"] for x in P[:3]]
    else:
        dirs = [(obj["degree"][0], obj["knots_u"], a), (obj["degree"][1], obj["knots_v"], b)]
        coords = [abs(x) for row in obj["poles"] for P in row for x in P[:3]]
    size = max(coords)
    for p, knots, k in dirs:
        dom = knots[p:len(knots) - p]
        spans = sum(1 for x, y in zip(dom, dom[1:]) if y > x)
        size *= (p * spans / (dom[-1] - dom[0])) ** k
    return size


def compare_table(stats, kind, label, mine, ref, du, dv, exact, exact_ref, obj):
    """mine[k][a*(dv+1)+b] (nurbs_dump), ref[k][(a, b)] (OCCT), exact[k][(a, b)] (exact value
    for our representation obj), exact_ref (for OCCT's): per (a, b) the max errors over
    the sample relative to the larger of the largest exact norm of that derivative over
    the sample and its natural size (see natural_size(); this floor matters only for
    derivatives that nearly vanish, e.g. d^3/du^3 of a quadratic raised to degree 5,
    which both evaluators return as rounding noise)."""
    def dist(x, y):
        return vnorm([p - q for p, q in zip(x, y)])
    for a in range(du + 1):
        for b in range(dv + 1):
            idx = a * (dv + 1) + b
            n = len(ref)
            size = max(max(vnorm(exact[k][(a, b)]) for k in range(n)),
                       natural_size(obj, a, b))
            d = max(dist(mine[k][idx], ref[k][(a, b)]) for k in range(n)) / size
            eo = max(dist(mine[k][idx], exact[k][(a, b)]) for k in range(n)) / size
            ex = max(dist(ref[k][(a, b)], exact_ref[k][(a, b)]) for k in range(n)) / size
            stats.add_table((kind, a, b), d, eo, ex, "%s SKL[%d][%d]" % (label, a, b))


def surface_params(rng, s, occ):
    u0, u1, v0, v1 = occ.bounds()
    pts = [(rng.uniform(u0, u1), rng.uniform(v0, v1)) for _ in range(N_PARAM - 2)]
    if not any(s["per"]):
        pts += [(u0, v0), (u1, v1)]
    else:  # parameters outside the domain of a periodic direction wrap
        pts += [(rng.uniform(u0, u1) + (u1 - u0) * (2 if s["per"][0] else 0),
                 rng.uniform(v0, v1) - (v1 - v0) * (1 if s["per"][1] else 0)) for _ in range(2)]
    return pts


def occt_table(occ, pts, du, dv):
    ref = []
    for (u, v) in pts:
        row = {}
        for a in range(du + 1):
            for b in range(dv + 1):
                x = occ.value(u, v) if a + b == 0 else occ.getDN(u, v, a, b)
                row[(a, b)] = (x.x, x.y, x.z)
        ref.append(row)
    return ref


def occt_curve_table(occ, ts, d):
    ref = []
    for t in ts:
        row = {}
        for a in range(d + 1):
            x = occ.value(t) if a == 0 else occ.getDN(t, a)
            row[(a, 0)] = (x.x, x.y, x.z)
        ref.append(row)
    return ref


def occt_flat(knots, mults):
    return [x for x, m in zip(knots, mults) for _ in range(m)]


def compare_rep(stats, label, res, occ2, curve):
    """Knot vectors and poles after insertion/elevation: ours (res, JSON) against OCCT's."""
    ref = occt_to_c2b(occ2, curve)
    keys = ["knots"] if curve else ["knots_u", "knots_v"]
    same = res["degree"] == ref["degree"] and all(len(res[k]) == len(ref[k]) for k in keys)
    if not same:
        stats.add(("knots after ops",), float("inf"), label + ": degree or knot count differs")
        return
    kerr = max(abs(a - b) for k in keys for a, b in zip(res[k], ref[k]))
    stats.add(("knots after ops",), kerr, label + ": knot vectors")
    mine = res["poles"] if curve else [P for row in res["poles"] for P in row]
    other = ref["poles"] if curve else [P for row in ref["poles"] for P in row]
    if len(mine) != len(other):
        stats.add(("poles after ops",), float("inf"), label + ": pole count differs")
        return
    size = max(max(abs(x) for x in P[:3]) for P in other)
    err = max(max(abs(P[i] - Q[i]) for i in range(3)) for P, Q in zip(mine, other)) / size
    werr = max(abs(P[3] - Q[3]) / Q[3] for P, Q in zip(mine, other))
    stats.add(("poles after ops",), max(err, werr), label + ": poles and weights")


def check_surfaces(exe, rng, stats):
    for idx in range(N_SURF):
        s = random_surface(rng, idx)
        occ = occt_surface(s)
        pts = surface_params(rng, s, occ)
        label = "surface %d (degrees %d, %d, %d x %d poles, periodic %s)" % (
            idx, s["p"], s["q"], s["nu"], s["nv"], s["per"])
        out = run_dump(exe, {"surface": c2b_surface(s), "params": [list(x) for x in pts],
                             "du": ORDER, "dv": ORDER})
        ex = exact_table(out["result"], pts, ORDER, ORDER)
        compare_table(stats, "surface", label, out["derivs"], occt_table(occ, pts, ORDER, ORDER),
                      ORDER, ORDER, ex, exact_table(occt_to_c2b(occ, False), pts, ORDER, ORDER),
                      out["result"])

        # knot insertion in u and v, then degree elevation of the open directions
        u0, u1, v0, v1 = occ.bounds()
        tu, tv = rng.uniform(u0, u1), rng.uniform(v0, v1)
        mu, mv = rng.randint(1, s["p"]), rng.randint(1, s["q"])
        ops = [{"insert": [0, tu, mu]}, {"insert": [1, tv, mv]}]
        occ2 = occ.copy()
        occ2.insertUKnot(tu, mu, 0.0)
        occ2.insertVKnot(tv, mv, 0.0)
        eu = 0 if s["per"][0] else rng.randint(0, 2)
        ev = 0 if s["per"][1] else rng.randint(1, 2)
        if eu:
            ops.append({"elevate": [0, eu]})
        if ev:
            ops.append({"elevate": [1, ev]})
        if eu or ev:
            occ2.increaseDegree(s["p"] + eu, s["q"] + ev)
        out2 = run_dump(exe, {"surface": c2b_surface(s), "params": [list(x) for x in pts],
                              "du": ORDER, "dv": ORDER, "ops": ops})
        res = out2["result"]
        lab2 = label + " after insert (u %d, v %d) / elevate (%d, %d)" % (mu, mv, eu, ev)
        compare_table(stats, "surface after ops", lab2, out2["derivs"],
                      occt_table(occ2, pts, ORDER, ORDER), ORDER, ORDER,
                      exact_table(res, pts, ORDER, ORDER),
                      exact_table(occt_to_c2b(occ2, False), pts, ORDER, ORDER), res)
        if not any(s["per"]):
            compare_rep(stats, lab2, res, occ2, False)


def random_curve(rng, idx):
    p = 1 + idx % 5
    per = idx % 4 == 3
    n = p + 1 + rng.randint(0, 7) + (p if per else 0)
    rational = idx % 2 == 0
    scale = [1e-3, 1.0, 1e3][idx % 3]
    k = knot_data(rng, p, n, rng.uniform(-2, 2), rng.uniform(0.5, 3), per)
    poles = [[scale * (i + rng.uniform(-0.4, 0.4)), scale * rng.uniform(-1, 1),
              scale * rng.uniform(-1, 1), rng.uniform(0.5, 2.0) if rational else 1.0]
             for i in range(n)]
    return dict(p=p, n=n, per=per, k=k, poles=poles, rational=rational)


def check_curves(exe, rng, stats):
    for idx in range(N_CURVE):
        c = random_curve(rng, idx)
        occ = Part.BSplineCurve()
        occ.buildFromPolesMultsKnots([V(*P[:3]) for P in c["poles"]], c["k"][1], c["k"][0],
                                     c["per"], c["p"], [P[3] for P in c["poles"]])
        t0, t1 = occ.FirstParameter, occ.LastParameter
        ts = [rng.uniform(t0, t1) for _ in range(N_PARAM - 2)]
        ts += [t0, t1] if not c["per"] else [t0 + 0.3 * (t1 - t0) - 2 * (t1 - t0),
                                             t1 + 0.7 * (t1 - t0)]
        js = {"degree": c["p"], "knots": c["k"][2], "poles": c["poles"], "periodic": c["per"]}
        label = "curve %d (degree %d, %d poles, periodic %s)" % (idx, c["p"], c["n"], c["per"])
        out = run_dump(exe, {"curve": js, "params": ts, "d": ORDER})
        compare_table(stats, "curve", label, out["derivs"], occt_curve_table(occ, ts, ORDER), ORDER, 0,
                      exact_table(out["result"], ts, ORDER, 0),
                      exact_table(occt_to_c2b(occ, True), ts, ORDER, 0), out["result"])

        tk = rng.uniform(t0, t1)
        m = rng.randint(1, c["p"])
        ops = [{"insert": [0, tk, m]}]
        occ2 = occ.copy()
        occ2.insertKnot(tk, m, 0.0)
        e = 0 if c["per"] else rng.randint(1, 3)
        if e:
            ops.append({"elevate": [0, e]})
            occ2.increaseDegree(c["p"] + e)
        out2 = run_dump(exe, {"curve": js, "params": ts, "d": ORDER, "ops": ops})
        lab2 = label + " after insert %d / elevate %d" % (m, e)
        compare_table(stats, "curve after ops", lab2, out2["derivs"], occt_curve_table(occ2, ts, ORDER),
                      ORDER, 0, exact_table(out2["result"], ts, ORDER, 0),
                      exact_table(occt_to_c2b(occ2, True), ts, ORDER, 0), out2["result"])
        if not c["per"]:
            compare_rep(stats, lab2, out2["result"], occ2, True)


def main():
    if len(sys.argv) != 2:
        print("usage: test_occt.py path/to/nurbs_dump")
        return 2
    exe = sys.argv[1]
    rng = random.Random(20261121)
    stats = Stats()
    check_surfaces(exe, rng, stats)
    check_curves(exe, rng, stats)
    print("Relative errors, max over %d surfaces and %d curves x %d parameters (each relative to"
          % (N_SURF, N_CURVE, N_PARAM))
    print("the largest exact norm of that derivative over the sample, floored at its natural size):")
    print("  %-26s %12s %12s %12s" % ("derivative", "vs OCCT", "vs exact", "OCCT-exact"))
    for key in sorted(stats.worst, key=str):
        w = stats.worst[key]
        print("  %-26s %12.3g %12.3g %12.3g" % ("%s [%d][%d]" % key, w[0], w[1], w[2]))
    for key in sorted(stats.other, key=str):
        print("  %-26s %12.3g" % (" ".join(str(x) for x in key), stats.other[key]))
    if stats.fail:
        print("FAIL: %d comparisons:" % len(stats.fail))
        for f in stats.fail[:40]:
            print("  " + f)
        return 1
    print("ok: every derivative agrees with OCCT to %g relative or is at least as close to the"
          " exact value as OCCT's; knots and poles after insertion/elevation agree to %g" % (TOL, TOL))
    return 0


if __name__ == "__main__":
    sys.exit(main())
