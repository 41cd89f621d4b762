"""Type hints of ``repro``: "A Generalized Traction Curve for EHL Contacts" (Jacod, Venner,
Lugt 2001) from Python."""

import os
from typing import Any, Callable, Dict, List, Mapping, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

ArrayLike = Union[float, npt.ArrayLike]

LEVELS: Tuple[int, int]
"""The grid levels a point contact can be solved at (2^(level+1) points per direction)."""

class SolveError(RuntimeError):
    """A solve that did not produce a trustworthy answer."""

    kind: str
    """``"not_converged"``, ``"non_finite"``, ``"film_collapse"`` or ``"invalid_params"``."""
    residual_history: List[float]
    """The residual after each cycle (Newton iteration of a line contact)."""
    def __init__(self, message: str, kind: str, residual_history: List[float]) -> None: ...

class Solution:
    """One contact solved, as ``repro solve`` reports it."""

    json: str
    """The text of ``repro solve --json``."""
    text: str
    """The summary ``repro solve`` prints."""
    warning: Optional[str]
    """The thermal correction's warning (shear heating above 5 %), if any."""
    kind: str
    """``"point"`` (elliptical contact) or ``"line"``."""
    X: np.ndarray
    """X = x/a: 2-D ``[j, i]`` for a point contact, 1-D for a line contact."""
    Y: Optional[np.ndarray]
    """Y = y/b, 2-D ``[j, i]`` (None for a line contact)."""
    P: np.ndarray
    """Dimensionless pressure P = p/p_H on the grid of X (and Y)."""
    H: np.ndarray
    """Dimensionless film H = h/c (point contact; h Rx / a^2 for a line contact)."""
    tau_m: np.ndarray
    """Mean shear stress tau_m / tau0 (dimensionless), Eq. (8)'s integrand (Eq. 4 for Eyring),
    on the grid of P; 0 where P <= 0 (cavitated: the fill of the gap is unknown)."""
    hx: Optional[float]
    """Mesh size in X of the point contact's (innermost) grid."""
    hy: Optional[float]
    """Mesh size in Y."""
    m: float
    """Moes load parameter M."""
    l: float
    """Moes lubricant parameter L."""
    s_bar: float
    """Dimensionless slip S-bar, Eq. (9)."""
    h_central: float
    """Central film H at X = Y = 0: the grid's (``h_central_grid``), or where the level's own
    estimate missed the film bound (2 %, 5 % from M 5 000 up) on a level 6 or finer converged by
    cycles, that film tau-extrapolated (``errors["tau_central"]``), a higher-order value."""
    h_central_grid: float
    """The grid's own central film, ``H`` at X = Y = 0 (the key ``h_central_grid`` of
    ``repro solve --json``): what the fields show and what the friction's loaded film
    (H <= 4 h_central_grid) is measured against."""
    h_min: float
    """Minimum film H."""
    hc_moes: float
    """Central film in Moes units."""
    hmin_moes: float
    """Minimum film in Moes units."""
    mu_bar_sliding: float
    """Reduced sliding (Couette) friction mu-bar = mu p_H / tau0, Eq. (8)."""
    mu_bar_rolling: Optional[float]
    """Reduced rolling (Poiseuille) friction (None when not computed)."""
    mu_bar_total: float
    """Sliding plus rolling."""
    tau_c: float
    """Characteristic shear stress, Eq. (12)."""
    mu_bar_eq13: float
    """The mastercurve, Eq. (13): asinh(tau_c / 5)."""
    residual: float
    """The final residual of the solve."""
    method: str
    """How the solve was made (multigrid cycles, Newton-Krylov finish, ...)."""
    level: Optional[int]
    """The grid level solved on: one above the level asked for where that level's sliding
    friction was estimated more than 1 % off (a point contact whose level converged by its
    cycles)."""
    thermal: Optional[Dict[str, Any]]
    """The shear-heating post-process (None where it cannot be computed)."""
    errors: Optional[Dict[str, Any]]
    """The discretisation error estimate (levels, orders, extrapolated values)."""
    @property
    def mu_bar_thermal(self) -> Optional[float]: ...
    def as_dict(self) -> Dict[str, Any]:
        """The object of ``repro solve --json``."""

