"""The roller rig in time: the seed paper's mechatronic model and scenario.

    import rollerrig as rr
    res = rr.simulate()                           # the paper's scenario, default parameters
    res.time, res.creepage, res.fx                # named numpy arrays, one value per sample
    res = rr.simulate(duration=4.0, dt=0.004, method="polach",
                      params={"scenario": {"mu0": 0.3}}, targets=[0.02])
    res.summary()                                 # per target: creepage reached, settling, ...

The model (csrc/rr_rig.h): a wheelset on two rigidly joined rollers, its
axle boxes on springs and dampers, normal loads from its vertical and roll
balance, contact by rr_rig_contact (FASTSIM with falling friction by
default), roller and wheelset drives with PI speed controllers (eq. 10-11),
torque limiters and first-order lags, encoders (eq. 12) and the creepage
controller (eq. 13-16), sampled every dt; the plant is integrated between
samples by a fixed-step L-stable method.  Default parameters:
rollerrig/data/rig_default.toml, every value with its origin
(docs/parameters.md).
"""
import copy
import functools
import math
import os
import sys
import time
from dataclasses import dataclass

import numpy as np

from . import _core
from ._errors import RollerRigError, status_message
from .contact import _options
from .rig_contact import elastic_constants
from .geometry import RigGeometry, contact_table
from .profiles import Profile

try:
    import tomllib
except ImportError:                                     # Python < 3.11
    import tomli as tomllib

__all__ = ["default_parameters", "load_parameters", "build_rig", "simulate", "replay",
           "RigResult", "RECORD_FIELDS"]

DEFAULTS_PATH = os.path.join(os.path.dirname(__file__), "data", "rig_default.toml")

#: the per-sample record of the C rig (csrc/rr_rig.h, enum rr_rig_record_index)
RECORD_FIELDS = ("time", "creepage", "xi_est", "xi_ref", "roller_speed", "wheelset_speed",
                 "fx", "fy", "normal_load_left", "normal_load_right", "adhesion",
                 "torque_roller", "torque_wheelset", "w_ref", "x", "y", "yaw",
                 "creepage_left", "creepage_right", "torque_ref_roller",
                 "torque_ref_wheelset", "vx", "vy", "yaw_rate", "spin", "roller_spin",
                 "sample_status")

ODE_METHODS = {"ros2": _core.ODE_ROS2, "trbdf2": _core.ODE_TRBDF2,
               "lineuler": _core.ODE_LINEULER}


def load_parameters(path):
    """A parameter file (TOML, the layout of rig_default.toml) as a nested dict."""
    with open(path, "rb") as fh:
        return tomllib.load(fh)


@functools.lru_cache(maxsize=1)
def _defaults():
    return load_parameters(DEFAULTS_PATH)


def default_parameters():
    """The default parameter set (a fresh nested dict: change it freely)."""
    return copy.deepcopy(_defaults())


def _merge(base, over, where=""):
    """Override nested dict `base` by `over`, refusing unknown keys."""
    for key, value in over.items():
        name = f"{where}{key}"
        if key not in base:
            raise RollerRigError(f"params: unknown parameter '{name}'")
        if isinstance(base[key], dict):
            if not isinstance(value, dict):
                raise RollerRigError(f"params: '{name}' is a section; give a dict")
            _merge(base[key], value, name + ".")
        else:
            base[key] = value


def _number(params, section, key, positive=False, nonneg=False):
    v = params[section][key]
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v) \
            or (positive and v <= 0) or (nonneg and v < 0):
        need = " > 0" if positive else " >= 0" if nonneg else ""
        raise RollerRigError(f"params: {section}.{key} must be a finite number{need}, "
                             f"got {v!r}")
    return float(v)


def _flag(P, section, key):
    v = P[section][key]
    if not isinstance(v, bool):
        raise RollerRigError(f"params: {section}.{key} must be true or false, got {v!r}")
    return v


