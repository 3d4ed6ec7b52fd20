"""Pure-Python twin of parts of the rollerrig C core: the tests' slow reference.

Not part of the package: tests/test_twin.py compares each function here with
the C function it mirrors (and benchmarks/bench_contact.py times fastsim).

This module re-implements, with explicit loops and only the :mod:`math`
module, Kalker's creep coefficients (``csrc/contact/rr_kalker.c``), the friction
laws (``csrc/contact/rr_friction.c``), Kalker's linear theory and Polach's method
(``csrc/contact/rr_creep.c``) and FASTSIM with its blended and modified variants
(``csrc/contact/rr_fastsim.c``).  It is meant to be obviously correct rather than
fast: it follows the C formulas and their order of floating-point operations
wherever that matters for rounding (pressure normalisation, the march along
the rows, the Newton iteration of falling friction with its start, stopping
rule and step safeguard, the blending and modification of the
flexibilities), so its results agree with the C core to about 1e-12
relative.  It follows the C core as of commit 9bf61b0 (FASTSIM with the
"rect" or "strips" grid and the rigid slip taken at element centres); a
change of the C core that it does not follow fails test_twin.py.

Conventions (those of the C core, Kalker's and CONTACT's): SI units (m, s,
N, Pa, rad); x is the rolling direction, y lateral, z the normal into the
wheel; semi-axis ``a`` lies along x, ``b`` along y; material enters the
contact patch at x = +a.  The creepages ``cx`` (xi), ``cy`` (eta) [-] and
``cphi`` (phi) [rad/m] are the slip of the wheel relative to the roller (or
rail) divided by the rolling speed; with spin the rigid slip at (x, y) is
(cx - cphi y, cy + cphi x).  Forces act ON THE WHEEL: for small creepage
fx = -G a b C11 cx; mz is the sum of (x py - y px) dA about the patch
centre.

Invalid input raises :class:`ValueError` naming the offending argument (where
the C core returns an error status and NaN outputs).  A falling-friction
Newton iteration that hits its cap (the C status RR_WARN_NOT_CONVERGED) is
not reported: like the C core, the last iterate is used.  A friction
coefficient that underflows to exactly 0 (A = 0 with B w beyond about 745)
raises ValueError in Polach's method, which divides by it (the C core
returns NaN there); modified FASTSIM follows the C core (eps = inf) unless
alpha_inf = 0 makes the reduction factor 0, which raises ValueError.

References:

* J. J. Kalker, Three-Dimensional Elastic Bodies in Rolling Contact,
  Kluwer 1990, Table E.3 (creep coefficients), and the asymptotic formulas
  for g -> 0 of Kalker's thesis (1967) as used by E. Vollebregt's CONTACT
  (m_hertz.f90, linrol); C33 as transcribed in OpenVSD (tests/data/
  kalker_c33.csv).
* J. J. Kalker, "A fast algorithm for the simplified theory of rolling
  contact", Vehicle System Dynamics 11 (1982) 1-13 (FASTSIM).
* E. Vollebregt, P. Voltr, "Improved accuracy for FASTSIM using one or
  three flexibility values", Vehicle System Dynamics 61 (2023) 309
  (blended FASTSIM).
* M. Spiryagin, O. Polach, C. Cole, "Creep force modelling for rail
  traction vehicles based on the Fastsim algorithm", Vehicle System
  Dynamics 51 (2013) 1765-1783 (modified FASTSIM).
* O. Polach, "A fast wheel-rail forces calculation computer code", Vehicle
  System Dynamics 33 Suppl. (1999) 728-739 (Polach's method with spin).
* O. Polach, "Creep forces in simulations of traction vehicles running on
  adhesion limit", Wear 258 (2005) 992-1000 (falling friction, reduction
  factors kA, kS).
"""
import math

__all__ = ["kalker", "friction_mu", "linear", "polach", "fastsim"]

#: Largest FASTSIM grid dimension accepted (RR_FASTSIM_MAX_GRID).
MAX_GRID = 4096

#: Newton iterations for the falling-friction bound (FALLING_MAX_ITER).
FALLING_MAX_ITER = 50

