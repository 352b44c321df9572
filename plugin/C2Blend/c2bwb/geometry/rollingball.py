# SPDX-License-Identifier: LGPL-2.1-or-later
"""The topology of OCCT's rolling-ball fillet: which faces a blend replaces.

OCCT's fillet (BRepFilletAPI_MakeFillet, via Shape.makeFillet) gives, for each filleted
edge, a face whose two contact edges lie on the adjacent faces and whose cross-sections
(iso-curves across) join corresponding points. OCCT makes one such face per edge of a
tangent chain and splits closed edges at seams; faces that join each other tangentially
across a cross-section form one chain (FilletChain), which becomes one blend. This
module finds those faces in the result, classifies their edges and orders the chains;
contact.py traces the exact contact along a chain, with its faces as the guide.
"""
import Part

from .surface import angle, domain_distance, frame_at_point, off_surface, winds

TANGENT_ANGLE = 1e-3  # rad: a contact edge joins its faces tangentially
ON_SURFACE = 1e-7  # relative: a face of OCCT's result lies on an original surface


def interior_points(face, n=4):
    """Points of the face on an n x n grid of its parameter range, inside its domain and
    off its boundary (a regular hexagon's centre row of the grid runs through two of its
    vertices: such a point also lies on the neighbouring faces)."""
    u0, u1, v0, v1 = face.ParameterRange
    boundary = Part.Compound(face.Edges)
    tol = 1e-6 * face.BoundBox.DiagonalLength
    out = []
    for i in range(1, n + 1):
        for j in range(1, n + 1):
            u = u0 + (u1 - u0) * (i - 0.5) / n
            v = v0 + (v1 - v0) * (j - 0.5) / n
            if face.isPartOfDomain(u, v):
                p = Part.Vertex(face.Surface.value(u, v))
                if boundary.distToShape(p)[0] > tol:
                    out.append(p.Point)
    return out


def off_boundary(face):
    """How far (model units) a face of OCCT's result must leave the original solid's
    boundary to be a new face: 10 times its tolerance, at least 1e-6."""
    return 10.0 * max(face.Tolerance, 1e-7)


def new_faces(original, result):
    """Faces of `result` that do not lie on the boundary of `original` (the fillets):
    some interior point is farther than off_boundary from every original face (by
    OCCT's distance, then, where that is farther, by domain_distance from the original
    faces that wind round their surface's seam: see face_distance, OCCT puts a
    cylinder's face between the turns of a helical ridge away from most of it), or
    no original face's surface holds them all (on_surface). OCCT keeps the surface of
    each face it trims; where its fillet is coarse, a face it makes may lie within
    off_boundary of the original ones (a slot's floor fillet, R = 0.099, meeting a side
    hole: OCCT's 0.02-square face between it and the hole's rim fillet has tolerance
    0.041 and lies 0.006 to 0.038 off the hole's wall)."""
    boundary = Part.Compound(original.Faces)
    winding = [g for g in original.Faces if winds(g)]
    out = []
    for f in result.Faces:
        if any(f.isSame(g) for g in original.Faces):
            continue
        tol = off_boundary(f)
        inside = interior_points(f)
        off = any(boundary.distToShape(Part.Vertex(p))[0] > tol
                  and all(domain_distance(g, p) > tol for g in winding) for p in inside)
        if off and any(_extends(g, inside, tol) for g in original.Faces):
            continue
        if off or not any(on_surface(g, inside) for g in original.Faces):
            out.append(f)
    return out


def _extends(face, points, tol):
    """True when `points` (inside a face of OCCT's result) all lie on face's surface and
    one of them on face itself (within tol): that face of the result is an original one
    trimmed and extended, as a pocket's wall where a fillet of the rim's edge beside it
    ends in that wall (its end section cut out of the wall, below the old top)."""
    if not _on_surface_of(face.Surface, points):
        return False
    try:
        return any(face.distToShape(Part.Vertex(p))[0] <= tol for p in points)
    except RuntimeError:  # FreeCAD and OCCT errors derive from it
        return False


def on_surface(face, points):
    """True when every one of `points` lies within face's bounding box (enlarged by
    ON_SURFACE relative) and on its surface (_on_surface_of)."""
    box = face.BoundBox
    box.enlarge(ON_SURFACE * (1.0 + box.DiagonalLength))
    return all(box.isInside(p) for p in points) and _on_surface_of(face.Surface, points)


