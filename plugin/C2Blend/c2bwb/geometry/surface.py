# SPDX-License-Identifier: LGPL-2.1-or-later
"""Differential geometry of a FreeCAD face at a point (MATH.md sections 7 and 8).

Only FreeCAD, numpy and the standard library are used, so this runs headless.
Normals follow the face's orientation (outward for the faces of a valid solid).
"""
import math

import numpy

import FreeCAD
import Part

Vector = FreeCAD.Vector


class Frame:
    """Surface derivatives of `face` at parameters (u, v).

    Attributes: u, v; p (point); su, sv, suu, suv, svv (Vectors, model units);
    n (unit normal, oriented like the face).
    """

    __slots__ = ("face", "u", "v", "p", "su", "sv", "suu", "suv", "svv", "n")

    def __init__(self, face, u, v, surface=None):
        """surface: face.Surface, when the caller keeps it (getting it takes 2 to 5 us,
        as long as the six evaluations here)."""
        s = surface or face.Surface
        self.face, self.u, self.v = face, u, v
        self.p = s.value(u, v)
        self.su = s.getDN(u, v, 1, 0)
        self.sv = s.getDN(u, v, 0, 1)
        self.suu = s.getDN(u, v, 2, 0)
        self.suv = s.getDN(u, v, 1, 1)
        self.svv = s.getDN(u, v, 0, 2)
        n = self.su.cross(self.sv)
        # at a pole of a B-spline sphere (toNurbs) S_u is rounding noise, and so is the
        # normal: 0.15 rad off 1e-15 from the pole, 7e-5 rad 1e-12 from it (where
        # FreeCAD's normalize() did not raise its own error, as it does below 2.2e-16)
        size = n.Length
        if not size > 1e-12 * (self.su.dot(self.su) + self.sv.dot(self.sv)):
            raise ValueError("degenerate surface point (S_u x S_v = 0) at (%g, %g)" % (u, v))
        n = Vector(n.x / size, n.y / size, n.z / size)  # normalize()'s bits, any size
        self.n = -n if face.Orientation == "Reversed" else n

    def normal_derivatives(self):
        """(dn/du, dn/dv) of the oriented unit normal n (Weingarten: the part of the
        derivative of S_u x S_v along n removed, divided by |S_u x S_v|)."""
        big = self.su.cross(self.sv)
        scale = (-1.0 if self.face.Orientation == "Reversed" else 1.0) / big.Length
        return tuple((d - self.n * self.n.dot(d)) * scale
                     for d in (self.suu.cross(self.sv) + self.su.cross(self.suv),
                               self.suv.cross(self.sv) + self.su.cross(self.svv)))

    def coords(self, d):
        """(a, b) with d = a S_u + b S_v for a tangent vector d (least squares)."""
        e, f, g = self.su.dot(self.su), self.su.dot(self.sv), self.sv.dot(self.sv)
        p, q = d.dot(self.su), d.dot(self.sv)
        det = e * g - f * f
        return (g * p - f * q) / det, (e * q - f * p) / det

    def second_form(self, d1, d2):
        """II(d1, d2) = (second derivative along d1, d2) . n, for tangent vectors."""
        a1, b1 = self.coords(d1)
        a2, b2 = self.coords(d2)
        big_l, big_m, big_n = self.suu.dot(self.n), self.suv.dot(self.n), self.svv.dot(self.n)
        return a1 * a2 * big_l + (a1 * b2 + a2 * b1) * big_m + b1 * b2 * big_n

    def normal_curvature(self, d):
        """Normal curvature (1/model unit) in tangent direction d, sign from n."""
        return self.second_form(d, d) / d.dot(d)

    def third_along(self, d):
        """Normal part of the third derivative of the surface curve
        gamma(tau) = S(uv + tau delta + tau^2/2 eps), gamma'(0) = d, with eps chosen so
        that gamma''(0) is normal (gamma'' = II(d, d) n). Used for C3 data."""
        s = self.face.Surface
        a, b = self.coords(d)
        g2 = self.suu * (a * a) + self.suv * (2 * a * b) + self.svv * (b * b)
        tang = g2 - self.n * g2.dot(self.n)
        ea, eb = self.coords(tang)
        ea, eb = -ea, -eb
        d3 = [s.getDN(self.u, self.v, 3 - k, k) for k in range(4)]
        g3 = d3[0] * (a ** 3) + d3[1] * (3 * a * a * b) + d3[2] * (3 * a * b * b) + d3[3] * (b ** 3)
        mixed = (self.suu * (a * ea) + self.suv * (a * eb + b * ea) + self.svv * (b * eb)) * 3
        return self.n * (g3 + mixed).dot(self.n)

    def principal(self):
        """(k1, k2, K, H) with k1 >= k2, signs from n (MATH.md section 8)."""
        e, f, g = self.su.dot(self.su), self.su.dot(self.sv), self.sv.dot(self.sv)
        big_l, big_m, big_n = self.suu.dot(self.n), self.suv.dot(self.n), self.svv.dot(self.n)
        det = e * g - f * f
        k = (big_l * big_n - big_m * big_m) / det
        h = (e * big_n - 2 * f * big_m + g * big_l) / (2 * det)
        r = math.sqrt(max(h * h - k, 0.0))
        return h + r, h - r, k, h


