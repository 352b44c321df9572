#!/bin/sh
# expect.sh RC FRAGMENT CMD...: run CMD, require exit code RC, FRAGMENT in stderr
# (skip with "-"), and, for failures, an empty stdout (no partial CSV).
rc_want=$1; frag=$2; shift 2
out=$(mktemp); err=$(mktemp)
"$@" >"$out" 2>"$err"; rc=$?
status=0
if [ "$rc" != "$rc_want" ]; then echo "FAIL exit code $rc, want $rc_want: $*"; status=1; fi
if [ "$frag" != "-" ] && ! grep -qF -- "$frag" "$err"; then echo "FAIL stderr lacks '$frag'"; status=1; fi
if [ "$rc_want" != 0 ] && [ -s "$out" ]; then echo "FAIL stdout not empty on failure"; status=1; fi
echo "stderr: $(cat "$err")"
rm -f "$out" "$err"
[ $status = 0 ] && echo "ok   exit $rc: $*"
exit $status
