# SPDX-License-Identifier: LGPL-2.1-or-later
"""G2 fillets on solids (issue 5, MATH.md section 7): the steps, each in its module.

1. The input is checked: the selected edges, one closed solid, the radius or setback
   and the blend's parameters (inputs.py).
2. OCCT's rolling-ball fillet of the same radius gives the topology (which faces a
   fillet touches, rollingball.py) and a guide; where it fails, diagnose.py says why.
   Rolling-ball faces that join each other tangentially end to end (a tangent chain of
   edges, or an edge OCCT split at a seam) form one chain.
3. Each chain gets its PDE blend (solve.py): the exact contact of the ball on its two
   faces (contact.py), sampled uniformly in the arc length of the ball's centre curve,
   turned into G2 cross-boundary data, blended and fitted as a B-spline face. A chain
   whose side changes face (a rounded outline) has data only C1 along it: each run along
   one pair of faces gets the pointwise blend, and the runs meet at junctions; so do the
   pieces of a chain whose data are too rough because the contact crosses knot lines of a
   side face (knots.py).
4. An open chain that does not end on a plane across it (a slanted or curved end face,
   or another fillet met at an angle: a mitre) is traced past its ends and cut back by
   what lies there (ends.py); so is one that OCCT ends at a corner patch along a slanted
   edge, no ball's section: along that edge.
5. The faces of the original solid that the blends touch (their two sides and their end
   faces) are cut anew along the blends' boundary edges (recut.py). An end face grows by
   the region between the corner and the blend's end section where the fillet uncovers
   its surface, and a face by the region between its corner and a corner patch's edge
   cutting across it.
6. Where three or more fillets meet at a vertex, OCCT's corner patch ends their chains;
   when any of them is blended, the patch is replaced by a plate filling tangent to the
   blends' end sections and to the end sections of the fillets kept there (corners.py),
   measured and reported, never claimed G2. Where a convex and a concave fillet meet at a
   vertex whose third edge is not selected, OCCT's face between them vanishes at a point;
   that corner is set back along the third edge and filled likewise, meeting the face on
   the third edge's other side at an angle (setback.py). Where fillets follow an edge
   that curves tighter than their radius, OCCT ends them at a mitre with a face between
   them; both are set back from it and the corner is filled, tangent all round (turn.py).
7. Everything is sewn into a solid and checked by BRepCheck and OCCT's BOP check
   (assembly.py), and the continuity is measured along every trimline, mitre, junction
   and corner filling (here, with check.py).

Kept as OCCT made them, and reported as such with the reason (no G2 claim is made
there): chains whose side changes face where no blend is G2 to both faces, and chains
whose exact contact, blend, fit, cut or end face's growth cannot be built or whose blend
overshoots its faces (solve.NotReplaced, ends.trim, assembly.Unassembled; all of them
where OCCT raises an error while they are assembled), with the fillets that meet them in
a mitre, and the corner patches where every fillet is kept.
"""
import math
import time

import Part

from ..errors import C2BlendError, occt_message
from . import check as ck
from . import corners as cn
from . import ends
from . import solids as sl
from . import setback as sb
from . import turn as tn
from .knots import side_jump
from .rollingball import (TANGENT_ANGLE, RollingBallFace, chains, joined, midpoint,
                          new_faces, off_boundary)
from .surface import angle, frame_at_point
from . import inputs, solve, recut, assembly, diagnose


def _selected(shape, names, chains_):
    """{id(chain): [(name, edge)] of the selected edges of `shape` it fillets}: each edge
    goes to the chain whose faces are nearest to the edge's midpoint, of those with a
    face that touches the surfaces of the edge's two faces (_joins; of all, where none
    does). Nearest alone, a short edge whose own fillet the next one's consumes went to
    the other fillet at their vertex: the top edge over a chamfer, at the pocket's end
    wall, to the fillet between that wall and the chamfer (shapes.chamfered_pocket,
    R = 0.45), and the rim's fillet was named after none of the selected edges."""
    out = {}
    tol = 1e-7 * shape.BoundBox.DiagonalLength
    for n, e in names:
        mid = Part.Vertex(midpoint(e))
        faces = ck.edge_faces(shape, e)
        own = [c for c in chains_ if len(faces) == 2 and _joins(c, faces, tol)] or chains_
        c = min(own, key=lambda c: min(f.distToShape(mid)[0] for f in c.faces))
        out.setdefault(id(c), []).append((n, e))
    return out