def _on_surface_of(surface, points):
    """True when every one of `points` lies on `surface`: within ON_SURFACE of its
    projection there, relative to the point's size (1 + its largest coordinate)."""
    try:
        return all(off_surface(surface, p) <= ON_SURFACE * (1.0 + max(map(abs, p)))
                   for p in points)
    except RuntimeError:  # no projection (FreeCAD and OCCT errors derive from it)
        return False


def _unique_edges(face):
    out = []
    for e in face.Edges:
        if not any(e.isSame(o) for o in out):
            out.append(e)
    return out


def midpoint(edge):
    """The point of edge at the middle of its parameter range."""
    return edge.valueAt(0.5 * (edge.FirstParameter + edge.LastParameter))


def snap(c, lo, hi, period=None):
    """Parameter c brought to [lo, hi]: projections onto a periodic surface may return it
    a period away (on the seam, 0 for 2 pi), so the copy c + k period nearest to
    [lo, hi] is taken; then the end of [lo, hi] it lies within 1e-6 (relative) of, for
    a rounding off the end."""
    if period:
        c = min((c + k * period for k in (-1, 0, 1)), key=lambda x: max(lo - x, x - hi, 0.0))
    end = min((lo, hi), key=lambda x: abs(x - c))
    return end if abs(end - c) < 1e-6 * (1 + abs(hi - lo)) else c


def period(surface, k):
    """The period of the surface's parameter k (0: u, 1: v), or None."""
    if k == 0:
        return surface.UPeriod() if surface.isUPeriodic() else None
    return surface.VPeriod() if surface.isVPeriodic() else None


