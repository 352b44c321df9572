"""Test meshes with exact principal curvatures for c2blend-cgal-curvature.

Each surface is a regular grid in its parameter plane (u rows, v columns), triangulated
with the same diagonal everywhere, so the n-ring of a vertex is centrally symmetric in the
parameter plane: the condition under which a jet fit of degree d shows the even-order
super-convergence (curvature error O(h^d) instead of O(h^(d-1))) measured by test_cgal.py.

Vertices lie exactly on the surface (to rounding); normals, k1 >= k2 are computed from the
closed-form first and second derivatives with the C2Blend sign convention: n = Su x Sv /
|Su x Sv| (or its opposite with flip=True) and a curvature is positive when the surface
bends towards n. Nothing here uses C2Blend code.
"""

import math
import struct

import numpy as np


def principal_curvatures(su, sv, suu, suv, svv, n):
    """k1 >= k2 from the fundamental forms (arrays of shape (..., 3))."""
    e = np.sum(su * su, -1)
    f = np.sum(su * sv, -1)
    g = np.sum(sv * sv, -1)
    l = np.sum(suu * n, -1)
    m = np.sum(suv * n, -1)
    nn = np.sum(svv * n, -1)
    det = e * g - f * f
    k_gauss = (l * nn - m * m) / det
    h_mean = (e * nn - 2 * f * m + g * l) / (2 * det)
    rad = np.sqrt(np.maximum(h_mean * h_mean - k_gauss, 0.0))
    return h_mean + rad, h_mean - rad


class Surface:
    """A parametric surface S(u, v) with derivatives, on [u0, u1] x [v0, v1]."""

    name = "surface"
    periodic_u = False
    periodic_v = True

    def derivatives(self, u, v):
        raise NotImplementedError

    def exact(self, u, v):
        """Optional closed-form (k1, k2) along Su x Sv, to cross-check the generic formula."""
        return None

    def u_samples(self, rows):
        """The u values of the grid rows: uniform unless a surface overrides it."""
        if self.periodic_u:
            return self.u0 + (self.u1 - self.u0) * np.arange(rows) / rows
        return np.linspace(self.u0, self.u1, rows)


class SphereBand(Surface):
    """x = R sin(u) cos(v), y = R sin(u) sin(v), z = R cos(u): Su x Sv points outwards,
    so k1 = k2 = -1/R."""

    name = "sphere"

    def __init__(self, radius=1.0, u0=math.pi / 4, u1=3 * math.pi / 4):
        self.r, self.u0, self.u1, self.v0, self.v1 = radius, u0, u1, 0.0, 2 * math.pi

    def derivatives(self, u, v):
        r = self.r
        su_, cu, sv_, cv = np.sin(u), np.cos(u), np.sin(v), np.cos(v)
        z = np.zeros_like(u)
        s = np.stack([r * su_ * cv, r * su_ * sv_, r * cu], -1)
        su = np.stack([r * cu * cv, r * cu * sv_, -r * su_], -1)
        sv = np.stack([-r * su_ * sv_, r * su_ * cv, z], -1)
        suu = np.stack([-r * su_ * cv, -r * su_ * sv_, -r * cu], -1)
        suv = np.stack([-r * cu * sv_, r * cu * cv, z], -1)
        svv = np.stack([-r * su_ * cv, -r * su_ * sv_, z], -1)
        return s, su, sv, suu, suv, svv

    def exact(self, u, v):
        k = np.full(np.shape(u), -1.0 / self.r)
        return k, k


class Cylinder(Surface):
    """x = r cos(v), y = r sin(v), z = u: Su x Sv points inwards, so k1 = 1/r, k2 = 0."""

    name = "cylinder"

    def __init__(self, radius=1.0, length=2.0):
        self.r, self.u0, self.u1, self.v0, self.v1 = radius, 0.0, length, 0.0, 2 * math.pi

    def derivatives(self, u, v):
        r = self.r
        sv_, cv = np.sin(v), np.cos(v)
        z, o = np.zeros_like(u), np.ones_like(u)
        s = np.stack([r * cv, r * sv_, u], -1)
        su = np.stack([z, z, o], -1)
        sv = np.stack([-r * sv_, r * cv, z], -1)
        suu = np.stack([z, z, z], -1)
        suv = np.stack([z, z, z], -1)
        svv = np.stack([-r * cv, -r * sv_, z], -1)
        return s, su, sv, suu, suv, svv

    def exact(self, u, v):
        return np.full(np.shape(u), 1.0 / self.r), np.zeros(np.shape(u))


