# SPDX-License-Identifier: LGPL-2.1-or-later
"""The blends, the faces cut anew along them (recut.py) and the corner fillings
(corners.py) sewn into one solid, checked by BRepCheck and OCCT's BOP check
(bopcheck.py), and the findings read: which blend or filling a fault lies on (it is then
refused, Unassembled, and fillet() keeps OCCT's faces there), and which findings the
input solid or OCCT's own fillet share (reported, not held against the blends).
"""
import math

import Part

from ..errors import C2BlendError, occt_message
from . import check as ck
from . import bopcheck as bc
from . import corners as cn
from .surface import leaving, only_c0
from . import solve, recut

UNCHECKED = "passes BRepCheck; BOP check skipped (preview)"  # the check line, bop=False
C0_FINDING = "GeomAbs_C0"  # the BOP check's finding on geometry that is only C0
INTERFERENCE = "BOPAlgo SelfIntersect"  # the BOP check's finding on faces that interfere
# the BOP check's self-interference findings, which come and go on faces only C0
# (_c0_unreliable)
C0_UNRELIABLE = (INTERFERENCE, "BOPAlgo OperationAborted")
# two edges of a face's wire leaving a vertex in directions this close (rad) form a cusp
# there, whose tolerance may be raised (_tolerate_cusps) up to CUSP_REACH times the
# shorter edge's length
CUSP = 1e-3
CUSP_REACH = 0.05
CUSP_BISECTIONS = 4  # of the doubling's last step: the least tolerance found to 2^(1/16)
# where the BOP check finds two blends meeting at a mitre interfering, their vertex's
# tolerance may be raised up to this many times the mitre's length
# (_tolerate_mitre_ends): 170 times the longest stretch seen (5.8e-6 of the mitre's
# length), and below the cube root of the fits' accuracy relative to it (3e-8 to 8e-8,
# whose cube roots are 3e-3 to 4e-3)
MITRE_REACH = 1e-3


class Unassembled(Exception):
    """The original faces cannot be cut along these blends (attribute blends); the
    message says why. fillet() keeps OCCT's faces for them and assembles again."""

    def __init__(self, blends, message):
        super().__init__(message)
        self.blends = blends


class _Touched:
    """A face of the original solid that blends touch: orig; tools: the edges lying on
    its surface that bound it anew (blend edges, kept OCCT fillets' edges, legs of
    neighbours' growth regions); inside: those lying on the face itself, or their parts
    that do (parts_along); grown: an (end section, the edge it is or is a part of, corner,
    region) for each region it grows by (_growth, grown_face); legs: those of its and its
    neighbours' growth regions, along which it keeps its corners (cut_face); face: the
    face cut and grown, orig, or where it grows past its boundary and is a planar
    B-spline patch, orig on its plane (recut.extensible); owners:
    the blends concerned; occt: an edge of a fillet kept as OCCT's (or of a corner
    patch) leaves it away from its corners, so only OCCT's faces can take its place."""

    def __init__(self, orig):
        self.orig, self.tools, self.inside, self.grown, self.legs = orig, [], [], [], []
        self.face = orig
        self.owners, self.occt = [], False

    @staticmethod
    def of(touched, orig, blend):
        """The entry of `touched` for face orig (added if new), with blend an owner."""
        t = next((x for x in touched if x.orig.isSame(orig)), None)
        if t is None:
            t = _Touched(orig)
            touched.append(t)
        if not any(blend is x for x in t.owners):
            t.owners.append(blend)
        return t