# Kalker (1990) Table E.3: [half][row g = 0.1 * (i + 1)][C11, C22, C23, C33][nu = 0, 0.25, 0.5].
# half 0: a <= b (g = a/b); half 1: a >= b (g = b/a).  Row 9 (g = 1) is shared.
_KALKER_TABLE = (
    (   # a <= b
        ((2.51, 3.31, 4.85), (2.51, 2.52, 2.53), (0.334, 0.473, 0.731), (6.42, 8.28, 11.7)),
        ((2.59, 3.37, 4.81), (2.59, 2.63, 2.66), (0.483, 0.603, 0.809), (3.46, 4.27, 5.66)),
        ((2.68, 3.44, 4.80), (2.68, 2.75, 2.81), (0.607, 0.715, 0.889), (2.49, 2.96, 3.72)),
        ((2.78, 3.53, 4.82), (2.78, 2.88, 2.98), (0.720, 0.823, 0.977), (2.02, 2.32, 2.77)),
        ((2.88, 3.62, 4.83), (2.88, 3.01, 3.14), (0.827, 0.929, 1.07), (1.74, 1.93, 2.22)),
        ((2.98, 3.72, 4.91), (2.98, 3.14, 3.31), (0.930, 1.03, 1.18), (1.56, 1.68, 1.86)),
        ((3.09, 3.81, 4.97), (3.09, 3.28, 3.48), (1.03, 1.14, 1.29), (1.43, 1.50, 1.60)),
        ((3.19, 3.91, 5.05), (3.19, 3.41, 3.65), (1.13, 1.25, 1.40), (1.34, 1.37, 1.42)),
        ((3.29, 4.01, 5.12), (3.29, 3.54, 3.82), (1.23, 1.36, 1.51), (1.27, 1.27, 1.27)),
        ((3.40, 4.12, 5.20), (3.40, 3.67, 3.98), (1.33, 1.47, 1.63), (1.21, 1.19, 1.16)),
    ),
    (   # a >= b
        ((10.7, 11.7, 12.9), (10.7, 12.8, 16.0), (12.2, 14.6, 18.0), (0.795, 0.526, 0.228)),
        ((6.96, 7.78, 8.82), (6.96, 8.14, 9.79), (5.72, 6.63, 7.89), (0.828, 0.601, 0.341)),
        ((5.57, 6.34, 7.34), (5.57, 6.40, 7.51), (3.79, 4.32, 5.01), (0.868, 0.674, 0.446)),
        ((4.84, 5.57, 6.57), (4.84, 5.48, 6.31), (2.88, 3.24, 3.70), (0.912, 0.747, 0.549)),
        ((4.37, 5.10, 6.11), (4.37, 4.90, 5.56), (2.35, 2.62, 2.96), (0.958, 0.819, 0.650)),
        ((4.06, 4.78, 5.80), (4.06, 4.50, 5.04), (2.01, 2.23, 2.50), (1.01, 0.892, 0.751)),
        ((3.82, 4.54, 5.58), (3.82, 4.21, 4.67), (1.76, 1.95, 2.18), (1.05, 0.965, 0.852)),
        ((3.65, 4.36, 5.42), (3.65, 3.99, 4.39), (1.58, 1.75, 1.94), (1.10, 1.04, 0.954)),
        ((3.51, 4.22, 5.30), (3.51, 3.81, 4.16), (1.44, 1.59, 1.77), (1.16, 1.11, 1.06)),
        ((3.40, 4.12, 5.20), (3.40, 3.67, 3.98), (1.33, 1.47, 1.63), (1.21, 1.19, 1.16)),
    ),
)

_VARIANTS = ("fastsim", "blended", "modified")
_BOUNDS = ("parabolic", "elliptic")
_GRIDS = ("rect", "strips")
_SLIP_SPEEDS = ("local", "rigid")
_BLEND_RULES = ("contact", "spin")


# ---------------------------------------------------------------------------
# Input checks (the C core's rr_*_check functions, raising ValueError)
# ---------------------------------------------------------------------------

def _finite(name, value):
    """Return ``value`` as a float; ValueError naming ``name`` unless finite."""
    x = float(value)
    if not math.isfinite(x):
        raise ValueError(f"{name} must be finite, got {value!r}")
    return x


def _positive(name, value):
    """Return ``value`` as a float; ValueError naming ``name`` unless finite and > 0."""
    x = _finite(name, value)
    if not x > 0.0:
        raise ValueError(f"{name} must be > 0, got {value!r}")
    return x


def _in_range(name, value, lo, hi, lo_open=False, hi_open=False):
    """Return ``value`` as a float; ValueError naming ``name`` unless in the interval."""
    x = _finite(name, value)
    if (x <= lo if lo_open else x < lo) or (x >= hi if hi_open else x > hi):
        left = "(" if lo_open else "["
        right = ")" if hi_open else "]"
        raise ValueError(f"{name} must lie in {left}{lo}, {hi}{right}, got {value!r}")
    return x


def _check_nu(nu):
    """Poisson ratio: 0 <= nu <= 0.5 (RR_ERR_MATERIAL)."""
    return _in_range("nu", nu, 0.0, 0.5)


def _check_contact(a, b, N, G, nu, cx, cy, cphi, speed):
    """The contact problem's ellipse (rr_contact_problem_check): finite
    inputs, a, b, N, G > 0, 0 <= nu <= 0.5, speed >= 0.  Returns the inputs
    as floats."""
    a = _positive("a", a)
    b = _positive("b", b)
    N = _positive("N", N)
    G = _positive("G", G)
    nu = _check_nu(nu)
    cx = _finite("cx", cx)
    cy = _finite("cy", cy)
    cphi = _finite("cphi", cphi)
    speed = _finite("speed", speed)
    if speed < 0.0:
        raise ValueError(f"speed must be >= 0, got {speed!r}")
    return a, b, N, G, nu, cx, cy, cphi, speed


def _check_friction(mu0, A, B):
    """The friction law (rr_friction_check): mu0 > 0, 0 < A <= 1, B >= 0."""
    mu0 = _positive("mu0", mu0)
    A = _in_range("A", A, 0.0, 1.0, lo_open=True)
    B = _finite("B", B)
    if B < 0.0:
        raise ValueError(f"B must be >= 0, got {B!r}")
    return mu0, A, B


def _check_falling_speed(A, B, speed):
    """Falling friction needs a positive rolling speed (RR_ERR_SPEED)."""
    if _is_falling(A, B) and not speed > 0.0:
        raise ValueError(f"speed must be > 0 with falling friction (A < 1, B > 0), got {speed!r}")


