#!/usr/bin/env bash
# The default study writes a complete results folder and prints the replication table.
set -eu
sphkern=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
SPHKERN_PROGRESS_SECONDS=0 "$sphkern" run -o "$work/out" >"$work/stdout" 2>"$work/stderr"
for f in report.md results.json curves.csv method.md; do test -s "$work/out/$f"; done
# Progress as plain lines when stderr is a file (here at every step: SPHKERN_PROGRESS_SECONDS=0).
grep -Eq '^sphkern: info: study potapov2021, accuracy: 1/[0-9]+ done .*s so far, about [0-9]+ (s|min) left in this part \(1 of [0-9]\), then .*$' "$work/stderr"
# The report links the method document copied beside it, never a path of this machine.
grep -q '\[method.md\](method.md)' "$work/out/report.md"
if grep -q "$root" "$work/out/report.md"; then echo "report.md names a path of this machine" >&2; exit 1; fi
cmp "$work/out/method.md" "$root/share/docs/method.md"
if command -v gnuplot >/dev/null; then
    test -s "$work/out/plots/triangular-paper.svg"
    grep -q 'plots/triangular-default.svg' "$work/out/report.md"
fi
python3 -c "
import hashlib, json, re, sys
r = json.load(open('$work/out/results.json'))
assert r['sphkern_version'] and r['study']['name'] == 'potapov2021'
assert len(r['cases']) == 8 * 3 * 2, len(r['cases'])
# A row is reproduced only when every compared value agrees; the README, the guide to
# choosing k and the method document state the count this table gives.
rows = r['comparison']
reproduced = sum(c['status'] == 'reproduced' for c in rows)
assert all((c['status'] == 'reproduced') == (not c['differs_in']) for c in rows), rows
composite = [c for c in rows if c['reference']['kernel'] == 'composite']
assert [c['status'] for c in composite] == ['erratum', 'erratum'] and composite[1]['differs_in'] == ['eps_gradp'], composite
assert abs(composite[1]['computed']['eps_gradp'] + 1) < 1e-12, composite[1]
assert reproduced == 19, reproduced
stdout = open('$work/stdout').read()
assert f'{reproduced} of {len(rows)} rows reproduced' in stdout, stdout[:2000]
assert f'{reproduced} of the {len(rows)} rows of Table 1 are reproduced' in open('$root/README.md').read()
assert f'{reproduced} of the {len(rows)} rows of Table 1 are reproduced' in open('$root/share/docs/guide-choosing-k.md').read()
assert f'{reproduced} of its {len(rows)} rows are reproduced' in open('$root/share/docs/method.md').read()
# Provenance and the inputs in full, the hashes against Python's own SHA-256.
p = r['provenance']
assert p['sphkern_version'] == r['sphkern_version'] and p['command_line'][1:] == ['run', '-o', '$work/out'], p
assert re.fullmatch(r'\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ', p['date_utc']) and p['host']['threads'] >= 1, p
inputs = r['inputs']
study_bytes = open(r['study_file'], 'rb').read()
assert inputs['study']['sha256'] == hashlib.sha256(study_bytes).hexdigest() and inputs['study']['text'] == study_bytes.decode()
assert [l['name'] for l in inputs['lattices']] == ['triangular'] and inputs['lattices'][0]['definition']['dimension'] == 2
assert len(inputs['kernels']) == 8
for k in inputs['kernels']:
    assert k['sha256'] == hashlib.sha256(open(k['file'], 'rb').read()).hexdigest(), k
    assert k['abi'].startswith('2.'), k
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
            codes = rec.get('codes', {})
            assert rec['found'] and rec['interval'] == widest, rec
            assert set(codes) <= {'swift', 'phantom', 'gadget2', 'gadget4', 'pysph', 'dualsphysics'}, rec
            # Every code ships the cubic spline, and all but Phantom (3D only) run the triangular lattice's 2D;
            # PySPH's hdx is h over the rest spacing, k / a_p^(1/2) in 2D.
            if s['kernel'] == 'cubic_bspline':
                assert set(codes) == {'swift', 'gadget2', 'gadget4', 'pysph', 'dualsphysics'}, rec
            a_p = {'voronoi': 3 ** 0.5 / 2, 'cube': 1.0}.get(o['volume_coefficient'])
            if 'pysph' in codes and a_p:
                assert abs(codes['pysph'] - rec['k'] / a_p ** 0.5) < 1e-12 * codes['pysph'], (rec, a_p)
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
# The results file alone runs the study again; a changed number is found.
"$sphkern" run --reproduce "$work/out/results.json" >"$work/reproduce" 2>"$work/reproduce.err"
grep -Eq '^reproduced: all [0-9]+ numbers of .*results.json agree within a relative 1e-9$' "$work/reproduce"
altered=$(python3 -c "
import json
r = json.load(open('$work/out/results.json'))
i = next(i for i, c in enumerate(r['cases']) if c['roots'])
r['cases'][i]['roots'][0]['k'] += 1e-6
json.dump(r, open('$work/altered.json', 'w'))
print(f'/cases/{i}/roots/0/k')
")
status=0
"$sphkern" run --reproduce "$work/altered.json" >"$work/reproduce" 2>/dev/null || status=$?
test "$status" -eq 1
grep -q '^not reproduced: 1 of [0-9]* numbers' "$work/reproduce"
grep -q "^  $altered: recorded" "$work/reproduce"
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
# The particles section: an unperturbed fcc block gives the lattice's eps_rho at the same k
# (h = (h/l) V^(1/3), V = a_p d^3), a disturbed one does not.
cat >"$work/particles.json" <<'STUDY'
{"name": "p", "kernels": ["cubic_bspline", "wendland_c2"], "lattices": ["fcc"], "k": {"samples": 11},
 "particles": {"sources": [{"lattice": "fcc", "size": [10, 10, 10]}, {"lattice": "fcc", "size": [10, 10, 10], "sigma": 0.1},
                           {"poisson": 2, "count": 3000, "seed": 3}],
               "nh": {"min": 40, "max": 80, "steps": 2}}}
STUDY
"$sphkern" run "$work/particles.json" -o "$work/particles" --no-plots >/dev/null
python3 - "$work/particles/results.json" "$sphkern" <<'CHECK'
import json, subprocess, sys
r = json.load(open(sys.argv[1]))
cases = {(c["source"], c["kernel"]): c for c in r["particles"]}
assert len(cases) == 6, list(cases)
for kernel in ("cubic_bspline", "wendland_c2"):
    for p in cases[("fcc, 10x10x10 cells, sigma = 0 d", kernel)]["points"]:
        k = p["h_over_l"] * (2 ** -0.5) ** (1 / 3)
        e = json.loads(subprocess.run([sys.argv[2], "eps", kernel, "fcc", "--k", repr(k), "--json"],
                                      check=True, capture_output=True, text=True).stdout)
        s = p["statistics"]["e0"]
        assert abs(s["mean"] - e["eps_rho"]) < 1e-12 and s["std"] < 1e-12, (kernel, p["nh"], s, e["eps_rho"])
    disturbed = cases[("fcc, 10x10x10 cells, sigma = 0.1 d", kernel)]["points"]
    assert all(p["statistics"]["e0"]["std"] > 1e-3 for p in disturbed)
print("particles section: lattice limit and disorder as expected")
CHECK
# A --json document carries its provenance and, where the command has them, its inputs.
"$sphkern" eps cubic_bspline fcc --k 1.2 --json >"$work/eps.json"
"$sphkern" kernels --json >"$work/kernels.json"
python3 -c "
import hashlib, json
e = json.load(open('$work/eps.json'))
assert e['provenance']['command_line'][1:] == ['eps', 'cubic_bspline', 'fcc', '--k', '1.2', '--json'], e['provenance']
k, l = e['inputs']['kernels'][0], e['inputs']['lattices'][0]
assert k['name'] == 'cubic_bspline' and k['sha256'] == hashlib.sha256(open(k['file'], 'rb').read()).hexdigest()
assert l['definition'] == json.load(open(l['file'])) and l['sha256'] == hashlib.sha256(open(l['file'], 'rb').read()).hexdigest()
assert all(item['provenance']['sphkern_version'] for item in json.load(open('$work/kernels.json')))
"
# Every results.json written here, and the shipped studies, against their JSON Schemas.
python3 "$root/tests/cli/validate_study_schemas.py" "$root/share/schemas" "$root/share/studies" "$sphkern" \
    "$work/out/results.json" "$work/out3d/results.json" "$work/design/results.json" "$work/particles/results.json"
echo "1 passed, 0 failed"
