# SPDX-License-Identifier: LGPL-2.1-or-later
"""A face that winds round its periodic surface, cut into strips (recut._fused).

The cylinder's face under a helical ridge of 2 or more turns (tests/freecad/shapes.
helical_ridge) spans more than a period of its surface: with 3 turns its pcurves run
from u = -11.3 to 11.3, 3.6 periods. OCCT's general fuse cuts such a face wrongly:
along a helix midway between the ridge's turns, or along two lines of the cylinder's
axis, its pieces' areas add up to more than the face's, and some pieces are not valid;
with 2 turns its pieces add up, but OCCT's distance then puts points of the junction's
edges on the piece between the turns, which was dropped as under the fillet. It cuts a
face that spans at most half a period correctly.

So the face's domain is cut here in its own parameter plane: its wires' pcurves are laid
in the plane z = 0, and OCCT's general fuse cuts that planar face, where nothing winds,
along lines across the winding direction at most half a period apart (through the
face's vertices where they can be). Each planar piece then becomes a face on the
surface (a strip), bounded by the pieces of the face's own edges (split where the lines
cross them, so that they keep their vertices, whose tolerance covers gaps between the
pcurves: 5.7e-5 where the 3-turn ridge's junction meets the top face) and by edges
along the surface's iso-curves between the points where the lines cross those edges.
The strips are cut as any face is, and the pieces kept are merged again.

OCCT lays the pieces of the face's edges on the surface by projection. Its pcurve of
one may follow the edge's 3D curve closely but at other parameters (the 3-turn ridge's
junction between u = pi and 2 pi: 1.4e-8 off the curve, 1.8e-3 off at equal
parameters, so its tolerance became 2.4e-3). Such a piece is made again on the face's
own pcurve of its edge, restricted to the piece (whose 3D curve OCCT then computes from
it: within the edge's tolerance of the original).
"""

import FreeCAD
import Part

from .surface import winding

WINDS = 1e-3  # a face winds round its surface where it spans more than 1 + WINDS periods
EPS = 1e-6  # of a period: a cut this close to a domain's end would leave a sliver
SNAP = 1e-4  # largest gap, in the parameter plane, closed between a wire's pcurves
# a strip's edges, laid on the surface by OCCT's projection, or made again on the face's
# pcurves where that projection is off (see the module), may come this many times
# further off it than the face's own edges; else the strips are refused
LAID_TOL = 10.0
ISO_NODES = 16  # intervals of the interpolation of a curved iso-curve edge
ON = 1e-9  # a planar piece's edge lies on a pcurve or line within this; a strip's edge
# ends where a piece of the face's own edges does within this
# the strips' areas add up to the face's within this: OCCT's own area of a face is no
# closer (the 3-turn ridge's cylinder face: 462.838, 8.6e-4 over the closed form's
# 462.442, the band between two helices 2.4 apart in z on a cylinder r = 10, cut by the
# planes z = 0 and 12; the strips of the 2-turn one add up to its closed form to 7e-9)
AREA_REL = 2e-3


def needs_strips(face):
    """True where face winds round its surface by more than WINDS of a period (the pipe
    face of the helical ridge spans one period plus 5e-7 of one: it is cut whole)."""
    return winding(face, WINDS) is not None


def strips(face):
    """The pieces of `face` each within half a period of its surface, where it winds
    round it (needs_strips; else [face]): [Part.Face] with face's orientation, whose
    areas add up to face's. Raises ValueError saying what failed (a wire whose pcurves
    leave gaps wider than SNAP, OCCT's cut of the planar domain, a strip that bounds no
    valid face or whose edges OCCT lays off the surface)."""
    k = winding(face, WINDS)
    if k is None:
        return [face]
    s = face.Surface
    period = (s.UPeriod() if k == 0 else s.VPeriod())
    # the face's edges, their pcurves on it ((curve, first, last)), and those pcurves as
    # planar edges
    edges, pcurves, flat = [], [], []
    wires = []
    for w in _wires(face):
        es = list(w.OrderedEdges)
        pcs = [face.curveOnSurface(e)[:3] for e in es]
        edges += es
        pcurves += pcs
        wires.append(_flat_wire(es, pcs, flat))
    domain = Part.Face(wires[0])
    if len(wires) > 1:
        domain.cutHoles(wires[1:])
    box = domain.BoundBox
    lo, hi = (box.XMin, box.XMax) if k == 0 else (box.YMin, box.YMax)
    a, b = (box.YMin - 1.0, box.YMax + 1.0) if k == 0 else (box.XMin - 1.0, box.XMax + 1.0)
    cuts = _cuts(lo, hi, 0.5 * period, [v.Point.x if k == 0 else v.Point.y
                                  for w in wires for v in w.Vertexes])
    lines = [Part.LineSegment(*((FreeCAD.Vector(c, a, 0), FreeCAD.Vector(c, b, 0)) if k == 0
                                else (FreeCAD.Vector(a, c, 0), FreeCAD.Vector(b, c, 0))))
             .toShape() for c in cuts]
    try:
        pieces = domain.generalFuse(lines)[0].Faces
    except Exception as ex:  # FreeCAD's Part and OCCT errors come in several classes
        raise ValueError("cutting its domain into strips failed (%s)" % ex) from None
    if abs(sum(f.Area for f in pieces) - domain.Area) > AREA_REL * domain.Area:
        raise ValueError("its domain's strips do not make it up")
    limit = LAID_TOL * max([1e-7] + [e.Tolerance for e in edges])
    split = _split_edges(edges, flat, pieces)
    out = [_laid(s, k, f, flat, split, pcurves, face.Orientation, limit) for f in pieces]
    total = sum(f.Area for f in out)
    if abs(total - face.Area) > AREA_REL * face.Area:
        raise ValueError("its strips' areas add up to %.6g, not its %.6g" % (total, face.Area))
    return out