def _check_grid_size(name, n):
    """A FASTSIM grid dimension: an integer in [1, MAX_GRID] (RR_ERR_GRID)."""
    if isinstance(n, bool):
        raise ValueError(f"{name} must be an integer, got {n!r}")
    try:
        k = int(n)
    except (TypeError, ValueError, OverflowError):
        raise ValueError(f"{name} must be an integer, got {n!r}") from None
    if k != n:
        raise ValueError(f"{name} must be an integer, got {n!r}")
    if not 1 <= k <= MAX_GRID:
        raise ValueError(f"{name} must lie in [1, {MAX_GRID}], got {n!r}")
    return k


def _check_choice(name, value, choices):
    """One of a few named options (RR_ERR_METHOD)."""
    if value not in choices:
        raise ValueError(f"{name} must be one of {', '.join(map(repr, choices))}, got {value!r}")
    return value


# ---------------------------------------------------------------------------
# Kalker's creep coefficients (rr_kalker.c)
# ---------------------------------------------------------------------------

def _nu_parabola(c, nu):
    """Lagrange parabola through 1/C at nu = 0, 0.25, 0.5, evaluated at nu.

    ``c`` holds C at the three tabulated Poisson ratios (Kalker 1990,
    Table E.3); the parabola is in 1/C, and its value is inverted back.
    At a tabulated nu the tabulated value itself is returned."""
    if nu in (0.0, 0.25, 0.5):
        return c[(0.0, 0.25, 0.5).index(nu)]
    inv = (8.0 * (nu - 0.25) * (nu - 0.5) / c[0]
           - 16.0 * nu * (nu - 0.5) / c[1]
           + 8.0 * nu * (nu - 0.25) / c[2])
    return 1.0 / inv


def _kalker_asymptotic(half, g, nu):
    """Kalker's asymptotes (thesis 1967, as in CONTACT's linrol) for
    g = min(a/b, b/a) -> 0.  ``half`` 0: a << b (narrow in the rolling
    direction); 1: a >> b (long in the rolling direction).  CONTACT has none
    for C33: for a << b strip theory's pi^2 / (16 (1 - nu) g) plus the
    constant that meets the table at g = 0.1, for a >> b the table's value
    at g = 0.1 (rr_kalker.h).
    Returns (C11, C22, C23, C33)."""
    pi = math.pi
    c33_row0 = _nu_parabola(_KALKER_TABLE[half][0][3], nu)
    if half == 0:
        k33 = pi * pi / (16.0 * (1.0 - nu))
        c11 = pi * pi / (4.0 * (1.0 - nu))
        c22 = pi * pi / 4.0
        c23 = pi * math.sqrt(g) / (3.0 * (1.0 - nu)) * (1.0 + nu * (math.log(16.0 / g) - 5.0))
        c33 = k33 / g + (c33_row0 - 10.0 * k33)
    else:
        lam = math.log(16.0) - 2.0 * math.log(g)     # g * g may underflow
        d22 = (1.0 - nu) * lam + 2.0 * nu
        c11 = (2.0 * pi / (g * (lam - 2.0 * nu))
               * (1.0 + (3.0 - math.log(4.0)) / (lam - 2.0 * nu)))
        c22 = 2.0 * pi / g * (1.0 + (1.0 - nu) * (3.0 - math.log(4.0)) / d22) / d22
        c23 = 2.0 * pi / (3.0 * g * math.sqrt(g) * ((1.0 - nu) * lam - 2.0 + 4.0 * nu))
        c33 = c33_row0
    return c11, c22, c23, c33


def _kalker_tabulated(half, g, nu):
    """Kalker (1990) Table E.3 for 0.1 <= g <= 1: linear interpolation in g
    of C at each tabulated nu, then the parabola in 1/C over nu.
    Returns (C11, C22, C23, C33)."""
    # rows are g = 0.1 (row 0) ... 1.0 (row 9); the last interval ends at row 9
    pos = 10.0 * g - 1.0
    if abs(pos - math.floor(pos + 0.5)) < 1e-12:
        pos = math.floor(pos + 0.5)     # 10 * 0.3 - 1 = 2.0000000000000004: a node
    row = int(pos)
    if row > 8:
        row = 8
    frac = pos - row
    coeffs = []
    for k in range(4):              # C11, C22, C23, C33
        col = []
        for j in range(3):          # nu = 0, 0.25, 0.5
            c0 = _KALKER_TABLE[half][row][k][j]
            c1 = _KALKER_TABLE[half][row + 1][k][j]
            col.append(c0 if frac == 0.0 else c0 + frac * (c1 - c0))
        coeffs.append(_nu_parabola(col, nu))
    return tuple(coeffs)


def kalker(a_over_b, nu):
    """Kalker's creep coefficients (C11, C22, C23, C33) of the linear theory.

    Reference: J. J. Kalker, Three-Dimensional Elastic Bodies in Rolling
    Contact, Kluwer 1990, Table E.3 (g = 0.1 ... 1; nu = 0, 0.25, 0.5), and
    the asymptotic formulas for g -> 0 of Kalker's thesis (1967) as used by
    E. Vollebregt's CONTACT (m_hertz.f90, linrol); C33's continuation below
    g = 0.1 (none in CONTACT) as in rr_kalker.h.

    ``a_over_b`` is the semi-axis along the rolling direction over the
    lateral one (> 0), g = min(a/b, b/a); ``nu`` the Poisson ratio,
    0 <= nu <= 0.5.  For 0.1 <= g <= 1 the table is interpolated linearly in
    g on C at each tabulated nu, then a parabola through 1/C over nu; for
    g < 0.1 Kalker's asymptotes are used.  The linear theory then reads
    Fx = -G c^2 C11 xi, Fy = -G c^2 C22 eta - G c^3 C23 phi,
    Mz = G c^3 C23 eta - G c^4 C33 phi, c = sqrt(ab).

    Raises ValueError naming the argument for invalid input.
    """
    a_over_b = _finite("a_over_b", a_over_b)
    if a_over_b <= 0.0:
        raise ValueError(f"a_over_b must be > 0, got {a_over_b!r}")
    nu = _check_nu(nu)
    half = 0 if a_over_b <= 1.0 else 1
    g = a_over_b if half == 0 else 1.0 / a_over_b
    if g < 0.1:
        return _kalker_asymptotic(half, g, nu)
    return _kalker_tabulated(half, g, nu)


