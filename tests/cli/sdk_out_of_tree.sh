#!/usr/bin/env bash
# The SDK works for a third party: install sphkern to a temporary prefix, build the
# example plugin out of tree with find_package(sphkern), check it, install it.
# Usage: sdk_out_of_tree.sh BUILD_DIR EXAMPLE_DIR
set -eu
build=$1 example=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$example" -B "$work/example" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/example" >/dev/null
plugin="$work/example/morris_quintic_359.so"
# Hidden visibility: the entry is the only exported symbol of ours.
nm -D --defined-only "$plugin" | grep -q ' T sphkern_kernel_entry$'
! nm -D --defined-only "$plugin" | grep -q ' t \| T w$'
"$work/prefix/bin/sphkern" check --plugin "$plugin" --json >"$work/check.json"
python3 -c "
import json
r = json.load(open('$work/check.json'))
assert isinstance(r, list) and len(r) == 1, r
r = r[0]
assert r['kernel'] == 'morris_quintic_359', r['kernel']
assert abs(r['normalization']['3'] - 1.00279) < 5e-6, r['normalization']
assert abs(r['normalization']['2'] - 1) < 1e-9 and r['verdict'] == 'warn'
"
# The installed Python module finds the installed kernels, and loads the plugin built with the SDK.
if [[ -d "$build/python" ]]; then
    pydir=$(find "$work/prefix" -path '*dist-packages/sphkern*.so' -printf '%h\n' | head -n 1)
    [[ -n $pydir ]] || { echo "the Python module was not installed under dist-packages" >&2; exit 1; }
    PYTHONPATH="$pydir" /usr/bin/python3 -c "
import sphkern
assert sphkern.__file__.startswith('$work/prefix/'), sphkern.__file__
assert sphkern.load_plugin('$plugin')['name'] == 'morris_quintic_359'
names = [k['name'] for k in sphkern.kernels()]
assert 'cubic_bspline' in names and 'morris_quintic_359' in names, names
assert 'fcc' in [l['name'] for l in sphkern.lattices()]
r = sphkern.eps('morris_quintic_359', 'fcc', [1.0, 1.1])
assert r['eps_rho'].shape == (2,) and abs(r['eps_rho'][1]) < 0.1, r
"
fi
cmake --install "$work/example" --prefix "$work/prefix" >/dev/null
"$work/prefix/bin/sphkern" kernels --json | python3 -c "
import json, sys
names = [k['name'] for k in json.load(sys.stdin)]
assert 'morris_quintic_359' in names and 'cubic_bspline' in names, names
"
echo "1 passed, 0 failed"
