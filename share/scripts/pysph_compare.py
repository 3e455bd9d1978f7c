#!/usr/bin/python3
"""sphkern against PySPH, side by side in one run: the SPH density of the same
particles with the same cubic spline (PySPH's CubicSpline, support 2h).

Usage: /usr/bin/python3 share/scripts/pysph_compare.py [--sphkern build/sphkern] [--size 100,100,100]
Installs Debian's python3-pysph if it is missing (as root or through sudo).
sphkern writes the block's positions and densities (--csv); PySPH evaluates
SummationDensity on those positions through its SPHEvaluator; the script checks that
the densities agree to 1e-10 and prints both times and their ratio."""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time


def ensure_pysph():
    try:
        import pysph  # noqa: F401
    except ImportError:
        sudo = [] if os.geteuid() == 0 else ["sudo"]
        print("pysph_compare: installing python3-pysph", file=sys.stderr)
        subprocess.run(sudo + ["apt-get", "install", "-y", "-qq", "python3-pysph"], check=True,
                       stdout=sys.stderr, env=dict(os.environ, DEBIAN_FRONTEND="noninteractive"))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--sphkern", default="build/sphkern")
    parser.add_argument("--size", default="100,100,100")
    parser.add_argument("--k", type=float, default=1.2)
    parser.add_argument("--threads", type=int, default=0, help="sphkern threads (0: every core)")
    parser.add_argument("--openmp", action="store_true", help="let PySPH use OpenMP")
    args = parser.parse_args()
    ensure_pysph()
    import numpy as np

    with tempfile.TemporaryDirectory() as work:
        csv = os.path.join(work, "block.csv")
        # The free (non-periodic) block: PySPH's periodic domains are axis-aligned, fcc's cell is not.
        out = subprocess.run([args.sphkern, "block", "cubic_bspline", "fcc", "--k", str(args.k), "--size", args.size,
                              "--threads", str(args.threads), "--csv", csv, "--json"],
                             check=True, capture_output=True, text=True).stdout
        summary = json.loads(out)
        data = np.loadtxt(csv, delimiter=",", skiprows=1)
    x, y, z, eps_rho = data[:, 0], data[:, 1], data[:, 2], data[:, 4]
    a_p = summary["a_p"]
    n = len(x)

    from compyle.config import get_config
    from pysph.base.kernels import CubicSpline
    from pysph.base.utils import get_particle_array
    from pysph.sph.basic_equations import SummationDensity
    from pysph.sph.equation import Group
    from pysph.tools.sph_evaluator import SPHEvaluator

    get_config().use_openmp = args.openmp
    # d = 1, h = k d, m = rho0 a_p d^3 with rho0 = 1: rho = sum_j m W = 1 + eps_rho.
    fluid = get_particle_array(name="fluid", x=x, y=y, z=z, h=np.full(n, args.k), m=np.full(n, a_p),
                               rho=np.zeros(n))
    evaluator = SPHEvaluator(arrays=[fluid], equations=[Group(equations=[SummationDensity(dest="fluid",
                                                                                         sources=["fluid"])])],
                             dim=3, kernel=CubicSpline(dim=3))
    start = time.perf_counter()
    evaluator.evaluate()  # first call: compiles and builds the neighbour structures
    first = time.perf_counter() - start
    runs = []
    for _ in range(3):
        start = time.perf_counter()
        evaluator.evaluate()
        runs.append(time.perf_counter() - start)
    pysph_rho = fluid.get("rho")

    worst = float(np.max(np.abs(pysph_rho - (1.0 + eps_rho)) / pysph_rho))
    # sphkern's one sweep computes the density and the pressure gradient; PySPH only the density.
    sphkern_seconds = summary["seconds"]["evaluation"]
    pysph_time = min(runs)
    result = {
        "particles": n,
        "pair_interactions": summary["pair_interactions_per_pass"],
        "sphkern_threads": summary["threads"],
        "pysph_openmp": args.openmp,
        "sphkern_density_and_gradient_seconds": sphkern_seconds,
        "pysph_first_evaluate_seconds": first,
        "pysph_evaluate_seconds": pysph_time,
        "ratio_pysph_warm_over_sphkern": pysph_time / sphkern_seconds,
        "ratio_pysph_first_over_sphkern": first / sphkern_seconds,
        "max_relative_density_difference": worst,
    }
    print(json.dumps(result, indent=2))
    if worst > 1e-10:
        print(f"pysph_compare: densities differ by {worst:.3g} (more than 1e-10)", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