def solve(
    *,
    m: Optional[float] = ...,
    l: Optional[float] = ...,
    s_bar: Optional[float] = ...,
    d: Optional[float] = ...,
    lubricant: Optional[str] = ...,
    temperature: Optional[float] = ...,
    alpha: Optional[float] = ...,
    ph: Optional[float] = ...,
    um: Optional[float] = ...,
    tau0: Optional[float] = ...,
    rx: float = ...,
    ry: Optional[float] = ...,
    e_prime: float = ...,
    nu40: Optional[float] = ...,
    iso_vg: Optional[int] = ...,
    nu100: Optional[float] = ...,
    vi: Optional[float] = ...,
    rho15: Optional[float] = ...,
    expansion15: Optional[float] = ...,
    base_oil: Optional[str] = ...,
    slip: Optional[float] = ...,
    eta0: Optional[float] = ...,
    viscosity: Optional[str] = ...,
    density: Optional[str] = ...,
    rheology: Optional[str] = ...,
    lambda_lss: Optional[float] = ...,
    tau_l0: Optional[float] = ...,
    line: bool = ...,
    level: Optional[int] = ...,
    domain: Optional[str] = ...,
    edge: Optional[str] = ...,
    patch: Optional[str] = ...,
    max_cycles: Optional[int] = ...,
    newton_steps: Optional[int] = ...,
    rolling: bool = ...,
    cold: bool = ...,
    k_solid: float = ...,
    k_lubricant: float = ...,
    progress: Optional[Callable[[int, int, float, float], Any]] = ...,
) -> Solution:
    """Solve one contact exactly as ``repro solve`` does (the bits of ``--json``)."""

def predict(
    *,
    um: ArrayLike,
    slip: ArrayLike,
    tau0: ArrayLike,
    ph: Optional[ArrayLike] = ...,
    load: Optional[ArrayLike] = ...,
    temperature: Optional[ArrayLike] = ...,
    refined: bool = ...,
    lubricant: Optional[str] = ...,
    alpha: Optional[float] = ...,
    eta0: Optional[float] = ...,
    nu40: Optional[float] = ...,
    iso_vg: Optional[int] = ...,
    nu100: Optional[float] = ...,
    vi: Optional[float] = ...,
    rho15: Optional[float] = ...,
    expansion15: Optional[float] = ...,
    base_oil: Optional[str] = ...,
    viscosity: Optional[str] = ...,
    rx: float = ...,
    ry: Optional[float] = ...,
    e_prime: float = ...,
) -> Dict[str, np.ndarray]:
    """The mastercurve predictor of ``repro predict`` (Eq. 14) over broadcast arrays."""

def lubricant(
    *,
    temperature: Optional[ArrayLike] = ...,
    lubricant: Optional[str] = ...,
    alpha: Optional[float] = ...,
    eta0: Optional[float] = ...,
    nu40: Optional[float] = ...,
    iso_vg: Optional[int] = ...,
    nu100: Optional[float] = ...,
    vi: Optional[float] = ...,
    rho15: Optional[float] = ...,
    expansion15: Optional[float] = ...,
    base_oil: Optional[str] = ...,
) -> Dict[str, np.ndarray]:
    """A lubricant's eta0 (Pa s) and alpha (1/Pa), with alpha's band when correlated."""

def study(
    path_or_dict: Union[str, "os.PathLike[str]", Mapping[str, Any]],
    *,
    level: Optional[int] = ...,
    cache: Optional[Union[str, "os.PathLike[str]"]] = ...,
    out: Optional[Union[str, "os.PathLike[str]"]] = ...,
    progress: Optional[Callable[[int, int], Any]] = ...,
) -> Any:
    """A sweep through ``repro run``'s pipeline and cache: a DataFrame or a list of dicts."""