def assemble(shape, result, blended, fillet_faces, where, patches=(), bop=True,
             meanwhile=None):
    """The solid: the faces of `result` (OCCT's fillet of `shape`) with the replaced
    rolling-ball faces dropped, the blend faces added, and every face of `shape` that a
    blend touches (sides and ends) cut anew along the blends' boundary curves; sewn,
    with the holes left at the corner `patches` (rollingball.CornerPatch, some of whose
    fillets are blended) filled (corners.py), made a solid and checked (bopcheck.py;
    BRepCheck only when bop is False). meanwhile(solid), when given, is called with
    the first solid made while OCCT's BOP check of it runs in another process (the
    solid returned may differ, when a plate filling is remade). Returns (solid, the
    report's line on its check). Raises C2BlendError, or Unassembled for the blends at
    a corner that cannot be filled and for those to which BRepCheck's or the BOP
    check's faults belong (_rejected_faces, _bop_faulty)."""
    diag = shape.BoundBox.DiagonalLength
    tol = 1e-7 * diag
    drop = [f for b in blended for f in b.chain.faces] + [f for p in patches for f in p.faces]
    kept_fillets = [f for f in fillet_faces if not any(f.isSame(d) for d in drop)]
    faces_out = [b.face for b in blended]
    # the original faces the blends touch, with the blend's edges lying on each
    touched = []
    for b in blended:
        near = list(b.chain.sides) + [f for e in b.ends for f in e.faces
                                      if not any(f.isSame(g) for g in e.fillets)]
        for edge in b.face.Edges:
            res_face = recut.face_under(edge, near, solve.ON_FACE * b.fit["tolerance"])
            if res_face is None:
                continue  # a mitre, shared with another blend
            _Touched.of(touched, recut.original_face(shape, res_face), b).tools.append(edge)
    for t in list(touched):
        # edges of OCCT fillets kept, and of corner patches, on this face bound it too;
        # a patch's where they touch it (the two setbacks where a hole cuts a pocket's
        # wall, shapes.hole_through_pocket_wall, have their edges on the wall's plane,
        # each on one of the two faces the hole leaves of it)
        touching = [e for p in patches for e in p.tools
                    if t.orig.distToShape(e)[0] <= max(tol, 10.0 * e.Tolerance)]
        t.tools += [e for e in [e for k in kept_fillets for e in k.Edges] + touching
                    if not e.Degenerated and recut.face_under(e, [t.orig], tol) is not None]
        t.inside += [e for e in t.tools if not any(e is x for x in t.inside)
                     and recut.edge_on_face(e, t.orig, tol)]

        def across(x, f=t.orig):  # the surface beyond f's edge x, as far as it goes
            return next((recut.extended_surface(g, tol)
                         for g in shape.ancestorsOfType(x, Part.Face) if not g.isSame(f)), None)

        def meeting(v, f=t.orig):  # the solid's other faces at f's vertex v
            return [(("face", g.hashCode()), recut.extended_surface(g, tol))
                    for g in shape.ancestorsOfType(v, Part.Face) if not g.isSame(f)]
        beyond = [e for e in t.tools if not any(e is x for x in t.inside)]
        if beyond:  # the face grows past its boundary: a planar patch, as its plane
            t.face = recut.extensible(t.orig, tol)
        for e in beyond:
            parts = recut.parts_along(t.face, e, tol, across, meeting)
            if parts is None:
                own = [b for b in t.owners if any(e.isSame(x) for x in b.face.Edges)]
                if not own:  # an edge of a fillet kept as OCCT's, or of a corner patch
                    t.occt = True  # OCCT's faces may take this one's place (below)
                    continue
                raise Unassembled(own, "an end of its blend leaves face %s of the "
                                  "original solid away from the face's corners"
                                  % ck.element_name(shape, t.orig, "Face"))
            t.inside += parts[0]
            for section, (region, corner, legs) in parts[1]:
                t.grown.append((section, e, corner, region, legs))
                t.legs += legs
                for leg in legs:  # a leg beyond the face's edges cuts the face it crosses
                    if any(recut.edge_on_face(leg, x, tol) for x in t.orig.Edges):
                        continue
                    other = next((f for f in shape.Faces if not f.isSame(t.orig)
                                  and recut.edge_on_face(leg, f, tol)), None)
                    if other is None:
                        raise Unassembled(t.owners, "the region by which its blend's end "
                                          "extends face %s is not bounded by the solid's "
                                          "faces" % ck.element_name(shape, t.orig, "Face"))
                    o = _Touched.of(touched, other, t.owners[0])
                    o.tools.append(leg)
                    o.inside.append(leg)
                    o.legs.append(leg)
    kept = Part.Compound(result.Edges)
    # a seam is no corner, whatever part of it the fillets take: the piece of a cone
    # left between two fillets holds a piece of its seam, none of which OCCT keeps
    sharp = [e for e in shape.Edges if len(ck.edge_faces(shape, e)) == 2
             and not any(e.isSame(r) for r in result.Edges) and recut.is_consumed(e, kept, tol)]
    occt_vertices = result.Vertexes  # for recut.end_gap
    for t in touched:
        try:
            if t.occt:
                raise ValueError("an edge of a fillet kept as OCCT's, or of a corner "
                                 "patch, leaves it away from its corners")
            # trimlines that OCCT's fillet ends at one point of the face are cut
            # as meeting there (recut.end_gap)
            gap = recut.end_gap(t.inside, occt_vertices, tol)
            pieces = recut.cut_face(t.face, t.inside, sharp, t.legs, max(tol, 2.0 * gap))
            if not pieces and _occt_pieces(result, t, drop + kept_fillets, tol):
                # every piece touches an edge the fillets consume, yet OCCT's fillet
                # keeps some of the face (a pocket's wall under a boss, next to fillets
                # kept as OCCT's there: machined seed 10, part 55)
                raise ValueError("no piece of it is kept, where OCCT's fillet keeps some")
            for section, whole, corner, region, legs in t.grown:  # the fillets' end sections
                # extend the face: at each corner, the piece keeping it grows
                k = next((i for i, f in enumerate(pieces) if any(
                    (v.Point - corner).Length <= tol for v in f.Vertexes)), None)
                if k is None:
                    raise ValueError("no piece keeps the corner (%.6g, %.6g, %.6g)"
                                     % tuple(corner))
                pieces[k] = recut.grown_face(pieces[k], section, whole, corner, region, legs, tol)
        except Exception as ex:
            pieces = _occt_pieces(result, t, drop + kept_fillets, tol)
            if pieces is None:
                raise Unassembled(t.owners, "face %s of the original solid cannot be cut "
                                  "along its blend (%s)"
                                  % (ck.element_name(shape, t.orig, "Face"),
                                     occt_message(ex))) from None
        faces_out += pieces
    for f in result.Faces:
        if any(f.isSame(d) for d in drop):
            continue
        if not any(f.isSame(k) for k in kept_fillets) and \
                recut.piece_of(f, [t.orig for t in touched], tol):
            continue  # replaced by the pieces cut from the original face
        faces_out.append(f)
    shells = _sewn(faces_out)
    fills = []  # _Fill per corner patch
    if patches and len(shells) == len(result.Shells):  # fill the holes the blends leave
        holed = [s for s in shells if not s.isClosed()]  # (a void's shell may have some)
        holed = holed[0] if len(holed) == 1 else Part.Compound(holed)
        try:
            loops = cn.holes(holed, patches, 0.5 * min(f.BoundBox.DiagonalLength
                                                       for p in patches for f in p.faces))
        except cn.Unfilled:
            loops = []  # a sewing gap: reported below
        fills = [_Fill(holed, p, loop, blends_at_corner(p, blended))
                 for p, loop in zip(patches, loops)]

    def closed():  # the solid, sewn again with the fillings as they are now
        return _closed(_sewn(faces_out + [f.face for f in fills]) if fills else shells,
                       result, where, blended, tol)
    solid = closed()
    while fills:
        # OCCT's plate filling varies erratically with its input: a filling that
        # BRepCheck rejects once sewn, or whose neighbour it rejects, is remade with the
        # next trial (a blend's face rejected where it meets a filling that changed at
        # the 16th digit of the blend's poles: test_workbench.py,
        # test_a_filling_that_breaks_the_sewn_solid_is_remade)
        redo = _rejected_fills(solid, fills)
        if not redo or not all(f.refill() for f in redo):
            break
        solid = closed()
    first = solid
    overlap = (lambda: meanwhile(first)) if meanwhile else None
    if not bop:
        problems, line = bc.problems(solid, bop=False, meanwhile=overlap), UNCHECKED
    while bop:
        # OCCT's intersection may loop on a plate filling and a blend (seen): their
        # neighbourhoods are checked alongside, and a filling where it is stuck is
        # remade with the next trial
        faces = [patch_face(solid, f.patch) for f in fills]
        try:
            problems = bc.problems(solid, meanwhile=overlap, suspects=faces)
            overlap = None
            if problems and INTERFERENCE in problems and \
                    _tolerate_mitre_ends(solid, blended,
                                         {v.hashCode() for v in result.Vertexes}):
                continue  # checked again
            line = "passes BRepCheck and the BOP check"
            break
        except bc.Unfinished as ex:
            redo = [f for f, g in zip(fills, faces) if any(g.isSame(x) for x in ex.stuck)]
            if not redo or not all(f.refill() for f in redo):
                problems = bc.problems(solid, bop=False)
                line = ("passes BRepCheck, but %s (%s): Boolean operations on this solid "
                        "may not finish either" % (ex, _unfinished_why(redo, faces, solid)))
                break
            solid = closed()
            overlap = None
    orig = _input_problems(shape) if problems else None
    # an input that fails the BOP check for C0 geometry only does not stop the faults
    # that are new being looked for around the blends: they are the fillet's
    c0_input = orig is not None and _input_only_c0(shape, orig)
    unreliable = _c0_unreliable(solid) if orig and C0_FINDING in orig and bop and \
        _unreliable_count(problems) else []
    inherited = _inherited(problems, orig, solid, unreliable) if problems else None
    if inherited:
        problems, line = None, inherited
    blocks = orig if not c0_input else None
    kept = _input_faults_kept(problems, orig, solid, shape, tol) if problems and blocks \
        and bop else None
    if kept:
        problems, line = None, kept
    rejected = _rejected_faces(solid, blended, fills, shape) if problems else []
    if rejected:
        # FreeCAD's message then lists its faces' own statuses ("No error"), not those
        # in their context that failed
        problems = "BRepCheck rejects %s" % ", ".join(name for name, _ in rejected)
        # blame the blends and fillings rejected themselves, else those next to a
        # rejected face (a face cut along several blends would blame them all)
        own = [near for name, near in rejected if not name.startswith("face ")]
        at = [b for b in blended if any(b is x for near in own or [n for _, n in rejected]
                                        for x in near)]
        if at and not blocks:
            raise Unassembled(at, "the solid sewn with its blend is not valid: %s"
                              % problems)
    elif problems and bop and not blocks:
        # BRepCheck passes: the BOP check's findings (which name no face) are looked
        # for around each blend and filling, but for the C0 faces of a C0 input and
        # the self-interference findings of the faces where they are unreliable
        def ignore(near, finding):
            return c0_input and (finding.endswith(C0_FINDING) or (
                finding.endswith(C0_UNRELIABLE)
                and any(f.isSame(u) for f in near.Faces for u, _ in unreliable)))
        at = _bop_faulty(solid, blended, fills, ignore)
        if at:
            raise Unassembled(at, "OCCT's BOP check of the solid sewn with its blend "
                              "finds, around it: %s" % problems)
        line = _as_occt_fillet(problems, solid, result)
        if line:
            problems = None
    if problems:
        msg = ("the filleted solid is not valid after sewing (BRepCheck and BOP check: %s)"
               % problems)
        if orig:
            msg += ("; the input solid already fails that check (%s), so repair or "
                    "rebuild it first" % orig)
        raise C2BlendError(msg, where, "validity")
    return solid, line