def _newton_iterations(P):
    k = P["integration"]["newton_iterations"]
    if isinstance(k, bool) or not isinstance(k, int) or not 0 <= k <= 10:
        raise RollerRigError(f"params: integration.newton_iterations must be an integer "
                             f"from 0 to 10, got {k!r}")
    return k


def _c_params(P, dt, substeps, ode):
    """The C rig's parameter dict (rollerrig/_core.c, rig_fields) from a nested dict."""
    n = _number
    E = n(P, "contact", "youngs_modulus_Pa", positive=True)
    nu = n(P, "contact", "poisson_ratio", nonneg=True)
    if not nu < 0.5:
        raise RollerRigError(f"params: contact.poisson_ratio must be in [0, 0.5), got {nu!r}")
    law = P["contact"]["friction_law"]
    if law == "coulomb":
        A, B = 1.0, 0.0
    elif law == "polach_falling":
        A, B = n(P, "contact", "polach_A", positive=True), n(P, "contact", "polach_B_s_per_m",
                                                            nonneg=True)
    else:
        raise RollerRigError(f"params: contact.friction_law must be 'coulomb' or "
                             f"'polach_falling', got {law!r}")
    sense = P["scenario"]["drive_mode"]
    if sense not in ("braking", "traction"):
        raise RollerRigError(f"params: scenario.drive_mode must be 'braking' or 'traction', "
                             f"got {sense!r}")
    counts = {}
    for drive in ("roller_drive", "wheelset_drive"):
        c = P[drive]["encoder_counts_per_rev"]
        if isinstance(c, bool) or not isinstance(c, int) or c < 1:
            raise RollerRigError(f"params: {drive}.encoder_counts_per_rev must be an integer "
                                 f">= 1, got {c!r}")
        counts[drive] = c
    return {
        "mass": n(P, "wheelset", "mass_kg", positive=True),
        "Iyy": n(P, "wheelset", "spin_inertia_kg_m2", positive=True)
        + n(P, "wheelset_drive", "drive_inertia_kg_m2", nonneg=True),
        "Izz": n(P, "wheelset", "yaw_inertia_kg_m2", positive=True),
        "axlebox_y": n(P, "wheelset", "axlebox_half_spacing_m", positive=True),
        "kx": n(P, "suspension", "kx_N_per_m", nonneg=True),
        "ky": n(P, "suspension", "ky_N_per_m", nonneg=True),
        "kz": n(P, "suspension", "kz_N_per_m", nonneg=True),
        "cx": n(P, "suspension", "cx_N_s_per_m", nonneg=True),
        "cy": n(P, "suspension", "cy_N_s_per_m", nonneg=True),
        "cz": n(P, "suspension", "cz_N_s_per_m", nonneg=True),
        "preload": n(P, "suspension", "preload_total_N", nonneg=True),
        "g": n(P, "scenario", "g_m_s2", nonneg=True),
        "roller_inertia": n(P, "roller", "inertia_kg_m2", positive=True),
        "R0": n(P, "roller", "radius_m", positive=True),
        **dict(zip(("estar", "G"), elastic_constants(E, nu))), "nu": nu,
        "mu0": n(P, "scenario", "mu0", positive=True), "A": A, "B": B,
        "vmin": n(P, "contact", "min_rolling_speed_m_s", positive=True),
        "T": float(dt), "nsub": int(substeps), "ode_method": ODE_METHODS[ode],
        "newton_iters": _newton_iterations(P),
        "linear_tr": int(_flag(P, "integration", "linear_first_stage")),
        "newton_model": int(_flag(P, "integration", "newton_model")),
        "roller_Kp": n(P, "roller_drive", "kp_N_m_s_per_rad", nonneg=True),
        "roller_KI": n(P, "roller_drive", "ki_N_m_s_per_rad", nonneg=True),
        "roller_Tmax": n(P, "roller_drive", "torque_limit_N_m", positive=True),
        "wheelset_Kp": n(P, "wheelset_drive", "kp_N_m_s_per_rad", nonneg=True),
        "wheelset_KI": n(P, "wheelset_drive", "ki_N_m_s_per_rad", nonneg=True),
        "wheelset_Tmax": n(P, "wheelset_drive", "torque_limit_N_m", positive=True),
        "roller_tau": n(P, "roller_drive", "lag_time_constant_s", positive=True),
        "wheelset_tau": n(P, "wheelset_drive", "lag_time_constant_s", positive=True),
        "roller_counts": counts["roller_drive"], "wheelset_counts": counts["wheelset_drive"],
        "r_w": n(P, "wheelset", "wheel_radius_m", positive=True),
        "r_r": n(P, "roller", "radius_m", positive=True),
        "ctl_alpha": n(P, "creepage_controller", "alpha", nonneg=True),
        "ctl_beta": n(P, "creepage_controller", "beta", nonneg=True),
        "ctl_vmin": n(P, "creepage_controller", "min_reference_speed_m_s", positive=True),
        "sense": -1 if sense == "braking" else 1,
    }


