"""The C rig from checked parameters: its contact table, the creep-force
method and options, the drives' sampled speed loops, Rig (the C rig stepped
by hand) and build_rig."""
import functools
import math
import numbers

import numpy as np

from .. import _core
from . import control as _control
from .._errors import RollerRigError, status_message
from .._binding import METHODS, _as_float, check_creep_options, core, loop_method, rig_method
from ..geometry.profiles import Profile
from ..geometry.wheelset import MAX_ROWS, ContactTable, RigGeometry
from .params import (_FILE_OPTIONS, MAX_DT, MIN_DT, ODE_METHODS, PARAMETERS, _check_dt,
                     _defaults, _integer, _parameters, _real_arg, _short)


#: the creep-force methods the rig steps with (the registry's in_rig: not
#: iterative, and |F| <= mu N; csrc/rig/rr_rig.h, rr_rig_method_check)
RIG_METHODS = tuple(name for name, m in METHODS.items() if m.in_rig)


def _c_params(P, dt, substeps, ode):
    """The C rig's primary values {"section.key": value} (csrc/rig/rr_rig_params.h,
    rr_rig_config) of checked parameters, with the call's sample time,
    substeps and integrator; the C side derives the rig's parameters."""
    cp = {p.name: P[p.name.split(".")[0]][p.name.split(".")[1]]
          for p in PARAMETERS if not p.creep}
    cp["scenario.control_sample_time_s"] = float(dt)
    cp["integration.substeps"] = int(substeps)
    cp["integration.method"] = ode
    return cp


#: the parameters that make the rig's profiles and contact table
GEOMETRY_KEYS = ("wheelset.wheel_radius_m", "roller.radius_m", "wheelset.profile_half_width_m",
                 "wheelset.conicity", "roller.crown_radius_m", "wheelset.contact_half_spacing_m",
                 "integration.table_half_range_m", "integration.table_rows")


def _geometry(P):
    """The conical wheel on the crowned roller (the paper's first stage) and
    its table; a geometry that yields none is the parameters' fault, and the
    message says which ones made it."""
    W, R, I = P["wheelset"], P["roller"], P["integration"]
    try:
        return _rig_table(float(W["wheel_radius_m"]), float(R["radius_m"]),
                          float(W["profile_half_width_m"]), math.atan(float(W["conicity"])),
                          float(R["crown_radius_m"]), float(W["contact_half_spacing_m"]),
                          float(I["table_half_range_m"]), int(I["table_rows"]))
    except RollerRigError as e:
        values = ", ".join(f"{k} = {P[k.split('.')[0]][k.split('.')[1]]!r}"
                           for k in GEOMETRY_KEYS)
        raise RollerRigError(f"params: the rig's geometry ({values}) gives no contact "
                             f"table: {e}") from None


# The table is a pure function of these numbers and read-only, so runs on the
# same geometry (a sweep over controller or friction settings, a notebook
# re-running a cell) share one build instead of repeating its ~50 ms.
# The rows come from the C core's rr_rig_table_build (csrc/geometry/rr_tables.h),
# so a C program building the rig's table has this one, bit for bit; the
# profiles made here (the same points and spline, by the same C) are the
# table's geometry and check the numbers with messages that name them.
@functools.lru_cache(maxsize=8)
def _rig_table(r0, R0, hw, alpha, crown, span, reach, rows):
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


def _creep_options(func, P, method, nx, ny, creep, in_rig=True):
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


