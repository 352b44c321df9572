# SPDX-License-Identifier: LGPL-2.1-or-later
"""G2 fillets on solids (issue 5, MATH.md section 7).

Route: OCCT's rolling-ball fillet of the same radius gives trimlines (its contact edges)
and corresponding points (its cross-sections). Rolling-ball faces that join each other
tangentially end to end (a tangent chain of edges, or an edge OCCT split at a seam) form
one chain. Each chain whose two sides border one unfilleted face each is replaced by
one PDE blend with G2 cross-boundary data from those faces, sampled uniformly in arc
length and fitted as a B-spline face; planar faces at the fillet's ends get the blend's
end curve as their new boundary; everything is sewn into a solid and checked
(BRepCheck, and continuity along every trimline). Kept as OCCT made them, and reported
as such with the reason (no G2 claim is made there): corner patches where fillets meet
at a vertex, chains whose side changes face, ends on non-planar faces, and rolling-ball
surfaces that OCCT only approximates too roughly for exact G2 data (RoughTrimlines).
"""
import math
import time

import Part

from ..errors import C2BlendError
from . import check as ck
from .bspline import fit_surface, solve_sampled
from .rollingball import RollingBallFace, chains, new_faces
from .trimlines import ROWS, pair_rows, shape_for, spec_from_rows

DATA_REL = 1e-8  # target relative truncation error of the sampled boundary data
DATA_KEEP = 1e-6  # above this, the trimlines are too rough for a G2 blend: keep OCCT's face


class RoughTrimlines(Exception):
    """The rolling-ball trimlines are not smooth enough for an exact G2 blend."""


