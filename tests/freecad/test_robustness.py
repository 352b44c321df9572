"""FreeCAD robustness (issue 7): the workbench's operations driven with bad selections and
bad parameters. After each, the document's object list and every shape (BREP text hash
and volume) must be unchanged, and the error must name the object and sub-element."""
import math
import re

import FreeCAD
import Part
import pytest

import shapes
from c2bwb.errors import C2BlendError
from c2bwb.geometry import assembly, fillet as fl
from c2bwb.objects import make


@pytest.fixture(params=[0, 1], ids=["undo_off", "undo_on"])
def doc(request):
    """Documents made by scripts and freecadcmd have UndoMode 0, where aborting a
    transaction undoes nothing; the GUI's have 1."""
    d = FreeCAD.newDocument("Robust")
    d.UndoMode = request.param
    box = d.addObject("Part::Box", "Box")
    box.Length = box.Width = box.Height = 10
    s, _ = shapes.shaft_on_plate()
    sp = d.addObject("Part::Feature", "ShaftPlate")
    sp.Shape = s
    sheet = d.addObject("Part::Feature", "Sheet")
    sheet.Shape = Part.makeBox(10, 10, 10).Faces[0]
    d.addObject("Part::Feature", "Pair").Shape = Part.makeCompound(
        [Part.makeBox(10, 10, 10), Part.makeBox(10, 10, 10, FreeCAD.Vector(20, 0, 0))])
    d.addObject("Part::Feature", "OpenBox").Shape = Part.Shell(Part.makeBox(10, 10, 10).Faces[:5])
    b = Part.makeBox(10, 10, 10)
    d.addObject("Part::Feature", "Rounded").Shape = b.makeFillet(2.0, [b.Edges[0]])
    d.addObject("Part::Feature", "Inverted").Shape = b.reversed()
    d.addObject("Part::Feature", "ClosedShell").Shape = Part.Shell(Part.makeBox(10, 10, 10).Faces)
    d.addObject("Part::Feature", "Glued").Shape = Part.makeBox(10, 10, 10).generalFuse(
        [Part.makeBox(10, 10, 10, FreeCAD.Vector(10, 0, 0))])[0]  # sharing a face
    d.addObject("Part::Feature", "Misoriented").Shape = shapes.misoriented_box()
    # a solid whose shell is open (as a failed Boolean can leave): the box without its top
    d.addObject("Part::Feature", "OpenSolid").Shape = Part.Solid(
        Part.Shell(Part.makeBox(10, 10, 10).Faces[:5]))
    d.recompute()
    yield d
    FreeCAD.closeDocument(d.Name)


