#!/bin/sh
# GUI test: real FreeCAD under Xvfb with the workbench installed in a temporary user
# Mod folder. Usage: run_gui.sh MODULE_DIR OUT_DIR [CGAL_TOOL]. Fails unless the fillet is G2, the
# curvature map is shown and the screenshot is not blank.
set -eu
MODDIR=$1
OUT=$2
export C2B_CGAL_TOOL="${3:-}"
HERE=$(cd "$(dirname "$0")" && pwd)
SRC=$(cd "$HERE/../../.." && pwd)
mkdir -p "$OUT"
HOME=$(mktemp -d)
TMPDIR=$HOME   # FreeCAD's Start page leaves a FreeCADStartThumbnails folder in TMPDIR
export HOME TMPDIR
trap 'rm -rf "$HOME"' EXIT
MOD="$HOME/.local/share/FreeCAD/Mod/C2Blend"
mkdir -p "$MOD"
for f in "$SRC"/plugin/C2Blend/*; do ln -s "$f" "$MOD/"; done
ln -s "$MODDIR"/c2blend*.so "$MOD/"
rm -f "$OUT/gui_result.json"
C2B_GUI_OUT=$OUT C2B_GUI_TESTS=$SRC/tests/freecad QTWEBENGINE_DISABLE_SANDBOX=1 \
  timeout 300 xvfb-run -a -s "-screen 0 1280x1024x24" freecad "$HERE/gui_fillet.py" \
  > "$OUT/gui_log.txt" 2>&1 || true
cat "$OUT/gui_result.json"
/usr/bin/python3 - "$OUT/gui_result.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
assert r["ok"], r.get("error")
assert r["verdict"] == "G2" and r["valid"], r
assert r["map_nodes"] == 1, r
assert r["edge_check"][1] == "G2", r
assert r["non_white_fraction"] > 0.05 and r["colours"] > 50, r
assert r["blend_verdict"] == "G2", r
assert r["blend_preview"].startswith("G2; ") and r["blend_preview"].endswith("the blend face only"), r
assert r["blend_preview_drawn"], r
assert r["blend_solid_preview"].startswith("G2; ") and r["blend_solid_preview"].endswith("one solid, valid"), r
assert r["blend_accepted"] is True and r["blend_solid"][:3] == [True, "Solid", True], r
assert r["blend_edit_values"] == [True, "C2"], r
assert r["blend_edit_accepted"] is True and r["blend_edited"] == [False, "C1", "G1", "Face"], r
assert not r["blend_panel_opened"], r
assert r["stray_edge"] + ": the edge is not an edge of the selected face" in r["warnings"], r
assert r["bad_selections_unchanged"], r
assert "ShaftPlate.Face1: Face1 is not an edge; select only edges" in r["warnings"], r
assert "ShaftPlate.Vertex1: Vertex1 is not an edge; select only edges" in r["warnings"], r
assert "ShaftPlate: no edges selected" in r["warnings"], r
assert "pick a face and one of its edges on each of two sides (selected: ShaftPlate.Face1)" in r["warnings"], r
assert r["png_frames"] == 10 and r["png_sizes_ok"], r
assert r["edit_parameters"] == [2.0, "C2", [2.5, 1.0, 1.0, 1.0], 1.37], r
assert abs(r["slid_tension"] - 1.6) < 1e-6, r
assert r["typed"] == [1.0, 286, -0.5, 0], r
assert r["c1_parameters"] == [2.0, "C1", [2.5, 1.0, 1.0], 1.0], r
assert r["c1_accepted"] is True and r["c1_object"] == ["C1", "G1", False], r
assert r["too_large_accepted"] is False and r["too_large_kept"] == [2.0, True, False], r
assert r["too_large_message"].startswith("C2Fillet: "), r
assert r["box_parameters"] == [2.0, "C2", [1.0, 1.0, 1.0, 1.0], 1.0], r
assert abs(r["box_radius"] - 2.0) < 1e-12, r
assert r["box_blends"] == 12 and r["box_corners"] == 8 and r["box_valid"], r
assert r["box_solid_check"] == "passes BRepCheck and the BOP check", r
print("gui test: G2 fillet, curvature map shown, screenshot not blank; G2 blend faces; "
      "its panel makes one solid and edits it; 10 PNG animation frames; the fillet panel keeps "
      "exact values, makes a C1 fillet and keeps the fillet when an edit fails; a box's "
      "12 edges by setback, with 8 "
      "filled corners")
PY
if [ -n "$C2B_CGAL_TOOL" ]; then
  grep "CGAL jet fit vs analytic, blend faces" "$OUT/gui_log.txt"
  grep -E "CGAL jet fit vs analytic, Face[0-9]+, Face[0-9]+ " "$OUT/gui_log.txt"
fi
