"""The C rig from checked parameters: its contact table, the creep-force
method and options, the drives' sampled speed loops, :class:`Rig` (the C
rig stepped by hand) and :func:`build_rig`."""
from __future__ import annotations

import functools
import os
import math
from typing import (TYPE_CHECKING, Any, Callable, Dict, Iterable, List, Mapping, Optional,
                    Sequence, Tuple, Union)

from .._typing import Params

from .. import _core
from . import real_profiles as _real_profiles
from . import nonhertz_rig as _nonhertz_rig
from .._errors import RollerRigError, status_message
from .._binding import METHODS, check_creep_options, core, loop_method, rig_method
from ..geometry.profiles import Profile
from ..geometry.wheelset import MAX_ROWS, ContactTable, RigGeometry
from .params import (_FILE_OPTIONS, _SAMPLE_TIME, PARAMETERS, _c_values, _check_run, _defaults,
                     _parameters, _short)
from .params import _with_track
from .real_profiles import Numbers, Stamps
# the rig stepped by hand, in a room of its own
from ._stepper import Rig as Rig

if TYPE_CHECKING:
    from ..geometry.nonhertz import NonHertzTable

#: checked parameters {section: {key: value}}
_Merged = Dict[str, Dict[str, Any]]
#: a build of the rig (or of its table) from parameters and a run's own values
_Build = Callable[[_Merged, Mapping[str, Any]], object]


#: the creep-force methods the rig steps with (the registry's in_rig: not
#: iterative, and |F| <= mu N; csrc/rig/rr_rig.h, rr_rig_method_check)
RIG_METHODS = tuple(name for name, m in METHODS.items() if m.in_rig)


def _c_params(P: Mapping[str, Mapping[str, Any]], dt: float, substeps: int, ode: str,
              run: Optional[Mapping[str, Any]] = None) -> Dict[str, Any]:
    """The C rig's primary values {"section.key": value} (csrc/rig/rr_rig_params.h,
    rr_rig_config) of checked parameters, with the run's own values (run:
    simulate's duration, targets, ...; checked) and the call's sample time,
    substeps and integrator; the C side derives the rig's parameters."""
    cp = {**_c_values(P), **(run or {})}
    cp[_SAMPLE_TIME] = float(dt)
    cp["integration.substeps"] = int(substeps)
    cp["integration.method"] = ode
    return cp


#: the parameters that make the rig's profiles and contact table
GEOMETRY_KEYS = ("wheelset.wheel_radius_m", "roller.radius_m", "wheelset.profile_half_width_m",
                 "wheelset.conicity", "roller.crown_radius_m", "wheelset.contact_half_spacing_m",
                 "integration.table_half_range_m", "integration.table_rows")


#: the parameters that place and scale real profiles (rollerrig.rig.real_profiles)
PROFILE_KEYS = ("wheelset.profile", "wheelset.profile_right", "wheelset.profile_scale",
                "roller.profile", "roller.profile_right", "roller.profile_scale",
                "roller.gauge_m", "integration.profile_smoothing_m")


def _geometry(P: Mapping[str, Mapping[str, Any]]) -> ContactTable:
    """The rig's profiles and their table: the conical wheel on the crowned
    roller (the paper's first stage), or the real profiles the profile rows
    name (rollerrig.rig.real_profiles); a geometry that yields none is the
    parameters' fault, and the message says which ones made it."""
    W, R, I = P["wheelset"], P["roller"], P["integration"]
    numbers: Numbers = (float(W["wheel_radius_m"]), float(R["radius_m"]),
                        float(W["profile_half_width_m"]), math.atan(float(W["conicity"])),
                        float(R["crown_radius_m"]), float(W["contact_half_spacing_m"]),
                        float(I["table_half_range_m"]), int(I["table_rows"]))
    real = _real_profiles.profile_points(P) is not None
    keys = GEOMETRY_KEYS + (PROFILE_KEYS if real else ())
    try:
        if not real:
            return _rig_table(*numbers)
        values = (W["profile"], R["profile"], W["profile_right"], R["profile_right"])
        return _rig_profile_table(numbers, (float(W["profile_scale"]), float(R["profile_scale"]),
                                            float(R["gauge_m"])), values,
                                  *_real_profiles._stamps(P))
    except RollerRigError as e:
        named = ", ".join(f"{k} = {P[k.split('.')[0]][k.split('.')[1]]!r}" for k in keys)
        raise RollerRigError(f"params: the rig's geometry ({named}) gives no contact "
                             f"table: {e}") from None