def _occt_pieces(result, touched, skip, tol):
    """The faces of `result` (OCCT's fillet) that lie on touched.orig, a face the blends
    touch, none of `skip` (the rolling-ball faces replaced, and OCCT's fillets kept):
    they take that face's place when it cannot be cut, if every edge bounding it anew
    (touched.tools) lies on their edges. A blend's trimline is the exact contact, which
    OCCT's fillet has too where its face is a cylinder or a torus (between planes, or a
    plane and a coaxial cylinder or cone), so there a face that only blends' sides
    touch is OCCT's own where its cut fails; elsewhere the edges' test refuses it. The
    case: a block's top face, cut along one edge's blend and the fillets kept where a
    pocket's convex rim and concave corner meet (OCCT's face between them, a
    mixed-convexity vertex), had no piece keeping the pocket's corner. Where a blend
    ends on the face, its end section is not OCCT's: None."""
    faces = [f for f in result.Faces if not any(f.isSame(x) for x in skip)
             and recut.piece_of(f, [touched.orig], tol)]
    if not faces:
        return None
    edges = Part.Compound([e for f in faces for e in f.Edges])
    if all(edges.distToShape(Part.Vertex(p))[0] <= tol for e in touched.tools
           for p in recut.edge_points(e, (0.0, 0.25, 0.5, 0.75, 1.0))):
        return faces
    return None


