"""A controller of the user's in the rig's loop (simulate(controller=...)).

At each control sample the rig reads its encoders and drives (RigSignals:
what a real controller sees), calls the controller, and holds what it
returns over the sample: per drive a speed reference for the drive's PI
controller or a torque reference for the drive itself; a drive it leaves
out keeps the rig's own controller (csrc/rig/rr_rig.h, rr_rig_read and
rr_rig_write)::

    def controller(s):                      # s: RigSignals
        return {"wheelset_torque": -20.0}   # N m, held over the sample

A controller may have a method start(info) (RigInfo: the rig's sample
time, radii, encoder counts, torque limits), called once before the first
sample.  CreepageController is the paper's creepage controller (eq. 13-16)
written as such a controller: it gives the built-in controller's history
bit for bit, and is a template for one's own.
"""
from __future__ import annotations

import math
import numbers
from typing import Any, Callable, Dict, Mapping, NamedTuple, Tuple

from .. import _core


class RigSignals(NamedTuple):
    """What a controller sees at control sample k (taken at its start).

    The argument of a controller's call (:func:`simulate`'s controller),
    and the fields of :meth:`Rig.read` from t to xi_est.
    """

    k: int                   #: sample index
    t: float                 #: time [s]
    roller_count: float      #: encoder counters (whole counts) [-]
    wheelset_count: float
    roller_angle: float      #: the quantised angles, count 2 pi / counts [rad]
    wheelset_angle: float
    roller_speed: float      #: the encoders' speed estimates (eq. 12) [rad/s]
    wheelset_speed: float
    roller_torque: float     #: the drives' torques, as a torque sensor reads them [N m]
    wheelset_torque: float
    xi_est: float            #: eq. 16's creepage estimate, in the drive's sense [-]
    roller_ref: float        #: the scenario's roller speed reference [rad/s]
    xi_ref: float            #: the scenario's creepage target (NaN before the first) [-]


class RigInfo(NamedTuple):
    """The rig's settings a controller is configured with (start(info)),
    as :attr:`Rig.info` gives them."""

    dt: float                    #: control sample time [s]
    wheel_radius: float          #: eq. 15-16's wheel rolling radius r_w [m]
    roller_radius: float         #: eq. 15-16's roller rolling radius r_r [m]
    sense: int                   #: +1 traction, -1 braking (scenario.drive_mode)
    roller_counts: int           #: encoder counts per revolution
    wheelset_counts: int
    roller_torque_limit: float   #: the drives' limits [N m] (torque commands are clipped)
    wheelset_torque_limit: float
    alpha: float                 #: eq. 13-14's gains (creepage_controller section)
    beta: float
    min_reference_speed: float   #: eq. 16's least roller surface speed [m/s]


#: the keys a controller may return: (drive, mode); a drive left out keeps
#: the rig's own controller with the scenario's reference
COMMANDS = {
    "roller_speed": ("roller", _core.CMD_SPEED),        # [rad/s], to the roller's PI
    "roller_torque": ("roller", _core.CMD_TORQUE),      # [N m], to the roller drive
    "wheelset_speed": ("wheelset", _core.CMD_SPEED),    # [rad/s], to the wheelset's PI
    "wheelset_torque": ("wheelset", _core.CMD_TORQUE),  # [N m], to the wheelset drive
    "xi_ref": ("wheelset", _core.CMD_BUILTIN),          # a creepage target for eq. 13-16
}


def rig_info(info: Mapping[str, Any]) -> RigInfo:
    """RigInfo of the binding's Rig.info dict."""
    return RigInfo(**{k: info[k] for k in RigInfo._fields})


def safe_repr(value: object, how: Callable[[object], str] = repr) -> str:
    """repr (or str) of a value of the user's, or a stand-in if that raises."""
    try:
        return how(value)
    except Exception as exc:
        return f"<{type(value).__name__} whose {how.__name__}() raised {type(exc).__name__}>"


