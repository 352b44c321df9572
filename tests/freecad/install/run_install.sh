#!/bin/sh
# Install test: `cmake --install` of the build into a temporary prefix, the installed
# workbench folder linked into a temporary user's FreeCAD Mod path, and a fillet run by
# the real freecadcmd from the installed files alone (no source tree, no PYTHONPATH).
# Usage: run_install.sh BUILD_DIR
set -eu
BUILD=$1
HERE=$(cd "$(dirname "$0")" && pwd)
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
cmake --install "$BUILD" --prefix "$WORK/prefix" > "$WORK/install.log"
MOD="$WORK/prefix/share/freecad/Mod/C2Blend"
for f in Init.py InitGui.py C2Blend.py package.xml c2bwb/geometry/fillet.py \
         c2blend-cgal-curvature; do
  test -e "$MOD/$f" || { echo "not installed: $MOD/$f"; exit 1; }
done
ls "$MOD"/c2blend*.so > /dev/null || { echo "not installed: the c2blend module"; exit 1; }
test -z "$(find "$MOD" -name __pycache__)" || { echo "__pycache__ installed"; exit 1; }
export HOME="$WORK/home"
mkdir -p "$HOME/.local/share/FreeCAD/Mod"
ln -s "$MOD" "$HOME/.local/share/FreeCAD/Mod/C2Blend"
cp "$HERE/check_install.py" "$WORK/check_install.py"
cd "$WORK"
env -u PYTHONPATH -u C2B_MODULE_DIR -u C2B_CGAL_TOOL C2B_INSTALL_RESULT="$WORK/result.txt" \
  timeout 300 freecadcmd "$WORK/check_install.py" > "$WORK/freecadcmd.log" 2>&1 || true
if ! grep -q "^ok " "$WORK/result.txt" 2>/dev/null; then
  cat "$WORK/freecadcmd.log" "$WORK/result.txt" 2>/dev/null
  exit 1
fi
cat "$WORK/result.txt"