BAD_FILLETS = [
    # (object, edges, radius, kwargs, message fragment)
    ("Box", ["Face2"], 2.0, {}, r"Box\.Face2: Face2 is not an edge"),
    ("Box", ["Vertex1"], 2.0, {}, r"Box\.Vertex1: Vertex1 is not an edge"),
    ("Box", ["Edge99"], 2.0, {}, r"Box\.Edge99: no such edge \(the shape has 12 edges\)"),
    ("Box", [], 2.0, {}, r"Box: no edges given"),
    ("Sheet", ["Edge1"], 1.0, {}, r"Sheet\.Edge1: the edge has 1 adjacent face"),
    ("Box", ["Edge1"], -1.0, {}, r"Box: radius must be a positive number, got -1\.0"),
    ("Box", ["Edge1"], math.nan, {}, r"Box: radius must be a positive number"),
    ("Box", ["Edge1"], math.inf, {}, r"Box: radius must be a positive number"),
    ("Box", ["Edge1"], 0.0, {}, r"Box: radius must be a positive number"),
    ("Box", ["Edge1"], 20.0, {}, r"Box\.Edge1: OCCT's rolling-ball fillet of radius 20 failed"),
    ("Box", ["Edge1"], 1e-12, {}, r"Box\.Edge1: OCCT's rolling-ball fillet of radius 1e-12 "
     r"failed .*; radius 1e-12 is too small here: OCCT accepts "),
    ("Box", ["Edge1"], 1e-5, {}, r"Box\.Edge1: radius 1e-05 is too small: OCCT's fillet of it "
     r"cannot be told apart from the faces it joins"),
    ("Box", ["Edge1"], "2", {}, r"Box: radius must be a positive number, got '2'"),
    ("Box", ["Edge1"], 2.0, {"shape_params": None},
     r"Box: shape_params: C2 takes 4 shape parameters .*, a sequence of numbers, got None"),
    ("Box", ["Edge1"], 2.0, {"continuity": ["C2"]}, r"Box: continuity must be C1, C2 or C3"),
    ("Box", ["Edge1"], 2.0, {"tension": None}, r"Box: tension must be a positive number"),
    ("Box", [True], 2.0, {}, r"Box: True is not an edge"),
    ("Inverted", ["Edge1"], 2.0, {}, r"Inverted: the solid is inside out: its faces point "
     r"inwards \(volume -1000\)"),
    ("Box", ["Edge1"], 2.0, {"continuity": "C9"}, r"Box: continuity must be C1, C2 or C3"),
    ("Box", ["Edge1"], 2.0, {"tension": 0.0}, r"Box: tension must be a positive number"),
    ("Box", ["Edge1"], 2.0, {"tension": math.nan}, r"Box: tension must be a positive number"),
    ("Box", ["Edge1"], 2.0, {"shape_params": (2, 1, 1)},
     r"Box: shape_params: C2 takes 4 shape parameters \(gamma, eta, lambda, rho\), got 3"),
    ("Box", ["Edge1"], 2.0, {"shape_params": (1, math.inf, 1, 1)},
     r"Box: shape_params: shape parameters must be finite"),
    ("Box", ["Edge1", "Edge2", "Edge3"], 6.0, {}, r"Box\.Edge1, Box\.Edge2, Box\.Edge3: "),
    ("Pair", ["Edge1"], 20.0, {}, r"Pair\.Edge1: OCCT's rolling-ball fillet of radius 20 "
     r"failed"),  # its first solid's error, the compound's edge named
    ("Pair", ["Edge13"], 2.0, {"tension": 0.0}, r"Pair: tension must be a positive number"),
    ("Glued", ["Edge1"], 2.0, {}, r"Glued: the shape is a Compound of 2 solids that share "
     r"faces or edges \(as a CompSolid's do\), so a fillet of one would change another: make "
     r"one solid of them \(Part > Boolean > Union\), or separate them"),
    ("OpenBox", ["Edge1"], 2.0, {}, r"OpenBox: the shape is a Shell with 0 solid\(s\) and 5 "
     r"face\(s\) outside them; a fillet needs one closed solid; faces with free edges bound no "
     r"volume: close the shell first"),
    ("ClosedShell", ["Edge1"], 2.0, {}, r"ClosedShell: the shape is a Shell with 0 solid\(s\) "
     r"and 6 face\(s\) outside them; a fillet needs one closed solid; its faces close up: make "
     r"them a solid first \(Part > Convert to solid"),
    ("Misoriented", ["Edge10"], 2.0, {}, r"Misoriented: OCCT's rolling-ball fillet failed "
     r"\(the result is not a valid solid\) on a solid that is not valid itself \(isValid\(\) "
     r"is False\): repair it first; .* shape\.fix\(1e-7, 1e-7, 1e-7\) mends faults such as "
     r"a face oriented against the rest of its shell$"),
    ("OpenSolid", [lambda s: next(  # an edge of the open top: one face
        "Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
        if len(s.ancestorsOfType(e, Part.Face)) == 1)],
     2.0, {}, r"OpenSolid\.Edge\d+: the edge has 1 adjacent face; a fillet needs exactly 2 "
     r"\(it is a free edge of the solid's shell, which is open there, so the solid is not "
     r"closed and not valid: repair or rebuild it first"),
    ("OpenSolid", [lambda s: next(  # a vertical edge, between two faces
        "Edge%d" % (i + 1) for i, e in enumerate(s.Edges) if e.BoundBox.ZLength > 5)],
     2.0, {}, r"^OpenSolid: the solid is not closed: its shell is open along Edge\d+, "
     r"Edge\d+, Edge\d+ and Edge\d+ \(edges with one face\), so it is not valid: repair "
     r"or rebuild it first"),
    ("Rounded", [lambda s: next(  # where OCCT's fillet meets a face, tangentially
        "Edge%d" % (i + 1) for i, e in enumerate(s.Edges) if isinstance(e.Curve, Part.Line)
        and any(isinstance(f.Surface, Part.Cylinder) for f in s.ancestorsOfType(e, Part.Face)))],
     1.0, {}, r"Rounded\.Edge\d+: the faces meet tangentially along the edge .* no corner to "
     r"fillet"),
    ("ShaftPlate", [lambda s: next(  # the shaft's seam: one face, joined to itself
        "Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
        if any(e.isSeam(f) for f in s.ancestorsOfType(e, Part.Face)))],
     2.0, {}, r"ShaftPlate\.Edge\d+: the edge is the seam of Face\d+, where that closed face "
     r"joins itself smoothly: there is no corner to fillet"),
]


