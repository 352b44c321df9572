# Run by freecadcmd from the installed workbench (run_install.sh): the workbench, its
# module and its CGAL tool must come from the user's Mod folder, and a fillet work.
import os
import traceback

out = os.environ["C2B_INSTALL_RESULT"]
try:
    import FreeCAD
    import Part
    import C2Blend
    import c2blend
    from c2bwb.geometry import cgalcheck
    mod = os.path.join(FreeCAD.getUserAppDataDir(), "Mod", "C2Blend")
    for m in (C2Blend, c2blend):
        where = os.path.realpath(m.__file__)
        assert where.startswith(os.path.realpath(mod)), "%s from %s" % (m.__name__, where)
    tool = cgalcheck.find_tool()
    assert tool and os.path.realpath(tool).startswith(os.path.realpath(mod)), tool
    box = Part.makeBox(10, 10, 10)
    solid, rep = C2Blend.fillet_report(box, ["Edge1"], 2.0, label="Box")
    assert solid.isValid() and rep["verdict"] == "G2", rep["verdict"]
    msg = "ok installed workbench: %s, fillet %s, CGAL tool %s\n" % (
        os.path.dirname(C2Blend.__file__), rep["verdict"], os.path.basename(tool))
except Exception:
    msg = "failed\n" + traceback.format_exc()
with open(out, "w") as f:
    f.write(msg)
