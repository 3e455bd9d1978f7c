#!/usr/bin/python3
"""sphkern against other SPH density codes on the same particles: PySPH and yt.

Usage:
  /usr/bin/python3 share/scripts/peers_compare.py [--sphkern build/sphkern] [--threads 1]
      [--size 100,100,100] [--k 1.2] [--yt-particles 200000] [--neighbours 64]
      [--sample 2000] [--seed 1] [--skip-pysph] [--skip-yt] [--markdown]
  /usr/bin/python3 share/scripts/peers_compare.py --from-json RESULT.json --markdown

PySPH (Debian's python3-pysph): sphkern's `block` writes a free fcc block (--csv: positions
and eps_rho); PySPH's SummationDensity with its CubicSpline (support 2h) runs on those
positions through SPHEvaluator with m = a_p, h = k (d = 1), serial or, with --threads
above 1, OpenMP on that many threads: its first call (compiling and building the neighbour
structures), the best of three calls after update() (the search and the sum: what a step of
a run costs once the particles moved) and the best of three warm calls (wall and CPU time).
SPHEvaluator's neighbour search keeps each particle's list (LinkedListNNPS with cache=True;
NeighborCache in pysph/base/nnps_base.pyx finds a particle's neighbours on its first request
and keeps them until update()), so a warm call sums over stored lists and searches nothing.
They are timed against sphkern's block sweep (density and pressure gradient, neighbour search
included; and with the block's setup, which places the particles and builds the grid, as
PySPH's update() bins them) and against
`sphkern particles` on the same positions written as CSV with h = k (its grid and sums
phases, the sums' CPU time and the whole process), best of three, the three codes taking
turns so that a shared machine's load falls on each alike. Checked: PySPH's density against
1 + eps_rho of both sphkern commands, to 1e-10 relative, every particle.

yt (Debian's python3-yt): uniform random particles in the unit cube (free: yt's neighbour
searches in add_sph_fields do not wrap), loaded with yt.load_particles; add_sph_fields
computes each particle's smoothing length H (the distance to its n-th nearest other
particle) and its gather density sum_j m_j C w(r_ij / H_i), yt's cubic spline with support H
(yt/utilities/lib/particle_kdtree_tools.pyx, generate_smoothing_length and
estimate_density; the kernel sph_kernel_cubic in yt/geometry/particle_deposit.pxd).
Timed (yt is serial; sphkern on --threads, default 1): yt's whole computation (load, h and density) against the whole
`sphkern particles --nh N_H` process on the same particles (a CSV file), N_H the same
neighbour number, sphkern's own h; and yt's three routines (k-d tree, h, density) against
sphkern's h, grid and sums phases. Checked: on a sample, yt's H against the distance to the
n-th neighbour from scipy's cKDTree and yt's density against an independent sum of yt's
formula with yt's H, to 1e-10 relative; every particle of `sphkern particles` given yt's H
(a file h with --support-per-h 1) against yt's density divided by H^3 (yt's estimate_density
leaves out the 1/H^3 of the kernel), to 1e-10; a sample of sphkern's --nh density against an
independent sum with sphkern's h, to 1e-10.

Prints one JSON document with every time, every ratio (peer / sphkern) and the agreement
figures; --markdown prints a table for share/docs/BENCHMARKS.md instead. A disagreement
beyond 1e-10 exits 1 with one line on stderr (the JSON still printed); a failure to run
exits 2 with one line.
Installs python3-pysph and python3-yt if missing (as root or through sudo).
"""
import argparse
import inspect
import json
import os
import platform
import subprocess
import sys
import tempfile
import time

TOLERANCE = 1e-10


class Failure(Exception):
    pass


def ensure_package(module, package):
    try:
        __import__(module)
    except ImportError:
        sudo = [] if os.geteuid() == 0 else ["sudo"]
        print(f"peers_compare: installing {package}", file=sys.stderr)
        subprocess.run(sudo + ["apt-get", "install", "-y", "-qq", "--no-install-recommends", package], check=True,
                       stdout=sys.stderr, env=dict(os.environ, DEBIAN_FRONTEND="noninteractive"))