def _rejected_faces(solid, blended, fills, shape=None):
    """The faces of `solid` that BRepCheck rejects (in their own context: edges and
    pcurves that do not fit their surface, wires that do not close), each as (what it
    is, for messages: 'the blend face of ...', 'the plate filling of ...' or 'face
    FaceN of the filleted solid', followed by ', on FaceM of the input' where `shape`,
    the input solid, is given, since the filleted solid is not returned then; the
    blends of `blended` it belongs to: the blend whose face it is, those ending at the
    corner it fills, or those sharing an edge with it)."""
    out = []
    mine = [(b, blend_face(solid, b)) for b in blended]
    for f in solid.Faces:
        if f.isValid():
            continue
        own = next((b for b, g in mine if g.isSame(f)), None)
        fill = next((x for x in fills if patch_face(solid, x.patch).isSame(f)), None)
        if own is not None:
            out.append(("the blend face of %s" % own.where, [own]))
        elif fill is not None:
            out.append(("the plate filling of the %s" % fill.patch.where(),
                        blends_at_corner(fill.patch, blended)))
        else:
            on = "" if shape is None else ", on %s of the input" % ck.element_name(
                shape, recut.original_face(shape, f), "Face")
            out.append(("face %s of the filleted solid%s" % (ck.element_name(solid, f, "Face"),
                                                            on),
                        [b for b, g in mine
                         if any(e.isSame(x) for e in g.Edges for x in f.Edges)]))
    return out


def _rejected_fills(solid, fills):
    """The fillings of `fills` whose face in `solid` shares an edge with a face that
    BRepCheck rejects, or is one (a face shares all its edges with itself)."""
    edges = [e for f in solid.Faces if not f.isValid() for e in f.Edges]
    return [x for x in fills if edges and any(
        e.isSame(d) for e in patch_face(solid, x.patch).Edges for d in edges)]


def _bop_faulty(solid, blended, fills, ignore=None):
    """The blends of `blended` in whose neighbourhood in `solid` (the blend face, or
    the plate filling at its corner, with the faces next to it) OCCT's BOP check finds
    something wrong (bopcheck.faulty), but for findings that ignore(neighbourhood,
    finding) passes."""
    faces = [blend_face(solid, b) for b in blended]
    fill_faces = [patch_face(solid, f.patch) for f in fills]
    bad = bc.faulty(solid, faces + fill_faces, bc.NEAR_LIMIT, ignore)
    at = [b for b, g in zip(blended, faces) if any(g.isSame(x) for x in bad)]
    for f, g in zip(fills, fill_faces):
        if any(g.isSame(x) for x in bad):
            at += [b for b in blends_at_corner(f.patch, blended) if not any(b is x for x in at)]
    return at


def _inherited(problems, orig, solid, unreliable=()):
    """The report's line when the BOP check's only findings (`problems`) are faces or
    edges whose geometry is only C0 (GeomAbs_C0), the input solid has such geometry
    too (`orig`, its findings: B-spline faces with knots of full multiplicity, as after
    toNurbs()) and BRepCheck passes: those are the input's faces, cut anew but the
    same surfaces, not a defect of the fillet. Self-interference findings count as
    such too, up to as many as the faces `unreliable` (_c0_unreliable) have alone.
    None otherwise."""
    if not orig or C0_FINDING not in orig or bc.problems(solid, bop=False):
        return None
    flaky = _unreliable_count(problems)
    if not _only_c0(problems, (C0_FINDING,) + C0_UNRELIABLE) or \
            flaky > sum(n for _, n in unreliable):
        return None
    c0 = "; ".join(f for f in problems.split("; ") if C0_FINDING in f)
    line = ("passes BRepCheck; the BOP check finds geometry that is only C0 (%s), as in "
            "the input solid (%s)" % (c0, orig))
    if flaky:
        line += ("; its self-interference test also reports %s on %s, only C0 like the "
                 "input's face, whose edges do not interfere and whose boundary BRepCheck "
                 "accepts: on faces only C0 that test is unreliable (it reports the same "
                 "on plane cuts of such faces)"
                 % ("; ".join(f for f in problems.split("; ") if C0_FINDING not in f),
                    ", ".join("face %s" % ck.element_name(solid, f, "Face")
                              for f, _ in unreliable)))
    return line + ": Boolean operations on those faces may fail"


