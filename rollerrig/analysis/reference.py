"""Any creep-force method against CONTACT's exact theory: scores and error maps.

Two sets of reference numbers ship in rollerrig/data/reference (copies of
tests/data; each CSV's first line names its source):

- contact_test_table_mx11.csv: the 3220 cases of CONTACT's test_table
  (Vollebregt's statistical evaluation of contact methods): 5 ellipticities
  a/b x 4 spin levels x 7 creepage directions x 23 creepage magnitudes,
  exact steady rolling on an 11 x 11 grid (itself a few % off the continuum).
- creep_curves_exact_vs_fastsim.csv: CONTACT's creep-curve example
  (Polach's Eurosprinter wheel) in four series: exact theory with Coulomb
  friction, exact theory with falling friction and an interfacial layer,
  CONTACT's FASTSIM, and CONTACT's modified FASTSIM.

    import rollerrig.analysis.reference as ref
    r = ref.score("fastsim", nx=30, ny=30)     # r.error: |dF|/(mu N) per case
    r.overall["median"], r.by_spin[0.5]["p95"]
    print(ref.table([r, ref.score("fastsim_blended")]))
    import rollerrig.plot as rp
    rp.error_map(r)                            # one panel per spin level
    ref.score_curves("fastsim", nx=48, ny=44)[3].rms

Errors are the vector |(dFx, dFy)| / (mu N) and |dMz| / (mu N cp), cp the
table's length scale per a/b; forces on the wheel, CONTACT's convention and
ours alike.  The method's options are those of rollerrig.creep_forces, which
checks them (RollerRigError).
"""
from __future__ import annotations

from typing import Any, Dict, List, Mapping, Sequence, Tuple, Union

import csv
import functools
import inspect
import math
import os
import re
from typing import NamedTuple, Optional

import numpy as np
import numpy.typing as npt

from .._errors import RollerRigError
from .._typing import F64Array, FloatResult
from ..contact.creep import METHODS, FallingFriction, creep_forces

__all__ = ["ExactCases", "ScoreResult", "CreepCurve", "CurveScore", "exact_cases",
           "random_cases", "own_exact_cases", "score", "table", "creep_curves", "score_curves",
           "DATA_DIR", "TABLE_FILE", "CURVES_FILE"]

#: the folder of the shipped reference data (rollerrig/data/reference)
DATA_DIR = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "data",
                        "reference")
#: CONTACT's test table of 3220 exact cases (exact_cases), in DATA_DIR
TABLE_FILE = "contact_test_table_mx11.csv"
#: CONTACT's creep-curve example (creep_curves), in DATA_DIR
CURVES_FILE = "creep_curves_exact_vs_fastsim.csv"

MM = 1e-3          # m per mm
N_PER_MM2 = 1e6    # Pa per N/mm^2


def read_csv(name: str, folder: str = DATA_DIR) -> Tuple[str, List[Dict[str, str]]]:
    """Read a reference CSV: (the # source line without '#', list of row dicts).

    Raises
    ------
    RollerRigError
        If the first line is not a # source comment.
    """
    path = os.path.join(folder, name)
    with open(path, newline="") as f:
        comment = f.readline()
        if not comment.startswith("#"):
            raise RollerRigError(f"{path}: the first line should be a # source comment")
        rows = list(csv.DictReader(f))
    return comment[1:].strip(), rows


def _header_match(comment: str, pattern: str, what: str, name: str) -> re.Match[str]:
    m = re.search(pattern, comment)
    if m is None:
        raise RollerRigError(f"{name}: cannot read {what} from the header line")
    return m


def _header_number(comment: str, pattern: str, what: str, name: str) -> str:
    """The text of `pattern`'s one group in the header line."""
    return _header_match(comment, pattern, what, name).group(1)


def _header_numbers(comment: str, pattern: str, what: str, name: str) -> Tuple[str, ...]:
    """The texts of `pattern`'s groups (several) in the header line."""
    return _header_match(comment, pattern, what, name).groups()


def _frozen(arr: npt.ArrayLike) -> F64Array:
    arr = np.asarray(arr, dtype=float)
    arr.setflags(write=False)
    return arr


