# The types of the C extension rollerrig._core (rollerrig/_core_c/): its
# method table (module.c, core_methods), the Rig and CreepOptions types and
# the module constants, as the package calls them.  Arguments follow each
# function's PyArg_ParseTuple format: "d" a float, "i"/"n" an int, "O" any
# array-like the C code converts with PyArray_FROM_OTF (float64, C order).
# The dict results (gap_build's patch, wheel_exact's result, nonhertz_*'s
# info, Rig.info) have values of several types: Dict[str, Any].
from typing import Any, Dict, List, Optional, Tuple, Union, final

import numpy as np
import numpy.typing as npt

_F64 = npt.NDArray[np.float64]
_I8 = npt.NDArray[np.int8]
_Real = Union[float, int, np.floating[Any], np.integer[Any]]
_ArrayIn = npt.ArrayLike
# the 12 profile arrays (s, z, z'' of wheel and roller, left and right) and
# the pair's 8 parameters of PAIR_FORMAT (gap.c, geometry.c)
_Pair = Any

# ---------------------------------------------------------------- constants
CMD_BUILTIN: int
CMD_SPEED: int
CMD_TORQUE: int
ERR_CONTROLLER: int
ERR_FRICTION_LIMIT: int
ERR_UNTRUSTED: int
EXACT_MARGIN: int
EXACT_MAX_GRID: int
FRICTION_MAX: float
GAP_APART: int
GAP_FAR: int
GAP_FOLD: int
GAP_GIVEN: int
GAP_H_BUFFER: int
GAP_MAX_N: int
GAP_MAX_RUNS: int
GAP_OFF_PROFILE: int
GAP_PATCH_NONFINITE: int
GAP_PATCH_REACHES: int
GAP_POINT: int
GAP_REGION_BEYOND: int
GAP_REGION_ENDS: int
GAP_REGION_LONG: int
GAP_RUNS: int
GAP_SCAN: int
GAP_TOO_MANY: int
GAP_WEIGHTED: int
GAP_WEIGHTS: int
NH_CORR: int
NH_CORR_LEN: int
NH_MAX_PATCHES: int
NH_NODES: int
NH_NQ: int
NH_PATCH_LEN: int
NH_ROW_COEFF: int
NH_ROW_GRID: int
NH_ROW_HEAD: int
NH_ROW_LEN: int
NH_ROW_NODE: int
NH_ROW_SOLVE: int
ODE_LINEULER: int
ODE_ROS2: int
ODE_TRBDF2: int
REC_COUNT: int
RIG_MAX_LIST: int
RIG_NSTATE: int
RIG_PROFILE_POINTS: int
SEARCH_MAX_SAMPLES: int
SPLINE_NATURAL: int
SPLINE_NOT_A_KNOT: int
STATUS_MAX: int
STATUS_MIN: int
TABLE_ROW: int
WHEEL_EXACT_CREEP: int
WHEEL_EXACT_EDGE: int
WHEEL_EXACT_GAP: int
WHEEL_EXACT_HERTZ: int
WHEEL_EXACT_SETTLE: int
WHEEL_EXACT_SOLVE: int

# (name, type, unit, default, lo, hi, lo_open, hi_open, choices, doc): a
# choice's default is its name and lo, hi None; an int option's are ints
_OptionRow = Tuple[str, str, str, Union[float, int, str], Optional[Union[float, int]],
                   Optional[Union[float, int]], bool, bool, Tuple[str, ...], str]
#: (name, doc, options, has_field, saturates, direct, coulomb_only, rig_ok, takes_grid)
METHODS: Tuple[Tuple[str, str, Tuple[_OptionRow, ...], bool, bool, bool, bool, bool, bool], ...]
#: (name, unit, type, default, lo, hi, lo_open, hi_open, choices, text, creep, origin,
#: option); default None for a creep row
RIG_PARAMETERS: Tuple[Tuple[str, str, str, Union[None, float, int, bool, str, Tuple[float, ...]],
                            float, float, bool, bool, Tuple[str, ...], Optional[str], bool, str,
                            Optional[str]], ...]
RIG_SECTIONS: Tuple[Tuple[str, str], ...]
RIG_RETIRED: Tuple[Tuple[str, str], ...]
#: (name, width, unit, meaning)
RIG_RECORD: Tuple[Tuple[str, int, str, str], ...]
RIG_WHEEL_FIELDS: Tuple[Tuple[str, int, str, str], ...]

