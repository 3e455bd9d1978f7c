"""The types of the module sphkern (built from core/python/; tests/python/test_stub.py holds
this file to the module): every function, the Kernel class and the exceptions."""
from typing import Dict, Optional, Sequence, Union

import os
import numpy
import numpy.typing

__version__: str


class Error(Exception):
    """The base of every error sphkern raises; exit_code is the command line's for the same error."""
    exit_code: int


class BadValue(Error, ValueError):
    """A value out of its range, of the wrong kind, or not fitting the others given."""
    exit_code: int


class UnknownName(BadValue, LookupError):
    """A name that names nothing known: a kernel, lattice, study, code, parameter or a_p."""
    exit_code: int


class FileError(BadValue, FileNotFoundError):
    """An input file that is not there (a lattice, study, particle or plugin file)."""
    exit_code: int


class PluginError(Error, RuntimeError):
    """A plugin that cannot be loaded, validated or run."""
    exit_code: int


class OutputError(Error, OSError):
    """Results that cannot be written, or an output that exists (force replaces it)."""
    exit_code: int


class CheckFailed(Error):
    """A kernel check failed, or warned with strict; the checks' documents are on results."""
    exit_code: int
    results: list


class Kernel:
    """A kernel's functions h^D W and h^(D+1) dW/dr, vectorised over q = r / h."""

    @property
    def name(self) -> str:
        """The kernel's name."""
        ...

    @property
    def support(self) -> float:
        """The support radius R, in units of h."""
        ...

    @property
    def info(self) -> dict:
        """The kernel's entry, as kernels() lists it."""
        ...

    def w(self, q: numpy.typing.ArrayLike, dim: int, k: float=...) -> numpy.typing.NDArray[numpy.float64]:
        """The kernel h^D W(q) in D dimensions."""
        ...

    def dw(self, q: numpy.typing.ArrayLike, dim: int, k: float=...) -> numpy.typing.NDArray[numpy.float64]:
        """The kernel's derivative h^(D+1) dW/dr at q in D dimensions."""
        ...


def assess(kernel: str, lattice: Union[str, os.PathLike], *, k: Optional[float]=..., code: Optional[str]=..., value: Optional[float]=..., kmin: float=..., kmax: float=..., epsilon: float=..., gamma: float=..., coef_sound: Optional[float]=..., horizon: float=..., a_p: Union[str, float]=..., gravity: Optional[Sequence[float]]=..., site: int=..., params: Optional[Dict[str, float]]=..., box: Optional[Sequence[float]]=..., array: Optional[str]=..., neighbours_by: Optional[str]=..., bias_correction: bool=..., threads: int=..., steps: int=..., eta_range: Optional[Sequence[float]]=..., hfact_range: Optional[Sequence[float]]=..., nngb_range: Optional[Sequence[float]]=..., hdx_range: Optional[Sequence[float]]=..., coefh_range: Optional[Sequence[float]]=..., particle_radius_range: Optional[Sequence[float]]=..., shells: Optional[Sequence[float]]=..., continue_past_support: bool=..., glass: int=...) -> dict:
    """One verdict on a setting, k or an SPH code's own, on a lattice."""
    ...


def block(kernel: str, lattice: str, k: float, size: Sequence[int], *, periodic: bool=..., form: str=..., threads: int=..., a_p: Union[str, float]=..., vtk: Optional[str]=..., csv: Optional[str]=..., params: Optional[Dict[str, float]]=...) -> dict:
    """Direct SPH sums over a finite block of lattice cells, as `sphkern block --json`."""
    ...


def check(kernel: Union[str, Sequence[str], None]=..., *, all: bool=..., strict: bool=..., timeout: float=..., plugin: Union[str, Sequence[str], None]=..., params: Optional[Dict[str, float]]=...) -> list:
    """The kernel author's check-up, as `sphkern check --json`."""
    ...


def code_k(kernel: str, lattice: str, code: str, value: float, *, a_p: Union[str, float]=..., site: int=..., params: Optional[Dict[str, float]]=...) -> float:
    """The k at which an SPH code's own setting holds on a lattice at rest."""
    ...


def design(kernel: str, lattice: str, param: str, *, range: Optional[Sequence[float]]=..., kmin: float=..., kmax: float=..., a_p: Union[str, float]=..., gravity: Optional[Sequence[float]]=..., site: int=..., params: Optional[Dict[str, float]]=..., threads: int=...) -> dict:
    """Every (k, parameter) where both errors vanish, as `sphkern design --json`."""
    ...


def eps(kernel: str, lattice: str, k: numpy.typing.ArrayLike, *, a_p: Union[str, float]=..., gravity: Optional[Sequence[float]]=..., site: int=..., params: Optional[Dict[str, float]]=..., axis: str=..., shells: Optional[Sequence[float]]=..., continue_past_support: bool=...) -> dict:
    """The hydrostatic errors of a kernel on a lattice at one or many k."""
    ...


def kernel(name: str, params: Optional[Dict[str, float]]=...) -> Kernel:
    """A kernel as an object, its functions vectorised over q."""
    ...


def kernels() -> list:
    """Every kernel found, as `sphkern kernels --json` lists them."""
    ...


def lattices() -> list:
    """The shipped lattices, as `sphkern lattices --json` lists them."""
    ...


def load_lattice(path: str) -> dict:
    """Read and validate a lattice file."""
    ...


def load_plugin(path: str) -> dict:
    """Load a kernel plugin library or an expression kernel file."""
    ...