@pytest.mark.parametrize("name,edges,radius,kw,fragment", BAD_FILLETS)
def test_bad_fillet_leaves_document_unchanged(doc, name, edges, radius, kw, fragment):
    before = shapes.document_state(doc)
    undo = doc.UndoCount
    obj = doc.getObject(name)
    edges = [e(obj.Shape) if callable(e) else e for e in edges]
    with pytest.raises(C2BlendError, match=fragment):
        make.make_fillet(obj, edges, radius, **kw)
    assert shapes.document_state(doc) == before
    assert doc.UndoCount == undo  # no transaction was left behind


def test_the_advice_for_a_misoriented_solid_mends_it():
    """The Misoriented solid of the table, mended as its message advises: valid, the
    box's volume again, and its fillet G2. Before the message was written, OCCT's failure
    on it was put down to the radius ("whatever the radius")."""
    s = shapes.misoriented_box()
    assert not s.isValid()
    s.fix(1e-7, 1e-7, 1e-7)
    assert s.isValid() and abs(s.Volume - 1000.0) < 1e-9
    solid, rep = fl.fillet(s, ["Edge10"], 2.0, label="Misoriented")
    assert solid.isValid() and rep["verdict"] == "G2"


BAD_BLENDS = [
    ((("Box", ["Face1"])), ("ShaftPlate", ["Face1", "Edge1"]), r"Edge1 needs one face and one of its edges"),
    ((("Box", ["Face1", "Edge5"])), ("ShaftPlate", ["Face1", "Edge1"]), r"Box\.Face1\+Edge5: the edge is not an edge of the selected face"),
    ((("Box", ["Face1", "Edge1"])), ("ShaftPlate", ["Face99", "Edge1"]), r"ShaftPlate\.Face99\+Edge1: no such face: Face99 \(ShaftPlate has \d+ faces\)$"),
    ((("Box", ["Face1", "Edge1x"])), ("ShaftPlate", ["Face1", "Edge1"]), r"Box\.Face1\+Edge1x: no such edge: Edge1x \(Box has 12 edges\)$"),
]


@pytest.mark.parametrize("side1,side2,fragment", BAD_BLENDS)
def test_bad_blend_leaves_document_unchanged(doc, side1, side2, fragment):
    before = shapes.document_state(doc)
    s1 = (doc.getObject(side1[0]), side1[1])
    s2 = (doc.getObject(side2[0]), side2[1])
    with pytest.raises(C2BlendError, match=fragment):
        make.make_blend(s1, s2)
    assert shapes.document_state(doc) == before


