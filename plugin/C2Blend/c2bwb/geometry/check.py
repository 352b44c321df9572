# SPDX-License-Identifier: LGPL-2.1-or-later
"""Continuity across edges of a shape (MATH.md section 8), from the CAD faces alone.

For an edge between faces A and B, points along the edge are projected onto both
surfaces. At each point:
  g0 = distance between the two projections (model units);
  g1 = angle between the oriented normals (rad);
  g2 = |kA - kB|, the jump of the normal curvature in the direction across the edge
       (1/model units), and g2_rel = g2 / max(|kA|, |kB|, k_scale), where k_scale is
       the largest |principal curvature| of either face (curvature_scale) and at least
       1/diagonal: a fillet's curvature jump is measured against its own curvature,
       whatever its size (a fillet of radius 0.025 and one of 2 on the same part meet
       the same relative bound);
  dk = the largest jump of k1, k2 (principal curvatures) and of H.
Verdicts: G2 when g0 <= tol_g0, g1 <= tol_g1 and g2_rel <= tol_g2; G1 and G0 likewise.
tol_g0 is at least TOL_G0_REL of the shape's diagonal, so that a part's size does not
change its verdict (double precision holds positions to about 1e-16 of their size).
This works on any shape, including OCCT's own fillets (G1: their curvature jumps by 1/R
across the contact edges).
"""
import math
import numbers

import Part

from ..errors import C2BlendError
from .recut import EXCHANGE_GAP
from .surface import Frame, frame_at_point, frame_or_none, angle

TOL_G0 = 1e-6     # model units, and at least the edge tolerance
TOL_G0_REL = 1e-10  # of the diagonal: the g0 tolerance of large parts
TOL_G1 = 1e-8     # rad
TOL_G2 = 1e-6     # relative curvature jump
SIDE_JUMP = 1e-5  # a face's own relative curvature jump across a knot line (format_report)


def edge_faces(shape, edge):
    """The faces of `shape` that contain `edge` (distinct, in shape order)."""
    out = []
    for f in shape.ancestorsOfType(edge, Part.Face):
        if not any(f.isSame(g) for g in out):
            out.append(f)
    return out


def named_edges(shape, edges, label, purpose):
    """[(name, Part.Edge)] from Part.Edge objects, 'EdgeN' names or 1-based indices of
    edges of shape (`label` in messages; purpose: what the edges are for, e.g. 'fillet').
    A single edge, name or index stands for a list of one; an edge given twice counts
    once. Raises C2BlendError naming the offending element."""
    if not isinstance(shape, Part.Shape):
        raise C2BlendError("a Part shape is needed, got %s" % type(shape).__name__, label)
    if isinstance(edges, (str, numbers.Integral, Part.Shape)):
        edges = [edges]
    try:
        edges = list(edges)
    except TypeError:
        raise C2BlendError("edges must be a list of Part.Edge objects, 'EdgeN' names or "
                           "1-based indices, got %s" % type(edges).__name__, label) from None
    out = []
    for e in edges:
        if isinstance(e, bool) or not isinstance(e, (numbers.Integral, str, Part.Shape)):
            raise C2BlendError("%r is not an edge: give Part.Edge objects, 'EdgeN' names or "
                               "1-based indices" % (e,), label)
        if isinstance(e, numbers.Integral):
            e = "Edge%d" % e
        if isinstance(e, str):
            if not e.startswith("Edge"):
                raise C2BlendError("%s is not an edge; select edges to %s" % (e, purpose),
                                   "%s.%s" % (label, e))
            try:
                edge = shape.getElement(e)
            except Exception:
                raise C2BlendError("no such edge (the shape has %d edges)" % len(shape.Edges),
                                   "%s.%s" % (label, e)) from None
            out.append((e, edge))
            continue
        if not isinstance(e, Part.Shape) or e.ShapeType != "Edge":
            kind = getattr(e, "ShapeType", type(e).__name__)
            raise C2BlendError("a %s was given where an edge is needed; select edges to %s"
                               % (kind, purpose), label)
        name = element_name(shape, e, "Edge")
        if name == "?":
            raise C2BlendError("the edge does not belong to the shape%s"
                               % _lying_where(shape, e), label)
        out.append((name, e))
    if not out:
        raise C2BlendError("no edges given", label)
    return [x for i, x in enumerate(out) if all(x[0] != y[0] for y in out[:i])]