class Torus(Surface):
    """x = (R + r cos u) cos v, y = (R + r cos u) sin v, z = r sin u (closed): Su x Sv
    points inwards, the principal curvatures are 1/r and cos(u) / (R + r cos(u))."""

    name = "torus"
    periodic_u = True

    def __init__(self, major=2.0, minor=1.0, conformal=False):
        self.big, self.r, self.conformal = major, minor, conformal
        self.u0, self.u1, self.v0, self.v1 = 0.0, 2 * math.pi, 0.0, 2 * math.pi

    def conformal_period(self):
        """Length of the conformal coordinate s (ds = r du / (R + r cos u)) over one turn."""
        return 2 * math.pi * self.r / math.sqrt(self.big ** 2 - self.r ** 2)

    def u_samples(self, rows):
        """conformal=True: rows uniform in s, where the metric is (R + r cos u)^2 (ds^2 +
        dv^2), so a grid with equal steps in s and v is locally square everywhere (what the
        k-nearest neighbourhood needs to be symmetric); otherwise uniform in u."""
        if not self.conformal:
            return Surface.u_samples(self, rows)
        big, r = self.big, self.r
        q = math.sqrt(big * big - r * r)
        s = -0.5 * self.conformal_period() + self.conformal_period() * np.arange(rows) / rows
        return 2 * np.arctan(math.sqrt((big + r) / (big - r)) * np.tan(s * q / (2 * r)))

    def derivatives(self, u, v):
        big, r = self.big, self.r
        su_, cu, sv_, cv = np.sin(u), np.cos(u), np.sin(v), np.cos(v)
        w = big + r * cu
        z = np.zeros_like(u)
        s = np.stack([w * cv, w * sv_, r * su_], -1)
        su = np.stack([-r * su_ * cv, -r * su_ * sv_, r * cu], -1)
        sv = np.stack([-w * sv_, w * cv, z], -1)
        suu = np.stack([-r * cu * cv, -r * cu * sv_, -r * su_], -1)
        suv = np.stack([r * su_ * sv_, -r * su_ * cv, z], -1)
        svv = np.stack([-w * cv, -w * sv_, z], -1)
        return s, su, sv, suu, suv, svv

    def exact(self, u, v):
        a = np.full(np.shape(u), 1.0 / self.r)
        b = np.cos(u) / (self.big + self.r * np.cos(u))
        return np.maximum(a, b), np.minimum(a, b)


class Mesh:
    """Vertices, unit normals, exact k1 >= k2, triangles, and the grid shape."""

    def __init__(self, xyz, normal, k1, k2, tri, rows, cols):
        self.xyz, self.normal, self.k1, self.k2, self.tri = xyz, normal, k1, k2, tri
        self.rows, self.cols = rows, cols

    def scaled(self, s):
        return Mesh(self.xyz * s, self.normal, self.k1 / s, self.k2 / s, self.tri, self.rows, self.cols)