@functools.lru_cache(maxsize=8)
def _rig_profile_table(numbers: Numbers, scales: Tuple[float, float, float],
                       values: Tuple[object, object, object, object], smoothing: float,
                       stamps: Stamps) -> ContactTable:
    """The table on real profiles (rr_rig_table_build_profiles, in C from
    the points, as the FMU and a C program build it); its geometry the
    RigGeometry of the same points, scaled and placed (for lookups and
    plots: the table is the C core's)."""
    r0, R0, hw, alpha, crown, span, reach, rows = numbers
    if not (math.isfinite(reach) and reach > 0):
        raise RollerRigError(f"rig_table: the table's half range must be > 0 [m], got {reach!r}")
    if not 2 <= rows <= MAX_ROWS:
        raise RollerRigError(f"rig_table: the table's rows must be from 2 to {MAX_ROWS}, "
                             f"got {rows!r}")
    points = _real_profiles._points(*values, smoothing, stamps)[0]
    data, y0, dy = _real_profiles.rig_profile_table(numbers, scales, points, values)
    data.setflags(write=False)
    return ContactTable(_real_profiles.rig_geometry(numbers, scales, points), y0, dy, rows,
                        data)


# The table is a pure function of these numbers and read-only, so runs on the
# same geometry (a sweep over controller or friction settings, a notebook
# re-running a cell) share one build instead of repeating its ~50 ms.
# The rows come from the C core's rr_rig_table_build (csrc/geometry/rr_tables.h),
# so a C program building the rig's table has this one, bit for bit; the
# profiles made here (the same points and spline, by the same C) are the
# table's geometry and check the numbers with messages that name them.
@functools.lru_cache(maxsize=8)
def _rig_table(r0: float, R0: float, hw: float, alpha: float, crown: float, span: float,
               reach: float, rows: int) -> ContactTable:
    n = _core.RIG_PROFILE_POINTS
    g = RigGeometry(wheel=Profile.conical(alpha, (-hw, hw), r0=r0, n=n),
                    roller=Profile.cylinder((-hw, hw), crown_radius=crown, n=n),
                    wheel_radius=r0, roller_radius=R0, wheel_y=span, roller_y=span)
    g._params()
    if not (math.isfinite(reach) and reach > 0):
        raise RollerRigError(f"rig_table: the table's half range must be > 0 [m], got {reach!r}")
    if not 2 <= rows <= MAX_ROWS:
        raise RollerRigError(f"rig_table: the table's rows must be from 2 to {MAX_ROWS}, "
                             f"got {rows!r}")
    data, y0, dy, status, bad_y = _core.rig_table(r0, R0, hw, alpha, crown, span, reach, rows)
    if status < 0:
        where = f"at y_ws = {bad_y!r}: " if math.isfinite(bad_y) else ""
        raise RollerRigError(f"rig_table: {where}{status_message(status)}")
    data.setflags(write=False)
    return ContactTable(g, y0, dy, rows, data)


#: the keyword options of simulate / build_rig / replay that go to the creep-force
#: method: every option of the registry's methods (nx, ny are arguments of their own)
CREEP_OPTIONS = tuple(dict.fromkeys(o for m in METHODS.values() for o in m.options
                                    if o not in ("nx", "ny")))


def _creep_options(func: str, P: Mapping[str, Mapping[str, Any]], method: Optional[str],
                   nx: Optional[int], ny: Optional[int], creep: Mapping[str, Any],
                   in_rig: bool = True) -> Dict[str, object]:
    """The creep-force method and its options: the parameters' contact
    section (the keys of _FILE_OPTIONS the method has), overridden by the
    caller's (method, nx, ny, and `creep`: the method's options); checked
    by the registry.  in_rig: a method the rig steps with (RIG_METHODS),
    else one its contact model takes (replay).  Returns the keywords for
    the binding (method=...)."""
    C = P["contact"]
    method = method if method is not None else C["creep_method"]
    if not (isinstance(method, str) and method in METHODS):
        raise RollerRigError(f"{func}: method must be one of {', '.join(map(repr, METHODS))}, "
                             f"got {method!r:.60}")
    info = rig_method(func, method) if in_rig else loop_method(func, method)
    if info.coulomb_only and C["friction_law"] != "coulomb":
        raise RollerRigError(f"{func}: method {method!r} is built for Coulomb friction; the "
                             f"parameters' contact.friction_law is {C['friction_law']!r} "
                             f"(set it to 'coulomb')")
    unknown = set(creep) - set(CREEP_OPTIONS)
    if unknown:
        raise RollerRigError(f"{func}: unknown option(s) {sorted(unknown)}; the creep "
                             f"options are {list(CREEP_OPTIONS)}")
    has = METHODS[method].options
    opts = {o: C[key] for key, o in _FILE_OPTIONS.items() if o in has and key in C}
    # nx, ny are arguments of their own, like the file's keys: the grid of a
    # method that has one (a method without one takes no grid)
    opts.update({k: v for k, v in (("nx", nx), ("ny", ny)) if v is not None and k in has})
    opts.update(creep)
    return check_creep_options(func, method, opts)


