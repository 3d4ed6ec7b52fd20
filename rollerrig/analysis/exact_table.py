"""Creep-force tables built by the library's own exact theory (method
"exact_table").

For quasi-identical bodies and Coulomb friction the forces over mu N (and
the spin moment over mu N c, c = sqrt(ab)) depend only on nu, a/b and the
creepages over their saturation values.  The table's coordinates:

    x = cx C11 / s,  y = cy C22 / s,  z = cphi c C11 / s,  s = mu N / (G c^2)

(Kalker's coefficients of a/b and nu: the linear theory is fx = -x, fy =
-y - (C23 / C11) z there; the spin is scaled by C11, not C23, so that the
spin's rigid slip phi c is weighed as the creepage's: by C23 the spin of a
narrow ellipse saturates the patch at a few degrees from the creepage plane,
too sharp a ridge to interpolate.)  Two symmetries fold the space onto z >= 0,
x >= 0: all creepages reversed reverse the forces and the moment; the patch
mirrored in y maps (x, y, z) to (x, -y, -z) and (fx, fy, mz) to (fx, -fy,
-mz).  The folded point in spherical coordinates, the magnitude compacted:

    R = |(x, y, z)|,  alpha = atan2(hypot(x, y), z) in [0, pi/2] (0: pure spin),
    theta = atan2(y, x) in [-pi/2, pi/2],  u = R / (R + r0) in [0, 1],

and log(a/b) in [log 0.1, log 10]: four uniform axes.  The ends u = 0 (no
force) and u = 1 (full sliding: F = -mu int p w/|w| dA over Hertz's pressure
with the rigid slip w, by quadrature) are the analytic limits; inside, each
node is the exact theory extrapolated to the continuum (Richardson from nx
and 2 nx elements across, rr.exact_richardson).  The C core interpolates
with Catmull-Rom cubics along each axis (csrc/contact/rr_exact_table.c).

Rebuild the shipped table (about 130 000 nodes, some 40 CPU minutes):

    python -m rollerrig exact-table csrc/contact/rr_exact_table_data.c

then reinstall (`pip install .`); `--dask ADDRESS` builds on a Dask cluster.
"""
from __future__ import annotations

from dataclasses import dataclass
import math
import os
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

from .._typing import F64Array

#: the shipped table's nodes along (log a/b, alpha, theta, u)
DEFAULT_SHAPE = (21, 13, 23, 21)
#: the shipped table's r0, the scale of the compacted magnitude u = R / (R + r0)
R0 = 1.0
#: the range of a/b the tables cover (their first axis is log a/b)
AOB_RANGE = (0.1, 10.0)
#: the case every node is solved on (the normalised forces do not depend on it)
_C, _N, _MU, _G = 6e-3, 5e4, 0.3, 8.2e10
#: a path to write: a str or an os.PathLike of str, returned as given
_Path = Union[str, "os.PathLike[str]"]


