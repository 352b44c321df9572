"""C2Blend macro: G2 fillet of a shaft on a plate, with its continuity report.

Inside FreeCAD (workbench installed): Macro > Macros... > Execute, or
    freecadcmd examples/macro_c2_fillet.py
Outside FreeCAD (what `make demo` runs):
    PYTHONPATH=plugin/C2Blend:build/plugin/ext /usr/bin/python3 examples/macro_c2_fillet.py out
It writes OUT/demo.step (the filleted solid) and OUT/demo_report.json, and prints the
report next to the check of OCCT's own rolling-ball fillet of the same edge.
"""
import json
import os
import sys
import time

if "/usr/lib/freecad-python3/lib" not in sys.path:
    sys.path.append("/usr/lib/freecad-python3/lib")
import FreeCAD  # noqa: E402
import Part  # noqa: E402

import C2Blend  # noqa: E402
from c2bwb.objects.animate import write_shape  # noqa: E402

V = FreeCAD.Vector
out = sys.argv[1] if len(sys.argv) > 1 and not sys.argv[1].endswith(".py") else "out"
os.makedirs(out, exist_ok=True)

# the part: a shaft (r = 5) fused on a 40 x 40 x 5 plate; fillet the circular junction
plate = Part.makeBox(40, 40, 5, V(-20, -20, -5))
part = plate.fuse(Part.makeCylinder(5, 20)).removeSplitter()
junction = [e for e in part.Edges
            if isinstance(e.Curve, Part.Circle) and abs(e.Curve.Center.z) < 1e-9]

solid, report = C2Blend.fillet_report(part, junction, 2.0, continuity="C2", label="ShaftPlate")
write_shape(solid, os.path.join(out, "demo.step"))
with open(os.path.join(out, "demo_report.json.tmp"), "w") as f:
    json.dump(report, f, indent=1, default=float)
os.replace(os.path.join(out, "demo_report.json.tmp"), os.path.join(out, "demo_report.json"))

print("C2 fillet of ShaftPlate, R = 2: valid solid %s, volume %.4f (OCCT's fillet: %.4f)"
      % (solid.isValid(), solid.Volume, report["occt_volume"]))
for b in report["blends"]:
    print("  blend %s: %s, %d samples per trimline, data error %.1e, B-spline %d x %d poles, "
          "fit deviation %.1e (tolerance %.1e)"
          % (b["where"], "closed" if b["closed"] else "open", b["samples"], b["data_error"],
             b["poles"][0], b["poles"][1], b["fit_deviation"], b["fit_tolerance"]))
print("  continuity across the trimlines (%d samples each): %s"
      % (report["trimlines"][0]["samples"], report["verdict"]))
print("    " + C2Blend.format_report(report).replace("\n", "\n    "))
t0 = time.perf_counter()
rolling = part.makeFillet(2.0, junction)
t_occt = time.perf_counter() - t0
occt_edges = [e for e in rolling.Edges
              if len(rolling.ancestorsOfType(e, Part.Face)) == 2
              and any(f.Surface.__class__.__name__ == "Toroid"
                      for f in rolling.ancestorsOfType(e, Part.Face))
              and not e.isSeam(rolling.ancestorsOfType(e, Part.Face)[0])]
occt = C2Blend.check(rolling, occt_edges)
print("  OCCT's rolling-ball fillet of the same edge: %s" % occt["verdict"])
print("    " + C2Blend.format_report(occt).replace("\n", "\n    "))
# the first fillet of a session also starts the check server (bopcheck.py)
print("  time: %.0f ms (OCCT's makeFillet alone %.1f ms); wrote %s/demo.step and "
      "%s/demo_report.json" % (1e3 * report["seconds"], 1e3 * t_occt, out, out))