def _geometry(P):
    """The conical wheel on the crowned roller (the paper's first stage) and its table."""
    if P["wheelset"]["profile"] != "conical" or P["roller"]["profile"] != "crowned cylinder":
        raise RollerRigError("params: the rig model takes wheelset.profile = 'conical' and "
                             "roller.profile = 'crowned cylinder'")
    r0 = _number(P, "wheelset", "wheel_radius_m", positive=True)
    R0 = _number(P, "roller", "radius_m", positive=True)
    hw = _number(P, "wheelset", "profile_half_width_m", positive=True)
    alpha = math.atan(_number(P, "wheelset", "conicity", nonneg=True))
    crown = _number(P, "roller", "crown_radius_m", positive=True)
    span = _number(P, "wheelset", "contact_half_spacing_m", positive=True)
    reach = _number(P, "integration", "table_half_range_m", positive=True)
    rows = P["integration"]["table_rows"]
    return _rig_table(r0, R0, hw, alpha, crown, span, reach, int(rows))


# The table is a pure function of these numbers and read-only, so runs on the
# same geometry (a sweep over controller or friction settings, a notebook
# re-running a cell) share one build instead of repeating its ~50 ms.
@functools.lru_cache(maxsize=8)
def _rig_table(r0, R0, hw, alpha, crown, span, reach, rows):
    g = RigGeometry(wheel=Profile.conical(alpha, (-hw, hw), r0=r0, n=121),
                    roller=Profile.cylinder((-hw, hw), crown_radius=crown, n=121),
                    wheel_radius=r0, roller_radius=R0, wheel_y=span, roller_y=span)
    return contact_table(g, -reach, reach, rows)


def _creep_options(func, P, method, nx, ny, creep):
    """The creep-force method and its options: the parameters' contact
    section, overridden by the caller's (method, nx, ny, and `creep`:
    bound, grid, slip_speed, k0, alpha_inf, beta, kA, kS)."""
    C = P["contact"]
    opts = dict(method=method if method is not None else C["creep_method"],
                nx=nx if nx is not None else C["fastsim_nx"],
                ny=ny if ny is not None else C["fastsim_ny"], bound="parabolic", grid="rect",
                slip_speed=C["fastsim_slip_speed"], k0=0.54, alpha_inf=0.02, beta=0.62,
                kA=C["polach_kA"], kS=C["polach_kS"])
    unknown = set(creep) - set(opts)
    if unknown:
        raise RollerRigError(f"{func}: unknown option(s) {sorted(unknown)}")
    opts.update(creep)
    return opts