def pairing(kernel: str, lattice: str, k: Optional[float]=..., *, code: Optional[str]=..., value: Optional[float]=..., kmin: Optional[float]=..., kmax: Optional[float]=..., samples: int=..., noise: float=..., duration: float=..., damping: float=..., dt: float=..., gamma: float=..., horizon: float=..., seed: int=..., threads: int=..., params: Optional[Dict[str, float]]=...) -> dict:
    """Linear stability against the motion of a disturbed lattice, k by k, as `sphkern pairing --json`."""
    ...


def particles(kernel: str, positions: Union[numpy.typing.ArrayLike, str, os.PathLike, Sequence[str]], *, box: Optional[Sequence[float]]=..., h: Optional[numpy.typing.ArrayLike]=..., support_per_h: Optional[float]=..., h_over_l: Optional[float]=..., nh: Optional[float]=..., code: Optional[str]=..., value: Optional[float]=..., neighbours_by: Optional[str]=..., bias_correction: bool=..., masses: Optional[numpy.typing.ArrayLike]=..., densities: Optional[numpy.typing.ArrayLike]=..., rho0: Optional[float]=..., volume: Union[str, numpy.typing.ArrayLike, None]=..., gravity: Optional[Sequence[float]]=..., depth: float=..., threads: int=..., params: Optional[Dict[str, float]]=..., h_over_l_range: Optional[Sequence[float]]=..., nh_range: Optional[Sequence[float]]=..., steps: int=..., histogram: int=..., keep_going: bool=..., plot: Optional[str]=...) -> Union[dict, list]:
    """The consistency errors of a kernel on any particle set, as `sphkern particles --json`."""
    ...


def relax(kernel: str, source: str, *, size: Optional[Sequence[int]]=..., cell: Optional[str]=..., sigma: float=..., seed: int=..., count: Optional[int]=..., dim: Optional[int]=..., box: Optional[Sequence[float]]=..., particle_radius: Optional[float]=..., array: Optional[str]=..., h_over_l: Optional[float]=..., nh: Optional[float]=..., k: Optional[float]=..., code: Optional[str]=..., value: Optional[float]=..., method: str=..., steps: int=..., tolerance: float=..., gamma: float=..., dt: float=..., damping: float=..., alpha: float=..., max_move: float=..., threads: int=..., rdf_max: float=..., rdf_bins: int=..., memory_limit: float=..., output: Optional[str]=..., rho0: Optional[float]=..., u: Optional[float]=..., tile: Optional[Sequence[int]]=..., history: Optional[str]=..., params: Optional[Dict[str, float]]=...) -> dict:
    """Relax a particle set into a glass and judge it, as `sphkern relax --json`."""
    ...


def roots(kernel: str, lattice: str, *, kmin: float=..., kmax: float=..., a_p: Union[str, float]=..., gravity: Optional[Sequence[float]]=..., site: int=..., params: Optional[Dict[str, float]]=..., epsilon: float=..., lateral: bool=..., axis: str=..., stability: bool=..., gamma: float=..., steps: int=..., horizon: float=..., h_model: str=..., convention: Optional[str]=..., code: Optional[str]=..., shells: Optional[Sequence[float]]=..., continue_past_support: bool=..., threads: int=...) -> dict:
    """The roots in k of eps_rho and eps_gradp, and condition (22) in a window of k."""
    ...


def run(study: Optional[str]=..., output: Optional[str]=..., *, no_plots: bool=..., format: str=..., force: bool=..., reproduce: Optional[str]=...) -> dict:
    """Run a study into a results folder, as `sphkern run`."""
    ...


def settings(command: str) -> list:
    """The settings a command takes, as its table declares them once for the command line, Python and studies."""
    ...


def shells(lattice: str, radius: float, site: int=..., gravity: Optional[Sequence[float]]=...) -> dict:
    """The neighbour shells of a lattice site, as `sphkern shells --json`."""
    ...


def spectrum(kernel: str, dim: int, *, k: float=..., max: float=..., points: int=..., params: Optional[Dict[str, float]]=...) -> dict:
    """The Fourier transform of a kernel against kappa h, as `sphkern spectrum --json`."""
    ...


def stability(kernel: str, lattice: str, k: Optional[float]=..., *, gamma: float=..., wavevector: Optional[List[float]]=..., kmin: Optional[float]=..., kmax: Optional[float]=..., steps: int=..., grid: int=..., path: int=..., threads: int=..., horizon: float=..., params: Optional[Dict[str, float]]=..., h_model: str=..., code: Optional[str]=...) -> dict:
    """Linear stability of SPH on a lattice, as `sphkern stability --json`."""
    ...


def read_particles(path: str, *, array: Optional[str]=..., box: Optional[Sequence[float]]=..., dim: Optional[int]=..., particle_radius: Optional[float]=...) -> dict:
    """A particle file's arrays and header as sphkern reads them."""
    ...


def studies() -> list:
    """The shipped studies, as `sphkern studies --json` lists them."""
    ...


def surface(kernel: str, lattice: str, k: Optional[float]=..., *, code: Optional[str]=..., value: Optional[float]=..., form: str=..., layers: int=..., a_p: Union[str, float]=..., gravity: Optional[Sequence[float]]=..., site: int=..., params: Optional[Dict[str, float]]=..., termination: Optional[int]=...) -> dict:
    """The errors layer by layer below a free surface, as `sphkern surface --json`."""
    ...

