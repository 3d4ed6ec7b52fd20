"""Parameter sweeps: a vectorised function or the rig over a Cartesian grid::

    import numpy as np, rollerrig as rr
    ds = rr.sweep("creep_forces", {"cx": np.linspace(0, 0.01, 200),
                                   "mu": [0.2, 0.3, 0.4]},
                  a=4e-3, b=4e-3, N=500.0, nx=20, ny=20)
    ds.fx.sel(mu=0.3)                     # xarray: dims ("cx", "mu"), units in attrs

    ds = rr.sweep_rig({"scenario.mu0": [0.3, 0.4], "method": ["fastsim", "polach"]},
                      duration=4.0)
    ds.reached.sel(mu0=0.4)               # dims ("mu0", "creep_method", "target")
    ds.mu0.attrs["parameter"]             # "scenario.mu0"

Units are those of UNITS, or for a name whose meaning is the function's
own those of FUNCTION_UNITS: hertz's curvature sums A, B are in 1/m, and
creep_forces' friction law is swept as the axes friction.A [-] and
friction.B [s/m] (ds = rr.sweep("creep_forces", {"friction.B": [0.3, 0.6]},
...), selected as ds.fx.sel({"friction.B": 0.6})).

The grid's axes are named after the function's arguments (for sweep) or
parameter paths and simulate's arguments (for sweep_rig), in the order of
the dimensions; every other keyword argument is passed unchanged to each
call.  A parameter path's dimension is named by its last part ("mu0" for
"scenario.mu0"), so that it can be used as a keyword (.sel(mu0=0.4)), or
by the whole path with "." replaced by "_" ("roller_drive_kp_N_m_s_per_rad")
where two axes, or an axis and another name of the Dataset, would share
that last part; the path itself is in the coordinate's attrs["parameter"].
simulate's argument "method" is the dimension "creep_method", since
.sel(method=...) is xarray's own keyword.
The flattened grid is cut into chunks run on a thread pool (the C loops
release the GIL), a Dask client, or serially; every case's result is
independent of the chunking, so all backends give bitwise the same numbers.

The result is an xarray.Dataset (xarray: extra "sweep"), whichever packages
are installed; without xarray the sweep raises an ImportError naming the
extra before it runs.  output="dict" asks for plain numpy instead: the dict
{"coords", "data", "dims", "units", "attrs", "coord_attrs"} of arrays shaped
like the grid.  The progress bar is rollerrig's one mechanism
(rollerrig._progress: tqdm, shown once the work passes about a second).
"""
from __future__ import annotations

from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy.typing as npt

import copy
import inspect
import math
import numbers
import os
from types import ModuleType

import numpy as np

from .._errors import RollerRigError, check_status
from .._optional import require
from .._units import DIMENSIONLESS, cf_unit
from ..contact import creep as contact
from ..rig.build import CREEP_OPTIONS
from ..rig.params import (PARAMETERS, _parameter_problems, _retired, check_parameters,
                          load_parameters)
from ..rig.run import simulate
from ._backends import check_options, execute

__all__ = ["sweep", "sweep_rig", "UNITS", "FUNCTION_UNITS", "FUNCTIONS"]

#: the vectorised functions that sweep takes by name
FUNCTIONS: Dict[str, Callable[..., Any]] = {
    "creep_forces": contact.creep_forces, "hertz": contact.hertz,
    "kalker_coefficients": contact.kalker_coefficients}