def schedule(P, duration, dt, targets, target_times, roller_speed):
    """The references of each sample: roller speed [rad/s] and creepage
    target (NaN before the first target's start)."""
    n = int(round(duration / dt))
    idx = np.searchsorted(np.asarray(target_times), np.arange(n) * dt, side="right") - 1
    xi_ref = np.where(idx >= 0, np.asarray(targets, dtype=float)[np.clip(idx, 0, None)],
                      np.nan)
    return np.full(n, roller_speed / P["roller"]["radius_m"]), xi_ref


def build_rig(params=None, *, dt=None, method=None, substeps=None, ode=None, nx=None, ny=None,
              roller_speed=None, start="rolling", **creep):
    """The C rig (rollerrig._core.Rig) and the merged parameters, for
    stepping by hand (rig.sample / rig.advance / rig.rhs, e.g. to verify the
    integrator against another solver).  Returns (rig, params, table)."""
    P = default_parameters()
    if params:
        _merge(P, params)
    S, I = P["scenario"], P["integration"]
    dt = _check_dt(dt if dt is not None else S["control_sample_time_s"])
    substeps = substeps if substeps is not None else I["substeps"]
    if isinstance(substeps, bool) or not isinstance(substeps, int) or not 1 <= substeps <= 1000:
        raise RollerRigError(f"simulate: substeps must be an integer from 1 to 1000, "
                             f"got {substeps!r}")
    ode = ode if ode is not None else I["method"]
    if ode not in ODE_METHODS:
        raise RollerRigError(f"simulate: ode must be one of {sorted(ODE_METHODS)}, got {ode!r}")
    opts = _options("simulate", **_creep_options("simulate", P, method, nx, ny, creep))
    V = roller_speed if roller_speed is not None else S["roller_speed_m_s"]
    if not (isinstance(V, (int, float)) and math.isfinite(V)):
        raise RollerRigError(f"simulate: roller_speed must be a finite number, got {V!r}")
    if start not in ("rolling", "rest"):
        raise RollerRigError(f"simulate: start must be 'rolling' or 'rest', got {start!r}")
    table = _geometry(P)
    cp = _c_params(P, dt, substeps, ode)
    # eq. 15-16 with the rolling radii of the centred wheelset, as a rig is
    # calibrated: the profiles' nominal radii would bias the creepage by
    # (r - r0)/r0 + (R0 - R)/R0, about 0.2 % of creepage here
    centre = table.lookup(0.0)
    cp["r_w"], cp["r_r"] = float(centre.left.r[0]), float(centre.left.R[0])
    try:
        rig = _core.Rig(table.data, table.y0, table.dy, cp, opts,
                        V / cp["R0"] if start == "rolling" else 0.0)
    except ValueError as e:
        raise RollerRigError(f"simulate: {e}") from None
    return rig, P, table


def _check_dt(dt):
    if isinstance(dt, bool) or not isinstance(dt, (int, float)) or not math.isfinite(dt) \
            or not 1e-6 <= dt <= 0.1:
        raise RollerRigError(f"simulate: dt must be a step from 1e-6 to 0.1 s, got {dt!r}")
    return float(dt)