# ---------------------------------------------------------------------------
# Friction laws (rr_friction.c): Coulomb and Polach's falling friction
# ---------------------------------------------------------------------------

def _is_falling(A, B):
    """True if the coefficient falls with slip (A < 1 and B > 0)."""
    return A < 1.0 and B > 0.0


def _mu(w, mu0, A, B):
    """Polach (2005): mu(w) = mu0 [(1 - A) exp(-B w) + A], unchecked."""
    return mu0 * ((1.0 - A) * math.exp(-B * w) + A)


def _dmu(w, mu0, A, B):
    """d mu / d w of Polach's law [s/m], unchecked; <= 0."""
    return -mu0 * (1.0 - A) * B * math.exp(-B * w)


def friction_mu(w, mu0, A=1.0, B=0.0):
    """Friction coefficient at slip speed ``w`` [m/s] >= 0.

    Reference: O. Polach, "Creep forces in simulations of traction vehicles
    running on adhesion limit", Wear 258 (2005) 992-1000:
    mu(w) = mu0 [(1 - A) exp(-B w) + A].  A = 1 (or B = 0) is Coulomb
    friction.  CONTACT's exponential law is the same curve with
    mu_kin = A mu0, mu_exp = (1 - A) mu0, half-value slip speed ln 2 / B.

    ``mu0`` > 0 is the static coefficient, 0 <= ``A`` <= 1 the ratio of the
    limit at infinite slip to mu0, ``B`` >= 0 the decay rate [s/m].
    Raises ValueError naming the argument for invalid input.
    """
    w = _finite("w", w)
    if w < 0.0:
        raise ValueError(f"w must be >= 0, got {w!r}")
    mu0, A, B = _check_friction(mu0, A, B)
    return _mu(w, mu0, A, B)


# ---------------------------------------------------------------------------
# Kalker's linear theory (rr_creep.c, rr_linear)
# ---------------------------------------------------------------------------

def linear(cx, cy, cphi, a, b, N, G, nu):
    """Creep forces on the wheel by Kalker's linear theory: (fx, fy, mz).

    Reference: J. J. Kalker, Three-Dimensional Elastic Bodies in Rolling
    Contact, Kluwer 1990 (Table E.3 for C11, C22, C23, C33):
        fx = -G c^2 C11 cx,  fy = -G c^2 C22 cy - G c^3 C23 cphi,
        mz = G c^3 C23 cy - G c^4 C33 cphi,  c = sqrt(ab).
    N does not enter (no saturation) but is checked like the C core does.
    """
    a, b, N, G, nu, cx, cy, cphi, _ = _check_contact(a, b, N, G, nu, cx, cy, cphi, 0.0)
    c11, c22, c23, c33 = kalker(a / b, nu)
    ab = a * b
    c3 = ab * math.sqrt(ab)
    fx = -G * ab * c11 * cx
    fy = -G * (ab * c22 * cy + c3 * c23 * cphi)
    mz = G * (c3 * c23 * cy - ab * ab * c33 * cphi)
    return fx, fy, mz


# ---------------------------------------------------------------------------
# Polach's method (rr_creep.c, rr_polach)
# ---------------------------------------------------------------------------

def _polach_spin_force(a, b, N, G, mu, c23, syc, sc, cphi):
    """Polach's (1999) lateral spin force F_yS through K_M.

    eps_M = 8/3 G b c C23 |s_yC| / (N mu k_s), k_s = 1 + 6.3 (1 - exp(-a/b)),
    delta = (eps_M^2 - 1)/(eps_M^2 + 1),
    K_M = eps_M (delta^3/3 - delta^2/2 + 1/6) - sqrt((1 - delta^2)^3)/3,
    F_yS = 9/16 a N mu K_M k_s cphi / s_C; its small-creepage limit (for
    cx = 0) is Kalker's -G c^3 C23 cphi."""
    ks = 1.0 + 6.3 * (1.0 - math.exp(-a / b))
    epsm = 8.0 / 3.0 * G * b * math.sqrt(a * b) * c23 * abs(syc) / (N * mu * ks)
    e2 = epsm * epsm
    d = (e2 - 1.0) / (e2 + 1.0)
    q = 1.0 - d * d
    km = epsm * (d * d * d / 3.0 - d * d / 2.0 + 1.0 / 6.0) - math.sqrt(q * q * q) / 3.0
    return 9.0 / 16.0 * a * N * mu * km * ks * cphi / sc


