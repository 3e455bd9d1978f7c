// The docstrings of check, spectrum, block, pairing, relax, run and studies (numpydoc, as
// docstrings.hpp's): each names its command, and the arguments as the command's options.
#pragma once

namespace sphkern::doc {

inline constexpr const char* check = R"doc(The kernel author's check-up, as `sphkern check --json`.

Normalisation, derivative, continuity and moments of each kernel, each kernel checked in
a child process bounded by timeout.

Parameters
----------
kernel : str or sequence of str, optional
    The kernels to check, by name or file. Default: the kernels of plugin.
all : bool, default False
    Check every kernel found.
strict : bool, default False
    A warning fails the check too.
timeout : float, default 60.0
    Seconds a kernel may take, in [0.1, 3600].
plugin : str or sequence of str, optional
    Plugin or expression files: checked alone (without kernel and all), else loaded too.
params : dict of str to float, optional
    The parameters of every kernel checked.

Returns
-------
list of dict
    One document per kernel, as the command's --json array: kernel, verdict ("ok",
    "warn" or "fail") and checks (dimension, check, status, detail, and hint).

Raises
------
CheckFailed
    A kernel failed (or warned, with strict); the documents are on its results.

Examples
--------
>>> [r["verdict"] for r in sphkern.check("wendland_c2")]
['ok']
)doc";

inline constexpr const char* spectrum =
    R"doc(The Fourier transform of a kernel against kappa h, as `sphkern spectrum --json`.

Parameters
----------
kernel : str
    A kernel name, a plugin or expression file, or a blend "A+B".
dim : int
    The dimension D: 1, 2 or 3.
k : float, default 1.0
    k, for kernels whose formula depends on it, in [0.001, 100].
max : float, default 50.0
    The largest kappa h, in [0.1, 1000].
points : int, default 500
    Intervals on [0, max], 1 to 100000.
params : dict of str to float, optional
    The kernel's parameters.

Returns
-------
dict
    The document of `spectrum --json`: kernel, dimension, k, source ("plugin" or
    "quadrature"), min and at (the transform's minimum and its kappa h), first_zero (None
    where it has none), and curve, a numpy array of shape (points + 1, 2) of (kappa h, W^).

Examples
--------
>>> s = sphkern.spectrum("wendland_c2", 3, points=100)
>>> s["curve"].shape, s["source"]
((101, 2), 'quadrature')
)doc";

inline constexpr const char* block =
    R"doc(Direct SPH sums over a finite block of lattice cells, as `sphkern block --json`.

Parameters
----------
kernel : str
    A kernel name, a plugin or expression file, or a blend "A+B".
lattice : str
    A lattice name or file.
k : float
    The smoothing coefficient, h = k d.
size : sequence of int
    Cells along the basis vectors, [N1, N2] or [N1, N2, N3] (the last is vertical).
periodic : bool, default False
    Periodic lateral sides (the top is always free).
form : str, default "sum"
    The gradient form: "sum", "difference" or "monaghan".
threads : int, default 0
    Threads (0: every core).
a_p : str or float, default "voronoi"
    The volume coefficient: a name the lattice offers or a positive number.
vtk : str, optional
    Write the per-particle results as a legacy VTK file (ParaView).
csv : str, optional
    Write the per-particle results as CSV.
params : dict of str to float, optional
    The kernel's parameters.

Returns
-------
dict
    The document of `block --json` (kernel, lattice, k, a_p, size, particles, layers with
    each layer's extremes, timings ...) with the per-particle numpy arrays: positions (N, D),
    layer (N, int, 0 on top), eps_rho and eps_gradp (N).

Examples
--------
>>> b = sphkern.block("cubic_bspline", "sc", 1.2, [6, 6, 6], periodic=True)
>>> b["particles"], b["positions"].shape, int(b["layer"].max())
(216, (216, 3), 5)
)doc";

inline constexpr const char* pairing =
    R"doc(Linear stability against the motion of a disturbed lattice, k by k, as `sphkern pairing --json`.

Give k (or code and value), or kmin and kmax.

Parameters
----------
kernel : str
    A kernel name, a plugin or expression file, or a blend "A+B".
lattice : str
    A lattice name or file.