@dataclass(frozen=True)
class ExactTable:
    """A table of normalised exact forces on four uniform axes.

    The axes are (log a/b, alpha, theta, u) (the module docstring defines
    them); the values are the forces at the folded point.

    See Also
    --------
    build_exact_table : builds one.
    creep_forces : method "exact_table" interpolates the built-in one.
    """

    lo: Tuple[float, ...]   #: the axes' lower ends (log a/b, alpha [rad], theta [rad], u)
    hi: Tuple[float, ...]   #: the axes' upper ends, as lo
    #: float32 of shape (n0, n1, n2, n3, 3) holding fx / (mu N), fy / (mu N),
    #: mz / (mu N c) at the folded point (c = sqrt(ab))
    values: npt.NDArray[np.float32]
    nu: float           #: the Poisson ratio [-] it was built for
    r0: float           #: the scale of u = R / (R + r0) it was built with
    nx: int             #: the coarse grid of the exact theory at each node (and 2 nx)

    @property
    def shape(self) -> Tuple[int, ...]:
        """The nodes along each of the four axes, (n0, n1, n2, n3)."""
        return self.values.shape[:4]

    def axes(self) -> List[F64Array]:
        """The four axes' node values, a list of 1-D arrays (log a/b, alpha, theta, u)."""
        return [np.linspace(lo, hi, n) for lo, hi, n in zip(self.lo, self.hi, self.shape)]

    def save(self, path: _Path) -> _Path:
        """Write the table as .npz at `path` and return `path`.

        The name ends in .npz; a new path or a regular file, replaced whole
        (rollerrig._files.write_file).  :meth:`load` reads it back.
        """
        from .._files import write_file
        write_file(path, lambda fh: np.savez_compressed(
            fh, lo=np.array(self.lo), hi=np.array(self.hi), values=self.values, nu=self.nu,
            r0=self.r0, nx=self.nx), what="ExactTable.save: path", binary=True, suffix=".npz")
        return path

    @classmethod
    def load(cls, path: _Path) -> ExactTable:
        """Read a table written by :meth:`save` (a .npz file at `path`)."""
        with np.load(path) as z:
            return cls(tuple(float(v) for v in z["lo"]), tuple(float(v) for v in z["hi"]),
                       z["values"].astype(np.float32), float(z["nu"]), float(z["r0"]),
                       int(z["nx"]))

    def write_c(self, path: _Path) -> _Path:
        """Write the table as C source, the core's built-in table, at `path`; return `path`.

        The name ends in .c; a new path or a regular file, replaced whole
        (rollerrig._files.write_file).
        """
        from .._files import write_file
        n = self.shape
        flat = self.values.astype(np.float32).ravel()
        # the header names this generator by the path it had when the shipped table
        # was written (now rollerrig/analysis/exact_table.py); tests/test_exact_table.py
        # holds csrc/contact/rr_exact_table_data.c to this text, so both change together
        lines = [
            "/* rr_exact_table_data.c - the built-in exact-theory table (generated by",
            " * `python -m rollerrig exact-table`, rollerrig/exact_table.py: do not edit).",
            f" * nu = {self.nu!r}, r0 = {self.r0!r}, nodes {n[0]} x {n[1]} x {n[2]} x {n[3]}"
            f" (log a/b, alpha, theta, u),",
            f" * each the exact theory extrapolated from {self.nx} and {2 * self.nx}"
            " elements across. */",
            '#include "contact/rr_exact_table.h"',
            "",
            f"static const float values[{flat.size}] = {{",
        ]
        row: List[str] = []
        for v in flat:
            row.append(f"{float(v):.9g}f" if v != 0 else "0")
            if len(row) == 8:
                lines.append("    " + ", ".join(row) + ",")
                row = []
        if row:
            lines.append("    " + ", ".join(row) + ",")
        lines += [
            "};",
            "",
            "const rr_exact_table rr_exact_table_builtin = {",
            f"    {{{n[0]}, {n[1]}, {n[2]}, {n[3]}}},",
            "    {" + ", ".join(repr(float(v)) for v in self.lo) + "},",
            "    {" + ", ".join(repr(float(v)) for v in self.hi) + "},",
            f"    {self.nu!r}, {self.r0!r}, {self.nx}, values",
            "};",
            "",
        ]
        write_file(path, lambda f: f.write("\n".join(lines)), what="ExactTable.write_c: path",
                   suffix=".c")
        return path


def builtin_table() -> ExactTable:
    """The table compiled into the C core (the one method "exact_table" uses).

    Returns
    -------
    ExactTable
        Its values read-only.

    Examples
    --------
    >>> from rollerrig.analysis.exact_table import builtin_table
    >>> table = builtin_table()
    >>> table.shape, table.nu, table.nx
    ((21, 13, 23, 21), 0.28, 27)
    """
    from .. import _core
    shape, lo, hi, nu, r0, nx, raw = _core.exact_table_builtin()
    values = np.frombuffer(raw, dtype=np.float32).reshape(tuple(shape) + (3,)).copy()
    values.setflags(write=False)
    return ExactTable(tuple(lo), tuple(hi), values, nu, r0, nx)


def _node_case(log_aob: F64Array, alpha: F64Array, theta: F64Array, u: F64Array, nu: float,
               r0: float) -> Tuple[F64Array, F64Array, F64Array, F64Array, F64Array]:
    """Creepages and semi-axes of the nodes (arrays), u < 1."""
    from ..contact.creep import kalker_coefficients
    aob = np.exp(log_aob)
    a, b = _C * np.sqrt(aob), _C / np.sqrt(aob)
    k = kalker_coefficients(aob, nu)
    s = _MU * _N / (_G * _C * _C)
    R = r0 * u / (1.0 - u)
    x = R * np.sin(alpha) * np.cos(theta)
    y = R * np.sin(alpha) * np.sin(theta)
    z = R * np.cos(alpha)
    return x * s / k.c11, y * s / k.c22, z * s / (_C * k.c11), a, b


