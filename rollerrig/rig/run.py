"""The roller rig in time: the seed paper's mechatronic model and scenario.

::

    import rollerrig as rr
    res = rr.simulate()                           # the paper's scenario, default parameters
    res.time, res.creepage, res.fx                # named numpy arrays, one value per sample
    res = rr.simulate(duration=4.0, dt=0.004, method="polach",
                      params={"scenario": {"mu0": 0.3}}, targets=[0.02])
    res = rr.simulate(params="my.toml")           # a parameter file: any subset of the defaults
    res = rr.simulate(controller=my_controller)   # a controller of one's own in the loop
    res = rr.simulate(params={"adhesion": {"schedule_times_s": [5, 6],
                                           "schedule_mu0": [0.4, 0.1]}})   # mu in time
    res.summary()                                 # per target: creepage reached, settling, ...
    res.to_xarray(), res.to_dataframe()           # with xarray / pandas (extra "sweep")

The model (csrc/rig/rr_rig.h): a wheelset on two rigidly joined rollers, its
axle boxes on springs and dampers, normal loads from its vertical and roll
balance, contact by rr_rig_contact (FASTSIM with falling friction by
default), roller and wheelset drives with PI speed controllers (eq. 10-11),
torque limiters and first-order lags, encoders (eq. 12) and the creepage
controller (eq. 13-16), sampled every dt; the plant is integrated between
samples by a fixed-step L-stable method.  Default parameters:
rollerrig/data/rig_default.toml, every value with its origin
(docs/parameters.md).

simulate runs it (the rig's own controllers, or a controller of the
caller's: rollerrig.rig.control), sample by sample through the C loop; replay
feeds a run's kinematics through a contact model (the paper's Fig. 9).
"""
from __future__ import annotations

import math
import time
import warnings
from typing import (TYPE_CHECKING, Any, Callable, Dict, Iterable, Mapping, NoReturn, Optional,
                    Sequence, Tuple, cast)

import numpy as np
import numpy.typing as npt

from .. import _core, _progress
from .._typing import Controller, F64Array, Params
from . import control as _control
from .._errors import RollerRigError, RollerRigWarning, status_message
from .build import _build, _creep_options, _geometry
from .params import _SAMPLE_TIME, _check_run, _integer, _parameters, _real_arg, _short
from .params import _with_track
from .result import RECORD_FIELDS, RigResult, scenario_record

if TYPE_CHECKING:
    from .build import Rig
    from .contact import RigContact, WheelContact

#: checked parameters {section: {key: value}}
_Params = Mapping[str, Mapping[str, Any]]
#: (records kept, samples stepped, the run's status, the worst sample status,
#: samples warned): a run's stepping (_run_builtin, _run_controlled)
_Stepped = Tuple[F64Array, int, int, int, int]
#: simulate's RigResult of (records, status, message, samples stepped)
_Result = Callable[[F64Array, int, str, int], RigResult]


#: the default cap on the memory of a run's records [bytes]: 1 GiB, about
#: 4.6 million samples (5.1 hours at the 4 ms sample); simulate refuses a run
#: whose records would not fit and says which record_every would
RECORD_BYTES_CAP = 1 << 30
_BYTES_PER_SAMPLE = 8 * len(RECORD_FIELDS)
# samples stepped per call into the C loop: bounds the temporary records
# (14 MB) whatever the run's length and decimation
_CHUNK_SAMPLES = 1 << 16
#: a run whose samples did not converge more often than UNTRUSTED_SHARE of
#: them, and in at least UNTRUSTED_MIN samples, ends with status ERR_UNTRUSTED
#: (-19): the integrator fails again and again, its results cannot be
#: trusted.  Measured against the same runs converged (20 substeps, 3 Newton
#: iterations): the paper's scenario at 8 ms (208 of 2500 samples not
#: converged) misses its creepage by 40 % rms, mu0 stepped from 0.1 to 0.8
#: (24 of 100) by 89 %, a start from rest at 2 m/s (45 of 150) by 124 %;
#: the paper's at 4 ms (none) by 1.2 %.  A transient (a braking onset, a
#: step of the adhesion) leaves a few such samples, a warning (status 1):
#: in the tests' short runs 1 to 6 (up to 1 in 15)
UNTRUSTED_SHARE = 0.05
UNTRUSTED_MIN = 20


