"""Spline numerics of the profiles: the C2 interpolating cubic spline's node
slopes and the penalised least-squares smoothing spline (Reinsch 1967).
The package docstring (rollerrig.profiles) explains both."""
import numpy as np

def _solve_tridiagonal(sub, diag, sup, rhs):
    """Thomas algorithm; sub[0] and sup[-1] are unused.  Stable for the
    diagonally dominant systems built below."""
    n = len(diag)
    c = np.empty(n)
    d = np.empty(n)
    c[0] = sup[0] / diag[0] if n > 1 else 0.0
    d[0] = rhs[0] / diag[0]
    for i in range(1, n):
        m = diag[i] - sub[i] * c[i - 1]
        c[i] = sup[i] / m if i < n - 1 else 0.0
        d[i] = (rhs[i] - sub[i] * d[i - 1]) / m
    x = np.empty(n)
    x[-1] = d[-1]
    for i in range(n - 2, -1, -1):
        x[i] = d[i] - c[i] * x[i + 1]
    return x


def _spline_slopes(y, z, bc):
    """Node slopes of the C2 cubic spline through (y, z).

    Continuity of z'' at the interior nodes gives, for i = 1 .. n-2,
        h_i s_{i-1} + 2 (h_{i-1} + h_i) s_i + h_{i-1} s_{i+1}
            = 3 (h_i d_{i-1} + h_{i-1} d_i),
    with h_i = y_{i+1} - y_i and d_i = (z_{i+1} - z_i) / h_i.  The natural
    ends (z'' = 0) add 2 s_0 + s_1 = 3 d_0 and s_{n-2} + 2 s_{n-1} = 3 d_{n-2}:
    diagonally dominant.  The not-a-knot ends (z''' continuous at the second
    and the last-but-one node) add rows that are not dominant; each is
    eliminated into its neighbour, which leaves a dominant system in
    s_1 .. s_{n-2}; s_0 and s_{n-1} follow from the end rows.
    """
    n = len(y)
    h = np.diff(y)
    d = np.diff(z) / h
    sub = np.zeros(n)
    diag = np.zeros(n)
    sup = np.zeros(n)
    rhs = np.zeros(n)
    sub[1:-1] = h[1:]
    diag[1:-1] = 2.0 * (h[:-1] + h[1:])
    sup[1:-1] = h[:-1]
    rhs[1:-1] = 3.0 * (h[1:] * d[:-1] + h[:-1] * d[1:])
    if bc == "natural":
        diag[0], sup[0], rhs[0] = 2.0, 1.0, 3.0 * d[0]
        sub[-1], diag[-1], rhs[-1] = 1.0, 2.0, 3.0 * d[-1]
        return _solve_tridiagonal(sub, diag, sup, rhs)
    # not-a-knot end rows
    w0 = h[0] + h[1]
    a0, c0 = h[1], w0
    r0 = ((h[0] + 2.0 * w0) * h[1] * d[0] + h[0] ** 2 * d[1]) / w0
    w1 = h[-1] + h[-2]
    an, bn = h[-2], w1
    rn = (h[-1] ** 2 * d[-2] + (2.0 * w1 + h[-1]) * h[-2] * d[-1]) / w1
    # row 1 -= (sub_1 / a0) row 0 ; row n-2 -= (sup_{n-2} / an) row n-1
    f = sub[1] / a0
    diag[1] -= f * c0
    rhs[1] -= f * r0
    sub[1] = 0.0
    g = sup[-2] / an
    diag[-2] -= g * bn
    rhs[-2] -= g * rn
    sup[-2] = 0.0
    s = np.empty(n)
    s[1:-1] = _solve_tridiagonal(sub[1:-1], diag[1:-1], sup[1:-1], rhs[1:-1])
    s[0] = (r0 - c0 * s[1]) / a0
    s[-1] = (rn - bn * s[-2]) / an
    return s


def _solve_pentadiagonal_spd(d0, d1, d2, b):
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


def _smoothing_weights(y):
    """Trapezoid weights: the lateral length each point stands for."""
    h = np.diff(y)
    w = np.empty(len(y))
    w[0] = 0.5 * h[0]
    w[-1] = 0.5 * h[-1]
    w[1:-1] = 0.5 * (h[:-1] + h[1:])
    return w


def _smooth(y, z, lam):
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
        return None, bad + 1
    qg = np.zeros(len(y))
    qg[:-2] += a * g
    qg[1:-1] += b * g
    qg[2:] += c * g
    return z - lam * qg / w, None