def resolve_edges(shape, edges, label):
    """[(name, Part.Edge)] from Part.Edge objects, 'EdgeN' names or 1-based indices.
    Raises C2BlendError naming the offending element."""
    out = []
    for e in edges:
        if isinstance(e, int):
            e = "Edge%d" % e
        if isinstance(e, str):
            if not e.startswith("Edge"):
                raise C2BlendError("%s is not an edge; select edges to fillet" % e,
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
            raise C2BlendError("a %s was given where an edge is needed; select edges to "
                               "fillet" % kind, label)
        name = ck.element_name(shape, e, "Edge")
        if name == "?":
            raise C2BlendError("the edge does not belong to the shape", label)
        out.append((name, e))
    if not out:
        raise C2BlendError("no edges given", label)
    for name, edge in out:
        n = len(ck.edge_faces(shape, edge))
        if n != 2:
            raise C2BlendError("the edge has %d adjacent face%s; a fillet needs exactly 2"
                               % (n, "" if n == 1 else "s"), "%s.%s" % (label, name))
    return out


def check_params(radius, continuity, shape_params, tension, label):
    """Validate the numeric parameters; raise C2BlendError naming the bad one.
    Returns the shape parameters for the continuity (see trimlines.shape_for)."""
    if not (isinstance(radius, (int, float)) and math.isfinite(radius) and radius > 0):
        raise C2BlendError("radius must be a positive number, got %r" % (radius,), label,
                           "radius")
    if continuity not in ROWS:
        raise C2BlendError("continuity must be C1, C2 or C3, got %r" % (continuity,), label)
    try:
        shape = shape_for(continuity, shape_params)
    except (TypeError, ValueError) as ex:
        raise C2BlendError("shape_params: %s" % ex, label) from None
    if not (math.isfinite(tension) and tension > 0):
        raise C2BlendError("tension must be a positive number, got %r" % (tension,), label)
    return shape


def sample_rows(chain, n, nrows, tension, where):
    """Cross-boundary rows at n corresponding points of a rolling-ball chain."""
    return pair_rows(chain.sides[0], chain.sides[1], chain.section_pairs(n), nrows, tension,
                     where)


class Blended:
    """A rolling-ball chain replaced by a PDE blend: surface, face, fit and data facts."""

    def __init__(self, chain, where, surface, fit, samples, data_rel):
        self.chain, self.where, self.surface, self.fit = chain, where, surface, fit
        self.samples, self.data_rel = samples, data_rel
        self.face = Part.Face(surface)
        self.v_range = surface.bounds()[2:4]


def solve_face(chain, where, continuity, shape_params, tension, tol_rel, samples, max_samples):
    """The PDE blend replacing one rolling-ball chain (see bspline.solve_sampled)."""
    nrows = ROWS[continuity]
    blend, n, err = solve_sampled(
        lambda k: sample_rows(chain, k, nrows, tension, where),
        lambda r0, r1: spec_from_rows(r0, r1, continuity, shape_params, chain.closed,
                                      "fillet " + where),
        where, samples, max_samples, DATA_REL)
    if err > DATA_KEEP:
        raise RoughTrimlines(
            "OCCT's rolling-ball surface here is an approximation (face tolerance %.1e); the "
            "boundary data sampled from it converge only to %.1e (relative) with %d samples, "
            "too rough for an exact G2 blend" % (max(f.Tolerance for f in chain.faces), err, n))
    surface, fit = fit_surface(blend, tol_rel, where)
    return Blended(chain, where, surface, fit, n, err)


def _replace_edges(face, swaps):
    """A planar face like `face` with edges replaced per swaps [(old, new)]."""
    wires = []
    for w in face.Wires:
        es = [next((new for old, new in swaps if old.isSame(e)), e) for e in w.Edges]
        wires.append(Part.Wire(Part.__sortEdges__(es)))
    return Part.makeFace(wires, "Part::FaceMakerBullseye")


def assemble(result, blended, where):
    """The solid: result's faces with rolling-ball faces replaced by the blends and the
    planar end faces re-bounded; sewn, made a solid and checked. Raises C2BlendError."""
    swaps = {}  # planar end face index -> [(old edge, new edge)]
    faces_out = []
    drop = [f for b in blended for f in b.chain.faces]
    for b in blended:
        v0, v1 = b.v_range
        ends = {v: b.surface.value(0.5, v) for v in (v0, v1)}
        for e, plane in b.chain.ends:
            mid = e.valueAt(0.5 * (e.FirstParameter + e.LastParameter))
            v = min(ends, key=lambda x: (ends[x] - mid).Length)
            new = Part.Edge(b.surface.vIso(v))
            i = next(k for k, f in enumerate(result.Faces) if f.isSame(plane))
            swaps.setdefault(i, []).append((e, new))
        faces_out.append(b.face)
    for i, f in enumerate(result.Faces):
        if any(f.isSame(d) for d in drop):
            continue
        if i in swaps:
            try:
                f = _replace_edges(f, swaps[i])
            except Exception as ex:
                raise C2BlendError("cannot rebound the end face Face%d with the blend's end "
                                   "curve (%s)" % (i + 1, ex), where, "sewing") from None
        faces_out.append(f)
    sewn = Part.Compound(faces_out)
    sewn.sewShape()
    shells = sewn.Shells if sewn.ShapeType != "Shell" else [sewn]
    if len(shells) != 1 or not shells[0].isClosed():
        free = sum(1 for s in shells for e in s.Edges
                   if len(s.ancestorsOfType(e, Part.Face)) == 1
                   and not e.isSeam(s.ancestorsOfType(e, Part.Face)[0]))
        raise C2BlendError("sewing the blend faces to the solid failed: %d shell(s), %d free "
                           "edge(s) left (gaps wider than the sewing tolerance)"
                           % (len(shells), free), where, "sewing")
    solid = Part.Solid(shells[0])
    if solid.Volume < 0:
        solid.reverse()
    try:
        solid.check(True)  # BRepCheck_Analyzer, as isValid(), but says what is wrong
    except Exception as ex:
        raise C2BlendError("the filleted solid is not valid after sewing (BRepCheck: %s)"
                           % str(ex).strip(), where, "validity") from None
    return solid


def _where(label, names, chain):
    """Names of the selected edges nearest to a rolling-ball chain, for messages."""
    d = [(min(f.distToShape(e)[0] for f in chain.faces), n) for n, e in names]
    best = min(x for x, _ in d)
    return ", ".join("%s.%s" % (label, n) for x, n in d if x <= best + 1e-9 * (1 + best))


def _trimline_checks(solid, blended):
    """Continuity of the solid across both trimlines of each blend face, at 101 points
    per trimline, evaluated on the blend at known parameters and projected onto the
    neighbouring face of the solid."""
    out = []
    diag = solid.BoundBox.DiagonalLength
    for b in blended:
        face = _find_face(solid, b.surface)
        for side in (0.0, 1.0):
            pts = ck.trimline_points(b.surface, side)
            probe = Part.Vertex(pts[len(pts) // 2][0])
            nbrs = [f for e in face.Edges for f in ck.edge_faces(solid, e)
                    if not f.isSame(face) and e.distToShape(probe)[0] < 1e-6 * diag]
            if not nbrs:
                raise C2BlendError("the blend face is not joined to a face along u = %g"
                                   % side, b.where, "sewing")
            r = ck.compare(face, nbrs[0], pts, diag)
            r["edge"] = ck.element_name(solid, _edge_near(face, probe), "Edge")
            r["faces"] = [ck.element_name(solid, face, "Face"),
                          ck.element_name(solid, nbrs[0], "Face")]
            r["blend"] = b.where
            r["blend_face"] = r["faces"][0]
            out.append(r)
    return out


def _edge_near(face, vertex):
    return min(face.Edges, key=lambda e: e.distToShape(vertex)[0])


def _find_face(solid, surface):
    """The face of solid lying on surface (sewing keeps the surface, not the face)."""
    u0, u1, v0, v1 = surface.bounds()
    p = Part.Vertex(surface.value(0.5 * (u0 + u1), 0.5 * (v0 + v1)))
    return min(solid.Faces, key=lambda f: f.distToShape(p)[0])


def fillet(shape, edges, radius, continuity="C2", shape_params=(1.0, 1.0, 1.0, 1.0),
           tension=1.0, label="Shape", tol_rel=1e-7, samples=32, max_samples=1024):
    """G2 (C2 data) fillet of `edges` of solid `shape` at `radius` (model units).

    edges: Part.Edge objects of shape, 'EdgeN' names or 1-based indices.
    continuity: 'C1', 'C2' or 'C3' (rows of cross-boundary data matched).
    shape_params: (gamma, eta, lambda, rho) for C2, (b, c, d) for C1, (a0..a4) for C3;
    all ones (the default) fits any continuity. tension scales the cross derivatives.
    tol_rel: B-spline fit tolerance relative to each blend's bounding-box diagonal.
    Returns (Part.Solid, report dict). Raises C2BlendError naming `label` and the edge.
    The input shape is not modified.
    """
    t0 = time.perf_counter()
    shape_params = check_params(radius, continuity, shape_params, tension, label)
    names = resolve_edges(shape, edges, label)
    where_all = ", ".join("%s.%s" % (label, n) for n, _ in names)
    try:
        result = shape.makeFillet(radius, [e for _, e in names])
        ok = not result.isNull() and result.isValid()
    except Exception as ex:
        msg, ok = str(ex) or type(ex).__name__, False
    else:
        msg = "the result is not a valid solid"
    if not ok:
        raise C2BlendError("OCCT's rolling-ball fillet of radius %g failed (%s); the radius is "
                           "probably too large for the faces next to the edge"
                           % (radius, msg), where_all, "radius")
    t_occt = time.perf_counter() - t0
    fillet_faces = new_faces(shape, result)
    blended, kept = [], []
    for chain in chains([RollingBallFace(result, f, fillet_faces) for f in fillet_faces]):
        where = _where(label, names, chain)
        if chain.corner:
            kept.append({"where": where, "reason": chain.corner})
            continue
        try:
            blended.append(solve_face(chain, where, continuity, shape_params, tension, tol_rel,
                                      samples, max_samples))
        except RoughTrimlines as ex:
            kept.append({"where": where, "reason": str(ex)})
    t_solve = time.perf_counter()
    solid = assemble(result, blended, where_all) if blended else (
        result.Solids[0] if len(result.Solids) == 1 else result)
    t_assemble = time.perf_counter()
    checks = _trimline_checks(solid, blended)
    report = {
        "continuity": continuity, "radius": radius, "shape_params": list(shape_params),
        "tension": tension,
        "blends": [{"where": b.where, "samples": b.samples, "data_error": b.data_rel,
                    "fit_deviation": b.fit["deviation"], "fit_tolerance": b.fit["tolerance"],
                    "poles": list(b.fit["poles"].shape[:2]),
                    "closed": b.chain.closed} for b in blended],
        "kept_occt_faces": kept,
        "trimlines": checks,
        "volume": solid.Volume, "occt_volume": result.Volume,
        "seconds": time.perf_counter() - t0, "occt_seconds": t_occt,
        "stage_seconds": {"occt_fillet": t_occt, "trimlines_solve_fit": t_solve - t0 - t_occt,
                          "sew_and_brepcheck": t_assemble - t_solve,
                          "continuity_check": time.perf_counter() - t_assemble},
    }
    report["verdict"] = min([c["verdict"] for c in checks] + (["G1"] if kept else []),
                            key=ck.RANK.get) if (checks or kept) else "none"
    return solid, report