def sample_params(edge, n):
    """n parameters of the edge: interior points at (k + 1/2)/n, so no vertex is used
    (at vertices a third face may intervene)."""
    a, b = edge.FirstParameter, edge.LastParameter
    return [a + (b - a) * (k + 0.5) / n for k in range(n)]


SCALE_GRID = 9  # points per direction where curvature_scale looks


def curvature_scale(face):
    """The largest |principal curvature| (1/model units) of face at SCALE_GRID x
    SCALE_GRID points inside its parameter range (0 on a plane; degenerate points are
    skipped): the scale of its curvature jumps (g2_rel)."""
    if face.Surface.isPlanar():
        return 0.0
    u0, u1, v0, v1 = face.ParameterRange
    k = 0.0
    for i in range(SCALE_GRID):
        for j in range(SCALE_GRID):
            fr = frame_or_none(face, u0 + (u1 - u0) * (i + 0.5) / SCALE_GRID,
                               v0 + (v1 - v0) * (j + 0.5) / SCALE_GRID)
            if fr is not None:
                k1, k2 = fr.principal()[:2]
                k = max(k, abs(k1), abs(k2))
    return k


def _scale(face, scales):
    """curvature_scale(face), kept in the dict scales (None: not kept) by the face's
    hash, so that a report over many edges samples each face once."""
    if scales is None:
        return curvature_scale(face)
    key = face.hashCode()
    if key not in scales:
        scales[key] = curvature_scale(face)
    return scales[key]


def compare(fa, fb, points, diag, tol_g0=TOL_G0, oriented=True, scales=None):
    """Continuity between faces fa and fb at (point, tangent, uv) triples on their
    common boundary, in order along it, uv being the point's parameters on fa or None
    (then it is projected, starting from the previous point's parameters): worst g0, g1,
    g2, g2_rel, dk and a verdict (see the module doc; diag is the shape's diagonal).
    oriented=False compares faces that are not yet in one shell: their normals may be
    opposite, so fb's normal is flipped along the whole boundary where most of it faces
    away from fa's. scales: a dict shared by the comparisons of one report, where each
    face's curvature scale is kept."""
    tol_g0 = max(tol_g0, TOL_G0_REL * diag)
    k_scale = max(1.0 / diag, _scale(fa, scales), _scale(fb, scales))
    worst = {"g0": 0.0, "g1": 0.0, "g2": 0.0, "g2_rel": 0.0, "dk": 0.0}
    ka_max = kb_max = 0.0
    ga = gb = None  # each projection starts from the previous point's (points are in order)
    frames = []
    for p, tangent, uv in points:
        a = frame_at_point(fa, p, ga) if uv is None else Frame(fa, *uv)
        b = frame_at_point(fb, a.p, gb)
        ga, gb = (a.u, a.v), (b.u, b.v)
        frames.append((a, b, tangent))
    # one flip for the whole boundary, as most of it has it: where a face folds back over
    # the other (its cross derivative turns through zero), its normal turns there
    flip = not oriented and sum(a.n.dot(b.n) for a, b, _ in frames) < 0
    for a, b, tangent in frames:
        if flip:
            b.n = -b.n
        d = a.n.cross(tangent)
        d.normalize()
        db = d - b.n * d.dot(b.n)
        if db.Length < 1e-3:  # a sharp edge: no common cross direction
            ka = kb = g2 = g2_rel = math.inf
            pa = pb = (0.0, 0.0, 0.0, 0.0)
        else:
            ka, kb = a.normal_curvature(d), b.normal_curvature(db)
            pa, pb = a.principal(), b.principal()
            g2 = abs(ka - kb)
            g2_rel = g2 / max(abs(ka), abs(kb), k_scale)
        worst["g0"] = max(worst["g0"], (a.p - b.p).Length)
        worst["g1"] = max(worst["g1"], angle(a.n, b.n))
        worst["g2"] = max(worst["g2"], g2)
        worst["g2_rel"] = max(worst["g2_rel"], g2_rel)
        worst["dk"] = max(worst["dk"], abs(pa[0] - pb[0]), abs(pa[1] - pb[1]), abs(pa[3] - pb[3]))
        ka_max, kb_max = max(ka_max, abs(ka)), max(kb_max, abs(kb))
    if worst["g0"] > tol_g0:
        verdict = "none"
    elif worst["g1"] > TOL_G1:
        verdict = "G0"
    elif worst["g2_rel"] > TOL_G2:
        verdict = "G1"
    else:
        verdict = "G2"
    worst.update({"samples": len(points), "verdict": verdict,
                  "cross_curvature": (ka_max, kb_max), "curvature_scale": k_scale,
                  "tolerances": {"g0": tol_g0, "g1": TOL_G1, "g2_rel": TOL_G2}})
    return worst


