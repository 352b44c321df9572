#!/bin/sh
# C2 Fillet on PartDesign features in the real freecadcmd (which loads the PartDesign and
# Sketcher modules that plain python3 does not). Usage: run_partdesign.sh MODULE_DIR
set -eu
HERE=$(cd "$(dirname "$0")" && pwd)
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
export HOME="$WORK/home"
mkdir -p "$HOME"
C2B_MODULE_DIR=$1 C2B_RESULT="$WORK/result.txt" \
  C2B_PARTDESIGN_SCRIPT="$HERE/check_partdesign.py" \
  timeout 300 freecadcmd "$HERE/check_partdesign.py" > "$WORK/freecadcmd.log" 2>&1 || true
if ! grep -q "^ok " "$WORK/result.txt" 2>/dev/null; then
  cat "$WORK/freecadcmd.log" "$WORK/result.txt" 2>/dev/null
  exit 1
fi
cat "$WORK/result.txt"