BAD_CHECKS = [
    ("Box", ["Face2"], r"Box\.Face2: Face2 is not an edge; select edges to check"),
    ("Box", ["Edge99"], r"Box\.Edge99: no such edge \(the shape has 12 edges\)"),
    ("Box", [], r"Box: no edges given"),
    ("Sheet", ["Edge1"], r"Sheet\.Edge1: the edge has 1 adjacent face; continuity is "
     r"measured between two faces$"),
    ("ShaftPlate", [lambda s: next(
        "Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
        if any(e.isSeam(f) for f in s.ancestorsOfType(e, Part.Face)))],
     r"ShaftPlate\.Edge\d+: the edge has 1 adjacent face; continuity is measured between two "
     r"faces \(it is the seam where that closed face joins itself\)"),
]


@pytest.mark.parametrize("name,edges,fragment", BAD_CHECKS)
def test_bad_check_names_the_edge_and_leaves_document_unchanged(doc, name, edges, fragment):
    """Check continuity, from a script and as a document object, on edges it cannot
    check: the message names the object and the edge."""
    import C2Blend
    obj = doc.getObject(name)
    edges = [e(obj.Shape) if callable(e) else e for e in edges]
    with pytest.raises(C2Blend.Error, match=fragment):
        C2Blend.check(obj.Shape, edges, label=name)
    before = shapes.document_state(doc)
    with pytest.raises(C2BlendError, match=fragment):
        make.make_check(obj, edges)
    assert shapes.document_state(doc) == before


def _box_sides():
    b = Part.makeBox(10, 10, 10)
    return b, b.Faces[0], next(e for e in b.Faces[0].Edges)


SCRIPT_MISUSE = [
    # (call on the box b (Part.makeBox(10, 10, 10)) and its Face1 f and an edge e of it,
    #  message fragment); each raised TypeError, ValueError, AttributeError or OCCT's
    #  "Shape is null", or returned a verdict having measured nothing (samples=0)
    (lambda C, b, f, e: C.fillet(b, None, 2, label="Box"),
     r"^Box: edges must be a list of Part\.Edge objects, 'EdgeN' names or 1-based indices, "
     r"got NoneType$"),
    (lambda C, b, f, e: C.fillet(None, ["Edge1"], 2, label="Box"),
     r"^Box: a Part shape is needed, got NoneType$"),
    (lambda C, b, f, e: C.fillet(b, ["Edge1"], None, label="Box"),
     r"^Box: radius must be a positive number, got None$"),
    (lambda C, b, f, e: C.fillet(b, ["Edge1"], 2, shape_params=1.0, label="Box"),
     r"^Box: shape_params: C2 takes 4 shape parameters"),
    (lambda C, b, f, e: C.radius_for_setback(b, ["Edge1"], None, label="Box"),
     r"^Box: setback must be a positive number, got None$"),
    (lambda C, b, f, e: C.check(b.makeFillet(2, [b.Edges[0]]), ["Edge2"], samples=0),
     r"^Shape: samples must be a whole number of at least 1, got 0$"),
    (lambda C, b, f, e: C.check(b, ["Edge2"], samples=10.5),
     r"^Shape: samples must be a whole number of at least 1, got 10\.5$"),
    (lambda C, b, f, e: C.blend(None, e, f, e, labels=("A.Face1", "B.Face1")),
     r"^A\.Face1: a Part\.Face and one of its Part\.Edge objects are needed, got NoneType "
     r"and Edge$"),
    # a string is a sequence of its letters: "AB" was taken for the names "A" and "B"
    (lambda C, b, f, e: C.blend(f, e, f, e, labels="AB"),
     r"^blend: labels must be two names, one per face, as \('Cylinder\.Face1', "
     r"'Tube\.Face3'\); got 'AB'$"),
    (lambda C, b, f, e: C.blend(f, e, f, e, labels=("A.Face1", "B.Face1", "C.Face1")),
     r"^blend: labels must be two names, .*; got \('A\.Face1', 'B\.Face1', 'C\.Face1'\)$"),
    (lambda C, b, f, e: C.blend(f, e, f, e, labels=None),
     r"^blend: labels must be two names, .*; got None$"),
    (lambda C, b, f, e: C.blend_solid([]),
     r"^blend: a list of Part\.Face objects is needed .*, got an empty list$"),
    (lambda C, b, f, e: C.blend_solid(b.Edges),
     r"^blend: a list of Part\.Face objects is needed .*, got a list of Edge$"),
    # an edge of a copy, or of an equal shape built again, lies where one of b's does
    (lambda C, b, f, e: C.fillet(b, [b.copy().Edges[2]], 2, label="Box"),
     r"^Box: the edge does not belong to the shape \(it lies where Edge3 of the shape "
     r"does: pass that shape's own edge, or its name 'Edge3'"),
    (lambda C, b, f, e: C.check(b, [Part.makeBox(10, 10, 10).Edges[5]], label="Box"),
     r"^Box: the edge does not belong to the shape \(it lies where Edge6 "),
    (lambda C, b, f, e: C.fillet(b, [b.translated(FreeCAD.Vector(1, 0, 0)).Edges[0]], 2,
                                 label="Box"),
     r"^Box: the edge does not belong to the shape$"),
]


