#!/bin/bash
# Side-by-side timings of the stability answers of two builds, each command run REPEATS
# times alternately; prints the median wall and user seconds of each and their ratios.
# Usage: bash share/scripts/stability_scan_benchmark.sh NEW/sphkern OLD/sphkern [REPEATS]
# Prints a Markdown table row per command: new / old medians (wall, user) and the ratios.
set -eu
new=$1 old=$2 repeats=${3:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
here=$(cd "$(dirname "$0")/../studies" && pwd)
# The default study's stability section on its own: its kernels, lattice and window.
python3 - "$here/potapov2021.json" "$work/stability-2d.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
for key in ("modes", "compare_with", "surface", "$schema"):
    d.pop(key, None)
d["name"], d["plots"] = "stability-2d", False
json.dump(d, open(sys.argv[2], "w"))
PY
# A 3D stability study: eight kernels on the five 3D lattices, 100 k in [0.8, 1.6].
python3 - "$here/stability-3d.json" "$work/stability-8x5.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
d.pop("$schema", None)
d["name"], d["plots"] = "stability-8x5", False
d["kernels"].append("wendland_c2")
d["k"]["samples"] = 101
d["stability"]["k"]["steps"] = 99
json.dump(d, open(sys.argv[2], "w"))
PY
commands=(
    "run -o $work/out --no-plots --force"
    "run $work/stability-2d.json -o $work/out --no-plots --force"
    "roots cubic_bspline fcc --stability --json"
    "roots wendland_c2 hcp --stability --json"
    "roots all triangular --stability --json"
    "roots all fcc --stability --json"
    "roots all hcp --stability --json"
    "run $work/stability-8x5.json -o $work/out --no-plots --force"
)
median() { sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
for c in "${commands[@]}"; do
    for b in new old; do : >"$work/$b.wall"; : >"$work/$b.user"; done
    for ((i = 0; i < repeats; i++)); do
        for b in new old; do
            /usr/bin/time -o "$work/t" -f "%e %U" "${!b}" $c >/dev/null 2>&1
            read -r wall user <"$work/t"
            echo "$wall" >>"$work/$b.wall"; echo "$user" >>"$work/$b.user"
        done
    done
    nw=$(median <"$work/new.wall") ow=$(median <"$work/old.wall") nu=$(median <"$work/new.user") ou=$(median <"$work/old.user")
    printf '| `sphkern %s` | %s s / %s s | %s s / %s s | %.2f | %.2f |\n' "${c//$work/DIR}" "$nw" "$ow" "$nu" "$ou" \
        "$(echo "$nw / $ow" | bc -l)" "$(echo "$nu / $ou" | bc -l)"
done
