// The module's docstrings (numpydoc: summary, Parameters, Returns, Examples). pybind11 puts
// each function's signature, made from its binding, on the first line above them.
// tests/python/test_docstrings.py checks that every parameter is described and runs the examples.
#pragma once

#include <string>

namespace sphkern::doc {

inline constexpr const char* module =
    R"doc(sphkern: accuracy of SPH smoothing kernels on particle lattices and any particle set.

Every function returns what the command line's --json prints, as Python objects, with
numpy arrays where the input is an array. Lengths on a lattice are in units of its
nearest-neighbour distance d, and k = h / d.

Every error is a sphkern.Error with one line naming the argument, what is wrong and what
was expected, and its exit_code (the command line's for the same error): BadValue (a
ValueError), UnknownName (a BadValue and a LookupError: a kernel, lattice, study or code
that is not known), FileError (a BadValue and a FileNotFoundError), PluginError (a
RuntimeError), OutputError (an OSError) and CheckFailed. A wrong type where pybind11 checks
the signature raises TypeError; an interruption, KeyboardInterrupt.
)doc";

inline constexpr const char* kernels = R"doc(Every kernel found, as `sphkern kernels --json` lists them.

The shipped plugins, those on SPHKERN_PLUGIN_PATH and the files loaded with load_plugin.

Returns
-------
list of dict
    One dict per kernel: name, title, support (the support radius R in units of h),
    dimensions, parameters, breakpoints, separate_derivative, reference and file.

Examples
--------
>>> "cubic_bspline" in [k["name"] for k in sphkern.kernels()]
True
)doc";

inline constexpr const char* lattices = R"doc(The shipped lattices, as `sphkern lattices --json` lists them.

Returns
-------
list of dict
    One dict per lattice: name, title, dimension, sites (of the motif), gravity,
    volume_coefficients (a_p of each volume model) and file.

Examples
--------
>>> fcc = next(l for l in sphkern.lattices() if l["name"] == "fcc")
>>> fcc["dimension"], fcc["sites"]
(3, 1)
)doc";

inline constexpr const char* load_plugin = R"doc(Load a kernel plugin library or an expression kernel file.

The file is probed as the command line probes it (in a child process); afterwards its
kernel is known by name to every function.

Parameters
----------
path : str
    A plugin library (.so) or an expression kernel file (.json).

Returns
-------
dict
    The kernel's entry, as kernels() lists it.

Examples
--------
>>> import json, os, tempfile
>>> path = os.path.join(tempfile.mkdtemp(), "example_cubic.json")
>>> with open(path, "w") as f:
...     json.dump({"name": "example_cubic", "support": 2, "dimensions": [3],
...                "w": "q < 1 ? 1 - 1.5*q^2 + 0.75*q^3 : (q < 2 ? 0.25*(2-q)^3 : 0)"}, f)
>>> sphkern.load_plugin(path)["name"]
'example_cubic'
)doc";

inline constexpr const char* load_lattice = R"doc(Read and validate a lattice file.

Parameters
----------
path : str
    A lattice file (JSON; share/docs/lattice-format.md).

Returns
-------
dict
    The lattice's entry, as lattices() lists it. Its path can be given wherever a
    function takes a lattice.

Examples
--------
>>> fcc = next(l for l in sphkern.lattices() if l["name"] == "fcc")
>>> sphkern.load_lattice(fcc["file"])["name"]
'fcc'
)doc";

inline constexpr const char* eps = R"doc(The hydrostatic errors of a kernel on a lattice at one or many k.

One C++ loop over every k, without the GIL.

Parameters
----------
kernel : str
    A kernel name, a plugin or expression file, or a blend "A+B".
lattice : str
    A lattice name or a lattice file.
k : float or array_like
    k = h / d, the smoothing length over the nearest-neighbour distance; in (0, 100].
a_p : str or float, default "voronoi"
    The volume coefficient: a model the lattice offers ("voronoi", "ball", "cube") or
    a positive number (V = a_p d^D).
