#!/bin/sh
# Output atomicity of the CLI writers (base/c2b_atomic.h): mesh (PLY, OBJ, OFF), fit
# (JSON and IGES). A writer that is killed mid-write (SIGKILL) or fails (file size limit,
# i.e. a full disk; rename onto a directory; missing or unwritable directory) must leave
# no partial target: a pre-existing target keeps its old content, a new target does
# not appear, and on a reported failure no temporary file is left behind.
#   test_atomic.sh C2BLEND EXAMPLES_DIR
set -u
c=${1:?usage: test_atomic.sh C2BLEND EXAMPLES_DIR}
ex=${2:?usage: test_atomic.sh C2BLEND EXAMPLES_DIR}
spec=$ex/thesis_eq130_131.json
d=$(mktemp -d)
trap 'chmod -R u+w "$d" 2>/dev/null; rm -rf "$d"' EXIT
fails=0
ok() { echo "ok   $*"; }
bad() { echo "FAIL $*"; fails=$((fails + 1)); }
old() { printf 'OLD CONTENT %s\n' "$1" >"$1"; }
same_old() { [ "$(cat "$1" 2>/dev/null)" = "OLD CONTENT $1" ]; }
no_tmp() { [ -z "$(find "$1" -name '*.tmp-*' 2>/dev/null)" ]; }

# 1. SIGKILL while the temporary is being written: the old target stays as it was.
for ext in ply obj off; do
  t=$d/kill.$ext
  old "$t"
  "$c" mesh "$spec" --n 512 -o "$t" >/dev/null 2>&1 &
  pid=$!
  i=0
  while [ $i -lt 3000 ] && [ -z "$(find "$d" -name "kill.$ext.tmp-*" -size +1k 2>/dev/null)" ]; do
    i=$((i + 1)); sleep 0.01
  done
  kill -9 $pid 2>/dev/null
  wait $pid 2>/dev/null
  if [ $i -ge 3000 ]; then
    bad "kill $ext: no temporary file seen being written"
  elif same_old "$t"; then
    ok "kill -9 mid-write ($ext, after $i polls): target unchanged"
  else
    bad "kill $ext: target changed: $(head -c 60 "$t")"
  fi
  rm -f "$d"/kill.$ext.tmp-*
done

# 2. File size limit (a full disk: writes fail with EFBIG) for each writer.
limited() { # limited BLOCKS CMD...: run with SIGXFSZ ignored and ulimit -f BLOCKS
  blocks=$1; shift
  (trap '' XFSZ; ulimit -f "$blocks"; exec "$@") >/dev/null 2>"$d/err"
}
for ext in ply obj off; do
  t=$d/full.$ext
  old "$t"
  limited 20 "$c" mesh "$spec" --n 64 -o "$t"; rc=$?
  if [ $rc -eq 2 ] && same_old "$t" && no_tmp "$d" && [ -s "$d/err" ]; then
    ok "full disk ($ext): exit 2, target unchanged, no temporary: $(head -c 100 "$d/err")"
  else
    bad "full disk ($ext): exit $rc, $(head -c 100 "$d/err")"; ls "$d"
  fi
done
t=$d/full_fit.json
old "$t"
limited 1 "$c" fit "$spec" -o "$t"; rc=$?
if [ $rc -eq 2 ] && same_old "$t" && no_tmp "$d"; then ok "full disk (fit JSON): exit 2, target unchanged"
else bad "full disk (fit JSON): exit $rc, $(head -c 100 "$d/err")"; fi
t=$d/full_fit.igs
old "$t"
# 100 blocks: the JSON (about 47 kB) fits, the IGES file (about 62 kB) does not
limited 100 "$c" fit "$spec" -o "$d/fit_ok.json" --iges "$t"; rc=$?
if [ $rc -eq 2 ] && same_old "$t" && no_tmp "$d" && grep -q "$t" "$d/err"; then ok "full disk (IGES): exit 2, target unchanged: $(head -c 100 "$d/err")"
else bad "full disk (IGES): exit $rc, $(head -c 100 "$d/err")"; fi
rm -f "$d/fit_ok.json"

# 3. The target is a directory: the rename is refused; the directory is untouched.
mkdir "$d/isdir.ply"; old "$d/isdir.ply/keep"
"$c" mesh "$spec" --n 8 -o "$d/isdir.ply" >/dev/null 2>"$d/err"; rc=$?
if [ $rc -eq 2 ] && [ -d "$d/isdir.ply" ] && same_old "$d/isdir.ply/keep" && no_tmp "$d"; then
  ok "target is a directory: exit 2, untouched: $(head -c 100 "$d/err")"
else bad "target is a directory: exit $rc, $(head -c 100 "$d/err")"; fi

# 4. Missing directory: a clear error and no file.
"$c" fit "$spec" -o "$d/missing/dir/f.json" >/dev/null 2>"$d/err"; rc=$?
if [ $rc -eq 2 ] && [ ! -e "$d/missing" ]; then ok "missing directory: exit 2: $(head -c 100 "$d/err")"
else bad "missing directory: exit $rc"; fi

# 5. Unwritable directory (meaningless as root, who may write anyway).
if [ "$(id -u)" != 0 ]; then
  mkdir "$d/ro"; old "$d/ro/m.ply"; chmod 555 "$d/ro"
  "$c" mesh "$spec" --n 8 -o "$d/ro/m.ply" >/dev/null 2>"$d/err"; rc=$?
  if [ $rc -eq 2 ] && same_old "$d/ro/m.ply"; then ok "unwritable directory: exit 2, target unchanged"
  else bad "unwritable directory: exit $rc"; fi
  chmod 755 "$d/ro"
else
  echo "skip unwritable directory (running as root)"
fi

# 6. A successful write replaces the old target completely.
t=$d/good.ply
old "$t"
if "$c" mesh "$spec" --n 8 -o "$t" >/dev/null 2>&1 && head -1 "$t" | grep -q '^ply' && no_tmp "$d"; then
  ok "successful write replaces the target"
else bad "successful write"; fi

[ $fails -eq 0 ] && echo "atomicity: all checks passed"
exit $fails
