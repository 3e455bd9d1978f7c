#!/usr/bin/env python3
"""How many candidates the engine's neighbour search scans per neighbour kept, and what other
ways of cutting them would save (BENCHMARKS.md, "Where the search's time goes"). A model of the
grid in numpy, not the engine: bins a reach R across (y, z) and R/4 along x; a cluster is the
particles of `per` consecutive bins of a row; its candidates are the points of the 3 x 3 rows
around it within R of the box around its particles (gather_cluster); each particle then scans
them all (gather_from_cluster). Compared, for fcc (k = 1.2, R = 2.4 d) and a Poisson set of
the same density:
- other cluster shapes: the candidates per neighbour, and the points the cluster's gather
  scans per neighbour (its rows cut along x to the box widened by a reach and a bin: a bound
  on the chord the engine cuts);
- groups of 8 candidates with their bounding boxes, skipped where a particle is out of reach;
- each particle's rows cut to its own chord (bins of R/4 along x).
Usage: share/scripts/candidate_counts.py"""
import numpy as np

R = 2.4  # the cubic spline's support 2h at h = 1.2 d
CELLS = 16


def fcc_and_poisson():
    a = 4 ** (1 / 3)  # fcc's cubic cell with 4 sites and unit volume per site
    base = np.array([[0, 0, 0], [.5, .5, 0], [.5, 0, .5], [0, .5, .5]])
    idx = np.stack(np.meshgrid(range(CELLS), range(CELLS), range(CELLS), indexing="ij"), -1).reshape(-1, 3)
    fcc = ((idx[:, None, :] + base[None]) * a).reshape(-1, 3)
    poisson = np.random.default_rng(1).random(fcc.shape) * CELLS * a
    return {"fcc": fcc, "Poisson": poisson}


def clusters(P, across, x_bins_per_reach, per):
    """Each sampled cluster's particles and candidates (with their bins), away from the edges."""
    xw, yw = R / x_bins_per_reach, R / across
    bx, by, bz = (np.floor(P[:, 0] / xw).astype(int), np.floor(P[:, 1] / yw).astype(int), np.floor(P[:, 2] / yw).astype(int))
    order = np.lexsort((bx, by, bz))  # the grid's order: rows along x, bins along each row
    P, bx, by, bz = P[order], bx[order], by[order], bz[order]
    c0, x0 = int(3 * R / yw), int(3 * R / xw) // per * per
    for cz in range(c0, c0 + 2):
        for cy in range(c0, c0 + 2):
            for cx in range(x0, x0 + 6 * per, per):
                own = (bz == cz) & (by == cy) & (bx >= cx) & (bx < cx + per)
                if not own.any():
                    continue
                I = P[own]
                lo, hi = I.min(0), I.max(0)
                rows = (abs(bz - cz) <= across) & (abs(by - cy) <= across)
                scanned = rows & (P[:, 0] >= lo[0] - R - xw) & (P[:, 0] <= hi[0] + R + xw)
                e = np.maximum(0, np.maximum(lo - P, P - hi))
                keep = rows & ((e ** 2).sum(1) <= R * R)
                yield I, P[keep], (bx[keep], by[keep], bz[keep]), scanned.sum(), (xw, yw)


def neighbours(C, p):
    d = ((C - p) ** 2).sum(1)
    return ((d <= R * R) & (d > 0)).sum()


def main():
    print("| set | cluster (bins across a reach, along x a reach, per cluster) | particles a cluster | "
          "candidates a neighbour | gather's scan a neighbour |")
    print("|---|---|---:|---:|---:|")
    sets = fcc_and_poisson()
    for name, P in sets.items():
        for shape in ((1, 4, 2), (1, 4, 1), (2, 4, 4), (2, 4, 2)):
            parts = cands = nbrs = scan = count = 0
            for I, C, _, scanned, _ in clusters(P, *shape):
                for p in I:
                    cands += len(C)
                    nbrs += neighbours(C, p)
                parts += len(I)
                scan += scanned
                count += 1
            engine = " (the engine's)" if shape == (1, 4, 2) else ""
            print(f"| {name} | {shape[0]}, {shape[1]}, {shape[2]}{engine} | {parts / count:.1f} | {cands / nbrs:.2f} | "
                  f"{scan / nbrs:.2f} |")
    print()
    print("| set | candidates a neighbour (the engine's) | after groups of 8 pruned by their boxes | after each particle's own chord |")
    print("|---|---:|---:|---:|")
    for name, P in sets.items():
        cands = grouped = chord = nbrs = 0
        for I, C, (cbx, cby, cbz), _, (xw, yw) in clusters(P, 1, 4, 2):
            groups = [C[g:g + 8] for g in range(0, len(C), 8)]
            glo = np.array([g.min(0) for g in groups])
            ghi = np.array([g.max(0) for g in groups])
            sizes = np.array([len(g) for g in groups])
            for p in I:
                nbrs += neighbours(C, p)
                cands += len(C)
                d = np.maximum(0, np.maximum(glo - p, p - ghi))
                grouped += sizes[(d ** 2).sum(1) <= R * R].sum()
                gy = np.maximum(0, np.maximum(cby * yw - p[1], p[1] - (cby + 1) * yw))
                gz = np.maximum(0, np.maximum(cbz * yw - p[2], p[2] - (cbz + 1) * yw))
                half = np.sqrt(np.maximum(0, R * R - gy ** 2 - gz ** 2))
                chord += ((cbx >= np.floor((p[0] - half) / xw)) & (cbx <= np.floor((p[0] + half) / xw))).sum()
        print(f"| {name} | {cands / nbrs:.2f} | {grouped / nbrs:.2f} | {chord / nbrs:.2f} |")


if __name__ == "__main__":
    main()
