#!/usr/bin/env bash
# Measures sphkern and writes share/docs/BENCHMARKS.md (every figure in it comes from here).
# Usage: bash share/scripts/benchmarks.sh [BUILD] [BASELINE]
#   BUILD     the build folder to measure (default: build)
#   BASELINE  an earlier sphkern executable, built beside this one, to compare with in the
#             same run (e.g. a checkout of an earlier commit built in /tmp/base/build)
# Needs hyperfine (apt-get install hyperfine); installs PySPH from Debian for the comparison.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
baseline=${2:-}
sphkern="$PWD/$build/sphkern"
out=share/docs/BENCHMARKS.md
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
command -v hyperfine >/dev/null || { echo "benchmarks: hyperfine is needed (apt-get install hyperfine)" >&2; exit 2; }
# A cache of plugin probes of its own, warmed by the first run of each command.
export XDG_CACHE_HOME="$work/cache"

lattices=$("$sphkern" lattices --json | python3 -c "import json,sys; print(' '.join(l['name'] for l in json.load(sys.stdin)))")
cat >"$work/shells.sh" <<SH
for l in $lattices; do "$sphkern" shells \$l --radius 6 --json >/dev/null; done
SH
pairs=$("$sphkern" roots all all --json | python3 -c "import json,sys; print(len(json.load(sys.stdin)))")

hyperfine -N -w 3 -r 20 --export-markdown "$work/study.md" \
    "$sphkern run --no-plots --force -o $work/study" >&2
hyperfine -w 2 -r 10 --export-markdown "$work/shells.md" "bash $work/shells.sh" >&2
hyperfine -N -w 2 -r 10 --export-markdown "$work/roots.md" "$sphkern roots all all --json" >&2

# The ceiling of the fused sweep's arithmetic on one core (Google Benchmark), first: the
# block table divides by it.
"$PWD/$build/tests/kernel_call_benchmark" --benchmark_repetitions=10 --benchmark_report_aggregates_only=true \
    --benchmark_format=json >"$work/calls.json" 2>/dev/null

# The block engine from 10^4 to 8 10^6 particles of a periodic fcc block, three runs each.
for n in 22 46 100 200; do
    for run in 1 2 3; do
        start=$(date +%s%N)
        "$sphkern" block cubic_bspline fcc --k 1.2 --size $n,$n,$n --periodic --json >"$work/block-$n-$run.json"
        echo $((($(date +%s%N) - start) / 1000)) >"$work/block-$n-$run.wall"
    done
done
python3 - "$work" >"$work/block.md" <<'PY'
import json, statistics, sys
work = sys.argv[1]
calls = json.load(open(f"{work}/calls.json"))
ceiling = [b for b in calls["benchmarks"] if b["run_name"] == "fused_pair_ceiling" and b.get("aggregate_name") == "median"][0]
per_core = ceiling["items_per_second"]
print("| particles | pairs per sum | setup [s] | density + gradient [s] | whole process [s] | pairs per second | fraction of the ceiling |")
print("|---:|---:|---:|---:|---:|---:|---:|")
for n in (22, 46, 100, 200):
    runs = [json.load(open(f"{work}/block-{n}-{i}.json")) for i in (1, 2, 3)]
    walls = [int(open(f"{work}/block-{n}-{i}.wall").read()) / 1e6 for i in (1, 2, 3)]
    r = runs[0]
    setup = statistics.median(x["seconds"]["setup"] for x in runs)
    evaluation = statistics.median(x["seconds"]["evaluation"] for x in runs)
    rate = r["pair_interactions_per_pass"] / evaluation
    print(f"| {r['particles']} | {r['pair_interactions_per_pass']} | {setup:.4f} | {evaluation:.4f} | "
          f"{statistics.median(walls):.3f} | {rate:.3g} | {rate / (per_core * r['threads']):.2f} |")
print(f"\nMedians of three runs, {runs[0]['threads']} threads, one fused sweep (`fused_passes`: "
      f"{str(runs[0]['fused_passes']).lower()}). A pair is counted once, though it feeds both sums. The ceiling is "
      f"measured, not quoted from a datasheet: `fused_pair_ceiling` (Google Benchmark, below) runs the sweep's "
      f"per-pair arithmetic (distance, one sqrt, one division, the plugin's W and W', both sums) on 100 pairs that "
      f"stay in L1, with the same vector clones: {per_core:.3g} pairs per second on one core, "
      f"{per_core * runs[0]['threads']:.3g} on {runs[0]['threads']}. The fraction is the block's rate over that: "
      f"what is left is the neighbour search, the pairs of the stencil outside the support (computed, then masked) "
      f"and memory traffic.")
