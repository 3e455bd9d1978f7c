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
st = r['stability']
assert len(st) == 8 and all(len(s['k']) == 101 and len(s['branch_minima'][0]) == 2 for s in st), len(st)
for s in st:  # a sample is stable exactly when it lies in a stable interval
    for k, ok in zip(s['k'], s['stable']):
        assert ok == any(a <= k <= b for a, b in s['stable_intervals']), (s['kernel'], k)
    for k, v in zip(s['k'], s['verdict']):  # stable at the horizon: every verdict but unstable
        assert (v != 'unstable') == any(a <= k <= b for a, b in s['stable_at_horizon']), (s['kernel'], k, v)
    for o in s['overlap']:
        for a, b in o['accurate_and_stable']:
            assert any(x <= a and b <= y for x, y in o['accurate']) and any(x <= a and b <= y for x, y in s['stable_at_horizon'])
        rec = o['recommended']
        if o['accurate_and_stable']:
            widest = max(o['accurate_and_stable'], key=lambda i: i[1] - i[0])
            # SWIFT's gamma is not defined for the 2D super-Gaussian (its second moment is -1)
            names = {'pysph', 'dualsphysics', 'gadget', 'splishsplash'} | ({'swift'} if s['kernel'] != 'super_gaussian' else set())
            assert rec['found'] and rec['interval'] == widest and set(rec['conventions']) == names, rec
        else:
            assert not rec['found'], rec
"
grep -q '### Recommended k' "$work/out/report.md"
grep -q '## Free-surface profiles' "$work/out/report.md"
grep -q '## Linear stability' "$work/out/report.md"
if command -v gnuplot >/dev/null; then
    test -s "$work/out/plots/triangular-stability.svg"
    test -s "$work/out/plots/triangular-dispersion.svg"
fi
"$sphkern" run lattices-3d --no-plots -o "$work/out3d" >/dev/null
python3 -c "
import json
r = json.load(open('$work/out3d/results.json'))
assert len(r['cases']) == 10 * 5 * 3, len(r['cases'])
"
"$sphkern" run design --no-plots -o "$work/design" >/dev/null
python3 -c "
import json
r = json.load(open('$work/design/results.json'))
found = {(s['lattice'], s['kernel']): len(s['solutions']) for s in r['sweeps']}
assert all(found[(l, k)] > 0 for l in ('triangular', 'fcc') for k in ('cubic_bspline+desbrun_spiky', 'wendland_c2_shape')), found
assert all(abs(x['eps_rho']) < 1e-9 and abs(x['eps_gradp']) < 1e-9 for s in r['sweeps'] for x in s['solutions'])
"
# Each designed blend, confirmed by sphkern eps at that point.
for lattice in triangular fcc; do
    "$sphkern" design cubic_bspline+desbrun_spiky $lattice --param alpha --json >"$work/d.json"
    python3 -c "
import json
d = json.load(open('$work/d.json'))
assert d['solutions'], d
for s in d['solutions']: print(repr(s['k']), repr(s['parameter']))
" | while read -r k alpha; do
        "$sphkern" eps cubic_bspline+desbrun_spiky $lattice --k "$k" --set alpha="$alpha" --json |
            python3 -c "import json,sys; e = json.load(sys.stdin); assert abs(e['eps_rho']) < 1e-9 and abs(e['eps_gradp']) < 1e-9, e"
    done
done
# Every results.json written here, and the shipped studies, against their JSON Schemas.
root=$(cd "$(dirname "$0")/../.." && pwd)
python3 "$root/tests/cli/validate_study_schemas.py" "$root/share/schemas" "$root/share/studies" "$sphkern" \
    "$work/out/results.json" "$work/out3d/results.json" "$work/design/results.json"
echo "1 passed, 0 failed"
