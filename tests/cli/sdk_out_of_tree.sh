#!/usr/bin/env bash
# The SDK works for a third party: install sphkern to a temporary prefix, build the
# example plugin out of tree with find_package(sphkern), check it, install it.
# The C++ example too: its second derivative extension, the ABI version the package
# exports, and its default build type.
# Usage: sdk_out_of_tree.sh BUILD_DIR EXAMPLE_DIR CXX_EXAMPLE_DIR
set -eu
build=$1 example=$2 cxx_example=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
# Where the build put libraries: on Debian a multiarch folder (lib/x86_64-linux-gnu), found
# by find_package and by the installed sphkern alike.
libdir=$(sed -n 's/^CMAKE_INSTALL_LIBDIR:[A-Z]*=//p' "$build/CMakeCache.txt")
test -d "$work/prefix/$libdir/sphkern/plugins" && test -f "$work/prefix/$libdir/cmake/sphkern/sphkernConfig.cmake"
echo "installed with libdir $libdir"
cmake -S "$example" -B "$work/example" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/example" >/dev/null
grep -q '^CMAKE_BUILD_TYPE:STRING=Release$' "$work/example/CMakeCache.txt"
plugin="$work/example/morris_quintic_359.so"
# Hidden visibility: the entry is the only exported symbol of ours.
nm -D --defined-only "$plugin" | grep -q ' T sphkern_kernel_entry$'
! nm -D --defined-only "$plugin" | grep -q ' t \| T w$'
# Its 3D constant 3/(359 pi) is off by 120/(359/3) - 1 = 0.279%: a wrong constant fails (exit 1), with the factor.
status=0
"$work/prefix/bin/sphkern" check --plugin "$plugin" --json >"$work/check.json" || status=$?
test "$status" -eq 1
python3 -c "
import json
r = json.load(open('$work/check.json'))
assert isinstance(r, list) and len(r) == 1, r
r = r[0]
assert r['kernel'] == 'morris_quintic_359', r['kernel']
assert abs(r['normalization']['3'] - 360 / 359) < 1e-9, r['normalization']
assert abs(r['normalization']['2'] - 1) < 1e-9 and r['verdict'] == 'fail'
n3 = [c for c in r['checks'] if c['check'] == 'normalization' and c['dimension'] == 3][0]
assert n3['status'] == 'fail' and 'divide the 3D constant by 1.00278' in n3['hint'], n3
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
# The C++ plugin: the package says which ABI the header has; sphkern checks the plugin's W''.
header=$(find "$work/prefix/include" -name kernel_plugin.h)
major=$(sed -n 's/^#define SPHKERN_KERNEL_ABI_MAJOR \([0-9]*\)u$/\1/p' "$header")
minor=$(sed -n 's/^#define SPHKERN_KERNEL_ABI_MINOR \([0-9]*\)u$/\1/p' "$header")
cmake -S "$cxx_example" -B "$work/cxx" -DCMAKE_PREFIX_PATH="$work/prefix" >"$work/cxx.log"
grep -q "sphkern plugin ABI $major.$minor\$" "$work/cxx.log"
cmake --build "$work/cxx" >/dev/null
nm -D --defined-only "$work/cxx/lucy_quartic.so" | grep -q ' T sphkern_kernel_entry$'
"$work/prefix/bin/sphkern" check --plugin "$work/cxx/lucy_quartic.so" --json >"$work/cxx.json"
python3 -c "
import json
r = json.load(open('$work/cxx.json'))[0]
# Lucy's kernel is no Wendland function: its 2D and 3D transforms dip below zero (a warning).
assert r['kernel'] == 'lucy_quartic' and r['verdict'] == 'warn', (r['kernel'], r['verdict'])
assert {(c['check'], c['dimension']) for c in r['checks'] if c['status'] != 'ok'} == {('fourier', 2), ('fourier', 3)}, r['checks']
assert all(abs(r['normalization'][d] - 1) < 1e-9 for d in '123'), r['normalization']
assert r['second_derivative'] == 'plugin'
assert [c for c in r['checks'] if c['check'] == 'second_derivative' and c['status'] == 'ok'], r['checks']
"
cmake --install "$work/example" --prefix "$work/prefix" >/dev/null
"$work/prefix/bin/sphkern" kernels --json | python3 -c "
import json, sys
names = [k['name'] for k in json.load(sys.stdin)]
assert 'morris_quintic_359' in names and 'cubic_bspline' in names, names
"
echo "1 passed, 0 failed"
