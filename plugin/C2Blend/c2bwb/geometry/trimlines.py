# SPDX-License-Identifier: LGPL-2.1-or-later
"""Boundary data of a blend from two CAD faces (MATH.md section 7).

A blend runs from face F1 (u = 0) to face F2 (u = 1). Given corresponding trimline
points T1(v) on F1 and T2(v) on F2, the cross-boundary rows are

    S = T1,  S_u = s1 d1,  S_uu = s1^2 II1(d1, d1) N1  (,  S_uuu = s1^3 g1)
    S = T2,  S_u = -s2 d2, S_uu = s2^2 II2(d2, d2) N2  (, S_uuu = -s2^3 g2)

with d_i the unit tangent of F_i perpendicular to the trimline, pointing from F_i towards
the blend, and s_i = tension * |T2 - T1|. These rows make the blend's tangent plane and
second fundamental form equal to the face's along the trimline (G2) for any s_i > 0.
"""
import math

from ..errors import C2BlendError

ROWS = {"C1": 2, "C2": 3, "C3": 4}
# the PDE's shape parameters per continuity (README "What the kernel computes")
SHAPE_NAMES = {"C1": ("b", "c", "d"), "C2": ("gamma", "eta", "lambda", "rho"),
               "C3": ("a0", "a1", "a2", "a3", "a4")}


def pointwise_shape(continuity):
    """Shape parameters of the pointwise blend: only the PDE's pure u-derivative term,
    d^2n S / du^2n = 0 (n = 2, 3, 4 for C1, C2, C3), so each u-curve is the Hermite
    polynomial of degree 2n - 1 of the data at its own v. It is the PDE's own solution
    wherever the data are linear in v (a straight edge), and it is as smooth in v as
    the data are."""
    n = len(SHAPE_NAMES[continuity])
    return (1.0,) + (0.0,) * (n - 1)


def shape_for(continuity, shape_params):
    """The shape parameters for continuity: as given when their number fits; all ones
    (the default of any length) becomes all ones of the right length. Raises
    ValueError naming the expected parameters otherwise."""
    names = SHAPE_NAMES[continuity]
    try:
        values = tuple(float(p) for p in shape_params)
    except (TypeError, ValueError):
        raise ValueError("%s takes %d shape parameters (%s), a sequence of numbers, got %r"
                         % (continuity, len(names), ", ".join(names), shape_params)) from None
    if not all(math.isfinite(p) for p in values):
        raise ValueError("shape parameters must be finite, got %r" % (values,))
    if len(values) == len(names):
        return values
    if values and all(p == 1.0 for p in values):
        return (1.0,) * len(names)
    raise ValueError("%s takes %d shape parameters (%s), got %d"
                     % (continuity, len(names), ", ".join(names), len(values)))


def side_rows(fr, tangent, towards, scale, nrows, sign):
    """Cross-boundary rows at one trimline point.

    fr: the primary face's surface.Frame at the trimline point; tangent: the trimline's
    tangent there; towards: any vector pointing from the face into the blend (fixes the
    sign of d); scale: s > 0; sign: +1 for u = 0, -1 for u = 1.
    Returns a list of nrows (x, y, z) tuples.
    """
    d = fr.n.cross(tangent)
    if d.Length == 0.0:
        raise ValueError("trimline tangent is parallel to the face normal")
    d.normalize()
    if d.dot(towards) < 0.0:
        d = -d
    rows = [fr.p, d * (sign * scale)]
    if nrows > 2:
        rows.append(fr.n * (scale * scale * fr.normal_curvature(d)))
    if nrows > 3:
        rows.append(fr.third_along(d) * (sign * scale ** 3))
    return [tuple(r) for r in rows]


def pair_rows(pairs, nrows, tension, where):
    """Rows of both sides at corresponding trimline points.

    pairs: (frame1, tangent1, towards1, frame2, tangent2, towards2) per sample, with the
    frames of face 1 and face 2 at the two points, as side_rows takes them; both sides
    use the cross speed s = tension * |p2 - p1|.
    Returns (rows0, rows1). Raises C2BlendError naming `where` where the trimlines touch.
    """
    rows0, rows1 = [], []
    for f1, g1, out1, f2, g2, out2 in pairs:
        s = tension * (f2.p - f1.p).Length
        if s <= 0:
            raise C2BlendError("the trimlines touch at (%.6g, %.6g, %.6g); a blend needs a gap"
                               % (f1.p.x, f1.p.y, f1.p.z), where, "selection")
        rows0.append(side_rows(f1, g1, out1, s, nrows, 1))
        rows1.append(side_rows(f2, g2, out2, s, nrows, -1))
    return rows0, rows1


def v_length(rows0, rows1, periodic):
    """Length of the v-range that makes the blend's parametrisation nearly isotropic:
    the mean trimline length divided by the mean cross speed |S_u|. Without it a long
    trimline mapped onto [0, 1] has steep v-modes, and the PDE pulls the blend far
    from both faces (the modes decay like exp(-|k| u / v_length))."""
    def length(rows):
        pts = [r[0] for r in rows] + ([rows[0][0]] if periodic else [])
        return sum(math.dist(a, b) for a, b in zip(pts, pts[1:]))
    speed = sum(math.hypot(*r[1]) for r in rows0 + rows1) / (len(rows0) + len(rows1))
    return max(0.5 * (length(rows0) + length(rows1)) / speed, 1e-3)


def spec_from_rows(rows0, rows1, continuity, shape_params, periodic, name):
    """A C2Blend spec (dict) with sampled boundary rows.

    rows0/rows1: per sample, the list of rows from side_rows. Samples are uniform in
    v over [0, v_length] (see v_length); periodic data do not repeat the end point.
    """
    n = ROWS[continuity]
    return {
        "name": name,
        "continuity": continuity,
        "shape": list(shape_params),
        "v_range": [0.0, v_length(rows0, rows1, periodic)],
        "periodic": bool(periodic),
        "boundary": {
            "u0": [{"samples": [list(r[k]) for r in rows0]} for k in range(n)],
            "u1": [{"samples": [list(r[k]) for r in rows1]} for k in range(n)],
        },
    }