k : float, optional
    One k (h = k d).
code : str, optional
    An SPH code whose own setting gives the one k, with value (as eps's code).
value : float, optional
    The code's parameter, with code.
kmin, kmax : float, optional
    A range of k, with samples.
samples : int, default 1
    Evenly spaced k over [kmin, kmax], 1 to 1000.
noise : float, default 0.001
    The Gaussian displacement per axis at the start, in units of d, in (0, 0.01].
duration : float, default 100.0
    The time of motion, in units of d / c.
damping : float, default 0.1
    The velocity damping rate, in units of c / h.
dt : float, default 0.2
    The time step, in units of h / c.
gamma : float, default 5/3
    The adiabatic index of P = rho0 c^2 / gamma (rho / rho0)^gamma.
horizon : float, default 100.0
    The growth time (d / c) beyond which the linear verdict is weak.
seed : int, default 1
    The seed of the noise.
threads : int, default 0
    Threads (0: every core).
params : dict of str to float, optional
    The kernel's parameters.

Returns
-------
dict
    The document of `pairing --json`: the settings and points, one dict per k (verdict,
    omega2, growth_time, predicted and measured rates, rms and paired fractions at the start
    and end, expected, outcome, agrees), and code where a code's setting gave k.

Examples
--------
>>> p = sphkern.pairing("cubic_bspline", "sc", 1.0, duration=2.0)
>>> len(p["points"]), p["points"][0]["k"]
(1, 1.0)
)doc";

inline constexpr const char* relax = R"doc(Relax a particle set into a glass and judge it, as `sphkern relax --json`.

The set (a lattice block, a Poisson set or a particle file) moves in its periodic box under
the SPH pressure force with damping, or by particle shifting, at one fixed h.

Parameters
----------
kernel : str
    A kernel name, a plugin or expression file, or a blend "A+B".
source : str
    A lattice (name or file), "poisson", or a particle file (.h5/.hdf5, .csv, .vtk, a GADGET
    binary snapshot, a Phantom dump).
size : sequence of int, optional
    Lattice: the cells of the periodic block, [N1, N2] or [N1, N2, N3].
cell : str, optional
    Lattice: the cell size counts, "primitive" (default) or "rectangular".
sigma : float, default 0.0
    Lattice: the Gaussian displacement per axis, in units of d.
seed : int, default 1
    Lattice and poisson: the random seed.
count : int, optional
    Poisson: the number of particles.
dim : int, optional
    Poisson: 2 or 3 (default 3); file: 2 reads a 3-column set with one constant coordinate.
box : sequence of float, optional
    Poisson: the box sides (default 1); file: a periodic box from the origin.
particle_radius : float, optional
    SPlisHSPlasH VTK file: the scene's particle radius r; h = r, support 4 r.
array : str, optional
    PySPH file: the particle array, or "A,B,...".
h_over_l : float, optional
    h over the mean spacing l = V^(1/D), sphkern's own. Default, without nh and k: 1.2.
nh : float, optional
    h from the neighbour number N_H = c_D (R h)^D n.
k : float, optional
    Lattice: h = k d.
code : str, optional
    The code output is for: "swift", "gadget2", "gadget4" or "pysph", its layout and h; with
    value, the run's h and each written h as the code sets it.
value : float, optional
    The code's parameter (SWIFT's eta, GADGET's nngb, PySPH's hdx), with code.
method : str, default "pressure"
    "pressure" (SPH pressure force with damping) or "shift" (particle shifting).
steps : int, default 200
    At most this many steps.
tolerance : float, default 0.0
    Stop once a step's RMS move is below this many h (0: never).
gamma : float, default 5/3
    pressure: the adiabatic index of P = rho0 c^2 / gamma (rho / rho0)^gamma.
dt : float, default 0.2
    pressure: the time step, in units of h / c.
damping : float, default 0.5
    pressure: the velocity damping rate, in units of c / h.
alpha : float, default 0.1
    shift: dx = -alpha h^2 sum_j V_j grad W_ij.
max_move : float, default 0.1
    shift: the largest move of a step, in units of h.
threads : int, default 0
    Threads (0: every core).
rdf_max : float, default 3.0
    g(r) up to this many mean spacings.