class RollingBallFace:
    """One rolling-ball face and its surroundings.

    Attributes: face; contacts: [(edge, neighbour face), (edge, neighbour face)];
    ends: [(edge, neighbour face)] (empty for a closed fillet): faces met at an angle,
    end faces of the solid or other fillets (mitres);
    links: [(edge, fillet face)], tangent joins to other rolling-ball faces of a chain;
    corners: [(edge, corner patch)], tangent joins to corner patches (chains(); the
    patch's RollingBallFace);
    corner: None, or a string saying why the face cannot be replaced (corner patch).
    between: True for OCCT's face between two or more fillets that it meets at an angle
    (where a concave and a convex fillet meet at a vertex whose third edge is not
    filleted); setback: where fillet.py sets that corner back (setback.Setback), which
    makes the face a corner patch, replaced by a filling, and its fillets' ends there
    its corners.
    patch: True for a corner patch: a face with two or more tangent joins to other
    rolling-ball faces but not two contacts (where three fillets meet at a vertex);
    touches: a corner patch's faces of the solid (not fillets) that share a vertex
    with it, [] for a fillet.
    along: 0 or 1, the surface parameter along the fillet; range: its range on the face;
    across: (c1, c2), the across-parameters of the two contacts.
    """

    def __init__(self, result, face, fillet_faces):
        self.face = face
        self.surface = face.Surface  # kept: getting it costs as much as an evaluation
        self.contacts, self.ends, self.links, self.corners = [], [], [], []
        self.corner = None
        self.between = False
        self.setback = None  # setback.Setback or turn.Turn: fillet.py makes this a patch
        met = 0  # fillets met at an angle
        for e in _unique_edges(face):
            nbrs = [f for f in result.ancestorsOfType(e, Part.Face) if not f.isSame(face)]
            if not nbrs:  # a seam
                continue
            nb = nbrs[0]
            p = midpoint(e)
            tangent = angle(frame_at_point(face, p).n, frame_at_point(nb, p).n) < TANGENT_ANGLE
            is_fillet = any(nb.isSame(g) for g in fillet_faces)
            if is_fillet and tangent:
                self.links.append((e, nb))
            elif tangent:
                self.contacts.append((e, nb))
            else:  # an end face, or another fillet met at an angle (a mitre)
                self.ends.append((e, nb))
                met += 1 if is_fillet else 0
        self.patch = len(self.contacts) != 2 and len(self.links) >= 2
        # a corner patch's faces of the solid (not fillets) that it touches at a vertex:
        # where three fillets meet, the ball touching all three faces ends each fillet
        self.touches = []
        if self.patch:
            for v in face.Vertexes:
                for f in result.ancestorsOfType(v, Part.Face):
                    if not any(f.isSame(g) for g in fillet_faces + self.touches):
                        self.touches.append(f)
        if self.corner is None and len(self.contacts) != 2 and met >= 2 and not self.patch:
            self.between = True
            self.corner = ("it is OCCT's face between %d fillets at a vertex, which it "
                           "meets at an angle, not tangent: no corner patch that a filling "
                           "replaces, so the fillets there are kept with it" % met)
        if self.corner is None and len(self.contacts) != 2:
            self.corner = ("it has %d tangent contact edges instead of 2 (a corner "
                           "patch, or a fillet that uses up a whole face)"
                           % len(self.contacts))
        if self.corner is None:
            self.corner = next(("it meets another fillet along a contact edge (a corner patch)"
                                for e, _ in self.links if any(e.isSame(c) for c, _ in self.contacts)), None)
        if self.corner is None:
            self._orient()

    def _orient(self):
        """along: the surface parameter whose derivative carries the contact edge's
        tangent (from derivatives, not from two points' parameters, which a periodic
        surface may give a period apart when the edge lies on its seam); across: the
        contacts' across-parameters, brought into the face's range."""
        s = self.face.Surface
        e1 = self.contacts[0][0]
        u, v = s.parameter(midpoint(e1))
        t = e1.tangentAt(0.5 * (e1.FirstParameter + e1.LastParameter))
        su, sv = s.getDN(u, v, 1, 0), s.getDN(u, v, 0, 1)
        n = su.cross(sv)
        # t = alpha su + beta sv: alpha = (t x sv) . n / |n|^2, beta = (su x t) . n / |n|^2
        self.along = 0 if abs(t.cross(sv).dot(n)) > abs(su.cross(t).dot(n)) else 1
        across = 1 - self.along
        r = self.face.ParameterRange
        lo, hi = (r[2], r[3]) if across == 1 else (r[0], r[1])
        self.across = tuple(snap(s.parameter(midpoint(e))[across], lo, hi, period(s, across))
                            for e, _ in self.contacts)
        self.range = (r[0], r[1]) if self.along == 0 else (r[2], r[3])

    def point(self, a, c):
        """Surface point at along-parameter a and across-parameter c."""
        return self.surface.value(a, c) if self.along == 0 else self.surface.value(c, a)

    def derivative(self, a, c, along):
        """First derivative of the face's surface along (True) or across (False)."""
        du = 1 if (self.along == 0) == along else 0
        return self.surface.getDN(*((a, c) if self.along == 0 else (c, a)), du, 1 - du)

    def along_at(self, edge):
        """The end of the along-range (range[0] or range[1]) at which `edge` (a link)
        lies, or None when it lies inside the range. On a periodic along-parameter the
        projection may return the end a period away (0 for 2 pi); snap folds it back."""
        a = self.along_of(midpoint(edge))
        return a if a in self.range else None

    def along_of(self, p):
        """The along-parameter of the face's point nearest to p, within range."""
        s = self.face.Surface
        return snap(s.parameter(p)[self.along], *self.range, period(s, self.along))

    def oblique(self, edge):
        """True when the link `edge` starts at an end of the along-range but does not
        stay there: OCCT split the fillet across it at an angle."""
        return sum(self.along_of(v.Point) in self.range for v in edge.Vertexes) == 1


class Section:
    """One member of a chain, run from along-parameter a_start to a_end, with the
    across-parameters of side 1 and side 2 (cm: their mean, the mid-line) and the faces
    it touches there (sides)."""

    def __init__(self, rbf, a_start, a_end, c1, c2, sides):
        self.rbf, self.a_start, self.a_end, self.c1, self.c2 = rbf, a_start, a_end, c1, c2
        self.cm = 0.5 * (c1 + c2)
        self.sides = sides


def _same_sides(a, b):
    return a[0].isSame(b[0]) and a[1].isSame(b[1])