def _build(func: str, P: _Merged, *, dt: Optional[float], method: Optional[str],
           substeps: Optional[int], ode: Optional[str], nx: Optional[int], ny: Optional[int],
           roller_speed: Optional[float], start: str, creep: Mapping[str, Any],
           given_dt: Optional[bool] = None, run: Optional[Mapping[str, Any]] = None,
           names: Optional[Mapping[str, str]] = None
           ) -> Tuple[Rig, ContactTable, float, float, str]:
    """(the C rig, its table, dt, roller speed [m/s], method) of checked
    parameters P; given_dt: whether the caller gave dt (default: dt not
    None), for messages; run, names: more of the run's own values
    {"section.key": value} (simulate's duration, targets, start times) and
    the arguments that gave them."""
    P = _with_track(func, P)              # scenario.track: the rail for the rollers
    given_dt = dt is not None if given_dt is None else given_dt
    own: Dict[str, Any] = dict(run or {})
    named: Dict[str, str] = dict(names or {})
    own[_SAMPLE_TIME] = dt if dt is not None else P["scenario"]["control_sample_time_s"]
    if given_dt:
        named[_SAMPLE_TIME] = "dt"
    values_given: Tuple[Tuple[str, str, object], ...] = (
        ("integration.substeps", "substeps", substeps), ("integration.method", "ode", ode),
        ("scenario.roller_speed_m_s", "roller_speed", roller_speed))
    for key, arg, v in values_given:
        if v is not None:
            own[key], named[key] = v, arg
    # every value and rule of the run's configuration (the drives' loops at
    # dt too), each problem named, before anything is built
    values = _check_run(func, P, own, named)
    step, substeps_, ode_ = (float(values[_SAMPLE_TIME]), int(values["integration.substeps"]),
                             str(values["integration.method"]))
    V = float(values["scenario.roller_speed_m_s"])
    opts = _creep_options(func, P, method, nx, ny, creep)
    if start not in ("rolling", "rest"):
        raise RollerRigError(f"{func}: start must be 'rolling' or 'rest', got {start!r}")

    def make(Q: _Merged, run: Mapping[str, Any],
             table: Optional[ContactTable] = None) -> _core.Rig:
        table = _geometry(Q) if table is None else table
        cp = _c_params(Q, step, substeps_, ode_, run)
        # the non-Hertzian tables of P (built or read once, below); another
        # set of values (_culprits' search) is tried on Hertz
        nh = nh_tables if Q is P else None
        if nh is None:
            cp["contact.patch"] = "hertz"
        # the C side (rr_rig_params_set_table) takes eq. 15-16's radii at the
        # centred wheelset's rolling radii, as a rig is calibrated: the
        # profiles' nominal radii would bias the creepage by
        # (r - r0)/r0 + (R0 - R)/R0, about 0.2 % of creepage here
        return core(_core.Rig, table.data, table.y0, table.dy, cp, opts,
                    float(cp["scenario.roller_speed_m_s"]) / float(Q["roller"]["radius_m"])
                    if start == "rolling" else 0.0, nh)
    try:
        table = _geometry(P)
    except RollerRigError as e:
        raise _cannot_start(func, e, _culprits(P, own, named, GEOMETRY_KEYS,
                                               lambda Q, run: _geometry(Q))) from None
    nh_tables: Optional[Tuple[Any, ...]] = None
    if P["contact"]["patch"] == "nonhertz":
        try:
            nh_tables = _nonhertz_rig.c_tables(_nonhertz_rig.table_for(P, table))
        except RollerRigError as e:
            raise RollerRigError(f"{func}: contact.patch = 'nonhertz': {e}") from None
    try:
        rig = make(P, own, table)
    except (ValueError, RollerRigError) as e:
        raise _cannot_start(func, e, _culprits(P, own, named, [p.name for p in PARAMETERS
                                                               if not p.creep], make)) from None
    return Rig(rig), table, step, V, str(opts["method"])


def _cannot_start(func: str, e: Exception, culprits: Sequence[str]) -> RollerRigError:
    named = f"the rig cannot start with {', '.join(culprits)}: " if culprits else ""
    return RollerRigError(f"{func}: {named}{e}")