def trimline_points(surface, side, n=101, v_range=None):
    """(point, tangent, (u, v)) at n v-midpoints of the u = side trimline of surface,
    over v_range (default: the surface's whole v-range)."""
    v0, v1 = v_range or surface.bounds()[2:4]
    out = []
    for k in range(n):
        v = v0 + (v1 - v0) * (k + 0.5) / n
        out.append((surface.value(side, v), surface.getDN(side, v, 0, 1), (side, v)))
    return out


def check_edge(shape, edge, samples=101, diagonal=None, scales=None):
    """Continuity report (dict) for one edge shared by two faces of `shape` (scales: see
    compare).

    Raises ValueError when the edge does not have exactly two faces.
    """
    faces = edge_faces(shape, edge)
    if len(faces) != 2:
        raise ValueError("the edge has %d adjacent faces, continuity needs 2" % len(faces))
    points = [(edge.valueAt(t), edge.tangentAt(t), None) for t in sample_params(edge, samples)]
    return compare(faces[0], faces[1], points, diagonal or shape.BoundBox.DiagonalLength,
                   max(TOL_G0, edge.Tolerance), scales=scales)


def _lying_where(shape, edge):
    """' (it lies where EdgeN of the shape does: ...)' when an edge of shape has the same
    ends and midpoint as `edge` (to 1e-9 of its length), as an edge of shape.copy() or of
    an equal shape built again; '' otherwise."""
    def points(e):
        a, b = e.ParameterRange
        return [e.valueAt(t) for t in (a, 0.5 * (a + b), b)]
    mine, tol = points(edge), 1e-9 * max(edge.Length, 1e-9)
    for i, f in enumerate(shape.Edges):
        theirs = points(f)
        if any(all((p - q).Length <= tol for p, q in zip(mine, order))
               for order in (theirs, theirs[::-1])):
            return (" (it lies where Edge%d of the shape does: pass that shape's own edge, "
                    "or its name 'Edge%d'; an edge of shape.copy() or of another shape is "
                    "not the same edge)" % (i + 1, i + 1))
    return ""


def element_name(shape, sub, kind):
    """FreeCAD sub-element name ('Edge3', 'Face1') of sub in shape, or '?'."""
    subs = shape.Edges if kind == "Edge" else shape.Faces
    for i, s in enumerate(subs):
        if s.isSame(sub):
            return "%s%d" % (kind, i + 1)
    return "?"


RANK = {"none": 0, "G0": 1, "G1": 2, "G2": 3}


def check(shape, edges, samples=101, label="Shape"):
    """Continuity report for the given edges of shape.

    edges: Part.Edge objects, names like 'Edge3' or 1-based indices. Returns
    {"edges": [{"edge": "Edge3", "faces": ["Face1", "Face2"], ...per-edge dict...}],
     "verdict": worst verdict}. Raises C2BlendError naming `label` and the edge when an
    edge is not one of shape's or does not lie between two faces.
    """
    if isinstance(samples, bool) or not isinstance(samples, numbers.Integral) or samples < 1:
        raise C2BlendError("samples must be a whole number of at least 1, got %r"
                           % (samples,), label)
    named = named_edges(shape, edges, label, "check")
    for name, edge in named:
        faces = edge_faces(shape, edge)
        if len(faces) != 2:
            raise C2BlendError("the edge has %d adjacent face%s; continuity is measured "
                               "between two faces%s"
                               % (len(faces), "" if len(faces) == 1 else "s",
                                  " (it is the seam where that closed face joins itself)"
                                  if len(faces) == 1 and edge.isSeam(faces[0]) else ""),
                               "%s.%s" % (label, name))
    out = []
    diag = shape.BoundBox.DiagonalLength
    scales = {}
    for name, edge in named:
        rep = check_edge(shape, edge, samples, diag, scales)
        rep["edge"] = name
        rep["faces"] = [element_name(shape, f, "Face") for f in edge_faces(shape, edge)]
        out.append(rep)
    verdict = min((r["verdict"] for r in out), key=RANK.get) if out else "none"
    return {"edges": out, "verdict": verdict}