gravity : sequence of float, optional
    The direction of gravity, one component per dimension. Default: the lattice's.
site : int, default 0
    The motif site the errors are computed at.
params : dict of str to float, optional
    The kernel's parameters, as `--set NAME=VALUE`.
axis : str, default "k"
    The scale of k: "k" (h / d) or "h_over_l" (h / V^(1/D)).
shells : sequence of float, optional
    Sum over these shell radii only (in d), as the paper does; default every shell inside
    the support.
continue_past_support : bool, default False
    With shells: the kernel's formula evaluated past q = R instead of truncated.

Returns
-------
dict of numpy.ndarray
    eps_rho, eps_gradp, eps_lateral (float) and nh (int, the neighbours inside the
    support), each shaped like k.

Examples
--------
>>> r = sphkern.eps("cubic_bspline", "fcc", [1.0, 1.2])
>>> r["eps_rho"].shape, r["nh"].dtype.kind
((2,), 'i')
>>> bool(abs(sphkern.eps("cubic_bspline", "fcc", 1.2)["eps_rho"]) < 0.01)
True
)doc";

inline constexpr const char* assess =
    R"doc(One verdict on a setting, k or an SPH code's own, on a lattice or a particle file.

As `sphkern assess`: the errors at every site against condition (22) with the margin, the
linear verdict for fixed and adaptive h, the recommended setting of a window of k, and one
line a person can act on. On a particle file, a code's setting judged on the set: its
interior and free surface told apart, condition (22) on the interior, the same setting's
linear stability on every lattice of the set's dimension; or the code's parameter swept
over a range, and the value the set needs.

Parameters
----------
kernel : str
    A kernel's name, or a plugin or expression file.
lattice : str or os.PathLike
    A lattice's name or file, or a particle file (SWIFT, GADGET, PySPH, CSV, VTK, a GADGET
    binary snapshot, a Phantom dump).
k : float, optional
    The setting as sphkern's k = h / d; else code and value.
code : str, optional
    "swift", "phantom", "gadget2", "gadget4", "pysph" or "dualsphysics".
value : float, optional
    The code's own setting (SWIFT's eta, Phantom's hfact, GADGET's weighted neighbour
    number, PySPH's hdx, DualSPHysics' coefh).
kmin : float, default 0.75
    The window of the recommended setting, smallest k.
kmax : float, default 2.0
    Its largest k.
epsilon : float, default 0.01
    The tolerance of condition (22).
gamma : float, default 5/3
    The adiabatic index of the stability analysis (an ideal gas at rest).
coef_sound : float, optional
    With a weakly compressible code ("dualsphysics", "pysph"): its sound speed over
    sqrt(g H), whose hydrostatic pressure at rest, up to rho c^2 / coef_sound^2, the stability
    assumes; default the code's (20, 10 sqrt(2)).
horizon : float, default 100
    The growth time, in d/c, that separates weak instabilities from unstable ones.
a_p : str or float, default "voronoi"
    The volume coefficient: a name the lattice offers or a number.
gravity : sequence of float, optional
    The direction of gravity; the lattice's by default.
site : int, default 0
    The motif site reported first.
params : dict, optional
    Parameter values of a kernel family.
box : sequence of float, optional
    Particle file: a periodic box from the origin.
array : str, optional
    PySPH file: the particle array, or several ("fluid,solid"; the first is measured).
neighbours_by : str, optional
    Particle file: what the code's density solve counts, "number" or "mass".
bias_correction : bool, default False
    Particle file: the density bias the code subtracts when built so ("gadget4":
    WENDLAND_BIAS_CORRECTION).
threads : int, default 0
    Threads of a particle file's sums, or of a lattice's window's stability scan over k; 0:
    every core. The answer is the same on any number.
steps : int, default 10
    Particle file: steps of a parameter's sweep.
eta_range, hfact_range, nngb_range, hdx_range, coefh_range, particle_radius_range : sequence of float, optional
    Particle file: the code's parameter swept over [A, B] in steps, without value (the
    keyword of code's own parameter).
