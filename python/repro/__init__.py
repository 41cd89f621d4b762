"""repro: "A Generalized Traction Curve for EHL Contacts" (Jacod, Venner, Lugt 2001) from Python.

The elastohydrodynamic (EHL) solver of the ``repro`` crate, its friction and the paper's
mastercurve, called from Python with the bits of the command line:

- :func:`solve` -- one elliptical (point) or line contact, as ``repro solve``: film thickness,
  reduced friction mu-bar, the characteristic shear stress tau_c (Eq. 12), the mastercurve
  Eq. (13), the thermal correction, discretisation error estimates, and the pressure, film
  and mean shear stress fields as numpy arrays.
- :func:`predict` -- the mastercurve predictor of ``repro predict`` (Eq. 14,
  mu-bar = asinh(tau_c / 5)) over numpy arrays, microseconds per contact.
- :func:`lubricant` -- a lubricant's eta0 and alpha (Table 1, given, or a datasheet).
- :func:`study` -- a sweep through the pipeline and cache of ``repro run``.
"""

from __future__ import annotations

import csv as _csv
import json as _json
import os as _os
import tempfile as _tempfile
import typing as _typing
from collections.abc import Mapping as _Mapping

import numpy as _np

if _typing.TYPE_CHECKING:  # names of the annotations, which are strings at run time
    import os
    from typing import Any, Callable, Dict, List, Mapping, Optional, Union

    import numpy as np

# The module's namespace is its API (``dir(repro)``): the future import's binding goes too.
del annotations

__all__ = ["solve", "predict", "lubricant", "study", "Solution", "SolveError", "LEVELS"]


class SolveError(RuntimeError):
    """A solve that did not produce a trustworthy answer.

    ``kind`` says how it failed (``"not_converged"``, ``"non_finite"``, ``"film_collapse"``,
    ``"invalid_params"``) and ``residual_history`` holds the residual after each cycle (or
    Newton iteration of a line contact).
    """

    def __init__(self, message: str, kind: str, residual_history: List[float]):
        super().__init__(message)
        self.kind = kind
        self.residual_history = list(residual_history)


from . import _repro  # noqa: E402  (SolveError must exist before the module raises it)

LEVELS = _repro.LEVELS


class Solution:
    """One contact solved, as ``repro solve`` reports it.

    ``json`` is the text of ``repro solve --json`` and :meth:`as_dict` its object; the
    attributes are its main keys. For a point contact ``X``, ``Y``, ``P``, ``H`` are 2-D
    arrays indexed ``[j, i]`` (Y rows, X columns) of the dimensionless coordinates
    ``X = x/a``, ``Y = y/b``, pressure ``P = p/p_H`` and film ``H = h/c`` (ready for
    ``matplotlib.pyplot.contourf(s.X, s.Y, s.P)``); for a line contact ``X``, ``P``, ``H``
    are 1-D and ``Y`` is None. ``tau_m`` is the mean shear stress tau_m / tau0 on the same
    grid, the integrand of Eq. (8) (Eq. 4 for Eyring at the Couette argument
    N S eta_bar(P) / H): its sum over the pressurised interior nodes of the loaded film
    (H <= 4 h_central_grid) times ``hx * hy / (2 pi / 3)`` is ``mu_bar_sliding`` (a line
    contact's: over the interior nodes with P > 0, divided by their sum of P). It is 0 where
    P <= 0, as Eq. (8) counts it: the cavitation condition does not say how much of the
    ruptured gap there is lubricant.
    """

    def __init__(self, raw: Dict[str, Any]):
        self.json: str = raw["json"]
        self.text: str = raw["text"]
        self.warning: Optional[str] = raw["warning"]
        self.kind: str = raw["kind"]
        self.X: np.ndarray = raw["X"]
        self.Y: Optional[np.ndarray] = raw.get("Y")
        self.P: np.ndarray = raw["P"]
        self.H: np.ndarray = raw["H"]
        self.tau_m: np.ndarray = raw["tau_m"]
        self.hx: Optional[float] = raw.get("hx")
        self.hy: Optional[float] = raw.get("hy")
        # Wall time of the library's solve and report inside the call (the rest is the
        # binding's: arguments, arrays, JSON parsing).
        self._library_seconds: float = raw["library_seconds"]
        d = _json.loads(self.json)
        self._dict = d
        self.m: float = d["m"]
        self.l: float = d["l"]
        self.s_bar: float = d["s_bar"]
        self.h_central: float = d["h_central"]
        self.h_min: float = d["h_min"]
        self.hc_moes: float = d["hc_moes"]
        self.hmin_moes: float = d["hmin_moes"]
        self.mu_bar_sliding: float = d["mu_bar_sliding"]
        self.mu_bar_rolling: Optional[float] = d["mu_bar_rolling"]
        self.mu_bar_total: float = d["mu_bar_total"]
        self.tau_c: float = d["tau_c"]
        self.mu_bar_eq13: float = d["mu_bar_eq13"]
        self.residual: float = d["residual"]
        self.method: str = d.get("method", "")
        self.level: Optional[int] = d.get("level")
        self.thermal: Optional[Dict[str, Any]] = d.get("thermal")
        self.errors: Optional[Dict[str, Any]] = d.get("discretisation_error")
        # The grid's own central film, H at X = Y = 0: `h_central` is it tau-extrapolated
        # where the solve extrapolated it.
        self.h_central_grid: float = d["h_central_grid"]

    def as_dict(self) -> Dict[str, Any]:
        """The object of ``repro solve --json`` (a fresh copy)."""
        return _json.loads(self.json)

    @property
    def mu_bar_thermal(self) -> Optional[float]:
        """The sliding friction with the shear-heating correction, where it was computed."""
        t = self.thermal
        return t.get("mu_bar_sliding") if isinstance(t, dict) else None

    def __repr__(self) -> str:
        return (
            f"Solution({self.kind}, M={self.m:.4g}, L={self.l:.4g}, "
            f"mu_bar_sliding={self.mu_bar_sliding:.6g}, h_central={self.h_central:.6g})"
        )

    def __str__(self) -> str:
        return self.text


