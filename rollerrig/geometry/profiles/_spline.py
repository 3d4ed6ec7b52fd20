"""Spline numerics of the profiles: the C2 interpolating cubic spline's node
slopes and the penalised least-squares smoothing spline (Reinsch 1967).
The package docstring (rollerrig.geometry.profiles) explains both."""
from __future__ import annotations

from typing import Optional, Tuple

import numpy as np

from ... import _core
from ..._errors import RollerRigError, status_message
from ..._typing import F64Array


def _spline_fit(y: F64Array, z: F64Array,
                bc: str) -> Tuple[F64Array, F64Array, F64Array, F64Array]:
    """The C2 cubic spline through (y, z), by the C core (rr_spline_fit,
    csrc/util/rr_spline.h: a C program builds the same spline, bit for bit):
    node slopes s [n], per-interval coefficients c2, c3 [n - 1] with
    z = z_i + t (s_i + t (c2_i + t c3_i)), t = y - y_i, and the second
    derivatives at the knots d2 [n] (the array the C geometry reads).

    Continuity of z'' at the interior nodes gives, for i = 1 .. n-2,
        h_i s_{i-1} + 2 (h_{i-1} + h_i) s_i + h_{i-1} s_{i+1}
            = 3 (h_i d_{i-1} + h_{i-1} d_i),
    with h_i = y_{i+1} - y_i and d_i = (z_{i+1} - z_i) / h_i.  The natural
    ends (z'' = 0) add 2 s_0 + s_1 = 3 d_0 and s_{n-2} + 2 s_{n-1} = 3 d_{n-2}:
    diagonally dominant.  The not-a-knot ends (z''' continuous at the second
    and the last-but-one node) add rows that are not dominant; each is
    eliminated into its neighbour, which leaves a dominant system in
    s_1 .. s_{n-2}; s_0 and s_{n-1} follow from the end rows.
    y, z: float64 arrays that passed Profile's checks; RollerRigError with
    the core's status otherwise.
    """
    end = _core.SPLINE_NATURAL if bc == "natural" else _core.SPLINE_NOT_A_KNOT
    status, s, c2, c3, d2 = _core.spline_fit(y, z, end)
    if status < 0:
        raise RollerRigError(f"Profile: the spline through these points: "
                             f"{status_message(status)}")
    return s, c2, c3, d2


def _solve_pentadiagonal_spd(d0: F64Array, d1: F64Array, d2: F64Array, b: F64Array
                             ) -> Tuple[Optional[F64Array], Optional[int]]:
    """Solve M x = b for a symmetric positive definite M given by its main
    diagonal d0, first and second super-diagonals d1, d2 (LDL^T, no pivoting).
    Returns (x, None), or (None, i) if pivot i is below 1e-12 of its diagonal
    entry: M's condition number then exceeds 1e12 and x keeps no digits
    worth having (a pivot of 0 made x NaN)."""
    m = len(d0)
    D = np.empty(m)
    L1 = np.zeros(m)   # L[i, i-1]
    L2 = np.zeros(m)   # L[i, i-2]
    for i in range(m):
        if i >= 2:
            L2[i] = d2[i - 2] / D[i - 2]
        if i >= 1:
            t = d1[i - 1] - (L2[i] * D[i - 2] * L1[i - 1] if i >= 2 else 0.0)
            L1[i] = t / D[i - 1]
        D[i] = d0[i] - L1[i] ** 2 * (D[i - 1] if i >= 1 else 0.0) \
            - L2[i] ** 2 * (D[i - 2] if i >= 2 else 0.0)
        if not D[i] > 1e-12 * d0[i]:
            return None, i
    x = np.array(b, dtype=float)
    for i in range(1, m):
        x[i] -= L1[i] * x[i - 1] + (L2[i] * x[i - 2] if i >= 2 else 0.0)
    x /= D
    for i in range(m - 2, -1, -1):
        x[i] -= L1[i + 1] * x[i + 1] + (L2[i + 2] * x[i + 2] if i + 2 < m else 0.0)
    return x, None


def _smoothing_weights(y: F64Array) -> F64Array:
    """Trapezoid weights: the lateral length each point stands for."""
    h = np.diff(y)
    w = np.empty(len(y))
    w[0] = 0.5 * h[0]
    w[-1] = 0.5 * h[-1]
    w[1:-1] = 0.5 * (h[:-1] + h[1:])
    return w


def _smooth(y: F64Array, z: F64Array,
            lam: float) -> Tuple[Optional[F64Array], Optional[int]]:
    """Values at the nodes of the natural cubic smoothing spline minimising
    sum w_i (z_i - f_i)^2 + lam * integral f''^2 (Reinsch's algorithm, Green
    and Silverman 1994, sec. 2.3): (R + lam Q^T W^-1 Q) g = Q^T z and
    f = z - lam W^-1 Q g, g the second derivatives at the interior nodes.
    Returns (f, None), or (None, j) if the system is numerically singular
    near node j (points far closer together than the smoothing length)."""
    w = _smoothing_weights(y)
    h = np.diff(y)
    # column j (interior node j = 1 .. n-2) of Q: rows j-1, j, j+1
    a = 1.0 / h[:-1]                    # Q[j-1, j]
    c = 1.0 / h[1:]                     # Q[j+1, j]
    b = -a - c                          # Q[j, j]
    wm, w0, wp = w[:-2], w[1:-1], w[2:]
    d0 = (h[:-1] + h[1:]) / 3.0 + lam * (a * a / wm + b * b / w0 + c * c / wp)
    d1 = h[1:-1] / 6.0 + lam * (b[:-1] * a[1:] / w0[:-1] + c[:-1] * b[1:] / wp[:-1])
    d2 = lam * (c[:-2] * a[2:] / wp[:-2])
    dz = np.diff(z) / h
    g, bad = _solve_pentadiagonal_spd(d0, d1, d2, dz[1:] - dz[:-1])
    if g is None:
        assert bad is not None      # (None, i) from the solver: i is set
        return None, bad + 1
    qg = np.zeros(len(y))
    qg[:-2] += a * g
    qg[1:-1] += b * g
    qg[2:] += c * g
    return z - lam * qg / w, None