# --------------------------------------------------------------------------
# the 3220 cases of CONTACT's test_table
# --------------------------------------------------------------------------

class ExactCases(NamedTuple):
    """Exact reference cases in SI, one array element per case.

    CONTACT's test table (:func:`exact_cases`, 3220; N, mu, G, nu one number
    each) or the library's own (:func:`own_exact_cases`; N and mu per case).
    """

    cx: np.ndarray          #: longitudinal creepage [-]
    cy: np.ndarray          #: lateral creepage [-]
    cphi: np.ndarray        #: spin [rad/m]
    a: np.ndarray           #: semi-axis along the rolling direction [m]
    b: np.ndarray           #: lateral semi-axis [m]
    cp: np.ndarray          #: the table's length scale of the case's a/b [m]
    Fx: np.ndarray          #: exact FX / (mu N), on the wheel
    Fy: np.ndarray          #: exact FY / (mu N)
    Mz: np.ndarray          #: exact MZ / (mu N cp)
    pct_slip: np.ndarray    #: exact share of the area in slip [%]
    a_over_b: np.ndarray    #: ellipticity (0.2, 0.5, 1, 2, 5)
    spin: np.ndarray        #: normalised spin level (0, 0.5, 1, 2)
    angle: np.ndarray       #: creepage direction atan2(cy, cx) [rad] (-pi/2 .. pi/2)
    magnitude: np.ndarray   #: normalised creepage magnitude (0 .. 12)
    N: FloatResult          #: normal load [N] (an array in own_exact_cases)
    mu: FloatResult         #: friction coefficient (an array in own_exact_cases)
    G: float                #: shear modulus [Pa]
    nu: float               #: Poisson's ratio
    source: str             #: the CSV's source line
    label: str = "exact reference cases"   #: what they are, short: the score tables' caption


def _table_header_params(comment: str) -> Dict[float, Tuple[float, float]]:
    """{a/b: (rho [mm], cp [mm])} from the header line of the test table."""
    found = re.findall(r"a/b=\s*([0-9.]+):\s*rho=\s*([0-9.]+)\s*,\s*cp=\s*([0-9.]+)", comment)
    params = {float(aob): (float(rho), float(cp)) for aob, rho, cp in found}
    if len(params) != 5:
        raise RollerRigError(f"{TABLE_FILE}: cannot read rho, cp per a/b from the header "
                             f"line (found {found})")
    return params


@functools.lru_cache(maxsize=None)
def exact_cases() -> ExactCases:
    """The 3220 exact cases of CONTACT's test table, in SI.

    Returns
    -------
    ExactCases
        Decoded as the CSV's header line says (cached; the arrays are
        read-only).

    See Also
    --------
    score : a method's errors on these cases.

    Notes
    -----
    cx = m mu cos(ang) cp/rho, cy = m mu sin(ang) cp/rho, cphi = mu s / rho,
    with m the magnitude, ang the direction, s the spin level and rho, cp
    (mm) per a/b from the header; a = aa, b = aa / (a/b); G = 82000 N/mm^2,
    N = 82000 N, mu = 0.3, nu = 0.28 (test_table.f90's settings).

    Examples
    --------
    >>> import rollerrig as rr
    >>> cases = rr.reference.exact_cases()
    >>> cases.cx.shape, cases.N, cases.mu
    ((3220,), 82000.0, 0.3)
    """
    comment, rows = read_csv(TABLE_FILE)
    name = TABLE_FILE
    G = float(_header_number(comment, r"\bG=\s*([0-9.]+)", "G", name)) * N_PER_MM2
    nu = float(_header_number(comment, r"\bnu=\s*([0-9.]+)", "nu", name))
    mu = float(_header_number(comment, r"\bmu=\s*([0-9.]+)", "mu", name))
    N = float(_header_number(comment, r"\bFN=\S*?([0-9.]+) N", "FN", name))
    params = _table_header_params(comment)
    col = {k: np.array([float(r[k]) for r in rows])
           for k in ("a_over_b", "aa_mm", "spin_norm", "creep_angle_rad", "creep_mgn",
                     "Fx", "Fy", "Mz", "pct_slip")}
    aob = col["a_over_b"]
    rho = np.array([params[v][0] for v in aob])       # mm
    cp = np.array([params[v][1] for v in aob])        # mm
    mgn, ang = col["creep_mgn"], col["creep_angle_rad"]
    return ExactCases(
        cx=_frozen(mgn * mu * np.cos(ang) * cp / rho),
        cy=_frozen(mgn * mu * np.sin(ang) * cp / rho),
        cphi=_frozen(mu * col["spin_norm"] / rho / MM),      # rad/mm -> rad/m
        a=_frozen(col["aa_mm"] * MM), b=_frozen(col["aa_mm"] / aob * MM), cp=_frozen(cp * MM),
        Fx=_frozen(col["Fx"]), Fy=_frozen(col["Fy"]), Mz=_frozen(col["Mz"]),
        pct_slip=_frozen(col["pct_slip"]), a_over_b=_frozen(aob),
        spin=_frozen(col["spin_norm"]), angle=_frozen(ang), magnitude=_frozen(mgn),
        N=N, mu=mu, G=G, nu=nu, source=comment,
        label=f"CONTACT's exact theory (11 x 11 grid, {len(aob)} cases)")