def _input_faults_kept(problems, orig, solid, shape, tol):
    """The report's line when the input solid `shape` fails the BOP check beyond C0
    geometry (`orig`, its findings) and the filleted solid's findings (`problems`) are
    the input's, kept: BRepCheck passes; no kind of finding is more frequent than on
    the input (but C0 geometry, where the input has it: faces cut anew multiply it);
    every kind beyond C0 is found on faces checked alone; and each such face is a
    piece of an input face that the check, alone, finds faulty too (so no blend or
    plate filling is). The case: a block made B-splines whose face's edge curves lie
    off it between BRepCheck's samples (BOPAlgo_InvalidCurveOnSurface), which OCCT's
    own fillet keeps too (shapes.off_curve_block). None otherwise: the fillet's error
    then names the input's findings."""
    if bc.problems(solid, bop=False) is not None:
        return None
    theirs, c0 = _counts(orig), C0_FINDING in orig
    mine = {k: n for k, n in _counts(problems).items() if not (c0 and k.endswith(C0_FINDING))}
    if any(n > theirs.get(k, 0) for k, n in mine.items()):
        return None
    try:
        faulty = [f for f in shape.Faces if _faults_alone(f)]
        kept = [(f, k) for f, k in ((f, _faults_alone(f)) for f in solid.Faces) if k]
    except bc.Unfinished:
        return None
    if not kept or not all(recut.piece_of(f, faulty, tol) for f, _ in kept) or \
            not set(mine) <= {x for _, k in kept for x in k}:
        return None
    return ("passes BRepCheck; the BOP check finds %s, as in the input solid (%s): "
            "beyond C0 geometry, on faces kept from its %s, which the check finds "
            "faulty alone too: repair the input for Boolean operations on them"
            % (problems, orig, ", ".join(ck.element_name(shape, f, "Face") for f in faulty)))


def _faults_alone(face):
    """The kinds of finding beyond C0 geometry (as in _counts) of the BOP check of
    `face` alone. Raises bopcheck.Unfinished."""
    found = bc.problems(face, bc.NEAR_LIMIT)
    return [k for k in _counts(found) if not k.endswith(C0_FINDING)] if found else []


def _as_occt_fillet(problems, solid, result):
    """The report's line when BRepCheck passes on `solid` and the BOP check's findings
    (`problems`, none of them around a blend or plate filling: _bop_faulty) are no
    more, of each kind, than on OCCT's own fillet `result` of the same edges, which
    FreeCAD's Fillet returns: they lie in what the solid keeps of OCCT's fillet (tiny
    edges and self-intersecting vertices where two arcs of crossing slots are filleted
    at R = 0.03, shapes.three_slots), and that fillet would have them too. None
    otherwise, and when OCCT's fillet passes or its check does not finish."""
    if bc.problems(solid, bop=False) is not None:
        return None
    try:
        occt = bc.problems(result)
    except bc.Unfinished:
        return None
    if occt is None:
        return None
    theirs = _counts(occt)
    if any(n > theirs.get(f, 0) for f, n in _counts(problems).items()):
        return None
    return ("passes BRepCheck; the BOP check finds %s, as it does on OCCT's own fillet of "
            "these edges (FreeCAD's Fillet gives the same: %s), and none of it around a "
            "blend or plate filling (each checked with the faces next to it): Boolean "
            "operations on it may fail" % (problems, occt))


def _counts(findings):
    """{finding: count} of a problems line (bopcheck.problems)."""
    out = {}
    for f in findings.split("; "):
        text, _, n = f.rpartition(" (")
        if text and n.endswith(")") and n[:-1].isdigit():
            out[text] = out.get(text, 0) + int(n[:-1])
        else:
            out[f] = out.get(f, 0) + 1
    return out


def _unreliable_count(findings):
    """How many of the findings of a problems line are self-interference findings
    (C0_UNRELIABLE)."""
    return sum(n for f, n in _counts(findings).items() if f.endswith(C0_UNRELIABLE))


def _only_c0(findings, kinds=(C0_FINDING,)):
    """True when every finding of a problems line (bopcheck.problems) is on geometry
    that is only C0 (or, with `kinds`, ends with one of those)."""
    return all(f.endswith(tuple(kinds)) for f in _counts(findings))


def _input_only_c0(shape, findings):
    """True when the BOP check's `findings` on `shape` (a problems line) are geometry
    only C0 and, no more often than _c0_unreliable finds it on shape's faces, self-
    interference on faces only C0 (a toNurbs() sphere through a plate gets it)."""
    if C0_FINDING not in findings or \
            not _only_c0(findings, C0_UNRELIABLE + (C0_FINDING,)):
        return False
    flaky = _unreliable_count(findings)
    return not flaky or flaky <= sum(n for _, n in _c0_unreliable(shape))