PROJECT_ITER = 20
PROJECT_DONE = 1e-13  # relative parameter step at which a projection is converged


def project(surface, p, guess=None):
    """(u, v) of the orthogonal projection of point p onto surface.

    With a guess (u, v) near the answer, Newton's method on the stationarity of
    |S(u, v) - p|^2 (what marching along a curve provides): microseconds, where OCCT's
    global projection (surface.parameter) costs about 0.4 ms on a B-spline surface.
    Without a guess, or when Newton does not converge to a minimum inside the bounds of
    a non-periodic direction, OCCT's global projection is used."""
    if guess is None:
        return surface.parameter(p)
    u, v = guess
    bounds = surface.bounds()
    periodic = (surface.isUPeriodic(), surface.isVPeriodic())
    for _ in range(PROJECT_ITER):
        r = surface.value(u, v) - p
        su, sv = surface.getDN(u, v, 1, 0), surface.getDN(u, v, 0, 1)
        suu, suv, svv = (surface.getDN(u, v, 2, 0), surface.getDN(u, v, 1, 1),
                         surface.getDN(u, v, 0, 2))
        a, b, c = su.dot(su) + suu.dot(r), su.dot(sv) + suv.dot(r), sv.dot(sv) + svv.dot(r)
        det = a * c - b * b
        if not (a > 0.0 and det > 0.0):
            break  # not near a minimum
        gu, gv = su.dot(r), sv.dot(r)
        du, dv = -(c * gu - b * gv) / det, -(a * gv - b * gu) / det
        u, v = u + du, v + dv
        if any(not periodic[k] and not bounds[2 * k] - 1e-9 <= (u, v)[k] <= bounds[2 * k + 1] + 1e-9
               for k in (0, 1)):
            break  # left the surface
        if abs(du) + abs(dv) <= PROJECT_DONE * (1.0 + abs(u) + abs(v)):
            return u, v
    return surface.parameter(p)


def frame_at_point(face, p, guess=None):
    """Frame of `face` at the orthogonal projection of point p onto its surface (see
    project for the guess)."""
    u, v = project(face.Surface, p, guess)
    return Frame(face, u, v)


def off_surface(surface, p, guess=None):
    """Distance from point p to its orthogonal projection onto surface (see project for
    the guess)."""
    return (surface.value(*project(surface, p, guess)) - p).Length


def face_distance(face, p):
    """Distance (model units) from point p to face. OCCT's (distToShape) classifies
    the projection of p within one period of a periodic surface, so it misses the
    parts of a face whose domain spans more than a period, its boundary winding round
    the surface's seam: a cylinder's face between the turns of a helical ridge, whose
    pcurves span 3.6 periods, was put 1.2 away from points lying on it. On such a face
    (winds), domain_distance is taken when shorter. (Given another kind of shape, as
    an edge, OCCT's distance.)"""
    d = face.distToShape(Part.Vertex(p))[0]
    if d == 0.0 or not isinstance(face, Part.Face) or not winds(face):
        return d
    return min(d, domain_distance(face, p))


def domain_distance(face, p):
    """Distance from point p to its projection onto face's surface where the face's
    domain test (isPartOfDomain, which follows the pcurves round the seam) holds that
    projection, else infinity."""
    s = face.Surface
    try:
        u, v = s.parameter(p)
    except RuntimeError:  # no projection (FreeCAD and OCCT errors derive from it)
        return math.inf
    return (s.value(u, v) - p).Length if face.isPartOfDomain(u, v) else math.inf


