# Run by freecadcmd (run_partdesign.sh): C2 Fillet in a PartDesign workflow, where users
# work. A Body's Pad (a 20 x 10 sketch rectangle) has its top front edge filleted
# (R = 2) by a C2Fillet object on the Pad and another on the Body; the Pad is then made
# taller, and both fillets follow on recompute; then its length is driven by a Clock
# and animated, a BREP per frame. Expected volumes are closed forms: the
# box less 20 times the area between the corner and the blend's quintic cross-section
# (test_workbench._corner_area). Writes "ok ..." or the failure to C2B_RESULT.
import os
import sys
import traceback

out = os.environ["C2B_RESULT"]
try:
    here = os.path.dirname(os.path.abspath(os.environ["C2B_PARTDESIGN_SCRIPT"]))
    sys.path[:0] = [os.path.join(here, "..", "..", "..", "plugin", "C2Blend"),
                    os.path.join(here, ".."), os.environ["C2B_MODULE_DIR"]]
    import FreeCAD
    import Part
    from c2bwb.objects import make
    from test_workbench import _corner_area

    V = FreeCAD.Vector
    doc = FreeCAD.newDocument("PartDesignFillet")
    body = doc.addObject("PartDesign::Body", "Body")
    sketch = body.newObject("Sketcher::SketchObject", "Sketch")
    corners = [V(0, 0, 0), V(20, 0, 0), V(20, 10, 0), V(0, 10, 0)]
    for a, b in zip(corners, corners[1:] + corners[:1]):
        sketch.addGeometry(Part.LineSegment(a, b))
    pad = body.newObject("PartDesign::Pad", "Pad")
    pad.Profile = sketch
    pad.Length = 8
    doc.recompute()
    front = next("Edge%d" % (i + 1) for i, e in enumerate(pad.Shape.Edges)
                 if e.BoundBox.ZMin > 8 - 1e-9 and e.BoundBox.YMax < 1e-9)
    fillets = [make.make_fillet(base, [front], 2.0) for base in (pad, body)]
    area = _corner_area(2.0)
    lines = []
    for height in (8.0, 12.0):
        pad.Length = height
        doc.recompute()
        expected = 20.0 * 10.0 * height - 20.0 * area
        for f in fillets:
            s = f.Shape
            assert "Invalid" not in f.State, (f.Name, f.State)
            assert f.Verdict == "G2", (f.Name, f.Verdict)
            assert s.isValid() and abs(s.BoundBox.ZMax - height) < 1e-9, f.Name
            assert abs(s.Volume - expected) < 1e-7 * expected, (f.Name, s.Volume, expected)
        lines.append("height %g: volume %.9g (closed form %.9g)" % (height, s.Volume,
                                                                   expected))
    # the Pad's length driven by a Clock through an expression, animated over 3 frames
    # (BREP per frame): each frame's fillets are G2 with the closed-form volume
    import tempfile
    from c2bwb.objects import animate
    clock = make.make_clock(doc)
    pad.setExpression("Length", "%s.Time * 4 mm + 8 mm" % clock.Name)
    folder = tempfile.mkdtemp(dir=os.path.dirname(out))  # removed with the run's folder
    frames = animate.animate(doc, clock, [0.0, 0.5, 1.0], fillets, folder, "brep")
    for frame in frames:
        assert set(frame["verdicts"].values()) == {"G2"}, frame
        height = 8.0 + 4.0 * frame["t"]
        expected = 20.0 * 10.0 * height - 20.0 * area
        for path in frame["files"]:
            v = Part.read(path).Volume
            assert abs(v - expected) < 1e-7 * expected, (path, v, expected)
    lines.append("animated by a Clock: %d frames, G2, volumes by the closed form"
                 % len(frames))
    msg = "ok PartDesign Pad filleted on the Pad and on the Body, G2; %s\n" % "; ".join(lines)
except Exception:
    msg = "failed\n" + traceback.format_exc()
with open(out, "w") as f:
    f.write(msg)