def polach(cx, cy, cphi, a, b, N, mu, G, nu, speed=0.0, A=1.0, B=0.0, kA=1.0, kS=1.0):
    """Creep forces on the wheel by Polach's method with spin: (fx, fy, mz).

    References: O. Polach, "A fast wheel-rail forces calculation computer
    code", Vehicle System Dynamics 33 Suppl. (1999) 728-739; O. Polach,
    Wear 258 (2005) 992-1000 (reduction factors kA, kS, falling friction).

    With s_yC = cy + cphi a if that grows |cy| (else cy), s_C = |(cx, s_yC)|,
    mu = mu(speed s_C) (``mu`` is the static mu0 of the friction law with
    ``A``, ``B``), eps = pi G a b C s_C / (4 N mu),
    C = |(C11 cx, C22 cy)| / |(cx, cy)|:
        F = 2 N mu / pi [kA eps / (1 + (kA eps)^2) + atan(kS eps)],
        fx = -F cx / s_C,  fy = -F cy / s_C + F_yS (Polach's spin force).
    The method gives no spin moment: mz = 0.  0 < kS <= kA <= 1; falling
    friction (A < 1, B > 0) needs speed > 0.
    """
    a, b, N, G, nu, cx, cy, cphi, speed = _check_contact(a, b, N, G, nu, cx, cy, cphi, speed)
    mu0, A, B = _check_friction(mu, A, B)
    kA = _in_range("kA", kA, 0.0, 1.0, lo_open=True)
    kS = _in_range("kS", kS, 0.0, kA, lo_open=True)      # Polach: kS <= kA
    _check_falling_speed(A, B, speed)
    c11, c22, c23, _ = kalker(a / b, nu)

    fx = fy = mz = 0.0
    # spin adds to the lateral creepage only where it increases it
    syc = cy + cphi * a
    if abs(syc) <= abs(cy):
        syc = cy
    sc = math.hypot(cx, syc)
    if sc == 0.0:
        return fx, fy, mz
    s = math.hypot(cx, cy)
    mu_c = _mu(speed * sc, mu0, A, B)
    if mu_c == 0.0:
        raise ValueError("A, B: the friction coefficient at the rigid slip speed underflows "
                         "to 0 (A = 0, B w > ~745); Polach's method divides by it (the C "
                         "core returns NaN there)")
    if s > 0.0:
        cjj = math.hypot(c11 * cx, c22 * cy) / s
        eps = math.pi * G * a * b * cjj * sc / (4.0 * N * mu_c)
        F = 2.0 * N * mu_c / math.pi * (kA * eps / (1.0 + kA * eps * kA * eps) + math.atan(kS * eps))
        fx = -F * cx / sc
        fy = -F * cy / sc
    if cphi != 0.0:
        fy += _polach_spin_force(a, b, N, G, mu_c, c23, syc, sc, cphi)
    return fx, fy, mz


# ---------------------------------------------------------------------------
# FASTSIM and its variants (rr_fastsim.c)
# ---------------------------------------------------------------------------

def _kalker_flexibilities(a, b, G, c11, c22, c23):
    """Kalker's (1982) three flexibilities of the simplified theory [m/Pa]:
    L1 = 8a/(3 C11 G), L2 = 8a/(3 C22 G), L3 = pi a sqrt(a/b)/(4 C23 G)."""
    L1 = 8.0 * a / (3.0 * c11 * G)
    L2 = 8.0 * a / (3.0 * c22 * G)
    L3 = math.pi * a * math.sqrt(a / b) / (4.0 * c23 * G)
    return L1, L2, L3


def _blend_flexibilities(L1, L2, L3, cx, cy, cphi, a, b, N, G, mu0, c11, c22, c23,
                         rule="contact"):
    """Blended FASTSIM (Vollebregt and Voltr 2023): move each L_i toward the
    single flexibility L = (cx^2 + cy^2 + pe^2)/(cx^2/L1 + cy^2/L2 + pe^2/L3),
    pe = 3 pi a cphi/32 (CONTACT's simpflex), with weight w = min(1, f/3).
    With the characteristic creepages ch_x = mu0 N/(G c^2 C11),
    ch_y = mu0 N/(G c^2 C22), ch_phi = mu0 N/(G c^3 C23): rule "contact"
    (CONTACT's simpflex) f = |(cx, cy)|/|(ch_x, ch_y)|, no spin; rule
    "spin" f = |(cx/ch_x, cy/ch_y, cphi/ch_phi)|."""
    ab = a * b
    cc = math.sqrt(ab)
    sat = mu0 * N / G
    if rule == "contact":
        chx = sat / (ab * c11)
        chy = sat / (ab * c22)
        w = math.hypot(cx, cy) / math.hypot(chx, chy) / 3.0
    else:
        fx = cx * ab * c11 / sat
        fy = cy * ab * c22 / sat
        fp = cphi * ab * cc * c23 / sat
        w = math.sqrt(fx * fx + fy * fy + fp * fp) / 3.0
    if w > 1.0:
        w = 1.0
    if w > 0.0:
        pe = cphi * 3.0 * math.pi * a / 32.0
        x2 = cx * cx
        y2 = cy * cy
        p2 = pe * pe
        L = (x2 + y2 + p2) / (x2 / L1 + y2 / L2 + p2 / L3)
        L1 += w * (L - L1)
        L2 += w * (L - L2)
        L3 += w * (L - L3)
    return L1, L2, L3