shells : sequence of float, optional
    Sum over these shell radii only (in d), as the paper does; default every shell inside
    the support.
continue_past_support : bool, default False
    With shells: the kernel's formula evaluated past q = R instead of truncated.
glass : int, default 0
    Lattice: also relax a glass of this many particles (100 to 10^5) at the recommended
    setting until its RMS e0 settles, and measure it there (0: none).

Returns
-------
dict
    On a particle file, the document of `assess FILE --json` (particles, interior, surface,
    condition_22, stability per lattice, verdict), or of its sweep (points, needed). On a
    lattice, the document of `assess --json`: eps (as `eps --json`, with code), pressure (the model at
    rest the stability assumes), condition_22
    (epsilon, holds, margin), stability (per h model: verdict, growth_time and mode where a
    mode grows), window, recommended (found, k, interval, and code), glass (with glass:
    particles, h_over_l, steps, settled, e0 and eps_gradp, the lattice's), verdict (the line).

Examples
--------
>>> a = sphkern.assess("wendland_c2", "fcc", code="swift", value=1.2348)
>>> a["condition_22"]["holds"], a["stability"][1]["verdict"]
(False, 'stable')
)doc";

inline constexpr const char* code_k = R"doc(The k at which an SPH code's own setting holds on a lattice at rest.

As `sphkern eps --code`: SWIFT, Phantom and GADGET solve for h with the SPH density, and so
does this, with the lattice's own density at the site; PySPH and DualSPHysics set h from
the rest spacing.

Parameters
----------
kernel : str
    A kernel's name, or a plugin or expression file; the code must ship it.
lattice : str
    A lattice's name or file.
code : str
    "swift" (eta), "phantom" (hfact), "gadget2" or "gadget4" (the weighted neighbour
    number), "pysph" (hdx), "dualsphysics" (coefh) or "splishsplash" (the particle radius
    in d; its a_p, 0.8 (2 r)^D, is under "a_p").
value : float
    The code's setting.
a_p : str or float, default "voronoi"
    The volume coefficient: a name the lattice offers or a number.
site : int, default 0
    The motif site whose density the code sees.
params : dict, optional
    Parameter values of a kernel family.

Returns
-------
float
    k = h / d, sphkern's smoothing coefficient.

Examples
--------
>>> round(sphkern.code_k("wendland_c2", "fcc", "swift", 1.2348), 4)
1.0606
)doc";

inline constexpr const char* shells = R"doc(The neighbour shells of a lattice site, as `sphkern shells --json`.

Parameters
----------
lattice : str
    A lattice name or a lattice file.
radius : float
    The shells up to this distance, in units of d.
site : int, default 0
    The motif site at the centre.
gravity : sequence of float, optional
    The direction of the gravity moment. Default: the lattice's.

Returns
-------
dict
    lattice, site, radius and shells: one dict per shell with radius, radius_squared,
    count, cumulative and gravity_moment.

Examples
--------
>>> [s["count"] for s in sphkern.shells("fcc", 1.5)["shells"]]
[12, 6]
)doc";

inline constexpr const char* surface =
    R"doc(The errors layer by layer below a free surface, as `sphkern surface --json`.

Parameters
----------
kernel : str
    A kernel name, a plugin or expression file, or a blend "A+B".
lattice : str
    A lattice name or a lattice file.
k : float, optional
    k = h / d, in (0, 100]. Or code and value.
code : str, optional
    A code's own setting instead of k, with value its parameter: "swift" (eta), "phantom"
    (hfact), "gadget2" or "gadget4" (nngb), "pysph" (hdx), "dualsphysics" (coefh),
    "splishsplash" (the particle radius in d, which also fixes a_p = 0.8 (2 r)^D); its k is
    found from the bulk's SPH density at site, and the document carries it under "code".
value : float, optional
    The code's parameter, with code.
form : str, default "sum"
    The gradient form: "sum", "difference" or "monaghan".