class Rig:
    """The rig stepped by hand (build_rig): the C rig of csrc/rig/rr_rig.h, its
    arguments checked here (RollerRigError naming them).

    sample(roller_ref, xi_ref) -> status: the sampling instant (encoders,
        creepage controller, PI controllers); roller_ref the roller speed
        reference [rad/s], xi_ref the creepage target (NaN: no creepage
        control, the wheelset held at free rolling); the same as
    read() -> (signals, status): the sampling instant's measurement (the
        fields of rollerrig.rig.control.RigSignals from t to xi_est), then
    write(roller_mode, roller_ref, wheelset_mode, wheelset_ref, mu0=nan)
        -> status: the references held over the sample; modes
        _core.CMD_BUILTIN (the rig's controllers: roller speed, creepage
        target), CMD_SPEED [rad/s], CMD_TORQUE [N m]; mu0 the friction
        coefficient over the sample (NaN: the adhesion section's);
        csrc/rig/rr_rig.h, rr_rig_read, rr_rig_write
    info: the controllers' settings (rollerrig.rig.control.RigInfo)
    advance() -> (record, status): the plant over one sample
    run(roller_ref, xi_ref, out=None) -> (records, status): one sample per
        element of the two 1-D arrays, records of shape (n,
        len(RECORD_FIELDS)) (written into `out` if given: a writable
        C-contiguous float64 array of that shape); stops at the first error
        (the rest NaN); status the worst of the run
    record() -> (record, status); rhs(t, y) -> (dydt, status); jac(t, y)
        -> (J, status); set_state(t, y) -> status: the plant's right-hand
        side, its approximate Jacobian and its state y (RIG_STATE, 12 values)
    t [s], y, status: the rig's time, state (a copy) and last status
    Statuses: 0 ok, 1 a warning, < 0 an error (rollerrig.STATUS); after an
    error the rig keeps its last good state and refuses to step on.  One
    thread at a time: a second thread gets RuntimeError.
    """

    __slots__ = ("_core",)

    def __init__(self, core):
        self._core = core

    def __repr__(self):
        return f"Rig(t = {self.t:g} s, status {self.status})"

    @staticmethod
    def _scalar(func, name, v):
        """A real number (NaN and infinities pass: the C rig answers them
        with a status, as it does for a NaN state)."""
        if isinstance(v, numbers.Real) and not isinstance(v, bool):
            try:
                return float(v)
            except OverflowError:                      # an int beyond a double
                pass
        raise RollerRigError(f"{func}: {name} must be a real number, got {_short(v)}")

    @staticmethod
    def _array(func, name, v, n=None):
        a = _as_float(func, name, v) if not (np.ndim(v) == 1 and np.size(v) == 0) \
            else np.zeros(0)
        if a.ndim != 1 or (n is not None and a.size != n):
            want = f"{n} values" if n is not None else "a 1-D array"
            raise RollerRigError(f"{func}: {name} must be {want}, got shape {a.shape}")
        return np.ascontiguousarray(a)

    def run(self, roller_ref, xi_ref, out=None):
        r = self._array("Rig.run", "roller_ref", roller_ref)
        x = self._array("Rig.run", "xi_ref", xi_ref, r.size)
        return self._core.run(r, x) if out is None else self._core.run(r, x, out)

    def sample(self, roller_ref, xi_ref):
        return self._core.sample(self._scalar("Rig.sample", "roller_ref", roller_ref),
                                 self._scalar("Rig.sample", "xi_ref", xi_ref))

    def read(self):
        return self._core.read()

    def write(self, roller_mode, roller_ref, wheelset_mode, wheelset_ref, mu0=math.nan):
        modes = (_core.CMD_BUILTIN, _core.CMD_SPEED, _core.CMD_TORQUE)
        for name, mode in (("roller_mode", roller_mode), ("wheelset_mode", wheelset_mode)):
            if mode not in modes or isinstance(mode, bool):
                raise RollerRigError(f"Rig.write: {name} must be one of {modes} (builtin, "
                                     f"speed, torque), got {_short(mode)}")
        return self._core.write(int(roller_mode), self._scalar("Rig.write", "roller_ref",
                                                               roller_ref),
                                int(wheelset_mode), self._scalar("Rig.write", "wheelset_ref",
                                                                 wheelset_ref),
                                self._scalar("Rig.write", "mu0", mu0))

    def advance(self):
        return self._core.advance()

    def record(self):
        return self._core.record()

    def _t_y(self, func, t, y):
        return (self._scalar(func, "t", t),
                self._array(func, "y", y, _core.RIG_NSTATE))

    def rhs(self, t, y):
        return self._core.rhs(*self._t_y("Rig.rhs", t, y))

    def jac(self, t, y):
        return self._core.jac(*self._t_y("Rig.jac", t, y))

    def set_state(self, t, y):
        return self._core.set_state(*self._t_y("Rig.set_state", t, y))

    @property
    def t(self):
        return self._core.t

    @property
    def y(self):
        return self._core.y

    @property
    def status(self):
        return self._core.status

    @property
    def info(self):
        return _control.rig_info(self._core.info)