def solve(
    *,
    progress: Optional[Callable[[int, int, float, float], Any]] = None,
    **inputs: Any,
) -> Solution:
    """Solve one contact exactly as ``repro solve`` does (same keywords as its flags, with
    ``_`` for ``-``: ``m``, ``l``, ``s_bar``, ``d`` in Moes groups, or ``lubricant``,
    ``temperature``, ``ph``, ``um``, ``slip``, ``tau0`` physically, or a datasheet ``nu40`` /
    ``iso_vg``, ``nu100`` / ``vi``, ``rho15``, ``base_oil``; ``level`` (``exact_level=True``
    for that level alone, no finer one for the accuracy target), ``line=True`` for a
    line contact, ``cold=True``, physics ``viscosity``, ``density``, ``rheology``,
    ``patch="inlet"``, ``"lobes"`` or ``"inlet-and-lobes"`` for the composite grid's
    patches).

    The case goes through the one case -> parameters rule and is solved from its base, so the
    result has the bits of ``repro solve --json``. The GIL is released during the solve;
    ``progress(level, step, residual, h_central)`` hears of every solver step.

    Raises ValueError naming the keyword for bad input, :class:`SolveError` when the solve
    fails.
    """
    return Solution(_repro._solve(progress=progress, **inputs))


def _array(v: Any) -> np.ndarray:
    return _np.ascontiguousarray(_np.atleast_1d(_np.asarray(v, dtype=_np.float64)))


def predict(
    *,
    um: Any,
    slip: Any,
    tau0: Any,
    ph: Any = None,
    load: Any = None,
    temperature: Any = None,
    refined: bool = False,
    **lubricant: Any,
) -> Dict[str, np.ndarray]:
    """The friction of a contact from the mastercurve, as ``repro predict``: Sec. IV's
    transform gives tau_c (Eq. 12), Eq. (14) gives ``mu_bar = asinh(tau_c / 5)`` and Eq. (8)
    ``mu = mu_bar tau0 / p_H``; also the refined formula (beyond the paper).

    ``ph`` (Pa) or ``load`` (N), ``um`` (m/s), ``slip``, ``tau0`` (Pa) and ``temperature`` (C)
    may be numpy arrays (broadcast together). The lubricant keywords are those of
    :func:`lubricant`; also ``viscosity``, ``rx``, ``ry``, ``e_prime``. Returns a dict of
    arrays: tau_c, m, l, s_bar, ph_pa, hc_m (the Eq. 10 film, m), eta_bar_ph, mu_bar, mu, and
    mu_bar_low, mu_bar_high (Eq. 14 over a correlated alpha's band, else NaN); with
    ``refined=True`` also mu_bar_refined, mu_refined (the refined formula, beyond the paper:
    its flat-film integral costs tens of microseconds a contact, Eq. 14 about one).
    """
    named = {"um": um, "slip": slip, "tau0": tau0, "ph": ph, "load": load,
             "temperature": temperature}
    given = {k: _array(v) for k, v in named.items() if v is not None}
    shape = _np.broadcast_shapes(*(a.shape for a in given.values()))
    n = int(_np.prod(shape))
    flat = {k: (a.ravel() if a.size == 1 else _np.ascontiguousarray(_np.broadcast_to(a, shape).ravel()))
            for k, a in given.items()}
    out = _repro._predict(
        n=n, ph=flat.get("ph"), load=flat.get("load"), um=flat["um"], slip=flat["slip"],
        tau0=flat["tau0"], temperature=flat.get("temperature"), refined=refined, **lubricant)
    return {k: v.reshape(shape) for k, v in out.items()}