# --------------------------------------------------------------------------
# the library's own exact theory as the reference
# --------------------------------------------------------------------------

#: the split classes of own_exact_cases: a/b bins (their labels) and |psi| bins
_AOB_EDGES = (0.1, 0.3, 0.7, 1.4, 3.3, 10.01)
_AOB_LABELS = (0.2, 0.5, 1.0, 2.0, 5.0)


def random_cases(n: int = 3000, seed: int = 20261202) -> Dict[str, FloatResult]:
    """Seeded random Hertzian cases, drawn as CONTACT's 300 of
    tests/data/contact_exact_cases.csv were (wider a/b).

    Parameters
    ----------
    n : int, optional
        The number of cases.
    seed : int, optional
        The seed of numpy.random.default_rng.

    Returns
    -------
    dict
        Arrays of n: a_over_b [-], a, b, c [m], N [N], mu [-], cx, cy [-],
        cphi [rad/m], psi [-], m [-]; and G [Pa], nu [-] (numbers).

    Notes
    -----
    From numpy.random.default_rng(seed), in this order, each of size n:
    a/b log-uniform in [0.1, 10]; c = sqrt(ab) uniform 3-9 mm; N uniform
    5-120 kN; mu uniform 0.1-0.5; m uniform in [0, 3]; theta uniform in
    [0, 2 pi); psi uniform in [-1, 1], set to 0 for the last third of a
    random permutation.  G = 82 GPa, nu = 0.28; a = c sqrt(a/b), b = c /
    sqrt(a/b); (cx, cy) = m xi_ch (cos theta, sin theta) with xi_ch = mu N /
    (G c^2 C11), cphi = psi mu N / (G c^3 C23) (Kalker's coefficients).
    """
    rng = np.random.default_rng(seed)
    aob = np.exp(rng.uniform(np.log(0.1), np.log(10.0), n))
    c = rng.uniform(3e-3, 9e-3, n)
    N = rng.uniform(5e3, 120e3, n)
    mu = rng.uniform(0.1, 0.5, n)
    m = rng.uniform(0.0, 3.0, n)
    theta = rng.uniform(0.0, 2 * np.pi, n)
    psi = rng.uniform(-1.0, 1.0, n)
    psi[rng.permutation(n) >= (2 * n) // 3] = 0.0
    G, nu = 8.2e10, 0.28
    from ..contact.creep import kalker_coefficients
    k = kalker_coefficients(aob, nu)
    xi_ch = mu * N / (G * c * c * k.c11)
    return dict(a_over_b=aob, a=c * np.sqrt(aob), b=c / np.sqrt(aob), c=c, N=N, mu=mu, G=G,
                nu=nu, cx=m * xi_ch * np.cos(theta), cy=m * xi_ch * np.sin(theta),
                cphi=psi * mu * N / (G * c ** 3 * k.c23), psi=psi, m=m)


def own_exact_cases(n: int = 3000, seed: int = 20261202, nx: int = 27) -> ExactCases:
    """random_cases(n, seed) with the library's own exact theory as the reference.

    The reference is method "exact" extrapolated to the continuum from nx
    and 2 nx elements across (:func:`rollerrig.exact_richardson`).

    Parameters
    ----------
    n, seed
        As for :func:`random_cases`.
    nx : int, optional
        The coarse grid of the extrapolation.

    Returns
    -------
    ExactCases
        For score(..., cases=): forces over mu N, Mz over mu N c (cp = c =
        sqrt(ab)); a_over_b and spin are the split classes (a/b bins
        labelled 0.2 ... 5; ``|psi|`` 0, up to 0.5, up to 1 as 0, 0.5, 1).

    Notes
    -----
    About 20 ms a case at nx = 27.

    Examples
    --------
    >>> import rollerrig as rr
    >>> cases = rr.reference.own_exact_cases(n=6, nx=7)
    >>> r = rr.reference.score("fastsim", cases=cases, nx=10, ny=10)
    >>> r.overall["n"]
    6
    """
    from ..contact.exact import exact_richardson
    d = random_cases(n, seed)
    est, _ = exact_richardson(d["cx"], d["cy"], d["cphi"], a=d["a"], b=d["b"], N=d["N"],
                              mu=d["mu"], G=d["G"], nu=d["nu"], nx=nx)
    muN = d["mu"] * d["N"]
    edges, labels = np.array(_AOB_EDGES), np.array(_AOB_LABELS)
    aob_class = labels[np.clip(np.searchsorted(edges, d["a_over_b"]) - 1, 0, len(labels) - 1)]
    apsi = np.abs(d["psi"])
    spin_class = np.where(apsi == 0, 0.0, np.where(apsi <= 0.5, 0.5, 1.0))
    return ExactCases(
        cx=_frozen(d["cx"]), cy=_frozen(d["cy"]), cphi=_frozen(d["cphi"]), a=_frozen(d["a"]),
        b=_frozen(d["b"]), cp=_frozen(d["c"]), Fx=_frozen(est.fx / muN),
        Fy=_frozen(est.fy / muN), Mz=_frozen(est.mz / (muN * d["c"])),
        pct_slip=_frozen(np.full(n, np.nan)), a_over_b=_frozen(aob_class),
        spin=_frozen(spin_class), angle=_frozen(np.arctan2(d["cy"], d["cx"])),
        magnitude=_frozen(d["m"]), N=_frozen(d["N"]), mu=_frozen(d["mu"]),
        G=float(d["G"]), nu=float(d["nu"]),
        source=f"rollerrig's exact theory, Richardson {nx}/{2 * nx} across, "
               f"{n} random cases (seed {seed})",
        label=f"rollerrig's exact theory (Richardson {nx}/{2 * nx} across, {n} cases)")


# --------------------------------------------------------------------------
# scoring a method
# --------------------------------------------------------------------------

#: creep_forces arguments that the reference cases set
_CASE_ARGS = ("cx", "cy", "cphi", "a", "b", "N", "mu", "G", "nu")
_OPTION_ARGS = tuple(p for p, v in inspect.signature(creep_forces).parameters.items()
                     if p not in _CASE_ARGS and v.kind is not v.VAR_KEYWORD)
#: every option of the registry's methods (which method has which: METHODS)
_METHOD_OPTIONS = tuple(dict.fromkeys(o for m in METHODS.values() for o in m.options))


def _check_options(func: str, options: Mapping[str, Any], fixed: Sequence[str]) -> None:
    """The case's own arguments are refused; an option no method has is named
    here, the others are checked for the method by the registry."""
    known = _OPTION_ARGS + _METHOD_OPTIONS
    for k in options:
        if k in fixed:
            raise RollerRigError(f"{func}: {k} is set by the reference cases, not an option")
        if k not in known:
            raise RollerRigError(f"{func}: unknown option {k!r}; creep_forces takes "
                                 f"{', '.join(o for o in known if o != 'method')}")


def _stats(err: npt.ArrayLike) -> Dict[str, float]:
    """{"median", "p95", "max", "n", "n_failed"} of the finite errors."""
    err = np.asarray(err, dtype=float)
    ok = np.isfinite(err)
    good = err[ok]
    if good.size == 0:
        return dict(median=math.nan, p95=math.nan, max=math.nan, n=0,
                    n_failed=int(err.size))
    return dict(median=float(np.median(good)), p95=float(np.percentile(good, 95)),
                max=float(np.max(good)), n=int(good.size), n_failed=int(err.size - good.size))


class ScoreResult(NamedTuple):
    """A method's errors on the exact cases, as :func:`score` returns them.

    Statistics are dicts {"median", "p95", "max", "n", "n_failed"} of the
    force error ``|(dFx, dFy)| / (mu N)`` over the cases that did not fail;
    mz_* the same of ``|dMz| / (mu N cp)`` (the Polach method has no spin
    moment, so its Mz error is the exact ``|Mz|``).
    """

    method: str             #: the method scored
    options: Dict[str, Any]  #: the creep_forces options given
    cases: ExactCases       #: the reference cases
    fx: np.ndarray          #: the method's FX / (mu N) per case
    fy: np.ndarray          #: the method's FY / (mu N) per case
    mz: np.ndarray          #: the method's MZ / (mu N cp)
    status: np.ndarray      #: creep_forces status per case
    error: np.ndarray       #: |(dFx, dFy)| / (mu N) per case (NaN where the method failed)
    mz_error: np.ndarray    #: |dMz| / (mu N cp) per case
    overall: Dict[str, float]       #: statistics of the force error over all cases
    by_spin: Dict[float, Dict[str, float]]          #: {spin level: statistics}
    by_ellipticity: Dict[float, Dict[str, float]]   #: {a/b: statistics}
    mz_overall: Dict[str, float]    #: statistics of the Mz error over all cases
    mz_by_spin: Dict[float, Dict[str, float]]   #: {spin level: statistics of the Mz error}
    mz_by_ellipticity: Dict[float, Dict[str, float]]    #: {a/b: statistics of the Mz error}

    @property
    def label(self) -> str:
        """The method and its options as text, e.g. "fastsim (nx=20, ny=20)"."""
        shown = {k: v for k, v in self.options.items() if k != "errors"}
        if not shown:
            return self.method
        return f"{self.method} ({', '.join(f'{k}={v!r}' for k, v in shown.items())})"

    def table(self) -> str:
        """A text table of the statistics, overall and split by spin and a/b."""
        return table(self)


def score(method: str = "fastsim", *, cases: Optional[ExactCases] = None,
          **creep_options: Any) -> ScoreResult:
    """Score a creep-force method against the 3220 exact cases.

    Parameters
    ----------
    method : str, optional
        A name of ``rollerrig.METHODS``.
    cases : ExactCases, optional
        The reference (default :func:`exact_cases`).
    **creep_options
        Any other keyword of creep_forces (nx, ny, grid, bound, k0, kA,
        friction, ...); errors defaults to "raise", "warn" or "ignore" keeps
        the failed cases as NaN, counted in n_failed.

    Returns
    -------
    ScoreResult
        The errors per case and their statistics (:class:`ScoreResult`).

    Raises
    ------
    RollerRigError
        For an unknown method or option, an argument the cases set (cx,
        ..., nu), and (errors="raise") a failed case.

    See Also
    --------
    table : the statistics of several results as text.
    rollerrig.plot.error_map : the errors over the creepage plane.

    Examples
    --------
    >>> import rollerrig as rr
    >>> r = rr.reference.score("fastsim", nx=10, ny=10)
    >>> r.label, r.overall["n"], round(r.overall["median"], 4)
    ('fastsim (nx=10, ny=10)', 3220, 0.0206)
    """
    func = "score"
    _check_options(func, creep_options, _CASE_ARGS)
    t = exact_cases() if cases is None else cases
    opts = dict(creep_options)
    opts.setdefault("errors", "raise")
    f = creep_forces(t.cx, t.cy, t.cphi, a=t.a, b=t.b, N=t.N, mu=t.mu, G=t.G, nu=t.nu,
                     method=method, **opts)
    scale = t.mu * t.N
    # arrays, as the cases' are (np.asarray: the same arrays, typed so)
    fx, fy, mz = (np.asarray(v) for v in (f.fx / scale, f.fy / scale, f.mz / (scale * t.cp)))
    err = np.hypot(fx - t.Fx, fy - t.Fy)
    mz_err = np.abs(mz - t.Mz)

    def split(e: F64Array, key: F64Array) -> Dict[float, Dict[str, float]]:
        return {float(v): _stats(e[key == v]) for v in np.unique(key)}

    return ScoreResult(
        method=method, options=dict(creep_options), cases=t, fx=fx, fy=fy, mz=mz,
        status=np.asarray(f.status), error=err, mz_error=mz_err,
        overall=_stats(err), by_spin=split(err, t.spin),
        by_ellipticity=split(err, t.a_over_b), mz_overall=_stats(mz_err),
        mz_by_spin=split(mz_err, t.spin), mz_by_ellipticity=split(mz_err, t.a_over_b))


def table(results: Union[ScoreResult, Sequence[ScoreResult], Dict[Any, ScoreResult]],
          split: bool = True) -> str:
    """A text table of one or more ScoreResults.

    Parameters
    ----------
    results : ScoreResult, list or dict of ScoreResult
        The results, one block each.
    split : bool, optional
        After each method's overall row, a row per spin level and per a/b.

    Returns
    -------
    str
        Columns: median, p95, max of ``|dF|/(mu N)``, the number of cases
        (n+k!: k cases failed), and median, p95 of ``|dMz|/(mu N cp)``; the
        caption names the cases scored (ExactCases.label).
    """
    if isinstance(results, ScoreResult):
        results = [results]
    elif isinstance(results, dict):
        results = list(results.values())
    results = list(results)
    width = max([len(r.label) for r in results] + [len("method")]) + 2
    head = (f"{'method':<{width}}{'cases':<10}{'median':>9}{'p95':>9}{'max':>9}{'n':>10}"
            f"{'Mz med':>9}{'Mz p95':>9}")
    lines = [head, "-" * len(head)]
    for r in results:
        rows = [("all", r.overall, r.mz_overall)]
        if split:
            rows += [(f"spin {k:g}", s, r.mz_by_spin[k]) for k, s in r.by_spin.items()]
            rows += [(f"a/b {k:g}", s, r.mz_by_ellipticity[k])
                     for k, s in r.by_ellipticity.items()]
        for i, (name, s, m) in enumerate(rows):
            label = r.label if i == 0 else ""
            n = f"{s['n']}" + (f"+{s['n_failed']}!" if s["n_failed"] else "")
            lines.append(f"{label:<{width}}{name:<10}{s['median']:>9.4f}{s['p95']:>9.4f}"
                         f"{s['max']:>9.4f}{n:>10}{m['median']:>9.4f}{m['p95']:>9.4f}")
    against = "; ".join(dict.fromkeys(r.cases.label for r in results))   # the cases' own
    lines.append(f"|dF|/(mu N) against {against}; "
                 "Mz: |dMz|/(mu N cp)" + (""
                 if not any(r.overall["n_failed"] for r in results)
                 else "; n+k!: k cases failed (NaN), left out"))
    return "\n".join(lines)


# --------------------------------------------------------------------------
# creep curves (CONTACT's tractcurv example)
# --------------------------------------------------------------------------

class CreepCurve(NamedTuple):
    """One series of creep_curves_exact_vs_fastsim.csv in SI (:func:`creep_curves`)."""

    series: int             #: the series number (1 to 4)
    description: str        #: the series' description in the file
    cx: np.ndarray          #: longitudinal creepage [-] (cy = cphi = 0)
    fx: np.ndarray          #: FX [N] on the wheel
    fx_n: np.ndarray        #: FX / (mu N), mu the series' static coefficient
    #: the creep_forces arguments of the physical case (a, b, N, mu, G, nu,
    #: speed, friction: CONTACT's static coefficient and its falling friction
    #: law as FallingFriction(A = FKIN/mu, B = ln 2/SABSH1))
    case: Dict[str, Any]
    #: the rollerrig method that reproduces how CONTACT computed the series
    #: (None for the exact theory)
    method: Optional[str]
    #: the method's options; they hold the series' grid nx, ny, read from the
    #: header (the exact theory's options are only the grid)
    options: Dict[str, Any]
    note: str               #: what rollerrig does not model of the series, if anything


def _curve_settings(comment: str) -> Tuple[Dict[str, float], Dict[str, Any], float,
                                            Dict[int, Tuple[float, float, float]],
                                            Dict[str, float], str]:
    name = CURVES_FILE
    a, b = _header_numbers(comment, r"\(a=([0-9.]+), b=([0-9.]+) mm\)", "a, b", name)
    nx, ny = _header_numbers(comment, r"grid (\d+)x(\d+)", "the grid", name)
    case = dict(a=float(a) * MM, b=float(b) * MM,
                N=float(_header_number(comment, r"FN=([0-9.]+) N", "FN", name)),
                G=float(_header_number(comment, r"G=([0-9.]+) N/mm\^2", "G", name)) * N_PER_MM2,
                nu=float(_header_number(comment, r"nu=([0-9.]+)", "nu", name)),
                speed=float(_header_number(comment, r"V=([0-9.]+) m/s", "V", name)))
    coulomb = float(_header_number(comment, r"static friction coefficient: ([0-9.]+) in",
                                   "FSTAT", name))
    falling = {int(s): (float(k), float(e), float(h)) for s, k, e, h in re.findall(
        r"series (\d) uses (?:exponential falling friction )?FKIN=([0-9.]+), "
        r"FEXP1=([0-9.]+), SABSH1=([0-9.]+) mm/s", comment)}
    k0, alpha, beta = _header_numbers(
        comment, r"K0_MF=([0-9.]+), ALFAMF=([0-9.]+), BETAMF=([0-9.]+)",
        "the modified FASTSIM parameters", name)
    layer = _header_number(comment, r"(interfacial layer [^;]*)", "the layer", name)
    return (case, dict(nx=int(nx), ny=int(ny), grid="rect", bound="parabolic"), coulomb,
            falling, dict(k0=float(k0), alpha_inf=float(alpha), beta=float(beta)), layer)


@functools.lru_cache(maxsize=None)
def _creep_curves() -> Dict[int, CreepCurve]:
    comment, rows = read_csv(CURVES_FILE)
    case0, grid, coulomb, falling, modified, layer = _curve_settings(comment)
    out = {}
    for k in sorted({int(r["series"]) for r in rows}):
        sel = [r for r in rows if int(r["series"]) == k]
        desc = sel[0]["series_description"]
        case: Dict[str, Any] = dict(case0, mu=coulomb, friction=None)
        if k in falling:
            fkin, fexp, sabsh = falling[k]
            mu0 = fkin + fexp
            case.update(mu=mu0, friction=FallingFriction(A=fkin / mu0,
                                                         B=math.log(2.0) / (sabsh * MM)))
        low = desc.lower()
        note = ""
        if low.startswith("exact"):
            method, options = None, dict(nx=grid["nx"], ny=grid["ny"])
            if "layer" in low:
                note = f"{layer}: not modelled by rollerrig"
        elif "modified fastsim" in low:
            method, options = "modified_fastsim", dict(grid, **modified)
        elif "fastsim" in low:
            method, options = "fastsim", dict(grid)
        else:
            raise RollerRigError(f"{CURVES_FILE}: series {k}: unknown method {desc!r}")
        out[k] = CreepCurve(
            series=k, description=desc,
            cx=_frozen([float(r["cksi"]) for r in sel]),
            fx=_frozen([float(r["FX"]) for r in sel]),
            fx_n=_frozen([float(r["fx_n"]) for r in sel]),
            case=case, method=method, options=options, note=note)
    return out


def creep_curves() -> Dict[int, CreepCurve]:
    """The series of CONTACT's creep-curve example.

    Returns
    -------
    dict
        {series number: CreepCurve}: 1 exact theory, Coulomb mu = 0.33; 2
        exact theory with falling friction and an interfacial layer (mu0 =
        0.33); 3 CONTACT's FASTSIM (parabolic bound, three flexibilities),
        mu = 0.33; 4 CONTACT's modified FASTSIM (k0, alpha_inf, beta) with
        falling friction, mu0 = 0.36.  a = 6.304 mm, b = 12.61 mm, N = 106.7
        kN, G = 82 GPa, nu = 0.28, V = 10 m/s; all read from the header.

    See Also
    --------
    score_curves : a method against each series.
    rollerrig.plot.creep_curves : draws a series as the reference.

    Examples
    --------
    >>> import rollerrig as rr
    >>> curves = rr.reference.creep_curves()
    >>> sorted(curves), curves[3].method, curves[3].options["nx"]
    ([1, 2, 3, 4], 'fastsim', 48)
    """
    return dict(_creep_curves())


class CurveScore(NamedTuple):
    """A method against one creep-curve series, as :func:`score_curves` gives it."""

    series: int             #: the series number
    description: str        #: the series' description
    cx: np.ndarray          #: the series' longitudinal creepage [-]
    reference: np.ndarray   #: CONTACT's FX / (mu N)
    model: np.ndarray       #: the method's FX / (mu N)
    error: np.ndarray       #: |dFx| / (mu N) per point
    rms: float              #: root mean square of error [-]
    max: float              #: largest error [-]


def score_curves(method: str = "fastsim", series: Optional[Union[int, Sequence[int]]] = None,
                 **opts: Any) -> Dict[int, CurveScore]:
    """Compare a method with each creep-curve series.

    Each series is computed with its physical case (CreepCurve.case: load,
    ellipse, static friction, falling friction law, speed).

    Parameters
    ----------
    method : str, optional
        A name of ``rollerrig.METHODS``.
    series : int or list of int, optional
        A series number or a list (default all).
    **opts
        The method's options (creep_forces keywords; defaults are
        creep_forces', not the series' grid: pass nx, ny from
        CreepCurve.options for that).

    Returns
    -------
    dict
        {series: CurveScore} with the RMS and max of ``|dFx| / (mu N)`` over
        the series' points, mu the series' static coefficient.

    Raises
    ------
    RollerRigError
        For a series not in the file, an argument the series set, a bad
        option, and (errors="raise", the default) a failed point.

    Examples
    --------
    >>> import rollerrig as rr
    >>> grid = rr.reference.creep_curves()[3].options
    >>> s = rr.reference.score_curves("fastsim", series=3, nx=grid["nx"], ny=grid["ny"])
    >>> print(f"{s[3].rms:.5f} {s[3].max:.5f}")
    0.00040 0.00139
    """
    func = "score_curves"
    _check_options(func, opts, ("cx", "cy", "cphi", "a", "b", "N", "mu", "G", "nu"))
    curves = _creep_curves()
    if series is None:
        wanted = sorted(curves)
    else:
        wanted = [series] if isinstance(series, (int, np.integer)) else list(series)
        bad = [s for s in wanted if s not in curves]
        if bad:
            raise RollerRigError(f"{func}: series must be among {sorted(curves)}, got {bad}")
    out = {}
    for k in wanted:
        c = curves[k]
        kw = dict(c.case)
        kw.update(opts)
        kw.setdefault("errors", "raise")
        f = creep_forces(c.cx, method=method, **kw)
        model = f.fx / (c.case["mu"] * c.case["N"])
        err = np.abs(model - c.fx_n)
        out[k] = CurveScore(series=k, description=c.description, cx=c.cx,
                            reference=c.fx_n, model=model, error=err,
                            rms=float(np.sqrt(np.mean(err ** 2))), max=float(np.max(err)))
    return out