#: units of the names that mean one thing across the library (inputs and
#: outputs), for the Dataset's attrs; CF / UDUNITS, "1" is dimensionless.  Polach's
#: friction law is friction.A [1] and friction.B [s/m] (a sweep axis of
#: creep_forces, the names of its messages)
UNITS = {
    "cx": "1", "cy": "1", "cphi": "rad/m", "a": "m", "b": "m", "N": "N", "mu": "1",
    "G": "Pa", "nu": "1", "speed": "m/s", "fx": "N", "fy": "N", "mz": "N m",
    "friction.A": "1", "friction.B": "s/m",
    "E": "Pa", "E2": "Pa", "nu2": "1", "p0": "Pa", "delta": "m",
    "a_over_b": "1", "c11": "1", "c22": "1", "c23": "1", "c33": "1",
    "k0": "1", "alpha_inf": "1", "beta": "1", "kA": "1", "kS": "1",
    # sweep_rig: simulate's arguments, the summary metrics (a parameter path's
    # unit is its declaration's, rollerrig.rig.PARAMETERS)
    "duration": "s", "dt": "s", "roller_speed": "m/s", "nx": "1", "ny": "1",
    "substeps": "1", "target": "1", "reached": "1", "settling_s": "s", "adhesion": "1",
    "peak_force_over_muN": "1", "alpha": "1",
}
_PARAMETER_UNITS = {p.name: cf_unit(p.unit) or DIMENSIONLESS for p in PARAMETERS}

#: names whose meaning is the function's: hertz's A, B are its curvature sums
FUNCTION_UNITS = {"hertz": {"A": "1/m", "B": "1/m"}}

#: the grid axes of creep_forces that set a field of its friction law
FRICTION_AXES = ("friction.A", "friction.B")

_STATUS_ATTRS = {"long_name": "C status per case: 0 OK, > 0 warning, < 0 error (result NaN)"}
_RIG_ATTRS = {
    "status": {"long_name": "run status: 0 OK, > 0 some samples warned, < 0 the run stopped "
                            "(see message)"},
    "message": {"long_name": "the run's message (RigResult.message)"},
    "reached": {"long_name": "creepage held (mean over the last 80 % of the target's "
                             "interval)"},
    "settling_s": {"long_name": "settling time (running mean over 0.25 s within 5 % of the "
                                "target)"},
    "adhesion": {"long_name": "adhesion coefficient held |fx| / N"},
    "peak_force_over_muN": {"long_name": "peak |fx| / (mu0 N) over the target's interval"},
    "target": {"long_name": "creepage target"},
}
OUTPUTS = ("xarray", "dict")

CHUNK_CASES = 100_000      # cases per chunk by default: ~0.15 s of FASTSIM 20 x 20


def _units(name: object, func: Optional[str] = None) -> Optional[str]:
    """The units of a name of function `func`'s, or of a parameter path (its
    declaration's, rollerrig.rig.PARAMETERS), or None when unknown."""
    name = str(name)
    if func is not None and name in FUNCTION_UNITS.get(func, {}):
        return FUNCTION_UNITS[func][name]
    if name in _PARAMETER_UNITS:
        return _PARAMETER_UNITS[name]
    if name in UNITS:
        return UNITS[name]
    return UNITS.get(name.rsplit(".", 1)[-1])


def _axes(func: str, grid: object,
          numeric: bool) -> Tuple[Tuple[str, ...], Tuple[npt.NDArray[Any], ...]]:
    """Check the grid: a non-empty dict of non-empty 1-D axes.  Returns (names, axes)."""
    if not isinstance(grid, dict) or not grid:
        raise RollerRigError(f"{func}: grid must be a non-empty dict name -> 1-D array, "
                             f"got {grid!r:.60}")
    names: List[str] = []
    axes: List[npt.NDArray[Any]] = []
    for name, values in grid.items():
        if not isinstance(name, str) or not name:
            raise RollerRigError(f"{func}: grid names must be non-empty strings, got {name!r}")
        arr = np.asarray(values)
        if arr.ndim != 1:
            raise RollerRigError(f"{func}: grid axis '{name}' must be 1-D, got shape "
                                 f"{arr.shape}")
        if arr.size == 0:
            raise RollerRigError(f"{func}: grid axis '{name}' is empty")
        if numeric and arr.dtype.kind not in "iuf":
            raise RollerRigError(f"{func}: grid axis '{name}' must be real numbers, got dtype "
                                 f"{arr.dtype} ({values!r:.60})")
        names.append(name)
        axes.append(arr)
    return tuple(names), tuple(axes)


# ---------------------------------------------------------------- sweep