def schedule(P: _Params, duration: float, dt: float, targets: Iterable[float],
             target_times: Iterable[float], roller_speed: float, first: int = 0,
             stop: Optional[int] = None) -> Tuple[F64Array, F64Array]:
    """The references of samples first <= k < stop.

    Sample k starts at k dt.  The rule is the C side's (rr_rig_schedule),
    which a C program of the rig follows too.

    Parameters
    ----------
    P : dict
        Checked parameters (nested dict).
    duration : float
        Simulated time [s].
    dt : float
        Control sample time [s].
    targets, target_times : sequence of float
        Creepage targets [-] and their start times [s].
    roller_speed : float
        Roller surface speed [m/s].
    first : int, optional
        The first sample.
    stop : int, optional
        One past the last sample (default: all of the duration).

    Returns
    -------
    roller_ref : numpy.ndarray
        Roller speed reference per sample [rad/s].
    xi_ref : numpy.ndarray
        Creepage target per sample [-] (NaN before the first target's
        start).
    """
    n = int(round(duration / dt))
    stop = n if stop is None else min(stop, n)
    return _core.rig_schedule(float(roller_speed), float(P["roller"]["radius_m"]),
                              [float(x) for x in targets], [float(t) for t in target_times],
                              float(dt), int(first), max(int(stop), int(first)))


# ------------------------------------------------------------------ simulate

_TARGETS, _STARTS, _DURATION = "scenario.targets", "scenario.target_start_s", "scenario.duration_s"


def _as_list(v: Any) -> Any:
    """A 1-D array as the list the C report takes (anything else as given:
    the report names what it is not)."""
    return v.tolist() if isinstance(v, np.ndarray) and v.ndim == 1 else v


def _target_schedule(P: _Params, duration: float, dt: float, targets: Any, target_times: Any,
                     names: Mapping[str, str]) -> Tuple[Tuple[float, ...], Tuple[float, ...]]:
    """(targets, start times) of a run: the scenario's (scaled to the
    duration where they do not fit it, with a warning), or the caller's
    (equal intervals of the duration where target_times is None); checked
    with the duration by the C report's rules (one start time per target,
    increasing, inside the duration).  names: the arguments' names of
    _check_run, more given here."""
    S = P["scenario"]
    names = dict(names, **{_STARTS: "target_times"} if target_times is not None else {})
    if targets is None:
        targets = S["targets"]
        if target_times is None:
            starts = [float(x) for x in S["target_start_s"]]
            target_times = starts
            if starts[-1] >= duration:
                scale = duration / float(S["duration_s"])
                target_times = [x * scale for x in starts]
                warnings.warn(
                    f"simulate: the scenario's target start times {starts} s "
                    f"(scenario.target_start_s, for scenario.duration_s = "
                    f"{S['duration_s']:g} s) do not all fall inside duration = "
                    f"{duration:g} s: scaled by {scale:g} to "
                    f"{[float(f'{x:.6g}') for x in target_times]} s", RollerRigWarning,
                    stacklevel=3)
    else:
        targets = _as_list(targets)
        names[_TARGETS] = "targets"
        if target_times is None and isinstance(targets, (list, tuple)):
            target_times = [duration * k / len(targets) for k in range(len(targets))]
    run = {_SAMPLE_TIME: dt, _DURATION: duration, _TARGETS: targets}
    if target_times is not None:
        run[_STARTS] = _as_list(target_times)
    _check_run("simulate", P, run, names, about=(_TARGETS, _STARTS, _DURATION))
    return tuple(float(x) for x in targets), tuple(float(x) for x in target_times)


def _first_sample(t: float, dt: float) -> int:
    """The first sample k whose start k dt (as the C schedule computes it,
    rr_rig_schedule) is at or after t."""
    k = max(0, math.ceil(t / dt))
    while k > 0 and (k - 1) * dt >= t:
        k -= 1
    while k * dt < t:
        k += 1
    return k


def _check_targets_applied(targets: Sequence[float], target_times: Sequence[float], dt: float,
                           n: int, duration_name: str, dt_name: str) -> None:
    """Refuse targets no sample would apply: the schedule gives each sample
    the target of the last start time at or before its start (k dt), so a
    target whose interval holds no sample start (it starts within one sample
    of the next, or after the last sample starts) never reaches the
    controller, and its row of the summary would be empty."""
    firsts = [_first_sample(t, dt) for t in target_times] + [n]
    never = [f"{x:g} from {t:g} s" for x, t, a, b in zip(targets, target_times, firsts,
                                                          firsts[1:]) if a >= min(b, n)]
    if never:
        # the run's arguments first (the command line names them as its options)
        raise RollerRigError(
            f"simulate: {duration_name} = {n * dt:g} s at {dt_name} = {dt:g} s ({n} sample"
            f"{'s' if n > 1 else ''}): {len(never)} of the {len(targets)} targets would never "
            f"be applied ({', '.join(never[:5])}{', ...' if len(never) > 5 else ''}): no "
            f"sample starts between such a target's start and the next's; lengthen "
            f"{duration_name} or space the target_times")