def processor():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def run_sphkern(argv):
    """Runs sphkern with --json; returns its answer and the whole process's wall seconds."""
    start = time.perf_counter()
    proc = subprocess.run(argv + ["--json"], capture_output=True, text=True)
    wall = time.perf_counter() - start
    if proc.returncode != 0:
        last = (proc.stderr.strip().splitlines() or ["no message"])[-1]
        raise Failure(f"{' '.join(argv[:3])} failed (exit {proc.returncode}): {last}")
    return json.loads(proc.stdout), wall


def best_of(runs, key):
    return min(runs, key=key)


def write_csv(path, columns, names):
    import numpy as np
    # %.17g: every double reads back exactly, so both codes see the same positions.
    np.savetxt(path, np.column_stack(columns), delimiter=",", header=",".join(names), comments="", fmt="%.17g")


def read_sphkern_csv(path):
    """Per-particle CSV of sphkern particles: returns (h, eps_rho) in file order."""
    import numpy as np
    with open(path) as f:
        names = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1)
    order = np.argsort(data[:, names.index("id")], kind="stable")
    return data[order, names.index("h")], data[order, names.index("eps_rho")]


def relative(a, b):
    import numpy as np
    return float(np.max(np.abs(a - b) / np.abs(b)))


def cubic_yt(q):
    """yt's sph_kernel_cubic (particle_deposit.pxd): 8/pi (1 - 6 q^2 + 6 q^3) to q = 1/2,
    8/pi 2 (1 - q)^3 to q = 1, 0 beyond; q = r / H with H the support radius."""
    import numpy as np
    c = 2.5464790894703255
    return c * np.where(q <= 0.5, 1.0 - 6.0 * q * q * (1.0 - q), np.where(q <= 1.0, 2.0 * (1.0 - q) ** 3, 0.0))