def _resolve(func: object) -> Tuple[str, Callable[..., Any], bool]:
    """(name, callable, known) for a function name or a callable."""
    if isinstance(func, str):
        if func not in FUNCTIONS:
            raise RollerRigError(f"sweep: unknown function {func!r}; give one of "
                                 f"{sorted(FUNCTIONS)} or a callable")
        return func, FUNCTIONS[func], True
    if not callable(func):
        raise RollerRigError(f"sweep: func must be a function name or a callable, "
                             f"got {func!r:.60}")
    for name, f in FUNCTIONS.items():
        if func is f:
            return name, f, True
    return getattr(func, "__name__", "func"), func, False


def _chunk(bounds: Tuple[int, int], func: Union[str, Callable[..., Any]], names: Sequence[str],
           axes: Sequence[npt.NDArray[Any]],
           fixed: Mapping[str, Any]) -> Dict[str, npt.NDArray[Any]]:
    """One chunk: the cases start <= i < stop of the flattened grid, as a
    dict of 1-D arrays (module level, so that Dask can send it)."""
    start, stop = bounds
    fn = FUNCTIONS[func] if isinstance(func, str) else func
    index = np.unravel_index(np.arange(start, stop), tuple(ax.size for ax in axes))
    kwargs = {name: ax[i] for name, ax, i in zip(names, axes, index)}
    kwargs, fixed = _with_friction(kwargs, fixed)
    out = fn(**kwargs, **fixed)
    if hasattr(out, "_asdict"):
        out = out._asdict()
    elif not isinstance(out, dict):
        raise RollerRigError(f"sweep: the function must return a NamedTuple (or dict) of "
                             f"arrays, got {type(out).__name__}")
    n = stop - start
    res: Dict[str, npt.NDArray[Any]] = {}
    for field, value in out.items():
        arr = np.asarray(value)
        if arr.size == 1 and n != 1:
            arr = np.full(n, arr.reshape(()))           # a field independent of the case
        if arr.size != n:
            raise RollerRigError(f"sweep: output field '{field}' has shape {arr.shape}; "
                                 f"expected one value per case ({n})")
        res[field] = arr.reshape(n)
    return res


def _friction_base(friction: object) -> contact.FallingFriction:
    """The law whose fields friction.A / friction.B axes replace: the fixed
    `friction` (a FallingFriction), or FallingFriction's defaults without one."""
    if friction is None:
        return contact.FallingFriction()
    if isinstance(friction, contact.FallingFriction):
        return friction
    raise RollerRigError(f"sweep: a grid axis {' or '.join(FRICTION_AXES)} sets a field of "
                         f"a FallingFriction; the fixed friction must be None or a "
                         f"FallingFriction, got {friction!r:.60}")


def _with_friction(kwargs: Dict[str, Any],
                   fixed: Mapping[str, Any]) -> Tuple[Dict[str, Any], Mapping[str, Any]]:
    """(kwargs, fixed) with the friction.A / friction.B axes turned into the
    argument friction=FallingFriction(A, B) of arrays, one value per case."""
    swept = {n[len("friction."):]: kwargs.pop(n) for n in FRICTION_AXES if n in kwargs}
    if not swept:
        return kwargs, fixed
    base = _friction_base(fixed.get("friction"))
    law = contact.FallingFriction(**dict(dict(A=base.A, B=base.B), **swept))
    return kwargs, dict(fixed, friction=law)


def _grid_index(shape: Tuple[int, ...], i: int) -> Tuple[int, ...]:
    return tuple(int(k) for k in np.unravel_index(i, shape))


def _as_attr(value: object) -> Union[str, numbers.Real]:
    """A fixed argument as a netCDF-friendly attribute value."""
    if isinstance(value, (bool, np.bool_)) or value is None:
        return str(value)
    if isinstance(value, (numbers.Integral, numbers.Real, str)):
        return value
    return repr(value)


def _check_output(func: str, output: str) -> Optional[ModuleType]:
    """Refuse a bad output before anything runs; the xarray module when it is wanted."""
    if output not in OUTPUTS:
        raise RollerRigError(f"{func}: output must be 'xarray' or 'dict', got {output!r}")
    if output == "xarray":
        return require("xarray", func, "sweep",
                       instead="or pass output='dict' for plain numpy arrays")
    return None