layers : int, default 4
    At least this many planes below the surface, until the bulk.
a_p : str or float, default "voronoi"
    The volume coefficient: a model the lattice offers or a positive number.
gravity : sequence of float, optional
    The direction of gravity, normal to a family of lattice planes. Default: the lattice's.
site : int, default 0
    The site on the top plane.
params : dict of str to float, optional
    The kernel's parameters.
termination : int, optional
    Which plane type is on top: an index of the document's terminations (default: the
    site's), as `--termination`.

Returns
-------
dict
    kernel, lattice, k, form, a_p, spacing, termination, terminations, first_moments,
    layers (one dict per plane: depth, n, eps_rho, eps_gradp, neighbours, sites) and bulk.

Examples
--------
>>> s = sphkern.surface("cubic_bspline", "fcc", 1.2)
>>> len(s["layers"]) >= 4, s["form"]
(True, 'sum')

SWIFT's eta, at the k of `sphkern.code_k`:

>>> c = sphkern.surface("wendland_c2", "fcc", code="swift", value=1.2348)
>>> c["k"] == sphkern.code_k("wendland_c2", "fcc", "swift", 1.2348), c["code"]["parameter"]
(True, 'eta')
)doc";

inline constexpr const char* roots = R"doc(The roots in k of eps_rho and eps_gradp, and condition (22) in a window of k.

Always the whole document of `sphkern roots --json` (one dict, whatever the options);
`stability` and `code` add a key each.

Parameters
----------
kernel : str
    A kernel name, a plugin or expression file, or a blend "A+B".
lattice : str
    A lattice name or a lattice file.
kmin, kmax : float, default 0.75 and 1.25
    The window, on the scale of `axis`.
a_p : str or float, default "voronoi"
    The volume coefficient: a model the lattice offers or a positive number.
gravity : sequence of float, optional
    The direction of gravity. Default: the lattice's.
site : int, default 0
    The motif site the roots are reported for.
params : dict of str to float, optional
    The kernel's parameters.
epsilon : float, default 0.01
    The tolerance of condition (22): |eps_rho| <= epsilon and |eps_gradp| <= epsilon.
lateral : bool, default False
    Count the lateral error in condition (22) too.
axis : str, default "k"
    The scale of the window: "k" (h / d), "h_over_l" (h / V^(1/D)) or "nh" (neighbours).
stability : bool, default False
    Add "stability": the stable k of the window, their overlap with condition (22) and
    the recommended k, as `roots --stability`.
gamma : float, default 5/3
    With stability: the adiabatic index.
steps : int, default 100
    With stability: the intervals of the k scan.
horizon : float, default 100
    With stability: the growth time, in d/c, that separates weak instabilities from
    unstable ones.
h_model : str, default "fixed"
    With stability: "fixed" or "adaptive" (h = (h/l) (m / rho)^(1/D) with the grad-h terms).
convention : str, optional
    The old name of code, kept as its alias (the same answer).
code : str, optional
    Add "code": every k of the answer as a code's own setting, with its own SPH density
    ("swift", "phantom", "gadget2", "gadget4", "pysph" or "dualsphysics"), as
    `roots --code`.
shells : sequence of float, optional
    Sum over these shell radii only (in d), as the paper does; default every shell inside
    the support.
continue_past_support : bool, default False
    With shells: the kernel's formula evaluated past q = R instead of truncated.
threads : int, default 0
    With stability: threads of the scan over k; 0: every core. The answer is the same on
    any number.

Returns
-------
dict
    roots (a list of dicts: function "rho" or "gradp", k, eps_rho, eps_gradp, lateral,
    neighbours, support_radius), jumps, acceptance and acceptance_every_direction
    (condition (22) along gravity and for every direction: verdict, intervals, best_k,
    best_max_error, epsilon), sites and all_sites (the same per site and over all sites),
    best_k_at_window_edge (and best_k_note when it is), window, k_range, h_over_l_range, axis,
    a_p, site, lateral_in_verdict, kernel and lattice; "stability" with stability=True,
    "code" with a code (or convention).