def _joins(chain, faces, tol):
    """Whether a rolling-ball face of `chain` has its two contact edges on the surfaces of
    the two `faces`, one each (recut.face_under): it fillets an edge between them."""
    for m in chain.members:
        under = [recut.face_under(c, faces, tol) for c, _ in m.contacts]
        if len(under) == 2 and all(u is not None for u in under) and \
                not under[0].isSame(under[1]):
            return True
    return False


def _tangent_ends(shape, label, edges):
    """'; ...' naming each end of `edges` [(name, edge)] of shape where its two faces
    become tangent (normals within TANGENT_ANGLE), as where two equal cylinders meet in a
    tee: the rolling ball's fillet shrinks to a point there, which OCCT's faces follow
    and which tells why they do not chain up; '' where none does."""
    out = []
    for n, e in edges:
        faces = ck.edge_faces(shape, e)
        if len(faces) != 2:
            continue
        for v in e.Vertexes:
            a = angle(frame_at_point(faces[0], v.Point).n, frame_at_point(faces[1], v.Point).n)
            if a < TANGENT_ANGLE or math.pi - a < TANGENT_ANGLE:
                out.append("%s.%s at (%.4g, %.4g, %.4g)" % ((label, n) + tuple(v.Point)))
    if not out:
        return ""
    return ("; the two faces become tangent at %s, where the rolling ball's fillet shrinks "
            "to a point: a blend needs two trimlines apart" % ", ".join(out))


def _measure(solid, blended, corners, result):
    """The continuity measures of a filleted solid for the report: {"trimlines",
    "mitres", "junctions", "corner_patches": [check per trimline, shared edge or filled
    corner patch (rollingball.CornerPatch of `corners`)], "exchange": the edges of the
    solid, and of `result` (OCCT's fillet) with keys "occt_...", whose curves lie apart
    (recut.curve_gaps)}; blended: the blends in it."""
    faces = [(b, assembly.blend_face(solid, b)) for b in blended]
    scales = {}  # each face's curvature scale, sampled once for all the checks
    return {"trimlines": _trimline_checks(solid, faces, scales),
            "mitres": _shared_edge_checks(solid, faces, False, scales),
            "junctions": _shared_edge_checks(solid, faces, True, scales),
            "corner_patches": [_corner_check(solid, p, scales) for p in corners]
            if blended else [],
            "exchange": {**recut.curve_gaps(solid),
                         **{"occt_" + k: x for k, x in recut.curve_gaps(result).items()}}}