def grid_mesh(surf, rows, cols, flip=False):
    """Samples surf on rows x cols parameter points. A periodic direction gets `rows`
    (`cols`) distinct points over its period and wraps; an open one includes both ends.
    flip=True reverses the normals and the face orientation (all curvatures change sign)."""
    u = surf.u_samples(rows)
    if surf.periodic_v:
        v = surf.v0 + (surf.v1 - surf.v0) * np.arange(cols) / cols
    else:
        v = np.linspace(surf.v0, surf.v1, cols)
    uu, vv = np.meshgrid(u, v, indexing="ij")
    s, su, sv, suu, suv, svv = surf.derivatives(uu, vv)
    n = np.cross(su, sv)
    n /= np.linalg.norm(n, axis=-1)[..., None]
    k1, k2 = principal_curvatures(su, sv, suu, suv, svv, n)
    ex = surf.exact(uu, vv)
    if ex is not None:
        assert np.allclose(k1, ex[0], atol=1e-12) and np.allclose(k2, ex[1], atol=1e-12), surf.name
    if flip:
        n, k1, k2 = -n, -k2, -k1
    tri = []
    ru = rows if surf.periodic_u else rows - 1
    rv = cols if surf.periodic_v else cols - 1
    for i in range(ru):
        for j in range(rv):
            i1, j1 = (i + 1) % rows, (j + 1) % cols
            a, b, c, d = i * cols + j, i * cols + j1, i1 * cols + j, i1 * cols + j1
            # (u, v) counter-clockwise: the face normal is along Su x Sv
            t1, t2 = (a, c, d), (a, d, b)
            if flip:
                t1, t2 = t1[::-1], t2[::-1]
            tri += [t1, t2]
    return Mesh(s.reshape(-1, 3), n.reshape(-1, 3), k1.ravel(), k2.ravel(), np.array(tri), rows, cols)


def write_ply(path, mesh, analytic=True, normals=True, binary=False, region=None, valid=None, big_endian=False):
    nv = len(mesh.xyz)
    region = np.zeros(nv, dtype=np.uint8) if region is None else region
    valid = np.ones(nv, dtype=np.uint8) if valid is None else valid
    props = ["x", "y", "z"] + (["nx", "ny", "nz"] if normals else []) + (["k1", "k2"] if analytic else [])
    order = ">" if big_endian else "<"
    fmt = ("binary_big_endian" if big_endian else "binary_little_endian") if binary else "ascii"
    head = ["ply", "format %s 1.0" % fmt,
            "comment c2blend-cgal-curvature test mesh", "element vertex %d" % nv]
    head += ["property double %s" % p for p in props]
    if analytic:
        head += ["property uchar region", "property uchar valid"]
    head += ["element face %d" % len(mesh.tri), "property list uchar int vertex_indices", "end_header"]
    cols = [mesh.xyz] + ([mesh.normal] if normals else []) + ([mesh.k1[:, None], mesh.k2[:, None]] if analytic else [])
    data = np.hstack(cols)
    with open(path, "wb") as f:
        f.write(("\n".join(head) + "\n").encode())
        if binary:
            for i in range(nv):
                f.write(struct.pack("%s%dd" % (order, data.shape[1]), *data[i]))
                if analytic:
                    f.write(struct.pack("%sBB" % order, int(region[i]), int(valid[i])))
            for t in mesh.tri:
                f.write(struct.pack("%sBiii" % order, 3, *(int(x) for x in t)))
        else:
            lines = []
            for i in range(nv):
                row = " ".join("%.17g" % x for x in data[i])
                if analytic:
                    row += " %d %d" % (region[i], valid[i])
                lines.append(row)
            lines += ["3 %d %d %d" % tuple(t) for t in mesh.tri]
            f.write(("\n".join(lines) + "\n").encode())


def write_off(path, mesh):
    with open(path, "w") as f:
        f.write("OFF\n# c2blend-cgal-curvature test mesh\n%d %d 0\n" % (len(mesh.xyz), len(mesh.tri)))
        for p in mesh.xyz:
            f.write("%.17g %.17g %.17g\n" % tuple(p))
        for t in mesh.tri:
            f.write("3 %d %d %d\n" % tuple(t))


def write_obj(path, mesh, normals=True):
    with open(path, "w") as f:
        f.write("# c2blend-cgal-curvature test mesh\n")
        for p in mesh.xyz:
            f.write("v %.17g %.17g %.17g\n" % tuple(p))
        if normals:
            for n in mesh.normal:
                f.write("vn %.17g %.17g %.17g\n" % tuple(n))
            for t in mesh.tri:
                f.write("f %d//%d %d//%d %d//%d\n" % (t[0] + 1, t[0] + 1, t[1] + 1, t[1] + 1, t[2] + 1, t[2] + 1))
        else:
            for t in mesh.tri:
                f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))