class FilletChain:
    """Rolling-ball faces joined tangentially end to end: one blend, or one per run.

    Attributes: faces; ends: [(edge, neighbour face)]; corners: [(edge, corner patch's
    RollingBallFace)], ends at corner patches; closed; corner: None or why the chain is kept;
    junctions: (False, False), see Run. When corner is None: sections, the members in
    order with their direction; sides: (F1, F2), the faces touched along side 1 and
    side 2 by the first section; runs: None when every section touches the same two
    faces, else [Run] (the side changes face along the chain, as a rounded rectangle's
    top edge runs along planes and cylinders).
    """

    junctions = (False, False)

    def __init__(self, members):
        self.members = members
        self.faces = [m.face for m in members]
        self.ends = [x for m in members for x in m.ends]
        self.corners = [x for m in members for x in m.corners]
        self.closed = not self.ends and not self.corners
        self.runs = None
        self.corner = next((m.corner for m in members if m.corner), None)
        if self.corner is None:
            self.corner = self._order()

    def _order(self):
        """Order the members into sections; returns why this cannot be done, or None."""
        ends = {}  # (member, along end) -> (other member, its along end)
        for m in self.members:
            for e, nb in m.links:
                o = next(x for x in self.members if x.face.isSame(nb))
                a, b = m.along_at(e), o.along_at(e)
                if (a is None or b is None) and (m.oblique(e) or o.oblique(e)):
                    return ("OCCT split its fillet at an angle to the fillet's cross-section "
                            "where it meets the next face of its chain")
                if a is None or b is None:
                    return ("OCCT's faces of this fillet meet along an edge inside one "
                            "face's range, not at a cross-section's end (another fillet "
                            "meets it there, or OCCT's fillet is irregular: see the solid "
                            "check)")
                ends[(id(m), a)] = (o, b)
        start = self.members[0]
        a_in = start.range[0]
        if not self.closed:
            loose = [(m, a) for m in self.members for a in m.range if (id(m), a) not in ends]
            if len(loose) != 2:
                return "the fillet chain has %d free ends instead of 2" % len(loose)
            start, a_in = loose[0]
        self.sections, m, a = [], start, a_in
        side1 = None  # the previous section's contact edge on side 1
        while True:
            a_out = m.range[1] if a == m.range[0] else m.range[0]
            contacts, across = m.contacts, m.across
            # side 1 continues where the previous section's side 1 ended
            if side1 is not None and contacts[1][0].distToShape(side1)[0] < \
                    contacts[0][0].distToShape(side1)[0]:
                contacts, across = contacts[::-1], across[::-1]
            side1 = contacts[0][0]
            self.sections.append(Section(m, a, a_out, *across,
                                         (contacts[0][1], contacts[1][1])))
            nxt = ends.get((id(m), a_out))
            if nxt is None or (nxt[0] is start and nxt[1] == a_in):
                break
            if len(self.sections) > len(self.members):
                return "the fillet chain does not close up"
            m, a = nxt
        if len(self.sections) != len(self.members):
            return "the rolling-ball faces do not form one chain"
        if self.closed and len(self.members) > 1 and \
                ends.get((id(m), self.sections[-1].a_end), (None,))[0] is not start:
            return "the fillet chain does not close up"
        self.sides = self.sections[0].sides
        if not all(_same_sides(x.sides, self.sides) for x in self.sections):
            self.runs = self._runs()
        return None

    def _runs(self):
        """The sections grouped into runs along which both sides stay on one face each
        (a closed chain's list rotated to start where a side changes face)."""
        secs = self.sections
        if self.closed:
            k = next(i for i in range(len(secs))
                     if not _same_sides(secs[i - 1].sides, secs[i].sides))
            secs = secs[k:] + secs[:k]
        groups = [[secs[0]]]
        for x in secs[1:]:
            if _same_sides(x.sides, groups[-1][-1].sides):
                groups[-1].append(x)
            else:
                groups.append([x])
        return [Run(g, (self.closed or i > 0, self.closed or i + 1 < len(groups)))
                for i, g in enumerate(groups)]


class Run:
    """Consecutive sections of a FilletChain whose sides stay on one face each: one
    blend of a chain whose side changes face. It has the attributes of an open
    FilletChain that a blend uses (sections, faces, ends, closed = False, sides);
    junctions: (at start, at end), True where the run meets the next run of the chain
    (across OCCT's cross-section between two of its faces, or where knots.split_at_knots
    cut it) instead of ending; ends: the end edges of its sections' faces unless given
    (a run cut from inside a face has only those at the chain's ends); corners: likewise,
    its ends at corner patches."""

    closed = False

    def __init__(self, sections, junctions, ends=None, corners=None):
        self.sections, self.junctions = sections, junctions
        self.faces = [x.rbf.face for x in sections]
        self.ends = [e for x in sections for e in x.rbf.ends] if ends is None else ends
        self.corners = [e for x in sections for e in x.rbf.corners] if corners is None \
            else corners
        self.sides = sections[0].sides