@dataclass
class RigResult:
    """Time histories of a rig run, one value per control sample (named
    numpy arrays; see RECORD_FIELDS), with the schedule and parameters."""

    records: np.ndarray
    params: dict
    targets: tuple
    target_times: tuple
    dt: float
    status: int
    message: str
    #: wall-clock seconds: "setup" (parameters, contact table: a one-off,
    #: as the paper's offline database) and "run" (the stepping loop)
    wall: dict = None

    def __getattr__(self, name):
        if name in RECORD_FIELDS:
            col = self.records[:, RECORD_FIELDS.index(name)]
            return col.astype(np.int8) if name == "sample_status" else col
        raise AttributeError(name)

    @property
    def normal_load(self):
        """Sum of both wheels' normal loads [N]."""
        return self.normal_load_left + self.normal_load_right

    def __len__(self):
        return self.records.shape[0]

    def to_dataframe(self):
        """The histories as a pandas DataFrame (pandas must be installed)."""
        import pandas as pd
        return pd.DataFrame({name: getattr(self, name) for name in RECORD_FIELDS})

    def summary(self, tol=0.05, window=0.25):
        """Per target: the creepage held (mean over the last 80 % of its
        interval), settling time (when the creepage's running mean over
        `window` seconds first comes within tol of the target; eq. 14's
        recovery steps then make a small sawtooth about it), the adhesion
        coefficient held, and the peak |fx| / (mu0 N) over the interval."""
        mu0 = self.params["scenario"]["mu0"]
        rows = []
        t = self.time
        ends = list(self.target_times[1:]) + [np.inf]
        k = max(1, int(round(window / self.dt)))
        for xi, t0, t1 in zip(self.targets, self.target_times, ends):
            sel = (t > t0) & (t <= t1) & np.isfinite(self.creepage)
            if np.count_nonzero(sel) < k:
                rows.append(dict(target=xi, reached=np.nan, settling_s=np.nan,
                                 adhesion=np.nan, peak_force_over_muN=np.nan))
                continue
            ts, cr = t[sel], self.creepage[sel]
            held = ts >= ts[0] + 0.2 * (ts[-1] - ts[0])
            mean = np.convolve(cr, np.ones(k) / k, mode="valid")   # ends at ts[k-1:]
            inside = np.flatnonzero(np.abs(mean - xi) <= tol * abs(xi))
            settle = ts[k - 1 + inside[0]] - t0 if inside.size else np.nan
            peak = np.max(np.abs(self.fx[sel]) / (mu0 * self.normal_load[sel]))
            rows.append(dict(target=xi, reached=float(np.mean(cr[held])),
                             settling_s=float(settle),
                             adhesion=float(np.mean(self.adhesion[sel][held])),
                             peak_force_over_muN=float(peak)))
        return rows

    def table(self, tol=0.05):
        """summary() as aligned text."""
        lines = [f"{'target':>8} {'reached':>9} {'settling s':>10} {'adhesion':>9} "
                 f"{'peak F/muN':>10}"]
        for r in self.summary(tol):
            lines.append(f"{r['target']:8.3f} {r['reached']:9.5f} {r['settling_s']:10.3f} "
                         f"{r['adhesion']:9.4f} {r['peak_force_over_muN']:10.4f}")
        return "\n".join(lines)