def winds(face):
    """True when face's domain spans more than one period of its surface."""
    return winding(face) is not None


def winding(face, margin=1e-9):
    """0 (u) or 1 (v): the first direction in which face's domain spans more than 1 +
    margin periods of its surface; None where it spans no more in either."""
    spans = _spans(face)
    return next((k for k in (0, 1) if spans[k] > 1.0 + margin), None)


def periods(face):
    """How many periods of its surface face's domain spans: the larger of its spans in
    the surface's periodic directions, each divided by the period (0 when the surface
    is not periodic)."""
    return max(_spans(face))


def _spans(face):
    """[u span, v span] of face's domain, each in periods of its surface (0 in a
    direction where the surface is not periodic)."""
    s = face.Surface
    u0, u1, v0, v1 = face.ParameterRange
    return [(u1 - u0) / s.UPeriod() if s.isUPeriodic() else 0.0,
            (v1 - v0) / s.VPeriod() if s.isVPeriodic() else 0.0]


def frame_or_none(face, u, v):
    """Frame of face at (u, v), or None where the surface is degenerate (a pole)."""
    try:
        return Frame(face, u, v)
    except ValueError:
        return None


def tessellation(face, deflection):
    """OCCT's tessellation of face: points, triangles, and each point's (u, v) on the
    surface. These are the (u, v) of the triangulation's nodes (face.getUVNodes(), in
    another order, with seam nodes not merged): each point takes those of the node whose
    surface point is nearest to it, within 1e-9 of the face's size. Only a point with no
    such node is projected by OCCT (0.4 ms and more on a B-spline surface)."""
    pts, tris = face.tessellate(deflection)
    surface, uvn = face.Surface, face.getUVNodes() if pts else []
    if not uvn:
        return pts, tris, [surface.parameter(p) for p in pts]
    nodes = numpy.array([tuple(surface.value(u, v)) for u, v in uvn])
    tol = 1e-9 * max(face.BoundBox.DiagonalLength, 1e-300)
    uvs = []
    for k in range(0, len(pts), 512):  # nearest node, in blocks of points
        block = numpy.array([tuple(p) for p in pts[k:k + 512]])
        d2 = ((block[:, None, :] - nodes[None, :, :]) ** 2).sum(axis=2)
        for i, p in enumerate(pts[k:k + 512]):
            j = int(d2[i].argmin())
            uvs.append(uvn[j] if d2[i, j] <= tol * tol else surface.parameter(p))
    return pts, tris, uvs


def only_c0(face):
    """True for a B-spline face whose surface is only C0 (knots of full multiplicity,
    as toNurbs() and a rotating transformGeometry make), which the BOP check reports
    as GeomAbs_C0. OCCT's integration of its area (face.Area) is off by up to 0.9%
    there. A toNurbs() sphere r = 5 gets 315.32
    for 314.16, a band of it 2.7e-3 too much; its cap of height 7, 219.91, gets 220.19
    to 221.87 as the sphere is turned (mesh_area: 219.90)."""
    s = face.Surface
    return isinstance(s, Part.BSplineSurface) and s.Continuity == "C0"


def mesh_area(face, deflection):
    """The area of OCCT's triangulation of a copy of face (face itself keeps none),
    with the given deflection (model units): below the face's by about the deflection
    over the surface's radius of curvature, whatever the parametrisation."""
    pts, tris = face.copy().tessellate(deflection)
    if not tris:
        return 0.0
    p = numpy.array([tuple(x) for x in pts])
    t = numpy.array(tris, dtype=int).reshape(-1, 3)
    return 0.5 * float(numpy.linalg.norm(numpy.cross(p[t[:, 1]] - p[t[:, 0]],
                                                     p[t[:, 2]] - p[t[:, 0]]), axis=1).sum())


def leaving(edge, point):
    """The unit tangent of edge at its end at `point` (the nearer end), pointing into
    the edge."""
    a, b = edge.FirstParameter, edge.LastParameter
    first = (edge.valueAt(a) - point).Length <= (edge.valueAt(b) - point).Length
    d = edge.tangentAt(a if first else b)
    return d if first else -d


def angle(a, b):
    """Angle in radians between two vectors, accurate for tiny angles."""
    return math.atan2(a.cross(b).Length, a.dot(b))