def _build(func, P, *, dt, method, substeps, ode, nx, ny, roller_speed, start, creep,
           given_dt=None):
    """(the C rig, dt, roller speed [m/s], creep options) of checked parameters P;
    given_dt: whether the caller gave dt (default: dt not None), for messages."""
    S, I = P["scenario"], P["integration"]
    given_dt = dt is not None if given_dt is None else given_dt
    dt = _check_dt(func, dt if dt is not None else S["control_sample_time_s"])
    substeps = substeps if substeps is not None else I["substeps"]
    if _integer(1, 1000)(substeps):
        raise RollerRigError(f"{func}: substeps must be an integer from 1 to 1000, "
                             f"got {substeps!r}")
    ode = ode if ode is not None else I["method"]
    if ode not in ODE_METHODS:
        raise RollerRigError(f"{func}: ode must be one of {sorted(ODE_METHODS)}, got {ode!r}")
    _check_loops(func, P, _c_params(P, dt, int(substeps), ode),
                 "dt" if given_dt else "scenario.control_sample_time_s")
    opts = _creep_options(func, P, method, nx, ny, creep)
    c_opts = opts
    V = _real_arg(func, "roller_speed", roller_speed if roller_speed is not None
                  else S["roller_speed_m_s"], unit="m/s")
    if start not in ("rolling", "rest"):
        raise RollerRigError(f"{func}: start must be 'rolling' or 'rest', got {start!r}")

    def make(P, V):
        V = P["scenario"]["roller_speed_m_s"] if V is None else V
        table = _geometry(P)
        cp = _c_params(P, dt, int(substeps), ode)
        # the C side (rr_rig_params_set_table) takes eq. 15-16's radii at the
        # centred wheelset's rolling radii, as a rig is calibrated: the
        # profiles' nominal radii would bias the creepage by
        # (r - r0)/r0 + (R0 - R)/R0, about 0.2 % of creepage here
        return table, core(_core.Rig, table.data, table.y0, table.dy, cp, c_opts,
                           V / float(P["roller"]["radius_m"]) if start == "rolling"
                           else 0.0)
    given_V = None if roller_speed is None else V      # None: the scenario's own
    try:
        table, rig = make(P, given_V)
    except (ValueError, RollerRigError) as e:
        culprits = _culprits(P, given_V, make)
        named = f"the rig cannot start with {', '.join(culprits)}: " if culprits else ""
        raise RollerRigError(f"{func}: {named}{e}") from None
    return Rig(rig), table, dt, V, opts["method"]