Examples
--------
>>> r = sphkern.roots("cubic_bspline", "fcc")
>>> [x["function"] for x in r["roots"]], r["acceptance"]["verdict"]
(['rho', 'rho', 'gradp'], 'pass')
>>> "stability" in sphkern.roots("cubic_bspline", "fcc", stability=True, steps=10)
True
)doc";

inline constexpr const char* stability = R"doc(Linear stability of SPH on a lattice, as `sphkern stability --json`.

k alone: the Brillouin-zone scan; with wavevector, the modes there; with path, the
dispersion curves; kmin and kmax (without k): the verdict against k.

Parameters
----------
kernel : str
    A kernel name, a plugin or expression file, or a blend "A+B".
lattice : str
    A lattice name or a lattice file.
k : float, optional
    k = h / d of the zone scan, the modes at `wavevector` or the curves along `path`.
gamma : float, default 5/3
    The adiabatic index of the equation of state.
wavevector : sequence of float, optional
    A wave vector, one component per dimension, in units of 1/d.
kmin, kmax : float, optional
    The k interval of a scan against k (both, without k).
steps : int, default 50
    The intervals of the scan against k.
grid : int, default 0
    Points per reciprocal axis of the zone grid (0: 8 in 3D, 32 in 2D, doubled until the
    minimum settles).
path : int, default 0
    About this many points along the high-symmetry path (0: no curves).
threads : int, default 0
    Threads (0: every core).
horizon : float, default 100
    The growth time, in d/c, that separates weak instabilities from unstable ones.
params : dict of str to float, optional
    The kernel's parameters.
h_model : str, default "fixed"
    "fixed" or "adaptive" (h = (h/l) (m / rho)^(1/D) with the grad-h terms; k is the
    equilibrium h = k d in both).
code : str, optional
    With kmin and kmax: add "code", the stable intervals in a code's own setting with its
    own SPH density ("swift", "phantom", "gadget2", "gadget4", "pysph" or "dualsphysics"),
    as `stability --code`.

Returns
-------
dict
    For the zone scan: verdict ("stable", "weak" or "unstable"), stable, growth_time (in
    d/c), min_omega2, mode, branches, sound_speed, long_wave, zone_scan and the inputs
    (kernel, lattice, k, gamma, horizon, h_model); the other requests as the command
    line's JSON has them.

Examples
--------
>>> s = sphkern.stability("cubic_bspline", "fcc", 1.2)
>>> s["verdict"] in ("stable", "weak", "unstable"), s["h_model"]
(True, 'fixed')
)doc";

inline constexpr const char* design = R"doc(Every (k, parameter) where both errors vanish, as `sphkern design --json`.

Parameters
----------
kernel : str
    A kernel with a parameter, or a blend "A+B" (parameter alpha).
lattice : str
    A lattice name or a lattice file.
param : str
    The parameter to solve for.
range : sequence of float, optional
    [min, max] of the parameter. Default: blends [-1, 2], else the declared range.
kmin, kmax : float, default 0.75 and 1.25
    The k window.
a_p : str or float, default "voronoi"
    The volume coefficient: a model the lattice offers or a positive number.
gravity : sequence of float, optional
    The direction of gravity. Default: the lattice's.
site : int, default 0
    The motif site.
params : dict of str to float, optional
    The kernel's other parameters.
threads : int, default 0
    Threads of the scan along the parameter; 0: every core. The answer is the same on any
    number.

Returns
-------
dict
    kernel, lattice, parameter, range, k_range, a_p, note and solutions (one dict each:
    k, parameter, eps_rho, eps_gradp, neighbours, jacobian_condition, non_negative,
    ap_plus_1_percent, method).

Examples
--------
>>> d = sphkern.design("cubic_bspline+desbrun_spiky", "triangular", "alpha")
>>> len(d["solutions"]) > 0, d["parameter"]
(True, 'alpha')
)doc";