def _modify_flexibilities(L1, L2, L3, cx, cy, cphi, a, b, N, G, c11, mu_rigid,
                          k0, alpha_inf, beta):
    """Modified FASTSIM (Spiryagin, Polach and Cole 2013; CONTACT's
    fastsim_params): divide every L_i by
    k = k0 (alpha_inf + (1 - alpha_inf)/(1 + beta eps)),
    eps = pi G a b k0 C11 |(cx, cy + a cphi)| / (4 mu N), the spin term kept
    only where it grows |cy|, mu at the rigid slip speed.  A mu that
    underflows to 0 (A = 0, B w beyond about 745) gives eps = inf, as the
    C core's division does: the full reduction k = k0 alpha_inf."""
    nphi = cy + cphi * a
    if abs(nphi) < abs(cy):
        nphi = cy
    if mu_rigid == 0.0:
        eps = math.inf
    else:
        eps = math.pi * G * a * b * k0 * c11 * math.hypot(cx, nphi) / (4.0 * mu_rigid * N)
    kf = k0 * (alpha_inf + (1.0 - alpha_inf) / (1.0 + beta * eps))
    if kf == 0.0:
        raise ValueError("alpha_inf: the flexibility reduction factor k0 (alpha_inf + ...) is 0 "
                         "(alpha_inf = 0 with mu at the rigid slip speed underflowing to 0)")
    return L1 / kf, L2 / kf, L3 / kf


def _pressure_shape(bound, q):
    """Pressure shape at q = 1 - x^2/a^2 - y^2/b^2 > 0: q (Kalker's
    parabolic bound) or sqrt(q) (Hertzian, elliptic bound)."""
    return q if bound == "parabolic" else math.sqrt(q)


def _row_geometry(j, ny, a, b, grid):
    """Row j of the grid: (w2, y, aj) with y_j/b = (2 j + 1 - ny)/ny (rows j
    and ny - 1 - j at exactly -y and y), w2 = 1 - y_j^2/b^2, and aj the
    row's half-length: a ("rect", the ellipse's bounding box) or a sqrt(w2)
    ("strips", the row's own chord)."""
    yh = (2.0 * j + 1.0 - ny) / ny
    w2 = 1.0 - yh * yh
    y = yh * b
    aj = a * math.sqrt(w2) if grid == "strips" else a
    return w2, y, aj


def _pressure_scale(a, b, N, nx, ny, bound, grid):
    """Scale of the pressure p = scale * shape(q) at the element centres so
    that it sums to N over the grid (full sliding then gives exactly
    |F| = mu N).  The sum runs over the element centres x = ((nx - 1)/2 - i) h
    of every row (elements i and nx - 1 - i at exactly -x and x), computed
    as in the march, empty elements (q <= 0) left out."""
    dy = 2.0 * b / ny
    S = 0.0
    for j in range(ny):
        w2, _, aj = _row_geometry(j, ny, a, b, grid)
        h = 2.0 * aj / nx
        row = 0.0
        for i in range(nx):
            t = ((0.5 * (nx - 1) - i) * h) / a
            q = w2 - t * t
            if q > 0.0:
                row += _pressure_shape(bound, q)
        S += row * h
    return N / (S * dy)


def _falling_bound(speed, pn, m, leff_step, mu0, A, B):
    """Traction bound g = mu(speed s) pn of a slipping element with falling
    friction at its own slip speed (rr_fastsim.h, RR_SLIP_LOCAL; friction
    law of Polach 2005).

    The slip ratio s solves s = leff_step (m - mu(speed s) pn), m = |p*|
    the adhesion trial traction.  The residual is convex and increasing past
    its root; Newton's method from the kinetic bound (mu = A mu0) approaches
    the root from above.  Safeguard: a step larger than s is replaced by
    s/2; stop when |ds| <= 1e-13 s or |f| <= 8e-16 leff_step m (rounding
    noise), else after FALLING_MAX_ITER steps.  Returns (g, converged)."""
    s = leff_step * (m - A * mu0 * pn)
    for _ in range(FALLING_MAX_ITER):
        v = speed * s
        f = s - leff_step * (m - _mu(v, mu0, A, B) * pn)
        df = 1.0 + leff_step * pn * speed * _dmu(v, mu0, A, B)
        ds = f / df if df > 0.0 else 0.0
        if ds > s:
            ds = 0.5 * s        # never step below zero slip
        s -= ds
        if abs(ds) <= 1e-13 * s or abs(f) <= 8e-16 * leff_step * m:
            return _mu(speed * s, mu0, A, B) * pn, True
    return _mu(speed * s, mu0, A, B) * pn, False