def _c0_unreliable(solid):
    """[(face, count)]: the B-spline faces of `solid` on which, checked alone, the BOP
    check finds geometry that is only C0 and self-interference (C0_UNRELIABLE, count
    such findings) but nothing else, whose edges checked together show no
    interference, and which BRepCheck accepts (it tests the boundary's self-
    intersection in the face's parameters). On such faces OCCT 7.6's
    self-interference test is unreliable: the surface of FreeCAD's Part Ellipsoid
    (6 x 3 x 3, a rational B-spline with double knots) cut by the plane z = c with
    OCCT's own Boolean gets SelfIntersect at c = -2, 0, 2 and 2.5 and nothing at -1,
    0.2 to 1.5; a toNurbs() sphere r = 5 about z = 7 gets it at 5.5 to 9 and not at
    3 to 5.2 (tests/freecad: test_a_part_ellipsoid_on_a_plate_is_g2 and the test
    before it). A region bounded by a plane section cannot intersect itself."""
    out = []
    for f in solid.Faces:
        if not only_c0(f):  # no other face gets GeomAbs_C0: not worth a check
            continue
        try:
            found = bc.problems(f, bc.NEAR_LIMIT)
            if found is None or C0_FINDING not in found or \
                    not _only_c0(found, C0_UNRELIABLE + (C0_FINDING,)):
                continue
            count = _unreliable_count(found)
            edges = bc.problems(Part.Compound(f.Edges), bc.NEAR_LIMIT)
        except bc.Unfinished:
            continue
        if count and (edges is None or _only_c0(edges)) and f.isValid():
            out.append((f, count))
    return out


class _Fill:
    """The plate filling (face) of a corner patch's hole (edges loop of the open
    shell), with the trials tried (corners.fill). Raises Unassembled for
    `blends`, those ending there, when the hole cannot be filled."""

    def __init__(self, shell, patch, loop, blends):
        self.shell, self.patch, self.loop = shell, patch, loop
        self.tried, self.face, self.error = [], None, None
        if not self.refill():
            raise Unassembled(blends, "the %s cannot be replaced: %s"
                              % (patch.where(), self.error))

    def refill(self):
        """Fill again with the trials not yet tried; False when none is left or none
        gives a face (error says why)."""
        left = [t for t in cn.TRIALS if t not in self.tried]
        if not left:
            return False
        try:
            self.face, trial = cn.fill(self.shell, self.loop, self.patch.guide, left,
                                       self.patch.creases)
        except cn.Unfilled as ex:
            self.error = str(ex)
            return False
        self.tried.append(trial)
        return True


def _closed(shells, result, where, blended, fuzzy):
    """The solid bounded by the closed shells of `shells`, as many as `result` (OCCT's
    fillet) has: the outer one facing outwards, those of voids inwards, with the
    tolerance of each edge not in `result` (OCCT's fillet) raised to its pcurves'
    deviation, and of its vertices to the gaps up to `fuzzy` (the faces' cut's) that
    the cut leaves there (update_tolerances). A sewing that left free edges raises
    Unassembled for the blends (of `blended`) those edges touch, which are then kept as
    OCCT's, or C2BlendError when they touch none."""
    if len(shells) != len(result.Shells) or not all(s.isClosed() for s in shells):
        free = [e for s in shells for e in s.Edges
                if len(s.ancestorsOfType(e, Part.Face)) == 1
                and not e.isSeam(s.ancestorsOfType(e, Part.Face)[0])]
        sewn = Part.Compound(shells)

        def unsewn(b):  # left out of every shell, or next to a free edge
            tol = solve.ON_FACE * b.fit["tolerance"]
            return sewn.isNull() or sewn.distToShape(Part.Vertex(b.probe))[0] > tol or \
                any(b.face.distToShape(e)[0] <= tol for e in free)
        at = [b for b in blended if unsewn(b)]
        if at:
            raise Unassembled(at, "sewing its blend to the faces it meets left %d free "
                              "edge(s) (gaps wider than the sewing tolerance), or the "
                              "blend outside the shell" % len(free))
        raise C2BlendError("sewing the blend faces to the solid failed: %d shell(s), %d free "
                           "edge(s) left (gaps wider than the sewing tolerance)"
                           % (len(shells), len(free)), where, "sewing")
    solids = [_outwards(s) for s in shells]
    solid = max(solids, key=lambda s: s.Volume)  # the outer shell's, around every void
    if len(solids) > 1:
        solid = Part.makeSolid(Part.Compound(
            [solid.Shells[0]] + [s.Shells[0].reversed() for s in solids if s is not solid]))
    # every edge that cutting or sewing made anew (those of OCCT's result are as they
    # were): the blends' edges, and an original face's other edges, rebuilt by the cut
    # (a cylinder's second hole opening kept 1.5e-7 against its pcurve's 2e-7)
    old = {e.hashCode() for e in result.Edges}
    recut.update_tolerances([e for e in solid.Edges if e.hashCode() not in old], fuzzy)
    _tolerate_cusps(solid, {v.hashCode() for v in result.Vertexes})
    return solid