def pysph_part(args, work, sphkern):
    import numpy as np
    csv = os.path.join(work, "block.csv")
    threads = str(args.threads)
    # The free (non-periodic) block: PySPH's periodic domains are axis-aligned, fcc's cell is not.
    block_cmd = [sphkern, "block", "cubic_bspline", "fcc", "--k", str(args.k), "--size", args.size,
                 "--threads", threads]
    summary, _ = run_sphkern(block_cmd + ["--csv", csv])
    data = np.loadtxt(csv, delimiter=",", skiprows=1)
    x, y, z, eps_rho = data[:, 0], data[:, 1], data[:, 2], data[:, 4]
    a_p = summary["a_p"]
    n = len(x)

    # The same positions for sphkern particles: h = k (d = 1) as a file h with support 2h,
    # m = a_p and rho = 1 (volume m / rho = a_p), rho0 = 1 so that rho = 1 + eps_rho.
    pcsv = os.path.join(work, "block_particles.csv")
    write_csv(pcsv, [x, y, z, np.full(n, args.k), np.full(n, a_p), np.ones(n)], ["x", "y", "z", "h", "m", "rho"])
    particles_cmd = [sphkern, "particles", "cubic_bspline", pcsv, "--support-per-h", "2", "--rho0", "1",
                     "--threads", threads]
    out = os.path.join(work, "block_particles_out.csv")
    run_sphkern(particles_cmd + ["--csv", out])
    _, particles_eps_rho = read_sphkern_csv(out)

    from compyle.config import get_config
    from pysph.base.kernels import CubicSpline
    from pysph.base.utils import get_particle_array
    from pysph.sph.basic_equations import SummationDensity
    from pysph.sph.equation import Group
    from pysph.tools.sph_evaluator import SPHEvaluator

    get_config().use_openmp = args.threads > 1
    # d = 1, h = k d, m = rho0 a_p d^3 with rho0 = 1: rho = sum_j m W = 1 + eps_rho.
    fluid = get_particle_array(name="fluid", x=x, y=y, z=z, h=np.full(n, args.k), m=np.full(n, a_p),
                               rho=np.zeros(n))
    evaluator = SPHEvaluator(arrays=[fluid], equations=[Group(equations=[SummationDensity(dest="fluid",
                                                                                         sources=["fluid"])])],
                             dim=3, kernel=CubicSpline(dim=3))
    start = time.perf_counter()
    evaluator.evaluate()  # first call: compiles (unless cached) and builds the neighbour structures
    first = time.perf_counter() - start
    # Three rounds, each code once per round, so that the load of a shared machine falls on
    # all of them alike; the block's sweep and the particles' runs without the CSV they wrote.
    runs, cpus, searched, searched_cpus, blocks, particle_runs = [], [], [], [], [], []
    for _ in range(3):
        blocks.append(run_sphkern(block_cmd)[0])
        particle_runs.append(run_sphkern(particles_cmd))
        start, start_cpu = time.perf_counter(), time.process_time()
        evaluator.update()  # the stored neighbour lists emptied: the next call searches again
        evaluator.evaluate()
        searched.append(time.perf_counter() - start)
        searched_cpus.append(time.process_time() - start_cpu)
        start, start_cpu = time.perf_counter(), time.process_time()
        evaluator.evaluate()
        runs.append(time.perf_counter() - start)
        cpus.append(time.process_time() - start_cpu)
    warm, warm_cpu = min(runs), min(cpus)
    search, search_cpu = min(searched), min(searched_cpus)
    block_seconds = min(b["seconds"]["evaluation"] for b in blocks)
    # The block's setup places its particles and builds its grid (PySPH's update() bins).
    block_with_setup = min(b["seconds"]["evaluation"] + b["seconds"]["setup"] for b in blocks)
    best, _ = best_of(particle_runs, key=lambda r: r[0]["phases"]["grid"] + r[0]["phases"]["sums"])
    particles_compute = best["phases"]["grid"] + best["phases"]["sums"]
    particles_wall = min(r[1] for r in particle_runs)
    particles_sums_cpu = min(r[0]["cpu_seconds"] for r in particle_runs)
    rho = fluid.get("rho")

    return {
        "set": f"free fcc block of {args.size} cells, h = {args.k} d",
        "size": args.size,
        "particles": n,
        "pair_interactions": summary["pair_interactions_per_pass"],
        "pysph_version": __import__("pysph").__version__,
        "pysph_openmp": args.threads > 1,
        "pysph_first_evaluate_seconds": first,
        # The evaluator's own construction of its search (the attribute is not visible from Python).
        "pysph_neighbour_lists_kept": "cache=True" in inspect.getsource(SPHEvaluator._create_nnps),
        "pysph_update_and_evaluate_seconds": search,
        "pysph_update_and_evaluate_cpu_seconds": search_cpu,
        "pysph_warm_evaluate_seconds": warm,
        "pysph_warm_evaluate_cpu_seconds": warm_cpu,
        "sphkern_block_density_and_gradient_seconds": block_seconds,
        "sphkern_block_setup_and_sweep_seconds": block_with_setup,
        "sphkern_particles_grid_and_sums_seconds": particles_compute,
        "sphkern_particles_phases": best["phases"],
        "sphkern_particles_whole_process_seconds": particles_wall,
        "sphkern_particles_sums_cpu_seconds": particles_sums_cpu,
        "ratio_pysph_first_over_sphkern_block": first / block_seconds,
        "ratio_pysph_update_and_evaluate_over_sphkern_block": search / block_seconds,
        "ratio_pysph_update_and_evaluate_over_sphkern_block_with_setup": search / block_with_setup,
        "ratio_pysph_update_and_evaluate_over_sphkern_particles": search / particles_compute,
        "ratio_pysph_warm_over_sphkern_block": warm / block_seconds,
        "ratio_pysph_first_over_sphkern_particles": first / particles_compute,
        "ratio_pysph_warm_over_sphkern_particles": warm / particles_compute,
        "ratio_pysph_warm_over_sphkern_particles_whole_process": warm / particles_wall,
        "ratio_pysph_warm_cpu_over_sphkern_particles_sums_cpu": warm_cpu / particles_sums_cpu,
        "max_relative_difference_pysph_vs_block": relative(1.0 + eps_rho, rho),
        "max_relative_difference_pysph_vs_particles": relative(1.0 + particles_eps_rho, rho),
    }