def _wires(face):
    """face's wires, its outer wire first."""
    return [face.OuterWire] + [w for w in face.Wires if not w.isSame(face.OuterWire)]


def _cuts(lo, hi, step, at):
    """Where to cut [lo, hi] so that no piece spans more than `step`: at the values
    `at` (the face's vertices) where they can be, so that fewer of the face's edges are
    split at new vertices, else `step` on from the last cut."""
    inner = sorted(x for x in at if lo + EPS * step < x < hi - EPS * step)
    out, last = [], lo
    while hi - last > step:
        reach = [x for x in inner if last + EPS * step < x <= last + step]
        last = reach[-1] if reach else last + step
        out.append(last)
    return out


def _flat_wire(edges, pcurves, flat):
    """The wire of a face's `edges` (in order) as a closed wire in the plane z = 0 of
    their `pcurves` on the face ((curve, first, last) per edge; u, v as x, y, each with
    its edge's parameters), gaps between consecutive pcurves (up to SNAP; the face's
    tolerance allows them) closed by moving their ends together. Appends each planar
    curve to `flat`."""
    curves = []
    for e, (c2d, a, b) in zip(edges, pcurves):
        curves.append((c2d.toBSpline(a, b), e.Orientation == "Reversed"))
    for (c, rc), (d, rd) in zip(curves, curves[1:] + curves[:1]):
        i, j = (1 if rc else c.NbPoles), (d.NbPoles if rd else 1)  # c's end, d's start
        p, q = c.getPole(i), d.getPole(j)
        if (p - q).length() > SNAP:
            raise ValueError("its pcurves leave a gap of %.2g in its parameter plane"
                             % (p - q).length())
        m = (p + q) * 0.5
        c.setPole(i, m)
        d.setPole(j, m)
    out = []
    for c, _ in curves:
        g = Part.BSplineCurve()
        g.buildFromPolesMultsKnots([FreeCAD.Vector(p.x, p.y, 0) for p in c.getPoles()],
                                   c.getMultiplicities(), c.getKnots(), False, c.Degree,
                                   c.getWeights())
        flat.append(g)
        out.append(g.toShape())
    wire = Part.Wire(out)
    if not wire.isClosed():
        raise ValueError("its pcurves do not make a closed wire")
    return wire


def _source(e, flat):
    """Index in `flat` of the planar curve that the planar edge e lies on, or None (it
    lies on a cutting line)."""
    a, b = e.FirstParameter, e.LastParameter
    m = e.valueAt(0.5 * (a + b))
    for i, g in enumerate(flat):
        if g.FirstParameter <= a <= g.LastParameter and \
                (g.value(0.5 * (a + b)) - m).Length <= ON:
            return i
    return None


def _split_edges(edges, flat, pieces):
    """{(index of an edge of `edges`, first parameter, last parameter): the piece of
    that edge between them}: each edge split, keeping its vertices, at the parameters
    where the planar `pieces`' edges on its pcurve (flat) end."""
    cuts = {}
    for f in pieces:
        for e in f.Edges:
            i = _source(e, flat)
            if i is not None:
                cuts.setdefault(i, set()).update((e.FirstParameter, e.LastParameter))
    out = {}
    for i, ts in cuts.items():
        ts = sorted(ts)
        inner = ts[1:-1]
        parts = edges[i].split(inner).Edges if inner else [edges[i]]
        for t0, t1 in zip(ts, ts[1:]):
            piece = min(parts, key=lambda x: abs(x.FirstParameter - t0)
                        + abs(x.LastParameter - t1))
            out[(i, t0, t1)] = piece
    return out


