#!/bin/sh
# Run a representative subset of the tests under Valgrind memcheck: the kernel, NURBS,
# validation and check unit tests, and CLI runs of every command (success and failure
# paths, including the bad-input corpus). Any invalid read or write, use of an
# uninitialised value, or definite/indirect leak fails the run.
#   tests/valgrind/run.sh BUILD_DIR   (a normal gcc build, without sanitizers)
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
b=${1:?usage: run.sh BUILD_DIR}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
ex=$root/examples
bad=$root/tests/bad
vg="valgrind -q --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite,indirect
    --show-leak-kinds=definite,indirect --suppressions=$here/c2blend.supp"
fails=0; runs=0
# run EXPECTED_EXIT CMD...: the program's own exit code must be EXPECTED_EXIT and
# valgrind must report nothing (exit 99 is valgrind's).
run() {
  want=$1; shift
  runs=$((runs + 1))
  t0=$(date +%s)
  $vg "$@" >"$tmp/out" 2>"$tmp/err"
  rc=$?
  dt=$(($(date +%s) - t0))
  if [ $rc -eq 99 ] || [ $rc -ne "$want" ]; then
    fails=$((fails + 1))
    echo "FAIL (exit $rc, want $want): $*"
    grep -E '^==[0-9]+==' "$tmp/err" | head -30
  else
    echo "ok   ${dt}s $*"
  fi
}
c=$b/tools/c2blend
# test_blend and test_quadric are left out (4-5 min each under memcheck); ASan/UBSan run
# them in every make test
for t in tests/test_mode tests/test_spec tests/test_vseries tests/nurbs/test_nurbs \
         tests/validation/test_curv; do
  run 0 "$b/$t"
done
run 0 "$b/tests/check/test_check" "$ex"
run 0 "$c" info "$ex/thesis_eq130_131.json"
run 0 "$c" info "$ex/thesis_eq127_129.json" --t 0.3
run 0 "$c" info "$ex/seed001_eq17.json"
run 0 "$c" info "$ex/thesis_eq055_057.json"
run 0 "$c" eval "$root/tests/cli/thesis_eq2_4.json" --u 9 --v 17
run 0 "$c" eval "$ex/thesis_eq130_131.json" --u 9 --v 17 --derivs
run 0 "$c" eval "$ex/nurbs_cubic_quartic.json" --u 5 --v 5
run 0 "$c" mesh "$ex/nurbs_cubic_quartic.json" --n 8 --with-primaries 0.2 -o "$tmp/m.ply"
run 0 "$c" mesh "$ex/thesis_eq130_131.json" --n 8 -o "$tmp/m.obj"
run 0 "$c" fit "$ex/thesis_eq130_131.json" -o "$tmp/f.json" --iges "$tmp/f.igs"
run 0 "$c" check "$ex/thesis_eq130_131.json" --samples 17
run 0 "$c" profile "$ex/thesis_eq130_131.json" --with-primaries 0.2 --n 21
# every spec-level case of the bad-input corpus (error paths free what they allocated)
grep -v '^#' "$bad/MANIFEST.tsv" | while IFS='	' read -r file scope command rc frag; do
  [ "$scope" = spec ] || continue
  verb=${command%% *}; rest=${command#"$verb"}
  # shellcheck disable=SC2086
  run "$rc" "$c" "$verb" "$bad/$file" $rest
  echo "$runs $fails" >"$tmp/count"
done
if [ -f "$tmp/count" ]; then read -r runs fails <"$tmp/count"; fi
echo "valgrind: $runs runs, $fails failed"
[ "$fails" -eq 0 ]
