# SPDX-License-Identifier: LGPL-2.1-or-later
"""Trimlines and correspondence from OCCT's rolling-ball fillet.

OCCT's fillet (BRepFilletAPI_MakeFillet, via Shape.makeFillet) gives, for each filleted
edge, a face whose two contact edges are the trimlines on the adjacent faces and whose
cross-sections (iso-curves across) join corresponding points. This module finds those
faces in the result, classifies their edges, and samples corresponding points.
"""
import Part

from .surface import frame_at_point, angle

TANGENT_ANGLE = 1e-3  # rad: a contact edge joins its faces tangentially


def interior_points(face, n=4):
    """Points of the face on an n x n grid of its parameter range, inside its domain."""
    u0, u1, v0, v1 = face.ParameterRange
    out = []
    for i in range(1, n + 1):
        for j in range(1, n + 1):
            u = u0 + (u1 - u0) * (i - 0.5) / n
            v = v0 + (v1 - v0) * (j - 0.5) / n
            if face.isPartOfDomain(u, v):
                out.append(face.Surface.value(u, v))
    return out


def new_faces(original, result):
    """Faces of `result` that do not lie on the boundary of `original` (the fillets):
    some interior point is farther than 10x the face tolerance from every original face."""
    boundary = Part.Compound(original.Faces)
    out = []
    for f in result.Faces:
        if any(f.isSame(g) for g in original.Faces):
            continue
        tol = 10.0 * max(f.Tolerance, 1e-7)
        if any(boundary.distToShape(Part.Vertex(p))[0] > tol for p in interior_points(f)):
            out.append(f)
    return out


def _unique_edges(face):
    out = []
    for e in face.Edges:
        if not any(e.isSame(o) for o in out):
            out.append(e)
    return out


def _snap(c, lo, hi):
    """c, or the end of [lo, hi] it lies within 1e-6 (relative) of: projections onto
    periodic surfaces may return a parameter a period away or a rounding off the end."""
    end = min((lo, hi), key=lambda x: abs(x - c))
    return end if abs(end - c) < 1e-6 * (1 + abs(hi - lo)) else c


class RollingBallFace:
    """One rolling-ball face and its surroundings.

    Attributes: face; contacts: [(edge, neighbour face), (edge, neighbour face)];
    ends: [(edge, neighbour face)] (empty for a closed fillet); seams: [edge];
    corner: None, or a string saying why the face cannot be replaced (corner patch).
    along: 0 or 1, the surface parameter along the fillet; across: (c1, c2).
    """

    def __init__(self, result, face, fillet_faces):
        self.face = face
        self.contacts, self.ends, self.seams = [], [], []
        self.corner = None
        for e in _unique_edges(face):
            nbrs = [f for f in result.ancestorsOfType(e, Part.Face) if not f.isSame(face)]
            if not nbrs:
                self.seams.append(e)
                continue
            nb = nbrs[0]
            p = e.valueAt(0.5 * (e.FirstParameter + e.LastParameter))
            tangent = angle(frame_at_point(face, p).n, frame_at_point(nb, p).n) < TANGENT_ANGLE
            is_fillet = any(nb.isSame(g) for g in fillet_faces)
            if is_fillet:
                self.corner = "it meets another fillet or corner patch of OCCT"
            if tangent and not is_fillet:
                self.contacts.append((e, nb))
            else:
                self.ends.append((e, nb))
        if self.corner is None and len(self.contacts) != 2:
            self.corner = ("it has %d tangent contact edges instead of 2 (a corner patch)"
                           % len(self.contacts))
        if self.corner is None:
            for e, nb in self.ends:
                if not nb.Surface.isPlanar():
                    self.corner = "an end of the fillet lies on a non-planar face"
        if self.corner is None:
            self._orient()

    def _orient(self):
        s = self.face.Surface
        e1 = self.contacts[0][0]
        pts = [e1.valueAt(e1.FirstParameter + k * (e1.LastParameter - e1.FirstParameter) / 3.0)
               for k in (1, 2)]
        uv = [s.parameter(p) for p in pts]
        self.along = 0 if abs(uv[0][0] - uv[1][0]) > abs(uv[0][1] - uv[1][1]) else 1
        across = 1 - self.along
        cs = []
        for e, _ in self.contacts:
            p = e.valueAt(0.5 * (e.FirstParameter + e.LastParameter))
            cs.append(s.parameter(p)[across])
        r = self.face.ParameterRange
        lo, hi = (r[2], r[3]) if across == 1 else (r[0], r[1])
        self.across = tuple(_snap(c, lo, hi) for c in cs)
        self.range = (r[0], r[1]) if self.along == 0 else (r[2], r[3])
        self.closed = not self.ends

    def point(self, a, c):
        """Surface point at along-parameter a and across-parameter c."""
        return self.face.Surface.value(a, c) if self.along == 0 else self.face.Surface.value(c, a)

    def derivative(self, a, c, along):
        """First derivative of the face's surface along (True) or across (False)."""
        du = 1 if (self.along == 0) == along else 0
        return self.face.Surface.getDN(*((a, c) if self.along == 0 else (c, a)), du, 1 - du)

    def samples(self, n):
        """n along-parameters: uniform, end point excluded when the fillet is closed."""
        a0, a1 = self.range
        if self.closed:
            return [a0 + (a1 - a0) * k / n for k in range(n)]
        return [a0 + (a1 - a0) * k / (n - 1) for k in range(n)]