# ---------------------------------------------------------------- types


@final
class CreepOptions:
    """Checked options for creep_forces1, creep_forces, fastsim_field and
    exact_hertz_problem (keywords only: method=..., <its options>)."""

    def __init__(self, **options: object) -> None: ...


@final
class Rig:
    """The rig's plant and controllers (rig.c): Rig(data, y0, dy, params,
    creep, mu0[, nonhertz])."""

    def __init__(self, data: _ArrayIn, y0: float, dy: float, params: Dict[str, object],
                 creep: Dict[str, object], mu0: float, nonhertz: object = ..., /) -> None: ...
    def run(self, roller_ref: _ArrayIn, xi_ref: _ArrayIn, options: object = ...,
            /) -> Tuple[_F64, int]: ...
    def sample(self, roller_ref: float, xi_ref: float, /) -> int: ...
    def read(self) -> Tuple[Tuple[float, float, float, float, float, float, float, float, float,
                                  float], int]: ...
    def write(self, roller_mode: int, roller_ref: float, wheelset_mode: int,
              wheelset_ref: float, mu0: float, /) -> int: ...
    def advance(self) -> Tuple[_F64, int]: ...
    def record(self) -> Tuple[_F64, int]: ...
    def rhs(self, t: float, y: _ArrayIn, /) -> Tuple[_F64, int]: ...
    def jac(self, t: float, y: _ArrayIn, /) -> Tuple[_F64, int]: ...
    def set_state(self, t: float, y: _ArrayIn, /) -> int: ...
    #: (names, values, status): the rig's whole state between samples
    def full_state(self) -> Tuple[Tuple[str, ...], _F64, int]: ...
    def set_full_state(self, values: _ArrayIn, /) -> int: ...
    @property
    def t(self) -> float: ...
    @property
    def y(self) -> _F64: ...
    @property
    def status(self) -> int: ...
    @property
    def info(self) -> Dict[str, Any]: ...

# ------------------------------------------------- contact (contact.c, batch.c)
# The elementwise functions take flat float64 arrays of one length (the
# package broadcasts them) and return float64 arrays and an int8 status.


def hertz(A: _ArrayIn, B: _ArrayIn, N: _ArrayIn, E1: _ArrayIn, nu1: _ArrayIn, E2: _ArrayIn,
          nu2: _ArrayIn, /) -> Tuple[_F64, _F64, _F64, _F64, _I8]: ...
def hertz1(A: _Real, B: _Real, N: _Real, E1: _Real, nu1: _Real, E2: _Real, nu2: _Real,
           /) -> Tuple[float, float, float, float, int]: ...
def kalker(a_over_b: _ArrayIn, nu: _ArrayIn, /) -> Tuple[_F64, _F64, _F64, _F64, _I8]: ...
def creep_forces(opts: CreepOptions, *case: _ArrayIn,
                 **options: object) -> Tuple[_F64, _F64, _F64, _I8]: ...
# (the method.c docstring says "-> None"; it returns the checked options)
def check_creep_options(func: str, options: Dict[str, object], /) -> CreepOptions: ...
def creep_forces1(opts: CreepOptions, cx: _Real, cy: _Real, cphi: _Real, a: _Real, b: _Real,
                  N: _Real, mu: _Real, G: _Real, nu: _Real, speed: _Real, A: _Real, B: _Real,
                  /) -> Tuple[float, float, float, int]: ...
def creep_blame(opts: CreepOptions, *case_and_status: object) -> Optional[str]: ...
def fastsim_field(*opts_and_case: object, **options: object) -> Tuple[
        float, float, float, int, _F64, _F64, _F64, _F64, _F64, _F64, _F64]: ...
def status_message(code: int, /) -> str: ...

# ------------------------------------------------------------ exact (exact.c)


def exact_hertz_problem(*opts_and_case: object, **options: object) -> Tuple[
        int, int, int, float, float, float, float, float, float, float, float, float, float,
        float, float, float, float, float, int]: ...
# (status, blamed, (mx, my, dx, dy, x0, y0), (fx, fy, mz, fn, ...), pn, px, py, sx, sy, state)
def exact_field(*opts_and_case: object, **options: object) -> Tuple[Any, ...]: ...
def exact_solve(opts: CreepOptions, h: _ArrayIn, dx: float, dy: float, x0: float, y0: float,
                N: float, mu: float, G: float, nu: float, cx: float, cy: float, cphi: float,
                /) -> Tuple[Any, ...]: ...