def yt_part(args, work, sphkern):
    import numpy as np
    from scipy.spatial import cKDTree

    n = args.yt_particles
    rng = np.random.default_rng(args.seed)
    pos = rng.random((n, 3))
    mass = np.full(n, 1.0 / n)
    # m = 1/N and rho = 1: file volumes m / rho = 1/N (the unit cube's share), rho0 = 1.
    csv = os.path.join(work, "random.csv")
    write_csv(csv, [pos[:, 0], pos[:, 1], pos[:, 2], mass, np.ones(n)], ["x", "y", "z", "m", "rho"])
    pos = np.loadtxt(csv, delimiter=",", skiprows=1, usecols=(0, 1, 2))  # exactly what sphkern reads

    threads = str(args.threads)
    nh_cmd = [sphkern, "particles", "cubic_bspline", csv, "--nh", str(args.neighbours), "--rho0", "1",
              "--threads", threads]
    nh_runs = [run_sphkern(nh_cmd) for _ in range(3)]
    nh_wall = min(r[1] for r in nh_runs)
    nh_best = best_of(nh_runs, key=lambda r: sum(r[0]["phases"][p] for p in ("h", "grid", "sums")))[0]
    nh_compute = sum(nh_best["phases"][p] for p in ("h", "grid", "sums"))
    nh_out = os.path.join(work, "random_nh.csv")
    run_sphkern(nh_cmd + ["--csv", nh_out])
    nh_h, nh_eps_rho = read_sphkern_csv(nh_out)

    import yt
    from yt.config import ytcfg
    yt.set_log_level(50)
    ytcfg["yt", "suppress_stream_logging"] = True  # no progress bars on stderr
    from yt.utilities.lib.cykdtree import PyKDTree
    from yt.utilities.lib.particle_kdtree_tools import estimate_density, generate_smoothing_length

    fields = {"particle_position_x": pos[:, 0].copy(), "particle_position_y": pos[:, 1].copy(),
              "particle_position_z": pos[:, 2].copy(), "particle_mass": mass}
    bbox = np.array([[0.0, 1.0]] * 3)
    start = time.perf_counter()
    ds = yt.load_particles(fields, length_unit=1.0, mass_unit=1.0, bbox=bbox, periodicity=(False, False, False))
    ds.add_sph_fields(n_neighbors=args.neighbours, kernel="cubic", sph_ptype="io")
    ad = ds.all_data()
    yt_h = ad["io", "smoothing_length"].to("code_length").d
    yt_rho = ad["io", "density"].to("code_mass/code_length**3").d
    yt_whole = time.perf_counter() - start
    # yt's own order of the particles could differ from the file's: map through the positions.
    yt_pos = np.column_stack([ad["io", f"particle_position_{a}"].to("code_length").d for a in "xyz"])
    if not np.array_equal(yt_pos, pos):
        order = np.lexsort(pos.T[::-1])
        yt_order = np.lexsort(yt_pos.T[::-1])
        back = np.empty(n, dtype=int)
        back[order] = yt_order
        yt_h, yt_rho = yt_h[back], yt_rho[back]

    # yt's three routines alone, called as add_sph_fields calls them.
    start = time.perf_counter()
    tree = PyKDTree(pos.astype("float64"), left_edge=bbox[:, 0], right_edge=bbox[:, 1],
                    periodic=(False, False, False), leafsize=2 * args.neighbours)
    tree_pos = np.ascontiguousarray(pos[tree.idx])
    h_tree = generate_smoothing_length(tree_pos, tree, args.neighbours)
    rho_tree = estimate_density(tree_pos, mass[tree.idx], h_tree, tree, kernel_name="cubic")
    yt_core = time.perf_counter() - start
    core_order = np.argsort(tree.idx)
    core_same = bool(np.array_equal(h_tree[core_order], yt_h) and np.array_equal(rho_tree[core_order], yt_rho))

    # Independent check of yt on a sample: the n-th neighbour's distance and yt's sum.
    ktree = cKDTree(pos)
    sample = rng.choice(n, size=min(args.sample, n), replace=False)
    dist, _ = ktree.query(pos[sample], k=args.neighbours + 1)  # the particle itself is the first
    h_check = relative(yt_h[sample], dist[:, -1])
    mine = np.empty(len(sample))
    for i, p in enumerate(sample):
        js = np.array(ktree.query_ball_point(pos[p], yt_h[p]), dtype=int)
        r = np.sqrt(np.sum((pos[js] - pos[p]) ** 2, axis=1))
        # yt's sum: m_i w(0) plus the others strictly inside H, no 1/H^3 factor.
        js, r = js[(js != p) & (r < yt_h[p])], r[(js != p) & (r < yt_h[p])]
        mine[i] = mass[p] * cubic_yt(np.zeros(1))[0] + np.sum(mass[js] * cubic_yt(r / yt_h[p]))
    rho_check = relative(yt_rho[sample], mine)

    # sphkern with yt's H as its file h (support 1 H): its density must be yt's over H^3.
    h_csv = os.path.join(work, "random_yt_h.csv")
    write_csv(h_csv, [pos[:, 0], pos[:, 1], pos[:, 2], yt_h, mass, np.ones(n)],
              ["x", "y", "z", "h", "m", "rho"])
    h_out = os.path.join(work, "random_yt_h_out.csv")
    yth_answer, yth_wall = run_sphkern([sphkern, "particles", "cubic_bspline", h_csv, "--support-per-h", "1",
                                        "--rho0", "1", "--threads", threads, "--csv", h_out])
    _, yth_eps_rho = read_sphkern_csv(h_out)
    sphkern_vs_yt = relative(1.0 + yth_eps_rho, yt_rho / yt_h ** 3)

    # Independent check of sphkern's --nh density: the cubic B-spline with support 2h is
    # yt's kernel with H = 2h, over H^3.
    h_nh = float(nh_h[0])
    mine_nh = np.empty(len(sample))
    for i, p in enumerate(sample):
        js = np.array(ktree.query_ball_point(pos[p], 2.0 * h_nh), dtype=int)
        r = np.sqrt(np.sum((pos[js] - pos[p]) ** 2, axis=1))
        mine_nh[i] = np.sum(mass[js] * cubic_yt(r / (2.0 * h_nh))) / (2.0 * h_nh) ** 3
    nh_check = relative(1.0 + nh_eps_rho[sample], mine_nh)

    return {
        "set": f"uniform random in the unit cube, free, seed {args.seed}",
        "particles": n,
        "neighbours": args.neighbours,
        "yt_version": yt.__version__,
        "yt_h": "distance to the n-th nearest other particle (support radius H)",
        "yt_mean_h": float(np.mean(yt_h)),
        "sphkern_h": h_nh,
        "sphkern_support": 2.0 * h_nh,
        "sphkern_mean_neighbours": nh_best["mean_neighbours"],
        "yt_whole_seconds": yt_whole,
        "yt_tree_h_density_seconds": yt_core,
        "yt_routines_reproduce_add_sph_fields": core_same,
        "sphkern_nh_whole_process_seconds": nh_wall,
        "sphkern_nh_h_grid_sums_seconds": nh_compute,
        "sphkern_nh_phases": nh_best["phases"],
        "sphkern_yt_h_whole_process_seconds": yth_wall,
        "sphkern_yt_h_phases": yth_answer["phases"],
        "ratio_yt_whole_over_sphkern_whole_process": yt_whole / nh_wall,
        "ratio_yt_routines_over_sphkern_phases": yt_core / nh_compute,
        "sample": len(sample),
        "max_relative_difference_yt_h_vs_ckdtree": h_check,
        "max_relative_difference_yt_density_vs_independent_sum": rho_check,
        "max_relative_difference_sphkern_with_yt_h_vs_yt_density_over_h3": sphkern_vs_yt,
        "max_relative_difference_sphkern_nh_vs_independent_sum": nh_check,
        "yt_density_over_h3_mean": float(np.mean(yt_rho / yt_h ** 3)),
        "yt_density_mean": float(np.mean(yt_rho)),
    }