def _march_row(j, nx, ny, a, b, bound, grid, scale, L1, L2, L3, cx, cy, cphi,
               mu_bound, local, speed, mu0, A, B):
    """Kalker's (1982) explicit march along row j from the leading edge.

    Each element inside the ellipse adds its rigid slip, taken at its
    centre, divided by the flexibilities, times one element length h to its
    upstream neighbour's traction (the first element inside the contact
    starts from zero traction); the trial traction is then limited to the
    bound mu pn.  Elements outside the ellipse (only on the "rect" grid)
    carry no pressure or traction.  Returns the row's sums (sx, sy, sm) of
    px, py and x py - y px, its element length h, and its elements as a
    list, in march order (x decreasing), of (x, y, pn, px, py, slip)."""
    w2, y, aj = _row_geometry(j, ny, a, b, grid)
    h = 2.0 * aj / nx
    # rigid slip per unit length divided by the flexibility
    gx = cx / L1 - cphi * y / L3
    gy = cy / L2
    gphi = cphi / L3

    px = 0.0
    py = 0.0
    sx = sy = sm = 0.0
    elements = []
    for i in range(nx):
        x = (0.5 * (nx - 1) - i) * h
        t = x / a
        q = w2 - t * t
        pn = 0.0
        slip = False
        if q > 0.0:
            pn = scale * _pressure_shape(bound, q)
            tx = px - gx * h
            ty = py - (gy + gphi * x) * h
            m2 = tx * tx + ty * ty
            g = mu_bound * pn
            slip = m2 > g * g
            if slip:
                m = math.sqrt(m2)
                if local:
                    lx = L1 * tx
                    ly = L2 * ty
                    g, _ = _falling_bound(speed, pn, m, math.sqrt(lx * lx + ly * ly) / (m * h),
                                          mu0, A, B)
                px = tx * (g / m)
                py = ty * (g / m)
            else:
                px = tx
                py = ty
            sx += px
            sy += py
            sm += x * py - y * px
        else:
            px = py = 0.0       # outside the ellipse: no contact
        elements.append((x, y, pn, px, py, 1 if slip else 0))
    return sx, sy, sm, h, elements


def fastsim(cx, cy, cphi, a, b, N, mu, G, nu, speed=0.0, A=1.0, B=0.0, nx=30, ny=30,
            bound="parabolic", variant="fastsim", k0=0.54, alpha_inf=0.02, beta=0.62,
            slip_speed=None, field=False, grid="rect", blend_rule="contact"):
    """Creep forces on the wheel by FASTSIM: (fx, fy, mz), or with
    ``field=True`` (fx, fy, mz, dict(x, y, pn, px, py, slip)).

    References: J. J. Kalker, "A fast algorithm for the simplified theory of
    rolling contact", Vehicle System Dynamics 11 (1982) 1-13 (three
    flexibilities L1 = 8a/(3 C11 G), L2 = 8a/(3 C22 G),
    L3 = pi a sqrt(a/b)/(4 C23 G), parabolic traction bound, march from the
    leading edge); E. Vollebregt, P. Voltr, Vehicle System Dynamics 61
    (2023) 309 (``variant="blended"``: from three flexibilities to one as
    the creepage grows); M. Spiryagin, O. Polach, C. Cole, Vehicle System
    Dynamics 51 (2013) 1765-1783 (``variant="modified"``: flexibilities
    divided by k0 (alpha_inf + (1 - alpha_inf)/(1 + beta eps))); O. Polach,
    Wear 258 (2005) 992-1000 (falling friction with ``A``, ``B``; ``mu`` is
    its static mu0).

    Grid: ``ny`` rows of width 2b/ny, each cut into ``nx`` equal elements,
    pressure and traction at the centres, the pressure scaled to sum to N.
    ``grid`` "rect" (the C default: rows span the ellipse's bounding box
    |x| <= a, elements outside the ellipse empty, CONTACT's grid) or
    "strips" (each row spans its own chord, Kalker's strips).  ``bound``
    "parabolic" (Kalker's original) or "elliptic" (Hertzian).  With falling
    friction, ``slip_speed`` "local" uses each slipping element's own slip
    speed (Newton's method), "rigid" one mu at the rigid slip speed
    |(cx, cy)| speed; None means "rigid" for the modified variant, else
    "local".  ``k0``, ``alpha_inf``, ``beta`` are used (and checked) only
    by the modified variant, ``blend_rule`` ("contact" or "spin", see
    _blend_flexibilities) only by the blended one.

    The field is given as nested lists [ny][nx], rows j along y and x
    increasing along the inner index i (the C layout j * nx + i); ``slip``
    holds 1 (slip) or 0 (adhesion); elements outside the ellipse have zero
    pressure and traction.
    """
    variant = _check_choice("variant", variant, _VARIANTS)
    bound = _check_choice("bound", bound, _BOUNDS)
    grid = _check_choice("grid", grid, _GRIDS)
    if slip_speed is None:
        slip_speed = "rigid" if variant == "modified" else "local"
    slip_speed = _check_choice("slip_speed", slip_speed, _SLIP_SPEEDS)
    if variant == "blended":
        blend_rule = _check_choice("blend_rule", blend_rule, _BLEND_RULES)
    nx = _check_grid_size("nx", nx)
    ny = _check_grid_size("ny", ny)
    if variant == "modified":
        k0 = _in_range("k0", k0, 0.0, 1.0, lo_open=True)
        alpha_inf = _in_range("alpha_inf", alpha_inf, 0.0, 1.0)
        beta = _finite("beta", beta)
        if beta < 0.0:
            raise ValueError(f"beta must be >= 0, got {beta!r}")
    a, b, N, G, nu, cx, cy, cphi, speed = _check_contact(a, b, N, G, nu, cx, cy, cphi, speed)
    mu0, A, B = _check_friction(mu, A, B)
    _check_falling_speed(A, B, speed)
    c11, c22, c23, _ = kalker(a / b, nu)

    falling = _is_falling(A, B)
    mu_rigid = _mu(speed * math.hypot(cx, cy), mu0, A, B)
    L1, L2, L3 = _kalker_flexibilities(a, b, G, c11, c22, c23)
    if variant == "blended":
        L1, L2, L3 = _blend_flexibilities(L1, L2, L3, cx, cy, cphi, a, b, N, G, mu0,
                                          c11, c22, c23, blend_rule)
    elif variant == "modified":
        L1, L2, L3 = _modify_flexibilities(L1, L2, L3, cx, cy, cphi, a, b, N, G, c11,
                                           mu_rigid, k0, alpha_inf, beta)

    # local: mu from each element's own slip speed; rigid: one mu at the
    # rigid slip speed |(cx, cy)| speed for the whole patch
    local = falling and slip_speed == "local"
    mu_bound = mu_rigid if falling and not local else mu0

    scale = _pressure_scale(a, b, N, nx, ny, bound, grid)
    dy = 2.0 * b / ny
    fx = fy = mz = 0.0
    rows = []
    for j in range(ny):
        sx, sy, sm, h, elements = _march_row(j, nx, ny, a, b, bound, grid, scale, L1, L2, L3,
                                             cx, cy, cphi, mu_bound, local, speed, mu0, A, B)
        fx += sx * h
        fy += sy * h
        mz += sm * h
        rows.append(elements[::-1])     # x increasing along the row
    forces = (fx * dy, fy * dy, mz * dy)
    if not field:
        return forces
    names = ("x", "y", "pn", "px", "py", "slip")
    out = {name: [[element[k] for element in row] for row in rows]
           for k, name in enumerate(names)}
    return forces + (out,)


