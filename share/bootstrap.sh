#!/usr/bin/env bash
# Sets sphkern up on Debian 12 and runs it:
#   bash share/bootstrap.sh run [STUDY] [sphkern run options]   the default study (the main job)
#   bash share/bootstrap.sh test                                every test
# Installs the missing Debian packages (as root, or through sudo), configures and
# builds into build/, then runs.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(cmake make g++ libeigen3-dev libboost-dev libboost-filesystem-dev libspdlog-dev libfmt-dev
    nlohmann-json3-dev doctest-dev libcli11-dev libmuparser-dev libhdf5-dev libssl-dev voro++-dev gnuplot-nox libbenchmark-dev python3 python3-jsonschema python3-yaml dpkg-dev groff-base
    python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest python3-h5py)
# The tests compare with a peer code's own sums (PySPH compiles its equations with Cython), read
# files SPLASH writes (GADGET format 1) and reads (Phantom dumps), read ParaView's files with VTK,
# and hold the sources to clang-format.
[[ ${1:-run} == test ]] && packages+=(python3-pysph splash python3-vtk9 clang-format)
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
    echo "bootstrap: installing ${missing[*]}" >&2
    sudo=""
    [[ $(id -u) -eq 0 ]] || sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

# SPHKERN_WERROR=ON (CI) makes every compiler warning an error.
# Libraries in Debian's multiarch folder (lib/x86_64-linux-gnu), as Debian installs them.
multiarch=$(gcc -print-multiarch 2>/dev/null || true)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSPHKERN_WERROR="${SPHKERN_WERROR:-OFF}" \
    ${multiarch:+-DCMAKE_INSTALL_LIBDIR="lib/$multiarch"} >/dev/null

case "${1:-run}" in
run)
    # The program and its kernel plugins only: the tests, benchmarks and the Python module are for `test`.
    cmake --build build -j "$(nproc)" --target sphkern >&2
    shift || true
    if (($#)) && [[ $1 != -* ]]; then study=$1; shift; else study=potapov2021; fi
    exec build/sphkern run "$study" --force "$@"
    ;;
test)
    cmake --build build -j "$(nproc)" >&2
    exec ctest --test-dir build --output-on-failure -j 2
    ;;
*)
    echo "usage: bash share/bootstrap.sh run [STUDY] [options] | test" >&2
    exit 2
    ;;
esac
