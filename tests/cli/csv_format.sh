#!/bin/sh
# csv_format.sh C2BLEND SPEC: checks the eval CSV contract (header, row order, count,
# --points order and stdin, %.17g round trip) against hand-made expectations.
set -u
c2b=$1; spec=$2; fail=0
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
"$c2b" eval "$spec" --u 3 --v 4 > "$t/grid.csv" || { echo "FAIL eval"; exit 1; }
[ "$(head -1 "$t/grid.csv")" = "u,v,x,y,z" ] || { echo "FAIL header: $(head -1 "$t/grid.csv")"; fail=1; }
[ "$(wc -l < "$t/grid.csv")" = 13 ] || { echo "FAIL 3x4 grid should give 12 rows"; fail=1; }
# rows ordered by u, then v; u_i = i/(N-1)
[ "$(sed -n '2p;5p;6p;13p' "$t/grid.csv" | cut -d, -f1,2 | tr '\n' ' ')" = "0,0 0,1 0.5,0 1,1 " ] \
  || { echo "FAIL row order: $(sed -n '2p;5p;6p;13p' "$t/grid.csv" | cut -d, -f1,2 | tr '\n' ' ')"; fail=1; }
"$c2b" eval "$spec" --u 2 --v 2 --derivs > "$t/d.csv" || fail=1
[ "$(head -1 "$t/d.csv")" = "u,v,x,y,z,xu,yu,zu,xv,yv,zv,xuu,yuu,zuu,xuv,yuv,zuv,xvv,yvv,zvv" ] \
  || { echo "FAIL derivative header: $(head -1 "$t/d.csv")"; fail=1; }
printf '0.5 0.25\n# comment\n0.1,0.9\n\n1 0\n' > "$t/pts"
"$c2b" eval "$spec" --points "$t/pts" > "$t/p.csv" || fail=1
[ "$(cut -d, -f1,2 "$t/p.csv" | tr '\n' ' ')" = "u,v 0.5,0.25 0.10000000000000001,0.90000000000000002 1,0 " ] \
  || { echo "FAIL points order/format: $(cut -d, -f1,2 "$t/p.csv" | tr '\n' ' ')"; fail=1; }
printf '0.5 0.25\n' | "$c2b" eval "$spec" --points - > "$t/s.csv" || fail=1
[ "$(sed -n 2p "$t/s.csv")" = "$(sed -n 2p "$t/p.csv")" ] || { echo "FAIL stdin points differ"; fail=1; }
# u=1, v=0 of the thesis eq. 2-4 example: (0, d, -0.027 h3) = (0, 0.6, -0.135)
row=$(sed -n 4p "$t/p.csv")
${PYTHON:-/usr/bin/python3} - "$row" <<'PY' || fail=1
import sys
u, v, x, y, z = map(float, sys.argv[1].split(","))
ok = abs(x) < 1e-13 and abs(y - 0.6) < 1e-13 and abs(z + 0.135) < 1e-13
print(("ok  " if ok else "FAIL") + " S(1,0) = (0, 0.6, -0.135): %r" % ((x, y, z),))
sys.exit(0 if ok else 1)
PY
[ $fail = 0 ] && echo "ok   csv contract"
exit $fail