def markdown(result):
    lines = [f"Processor: {result['processor']}; {result['threads']} thread(s) each "
             f"(PySPH {'OpenMP' if result['threads'] > 1 else 'serial'}, yt serial).", ""]
    lines.append("| peer | set | particles | peer's work | peer [s] | sphkern's work | sphkern [s] | peer / sphkern "
                 "| max relative density difference |")
    lines.append("|---|---|---:|---|---:|---|---:|---:|---:|")
    p = result.get("pysph")
    if p:
        mode = "OpenMP" if p["pysph_openmp"] else "serial"
        agree = f"{max(p['max_relative_difference_pysph_vs_block'], p['max_relative_difference_pysph_vs_particles']):.1e}"
        rows = [
            ("first evaluate()", p["pysph_first_evaluate_seconds"], "`block` density + gradient sweep",
             p["sphkern_block_density_and_gradient_seconds"]),
            ("update() + evaluate(): search and sum, best of 3", p["pysph_update_and_evaluate_seconds"],
             "`block` density + gradient sweep", p["sphkern_block_density_and_gradient_seconds"]),
            ("update() + evaluate(): search and sum, best of 3", p["pysph_update_and_evaluate_seconds"],
             "`block` setup (positions, grid) + sweep", p["sphkern_block_setup_and_sweep_seconds"]),
            ("warm evaluate(): stored lists, no search, best of 3", p["pysph_warm_evaluate_seconds"],
             "`block` density + gradient sweep", p["sphkern_block_density_and_gradient_seconds"]),
            ("first evaluate()", p["pysph_first_evaluate_seconds"], "`particles` grid + sums",
             p["sphkern_particles_grid_and_sums_seconds"]),
            ("update() + evaluate(): search and sum, best of 3", p["pysph_update_and_evaluate_seconds"],
             "`particles` grid + sums", p["sphkern_particles_grid_and_sums_seconds"]),
            ("warm evaluate(): stored lists, no search, best of 3", p["pysph_warm_evaluate_seconds"],
             "`particles` grid + sums", p["sphkern_particles_grid_and_sums_seconds"]),
            ("warm evaluate(): stored lists, no search, best of 3", p["pysph_warm_evaluate_seconds"],
             "`particles` whole process (CSV read)",
             p["sphkern_particles_whole_process_seconds"]),
            ("update() + evaluate(), CPU time", p["pysph_update_and_evaluate_cpu_seconds"],
             "`particles` sums, CPU time", p["sphkern_particles_sums_cpu_seconds"]),
        ]
        for work, peer, swork, s in rows:
            lines.append(f"| PySPH {p['pysph_version']} {mode} | fcc block {p['size']} | {p['particles']} "
                         f"| {work} | {peer:.4g} | {swork} | {s:.4g} | {peer / s:.3g} | {agree} |")
        if p.get("pysph_neighbour_lists_kept"):
            lines.append("")
            lines.append("PySPH's SPHEvaluator keeps each particle's neighbour list (its search is made with cache=True): its warm "
                         "evaluate() searches nothing; after update() it searches again, as sphkern's sweeps do.")
            lines.append("")
    y = result.get("yt")
    if y:
        agree = f"{y['max_relative_difference_yt_density_vs_independent_sum']:.1e} (own sum)"
        lines.append(f"| yt {y['yt_version']} | uniform random, free | {y['particles']} "
                     f"| load_particles + add_sph_fields ({y['neighbours']} neighbours) | {y['yt_whole_seconds']:.4g} "
                     f"| `particles --nh {y['neighbours']}` whole process | {y['sphkern_nh_whole_process_seconds']:.4g} "
                     f"| {y['ratio_yt_whole_over_sphkern_whole_process']:.3g} | {agree} |")
        lines.append(f"| yt {y['yt_version']} | uniform random, free | {y['particles']} "
                     f"| k-d tree + generate_smoothing_length + estimate_density | {y['yt_tree_h_density_seconds']:.4g} "
                     f"| `particles --nh {y['neighbours']}` h + grid + sums | {y['sphkern_nh_h_grid_sums_seconds']:.4g} "
                     f"| {y['ratio_yt_routines_over_sphkern_phases']:.3g} | {agree} |")
        lines.append("")
        lines.append(f"yt's H against cKDTree's {y['neighbours']}th-neighbour distance: "
                     f"{y['max_relative_difference_yt_h_vs_ckdtree']:.1e}; yt's density against an independent sum "
                     f"of its formula ({y['sample']} particles): "
                     f"{y['max_relative_difference_yt_density_vs_independent_sum']:.1e}; `sphkern particles` given "
                     f"yt's H against yt's density over H^3 (every particle): "
                     f"{y['max_relative_difference_sphkern_with_yt_h_vs_yt_density_over_h3']:.1e}; sphkern's --nh "
                     f"density against an independent sum: "
                     f"{y['max_relative_difference_sphkern_nh_vs_independent_sum']:.1e}.")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sphkern", default="build/sphkern")
    parser.add_argument("--threads", type=int, default=1,
                        help="threads of each code (default 1; above 1 PySPH runs with OpenMP)")
    parser.add_argument("--size", default="100,100,100", help="PySPH: cells of the fcc block")
    parser.add_argument("--k", type=float, default=1.2, help="PySPH: h = k d")
    parser.add_argument("--yt-particles", type=int, default=200000, help="yt: number of random particles")
    parser.add_argument("--neighbours", type=int, default=64, help="yt: n_neighbors, and sphkern's --nh")
    parser.add_argument("--sample", type=int, default=2000, help="yt: particles checked by the independent sum")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--skip-pysph", action="store_true")
    parser.add_argument("--skip-yt", action="store_true")
    parser.add_argument("--markdown", action="store_true", help="print the Markdown table instead of the JSON")
    parser.add_argument("--from-json", metavar="FILE",
                        help="measure nothing: print the table (with --markdown) of a JSON document this script printed")
    args = parser.parse_args()
    if args.from_json:
        try:
            with open(args.from_json) as f:
                saved = json.load(f)
            print(markdown(saved) if args.markdown else json.dumps(saved, indent=2))
        except (OSError, ValueError, KeyError) as e:
            print(f"peers_compare: {args.from_json}: {e}", file=sys.stderr)
            return 2
        return 0
    if args.threads < 1:
        print("peers_compare: --threads must be at least 1", file=sys.stderr)
        return 2
    sphkern = os.path.abspath(args.sphkern)
    if not os.access(sphkern, os.X_OK):
        print(f"peers_compare: no sphkern executable at {args.sphkern}", file=sys.stderr)
        return 2
    # OpenMP reads its thread count when PySPH's compiled code first runs.
    os.environ["OMP_NUM_THREADS"] = str(args.threads)

    result = {"processor": processor(), "cores": os.cpu_count(), "threads": args.threads,
              "sphkern_version": subprocess.run([sphkern, "--version"], capture_output=True,
                                                text=True).stdout.strip()}
    try:
        if not args.skip_pysph:
            ensure_package("pysph", "python3-pysph")
        if not args.skip_yt:
            ensure_package("yt", "python3-yt")
        with tempfile.TemporaryDirectory(prefix="peers_compare_") as work:
            if not args.skip_pysph:
                result["pysph"] = pysph_part(args, work, sphkern)
            if not args.skip_yt:
                result["yt"] = yt_part(args, work, sphkern)
    except (Failure, subprocess.CalledProcessError, OSError, ValueError, KeyError) as e:
        print(f"peers_compare: {e}", file=sys.stderr)
        return 2

    print(markdown(result) if args.markdown else json.dumps(result, indent=2))
    worst = []
    for part in ("pysph", "yt"):
        for key, value in result.get(part, {}).items():
            if key.startswith("max_relative_difference") and not value <= TOLERANCE:
                worst.append(f"{key} = {value:.3g}")
    if worst:
        print(f"peers_compare: densities differ by more than {TOLERANCE:g}: {'; '.join(worst)}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