def simulate(duration=None, dt=None, method=None, params=None, targets=None,
             target_times=None, *, roller_speed=None, start="rolling", nx=None, ny=None,
             substeps=None, ode=None, progress=False, **creep):
    """Run the rig: by default the seed paper's scenario on the default parameters.

    duration:  simulated time [s] (default scenario.duration_s)
    dt:        control sample time and integration step [s] (default
               scenario.control_sample_time_s, the paper's 4 ms)
    method:    creep-force method ("fastsim", "fastsim_blended",
               "modified_fastsim", "polach", "linear"); nx, ny the FASTSIM grid
    params:    nested dict overriding rig_default.toml, e.g.
               {"scenario": {"mu0": 0.3}, "wheelset": {"mass_kg": 15.0}}
    targets:   creepage targets in sequence (default the paper's 0.04, 0.015,
               0.02, 0.03); target_times their start times [s] (default:
               equal intervals over the duration)
    roller_speed: roller surface speed [m/s] held by its controller
    start:     "rolling" (wheelset rolling freely at roller_speed) or "rest"
               (everything at standstill; the roller drive spins the rig up)
    substeps, ode: plant steps per sample and the integrator ("ros2",
               "trbdf2", "lineuler")
    progress:  print a progress bar on stderr
    Returns RigResult.  A run that fails (a wheel off its roller, lift-off,
    NaN) stops cleanly: the result holds the history so far, its status
    and message say why.
    """
    t0 = time.perf_counter()
    rig, P, _ = build_rig(params, dt=dt, method=method, substeps=substeps, ode=ode, nx=nx,
                          ny=ny, roller_speed=roller_speed, start=start, **creep)
    S = P["scenario"]
    dt = _check_dt(dt if dt is not None else S["control_sample_time_s"])
    duration = duration if duration is not None else S["duration_s"]
    if isinstance(duration, bool) or not isinstance(duration, (int, float)) \
            or not math.isfinite(duration) or not 0 < duration <= 1e5:
        raise RollerRigError(f"simulate: duration must be in (0, 1e5] s, got {duration!r}")
    targets = tuple(float(x) for x in (targets if targets is not None else S["targets"]))
    if not targets or not all(math.isfinite(x) and 0 <= x < 1 for x in targets):
        raise RollerRigError(f"simulate: targets must be creepages in [0, 1), got {targets!r}")
    if target_times is None:
        if targets == tuple(S["targets"]) and duration == S["duration_s"]:
            target_times = S["target_start_s"]
        else:
            target_times = [duration * k / len(targets) for k in range(len(targets))]
    target_times = tuple(float(x) for x in target_times)
    if len(target_times) != len(targets) or any(b <= a for a, b in
                                                zip(target_times, target_times[1:])):
        raise RollerRigError(f"simulate: target_times must be increasing, one per target, "
                             f"got {target_times!r}")
    V = roller_speed if roller_speed is not None else S["roller_speed_m_s"]
    roller_ref, xi_ref = schedule(P, duration, dt, targets, target_times, V)
    n = xi_ref.size
    out = np.full((n, len(RECORD_FIELDS)), np.nan)
    chunk = max(1, n // 50)
    status = 0
    t1 = time.perf_counter()
    for start in range(0, n, chunk):
        stop = min(n, start + chunk)
        rec, status = rig.run(roller_ref[start:stop], xi_ref[start:stop])
        out[start:stop] = rec
        if progress:
            done = stop / n
            sys.stderr.write(f"\rsimulate [{'#' * int(40 * done):<40}] {100 * done:5.1f} %")
            sys.stderr.flush()
        if status < 0:
            good = np.isfinite(rec[:, 0]) & (rec[:, -1] >= 0)
            out = out[:start + int(np.count_nonzero(good))]
            break
    wall = {"setup": t1 - t0, "run": time.perf_counter() - t1}
    if progress:
        sys.stderr.write("\n")
    message = "ok" if status >= 0 else f"stopped at t = {rig.t:.4f} s: {status_message(status)}"
    return RigResult(out, P, targets, target_times, dt, int(status), message, wall)


def replay(res, *, method=None, nx=None, ny=None, **creep):
    """The seed paper's Fig. 9 procedure: the kinematics recorded in a run
    (a RigResult, e.g. an offline high-accuracy run kept as a database) fed
    sample by sample through a contact model (the real-time one by default:
    the parameters' method and grid) with the recorded normal loads.
    Returns rollerrig.RigContact for every sample; compare its
    left.fx + right.fx with res.fx."""
    from .rig_contact import rig_contact
    from .contact import FallingFriction

    P = res.params
    C = P["contact"]
    friction = (FallingFriction(A=C["polach_A"], B=C["polach_B_s_per_m"])
                if C["friction_law"] == "polach_falling" else None)
    opts = _creep_options("replay", P, method, nx, ny, creep)
    return rig_contact(_geometry(P), x=res.x, y=res.y, yaw=res.yaw, vx=res.vx, vy=res.vy,
                       yaw_rate=res.yaw_rate, spin=res.spin, roller_spin=res.roller_spin,
                       N_left=res.normal_load_left, N_right=res.normal_load_right,
                       mu=P["scenario"]["mu0"], friction=friction,
                       E=C["youngs_modulus_Pa"], nu=C["poisson_ratio"],
                       vmin=C["min_rolling_speed_m_s"], **opts)