def _laid(surface, k, flat_face, flat, split, pcurves, orientation, limit):
    """The face on `surface` whose domain is the planar face `flat_face` (u, v as x, y;
    k: 0 where u winds, 1 where v does): bounded by the pieces (split) of the original
    face's edges where flat_face's edges lie on their pcurves (flat), and by edges along
    the surface's iso-curves elsewhere (the cutting lines, _along), with `orientation`.
    A piece that OCCT's projection lays further than `limit` off the surface is made
    again on its edge's pcurve (pcurves: the face's, (curve, first, last) by edge
    index), and the face with
    it. Raises ValueError where the face is not valid, or an edge stays further than
    `limit` off the surface."""
    wires = []  # per wire: [(key of split or None, edge)]
    for w in _wires(flat_face):
        ordered = list(w.OrderedEdges)
        keys = [_source(e, flat) for e in ordered]
        keys = [None if i is None else (i, e.FirstParameter, e.LastParameter)
                for i, e in zip(keys, ordered)]
        ends = [v.Point for key in keys if key is not None for v in split[key].Vertexes]
        wires.append([(key, split[key] if key is not None else _along(surface, k, e, ends))
                      for key, e in zip(keys, ordered)])
    out = _bounded(surface, wires)
    off = [e for e in out.Edges if e.Tolerance > limit]
    if off:
        def remade(key, e):
            if key is None or not any(_same_ends(e, x) for x in off):
                return e
            i, t0, t1 = key
            return pcurves[i][0].toShape(surface, t0, t1)
        out = _bounded(surface, [[(key, remade(key, e)) for key, e in w] for w in wires])
    worst = max(e.Tolerance for e in out.Edges)
    if worst > limit:
        raise ValueError("an edge of a strip of it lies %.2g off its surface (laid on it "
                         "by projection)" % worst)
    out.Orientation = orientation
    return out


def _bounded(surface, wires):
    """The valid face on `surface` bounded by `wires` ([(key, edge or None)], the outer
    wire first), its edges' pcurves projected by OCCT where they have none on it.
    Raises ValueError where it is not valid."""
    made = [Part.Wire([e for _, e in w if e is not None]) for w in wires]
    out = Part.Face(surface, made[0])
    if len(made) > 1:
        out.cutHoles(made[1:])
    out.validate()
    if not out.isValid():
        raise ValueError("a strip of it bounds no valid face")
    return out


def _same_ends(a, b):
    """True where edges a and b end at the same points (either way round), to 1e-9."""
    p, q = [v.Point for v in a.Vertexes], [v.Point for v in b.Vertexes]
    if len(p) != len(q):
        return False
    return all((x - y).Length <= ON for x, y in zip(p, q)) or \
        all((x - y).Length <= ON for x, y in zip(p, reversed(q)))


def _along(surface, k, e, ends):
    """The edge along a cutting line of the planar edge e (a line across the winding
    direction k), between the points of `ends` (the ends of the strip's other edges)
    nearest to its ends, on the surface's iso-curve there: a segment where that is a
    line (a cylinder's or a cone's), else a B-spline through ISO_NODES + 1 of its points;
    None where the two ends are one point."""
    uv = [(v.Point.x, v.Point.y) for v in e.Vertexes]
    p, q = (min(ends, key=lambda x: (x - surface.value(*w)).Length) if ends
            else surface.value(*w) for w in uv)
    if (p - q).Length == 0:
        return None
    c = uv[0][k]
    iso = surface.uIso(c) if k == 0 else surface.vIso(c)
    if isinstance(iso, Part.Line):
        return Part.LineSegment(p, q).toShape()
    t0, t1 = uv[0][1 - k], uv[1][1 - k]
    pts = [iso.value(t0 + (t1 - t0) * j / ISO_NODES) for j in range(1, ISO_NODES)]
    curve = Part.BSplineCurve()
    curve.interpolate([p] + pts + [q])
    return curve.toShape()


def merged(pieces):
    """The faces that `pieces` (cut from the strips of one face) make up, joined again
    where they meet along the strips' cutting lines (OCCT's unification of faces on one
    surface, on copies: sewing rewrites the faces' edges), so that the filleted solid
    holds the face whole, not cut along lines that are no edges of the part. The
    pieces as they are where that unification fails, or gives faces that are not valid
    or do not add up to them."""
    if len(pieces) < 2:
        return pieces
    sewn = Part.Compound([f.copy() for f in pieces])
    sewn.sewShape()
    try:
        out = sewn.removeSplitter().Faces
    except Exception:  # noqa: BLE001 - OCCT's, in several classes: keep the pieces
        return pieces
    area = sum(f.Area for f in pieces)
    if not out or not all(f.isValid() for f in out) or \
            abs(sum(f.Area for f in out) - area) > AREA_REL * area:
        return pieces
    return out