@pytest.mark.parametrize("call,fragment", SCRIPT_MISUSE)
def test_scripting_misuse_raises_c2blend_errors(call, fragment):
    """Macros that pass the wrong kinds of arguments get C2Blend.Error naming the
    argument, not a Python or OCCT exception from deep inside."""
    import C2Blend
    b, f, e = _box_sides()
    with pytest.raises(C2Blend.Error, match=fragment):
        call(C2Blend, b, f, e)


def test_quantities_are_numbers():
    """A FreeCAD Quantity, as a length property gives (e.g. a C2Fillet's Radius), is a
    radius in mm."""
    import C2Blend
    b = Part.makeBox(10, 10, 10)
    a = C2Blend.fillet(b, ["Edge1"], FreeCAD.Units.Quantity("2 mm"))
    c = C2Blend.fillet(b, ["Edge1"], 2.0)
    assert abs(a.Volume - c.Volume) < 1e-9 * c.Volume
    assert C2Blend.radius_for_setback(b, ["Edge1"], FreeCAD.Units.Quantity("1.5 mm")) == \
        pytest.approx(1.5, rel=1e-12)


def test_single_and_repeated_edges_are_one_selection():
    """A single edge (object, name or index) stands for a list of one, and an edge given
    several ways is filleted once: the report names it once."""
    import C2Blend
    b = Part.makeBox(10, 10, 10)
    volumes = []
    for edges in (b.Edges[0], "Edge1", 1, ["Edge1", 1, b.Edges[0]]):
        solid, rep = C2Blend.fillet_report(b, edges, 2.0, label="Box")
        assert rep["verdict"] == "G2"
        assert [x["where"] for x in rep["blends"]] == ["Box.Edge1"]
        volumes.append(solid.Volume)
    assert max(volumes) - min(volumes) < 1e-9 * volumes[0]


def test_document_objects_store_the_edges_names(doc):
    """make_fillet and make_check take what the scripting API takes (a name, an index,
    a Part.Edge, or a list of them) and store the edges' names, once each: a single
    name was split into its letters ('E is not an edge'), and a Part.Edge could not be
    stored in the link."""
    box = doc.getObject("Box")
    f = make.make_fillet(box, "Edge1", 2.0)
    assert f.Base[1] == ["Edge1"] and f.Verdict == "G2"
    f2 = make.make_fillet(box, [box.Shape.Edges[0], 1, "Edge2"], 2.0)
    assert f2.Base[1] == ["Edge1", "Edge2"] and f2.Verdict == "G2"
    c = make.make_check(f, [3])
    assert c.Target[1] == ["Edge3"] and c.Verdict