class CornerPatch:
    """OCCT's corner patch where three or more fillets meet at a vertex, or its face
    between a convex and a concave fillet that is set back (a RollingBallFace with
    patch set), or OCCT's corner patches that share an edge (where a fillet between two
    corners vanishes: replaced together, they leave one hole; joined). rbfs: their
    RollingBallFaces; faces; chains: the FilletChains ending at them; setback: None or
    the setback.Setback (of a single face); tools: the edges bounding the faces around
    it anew (the faces' own but those they share, or the setback's); region: where the
    hole its filling fills lies (the faces, with the setback's edges); creases: the
    edges its filling only passes through, not tangent to the faces there: the
    setback's edge on the face whose rim stays sharp, or the faces' own edges where
    they meet a face at an angle (their RollingBallFaces' ends); guide: the face the
    filling may be pinned to (corners.fill), OCCT's single patch, or None: at a setback
    corner OCCT's face spans only part of the hole, and pins follow one face. It is
    replaced by a filling (corners.py) when any of those chains is blended."""

    def __init__(self, rbfs, chains_):
        self.rbfs = rbfs
        self.faces = [r.face for r in rbfs]
        self.chains = [c for c in chains_ if any(p is r for _, p in c.corners for r in rbfs)]
        self.setback = rbfs[0].setback  # (joined: none is set back)
        own = [e for f in self.faces for e in f.Edges]
        self.tools = self.setback.tools if self.setback else \
            [e for e in own if sum(e.isSame(x) for x in own) == 1]
        self.region = Part.Compound(self.faces + (self.tools if self.setback else []))
        self.creases = self.setback.creases if self.setback else \
            [e for r in rbfs for e, _ in r.ends]
        self.guide = self.faces[0] if len(self.faces) == 1 and not self.setback else None

    def where(self):
        """'corner patch at (x, y, z)', or 'corner patches at (x, y, z) and (x, y, z)',
        for messages."""
        at = ["(%.4g, %.4g, %.4g)" % tuple(f.CenterOfMass) for f in self.faces]
        if len(at) == 1:
            return "corner patch at " + at[0]
        return "corner patches at %s and %s" % (", ".join(at[:-1]), at[-1])


def chains(rbfs):
    """Group RollingBallFaces into FilletChains by their tangent links; a corner patch
    ends the chains that join it (or meet it at an angle: a setback corner's). Returns
    ([FilletChain], [CornerPatch]), a CornerPatch per patch (see joined)."""
    patches = [r for r in rbfs if r.patch]
    rbfs = [r for r in rbfs if not r.patch]

    def at_patch(pairs, r):  # [(edge, face)] but those on a patch, which go to r.corners
        rest = []
        for e, nb in pairs:
            patch = next((p for p in patches if nb.isSame(p.face)), None)
            if patch is None:
                rest.append((e, nb))
            else:
                r.corners.append((e, patch))
        return rest
    for r in rbfs:
        r.ends, r.links = at_patch(r.ends, r), at_patch(r.links, r)
    out = [FilletChain(g) for g in _grouped(
        rbfs, lambda r, m: any(nb.isSame(m.face) for _, nb in r.links))]
    return out, [CornerPatch([p], out) for p in patches]


def joined(patches, chains_):
    """`patches` (CornerPatch), each set of those that share an edge (none set back)
    made one CornerPatch (of chains_, the FilletChains): replaced together, they leave
    one hole, where a fillet between two corners vanishes. The others are returned as
    they are."""
    def share(p, q):
        return p.setback is None and q.setback is None and any(
            e.isSame(x) for f in p.faces for e in f.Edges for g in q.faces for x in g.Edges)
    return [g[0] if len(g) == 1 else CornerPatch([r for q in g for r in q.rbfs], chains_)
            for g in _grouped(patches, share)]


def _grouped(items, meets):
    """`items` in groups, each item with those before it for which meets(item, that)
    holds, and with their groups: [[item, ...]], each group's latest item first."""
    groups = []
    for x in items:
        linked = [g for g in groups if any(meets(x, y) for y in g)]
        groups = [g for g in groups if not any(g is m for m in linked)] + \
            [[x] + [y for g in linked for y in g]]
    return groups