def _record_plan(n: int, dt: float, record_every: int,
                 max_record_bytes: float) -> Tuple[int, int]:
    """(record_every, records kept) of a run of n samples, within the cap."""
    if _integer(1, max(1, n))(record_every):
        raise RollerRigError(f"simulate: record_every must be an integer from 1 to the "
                             f"number of samples ({n}), got {record_every!r}")
    cap = _real_arg("simulate", "max_record_bytes", max_record_bytes, 0.0, lo_open=True)
    kept = n // record_every
    need = kept * _BYTES_PER_SAMPLE
    if need > cap:
        fit = -(-n * _BYTES_PER_SAMPLE // int(cap)) if cap >= _BYTES_PER_SAMPLE else None
        advice = (f"keep one sample in {fit} (record_every={fit}; on the command line "
                  f"--record-every {fit})" if fit and fit <= n else "shorten the run")
        raise RollerRigError(
            f"simulate: the records of {kept} samples"
            f"{f' (one in {record_every} of {n})' if record_every > 1 else ''} would take "
            f"{need / 2**30:.3g} GiB, over max_record_bytes = {cap / 2**30:.3g} GiB; "
            f"{advice}, or raise max_record_bytes")
    return int(record_every), kept


def simulate(duration: Optional[float] = None, dt: Optional[float] = None,
             method: Optional[str] = None, params: Params = None,
             targets: Optional[npt.ArrayLike] = None, target_times: Optional[npt.ArrayLike] = None,
             *, roller_speed: Optional[float] = None, start: str = "rolling",
             nx: Optional[int] = None, ny: Optional[int] = None, substeps: Optional[int] = None,
             ode: Optional[str] = None, record_every: int = 1,
             max_record_bytes: int = RECORD_BYTES_CAP, progress: Optional[bool] = None,
             controller: Optional[Controller] = None, track: Optional[bool] = None,
             **creep: Any) -> RigResult:
    """Run the rig: by default the seed paper's scenario on the default parameters.

    Parameters
    ----------
    duration : float, optional
        Simulated time [s], at least one sample and at most 1e5 s (default
        scenario.duration_s); the run has round(duration / dt) samples (a
        RollerRigWarning says so where that is not the duration).
    dt : float, optional
        Control sample time and integration step [s], 1e-6 to 0.1 (default
        scenario.control_sample_time_s, the paper's 4 ms), at which both
        drives' sampled speed loops are stable (their PI gains on their
        inertias through their lags, eq. 10-13; with the default parameters
        6.7e-5 to 8.3e-3 s): another is refused before the run, naming the
        drive and the range.
    method : str, optional
        Creep-force method, one of :data:`RIG_METHODS` ("fastsim",
        "fastsim_blended", "modified_fastsim", "polach", "fastrip",
        "exact_table"; not "linear", which has no friction limit, nor
        "exact", solved at each step); default the parameters' contact
        section.
    params : None, dict or str or path-like, optional
        None, a nested dict overriding rig_default.toml, e.g. ``{"scenario":
        {"mu0": 0.3}, "wheelset": {"mass_kg": 15.0}}``, or the path of a
        TOML file of the same layout; every problem is reported at once
        (:func:`check_parameters`).  Its [adhesion] section changes the
        friction: a schedule of mu0 (and the falling law's A, B) in time, a
        contaminated patch on the roller circumference; res.mu_left,
        res.mu_right record it.
    targets : sequence of float, optional
        Creepage targets in sequence, magnitudes in [0, 1) in the drive's
        sense (default scenario.targets, the paper's 0.04, 0.015, 0.02,
        0.03).
    target_times : sequence of float, optional
        The targets' start times [s], increasing, inside the duration
        (Notes for the default).
    roller_speed : float, optional
        Roller surface speed [m/s] held by its controller (default
        scenario.roller_speed_m_s).
    start : {"rolling", "rest"}, optional
        "rolling" (wheelset rolling freely at roller_speed) or "rest"
        (everything at standstill; the roller drive spins the rig up).
    nx, ny : int, optional
        The FASTSIM grid (default: the parameters' contact section).
    substeps : int, optional
        Plant steps per sample.
    ode : {"ros2", "trbdf2", "lineuler"}, optional
        The integrator.
    record_every : int, optional
        Keep the record of every record_every-th sample only (the run still
        takes every sample): for long runs; 1 to the number of samples.
    max_record_bytes : float, optional
        Cap on the records' memory [bytes], > 0 (default
        :data:`RECORD_BYTES_CAP`, 1 GiB: 232 bytes per kept sample); a run
        over it is refused before it starts, with the record_every that
        would fit.
    progress : None or bool, optional
        None (default): a progress bar on stderr once the run passes about
        a second; True: from the start; False: none.
    controller : callable, optional
        None (the rig's own controllers), or a callable called at each
        control sample with what a real controller sees
        (:class:`rollerrig.rig.control.RigSignals`: time, encoder counts,
        angles and speeds, drive torques, eq. 16's estimate, the scenario's
        references) and returning the references held over the sample: a
        dict with any of roller_speed [rad/s] or roller_torque [N m],
        wheelset_speed, wheelset_torque or xi_ref (a creepage target for
        the rig's own controller); a drive left out (or None returned)
        keeps the rig's own controller.  Its method start(info), if any, is
        called first (:class:`rollerrig.rig.control.RigInfo`).
    track : bool, optional
        True: the same wheelset on tangent track (the rail a roller of
        radius ``rollerrig.rig.params.TRACK_RADIUS_M`` held at the roller
        speed, docs/lateral_dynamics.md); False: on the rollers; default
        scenario.track.
    **creep
        The creep-force method's options: bound, grid, slip_speed,
        blend_rule (blended FASTSIM), k0, alpha_inf, beta (modified
        FASTSIM), kA, kS (Polach); see :func:`rollerrig.creep_forces`.

    Returns
    -------
    RigResult
        The run's time histories (:class:`RigResult`: its fields, units
        and status codes).

    Raises
    ------
    RollerRigError
        Before the run: parameters or arguments out of range or breaking a
        rule (every problem of the parameters at once), a dt at which a
        drive's loop is unstable (naming the drive and the range), a
        target no sample would apply (its interval holds no sample's
        start), records over max_record_bytes (with the record_every that
        would fit), record_every not an integer from 1 to the number of
        samples, a controller that is not callable, track not True or
        False, an unknown method or option.  During the run: a controller that raises or returns NaN
        (or what is not a command) ends the run with a RollerRigError
        naming the sample, whose ``.result`` holds the history so far.

    Warns
    -----
    RollerRigWarning
        A duration that is not a whole number of samples; the scenario's
        target start times scaled to a shorter duration.

    See Also
    --------
    build_rig : the rig stepped by hand.
    replay : a run's kinematics through a contact model.
    rollerrig.rig.control.CreepageController : the paper's controller as
        one of the user's.

    Notes
    -----
    Without target_times: targets given here start at equal intervals
    over the duration; the scenario's own targets start at
    scenario.target_start_s when those all fall inside the duration,
    otherwise at those times scaled by duration / scenario.duration_s,
    with a RollerRigWarning saying so (the rule of a scenario.duration_s
    given without start times: :func:`check_parameters`).

    A run that fails (a wheel off its roller, lift-off, NaN, a creep force
    beyond mu N) stops cleanly: the result holds the history so far, its
    status and message say why.  A run whose samples did not converge more
    often than UNTRUSTED_SHARE (one in 20), in UNTRUSTED_MIN (20) samples
    or more, ends with status ERR_UNTRUSTED (-19), its message saying how
    many.

    Examples
    --------
    A short run to one creepage target (the paper's scenario is
    ``rr.simulate()``):

    >>> import rollerrig as rr
    >>> res = rr.simulate(duration=0.4, targets=[0.02], progress=False)
    >>> print(res.status, res.message, len(res.time))
    0 ok 100
    >>> print(f"t = {res.time[-1]:.3f} s, creepage {res.creepage[-1]:.3f}")
    t = 0.400 s, creepage 0.013
    """
    t0 = time.perf_counter()
    _progress.check("simulate", progress)
    if controller is not None and not callable(controller):
        raise RollerRigError(f"simulate: controller must be a callable (signals -> dict of "
                             f"references), got {_short(controller)}")
    P = _with_track("simulate", _parameters("simulate", params), track)
    scenario = scenario_record(params)          # the file as read (path, sha256) or None
    S = P["scenario"]
    given_dt = dt is not None
    names = {k: arg for k, arg, v in ((_SAMPLE_TIME, "dt", dt), (_DURATION, "duration", duration))
             if v is not None}
    duration_name, dt_name = names.get(_DURATION, _DURATION), names.get(_SAMPLE_TIME, _SAMPLE_TIME)
    # the sample time and the duration first (their ranges, one sample at
    # least): the samples and targets follow from them; the drives' loops at
    # dt with the rest of the rig (_build)
    run = _check_run("simulate", P, {_SAMPLE_TIME: dt if given_dt else S["control_sample_time_s"],
                                     _DURATION: duration if duration is not None
                                     else S["duration_s"]}, names, about=(_SAMPLE_TIME, _DURATION),
                     skip=("loop",))
    dt, duration = float(run[_SAMPLE_TIME]), float(run[_DURATION])
    n = max(1, int(round(duration / dt)))
    # a run of whole samples: say so where that changes the duration (by more
    # than the rounding of a dt given in single precision, 5e-8)
    if abs(n * dt - duration) > 1e-6 * duration:
        warnings.warn(f"simulate: {duration_name} = {duration:g} s is not a whole number of "
                      f"samples of "
                      f"{dt_name} = {dt:g} s: the run takes {n} samples, {n * dt:.9g} s",
                      RollerRigWarning, stacklevel=2)
    targets, target_times = _target_schedule(P, duration, dt, targets, target_times, names)
    _check_targets_applied(targets, target_times, dt, n, duration_name, dt_name)
    record_every, kept = _record_plan(n, dt, record_every, max_record_bytes)
    rig, _, dt, V, used = _build("simulate", P, dt=dt, method=method, substeps=substeps,
                                 ode=ode, nx=nx, ny=ny, roller_speed=roller_speed,
                                 start=start, creep=creep, given_dt=given_dt,
                                 run={_DURATION: duration, _TARGETS: list(targets),
                                      _STARTS: list(target_times)}, names=names)

    out = np.full((kept, len(RECORD_FIELDS)), np.nan)
    t1 = time.perf_counter()

    def result(out: F64Array, status: int, message: str, stepped: int) -> RigResult:
        wall = {"setup": t1 - t0, "run": time.perf_counter() - t1}
        return RigResult(out, P, targets, target_times, dt, int(status), message, wall,
                         record_every=record_every, method=used, samples=stepped,
                         scenario=scenario)
    if controller is not None:
        out, stepped, status, worst, warned = _run_controlled(
            rig, controller, P, duration, dt, targets, target_times, V, n, record_every, out,
            progress, result)
    else:
        out, stepped, status, worst, warned = _run_builtin(
            rig, P, duration, dt, targets, target_times, V, n, record_every, out, progress)
    status = status if status < 0 else worst
    if status == 0:
        message = "ok"
    elif status > 0 and warned > UNTRUSTED_SHARE * stepped and warned >= UNTRUSTED_MIN:
        message = (f"not to be trusted: {warned} of {stepped} samples did not converge "
                   f"(sample_status {status}: {status_message(status)}), more than one in "
                   f"{round(1 / UNTRUSTED_SHARE)}; more integration.substeps or "
                   f"newton_iterations (or a shorter dt) converge it")
        status = _core.ERR_UNTRUSTED
    elif status > 0:
        message = (f"ok with warnings: {warned} of {stepped} samples warned "
                   f"(sample_status {status}: {status_message(status)})")
    else:
        message = f"stopped at t = {rig.t:.4f} s: {status_message(status)}"
    return result(out, status, message, stepped)


def _run_builtin(rig: Rig, P: _Params, duration: float, dt: float, targets: Sequence[float],
                 target_times: Sequence[float], V: float, n: int, record_every: int,
                 out: F64Array, progress: Optional[bool]) -> _Stepped:
    """simulate's samples on the rig's own controllers, in chunks through
    the C loop.  Returns (records kept, samples stepped, the run's status,
    the worst sample status, samples warned)."""
    # about 50 steps of the progress bar; without one, as few calls as the bound allows
    chunk = max(1, min(n // 50 if progress is not False else n, _CHUNK_SAMPLES))
    with _progress.bar(progress, n, "simulate", "sample") as bar:
        return _builtin_chunks(rig, P, duration, dt, targets, target_times, V, n,
                               record_every, out, chunk, bar)


def _builtin_chunks(rig: Rig, P: _Params, duration: float, dt: float, targets: Sequence[float],
                    target_times: Sequence[float], V: float, n: int, record_every: int,
                    out: F64Array, chunk: int, bar: Any) -> _Stepped:
    stepped, worst, warned, status = 0, 0, 0, 0
    for first in range(0, n, chunk):
        stop = min(n, first + chunk)
        roller_ref, xi_ref = schedule(P, duration, dt, targets, target_times, V, first, stop)
        # every sample kept: the records straight into the result's rows
        rec, status = rig.run(roller_ref, xi_ref, out[first:stop] if record_every == 1
                              else None)
        if status < 0:
            good = np.isfinite(rec[:, 0]) & (rec[:, -1] >= 0)
            rec = rec[:int(np.argmin(good)) if not good.all() else len(rec)]
        # keep samples k = record_every - 1, 2 record_every - 1, ...: the
        # records every record_every dt, ending at the duration
        if record_every > 1:
            offset = (record_every - 1 - first) % record_every
            keep = rec[offset::record_every]
            at = (first + offset) // record_every
            out[at:at + len(keep)] = keep
        stepped = first + len(rec)
        # the worst warning of the chunk from its samples' own statuses: the
        # binding's run() may report only that of its last block of samples
        if len(rec):
            worst = max(worst, status, int(np.max(rec[:, -1])))
            warned += int(np.count_nonzero(rec[:, -1] > 0))
        bar.update(stop - first)
        if status < 0:
            out = out[:stepped // record_every]
            break
    return out, stepped, status, worst, warned


_XI_REF = RECORD_FIELDS.index("xi_ref")


def _run_controlled(rig: Rig, controller: Controller, P: _Params, duration: float, dt: float,
                    targets: Sequence[float], target_times: Sequence[float], V: float, n: int,
                    record_every: int, out: F64Array, progress: Optional[bool],
                    result: _Result) -> _Stepped:
    """simulate's samples with a controller of the user's
    (rollerrig.rig.control): read, call, write, advance, sample by sample; the
    records' xi_ref is the scenario's target the controller was given.
    Returns as _run_builtin; a controller that raises, or returns what is
    not a command (reading it raises, whatever the exception) or a command
    the rig refuses (NaN), ends the run with a RollerRigError whose .result
    holds the history so far."""
    core = rig._core
    stepped, worst, warned, status = 0, 0, 0, 0

    def fail(k: int, t: float, what: str, code: int,
             cause: Optional[BaseException] = None) -> NoReturn:
        kept = out[:k // record_every]
        text = (f"simulate: the controller failed at sample {k} (t = {t:.4f} s): {what}; "
                f"the history so far is in this error's .result")
        e = RollerRigError(text)
        # (the error carries the history so far: simulate's Raises)
        e.result = result(kept, code, text.split(": ", 1)[1], k)  # type: ignore[attr-defined]
        raise e from cause

    start = getattr(controller, "start", None)
    if start is not None:
        try:
            start(rig.info)
        except Exception as exc:
            fail(0, 0.0, f"its start(info) raised {type(exc).__name__}: "
                 f"{_control.safe_repr(exc, str)}", _core.ERR_CONTROLLER, exc)
    chunk = max(1, min(n // 50 if progress is not False else n, _CHUNK_SAMPLES))
    with _progress.bar(progress, n, "simulate", "sample") as bar:
        return _controlled_chunks(rig, controller, P, duration, dt, targets, target_times, V,
                                  n, record_every, out, chunk, bar, fail)


def _controlled_chunks(rig: Rig, controller: Controller, P: _Params, duration: float,
                       dt: float, targets: Sequence[float], target_times: Sequence[float],
                       V: float, n: int, record_every: int, out: F64Array, chunk: int, bar: Any,
                       fail: Callable[..., NoReturn]) -> _Stepped:
    core = rig._core
    stepped, worst, warned, status = 0, 0, 0, 0
    for first in range(0, n, chunk):
        stop = min(n, first + chunk)
        roller_ref, xi_ref = schedule(P, duration, dt, targets, target_times, V, first, stop)
        for k in range(first, stop):
            vals, status = core.read()
            if status < 0:
                break
            s = _control.RigSignals(k, *vals, float(roller_ref[k - first]),
                                    float(xi_ref[k - first]))
            try:
                cmd = controller(s)
            except Exception as exc:
                fail(k, s.t, f"it raised {type(exc).__name__}: {_control.safe_repr(exc, str)}",
                     _core.ERR_CONTROLLER, exc)
            try:
                modes = _control.command(cmd, s)
            except ValueError as exc:                   # named by command()
                fail(k, s.t, str(exc), _core.ERR_CONTROLLER, exc.__cause__)
            except Exception as exc:                    # whatever else reading it raised
                fail(k, s.t, f"reading what it returned raised {type(exc).__name__}: "
                     f"{_control.safe_repr(exc, str)}", _core.ERR_CONTROLLER, exc)
            status = core.write(*modes, math.nan)
            if status < 0:
                fail(k, s.t, f"the rig refused its command {_control.safe_repr(cmd):.80}: "
                     f"{status_message(status)}", status)
            rec, status = core.advance()
            rec[_XI_REF] = s.xi_ref
            if status < 0:
                break
            stepped = k + 1
            worst = max(worst, status)
            warned += status > 0
            if stepped % record_every == 0:
                out[stepped // record_every - 1] = rec
        bar.update(stop - first)
        if status < 0:
            out = out[:stepped // record_every]
            break
    return out, stepped, status, worst, warned


def replay(res: RigResult, *, method: Optional[str] = None, nx: Optional[int] = None,
           ny: Optional[int] = None, **creep: Any) -> RigContact[WheelContact]:
    """The seed paper's Fig. 9 procedure: a run's kinematics through a contact model.

    The kinematics recorded in a run (e.g. an offline high-accuracy run
    kept as a database) fed sample by sample through a contact model (the
    real-time one by default: the parameters' method and grid) with the
    recorded normal loads.

    Parameters
    ----------
    res : RigResult
        The run.
    method : str, optional
        The creep-force method (any of ``rollerrig.METHODS`` the contact
        model takes); default the run's parameters' contact section.
    nx, ny : int, optional
        The FASTSIM grid; default the parameters' contact section.
    **creep
        The method's options, as for :func:`simulate`.

    Returns
    -------
    RigContact
        For every sample (:class:`RigContact`); compare its ``left.fx +
        right.fx`` with ``res.fx``.

    Raises
    ------
    RollerRigError
        The run's adhesion changed (its [adhesion] section: mu_left,
        mu_right vary, or A, B do): replay takes one friction law,
        scenario.mu0 with the contact section's; an unknown method or
        option.

    See Also
    --------
    rig_contact : one contact evaluation.
    simulate : the run.
    """
    from .contact import rig_contact
    from ..contact.creep import FallingFriction

    P = res.params
    C, A = P["contact"], P["adhesion"]
    mu0 = P["scenario"]["mu0"]
    patch = (A["patch_mu0"], A["patch_polach_A"], A["patch_polach_B_s_per_m"])
    if (np.any(res.mu_left != mu0) or np.any(res.mu_right != mu0)
            or A["schedule_polach_A"] or A["schedule_polach_B_s_per_m"]
            or (A["patch_length_m"] > 0 and patch != (mu0, C["polach_A"], C["polach_B_s_per_m"]))):
        raise RollerRigError("replay: the run's adhesion changed (its [adhesion] section: "
                             "mu_left, mu_right vary, or A, B do); replay takes one friction "
                             "law, scenario.mu0 with the contact section's")
    friction = (FallingFriction(A=C["polach_A"], B=C["polach_B_s_per_m"])
                if C["friction_law"] == "polach_falling" else None)
    opts: Dict[str, Any] = _creep_options("replay", P, method, nx, ny, creep, in_rig=False)
    # (opts hold no patch: Hertz's wheels; overloads cannot tell through **opts)
    c = rig_contact(_geometry(P), x=res.x, y=res.y, yaw=res.yaw, vx=res.vx, vy=res.vy,
                    yaw_rate=res.yaw_rate, spin=res.spin, roller_spin=res.roller_spin,
                    N_left=res.normal_load_left, N_right=res.normal_load_right,
                    mu=P["scenario"]["mu0"], friction=friction,
                    E=C["youngs_modulus_Pa"], nu=C["poisson_ratio"],
                    vmin=C["min_rolling_speed_m_s"], **opts)
    return cast("RigContact[WheelContact]", c)