def _outwards(shell):
    """The solid that the closed `shell` bounds, its faces pointing outwards."""
    solid = Part.Solid(shell)
    if solid.Orientation == "Reversed" or solid.Volume < 0:
        # the sewn faces point inwards and Part.Solid only flagged the solid reversed
        # around them; OCCT's fillet and chamfer of such a solid give an inside-out,
        # invalid one. Reverse the faces themselves instead.
        solid = Part.Solid(Part.Shell([f.reversed() for f in shell.Faces]))
    return solid


def max_tolerances(shape):
    """{"vertex": the largest tolerance of shape's vertices, "edge": of its edges}."""
    return {"vertex": max(v.Tolerance for v in shape.Vertexes),
            "edge": max(e.Tolerance for e in shape.Edges)}


def _tolerate_cusps(solid, keep=frozenset()):
    """Raise the tolerance of the vertices at the cusps (_cusps) of each face of `solid`
    that BRepCheck rejects, together, doubling from 1e-6 until it passes, then bisecting
    the last step for the least that does (CUSP_BISECTIONS), each up to CUSP_REACH times
    the shorter of its two edges (else they are left as they were).
    Vertices whose hashCode is in `keep` (OCCT's result's, which it shares with the
    input) are left alone: the input is not modified.
    A concave fillet's end section in the face it ends on is tangent there to that
    face's edge along the other side, and the face it grows meets itself at that point
    at a cusp. A G2 blend's section leaves that edge as d^3 (a G1 one as d^2), so it runs
    within the edges' tolerance of it for a while, and BRepCheck takes the wire for
    self-intersecting unless the vertex's tolerance covers that stretch. Where the face
    cuts the fillet at a shallow angle, the section is stretched and the stretch long:
    the top and bottom faces of the 3-turn helical ridge's cylinder, where the junction
    climbs at 0.064 (pitch 4 on a circumference of 62.8), need 2.5e-3 (R = 0.3; OCCT's
    own G1 fillet there has 1.1e-4 to 1.3e-4; the doubling alone gave 4.1e-3)."""
    if solid.isValid():
        return
    for f in solid.Faces:
        if f.isValid():
            continue
        cusps = [(v, cap) for v, cap in _cusps(f) if v.hashCode() not in keep]
        start = [v.Tolerance for v, _ in cusps]

        def set_to(t):  # the cusps' tolerances t (within their caps), or as they were
            for (v, cap), t0 in zip(cusps, start):
                v.fixTolerance(max(min(t, cap), t0))
        if not cusps or _least_passing(set_to, f.isValid, 1e-6,
                                       lambda t: any(t < cap for _, cap in cusps)) is None:
            set_to(0.0)


def _tolerate_mitre_ends(solid, blended, keep=frozenset()):
    """Where OCCT's BOP check finds the faces in `solid` of two blends of `blended`
    that meet at a mitre (an edge they share) interfering, raise the tolerance of a
    vertex at an end of the mitre, one after the other, doubling it until the check of
    the two faces passes, up to MITRE_REACH times the mitre's length, then bisecting
    the last step for the least that does (CUSP_BISECTIONS); else leave it as it was.
    Vertices whose hashCode is in `keep` (OCCT's result's, shared with the input) are
    left alone. Returns whether any tolerance was raised.
    Two blends meet at a mitre along their intersection. At its end on a face that
    both touch, both are tangent to that face, and to each other, to second order (G2
    contact): there their intersection is defined only to the cube root of the fits'
    accuracy, and the BOP check may find the faces meeting on beyond the vertex. The
    cases (`tools/fillet_survey.py --random-edges 20 --seed 90 --splines`): part 10, a
    step, 13 of its edges at R = 2.146: the vertex's tolerance 1.2e-7, passing from
    4e-6 on (with 7 of those edges, the faces met 2.4e-5 beyond it;
    test_blends_meeting_beyond_their_mitre_have_its_end_tolerated); part 11, an
    octagonal prism, 14 edges at R = 1.714: a vertical edge's blend and a bottom
    edge's, the vertex's tolerance 1.3e-6, passing from 1e-5 on."""
    faces = [blend_face(solid, b) for b in blended]
    raised = False
    for i, a in enumerate(faces):
        for b in faces[i + 1:]:
            mitres = [e for e in a.Edges if any(e.isSame(x) for x in b.Edges)]
            if not mitres:
                continue
            pair = Part.Compound([a, b])  # sharing solid's vertices: raised there too

            def passes():
                try:
                    return bc.problems(pair, seconds=bc.NEAR_LIMIT) is None
                except bc.Unfinished:
                    return False
            cap = MITRE_REACH * min(e.Length for e in mitres)
            ends = [v for e in mitres for v in e.Vertexes if v.hashCode() not in keep]
            for v in ends:
                if passes():
                    break
                t0 = v.Tolerance
                if _least_passing(v.fixTolerance, passes, t0,
                                  lambda t: 2.0 * t <= cap) is None:
                    v.fixTolerance(t0)
                else:
                    raised = True
    return raised


