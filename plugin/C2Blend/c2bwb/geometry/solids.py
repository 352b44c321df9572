# SPDX-License-Identifier: LGPL-2.1-or-later
"""Fillets on a compound of several solids, as OCCT's makeFillet makes them: each solid
with selected edges is filleted on its own (fillet.py), the others are kept, and the
results form a compound in the same order (wires, edges and vertices in the compound
follow them, unchanged). The report is one, and every element it names (the selected
edges, the faces of the input, the faces and edges of the result) is named as in the
compound, the way FreeCAD's selection names it."""
import re

import Part

from ..errors import C2BlendError
from . import check as ck


def _leaves(shape):
    """The shapes in a compound that are not compounds themselves, nested ones opened."""
    for c in shape.childShapes():
        if c.ShapeType == "Compound":
            yield from _leaves(c)
        else:
            yield c


def separate(shape):
    """(solids, others) when `shape` is a compound of two or more solids, or of one with
    wires, edges or vertices beside it (others, kept in the result as they are), whose
    solids share no face or edge, and with no face outside them; None otherwise: one
    solid, or a shape that inputs.check_solid refuses, saying why."""
    if shape.isNull() or shape.ShapeType not in ("Compound", "CompSolid"):
        return None
    solids = shape.Solids
    others = [c for c in _leaves(shape) if c.ShapeType not in ("Solid", "CompSolid")]
    if any(c.ShapeType in ("Face", "Shell") for c in others) or not solids or \
            (len(solids) == 1 and not others):
        return None
    for kind in ("Faces", "Edges"):
        shared = {x.hashCode() for s in solids for x in getattr(s, kind)}
        if len(shared) != sum(len(getattr(s, kind)) for s in solids):
            return None
    return solids, others


def _offsets(shapes, kind):
    """The number of elements (kind: 'Faces' or 'Edges') before each of shapes, in the
    compound of them."""
    out, n = [], 0
    for s in shapes:
        out.append(n)
        n += len(getattr(s, kind))
    return out


def _shifted(name, offset):
    """'Face3' shifted by 5 is 'Face8'."""
    kind, k = re.fullmatch(r"([A-Za-z]+)(\d+)", name).groups()
    return "%s%d" % (kind, int(k) + offset)


def _input_faces(text, offset):
    """text with each 'FaceK of the original solid' (a face of one solid, as fillet's
    messages name them) renamed as the compound's face."""
    return re.sub(r"\bFace(\d+)(?= of the original solid)",
                  lambda m: "Face%d" % (int(m.group(1)) + offset), text)


def _renamed(rep, faces_in, faces_out, edges_out):
    """A solid's fillet report with its element names made the compound's: faces of the
    input in reasons (offset faces_in), faces and edges of the result in the continuity
    checks (offsets faces_out, edges_out). The selected edges are named as the
    compound's already."""
    for key in ("trimlines", "mitres", "junctions"):
        for r in rep[key]:
            r["edge"] = _shifted(r["edge"], edges_out)
            r["faces"] = [_shifted(f, faces_out) for f in r["faces"]]
    for r in rep["corner_patches"]:
        r["face"] = _shifted(r["face"], faces_out)
    for k in rep["kept_occt_faces"]:
        k["reason"] = _input_faces(k["reason"], faces_in)
    return rep


def fillet_each(parts, names, label, fillet_one, check_one):
    """Fillet the selected edges `names` ([(name in the compound, Part.Edge)]) of a
    compound of parts = (solids, others) (separate()): fillet_one(solid, its names) ->
    (solid, report) for each solid with edges, after check_one(solid, where) (which
    raises for a solid inside out). Returns (Part.Compound of the solids in their order,
    then the others, report): the reports' lists joined, the worst verdict, the volumes
    and times summed (fillet() sets the whole "seconds"), and "solids": [{"solid":
    number in the compound, "edges", "verdict", "solid_check"}]. A C2BlendError of one
    solid is raised with its faces named as the compound's."""
    solids, others = parts
    owner = [next(i for i, s in enumerate(solids) if any(e.isSame(x) for x in s.Edges))
             for _, e in names]
    faces_in = _offsets(solids, "Faces")
    out, done = [], []  # the solids of the result; (index, report) of those filleted
    for i, s in enumerate(solids):
        mine = [n for n, k in zip(names, owner) if k == i]
        if not mine:
            out.append(s)
            continue
        check_one(s, "%s, solid %d" % (label, i + 1))
        try:
            solid, rep = fillet_one(s, mine)
        except C2BlendError as ex:
            raise C2BlendError(_input_faces(ex.message, faces_in[i]), ex.where,
                               ex.kind) from None
        out.append(solid)
        done.append((i, rep))
    result = Part.Compound(out + others)
    faces_out, edges_out = _offsets(out, "Faces"), _offsets(out, "Edges")
    reports = [(i, _renamed(rep, faces_in[i], faces_out[i], edges_out[i]))
               for i, rep in done]
    first = reports[0][1]
    merged = {k: first[k] for k in ("continuity", "radius", "shape_params", "tension")}
    for key in ("blends", "kept_occt_faces", "trimlines", "mitres", "junctions",
                "corner_patches"):
        merged[key] = [x for _, rep in reports for x in rep[key]]
    lines = [rep["solid_check"] for _, rep in reports]
    merged["solid_check"] = lines[0] if len(set(lines)) == 1 else "; ".join(
        "solid %d: %s" % (i + 1, rep["solid_check"]) for i, rep in reports)
    untouched = sum(s.Volume for i, s in enumerate(solids) if i not in dict(reports))
    merged["volume"] = result.Volume
    merged["tolerance"] = {k: max(rep["tolerance"][k] for _, rep in reports)
                           for k in first["tolerance"]}
    merged["exchange"] = {k: (max if k.endswith("gap") else sum)(
        rep["exchange"][k] for _, rep in reports) for k in first["exchange"]}
    merged["occt_volume"] = untouched + sum(rep["occt_volume"] for _, rep in reports)
    merged["occt_seconds"] = sum(rep["occt_seconds"] for _, rep in reports)
    merged["stage_seconds"] = {k: sum(rep["stage_seconds"][k] for _, rep in reports)
                               for k in first["stage_seconds"]}
    merged["verdict"] = min((rep["verdict"] for _, rep in reports), key=ck.RANK.get)
    merged["solids"] = [{"solid": i + 1, "edges": ["%s.%s" % (label, n) for n, k
                                                   in zip((n for n, _ in names), owner)
                                                   if k == i],
                         "verdict": rep["verdict"], "solid_check": rep["solid_check"]}
                        for i, rep in reports]
    return result, merged