def _trimline_checks(solid, faces, scales):
    """Continuity of the solid across both trimlines of each blend face, at 101 points
    per trimline, evaluated on the blend at known parameters and projected onto the
    neighbouring face of the solid. faces: [(Blended, its face in solid)]; scales:
    check.compare's."""
    out = []
    diag = solid.BoundBox.DiagonalLength
    for b, face in faces:
        for side in (0.0, 1.0):
            v_range = ends.side_range(b, side)
            if v_range is None:
                continue  # the face does not reach this side
            pts = ck.trimline_points(b.surface, side, v_range=v_range)
            probe = Part.Vertex(pts[len(pts) // 2][0])
            nbrs = [f for e in face.Edges for f in ck.edge_faces(solid, e)
                    if not f.isSame(face) and e.distToShape(probe)[0] < 1e-6 * diag]
            if not nbrs:
                raise C2BlendError("the blend face is not joined to a face along u = %g"
                                   % side, b.where, "sewing")
            r = ck.compare(face, nbrs[0], pts, diag, scales=scales)
            r["edge"] = ck.element_name(solid, _edge_near(face, probe), "Edge")
            r["faces"] = [ck.element_name(solid, face, "Face"),
                          ck.element_name(solid, nbrs[0], "Face")]
            r["blend"] = b.where
            r["blend_face"] = r["faces"][0]
            out.append(r)
    return out


def _shared_edge_checks(solid, faces, junctions, scales):
    """Continuity across the edges where two blends meet: at an angle (mitres, junctions
    False), creases by construction, as where OCCT's fillets meet there; or where two
    runs of one chain meet (junctions True), G1 as the side faces are there, with the
    jump of a side face's own curvature there (knots.side_jump, relative:
    side_curvature_jump), which no blend can follow. Reported,
    not counted in the verdict, which is about the trimlines, except a junction whose
    blends meet at a crease (normals more than check.TOL_G1 apart; solve_runs accepts
    up to JUNCTION_TURN). faces: [(Blended, its face in solid)]; scales:
    check.compare's."""
    out = []
    for i, (b, f) in enumerate(faces):
        for o, g in faces[i + 1:]:
            if _consecutive(b, o) != junctions:
                continue
            for e in f.Edges:
                if any(e.isSame(x) for x in g.Edges):
                    r = ck.check_edge(solid, e, scales=scales)
                    r["edge"] = ck.element_name(solid, e, "Edge")
                    r["faces"] = [ck.element_name(solid, f, "Face"),
                                  ck.element_name(solid, g, "Face")]
                    r["blends"] = [b.where, o.where]
                    if junctions:
                        r["side_curvature_jump"] = side_jump(
                            [v.Point for v in e.Vertexes],
                            list(b.chain.sides) + list(o.chain.sides))
                    out.append(r)
    return out


def _corner_check(solid, patch, scales):
    """The continuity between the filling at a corner patch and the faces around it
    (check.check_edge along each of its edges): the worst of each measure, with the
    verdict by the report's criteria (scales: check.compare's)."""
    face = assembly.patch_face(solid, patch)
    edges = [e for e in face.Edges if not e.Degenerated]
    creased = [e for e in edges if any(cn.on_edge(e, c) for c in patch.creases)]
    rs = [ck.check_edge(solid, e, scales=scales) for e in edges
          if not any(e is c for c in creased)]
    out = {"where": patch.where(), "face": ck.element_name(solid, face, "Face"),
           "edges": len(rs), "g0": max(r["g0"] for r in rs),
           "g1": max(r["g1"] for r in rs), "g2_rel": max(r["g2_rel"] for r in rs),
           "verdict": min((r["verdict"] for r in rs), key=ck.RANK.get)}
    if creased:  # where it meets a face at an angle, as OCCT's patch or the rim does
        wall = [f for f in solid.ancestorsOfType(creased[0], Part.Face) if not f.isSame(face)]
        out["crease"] = {"edges": len(creased), "face": ck.element_name(solid, wall[0], "Face")
                         if wall else None, "setback": patch.setback is not None}
    return out


def _consecutive(a, b):
    """Whether blends a and b are runs of one chain that follow one another along it
    (solve_runs: the last run and the first of a closed chain too, Blended.ring; a
    run's own chain attribute is the run, never closed), and so meet at a junction.
    The first and last runs of a chain that is not closed can also share an edge: at a
    sharp corner of the outline that the chain runs round (a plate's top edge, its
    corners rounded but one), where they meet at a mitre as two chains do."""
    group = a.group
    if group is None or group is not b.group:
        return False
    i, j = sorted(next(k for k, x in enumerate(group) if x is y) for y in (a, b))
    return j - i == 1 or (a.ring and (i, j) == (0, len(group) - 1))


def _edge_near(face, vertex):
    return min(face.Edges, key=lambda e: e.distToShape(vertex)[0])


def _occt_face_at(label, face):
    """'Label, OCCT's face at (x, y, z)': a face of OCCT's fillet that no selected edge
    is nearest to (such as the face between two fillets at a vertex), for messages."""
    p = face.CenterOfMass
    return "%s, OCCT's face at (%.4g, %.4g, %.4g)" % (label, p.x, p.y, p.z)


def fillet(shape, edges, radius, continuity="C2", shape_params=(1.0, 1.0, 1.0, 1.0),
           tension=1.0, label="Shape", tol_rel=1e-8, samples=32, max_samples=1024,
           bop=True):
    """G2 (C2 data) fillet of `edges` of solid `shape` at `radius` (model units).

    edges: Part.Edge objects of shape, 'EdgeN' names or 1-based indices.
    continuity: 'C1', 'C2' or 'C3' (rows of cross-boundary data matched).
    shape_params: (gamma, eta, lambda, rho) for C2, (b, c, d) for C1, (a0..a4) for C3;
    all ones (the default) fits any continuity. tension scales the cross derivatives.
    tol_rel: B-spline fit tolerance relative to each blend's bounding-box diagonal. The
    fit's error in the normal must stay well below the G1 criterion (1e-8 rad): at 1e-7
    the pipe tee's normal angle was 7e-9 rad, at 1e-8 it is 3e-10.
    bop: run OCCT's BOP check on the result (False for a preview: it is half the time
    of a many-edge fillet, and can take its limit, bopcheck.LIMIT; BRepCheck still runs).
    Returns (Part.Solid, report dict). Raises C2BlendError naming `label` and the edge.
    Seams and edges between tangent faces among other edges are left out, as OCCT's
    fillet does, and listed in the report's "skipped_edges" with the reason.
    On a compound of solids, each solid with selected edges is filleted on its own, as
    OCCT's fillet does (solids.py): the result is then a Part.Compound, and the report
    also lists the solids filleted ("solids").
    The input shape is not modified.
    """
    t0 = time.perf_counter()
    radius, shape_params, tension = inputs.check_params(radius, continuity, shape_params,
                                                        tension, label)
    skipped = []  # seams and edges between tangent faces in a larger selection
    names = inputs.resolve_edges(shape, edges, label, skipped)

    def one(solid, names):
        return _fillet_solid(solid, names, radius, continuity, shape_params, tension, label,
                             tol_rel, samples, max_samples, bop)

    several = sl.separate(shape)
    if several:
        result, report = sl.fillet_each(several, names, label, one, inputs.check_solid)
    else:
        inputs.check_solid(shape, label)
        result, report = one(shape, names)
    report["skipped_edges"] = skipped
    report["seconds"] = time.perf_counter() - t0
    return result, report


def _fillet_solid(shape, names, radius, continuity, shape_params, tension, label, tol_rel,
                  samples, max_samples, bop):
    """fillet() of the edges `names` ([(name, Part.Edge of shape)]) of the closed solid
    `shape`, with the parameters checked (check_params): (solid, report without
    "skipped_edges")."""
    t0 = time.perf_counter()
    # OCCT's fillet shares faces and edges with its input, and what follows writes to
    # some of them (a tessellation sets a face's Checked flag): work on a copy
    own = [ck.element_name(shape, edge, "Edge") for _, edge in names]  # the solid's names
    shape = shape.copy()
    names = [(n, shape.getElement(o)) for (n, _), o in zip(names, own)]
    where_all = ", ".join("%s.%s" % (label, n) for n, _ in names)
    selected = [e for _, e in names]
    crash = diagnose.occt_crash(shape, selected, radius)
    if crash:
        raise C2BlendError(crash, where_all, "radius")
    result, msg = diagnose.rolling_ball(shape, selected, radius)
    if result is None and not shape.isValid():
        raise C2BlendError(diagnose.invalid_input(shape, msg), label)
    if result is None:
        raise C2BlendError(diagnose.rolling_ball_failure(shape, names, radius, msg, label),
                           where_all, "radius")
    t_occt = time.perf_counter() - t0
    fillet_faces = new_faces(shape, result)
    if not fillet_faces:
        raise C2BlendError("radius %g is too small: OCCT's fillet of it cannot be told "
                           "apart from the faces it joins (it lies within %.2g of them, 10 "
                           "times their tolerance); use a larger radius"
                           % (radius, max(off_boundary(f) for f in result.Faces)),
                           where_all, "radius")
    blended, kept = [], []
    rbfs = [RollingBallFace(result, f, fillet_faces) for f in fillet_faces]

    def original(f):  # the face of the input that a face f of OCCT's result lies on
        return recut.original_face(shape, f)
    for r in rbfs:  # OCCT's face between two fillets at a vertex: set back
        if not r.between:
            continue
        try:
            r.setback = sb.Setback(result, r.face, fillet_faces, radius, original)
        except (ValueError, Part.OCCError) as ex:
            r.corner += " (it cannot be set back: %s)" % ex
            arc = diagnose.tight_arc(shape, result, r.face, radius)
            if not arc:
                continue
            try:  # fillets following an edge that curves tighter than their radius
                r.setback = tn.Turn(result, r.face, rbfs, radius, original, arc)
            except (ValueError, Part.OCCError) as ex:
                r.corner += arc + " (nor beyond that edge: %s)" % ex
                continue
        r.patch, r.corner = True, None
    all_chains, patches = chains(rbfs)
    selected = _selected(shape, names, all_chains)
    for chain in all_chains:
        edges = selected.get(id(chain), [])
        where = ", ".join("%s.%s" % (label, n) for n, _ in edges) or \
            _occt_face_at(label, chain.faces[0])
        if chain.corner:
            reason = chain.corner + _tangent_ends(shape, label, edges)
            if any(m.between for m in chain.members):
                reason += diagnose.vertex_hint(shape, names, chain.faces[0], radius)
            kept.append({"where": where, "reason": reason})
            continue
        try:
            new = solve.solve_chain(chain, radius, where, continuity, shape_params, tension,
                                    tol_rel, samples, max_samples, fillet_faces)
        except solve.NotReplaced as ex:
            kept.append({"where": where, "reason": str(ex)})
            continue
        for b in new:
            b.source = chain
        blended += new
    t_solve = None
    measured = {}  # the solid whose continuity was measured, and the measures

    def measure(solid):
        t = time.perf_counter()
        try:
            checks = _measure(solid, blended, filled, result)
        except Exception:  # noqa: BLE001 - measured again once the solid is checked,
            return  # whose findings then explain it first
        measured.update(solid=solid, checks=checks, seconds=time.perf_counter() - t)

    hints = {}  # for corner_hint
    while True:  # a blend that cannot be cut back or cut into its faces is kept as OCCT's
        filled = joined([p for p in patches if assembly.blends_at_corner(p, blended)], all_chains)
        failed = ends.trim(blended, lambda f: recut.original_face(shape, f))
        if not failed:
            t_solve = t_solve or time.perf_counter()
            try:
                if blended:
                    solid, solid_check = assembly.assemble(shape, result, blended,
                                                           fillet_faces, where_all, filled,
                                                           bop, measure)
                else:
                    solid = result.Solids[0] if len(result.Solids) == 1 else result
                    solid_check = assembly.occt_result_check(shape, solid, bop)
                break
            except assembly.Unassembled as ex:
                failed = [(b, str(ex)) for b in ex.blends]
            except Part.OCCError as ex:  # not foreseen: OCCT's solid stands, and says why
                failed = [(b, "OCCT failed while the blends were assembled into the solid "
                           "(%s)" % occt_message(ex)) for b in blended]
        drop = []
        for b, reason in failed:
            if not any(b is x for x in drop):  # with the other runs of its chain, once
                kept.append({"where": b.where, "reason": reason + diagnose.corner_hint(
                    shape, names, selected.get(id(b.source), []), radius, hints)})
                drop += b.group or [b]
        blended = [b for b in blended if not any(b is x for x in drop)]
    t_assemble = time.perf_counter()
    overlapped = measured.get("seconds", 0.0) if measured.get("solid") is solid else 0.0
    if not overlapped:  # not measured while the BOP check ran
        measured.update(solid=solid, checks=_measure(solid, blended, filled, result))
        measured["seconds"] = time.perf_counter() - t_assemble
    checks, corner_checks = measured["checks"]["trimlines"], measured["checks"]["corner_patches"]
    for p in patches:  # not filled: OCCT's corner patch, or its face between two fillets
        if not any(r is x for q in filled for x in q.rbfs for r in p.rbfs):
            kept.append({"where": p.where(), "reason": "OCCT's corner patch, kept with the "
                         "fillets that meet there" if p.setback is None else
                         p.setback.kept + diagnose.vertex_hint(shape, names, p.faces[0],
                                                               radius)})
    report = {
        "continuity": continuity, "radius": radius, "shape_params": list(shape_params),
        "tension": tension,
        "blends": [{"where": b.where, "samples": b.samples, "data_error": b.data_rel,
                    "fit_deviation": b.fit["deviation"], "fit_tolerance": b.fit["tolerance"],
                    "poles": list(b.fit["poles"].shape[:2]),
                    "closed": b.chain.closed, "pointwise": b.group is not None}
                   for b in blended],
        "kept_occt_faces": kept,
        "solid_check": solid_check,
        **measured["checks"],
        "volume": solid.Volume, "occt_volume": result.Volume,
        "tolerance": {**assembly.max_tolerances(solid),
                      **{"occt_" + k: x for k, x in assembly.max_tolerances(result).items()}},
        "seconds": time.perf_counter() - t0, "occt_seconds": t_occt,
        # the continuity check overlaps OCCT's BOP check (in another process): the
        # stages count that time once, in continuity_check
        "stage_seconds": {"occt_fillet": t_occt, "trimlines_solve_fit": t_solve - t0 - t_occt,
                          "sew_and_brepcheck": t_assemble - t_solve - overlapped,
                          "continuity_check": measured["seconds"]},
    }
    creased = [j for j in measured["checks"]["junctions"] if j["g1"] > ck.TOL_G1]
    report["verdict"] = min([c["verdict"] for c in checks + corner_checks + creased]
                            + (["G1"] if kept else []),
                            key=ck.RANK.get) if (checks or kept) else "none"
    return solid, report