PY

# PySPH and yt side by side, one core each: the same particles, densities checked.
/usr/bin/python3 share/scripts/peers_compare.py --sphkern "$sphkern" >"$work/peers.json"

# The Python module: eps over 10^6 k in one call, against the command line and numpy.
if [[ -d "$PWD/$build/python" ]]; then
    PYTHONPATH="$PWD/$build/python" /usr/bin/python3 share/scripts/python_benchmark.py --sphkern "$sphkern" >"$work/python.json"
fi

# Before and after: the same commands through BASELINE and through this build, one after
# the other in this run (warm probe caches for both; the baseline has none).
if [[ -n $baseline ]]; then
    compare() { # compare NAME ARGS...: one hyperfine run of both executables; OUT is a folder of each's own
        local name=$1
        shift
        hyperfine -N -w 3 -r 15 --export-json "$work/vs-$name.json" -n before "$baseline ${*//OUT/$work/before-$name}" \
            -n after "$sphkern ${*//OUT/$work/after-$name}" >&2
    }
    compare roots roots cubic_bspline fcc
    compare study run --no-plots --force -o OUT
    # The baseline's own copy of the 3D study, so that both run the same file.
    compare study3d run "$(dirname "$baseline")/../share/studies/lattices-3d.json" --no-plots --force -o OUT
    compare block block cubic_bspline fcc --k 1.2 --size 100,100,100 --periodic
    compare kernels kernels
    # The first command after a plugin changes (an empty cache): every plugin is probed, in parallel.
    hyperfine -N -w 1 -r 10 --prepare "rm -rf $work/cache" --export-json "$work/vs-cold.json" \
        -n before "$baseline roots cubic_bspline fcc" -n after "$sphkern roots cubic_bspline fcc" >&2
fi

