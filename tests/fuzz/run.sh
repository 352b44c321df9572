#!/bin/sh
# Run the libFuzzer targets of tests/fuzz for a bounded time each.
#   tests/fuzz/run.sh FUZZ_BUILD_DIR [SECONDS] [TARGET...]
# SECONDS (default $FUZZ_SECONDS, else 60) per target; TARGETs default to all four:
# spec samples nurbs mesh. Each target starts from a scratch copy of its seed corpus
# tests/fuzz/corpus/<target> (the seeds are never modified). Exits non-zero when any
# target crashes, leaks, trips a sanitizer or times out; the crashing input is kept in
# $FUZZ_OUT/<target>/ (default build dir/fuzz-out) and its name printed.
set -u
here=$(cd "$(dirname "$0")" && pwd)
build=${1:?usage: run.sh FUZZ_BUILD_DIR [SECONDS] [TARGET...]}
shift
secs=${FUZZ_SECONDS:-60}
case ${1:-} in [0-9]*) secs=$1; shift ;; esac
targets=${*:-spec samples nurbs mesh}
out=${FUZZ_OUT:-$build/fuzz-out}
# libmatheval's own leak on syntax errors is suppressed (lsan.supp); the suppression
# needs full malloc stacks, through the library's frame-pointer-less code, which slows
# every allocation: only fuzz_spec, the one target that parses expressions, pays for it.
asan_spec="fast_unwind_on_malloc=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
asan_other=${ASAN_OPTIONS:-}
export LSAN_OPTIONS="suppressions=$here/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
status=0
for t in $targets; do
  bin=$build/tests/fuzz/fuzz_$t
  if [ ! -x "$bin" ]; then
    echo "fuzz: $bin not built" >&2
    status=1
    continue
  fi
  work=$out/$t
  mkdir -p "$work/corpus"
  cp "$here/corpus/$t/"* "$work/corpus/" 2>/dev/null
  # -timeout: one input may take at most 30 s; -rss_limit_mb: a clear limit, not OOM.
  if [ "$t" = spec ]; then ASAN_OPTIONS=$asan_spec; else ASAN_OPTIONS=$asan_other; fi
  export ASAN_OPTIONS
  "$bin" -max_total_time="$secs" -timeout=30 -rss_limit_mb=2048 -print_final_stats=1 \
         -artifact_prefix="$work/" "$work/corpus" >"$work/log" 2>&1
  rc=$?
  runs=$(grep -E '^stat::number_of_executed_units' "$work/log" | awk '{print $2}')
  if [ $rc -ne 0 ]; then
    echo "fuzz_$t: FAILED (exit $rc) after ${runs:-?} runs; see $work/log" >&2
    ls "$work"/crash-* "$work"/leak-* "$work"/timeout-* "$work"/oom-* 2>/dev/null >&2
    grep -E 'ERROR|SUMMARY|runtime error' "$work/log" | head -5 >&2
    status=1
  else
    echo "fuzz_$t: ok, ${secs} s, ${runs:-?} runs, corpus $(ls "$work/corpus" | wc -l) files"
  fi
done
exit $status
