"""Hunting, nonlinear: the limit cycle's amplitude against speed by a ramp
down in speed from a hunting cycle (issue 25; docs/lateral_dynamics.md).

    import rollerrig as rr
    h = rr.hunting(np.arange(120, 40, -2), {"suspension": {...}}, track=True)
    h.speeds, h.amplitude                 # [m/s], [m]: the bifurcation diagram
    h.nonlinear_critical_speed            # the lowest speed the cycle survives

The rig in time (its own integrator and controllers, the wheelset at free
rolling: no creepage target), stepped by hand: started at the first speed
with a lateral shift, held `settle` seconds at each speed then measured over
`measure` seconds, the next speed taken from the state the last one left (the
rail's or roller's speed and the wheelset's spin scaled together, so that no
creepage jump kicks it).  Amplitude: the largest |y| over the measurement;
a cycle is sustained where the measurement's last period is at least
SUSTAINED of its first.
"""
import math
from typing import Any, List, NamedTuple, Optional

import numpy as np
import numpy.typing as npt

from .._errors import RollerRigError, check_number, status_message
from .._typing import Params
from ..rig.build import build_rig
from ..rig.params import _parameters, _short, _with_track
from ..rig.result import RECORD_FIELDS

#: a cycle is sustained where its last period's amplitude is at least this
#: share of the measurement's first (a decaying one at 0.5 Vc loses 90 %)
SUSTAINED = 0.95
_Y, _SPIN, _RSPIN = 1, 8, 9


class Hunting(NamedTuple):
    """The hunting cycle against speed (:func:`rollerrig.hunting`)."""
    speeds: np.ndarray             #: [m/s], in the order run (decreasing)
    amplitude: np.ndarray          #: the amplitude of the lateral shift y at each [m]
    yaw_amplitude: np.ndarray      #: and of the yaw [rad]
    #: its frequency [Hz], from y's upward zero crossings (NaN without two)
    frequency_hz: np.ndarray
    sustained: np.ndarray          #: bool: the cycle held over the measurement
    #: the lowest speed of the first unbroken run of sustained cycles [m/s]
    #: (NaN if the first speed's is not sustained)
    nonlinear_critical_speed: float
    track: bool                    #: on tangent track


#: plant steps per 4 ms sample in the ramp.  The rig's Jacobian carries the
#: conicity's longitudinal creepage (csrc/rig/rr_rig_plant.c, linearise): at
#: 60 m/s on track (soft suspension) the hunting mode decays at -1.36/s at 1
#: substep, -1.30 at 4, against -1.26 linearised (without that term: +1.3/s
#: at 1 substep, a spurious cycle down to 50 m/s); the cycle's amplitude at 4
#: is within 1 % of 32's (tests/test_lateral_hunting.py)
SUBSTEPS = 4


def hunting(speeds: npt.ArrayLike, params: Params = None, *, track: bool = False,
            settle: float = 2.0, measure: float = 1.0, shift: float = 1e-3,
            substeps: int = SUBSTEPS, method: Optional[str] = None,
            **creep: Any) -> Hunting:
    """The limit cycle's amplitude against speed, by a ramp down.

    Parameters
    ----------
    speeds : array_like
        Decreasing speeds [m/s], finite and > 0; the first one above the
        critical speed, where the shift grows into a cycle.
    params : None, dict or str
        The rig's parameters, as :func:`rollerrig.stability`.
    track : bool
        True: on tangent track.
    settle, measure : float
        Seconds held at each speed before and while measuring, > 0.
    shift : float
        The lateral shift [m] the run starts from (at the first speed).
    substeps : int
        Plant steps per control sample (``SUBSTEPS``: the module says why).
    method : str, optional
        The creep-force method, as :func:`rollerrig.simulate`.
    **creep
        The method's options.

    Returns
    -------
    Hunting
        The amplitudes, frequencies and the nonlinear critical speed.

    Raises
    ------
    RollerRigError
        A bad argument, named.
    """
    func = "hunting"
    try:
        s = np.asarray(speeds, dtype=float).reshape(-1)
    except (TypeError, ValueError):
        raise RollerRigError(f"{func}: speeds must be an array of speeds [m/s], got "
                             f"{_short(speeds)}") from None
    if s.size == 0 or not np.all(np.isfinite(s)) or np.any(s <= 0) or np.any(np.diff(s) >= 0):
        raise RollerRigError(f"{func}: speeds must be a non-empty, decreasing array of finite "
                             f"speeds > 0 [m/s], got {_short(speeds)}")
    settle = check_number(func, "settle", settle, positive=True)
    measure = check_number(func, "measure", measure, positive=True)
    shift = check_number(func, "shift", shift, positive=True)
    P = _with_track(func, _parameters(func, params), track)
    rig, P, _ = build_rig(P, method=method, roller_speed=float(s[0]), substeps=substeps,
                          **creep)
    R0 = float(P["roller"]["radius_m"])
    dt = float(P["scenario"]["control_sample_time_s"])
    n_settle, n_measure = max(1, round(settle / dt)), max(2, round(measure / dt))
    iy, iyaw, it = (RECORD_FIELDS.index(k) for k in ("y", "yaw", "time"))
    y0 = np.array(rig.y)
    y0[_Y] += shift
    rig.set_state(rig.t, y0)
    amp: List[float] = []
    yaw_amp: List[float] = []
    freq: List[float] = []
    held: List[bool] = []
    V_prev = float(s[0])
    for V in s:
        y = np.array(rig.y)
        y[_SPIN] *= V / V_prev
        y[_RSPIN] = V / R0
        rig.set_state(rig.t, y)
        V_prev = V
        ref = np.full(n_settle + n_measure, V / R0)
        rec, st = rig.run(ref, np.full(ref.size, np.nan))
        if st < 0:
            raise RollerRigError(f"{func}: the run stopped at {V:g} m/s (t = {rig.t:.3f} s): "
                                 f"{status_message(st)}")
        w = rec[n_settle:]
        yy, tt = w[:, iy], w[:, it]
        amp.append(float(np.max(np.abs(yy))))
        yaw_amp.append(float(np.max(np.abs(w[:, iyaw]))))
        k = np.flatnonzero((yy[:-1] < 0) & (yy[1:] >= 0))
        tc = tt[k] - yy[k] * (tt[k + 1] - tt[k]) / (yy[k + 1] - yy[k])
        freq.append(1.0 / float(np.mean(np.diff(tc))) if tc.size >= 2 else math.nan)
        if tc.size >= 3:
            first = np.max(np.abs(yy[(tt >= tc[0]) & (tt < tc[1])]))
            last = np.max(np.abs(yy[(tt >= tc[-2]) & (tt < tc[-1])]))
            held.append(bool(last >= SUSTAINED * first))
        else:
            held.append(False)
    sus = np.array(held)
    crit = math.nan
    if sus[0]:
        end = int(np.argmin(sus)) if not sus.all() else sus.size
        crit = float(s[end - 1])
    return Hunting(s, np.array(amp), np.array(yaw_amp), np.array(freq), sus, crit,
                   bool(P["scenario"]["track"]))