inline constexpr const char* kernel_class =
    R"doc(A kernel's functions h^D W and h^(D+1) dW/dr, vectorised over q = r / h.

Made by sphkern.kernel(name).
)doc";

inline constexpr const char* kernel_name = "The kernel's name.";
inline constexpr const char* kernel_support = "The support radius R, in units of h.";
inline constexpr const char* kernel_info = "The kernel's entry, as kernels() lists it.";

// The arguments Kernel.w and Kernel.dw share.
inline constexpr const char* q_dim_k = R"doc(
Parameters
----------
q : float or array_like
    q = r / h, each >= 0.
dim : int
    The dimension D (one the kernel supports).
k : float, default 1.0
    k = h / d, for kernels whose formula depends on it.

)doc";

inline const std::string kernel_w = std::string("The kernel h^D W(q) in D dimensions.\n") + q_dim_k + R"doc(Returns
-------
numpy.ndarray
    h^D W, shaped like q.

Examples
--------
>>> sphkern.kernel("cubic_bspline").w([0.0, 1.0, 2.0], 3)
array([0.31830989, 0.07957747, 0.        ])
)doc";

inline const std::string kernel_dw = std::string("The kernel's derivative h^(D+1) dW/dr at q in D dimensions.\n") +
                                     q_dim_k +
                                     R"doc(Returns
-------
numpy.ndarray
    h^(D+1) dW/dr, shaped like q.

Examples
--------
>>> bool(sphkern.kernel("cubic_bspline").dw(1.0, 3) < 0)
True
)doc";

inline constexpr const char* kernel = R"doc(A kernel as an object, its functions vectorised over q.

Parameters
----------
name : str
    A kernel name, a plugin or expression file, or a blend "A+B".
params : dict of str to float, optional
    The kernel's parameters.

Returns
-------
Kernel
    With name, support, info, w(q, dim, k) and dw(q, dim, k).

Examples
--------
>>> kern = sphkern.kernel("wendland_c2")
>>> kern.name, kern.support
('wendland_c2', 2.0)
)doc";

inline constexpr const char* particles =
    R"doc(The consistency errors of a kernel on any particle set, as `sphkern particles --json`.

Positions are copied once; the sums run without the GIL. With masses, eps_rho is
sum_j m_j W_ij / rho0 - 1; without, it equals e0 = sum_j V_j W_ij - 1 (share/docs/method.md,
section 11). Lengths (positions, box, h) are in any one unit; masses, densities and rho0 in
units consistent with it.

Parameters
----------
kernel : str
    A kernel name, a plugin or expression file, or a blend "A+B".
positions : array_like, str, os.PathLike or sequence of str
    The positions, shape (N, 2) or (N, 3); or a particle file, read as `sphkern particles
    FILE` reads it (its h, masses, densities and box as the file has them); or a run's files,
    measured one by one and returned as a list of documents, each with the file's "time", in
    the order of those times (the order given where a file has none).
box : sequence of float, optional
    The sides of a periodic box with a corner at the origin, one per dimension.
    Default: no box (free particles), or a file's own.
h : float or array_like, optional
    The smoothing lengths, one number or one per particle, as stored: the support radius
    is support_per_h times h.
support_per_h : float, optional
    The support radius over the stored h, as the command line's --support-per-h
    (GADGET 1, SWIFT its kernel gamma, DualSPHysics 2, SPlisHSPlasH 4 with its particle
    radii as h). Default: the
    kernel's support R, that is h is sphkern's own.