rdf_bins : int, default 60
    The bins of g(r).
memory_limit : float, default 0.0
    The memory budget in GiB (0: three quarters of the available memory).
output : str, optional
    Write the relaxed set: .h5/.hdf5 (SWIFT's layout, or code's), .csv, or with code "phantom"
    any other name (a Phantom full dump).
rho0 : float, optional
    With output: the density written, masses rho0 V (default 1).
u : float, optional
    With an HDF5 or Phantom output: the internal energy written (default c^2 / (gamma (gamma - 1))).
tile : sequence of int, optional
    With output: write [N1, N2] or [N1, N2, N3] copies of the relaxed set side by side.
history : str, optional
    Write the history of the run: F.csv its steps as CSV, F.pvd the particles at every
    step as a ParaView series (F_k.vtu beside F.pvd).
params : dict of str to float, optional
    The kernel's parameters.

Returns
-------
dict
    The document of `relax --json` (source, settings, h, h_over_l, nh, steps_taken, stop,
    history, final, glass, poisson_rms_e0, ...; code and output where given) with the
    relaxed positions as a numpy array of shape (N, D) under positions.

Examples
--------
>>> r = sphkern.relax("cubic_bspline", "poisson", count=200, dim=2, steps=20)
>>> r["positions"].shape, r["steps_taken"]
((200, 2), 20)
)doc";

inline constexpr const char* run = R"doc(Run a study into a results folder, as `sphkern run`.

The folder is complete or not written at all: report.md, results.json, curves.csv and,
where gnuplot is found and the study asks for them, the figures (without gnuplot, a
RuntimeWarning says they were skipped).

Parameters
----------
study : str, optional
    A study file, or the name of a shipped study (studies()). Default: potapov2021.
output : str, optional
    The results folder. Default: sphkern-results/<study name>.
no_plots : bool, default False
    Do not draw the figures.
format : str, default "svg"
    The figure formats, comma-separated: svg, png, pdf.
force : bool, default False
    Replace a results folder sphkern wrote.
reproduce : str, optional
    A results.json: run the study it records again and say whether the numbers agree. Not
    with study, output or force.

Returns
-------
dict
    folder (the absolute path), cases, figures (the files drawn) and summary (the markdown
    the command prints); with reproduce: agreed (bool) and report (the text the command
    prints).

Examples
--------
>>> import os, tempfile
>>> folder = os.path.join(tempfile.mkdtemp(), "design")
>>> r = sphkern.run("design", folder, no_plots=True)
>>> sorted(os.listdir(r["folder"]))[:3]
['.sphkern-output', 'curves.csv', 'method.md']
>>> sphkern.run(reproduce=os.path.join(folder, "results.json"))["agreed"]
True
)doc";

inline constexpr const char* studies = R"doc(The shipped studies, as `sphkern studies --json` lists them.

Returns
-------
list of dict
    One dict per study: name, title, kernels (their number), lattices and file.

Examples
--------
>>> "potapov2021" in [s["name"] for s in sphkern.studies()]
True
)doc";

inline constexpr const char* settings =
    R"doc(The settings a command takes, as its table declares them once for the command line, Python and studies.

Parameters
----------
command : str
    A command of `sphkern --help` ("roots", "particles", ...).

Returns
-------
list of dict
    One dict per setting, in the order of the command's --help: key, type ("number",
    "integer", "word", "flag" or "list"), default (None where there is none), help, option
    (the command line's spelling, None where it has none), keyword (Python's, None where it
    has none), study (the JSON Pointer of the study section's key that takes it, below
    the section: "/k/steps"; None where studies have none), positional, required, hidden
    (an old name the command line keeps) and bounds (None, or the values a number may
    take: min, max, low "open" or "closed", the unit, and count: a whole number from min to
    max).

Examples
--------
>>> [s["default"] for s in sphkern.settings("roots") if s["key"] == "kmin"]
[0.75]
>>> [s["option"] for s in sphkern.settings("eps") if s["key"] == "a_p"]
['--ap']
>>> [s["study"] for s in sphkern.settings("stability") if s["key"] == "path"]
['/path_points']
)doc";

} // namespace sphkern::doc
