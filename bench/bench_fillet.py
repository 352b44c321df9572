"""End-to-end C2 fillet against OCCT's makeFillet on the same edges, in the same run.

Prints markdown rows (median of repeated runs) with the ratio C2Blend / OCCT, and the
C2Blend time split into stages. Target of issue 5: ratio <= 2 for the shaft-on-plate
edge. A second peer is OCCT's fillet followed by the checks that every C2Blend result
gets (BRepCheck through isValid, and OCCT's BOP argument check, Shape.check(True)), in
this process: it says how much of the ratio is validation that OCCT's fillet skips.
Run: ctest -L bench (or make bench).
"""
import os
import statistics
import sys
import time

sys.path.append("/usr/lib/freecad-python3/lib")
import FreeCAD  # noqa: E402,F401  (initialises FreeCAD before Part is imported)

sys.path.append(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "freecad"))
import shapes  # noqa: E402
from c2bwb.geometry import fillet as fl  # noqa: E402

REPEAT = int(os.environ.get("C2B_BENCH_REPEAT", "15"))


def median_time(fn):
    ts = []
    for _ in range(REPEAT):
        t = time.perf_counter()
        out = fn()
        ts.append(time.perf_counter() - t)
    return statistics.median(ts), out


def occt_checked(shape, radius, edges):
    """OCCT's fillet, then BRepCheck and OCCT's BOP check of it (raises if either fails)."""
    result = shape.makeFillet(radius, edges)
    if not result.isValid():
        raise RuntimeError("OCCT's fillet is not valid")
    result.check(True)
    return result


CASES = [("box edge, R = 2", lambda: (shapes.box(), "Edge1"), 2.0),
         ("shaft on plate, R = 2", shapes.shaft_on_plate, 2.0),
         ("loft (B-spline) / plane, R = 1.5", shapes.loft, 1.5),
         ("pipe tee (2 edges, one chain), R = 1", shapes.pipe_tee, 1.0)]

print("| fillet | OCCT makeFillet (ms) | C2Blend (ms) | ratio | OCCT + validity checks (ms) | ratio to it "
      "| solve+fit | sew+BRepCheck | G2 check | verdict |")
print("|---|---|---|---|---|---|---|---|---|---|")
for name, make, radius in CASES:
    shape, edges = make()
    edges = [edges] if isinstance(edges, str) else edges
    es = [shape.getElement(e) for e in edges]
    t_occt, _ = median_time(lambda: shape.makeFillet(radius, es))
    t_checked, _ = median_time(lambda: occt_checked(shape, radius, es))
    t_c2, (solid, rep) = median_time(lambda: fl.fillet(shape, edges, radius))
    st = rep["stage_seconds"]
    print("| %s | %.2f | %.1f | %.0fx | %.2f | %.0fx | %.1f ms | %.1f ms | %.1f ms | %s |"
          % (name, 1e3 * t_occt, 1e3 * t_c2, t_c2 / t_occt, 1e3 * t_checked, t_c2 / t_checked,
             1e3 * st["trimlines_solve_fit"],
             1e3 * st["sew_and_brepcheck"], 1e3 * st["continuity_check"], rep["verdict"]))
