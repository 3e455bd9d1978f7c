#!/bin/bash
# 101 k values (--steps 100) of every 3D-capable paper kernel on five 3D lattices.
# Usage: bash share/scripts/stability_benchmark.sh build/sphkern
s=${1:-build/sphkern}
for l in sc fcc bcc hcp hex_prism; do
  for kern in cubic_bspline desbrun_spiky johnson_quadratic liu_quartic morris_quintic muller_poly6 super_gaussian; do
    "$s" stability $kern $l --kmin 0.8 --kmax 1.6 --steps 100 --json >/dev/null || exit 1
  done
done