def full_sliding(log_aob: npt.ArrayLike, alpha: npt.ArrayLike, theta: npt.ArrayLike,
                 nu: float, *, nr: int = 160, nb: int = 320) -> F64Array:
    """The full-sliding limit (u = 1) of the normalised forces.

    -mu p w/``|w|`` integrated over Hertz's pressure, w the rigid slip
    (cx - cphi y, cy + cphi x) in the direction (alpha, theta).

    Parameters
    ----------
    log_aob, alpha, theta : float or array_like
        The point: log(a/b), alpha [rad], theta [rad]; broadcast.
    nu : float
        Poisson ratio [-].
    nr, nb : int, optional
        Gauss-Legendre points in the radius of the unit disc, midpoint-rule
        points in the angle.

    Returns
    -------
    ndarray
        Shape (..., 3): fx / (mu N), fy / (mu N), mz / (mu N c).

    Notes
    -----
    The slip's direction jumps only at the spin centre, a point: the
    quadrature is accurate to about 1e-5.

    Examples
    --------
    Pure longitudinal sliding on a circle: fx = -mu N.

    >>> import numpy as np
    >>> from rollerrig.analysis.exact_table import full_sliding
    >>> full_sliding(0.0, np.pi / 2, 0.0, 0.28).round(4) + 0.0
    array([-1.,  0.,  0.])
    """
    from ..contact.creep import kalker_coefficients
    log_aob, alpha, theta = np.broadcast_arrays(*(np.asarray(v, float)
                                                  for v in (log_aob, alpha, theta)))
    aob = np.exp(log_aob)
    a, b = np.sqrt(aob), 1.0 / np.sqrt(aob)          # c = 1
    k = kalker_coefficients(aob, nu)
    cx = np.sin(alpha) * np.cos(theta) / k.c11
    cy = np.sin(alpha) * np.sin(theta) / k.c22
    cphi = np.cos(alpha) / k.c11
    t, wt = np.polynomial.legendre.leggauss(nr)
    rho = 0.5 * (t + 1.0)
    beta = (np.arange(nb) + 0.5) * (2 * np.pi / nb)
    # weights of the unit disc with Hertz's p / N = 3/(2 pi ab) sqrt(1 - rho^2), dA = ab rho
    w = (0.5 * wt * rho * np.sqrt(1.0 - rho * rho))[:, None] * (3.0 / nb) * np.ones(nb)
    cb, sb = np.cos(beta), np.sin(beta)
    out = np.empty(log_aob.shape + (3,))
    for i in np.ndindex(log_aob.shape):
        X = a[i] * rho[:, None] * cb
        Y = b[i] * rho[:, None] * sb
        wx = cx[i] - cphi[i] * Y
        wy = cy[i] + cphi[i] * X
        m = np.hypot(wx, wy)
        m[m == 0.0] = np.inf
        ux, uy = wx / m, wy / m
        out[i] = (-(w * ux).sum(), -(w * uy).sum(), -(w * (X * uy - Y * ux)).sum())
    return out


def node_values(log_aob: npt.ArrayLike, alpha: npt.ArrayLike, theta: npt.ArrayLike,
                u: npt.ArrayLike, *, nu: float, nx: int, r0: float = R0) -> Dict[str, F64Array]:
    """The table's values at nodes.

    Parameters
    ----------
    log_aob, alpha, theta, u : array_like
        The nodes' coordinates (1-D arrays of one length; alpha, theta
        [rad]).
    nu : float
        Poisson ratio [-].
    nx : int
        The exact theory's coarse grid (rr.exact_richardson from nx and 2
        nx); u = 0 gives 0, u = 1 the full-sliding limit.
    r0 : float, optional
        The scale of u = R / (R + r0).

    Returns
    -------
    dict
        {"fx", "fy", "mz"}: 1-D arrays of fx / (mu N), fy / (mu N),
        mz / (mu N c).
    """
    from ..contact.exact import exact_richardson
    log_aob, alpha, theta, u = (np.asarray(v, float) for v in (log_aob, alpha, theta, u))
    out = np.zeros(u.shape + (3,))
    inner = (u > 0.0) & (u < 1.0)
    if inner.any():
        cx, cy, cphi, a, b = _node_case(log_aob[inner], alpha[inner], theta[inner], u[inner],
                                        nu, r0)
        est, _ = exact_richardson(cx, cy, cphi, a=a, b=b, N=_N, mu=_MU, G=_G, nu=nu, nx=nx,
                                  errors="raise")
        muN = _MU * _N
        out[inner] = np.stack([est.fx / muN, est.fy / muN, est.mz / (muN * _C)], -1)
    edge = u >= 1.0
    if edge.any():
        out[edge] = full_sliding(log_aob[edge], alpha[edge], theta[edge], nu)
    return {"fx": out[:, 0], "fy": out[:, 1], "mz": out[:, 2]}


