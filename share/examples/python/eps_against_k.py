#!/usr/bin/python3
"""eps_rho and eps_gradP against k for a few kernels on one lattice, as a notebook would
draw them: one call of sphkern.eps per kernel over a whole numpy array of k.

    PYTHONPATH=build/python /usr/bin/python3 share/examples/python/eps_against_k.py [LATTICE] [-o FIGURE.png]

matplotlib is optional: without it the script prints a table instead of drawing."""
import argparse
import sys

import numpy as np

import sphkern


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("lattice", nargs="?", default="fcc")
    parser.add_argument("-o", "--output", default="eps_against_k.png")
    parser.add_argument("--kernels", default="cubic_bspline,wendland_c2,wendland_c4,morris_quintic")
    args = parser.parse_args()

    ks = np.linspace(0.75, 1.25, 2001)
    curves = {name: sphkern.eps(name, args.lattice, ks) for name in args.kernels.split(",")}
    # Where each kernel is best: the k minimising the larger of the two errors.
    for name, eps in curves.items():
        worst = np.maximum(np.abs(eps["eps_rho"]), np.abs(eps["eps_gradp"]))
        i = int(np.argmin(worst))
        print(f"{name:<16} best k = {ks[i]:.4f}: eps_rho = {eps['eps_rho'][i]:+.5f}, "
              f"eps_gradP = {eps['eps_gradp'][i]:+.5f}, N_H = {eps['nh'][i]}")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib is not installed (apt-get install python3-matplotlib): no figure drawn", file=sys.stderr)
        return 0
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
    for name, eps in curves.items():
        top.plot(ks, eps["eps_rho"], label=name)
        bottom.plot(ks, eps["eps_gradp"], label=name)
    for axis, label in ((top, r"$\varepsilon_\rho$"), (bottom, r"$\varepsilon_{\nabla P}$")):
        axis.axhspan(-0.01, 0.01, color="0.9")
        axis.set_ylim(-0.1, 0.1)
        axis.set_ylabel(label)
        axis.grid(True)
    top.legend(fontsize=8)
    top.set_title(f"sphkern on {args.lattice} (a_p = voronoi)")
    bottom.set_xlabel("k = h / d")
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)
    print(f"wrote {args.output}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