def _least_passing(set_to, passes, t, more):
    """The least tolerance for which passes() holds once set_to(it) has set it, left
    set: from t, doubled while more(t) until it passes, then the last step bisected
    (CUSP_BISECTIONS) for the least that does, to 2^(1/16). None where none passes
    before more(t) fails; the last one tried is then left set."""
    def at(x):
        set_to(x)
        return passes()
    while more(t):
        t *= 2.0
        if at(t):  # the least that passes lies in (t / 2, t]
            lo = 0.5 * t
            for _ in range(CUSP_BISECTIONS):
                mid = math.sqrt(lo * t)
                lo, t = (lo, mid) if at(mid) else (mid, t)
            set_to(t)
            return t
    return None


def _cusps(face):
    """[(vertex, largest tolerance allowed there)] for each vertex of face's wires where
    two consecutive edges leave it in directions within CUSP of each other."""
    out = []
    for w in face.Wires:
        es = [e for e in w.OrderedEdges if not e.Degenerated]
        for a, b in zip(es, es[1:] + es[:1]):
            shared = [v for v in a.Vertexes if any(v.isSame(x) for x in b.Vertexes)]
            if len(shared) != 1 or a.isSame(b):
                continue
            v = shared[0]
            try:
                da, db = leaving(a, v.Point), leaving(b, v.Point)
            except Exception:  # noqa: BLE001 - OCCT's: no tangent there, no cusp found
                continue
            if da.getAngle(db) < CUSP:
                out.append((v, CUSP_REACH * min(a.Length, b.Length)))
    return out


def _sewn(faces):
    """The shells of `faces` sewn together."""
    sewn = Part.Compound(faces)
    sewn.sewShape()
    return sewn.Shells if sewn.ShapeType != "Shell" else [sewn]


def blends_at_corner(patch, blended):
    """The blends of `blended` that replace fillets ending at the corner patch."""
    return [b for b in blended if any(b.source is c for c in patch.chains)]


def patch_face(solid, patch):
    """The face of `solid` that fills the hole at the corner patch: the face nearest to
    a point of the patch (of its first face) near its centre."""
    face = patch.faces[0]
    return _nearest_face(solid, face.Surface.value(*face.Surface.parameter(face.CenterOfMass)))


def _nearest_face(solid, point):
    """The face of solid nearest to point (on or next to it): among the faces whose
    bounding box, grown by a millionth of the solid's, holds the point (all faces if
    none does), which spares the distance to most faces of a large solid."""
    grow = 1e-6 * solid.BoundBox.DiagonalLength
    near = []
    for f in solid.Faces:
        box = f.BoundBox  # a copy
        box.enlarge(grow)
        if box.isInside(point):
            near.append(f)
    vertex = Part.Vertex(point)
    return min(near or solid.Faces, key=lambda f: f.distToShape(vertex)[0])


def _unfinished_why(stuck, faces, solid):
    """Why the BOP check of `solid`, with plate fillings `faces`, did not finish, as far as
    is known: the fillings `stuck` (each tried with every trial) where the check of
    their neighbourhood does not finish either; where there are none, but fillings, the
    check of each one's neighbourhood finished (bopcheck._watched checks them all), so
    the whole is slow, or loops elsewhere. A prism with 15 edges filleted at R = 1.954
    and 10 corners filled (tools/fillet_survey.py --random-edges 40 --seed 19 --turned,
    part 36) took 53 s of processor time to pass, its fillings' neighbourhoods 2 to
    10 s each."""
    if stuck:
        return ("it loops on faces tangent along an edge, at the %s, with every plate "
                "filling tried" % ", ".join(f.patch.where() for f in stuck))
    if faces:
        return ("the neighbourhood of each of its %d plate filling(s) passes it within "
                "%.0f s: it is slow on this solid's %d faces, or loops on two faces tangent "
                "along an edge elsewhere" % (len(faces), bc.NEAR_LIMIT, len(solid.Faces)))
    return "it loops on faces tangent along an edge, or is slow on this solid"


def occt_result_check(shape, result, bop=True):
    """The report's line on a solid returned as OCCT's fillet made it (every chain kept):
    isValid() holds (rolling_ball), but OCCT's own fillet is not checked further, and
    can fail the BOP argument check that C2Blend's own solids pass (not run when bop is
    False)."""
    if not bop:
        return "OCCT's rolling-ball solid, unchanged: passes isValid(); BOP check skipped"
    try:
        problems = bc.problems(result)
    except bc.Unfinished as ex:
        return ("OCCT's rolling-ball solid, unchanged: it passes isValid(), but %s"
                % ex)
    if problems is None:
        return "OCCT's rolling-ball solid, unchanged: passes BRepCheck and the BOP check"
    orig = _input_problems(shape)
    return ("OCCT's rolling-ball solid, unchanged (FreeCAD's Fillet gives the same): it "
            "passes isValid(), but the BOP check finds: %s%s; Boolean operations on it "
            "may fail" % (problems, "" if orig is None else " (in the input solid: %s)" % orig))


def _input_problems(shape):
    """What the BOP check finds wrong with the input solid (bopcheck.problems), None
    also when the check does not finish."""
    try:
        return bc.problems(shape)
    except bc.Unfinished:
        return None


def blend_face(solid, b):
    """The face of solid made from blend b (sewing keeps the surface, not the face)."""
    return _nearest_face(solid, b.probe)