def command(out: object, s: RigSignals) -> Tuple[int, float, int, float]:
    """(roller_mode, roller_ref, wheelset_mode, wheelset_ref) of a
    controller's return value `out` at signals s; ValueError naming what
    is wrong (a mapping whose items() raises, a value whose float() does).
    NaN and infinities pass: the C rig refuses them."""
    roller = (_core.CMD_BUILTIN, s.roller_ref)
    wheelset = (_core.CMD_BUILTIN, s.xi_ref)
    if out is None:
        return roller + wheelset
    if not hasattr(out, "items"):
        raise ValueError(f"it returned {type(out).__name__} {safe_repr(out):.60}, not a dict "
                         f"of references ({', '.join(COMMANDS)}) or None")
    try:
        items = list(out.items())
    except Exception as exc:
        raise ValueError(f"it returned a {type(out).__name__} whose items() raised "
                         f"{type(exc).__name__}: {safe_repr(exc, str):.80}") from exc
    given: Dict[str, str] = {}
    for key, value in items:
        if not isinstance(key, str) or key not in COMMANDS:
            raise ValueError(f"it returned the unknown key {safe_repr(key):.40} (the keys are "
                             f"{', '.join(COMMANDS)})")
        drive, mode = COMMANDS[key]
        if drive in given:
            raise ValueError(f"it returned both {given[drive]!r} and {key!r} for the {drive}")
        given[drive] = key
        if not isinstance(value, numbers.Real) or isinstance(value, bool):
            raise ValueError(f"it returned {key} = {safe_repr(value):.40}, not a real number")
        try:
            ref = float(value)
        except OverflowError:
            ref = math.inf
        except Exception as exc:
            raise ValueError(f"it returned {key} = a {type(value).__name__} whose float() "
                             f"raised {type(exc).__name__}: {safe_repr(exc, str):.80}") from exc
        if drive == "roller":
            roller = (mode, ref)
        else:
            wheelset = (mode, ref)
    return roller + wheelset


class CreepageController:
    """The paper's creepage controller as a controller of the user's.

    Eq. 13-16, csrc/rig/rr_control.h: from the encoders' speeds it moves
    the coefficient K toward the scenario's target (eq. 13-14) and returns
    the wheelset speed reference K (r_r / r_w) w_roller (eq. 15); before the
    first target it holds the wheelset at free rolling.  The roller keeps
    the rig's own speed controller.

    See Also
    --------
    simulate : its controller argument.
    RigSignals : what it sees at each sample.

    Notes
    -----
    In the loop it gives the built-in controller's history bit for bit
    (the same operations in the same order), so it is the template for
    one's own.

    Examples
    --------
    >>> import numpy as np
    >>> import rollerrig as rr
    >>> from rollerrig.rig.control import CreepageController
    >>> own = rr.simulate(duration=0.4, targets=[0.02], progress=False)
    >>> user = rr.simulate(duration=0.4, targets=[0.02], progress=False,
    ...                    controller=CreepageController())
    >>> print(user.status, np.array_equal(own.creepage, user.creepage))
    0 True
    """

    def start(self, info: RigInfo) -> None:
        """Configure the controller before the first sample.

        Parameters
        ----------
        info : RigInfo
            The rig's settings (sample time, radii, sense, gains alpha and
            beta, ...).

        Notes
        -----
        Resets K to 1 and the control to inactive (the wheelset at free
        rolling until the first target).
        """
        self.info = info
        self.K = 1.0
        self.active = False
        self.xi_last = 0.0              # the estimate of the last sample without control

    def __call__(self, s: RigSignals) -> Dict[str, float]:
        """The references for sample s.

        Parameters
        ----------
        s : RigSignals
            What the controller sees at the sample.

        Returns
        -------
        dict
            ``{"wheelset_speed": w}`` [rad/s]: free rolling (r_r / r_w
            w_roller) before the first target, else K (r_r / r_w)
            w_roller (eq. 15).
        """
        i = self.info
        if math.isnan(s.xi_ref):
            self.active = False
            self.xi_last = s.xi_est
            return {"wheelset_speed": s.roller_speed * i.roller_radius / i.wheel_radius}
        if not self.active:
            # control starts from the wheelset's present speed ratio (eq. 15)
            self.K = 1.0 + i.sense * self.xi_last
            self.active = True
        dxi = s.xi_ref - s.xi_est
        K = self.K + i.sense * i.alpha * dxi if dxi >= 0.0 else self.K - i.sense * i.beta
        self.K = 0.0 if K < 0.0 else K
        return {"wheelset_speed": self.K * i.roller_radius / i.wheel_radius * s.roller_speed}