def _check_loops(func, P, cp, name):
    """Refuse a sample time at which a drive's sampled speed loop is
    unstable (csrc/rig/rr_rig.h, rr_rig_speed_loops; the C rig refuses it
    too): the message names the drive, the settings its loop depends on and
    the sample times at which it is stable (rr_speed_loop_range)."""
    R, W = P["roller_drive"], P["wheelset_drive"]
    settings = (
        f"roller_drive.kp_N_m_s_per_rad = {R['kp_N_m_s_per_rad']:g}, ki_N_m_s_per_rad = "
        f"{R['ki_N_m_s_per_rad']:g} and lag_time_constant_s = {R['lag_time_constant_s']:g} on "
        f"roller.inertia_kg_m2 = {P['roller']['inertia_kg_m2']:g}",
        f"wheelset_drive.kp_N_m_s_per_rad = {W['kp_N_m_s_per_rad']:g}, ki_N_m_s_per_rad = "
        f"{W['ki_N_m_s_per_rad']:g} and lag_time_constant_s = {W['lag_time_constant_s']:g} on "
        f"wheelset.spin_inertia_kg_m2 + wheelset_drive.drive_inertia_kg_m2 = "
        f"{P['wheelset']['spin_inertia_kg_m2'] + W['drive_inertia_kg_m2']:g}, within eq. 13's "
        f"creepage_controller.alpha = {P['creepage_controller']['alpha']:g}")
    dt = cp["scenario.control_sample_time_s"]
    for drive, text, (stable, rho, lo, hi) in zip(("roller", "wheelset"), settings,
                                                  core(_core.rig_speed_loops, cp)):
        if stable:
            continue
        where = (f"it is stable for sample times from {lo:.3g} to {hi:.3g} s"
                 if not math.isnan(lo) else
                 f"it is stable at no sample time from {MIN_DT:g} to {MAX_DT:g} s")
        raise RollerRigError(
            f"{func}: {name} = {dt:g} s: the {drive} drive's sampled speed loop ({text}) is "
            f"unstable at this sample time (its largest closed-loop pole |z| = {rho:.4g}); "
            f"{where}")


def _culprits(P, given_V, make):
    """The changed values the rig cannot start with: each parameter that
    differs from its default, and a given roller speed, is put back to its
    default alone; those whose default lets the rig start are named (the
    core's status cannot say which of 44 numbers overflowed)."""
    D = _defaults()

    def starts(Q, V):
        try:
            make(Q, V)
        except (ValueError, RollerRigError):
            return False
        return True
    found = []
    for section, values in P.items():
        for key, v in values.items():
            if v == D[section][key]:
                continue
            Q = {k: dict(s) for k, s in P.items()}
            Q[section][key] = D[section][key]
            if starts(Q, given_V):
                found.append(f"params {section}.{key} = {v!r}")
    if given_V is not None and starts(P, D["scenario"]["roller_speed_m_s"]):
        found.append(f"roller_speed = {given_V!r}")
    return found


def build_rig(params=None, *, dt=None, method=None, substeps=None, ode=None, nx=None, ny=None,
              roller_speed=None, start="rolling", **creep):
    """The rig (rollerrig.Rig, over the C rig) and the merged parameters,
    for stepping by hand (rig.sample / rig.advance / rig.rhs, e.g. to verify
    the integrator against another solver).  Returns (rig, params, table).

    params:  None (the defaults), a nested dict overriding rig_default.toml
             or the path of a TOML file doing so; checked by
             check_parameters (one RollerRigError listing every problem)
    dt:      control sample time [s], 1e-6 to 0.1 where the drives'
             sampled speed loops are stable (as simulate; default
             scenario.control_sample_time_s, 4 ms)
    method, nx, ny, **creep: the creep-force method, its FASTSIM grid and
             options (CREEP_OPTIONS: bound, grid, slip_speed, blend_rule, k0,
             alpha_inf, beta, kA, kS; see rollerrig.creep_forces); default
             the parameters' contact section
    substeps, ode: plant steps per sample (1 to 1000) and the integrator
             ("trbdf2", "ros2", "lineuler"); default the integration section
    roller_speed: roller surface speed [m/s] of the initial state
    start:   "rolling" (the wheelset rolling freely at roller_speed) or
             "rest"
    table:   the contact table (rollerrig.ContactTable) of the conical wheel
             on its crowned roller
    """
    P = _parameters("build_rig", params)
    rig, table, *_ = _build("build_rig", P, dt=dt, method=method, substeps=substeps, ode=ode,
                            nx=nx, ny=ny, roller_speed=roller_speed, start=start, creep=creep)
    return rig, P, table