def side_jump_words(jump):
    """Why two blends meet at a crease where a side face's own principal curvatures jump
    by `jump` (relative, knots.side_jump), for reports and reasons."""
    return ("a side face's own curvature jumps by %.2g (relative) there: it is only G1 "
            "across its knot line or seam (as at the start of a closed curve from FreeCAD "
            "0.20's periodic interpolate), so no fillet is G2 to it on both sides" % jump)


def format_report(rep):
    """Human-readable lines for the Report view, of a check report (check()) or of a
    fillet or blend report (its trimlines, corner fillings and the OCCT faces it kept)."""
    lines = []
    for r in rep["edges"] if "edges" in rep else rep["trimlines"]:
        lines.append("%s (%s): %s  G0 %.2e  G1 %.2e rad  curvature jump %.3g (rel %.2e)"
                     % (r["edge"], "/".join(r["faces"]), r["verdict"], r["g0"], r["g1"],
                        r["g2"], r["g2_rel"]))
    for r in rep.get("mitres", []):
        lines.append("%s (%s): mitre where two fillets meet at an angle, a crease as in OCCT "
                     "(not a trimline, not in the verdict): %s, normals %.3g rad apart"
                     % (r["edge"], "/".join(r["faces"]), r["verdict"], r["g1"]))
    for r in rep.get("junctions", []):
        if r["g1"] > TOL_G1:
            lines.append("%s (%s): junction of two pointwise blends that meet at a crease, "
                         "where a side changes face or crosses a knot line (as one only C2 "
                         "crossed obliquely; never G2; in the verdict): %s, normals %.2e "
                         "rad apart, edges %.2e apart"
                         % (r["edge"], "/".join(r["faces"]), r["verdict"], r["g1"], r["g0"]))
            if r.get("side_curvature_jump", 0.0) > SIDE_JUMP:
                lines[-1] += "; " + side_jump_words(r["side_curvature_jump"])
            continue
        lines.append("%s (%s): junction of two pointwise blends, where a side changes face "
                     "or crosses a knot line (not a trimline, not in the verdict): %s, as "
                     "the faces there; normals %.3g rad apart, curvature jump %.3g"
                     % (r["edge"], "/".join(r["faces"]), r["verdict"], r["g1"], r["g2"]))
    for r in rep.get("corner_patches", []):
        lines.append("%s (%s): OCCT's corner patch replaced by its plate filling, tangent to "
                     "the blends' ends within tolerance (never G2; in the verdict): %s, edges "
                     "%.2e apart, normals %.2e rad apart"
                     % (r["where"], r["face"], r["verdict"], r["g0"], r["g1"]))
        if "crease" in r and r["crease"]["setback"]:  # setback.py
            lines[-1] += ("; set back from a vertex whose third edge stays sharp, it meets "
                          "%s at an angle there, as the top face meets it along that edge "
                          "(not in those measures)" % r["crease"]["face"])
        elif "crease" in r:
            lines[-1] += ("; it meets %s at an angle, as OCCT's corner patch does (not in "
                          "those measures)" % r["crease"]["face"])
    for k in rep.get("skipped_edges", []):
        lines.append("%s: left out of the fillet: %s" % (k["where"], k["reason"]))
    for k in rep.get("kept_occt_faces", []):
        lines.append("%s: kept OCCT's rolling-ball face (G1 only, no G2 claim): %s"
                     % (k["where"], k["reason"]))
    if "solid_check" in rep:
        lines.append("solid: %s" % rep["solid_check"])
    if "tolerance" in rep:
        t = rep["tolerance"]
        lines.append("tolerances: largest vertex %.2g, edge %.2g (OCCT's fillet: %.2g, %.2g)"
                     % (t["vertex"], t["edge"], t["occt_vertex"], t["occt_edge"]))
    if "exchange" in rep:
        x = rep["exchange"]
        lines.append("exchange: %d edge(s) whose curves lie more than %.0e apart on their "
                     "faces, the largest gap %.2g (OCCT's fillet: %d, %.2g)"
                     % (x["edges"], EXCHANGE_GAP, x["gap"], x["occt_edges"], x["occt_gap"]))
        if x["edges"]:
            lines[-1] += ("; a STEP file keeps no tolerances, so OCCT's BOP check of the "
                          "solid read back from one may find those edges off their faces")
    return lines
