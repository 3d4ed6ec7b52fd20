"""Rig: the C rig stepped by hand, as rollerrig.rig.build.build_rig returns
it (csrc/rig/rr_rig.h), every argument checked here, RollerRigError naming
it."""
from __future__ import annotations

import math
import numbers
from typing import Dict, Optional, Tuple

import numpy as np
import numpy.typing as npt

from .. import _core
from .._binding import _as_float
from .._errors import RollerRigError, status_message
from .._typing import F64Array
from . import control as _control
from ._param_file import _short


class Rig:
    """The rig stepped by hand, as :func:`build_rig` returns it.

    The C rig of csrc/rig/rr_rig.h, its arguments checked here
    (RollerRigError naming them).  A control sample is either
    :meth:`sample` (the rig's own controllers) or :meth:`read`, then
    :meth:`write` (references of one's own), followed by :meth:`advance`
    (the plant over the sample); :meth:`run` steps many samples at once.
    :meth:`rhs`, :meth:`jac` and :meth:`set_state` expose the plant's
    right-hand side, its approximate Jacobian and its state (e.g. to verify
    the integrator against another solver).  The properties :attr:`t`,
    :attr:`y`, :attr:`status` and :attr:`info` give its time, state,
    last status and the controllers' settings.

    See Also
    --------
    build_rig : the rig of a set of parameters.
    simulate : the whole scenario, sample by sample through the C loop.
    rollerrig.rig.control.RigSignals : what :meth:`read` measures.

    Notes
    -----
    Statuses: 0 ok, 1 a warning, < 0 an error (``rollerrig.STATUS``);
    after an error the rig keeps its last good state and refuses to step
    on.  One thread at a time: a second thread gets RuntimeError.
    """

    __slots__ = ("_core",)

    def __init__(self, core: _core.Rig) -> None:
        self._core = core

    def __repr__(self) -> str:
        return f"Rig(t = {self.t:g} s, status {self.status})"

    @staticmethod
    def _scalar(func: str, name: str, v: object) -> float:
        """A real number (NaN and infinities pass: the C rig answers them
        with a status, as it does for a NaN state)."""
        if isinstance(v, numbers.Real) and not isinstance(v, bool):
            try:
                return float(v)
            except OverflowError:                      # an int beyond a double
                pass
        raise RollerRigError(f"{func}: {name} must be a real number, got {_short(v)}")

    @staticmethod
    def _array(func: str, name: str, v: npt.ArrayLike, n: Optional[int] = None) -> F64Array:
        a = _as_float(func, name, v) if not (np.ndim(v) == 1 and np.size(v) == 0) \
            else np.zeros(0)
        if a.ndim != 1 or (n is not None and a.size != n):
            want = f"{n} values" if n is not None else "a 1-D array"
            raise RollerRigError(f"{func}: {name} must be {want}, got shape {a.shape}")
        return np.ascontiguousarray(a)

    def run(self, roller_ref: npt.ArrayLike, xi_ref: npt.ArrayLike,
            out: Optional[F64Array] = None) -> Tuple[F64Array, int]:
        """Step one sample per element of the references.

        Parameters
        ----------
        roller_ref : array_like
            Roller speed reference per sample [rad/s], 1-D.
        xi_ref : array_like
            Creepage target per sample [-], 1-D of the same length (NaN:
            no creepage control, the wheelset held at free rolling).
        out : numpy.ndarray, optional
            Where to write the records: a writable C-contiguous float64
            array of shape (n, len(RECORD_FIELDS)).

        Returns
        -------
        records : numpy.ndarray
            Shape (n, len(RECORD_FIELDS)) (``out`` if given), one record
            per sample (:data:`RECORD_FIELDS`); after the first error the
            rest NaN.
        status : int
            The worst status of the run (the class's Notes).

        Raises
        ------
        RollerRigError
            A reference not a 1-D array of real numbers, or the two of
            different lengths.

        Notes
        -----
        The run stops at the first error (status < 0).
        """
        r = self._array("Rig.run", "roller_ref", roller_ref)
        x = self._array("Rig.run", "xi_ref", xi_ref, r.size)
        return self._core.run(r, x) if out is None else self._core.run(r, x, out)

    def sample(self, roller_ref: float, xi_ref: float) -> int:
        """The sampling instant with the rig's own controllers.

        Encoders, creepage controller and PI controllers; the same as
        :meth:`read` then :meth:`write` with the builtin modes.

        Parameters
        ----------
        roller_ref : float
            Roller speed reference [rad/s].
        xi_ref : float
            Creepage target [-] (NaN: no creepage control, the wheelset
            held at free rolling).

        Returns
        -------
        int
            Status (the class's Notes).

        Raises
        ------
        RollerRigError
            An argument not a real number.
        """
        return self._core.sample(self._scalar("Rig.sample", "roller_ref", roller_ref),
                                 self._scalar("Rig.sample", "xi_ref", xi_ref))

    def read(self) -> Tuple[Tuple[float, ...], int]:
        """The sampling instant's measurement.

        Returns
        -------
        signals : tuple of float
            The fields of :class:`rollerrig.rig.control.RigSignals` from t
            to xi_est (time, encoder counts, angles and speeds, drive
            torques, eq. 16's creepage estimate).
        status : int
            Status (the class's Notes).

        See Also
        --------
        write : the references held over the sample, after read.
        """
        return self._core.read()

    def write(self, roller_mode: int, roller_ref: float, wheelset_mode: int, wheelset_ref: float,
              mu0: float = math.nan) -> int:
        """The references held over the sample (after :meth:`read`).

        csrc/rig/rr_rig.h, rr_rig_read, rr_rig_write.

        Parameters
        ----------
        roller_mode, wheelset_mode : int
            ``_core.CMD_BUILTIN`` (the rig's controllers: roller speed,
            creepage target), ``CMD_SPEED`` (a speed reference [rad/s] to
            the drive's PI controller) or ``CMD_TORQUE`` (a torque
            reference [N m] to the drive).
        roller_ref, wheelset_ref : float
            The references in the modes' units (builtin: the roller speed
            [rad/s], the creepage target [-]).
        mu0 : float, optional
            Friction coefficient over the sample [-] (NaN: the adhesion
            section's).

        Returns
        -------
        int
            Status (the class's Notes).

        Raises
        ------
        RollerRigError
            A mode not one of the three, a reference or mu0 not a real
            number.
        """
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

    def advance(self) -> Tuple[F64Array, int]:
        """The plant over one sample.

        Returns
        -------
        record : numpy.ndarray
            The sample's record (:data:`RECORD_FIELDS`).
        status : int
            Status (the class's Notes).
        """
        return self._core.advance()

    def record(self) -> Tuple[F64Array, int]:
        """The record of the present state.

        Returns
        -------
        record : numpy.ndarray
            The record (:data:`RECORD_FIELDS`).
        status : int
            Status (the class's Notes).
        """
        return self._core.record()

    def _t_y(self, func: str, t: float, y: npt.ArrayLike) -> Tuple[float, F64Array]:
        return (self._scalar(func, "t", t),
                self._array(func, "y", y, _core.RIG_NSTATE))

    def rhs(self, t: float, y: npt.ArrayLike) -> Tuple[F64Array, int]:
        """The plant's right-hand side dy/dt at (t, y).

        Parameters
        ----------
        t : float
            Time [s].
        y : array_like
            State, RIG_STATE (12 values).

        Returns
        -------
        dydt : numpy.ndarray
            The derivative of the state (12 values).
        status : int
            Status (the class's Notes).

        Raises
        ------
        RollerRigError
            t not a real number, y not 12 real numbers.
        """
        return self._core.rhs(*self._t_y("Rig.rhs", t, y))

    def jac(self, t: float, y: npt.ArrayLike) -> Tuple[F64Array, int]:
        """The plant's approximate Jacobian at (t, y).

        Parameters
        ----------
        t : float
            Time [s].
        y : array_like
            State, RIG_STATE (12 values).

        Returns
        -------
        J : numpy.ndarray
            The approximate Jacobian d(dy/dt)/dy, 12 x 12.
        status : int
            Status (the class's Notes).

        Raises
        ------
        RollerRigError
            t not a real number, y not 12 real numbers.
        """
        return self._core.jac(*self._t_y("Rig.jac", t, y))

    def set_state(self, t: float, y: npt.ArrayLike) -> int:
        """Set the rig's time and plant state.

        Parameters
        ----------
        t : float
            Time [s].
        y : array_like
            State, RIG_STATE (12 values).

        Returns
        -------
        int
            Status (the class's Notes).

        Raises
        ------
        RollerRigError
            t not a real number, y not 12 real numbers.
        """
        return self._core.set_state(*self._t_y("Rig.set_state", t, y))

    def full_state(self) -> Dict[str, float]:
        """The rig's whole state between samples (rr_rig_get_full_state: the
        plant, held references and friction, PI integrals, encoders,
        creepage controller) as a dict name -> float, in the C order; a
        checkpoint for set_full_state.  RollerRigError within a sample (after
        read or sample, before advance) or on a rig that never started."""
        names, values, status = self._core.full_state()
        if status < 0:
            raise RollerRigError(f"Rig.full_state: {status_message(status)}")
        return dict(zip(names, values.tolist()))

    def set_full_state(self, state: Dict[str, float]) -> int:
        """Put the rig at `state`, a dict of every name of full_state() (the
        samples from there are those that followed where it was taken) ->
        status: 0, a warning, or the C check's error (a NaN, a flag or
        counter not its kind, a wheel off its roller: nothing changes)."""
        names = self._core.full_state()[0]
        if not isinstance(state, dict):
            raise RollerRigError("Rig.set_full_state: state must be a dict of the names of "
                                 f"Rig.full_state(), got {_short(state)}")
        missing = [n for n in names if n not in state]
        unknown = [k for k in state if k not in names]
        if missing or unknown:
            raise RollerRigError(f"Rig.set_full_state: state lacks {missing} and has unknown "
                                 f"{unknown}" if missing and unknown else
                                 f"Rig.set_full_state: state lacks {missing}" if missing else
                                 f"Rig.set_full_state: state has unknown names {unknown}")
        values = [self._scalar("Rig.set_full_state", f"state[{n!r}]", state[n]) for n in names]
        return self._core.set_full_state(np.array(values))

    @property
    def t(self) -> float:
        """The rig's time [s]."""
        return self._core.t

    @property
    def y(self) -> F64Array:
        """The plant's state (a copy; RIG_STATE, 12 values)."""
        return self._core.y

    @property
    def status(self) -> int:
        """The rig's last status (the class's Notes)."""
        return self._core.status

    @property
    def info(self) -> _control.RigInfo:
        """The controllers' settings (:class:`rollerrig.rig.control.RigInfo`)."""
        return _control.rig_info(self._core.info)
