#!/bin/sh
# The demo: blend the thesis' two cylinders (eqs. 130-131, Table 4), print the result
# summary and write out/demo.csv and out/demo.png; then fillet a shaft on a plate with the
# workbench's code, headless, and write out/demo.step and out/demo_report.json.
set -eu
BUILD=${1:-build}
C2B="$BUILD/tools/c2blend"
SPEC=examples/thesis_eq130_131.json
mkdir -p out
"$C2B" info "$SPEC" > out/demo_info.json.tmp && mv out/demo_info.json.tmp out/demo_info.json
PY=${PYTHON:-/usr/bin/python3}
"$PY" - out/demo_info.json <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
print("C2Blend demo: %s" % d["name"])
print("  %s blend, t = %g, v in [%g, %g]%s" % (d["continuity"], d["time"], d["v_range"][0],
      d["v_range"][1], ", periodic" if d["periodic"] else ""))
for c in d["components"]:
    modes = ", ".join("%s%s" % (m["kind"], "(omega=%.4g, beta=%.4g)" % (m["omega"], m["beta"])
                      if "omega" in m else "^%d" % m["power"]) for m in c["modes"])
    print("  %s: shape %s; modes: %s" % (c["component"], c["shape"], modes or "none"))
print("  largest boundary-system condition estimate: %.3g" % d["max_condition"])
print("  truncation error of the boundary data expansion: %.3g" % d["truncation_error"])
print("  boundary data reproduced (max |d^k S/du^k - C_k| over 101 v per trimline):")
for r in d["boundary_residuals"]:
    print("    %-3s %-5s %.2e   (data scale %.3g)" % (r["side"], r["datum"], r["max_abs"], r["data_scale"]))
t = d["time_ms"]
print("  time: projection %.3f ms, modes %.3f ms, solve %.3f ms" % (t["projection"], t["modes"], t["solve"]))
PY
"$C2B" check "$SPEC" --table > out/demo_check.json.tmp && mv out/demo_check.json.tmp out/demo_check.json
"$PY" - out/demo_check.json <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
print("  continuity report (c2blend check, %d matched points per trimline):" % d["trimlines"][0]["samples"])
for t in d["trimlines"]:
    tb = t["table"]
    print("    u=%d: %s / %s   G0 %.1e  G1 %.1e rad  G2 %.1e (relative)   "
          "curvature along/across: blend (%.4g, %.4g), primary (%.4g, %.4g)"
          % (t["side"], t["verdict"], t["parametric_verdict"], t["g0_max"], t["g1_max_rad"],
             t["g2_max_rel"], tb["blend"][0], tb["blend"][1], tb["primary"][0], tb["primary"][1]))
PY
"$C2B" eval "$SPEC" --u 41 --v 65 > out/demo.csv.tmp && mv out/demo.csv.tmp out/demo.csv
echo "  wrote out/demo.csv (41 x 65 grid, u then v), out/demo_info.json and out/demo_check.json"
if "$PY" tools/plot_mesh.py "$SPEC" -o out/demo.png --c2blend "$C2B" --width 0.15 > /dev/null 2>&1; then
  echo "  wrote out/demo.png"
fi
echo
# The workbench's main job, headless: a G2 fillet on a real solid, its continuity report,
# and the check of OCCT's own (G1) fillet of the same edge; writes out/demo.step.
HOME=$(mktemp -d) PYTHONPATH="plugin/C2Blend:$BUILD/plugin/ext" "$PY" examples/macro_c2_fillet.py out