h_over_l : float, optional
    sphkern's own h over the mean spacing l = V^(1/D), V the mean volume, in (0, 100].
    Default, without h and nh: 1.2. (SWIFT's eta is code="swift" with value.)
nh : float, optional
    h from the neighbour number N_H, in [1, 100000].
code : str, optional
    h as an SPH code sets it, with value its parameter: "swift" (eta), "phantom" (hfact),
    "gadget2" or "gadget4" (nngb) solve every particle's h with its own SPH density,
    h_i = c (m_i / rho_i)^(1/D); "pysph" (hdx) and "dualsphysics" (coefh) take it from the
    mean spacing. Not with h, h_over_l or nh. Without value, with h: that h as the code stores
    it (its support over h, and PySPH's pair h (h_i + h_j) / 2 in the sums), not with
    support_per_h. The document carries it under "code".
value : float, optional
    The code's parameter, with code.
neighbours_by : str, optional
    With code and value: what the code's density solve counts, "number" or "mass" (default
    the code's; SWIFT's use_mass_weighted_num_ngb is "mass").
bias_correction : bool, optional
    With code and value: the bias the code subtracts from each density when built so
    ("gadget4": WENDLAND_BIAS_CORRECTION, its Wendland kernels in 3D, a whole nngb).
masses : float or array_like, optional
    The masses m_j, one number or one per particle: eps_rho is computed with them.
densities : float or array_like, optional
    The densities rho_j, one number or one per particle: with masses they give the
    volumes V_j = m_j / rho_j. Not with volume.
rho0 : float, optional
    The reference density of eps_rho, with masses. Default: the total mass over the total
    volume.
volume : str or array_like, optional
    The volumes V_j: "uniform" (box / N), "voronoi" (both need box) or one number or
    one per particle. Default: m / rho with densities, else "uniform".
gravity : sequence of float, optional
    The direction of the gradient errors, one component per dimension. Default: -y in
    2D, -z in 3D.
depth : float, default 1.0
    The depth of the sum form's eps_gradp_sum, in units of h.
threads : int, default 0
    Threads (0: every core).
params : dict of str to float, optional
    The kernel's parameters.
h_over_l_range, nh_range : sequence of float, optional
    A sweep of h / l or of N_H over [A, B] in steps, one h for every particle at each value.
steps : int, default 10
    Steps of a sweep.
histogram : int, default 0
    Bins of the histograms of e0, eps_rho, eps_gradp and eps_gradp_sum (0: none).
keep_going : bool, default False
    With a run's files: a snapshot that fails on its input is skipped, with a RuntimeWarning
    naming it (without: its error stops the series).
plot : str, optional
    With a run's files: the errors against time drawn into this .svg, .png or .pdf file (gnuplot).

Returns
-------
dict
    The document of `particles --json` (statistics of every measure, rho0, h_over_l, nh,
    mean_neighbours, source, ...) with per-particle numpy arrays in its place: e0, eps_rho,
    eps_gradp, eps_gradp_sum (N), e1 and m1 (N, D), E (N, D, D), neighbours (N, int),
    h (N, sphkern's own h: the support is R h) and volume (N); the volume model the
    document names ("uniform", "file", "voronoi") is under volume_model. A sweep gives
    the document alone, with its points.

Examples
--------
>>> import numpy as np
>>> x = np.random.default_rng(1).uniform(0, 1, (400, 2))
>>> r = sphkern.particles("cubic_bspline", x, box=[1, 1], h_over_l=1.3)
>>> r["eps_rho"].shape, r["E"].shape
((400,), (400, 2, 2))

Masses and densities, and h stored as the support radius (GADGET's convention):

>>> m, rho = np.full(400, 1 / 400), np.ones(400)
>>> s = sphkern.particles("cubic_bspline", x, box=[1, 1], h=2 * r["h"], support_per_h=1.0,
...                       masses=m, densities=rho)
>>> bool(np.array_equal(s["h"], r["h"])), s["rho0"], s["volume_model"]
(True, 1.0, 'file')

SWIFT's eta, each particle's h solved with its own SPH density:

>>> y = np.random.default_rng(2).uniform(0, 1, (2000, 3))
>>> w = sphkern.particles("wendland_c2", y, box=[1, 1, 1], code="swift", value=1.2348)
>>> w["code"]["h_from"], bool(w["h"].min() < w["h"].max())
('sph_density', True)
)doc";

} // namespace sphkern::doc
