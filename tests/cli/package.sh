#!/usr/bin/env bash
# The Debian package: cpack builds it from this build tree; its metadata and its file
# list hold the program, the plugins, the data, the example lattices, the documents (the
# README and every document of share/docs it links), the man page and the bash completion.
# Usage: package.sh BUILD_DIR
set -eu
build=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work" >"$work/cpack.log" 2>&1 || { cat "$work/cpack.log" >&2; exit 1; }
deb=$(find "$work" -maxdepth 1 -name 'sphkern_*.deb')
test -n "$deb"
version=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$build/CMakeCache.txt")
test "$(dpkg-deb -f "$deb" Package)" = sphkern
test "$(dpkg-deb -f "$deb" Version)" = "$version"
dpkg-deb -f "$deb" Depends | grep -q 'libc6'
prefix=$(sed -n 's/^CMAKE_INSTALL_PREFIX:PATH=//p' "$build/CMakeCache.txt")
dpkg-deb -c "$deb" | awk '{print $6}' | sed 's|^\./|/|' >"$work/files"
for f in bin/sphkern share/man/man1/sphkern.1 share/bash-completion/completions/sphkern \
    share/doc/sphkern/README.md share/doc/sphkern/method.md share/doc/sphkern/LICENSE share/doc/sphkern/CITATION.cff \
    share/doc/sphkern/CHANGELOG.md share/doc/sphkern/examples/kernel-plugin/morris_quintic_359.c \
    share/sphkern/lattices/triangular.json share/sphkern/lattices/examples/honeycomb.json \
    share/sphkern/lattices/examples/kagome.json share/sphkern/lattices/examples/lieb.json \
    share/sphkern/lattices/examples/diamond.json share/sphkern/studies/potapov2021.json \
    include/sphkern/kernel_plugin.h; do
    grep -qx "$prefix/$f" "$work/files" || { echo "the package lacks $prefix/$f" >&2; exit 1; }
done
grep -Eq "^$prefix/lib/([a-z0-9_-]+/)?sphkern/plugins/cubic_bspline.so$" "$work/files"
# Every document of share/docs, beside the README that links it and in the data folder.
source_dir=$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$build/CMakeCache.txt")
documents=$(cd "$source_dir/share/docs" && ls -- *.md)
test "$(wc -w <<<"$documents")" -ge 10
for d in $documents; do
    for f in share/doc/sphkern/share/docs/$d share/sphkern/docs/$d; do
        grep -qx "$prefix/$f" "$work/files" || { echo "the package lacks $prefix/$f" >&2; exit 1; }
    done
done
# ... and the links between the installed documents resolve.
dpkg-deb -x "$deb" "$work/root"
/usr/bin/python3 "$source_dir/tests/cli/docs_links.py" "$work/root$prefix/share/doc/sphkern" >/dev/null
echo "package $(basename "$deb"): $(grep -c . "$work/files") entries"