{
    echo "# Benchmarks"
    echo
    echo "Generated by \`bash share/scripts/benchmarks.sh\` on $(nproc) cores ($(uname -m)), $(date -u +%Y-%m-%d)."
    echo "Times are wall-clock, measured with hyperfine; each command starts a fresh sphkern process."
    echo "Plugins are probed in a child process the first time sphkern sees a file; the probe cache"
    echo "(warm here, after the first run) spares that on later runs."
    echo
    if [[ -n $baseline ]]; then
        echo "## Before and after"
        echo
        echo "Each command through an earlier build (before: $(cd "$(dirname "$baseline")/.." && git log -1 --format='commit %h, %s' 2>/dev/null || echo "$baseline"))"
        echo "and through this one (after), measured with hyperfine in one run of this script on one machine: mean of 15 runs after"
        echo "3 warm-ups. The ratio holds where absolute times drift on a shared machine."
        echo
        python3 - "$work" <<'PY'
import json, sys
rows = [("roots", "`roots cubic_bspline fcc`", 2.0), ("study", "`run --no-plots` (the default study)", 1.5),
        ("study3d", "`run lattices-3d.json --no-plots` (the baseline's k-window version)", None),
        ("block", "`block cubic_bspline fcc --k 1.2 --size 100,100,100 --periodic`, whole process", 1.8),
        ("kernels", "`kernels`", None), ("cold", "`roots cubic_bspline fcc`, empty probe cache", None)]
print("| command | before [ms] | after [ms] | speed-up | target | met |\n|---|---:|---:|---:|---:|---|")
for name, label, target in rows:
    r = {x["command"]: x["mean"] for x in json.load(open(f"{sys.argv[1]}/vs-{name}.json"))["results"]}
    ratio = r["before"] / r["after"]
    met = "" if target is None else ("yes" if ratio >= target else "no")
    print(f"| {label} | {1e3 * r['before']:.1f} | {1e3 * r['after']:.1f} | {ratio:.2f} | "
          f"{'' if target is None else f'>= {target}'} | {met} |")
PY
        echo
    fi
    echo "## The default study without plots (target: under 0.3 s)"
    echo
    echo "\`sphkern run --no-plots\`: 8 kernels x 3 a_p x 2 modes, 501 samples per curve, roots, jumps, condition (22)."
    echo
    sed "s#$sphkern#sphkern#g; s#$work/study#DIR#g" "$work/study.md"
    echo
    echo "## Shells of all seven lattices up to 6 d (target: well under a second)"
    echo
    echo "One \`sphkern shells <lattice> --radius 6 --json\` process per lattice, all seven in a row."
    echo
    sed "s#bash $work/shells.sh#shells of $lattices#" "$work/shells.md"
    echo
    echo "## \`sphkern roots\` for every kernel on every shipped lattice (target: under 1 s)"
    echo
    echo "\`sphkern roots all all --json\`: $pairs kernel-lattice pairs (every kernel on every lattice of a dimension it supports) in one process."
    echo
    sed "s#$sphkern#sphkern#g" "$work/roots.md"
    echo
    echo "## The particle-block engine from 10^4 to 8 10^6 particles"
    echo
    echo "\`sphkern block cubic_bspline fcc --k 1.2 --size N,N,N --periodic --json\` for N = 22, 46, 100, 200:"
    echo
    cat "$work/block.md"
    echo
    echo "## Against PySPH and yt"
    echo
    echo "\`/usr/bin/python3 share/scripts/peers_compare.py\` (its docstring says what is run and checked), one core each:"
    echo
    /usr/bin/python3 share/scripts/peers_compare.py --from-json "$work/peers.json" --markdown
    echo
    if [[ -f "$work/python.json" ]]; then
        echo "## The Python module: eps over 10^6 values of k"
        echo
        echo "\`PYTHONPATH=$build/python /usr/bin/python3 share/scripts/python_benchmark.py\`: cubic_bspline on fcc, k from 0.75"
        echo "to 1.25. The module takes the whole numpy array in one call (the GIL released); the command line takes one"
        echo "process per k (timed on a sample, its total is that time per call times 10^6); numpy sums W over the explicit"
        echo "lattice points for every k (vectorised, in chunks)."
        echo
        python3 - "$work" <<'PY'
import json, sys
r = json.load(open(f"{sys.argv[1]}/python.json"))
m = r["module_seconds"]
print("| way | seconds for 10^6 k | relative to the module |\n|---|---:|---:|")
print(f"| `sphkern.eps(kernel, lattice, ks)` | {m:.3f} | 1 |")
print(f"| numpy brute force over {r['numpy_lattice_points']} lattice points | {r['numpy_seconds']:.2f} | {r['numpy_seconds'] / m:.0f} |")
print(f"| `sphkern eps --json`, one process per k ({r['cli_seconds_per_call'] * 1e3:.1f} ms per call, "
      f"{r['cli_sample']} timed) | {r['cli_seconds_for_all']:.0f} | {r['cli_seconds_for_all'] / m:.2g} |")
print(f"\nThe module and numpy agree to {r['max_difference_module_numpy']:.1e} in eps_rho over all 10^6 values; the "
      f"module and the command line to {r['max_difference_module_cli']:.1e} on the sample.")
PY
        echo
    fi
    echo "## The plugin call cost (target: the batch interface within 10% of inline code) and the pair ceiling"
    echo
    echo "\`$build/tests/kernel_call_benchmark --benchmark_repetitions=10\` (Google Benchmark): the cubic_bspline plugin's"
    echo "batch and scalar functions on 100 values of q, against the same source compiled into the benchmark; and"
    echo "\`fused_pair_ceiling\`, the block sweep's per-pair work on 100 pairs in L1 (items are pairs)."
    echo
    python3 - "$work" <<'PY'
import json, sys
r = json.load(open(f"{sys.argv[1]}/calls.json"))
med = {b["run_name"]: b for b in r["benchmarks"] if b.get("aggregate_name") == "median"}
print("| benchmark | median time per 100 values [ns] | values per second |\n|---|---:|---:|")
for name in ("inline_batch", "plugin_batch", "plugin_scalar", "fused_pair_ceiling"):
    b = med[name]
    print(f"| {name} | {b['real_time']:.1f} | {b['items_per_second']:.3g} |")
ratio = med["plugin_batch"]["real_time"] / med["inline_batch"]["real_time"]
print(f"\nplugin_batch / inline_batch = {ratio:.3f}.")
PY
} >"$out"
echo "wrote $out" >&2