def _culprits(P: _Merged, run: Mapping[str, Any], names: Mapping[str, str], keys: Iterable[str],
              build: _Build) -> List[str]:
    """The changed values the rig cannot start with, where every value is in
    range and every rule holds (_check_run said so): each of `keys` that
    differs from its default (not one the run replaces: its own values are
    arguments), and a given roller speed, is put back to its default alone,
    build(Q, run) tried; those whose default lets it succeed are named.

    The one rebuild that stays (issue 23): the start's evaluation (the
    contact table of the geometry; the normal loads, the contact and the
    drives at the first state) can overflow or underflow for values each in
    range and far from the rig (wheelset.mass_kg = 1e300, scenario.mu0 =
    1e100, contact.youngs_modulus_Pa = 1e300: RR_ERR_RANGE from the contact
    layer), which no bound on a value or a pair of them predicts without
    evaluating the rig; the core's status cannot say which of the numbers
    it read was at fault.  So only after such a failure, one build per
    changed value (where the geometry gives no table: one table per changed
    geometry key, and no rig)."""
    D = _defaults()

    def succeeds(Q: _Merged, run: Mapping[str, Any]) -> bool:
        try:
            build(Q, run)
        except (ValueError, RollerRigError):
            return False
        return True
    found: List[str] = []
    for name in keys:
        section, key = name.split(".")
        v = P[section][key]
        if name in run or v == D[section][key]:
            continue
        Q = {k: dict(s) for k, s in P.items()}
        Q[section][key] = D[section][key]
        if succeeds(Q, run):
            found.append(f"params {name} = {v!r}")
    V = "scenario.roller_speed_m_s"
    if V in names and succeeds(P, {**run, V: D["scenario"]["roller_speed_m_s"]}):
        found.append(f"{names[V]} = {run[V]!r}")
    return found


def build_rig(params: Params = None, *, dt: Optional[float] = None, method: Optional[str] = None,
              substeps: Optional[int] = None, ode: Optional[str] = None,
              nx: Optional[int] = None, ny: Optional[int] = None,
              roller_speed: Optional[float] = None, start: str = "rolling",
              track: Optional[bool] = None,
              **creep: Any) -> Tuple["Rig", Dict[str, Dict[str, Any]], ContactTable]:
    """The rig and the merged parameters, for stepping by hand.

    E.g. rig.sample / rig.advance / rig.rhs, to verify the integrator
    against another solver.

    Parameters
    ----------
    params : None, dict or str or path-like, optional
        None (the defaults), a nested dict overriding rig_default.toml or
        the path of a TOML file doing so; checked by
        :func:`check_parameters` (one RollerRigError listing every
        problem).
    dt : float, optional
        Control sample time [s], 1e-6 to 0.1 where the drives' sampled
        speed loops are stable (as :func:`simulate`; default
        scenario.control_sample_time_s, 4 ms).
    method : str, optional
        The creep-force method, one of :data:`RIG_METHODS`; default the
        parameters' contact section.
    substeps : int, optional
        Plant steps per sample, 1 to 1000; default the integration section.
    ode : {"trbdf2", "ros2", "lineuler"}, optional
        The integrator; default the integration section.
    nx, ny : int, optional
        The FASTSIM grid; default the parameters' contact section.
    roller_speed : float, optional
        Roller surface speed [m/s] of the initial state.
    start : {"rolling", "rest"}, optional
        "rolling": the wheelset rolling freely at roller_speed; "rest".
    track : bool, optional
        True: on tangent track (:func:`simulate`'s track); default
        scenario.track.
    **creep
        The creep-force method's options (:data:`CREEP_OPTIONS`: bound,
        grid, slip_speed, blend_rule, k0, alpha_inf, beta, kA, kS; see
        :func:`rollerrig.creep_forces`); default the parameters' contact
        section.

    Returns
    -------
    rig : Rig
        The rig (:class:`rollerrig.Rig`, over the C rig).
    params : dict
        The merged parameters.
    table : ContactTable
        The contact table (:class:`rollerrig.ContactTable`) of the conical
        wheel on its crowned roller.

    Raises
    ------
    RollerRigError
        A parameter or argument out of range or breaking a rule (every
        problem of the parameters at once), a dt at which a drive's speed
        loop is unstable, an unknown method or option, a start not
        "rolling" or "rest", track not True or False, a geometry that
        gives no contact table, or a rig that cannot start (naming the
        changed values it cannot start with).

    See Also
    --------
    Rig : the methods that step it.
    simulate : the whole scenario.

    Examples
    --------
    One control sample by hand, the rig's own controllers holding the
    roller at the scenario's speed, no creepage target:

    >>> import rollerrig as rr
    >>> rig, params, table = rr.build_rig()
    >>> w = params["scenario"]["roller_speed_m_s"] / params["roller"]["radius_m"]
    >>> rig.sample(w, float("nan")), rig.advance()[1]
    (0, 0)
    >>> print(f"t = {rig.t:.3f} s, status {rig.status}")
    t = 0.004 s, status 0
    """
    P = _with_track("build_rig", _parameters("build_rig", params), track)
    rig, table, *_ = _build("build_rig", P, dt=dt, method=method, substeps=substeps, ode=ode,
                            nx=nx, ny=ny, roller_speed=roller_speed, start=start, creep=creep)
    return rig, P, table