def sweep(func: Union[str, Callable[..., Any]], grid: Mapping[str, npt.ArrayLike], *,
          chunk: Optional[int] = None, backend: str = "threads", workers: Optional[int] = None,
          client: Any = None, progress: Optional[bool] = None, output: str = "xarray",
          **fixed: Any) -> Any:
    """Evaluate a vectorised function over the Cartesian grid of named axes.

    Parameters
    ----------
    func : str or callable
        "creep_forces", "hertz", "kalker_coefficients" (``FUNCTIONS``), or a
        callable taking keyword arrays (one value per case) and returning a
        NamedTuple (or dict) of arrays, as rr.creep_forces does.
    grid : dict
        name -> 1-D array: the axes, in the order of the dimensions, named
        after the function's arguments; for creep_forces also "friction.A"
        [-] and "friction.B" [s/m], fields of the FallingFriction law (the
        others from the fixed friction=FallingFriction(...), or its defaults
        without one).
    chunk : int, optional
        Cases per chunk (default: 100 000, fewer when that keeps a worker
        idle).
    backend : {"threads", "serial", "dask"}, optional
        "threads": a ThreadPoolExecutor of `workers` threads (the C loops
        release the GIL); "serial"; "dask": the client given or the running
        one.  Giving `client` selects Dask.
    workers : int, optional
        Threads of the "threads" backend; default os.cpu_count().
    client : dask.distributed.Client, optional
        The Dask client to run on.
    progress : bool or None, optional
        None (default): a progress bar once the sweep passes about a
        second; True: from the start; False: none.
    output : {"xarray", "dict"}, optional
        "xarray" (default; needs xarray, extra "sweep") or "dict" (plain
        numpy, whatever is installed).
    **fixed
        Every other keyword argument, passed unchanged to each call (e.g.
        a=..., b=..., N=..., mu=..., method="fastsim", nx=20; errors=).

    Returns
    -------
    xarray.Dataset or dict
        A Dataset with the axes as coordinates and one variable per output
        field (status as int8), units in each variable's attrs (``UNITS``,
        ``FUNCTION_UNITS``), the fixed arguments in the Dataset's attrs.
        With output="dict" the dict {"coords": {name: axis}, "data": {field:
        array shaped like the grid}, "dims": {field: dimension names},
        "units": {name: unit}, "attrs": the Dataset's attrs, "coord_attrs":
        {name: attrs}}.

    Raises
    ------
    RollerRigError
        For a bad axis (not 1-D, empty, not numbers for the library's
        functions), a name given both as an axis and as a fixed argument,
        a bad backend, workers, client, chunk, progress or output; with
        errors="raise", for a failed case; an exception in a chunk raises
        RollerRigError naming the chunk's index range, the original as its
        cause.
    ImportError
        For output="xarray" without xarray (naming the extra "sweep"),
        raised before the sweep runs.

    See Also
    --------
    sweep_rig : the rig's simulation over a grid of parameters.
    creep_forces, hertz, kalker_coefficients : the functions swept by name.

    Notes
    -----
    For the library's functions, failed cases are NaN with a negative
    status and one RollerRigWarning is given for the whole grid (or pass
    errors="raise" / "ignore").  The flattened grid is cut into chunks; every
    case's result is independent of the chunking, so all backends give
    bitwise the same numbers.

    Examples
    --------
    >>> import rollerrig as rr
    >>> ds = rr.sweep("creep_forces", {"cx": [1e-4, 2e-4, 4e-4], "mu": [0.2, 0.3]},
    ...               a=6e-3, b=4e-3, N=1e4, nx=20, ny=20, progress=False)
    >>> ds.fx.dims, ds.fx.attrs["units"]
    (('cx', 'mu'), 'N')
    >>> ds.fx.sel(mu=0.3).values.round(1)
    array([ -883.7, -1562.7, -2444.9])

    Plain numpy:

    >>> d = rr.sweep("hertz", {"N": [1e3, 1e4]}, A=7.2, B=3.3, output="dict", progress=False)
    >>> d["data"]["a"].round(6), d["units"]["a"]
    (array([0.000671, 0.001446]), 'm')
    """
    name, fn, known = _resolve(func)
    where = f"sweep({name})"
    names, axes = _axes("sweep", grid, numeric=known)
    backend, slots, client = check_options("sweep", backend, workers, client, progress)
    xr = _check_output("sweep", output)
    clash = sorted(set(names) & set(fixed))
    if clash:
        raise RollerRigError(f"sweep: {clash} given both as a grid axis and as a fixed argument")
    params: Optional[Mapping[str, inspect.Parameter]]
    try:
        params = inspect.signature(fn).parameters
    except (TypeError, ValueError):
        params = None
    friction_axes = [n for n in names if n in FRICTION_AXES]
    if friction_axes:
        if name != "creep_forces":
            raise RollerRigError(f"sweep: the grid axes {friction_axes} are creep_forces' "
                                 f"friction law; {name} has none")
        _friction_base(fixed.get("friction"))
    if params is not None:
        called = dict(fixed, **{n: 0.0 for n in names if n not in FRICTION_AXES})
        if friction_axes:
            called["friction"] = None
        try:
            inspect.signature(fn).bind(**called)
        except TypeError as exc:
            raise RollerRigError(f"sweep: {name}: {exc}") from None
    if known:
        for key, value in fixed.items():
            if np.ndim(value) > 0:
                raise RollerRigError(f"sweep: fixed argument '{key}' must be a scalar (sweep "
                                     f"it as a grid axis), got shape {np.shape(value)}")
    shape = tuple(ax.size for ax in axes)
    total = math.prod(shape)
    if chunk is None:
        chunk = max(1, min(CHUNK_CASES, -(-total // slots)))
    elif isinstance(chunk, bool) or not isinstance(chunk, numbers.Integral) or chunk < 1:
        raise RollerRigError(f"sweep: chunk must be an integer >= 1 (cases per chunk), "
                             f"got {chunk!r}")
    chunk = int(chunk)
    bounds = [(s, min(total, s + chunk)) for s in range(0, total, chunk)]
    sizes = [b - a for a, b in bounds]

    # the library's functions: no warning per chunk, one for the grid (below)
    errors = fixed.get("errors")
    call_fixed = dict(fixed)
    if known and errors is None:
        call_fixed["errors"] = "ignore"

    data: Dict[str, npt.NDArray[Any]] = {}

    def store(k: int, res: Dict[str, npt.NDArray[Any]]) -> None:
        start, stop = bounds[k]
        for field, arr in res.items():
            if field not in data:
                dtype = np.int8 if field == "status" else arr.dtype
                data[field] = np.empty(total, dtype=dtype)
            data[field][start:stop] = arr

    def describe(k: int) -> str:
        start, stop = bounds[k]
        return (f"chunk {k} of {len(bounds)} (cases {start} to {stop - 1}, grid index "
                f"{_grid_index(shape, start)} to {_grid_index(shape, stop - 1)})")

    common = dict(func=name if known else fn, names=names, axes=axes, fixed=call_fixed)
    execute(where, _chunk, bounds, sizes, describe, store, common, backend=backend,
            slots=slots, client=client, progress=progress, unit="case")
    data = {field: arr.reshape(shape) for field, arr in data.items()}

    if known and errors is None and "status" in data:
        args = {n: np.broadcast_to(ax.astype(float).reshape(
            [-1 if j == i else 1 for j in range(len(shape))]), shape)
            for i, (n, ax) in enumerate(zip(names, axes))}
        args.update({k: np.asarray(v, dtype=float) for k, v in fixed.items()
                     if isinstance(v, numbers.Real) and not isinstance(v, bool)})
        def blame(i: int, code: int) -> Optional[List[str]]:
            """the arguments the C core blames for the failed case i"""
            index = np.unravel_index(i, shape)
            kwargs = {n: float(ax[k]) for n, ax, k in zip(names, axes, index)}
            kwargs, case_fixed = _with_friction(kwargs, fixed)
            return contact._case_blame(name, dict(case_fixed, **kwargs), code)
        check_status(name, data["status"], args, "warn", blame)

    attrs = {"function": name, **{k: _as_attr(v) for k, v in fixed.items()}}
    return _package(xr, dict(zip(names, axes)), {f: names for f in data}, data, attrs,
                    {"status": _STATUS_ATTRS}, func=name if known else None)


def _package(xr: Optional[ModuleType], coords: Mapping[str, npt.NDArray[Any]],
             var_dims: Mapping[str, Tuple[str, ...]], data: Mapping[str, npt.NDArray[Any]],
             attrs: Mapping[str, object], extra_attrs: Mapping[str, Mapping[str, str]],
             paths: Optional[Mapping[str, str]] = None, func: Optional[str] = None) -> Any:
    """An xarray.Dataset (xr the module), or with xr None the plain dict.
    paths: {dimension: parameter path} of the dimensions named after one;
    func: the library function swept, whose names the units are of."""
    paths = paths or {}
    units = {n: _units(paths.get(n, n), func) for n in list(coords) + list(data)}
    units = {n: u for n, u in units.items() if u is not None and n != "status"}

    def attrs_of(n: str) -> Dict[str, str]:
        return dict(extra_attrs.get(n, {}), **({"units": units[n]} if n in units else {}),
                    **({"parameter": paths[n]} if n in paths else {}))
    if xr is None:
        return {"coords": coords, "data": data, "dims": {n: var_dims[n] for n in data},
                "units": units, "attrs": attrs,
                "coord_attrs": {n: attrs_of(n) for n in coords}}
    return xr.Dataset({n: (var_dims[n], arr, attrs_of(n)) for n, arr in data.items()},
                      coords={n: (n, ax, attrs_of(n)) for n, ax in coords.items()},
                      attrs=attrs)


# ---------------------------------------------------------------- sweep_rig

_RIG_METRICS = ("reached", "settling_s", "adhesion", "peak_force_over_muN")
_NOT_SWEPT = ("params", "targets", "target_times", "progress", "output", "record_every",
              "max_record_bytes")


def _with_value(base: Dict[str, Any], path: str, value: object) -> Dict[str, Any]:
    """A deep copy of nested dict `base` with the dotted `path` set to value."""
    params = copy.deepcopy(base)
    *sections, leaf = path.split(".")
    node = params
    for part in sections:
        node = node.setdefault(part, {})
    node[leaf] = value
    return params


def _rig_point(k: int, names: Sequence[str], axes: Sequence[npt.NDArray[Any]],
              base: Dict[str, Any], options: Mapping[str, Any]
              ) -> Tuple[Tuple[float, ...], npt.NDArray[np.float64], int, str]:
    """Run simulate at flat grid point k (module level, so that Dask can send it).
    Returns (targets, metrics [len(targets) x 4], status, message)."""
    shape = tuple(ax.size for ax in axes)
    index = np.unravel_index(k, shape)
    params = copy.deepcopy(base)
    kwargs = dict(options)
    for name, ax, i in zip(names, axes, index):
        value = ax[i].item()          # plain Python numbers: the rig checks int/float types
        if "." in name:
            params = _with_value(params, name, value)
        else:
            kwargs[name] = value
    res = simulate(params=params, progress=False, **kwargs)
    rows = res.summary()
    metrics = np.array([[row[m] for m in _RIG_METRICS] for row in rows], dtype=float)
    return res.targets, metrics, res.status, res.message


# keywords of xarray's Dataset.sel itself: a dimension of that name could
# not be selected as .sel(name=...)
_SEL_KEYWORDS = {"method", "tolerance", "drop", "indexers"}
#: the dimension of a simulate argument whose own name is one of those
RENAMED_ARGUMENTS = {"method": "creep_method"}


def _dimension_names(names: Sequence[str]) -> Tuple[str, ...]:
    """The Dataset's dimension for each grid axis: a parameter path by its
    last part when that is unique, else by the path with "." -> "_"; a
    simulate argument by its own name, but "method" as "creep_method"
    (RENAMED_ARGUMENTS: .sel(method=...) is xarray's own keyword)."""
    leaves = [n.rsplit(".", 1)[-1] for n in names]
    args = [RENAMED_ARGUMENTS.get(n, n) for n in names if "." not in n]
    taken = set(_RIG_METRICS) | {"target", "status", "message"}
    dims = []
    for name, leaf in zip(names, leaves):
        if "." not in name:
            dims.append(RENAMED_ARGUMENTS.get(name, name))
        elif leaves.count(leaf) == 1 and leaf not in taken | _SEL_KEYWORDS | set(args):
            dims.append(leaf)
        else:
            dims.append(name.replace(".", "_"))
    clash = sorted({d for d in dims if dims.count(d) > 1 or d in taken})
    if clash:
        raise RollerRigError(f"sweep_rig: the grid axes {list(names)} give the dimension "
                             f"name(s) {clash} twice or a name of the result's variables")
    return tuple(dims)


def sweep_rig(grid: Mapping[str, Any], *, backend: str = "threads",
              workers: Optional[int] = None, client: Any = None,
              progress: Optional[bool] = None, output: str = "xarray",
              **simulate_kwargs: Any) -> Any:
    """Run rr.simulate at every point of a Cartesian grid of rig parameters.

    Parameters
    ----------
    grid : dict
        name -> 1-D array; a name is a dotted parameter path of the
        parameter file ("scenario.mu0", "wheelset.mass_kg") or one of
        simulate's own arguments ("dt", "method", "roller_speed", "nx",
        "ode", "k0", ...).
    backend, workers, client, progress, output
        As for :func:`sweep`; one run per task (the C time stepping releases
        the GIL, so threads scale).
    **simulate_kwargs
        Passed to every run (duration [s], targets, params as the base that
        the grid's paths override: a dict or a TOML file, ...).

    Returns
    -------
    xarray.Dataset or dict
        A Dataset with dims (grid axes..., "target") and the variables
        reached [-], settling_s [s], adhesion [-], peak_force_over_muN [-]
        (as RigResult.summary(), units and long_name in attrs), plus per
        point the run status (int8) and message.  With output="dict" the
        plain dict as for sweep.

    Raises
    ------
    RollerRigError
        Every value of every parameter axis is checked (check_parameters)
        before any run: a bad one raises, naming the axis and the value; a
        run that raises (e.g. dt out of range) raises naming the point;
        params neither a dict nor a TOML path.
    ImportError
        For output="xarray" without xarray (the extra "sweep").

    See Also
    --------
    simulate : one run.
    sweep : a vectorised function over a grid.

    Notes
    -----
    A parameter path's dimension is its last part (ds.reached.sel(mu0=0.4)
    for "scenario.mu0"), or the path with "." -> "_" where two axes share a
    last part; the coordinate's attrs["parameter"] holds the path;
    simulate's "method" is the dimension "creep_method" (.sel(method=...) is
    xarray's own keyword), with attrs["argument"] = "method".  A run that
    stops (status < 0) gives NaN for the targets it did not reach.

    Examples
    --------
    >>> import rollerrig as rr
    >>> ds = rr.sweep_rig({"scenario.mu0": [0.3, 0.4]}, duration=1.0, targets=[0.02],
    ...                   target_times=[0.0], progress=False)
    >>> ds.adhesion.dims, ds.mu0.attrs["parameter"]
    (('mu0', 'target'), 'scenario.mu0')
    >>> ds.adhesion.values.round(3)
    array([[0.292],
           [0.389]])
    """
    names, axes = _axes("sweep_rig", grid, numeric=False)
    backend, slots, client = check_options("sweep_rig", backend, workers, client, progress)
    xr = _check_output("sweep_rig", output)
    dims = _dimension_names(names)
    sim_args = set(inspect.signature(simulate).parameters) - {"creep"}
    base = simulate_kwargs.pop("params", None) or {}
    if isinstance(base, (str, os.PathLike)):
        base = load_parameters(base)
    elif not isinstance(base, dict):
        raise RollerRigError(f"sweep_rig: params must be a nested dict or the path of a TOML "
                             f"file, got {type(base).__name__}")
    base = copy.deepcopy(base)
    full = check_parameters(base, source="sweep_rig: params")
    for name, ax in zip(names, axes):
        if "." in name and _retired(name) is not None:
            _, problems = _parameter_problems(_with_value(base, name, ax[0].item()))
            raise RollerRigError(f"sweep_rig: grid axis '{name}' = {ax[0].item()!r}: "
                                 f"{problems[0]}")
        if "." in name:
            node: Any = full                    # a section, then a value
            parts = name.split(".")
            for depth, part in enumerate(parts):
                if not isinstance(node, dict) or part not in node:
                    raise RollerRigError(f"sweep_rig: unknown parameter '{name}' (no "
                                         f"'{'.'.join(parts[:depth + 1])}' in the parameter "
                                         f"file)")
                node = node[part]
            if isinstance(node, (dict, list)):
                raise RollerRigError(f"sweep_rig: '{name}' is not a single value; sweep its "
                                     f"entries")
            for value in ax:
                # the value's own problems; those between keys (kS <= kA)
                # depend on the other axes and show in the run
                _, problems = _parameter_problems(_with_value(base, name, value.item()))
                own = [p for p in problems if p.startswith(name + " ")]
                if own:
                    raise RollerRigError(f"sweep_rig: grid axis '{name}' = "
                                         f"{value.item()!r}: {own[0]}")
        elif name in _NOT_SWEPT or name not in (sim_args | set(CREEP_OPTIONS)):
            raise RollerRigError(f"sweep_rig: '{name}' is neither a parameter path "
                                 f"('section.key') nor a simulate argument that takes one "
                                 f"value "
                                 f"({sorted((sim_args | set(CREEP_OPTIONS)) - set(_NOT_SWEPT))})")
        if name in simulate_kwargs:
            raise RollerRigError(f"sweep_rig: '{name}' given both as a grid axis and as a "
                                 f"fixed argument")
    for key in ("progress", "output"):
        if key in simulate_kwargs:
            raise RollerRigError(f"sweep_rig: {key} is the sweep's own argument")

    shape = tuple(ax.size for ax in axes)
    total = math.prod(shape)
    found: Dict[str, Any] = {}

    def store(k: int, res: Tuple[Tuple[float, ...], npt.NDArray[np.float64], int, str]) -> None:
        targets, metrics, status, message = res
        if "targets" not in found:
            found["targets"] = targets
            found["metrics"] = np.full((total, len(targets), len(_RIG_METRICS)), np.nan)
            found["status"] = np.zeros(total, dtype=np.int8)
            found["message"] = np.empty(total, dtype=object)
        if tuple(targets) != tuple(found["targets"]):
            raise RollerRigError(f"sweep_rig: the targets differ between runs "
                                 f"({found['targets']} and {targets})")
        found["metrics"][k] = metrics
        found["status"][k] = status
        found["message"][k] = message

    def describe(k: int) -> str:
        index = _grid_index(shape, k)
        point = ", ".join(f"{n} = {ax[i].item()!r}" for n, ax, i in zip(names, axes, index))
        return f"run {k} (grid index {index}: {point})"

    common = dict(names=names, axes=axes, base=base, options=simulate_kwargs)
    execute("sweep_rig", _rig_point, list(range(total)), [1] * total, describe, store, common,
            backend=backend, slots=slots, client=client, progress=progress, unit="run")

    ntarget = len(found["targets"])
    data = {m: found["metrics"][:, :, j].reshape(shape + (ntarget,))
            for j, m in enumerate(_RIG_METRICS)}
    data["status"] = found["status"].reshape(shape)
    data["message"] = found["message"].astype(str).reshape(shape)
    coords = dict(zip(dims, axes))
    coords["target"] = np.asarray(found["targets"], dtype=float)
    var_dims = {m: dims + ("target",) for m in _RIG_METRICS}
    var_dims.update(status=dims, message=dims)
    attrs = {"function": "simulate",
             **{k: _as_attr(v) for k, v in simulate_kwargs.items()}}
    if base:
        attrs["params"] = repr(base)
    paths = {d: n for d, n in zip(dims, names) if "." in n}
    extra = dict(_RIG_ATTRS, **{d: {"argument": n} for d, n in zip(dims, names) if d != n
                                and "." not in n})
    return _package(xr, coords, var_dims, data, attrs, extra, paths)