def test_a_seam_among_the_edges_is_left_out_and_reported(doc):
    """The shaft's junction selected with the shaft's seam (as a box selection of the
    whole part picks it): the seam is left out, as OCCT's fillet leaves it out, instead
    of refusing the fillet. The object keeps the whole selection, and its report lists
    the seam ("left out of the fillet" in the Report view's lines). The seam alone is
    still refused (the bad-input table above)."""
    import json
    import C2Blend
    sp = doc.getObject("ShaftPlate")
    s = sp.Shape
    seam = next("Edge%d" % (i + 1) for i, e in enumerate(s.Edges)
                if any(e.isSeam(f) for f in s.ancestorsOfType(e, Part.Face)))
    junction = shapes.shaft_on_plate()[1]
    f = make.make_fillet(sp, [junction, seam], 2.0)
    assert f.Base[1] == [junction, seam] and f.Verdict == "G2"
    rep = json.loads(f.Report)
    assert [k["where"] for k in rep["skipped_edges"]] == ["ShaftPlate.%s" % seam]
    assert "seam of Face" in rep["skipped_edges"][0]["reason"]
    assert "ShaftPlate.%s: left out of the fillet: the edge is the seam" % seam in \
        C2Blend.format_report(rep)


@pytest.mark.parametrize("continuity,given,same", [
    ("C1", (0.1, 1.5, 0.5), (0.1, 1.5, 0.5)),
    ("C3", (0.1, 2.0, 2.0, 2.0, 2.0), (0.05, 1.0, 1.0, 1.0, 1.0))])
def test_document_object_with_c1_and_c3_shape_parameters(doc, continuity, given, same):
    """make_fillet takes C1's three and C3's five shape parameters. The object stores
    C3's divided by a4: the PDE is homogeneous in them, so (0.1, 2, 2, 2, 2) and
    (0.05, 1, 1, 1, 1) are the same blend. The object's shape must equal the scripting
    API's fillet with the second set, and differ from the default parameters' (on the
    shaft's circular junction: on a straight edge the data do not vary along it, and no
    shape parameter changes the blend)."""
    base, edge = doc.getObject("ShaftPlate"), shapes.shaft_on_plate()[1]
    obj = make.make_fillet(base, [edge], 2.0, continuity, given)
    ref = fl.fillet(base.Shape, [edge], 2.0, continuity, same)[0]
    default = fl.fillet(base.Shape, [edge], 2.0, continuity)[0]
    assert obj.Verdict == ("G1" if continuity == "C1" else "G2")
    assert abs(obj.Shape.Volume - ref.Volume) < 1e-9 * ref.Volume
    # relative volume changes: 8.0e-5 (C1) and 3.2e-6 (C3)
    assert abs(obj.Shape.Volume - default.Volume) > 1e-6 * ref.Volume
    with pytest.raises(C2BlendError, match=r"ShaftPlate: shape_params: .*divided by a4, which "
                       r"must not be 0"):
        make.make_fillet(base, [edge], 2.0, "C3", (1, 1, 1, 1, 0))


def _shape_of(doc, obj):
    """[(BREP hash, volume)] of obj's shape, from the document's fingerprint."""
    return [x[3:] for x in shapes.document_state(doc) if x[0] == obj.Name]


def test_failed_recompute_keeps_shape_and_undo_redo(doc):
    if doc.UndoMode == 0:
        pytest.skip("undo and redo need UndoMode 1")
    box = doc.getObject("Box")
    f = make.make_fillet(box, ["Edge1"], 2.0)
    good = shapes.document_state(doc)
    f.Radius = 30.0
    doc.recompute()
    assert "Invalid" in f.State and "too large" in f.Proxy.last_error
    assert _shape_of(doc, f) == [x[3:] for x in good if x[0] == f.Name]
    f.Radius = 2.0
    doc.recompute()
    assert shapes.document_state(doc) == good
    name = f.Name
    for _ in range(doc.UndoCount):  # back past the creation (one transaction)
        if name not in [o.Name for o in doc.Objects]:
            break
        doc.undo()
    assert [o.Name for o in doc.Objects] == ["Box", "ShaftPlate", "Sheet", "Pair", "OpenBox",
                                             "Rounded", "Inverted", "ClosedShell",
                                             "Glued", "Misoriented", "OpenSolid"]
    doc.redo()
    doc.recompute()
    assert doc.getObject(name).Shape.isValid()
    assert doc.getObject(name).Verdict == "G2"