# --------------------------------------------------------------------------
# the exact-theory table (csrc/contact/rr_exact_table.c)
# --------------------------------------------------------------------------

def _table_weights(n, lo, hi, q):
    """Catmull-Rom weights of nodes j0 .. j0 + 3 on an axis of n nodes, the
    node past an end replaced by the quadratic through the nearest three."""
    pos = (q - lo) / (hi - lo) * (n - 1)
    pos = min(max(pos, 0.0), n - 1)
    i = min(int(pos), n - 2)
    s = pos - i
    s2, s3 = s * s, s * s * s
    g = (0.5 * (-s3 + 2.0 * s2 - s), 0.5 * (3.0 * s3 - 5.0 * s2 + 2.0),
         0.5 * (-3.0 * s3 + 4.0 * s2 + s), 0.5 * (s3 - s2))
    if i == 0:
        return 0, (g[1] + 3.0 * g[0], g[2] - 3.0 * g[0], g[3] + g[0], 0.0)
    if i == n - 2:
        return n - 4, (0.0, g[0] + g[3], g[1] - 3.0 * g[3], g[2] + 3.0 * g[3])
    return i - 1, g


def exact_table(table, cx, cy, cphi, a, b, N, mu, G, nu, speed=0.0, A=1.0, B=0.0):
    """Forces from an exact-theory table (rollerrig.analysis.exact_table.ExactTable):
    the C lookup in loops, (fx, fy, mz) on the wheel."""
    _check_contact(a, b, N, G, nu, cx, cy, cphi, speed)
    _check_friction(mu, A, B)
    _check_falling_speed(A, B, speed)
    if abs(nu - table.nu) > 1e-9:
        raise ValueError(f"nu = {nu!r}: the table holds nu = {table.nu!r}")
    la = math.log(a / b)
    if not table.lo[0] - 1e-12 * abs(table.lo[0]) <= la <= table.hi[0] + 1e-12 * abs(table.hi[0]):
        raise ValueError(f"a/b = {a / b!r} outside the table")
    c11, c22, c23, c33 = kalker(a / b, nu)
    cc = math.sqrt(a) * math.sqrt(b)
    for e in range(5):
        x, y = math.ldexp(cx, -600 * e) * c11, math.ldexp(cy, -600 * e) * c22
        z = math.ldexp(cphi, -600 * e) * cc * c11
        if all(math.isfinite(v) for v in (x, y, z)):
            break
    m = max(abs(x), abs(y), abs(z))
    if m == 0.0:
        return 0.0, 0.0, 0.0
    muN = friction_mu(speed * math.hypot(cx, cy), mu, A, B) * N
    sign = sx = 1.0
    if z < 0.0:
        sign, x, y, z = -1.0, -x, -y, -z
    if x < 0.0:
        sx, x = -1.0, -x
    sy = 1.0
    if z == 0.0 and y < 0.0:
        sy, y = -1.0, -y
    R = m * math.sqrt((x / m) ** 2 + (y / m) ** 2 + (z / m) ** 2) / (muN / G / cc / cc)
    R = math.ldexp(R, 600 * e)
    q = (la, math.atan2(math.hypot(x, y), z), math.atan2(y, x), 1.0 / (1.0 + table.r0 / R))
    n = table.values.shape[:4]
    base, w = zip(*(_table_weights(n[d], table.lo[d], table.hi[d], q[d]) for d in range(4)))
    f = [0.0, 0.0, 0.0]
    for i0 in range(4):
        for i1 in range(4):
            for i2 in range(4):
                for i3 in range(4):
                    wt = w[0][i0] * w[1][i1] * w[2][i2] * w[3][i3]
                    v = table.values[base[0] + i0, base[1] + i1, base[2] + i2, base[3] + i3]
                    for k in range(3):
                        f[k] += wt * float(v[k])
    if x == 0.0:
        f[0] = 0.0
    if y == 0.0 and z == 0.0:
        f[1] = f[2] = 0.0
    h = math.hypot(f[0], f[1])
    if h > 1.0:
        f[0], f[1] = f[0] / h, f[1] / h
    return sign * sx * f[0] * muN, sign * sy * f[1] * muN, sign * sy * f[2] * muN * cc