def lubricant(*, temperature: Any = None, **spec: Any) -> Dict[str, np.ndarray]:
    """A lubricant's ambient viscosity eta0 (Pa s) and pressure-viscosity coefficient alpha
    (1/Pa) at ``temperature`` (C, scalar or array): a lubricant of Table 1 (``lubricant=``
    "traction-fluid", "mineral-oil-a", "5p4e"), given (``alpha``, ``eta0``), or a datasheet
    (``nu40`` or ``iso_vg``, ``nu100`` or ``vi``, ``rho15``, ``expansion15``, ``base_oil`` in
    "mineral", "pao", "pag"): eta0 = nu rho by ASTM D341 and D1250, alpha by AGMA 925 with
    its band (``alpha_low_per_pa``, ``alpha_high_per_pa``; NaN when alpha is not correlated).
    """
    t = None if temperature is None else _array(temperature)
    out = _repro._lubricant(temperature=None if t is None else t.ravel(), **spec)
    shape = () if t is None or _np.ndim(temperature) == 0 else t.shape
    return {k: v.reshape(shape) for k, v in out.items()}


def study(
    path_or_dict: Union[str, os.PathLike, Mapping[str, Any]],
    *,
    level: Optional[int] = None,
    cache: Optional[Union[str, os.PathLike]] = ".repro-cache",
    out: Optional[Union[str, os.PathLike]] = None,
    progress: Optional[Callable[[int, int], Any]] = None,
) -> Any:
    """Run a sweep (a file in the format of cases/*.toml, or the same as a dict) through the
    pipeline and cache of ``repro run``, in parallel: the rows of its CSV (one per case:
    inputs, M, L, S-bar, alpha-bar, tau_c, film, friction, deviation from Eq. 13) as a pandas
    DataFrame when pandas is installed, else a list of dicts of strings as the CSV has them.

    ``cache=None`` solves every case afresh. ``out`` keeps the CSV and SVG (default: a
    temporary folder). ``progress(done, total)`` hears of each case once it is in the cache
    (from the thread that solved it, holding the GIL). Ctrl-C, or an exception from
    ``progress``, stops the study: the cases in flight finish into the cache, no new one
    starts, and KeyboardInterrupt (or the callback's exception) is raised; the next call
    takes the solved cases from the cache.
    """
    if isinstance(path_or_dict, _Mapping):
        # The sweep's format is TOML: a dict goes through JSON to the same parser as a file.
        text = _repro._toml_of_json(_json.dumps(dict(path_or_dict)))
        file, stem = "<dict>", "study"
    else:
        file = _os.fspath(path_or_dict)
        with open(file, encoding="utf-8") as f:
            text = f.read()
        stem = _os.path.splitext(_os.path.basename(file))[0] or "study"
    keep = out is not None
    folder = _os.fspath(out) if keep else _tempfile.mkdtemp(prefix="repro-study-")
    path, _, _ = _repro._study(text=text, file=file, stem=stem, out=folder, level=level,
                               cache=None if cache is None else _os.fspath(cache),
                               progress=progress)
    with open(path, newline="", encoding="utf-8") as f:
        text_csv = f.read()
    if not keep:
        import shutil
        shutil.rmtree(folder, ignore_errors=True)
    try:
        import pandas as pd
    except ImportError:
        return list(_csv.DictReader(text_csv.splitlines()))
    import io
    return pd.read_csv(io.StringIO(text_csv))