def write_points(params: Params, folder: Union[str, os.PathLike[str]]) -> Dict[str, str]:
    """Write the points the rig's table is built from, for a C program.

    One text file per real profile of `params` (full size, referenced as
    this module says): folder/wheel.txt, roller.txt, wheel_right.txt,
    roller_right.txt, two numbers a line (y z [m], every digit: %.17g),
    "# end natural" where the profile's spline is natural; on
    contact.patch = "nonhertz" its tables too (nonhertz_left.txt,
    nonhertz_right.txt).  For a C program (examples/rig_paper.c).

    Parameters
    ----------
    params : dict or str or path-like
        A nested dict or a scenario file's path, checked.
    folder : str or path-like
        The folder to write into.

    Returns
    -------
    dict
        ``{slot: path}`` of the files written.

    Raises
    ------
    RollerRigError
        Parameters that are not valid.
    """
    P = _parameters("write_points", params)
    points = _real_profiles.profile_points(P)
    out: Dict[str, str] = {}
    for name, s in zip(("wheel", "roller", "wheel_right", "roller_right"),
                       points or (None,) * 4):
        if s is None:
            continue
        path = os.path.join(os.fspath(folder), f"{name}.txt")
        with open(path, "w") as fh:
            fh.write(f"# {name}: y z [m], full size ({'end natural' if s[2] else 'not-a-knot'})\n")
            fh.writelines(f"{y:.17g} {z:.17g}\n" for y, z in zip(s[0], s[1]))
        out[name] = path
    if P["contact"]["patch"] == "nonhertz":
        # the non-Hertzian tables the run takes (built or read), for
        # examples/rig_paper.c's nonhertz_left=, nonhertz_right=
        nh = _nonhertz_rig.table_for(P, _geometry(P))
        for name, side in (("nonhertz_left", nh.side("left")),
                           ("nonhertz_right", nh.side("right"))):
            path = os.path.join(os.fspath(folder), f"{name}.txt")
            with open(path, "w") as fh:
                fh.write(f"# {name}: sigma R0 G nu mu_ref rows, then the rows "
                         f"({side.rows.shape[1]} numbers each; csrc/geometry/rr_nonhertz.h)\n")
                fh.write(" ".join(f"{v:.17g}" for v in side.head) + f" {side.rows.shape[0]}\n")
                for r in side.rows:
                    fh.write(" ".join(f"{v:.17g}" for v in r) + "\n")
            out[name] = path
    return out


def rig_nonhertz_table(params: Params = None,
                       path: Optional[Union[str, os.PathLike[str]]] = None) -> NonHertzTable:
    """The non-Hertzian contact's table of the rig of `params`.

    Built (or read: contact.nonhertz_table) as ``simulate(...,
    contact.patch = "nonhertz")`` would; the contact section's nonhertz_*
    rows set the build.

    Parameters
    ----------
    params : None, dict or str or path-like, optional
        None, a nested dict or a scenario file, as :func:`simulate` takes
        them.
    path : str or path-like, optional
        Where to save the table as .npz (then give it as
        contact.nonhertz_table).

    Returns
    -------
    NonHertzTable
        The table (:class:`rollerrig.NonHertzTable`).

    Raises
    ------
    RollerRigError
        Parameters that are not valid, a path that cannot be written, a
        geometry that gives no table.

    See Also
    --------
    nonhertz_table : the table of any profile pair.
    """
    P = _parameters("rig_nonhertz_table", params)
    if path is not None:
        from .._files import check_output
        check_output(path, what="rig_nonhertz_table: path")
    nh = _nonhertz_rig.table_for(P, _geometry(P))
    if path is not None:
        _nonhertz_rig.save(nh, P, os.fspath(path))
    return nh