def test_failed_sewing_leaves_document_unchanged(doc, monkeypatch):
    """A sewing that fails (injected) while a C2 Fillet is made: the error names the
    object and edge, and the document is left exactly as it was."""
    box = doc.getObject("Box")
    before, undo = shapes.document_state(doc), doc.UndoCount
    monkeypatch.setattr(assembly, "_sewn",
                        shapes.losing_far_face(assembly._sewn, box.Shape, box.Shape.Edge1))
    with pytest.raises(C2BlendError, match=r"^Box\.Edge1: sewing the blend faces .* failed"):
        make.make_fillet(box, ["Edge1"], 2.0)
    assert shapes.document_state(doc) == before
    assert doc.UndoCount == undo


def test_failed_sewing_on_recompute_keeps_the_previous_shape(doc, monkeypatch):
    """A C2 Fillet whose recompute fails in the sewing (injected) after its radius is
    changed keeps its previous shape and says why; once the fault is gone, the new radius
    is applied."""
    box = doc.getObject("Box")
    f = make.make_fillet(box, ["Edge1"], 2.0)
    good = _shape_of(doc, f)
    monkeypatch.setattr(assembly, "_sewn",
                        shapes.losing_far_face(assembly._sewn, box.Shape, box.Shape.Edge1))
    f.Radius = 3.0
    doc.recompute()
    assert "Invalid" in f.State
    assert re.match(r"Box\.Edge1: sewing the blend faces .* failed", f.Proxy.last_error)
    assert _shape_of(doc, f) == good
    monkeypatch.undo()
    f.touch()
    doc.recompute()
    assert "Invalid" not in f.State and f.Verdict == "G2" and f.Shape.isValid()
    # a larger radius takes more material away
    assert f.Shape.Volume < good[0][1]


def test_plugin_writers_are_atomic(tmp_path):
    """STEP/BREP frames are written to a temporary file and renamed: a failing write
    (the target is a directory; an unwritable folder) leaves no partial file, and an
    existing file is replaced only by a complete one."""
    from c2bwb.objects.animate import write_shape
    shape = Part.makeBox(1, 2, 3)
    target = tmp_path / "frame.step"
    write_shape(shape, str(target))
    first = target.read_bytes()
    assert b"ISO-10303-21" in first and Part.read(str(target)).isValid()
    (tmp_path / "dir.step").mkdir()
    with pytest.raises(C2BlendError, match=r"cannot write .*dir\.step"):
        write_shape(shape, str(tmp_path / "dir.step"))
    with pytest.raises(C2BlendError, match="cannot write"):
        write_shape(shape, str(tmp_path / "missing" / "x.brep"))
    write_shape(Part.makeBox(4, 5, 6), str(target))
    assert Part.read(str(target)).Volume == pytest.approx(120.0)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["dir.step", "frame.step"]


def test_a_frame_at_a_b_spline_sphere_s_pole_is_degenerate_not_an_error():
    """Near the pole of a B-spline sphere (toNurbs) S_u is rounding noise: the frame there
    is refused as degenerate (ValueError, which the contact tracing turns into a
    reason the fillet is kept), not FreeCAD's "Cannot normalize null vector", which
    escaped as an unexplained error from a part made B-splines. Away from the pole
    the normal is the sphere's, (p - centre) / r."""
    from c2bwb.geometry.surface import Frame
    face = Part.makeSphere(2.0).Faces[0].toNurbs().Faces[0]
    s = face.Surface
    v_top = s.bounds()[3]
    for dv in (0.0, 1e-16, 1e-15, 1e-12):
        with pytest.raises(ValueError, match="degenerate surface point"):
            Frame(face, 0.3, v_top - dv)
    for dv in (1e-6, 1e-3, 0.5):
        f = Frame(face, 0.3, v_top - dv)
        radial = f.p / f.p.Length
        assert f.p.Length == pytest.approx(2.0, abs=1e-12)
        assert f.n.getAngle(radial) < 1e-8