def build_exact_table(shape: Sequence[int] = DEFAULT_SHAPE, *, nu: float = 0.28, nx: int = 27,
                      r0: float = R0, backend: str = "threads", workers: Optional[int] = None,
                      client: Any = None, progress: Optional[bool] = None) -> ExactTable:
    """Build an ExactTable: the exact theory at every node.

    The nodes run through :func:`sweep` (on threads, or on a Dask cluster
    with client=, as the sweeps).

    Parameters
    ----------
    shape : tuple of 4 int, optional
        Nodes along (log a/b, alpha, theta, u), each >= 4 (odd theta for
        the symmetric middle node); default the shipped table's.
    nu : float, optional
        Poisson ratio [-], in [0, 0.5].
    nx : int, optional
        Elements across the ellipse of the coarse grid at each node (the
        fine grid has 2 nx; rr.exact_richardson).
    r0 : float, optional
        The scale of u = R / (R + r0).
    backend, workers, client, progress
        As for :func:`sweep`.

    Returns
    -------
    ExactTable
        The table (:class:`ExactTable`), symmetry zeros set exactly.

    Raises
    ------
    RollerRigError
        For a shape that is not four axes of >= 4 nodes, nu outside [0,
        0.5], and as sweep and exact_richardson.

    Notes
    -----
    The shipped table (about 130 000 nodes) takes some 40 CPU minutes.

    Examples
    --------
    A small table (a second or so):

    >>> import rollerrig as rr
    >>> table = rr.build_exact_table((4, 4, 5, 4), nx=5, progress=False)
    >>> table.shape, table.values.dtype
    ((4, 4, 5, 4), dtype('float32'))
    """
    from .sweep import sweep
    from .._errors import RollerRigError
    shape = tuple(int(v) for v in shape)
    if len(shape) != 4 or min(shape) < 4:
        raise RollerRigError(f"build_exact_table: shape = {shape}: four axes of >= 4 nodes")
    if not 0.0 <= nu <= 0.5:
        raise RollerRigError(f"build_exact_table: nu = {nu!r} outside [0, 0.5]")
    lo = (math.log(AOB_RANGE[0]), 0.0, -math.pi / 2, 0.0)
    hi = (math.log(AOB_RANGE[1]), math.pi / 2, math.pi / 2, 1.0)
    grid = {name: np.linspace(l, h, n) for name, l, h, n in
            zip(("log_aob", "alpha", "theta", "u"), lo, hi, shape)}

    res = sweep(node_values, grid, backend=backend, workers=workers, client=client,
                progress=progress, output="dict", chunk=64, nu=float(nu), nx=int(nx),
                r0=float(r0))
    values = np.stack([res["data"][k] for k in ("fx", "fy", "mz")], -1)
    return ExactTable(lo, hi, symmetry_zeros(values).astype(np.float32), float(nu), float(r0),
                      int(nx))


def symmetry_zeros(values: npt.ArrayLike) -> F64Array:
    """The forces that the symmetries make vanish, set to zero at the nodes.

    The solver leaves its round-off there, some 1e-7: fx where x = 0 (pure
    spin, alpha = 0, and theta = +-pi/2: reversed and mirrored, such a point
    maps onto itself with fx reversed); fy and mz where y = z = 0
    (alpha = pi/2, theta = 0: mirrored onto itself).  Needs odd theta nodes
    for the middle one.

    Parameters
    ----------
    values : array_like, shape (n0, n1, n2, n3, 3)
        A table's values.

    Returns
    -------
    ndarray
        A float64 copy with those values zero.
    """
    v = np.array(values, dtype=float)
    v[:, 0, :, :, 0] = 0.0
    v[:, :, 0, :, 0] = v[:, :, -1, :, 0] = 0.0
    if v.shape[2] % 2:
        v[:, -1, v.shape[2] // 2, :, 1:] = 0.0
    return v