#: (shape, lo, hi, nu, r0, nx, float32 bytes)
def exact_table_builtin() -> Tuple[Tuple[int, int, int, int], Tuple[float, float, float, float],
                                   Tuple[float, float, float, float], float, float, int,
                                   bytes]: ...

# ------------------------------------------------- geometry (geometry.c, gap.c)


def wheelset_contact(*pair_and_args: Any) -> Tuple[Any, ...]: ...
def gap_build(*pair_and_args: Any) -> Tuple[int, _F64, Dict[str, Any]]: ...
def wheel_exact(*pair_and_args: Any) -> Tuple[Any, ...]: ...
def contact_table(*pair_and_args: Any) -> Tuple[_F64, int, float]: ...
def table_lookup(data: _ArrayIn, y0: float, dy: float, y: _ArrayIn,
                 /) -> Tuple[_I8, _F64, _F64, _F64, _F64, _F64, _F64]: ...
def spline_fit(y: _ArrayIn, z: _ArrayIn, end: object, /) -> Tuple[int, _F64, _F64, _F64, _F64]: ...
def analytic_profile(kind: object, param: float, y_min: float, y_max: float, n: object,
                     /) -> Tuple[int, _F64, _F64]: ...
def profile_table(wheel_y: _ArrayIn, wheel_z: _ArrayIn, wheel_end: object, roller_y: _ArrayIn,
                  roller_z: _ArrayIn, roller_end: object,
                  radii: Tuple[float, float, float, float], y0: float, dy: float, n: object,
                  nsamples: object, tol: float, sep: float, /) -> Tuple[_F64, int, float]: ...

# ------------------------------------------- rig (rig.c, rig_contact.c, rig_config.c)


def rig_contact(*args: Any, **options: object) -> Tuple[Any, ...]: ...
#: (status, pose[11, n]): the pose at y moving with the rates of y_rates
def rig_row_kinematics(data: _F64, y0: float, dy: float, model: Tuple[float, float],
                       x: _ArrayIn, y: _ArrayIn, yaw: _ArrayIn, vx: _ArrayIn, vy: _ArrayIn,
                       yaw_rate: _ArrayIn, spin: _ArrayIn, roller_spin: _ArrayIn,
                       y_rates: _ArrayIn, /) -> Tuple[_I8, _F64]: ...
def rig_schedule(roller_speed: float, roller_radius: float, targets: _ArrayIn,
                 target_start: _ArrayIn, T: float, first: int, stop: int,
                 /) -> Tuple[_F64, _F64]: ...
def rig_table(r0: float, R0: float, half_width: float, alpha: float, crown: float,
              half_spacing: float, half_range: float, rows: object,
              /) -> Tuple[_F64, float, float, int, float]: ...
def rig_profile_table(geometry: Tuple[Any, ...], scales: Tuple[float, float, float],
                      profiles: Tuple[Any, Any, Any, Any],
                      /) -> Tuple[Optional[_F64], float, float, int, float, int, int]: ...
#: ((stable, rho, lo, hi) of the roller's and of the wheelset's sampled speed loop)
def rig_speed_loops(params: Dict[str, object], /) -> Tuple[Tuple[bool, float, float, float],
                                                           Tuple[bool, float, float, float]]: ...
#: [(key, status, rule, other, entry, value, lo, hi), ...]
def rig_config_report(params: Dict[str, object], /) -> List[
        Tuple[str, int, str, Optional[str], int, float, float, float]]: ...

# ------------------------------------------------------ non-Hertzian (nonhertz.c)


def nonhertz_row(*pair_and_args: Any) -> Tuple[int, _F64, Dict[str, int]]: ...
def nonhertz_check(rows: _ArrayIn, head: Tuple[float, float, float, float, float],
                   /) -> Tuple[int, int]: ...
def nonhertz_wheel(rows: _ArrayIn, head: Tuple[float, float, float, float, float],
                   case: Tuple[float, ...], motion0: Tuple[Tuple[float, float, float], ...],
                   motion1: Tuple[Tuple[float, float, float], ...],
                   /) -> Tuple[int, Dict[str, Any], Tuple[Dict[str, Any], ...]]: ...
def nonhertz_locate(rows: _ArrayIn, head: Tuple[float, float, float, float, float], y: float,
                    /) -> Tuple[int, int, float]: ...
