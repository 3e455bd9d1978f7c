#!/usr/bin/env bash
# The default study writes a complete results folder and prints the replication table.
set -eu
sphkern=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$sphkern" run -o "$work/out" >"$work/stdout"
for f in report.md results.json curves.csv; do test -s "$work/out/$f"; done
if command -v gnuplot >/dev/null; then
    test -s "$work/out/plots/triangular-paper.svg"
    grep -q 'plots/triangular-default.svg' "$work/out/report.md"
fi
grep -q '20 of 21 rows reproduced' "$work/stdout"
python3 -c "
import json, sys
r = json.load(open('$work/out/results.json'))
assert r['sphkern_version'] and r['study']['name'] == 'potapov2021'
assert len(r['cases']) == 8 * 3 * 2, len(r['cases'])
assert sum(c['status'] == 'reproduced' for c in r['comparison']) == 20
assert len(r['surface']) == 8 * 3 and all(len(s['layers']) >= 4 for s in r['surface'])
"
grep -q '## Free-surface profiles' "$work/out/report.md"
"$sphkern" run lattices-3d --no-plots -o "$work/out3d" >/dev/null
python3 -c "
import json
r = json.load(open('$work/out3d/results.json'))
assert len(r['cases']) == 10 * 5 * 3, len(r['cases'])
"
echo "1 passed, 0 failed"
