"""Kalker's creep coefficients: the table nodes, linear interpolation in g, the
parabola in 1/C over nu, C33's continuation below g = 0.1, the linear theory's
spin moment, broadcasting."""
import numpy as np
import pytest

import rollerrig as rr
from reference_cases import read_csv

ROWS = read_csv("kalker_creep_coefficients.csv")[1]
# C33 of the same table, a second, independent transcription (OpenVSD): its own
# file, its own source line
C33_SOURCE, C33_ROWS = read_csv("kalker_c33.csv")
# nu = 0.5 (incompressible) is the table's third column and accepted
NU_HALF = 0.5


def a_over_b(row):
    """a/b of a table row from its exact g (the a_over_b column is rounded, 3.333)."""
    g = float(row["g"])
    return g if row["table_half"] == "a<=b" else 1.0 / g


def c33_table(half, nu):
    """{g: C33} of one half of the C33 table at one tabulated nu; g = 1 (in the
    file's a <= b half only) belongs to both."""
    return {float(r["g"]): float(r["C33"]) for r in C33_ROWS
            if float(r["nu"]) == nu and (r["table_half"] == half or float(r["g"]) == 1.0)}


def table(half, nu):
    """{g: (C11, C22, C23, C33)} of one half of the table at one tabulated nu."""
    c33 = c33_table(half, nu)
    return {float(r["g"]): (float(r["C11"]), float(r["C22"]), float(r["C23"]),
                            c33[float(r["g"])])
            for r in ROWS if r["table_half"] == half and float(r["nu"]) == nu}


def test_every_node():
    aob = np.array([a_over_b(r) for r in ROWS])
    nu = np.array([float(r["nu"]) for r in ROWS])
    k = rr.kalker_coefficients(aob, nu)
    assert np.all(k.status == 0)
    for name in ("C11", "C22", "C23"):
        ref = np.array([float(r[name]) for r in ROWS])
        # the node values are copied from the same table: only the 1/(1/C) of the nu
        # parabola and a g = 1/(1/g) that lands 1 ulp off the node remain -> 1e-12
        np.testing.assert_allclose(getattr(k, name.lower()), ref, rtol=1e-12, err_msg=name)


def test_every_c33_node():
    assert "Table E.3" in C33_SOURCE and "C33" in C33_SOURCE
    assert len(C33_ROWS) == 57          # 19 g per nu: the two halves share g = 1
    aob = np.array([a_over_b(r) for r in C33_ROWS])
    nu = np.array([float(r["nu"]) for r in C33_ROWS])
    k = rr.kalker_coefficients(aob, nu)
    assert np.all(k.status == 0)
    ref = np.array([float(r["C33"]) for r in C33_ROWS])
    # as for the other coefficients: 1/(1/C) and g = 1/(1/g) only -> 1e-12
    np.testing.assert_allclose(k.c33, ref, rtol=1e-12)


def test_c33_file_has_the_creep_table_nodes():
    """The two transcriptions tabulate the same (half, g, nu) nodes."""
    def nodes(rows):
        return {(r["table_half"], float(r["g"]), float(r["nu"])) for r in rows}
    # the C33 file lists the shared row g = 1 once, in its a <= b half
    assert nodes(C33_ROWS) == nodes(ROWS) - {("a>=b", 1.0, nu) for nu in (0.0, 0.25, 0.5)}


def test_nu_half_is_accepted_and_above_it_refused():
    """An incompressible body is physical: Kalker's table has nu = 0.5."""
    k = rr.kalker_coefficients(0.5, 0.5)
    assert (k.c11, k.c22, k.c23, k.c33) == (4.83, 3.14, 1.07, 2.22)   # Table E.3, a/b = 0.5
    with pytest.raises(rr.RollerRigError, match="nu = 0.5000000000000001"):
        rr.kalker_coefficients(1.0, float(np.nextafter(0.5, 1.0)))


def test_row_g_one_is_shared():
    """a/b = 1 is the last row of both halves: both give the same values."""
    for nu in (0.0, 0.25, NU_HALF):
        lo = rr.kalker_coefficients(1.0, nu)
        hi = rr.kalker_coefficients(np.nextafter(1.0, 2.0), nu)
        # 1 ulp of a/b moves g by 1e-16 and C by less than 1e-14
        np.testing.assert_allclose([lo.c11, lo.c22, lo.c23, lo.c33],
                                   [hi.c11, hi.c22, hi.c23, hi.c33], rtol=1e-14)


@pytest.mark.parametrize("half", ["a<=b", "a>=b"])
def test_linear_in_g_between_nodes_at_quarter(half):
    """At nu = 0.25 (a tabulated nu) the coefficients are linear in g between nodes."""
    tab = table(half, 0.25)
    gs = sorted(tab)
    rng = np.random.default_rng(7)
    for g0, g1 in zip(gs[:-1], gs[1:]):
        t = np.concatenate([[0.25, 0.5, 0.75], rng.uniform(0.0, 1.0, 5)])
        g = g0 + t * (g1 - g0)
        aob = g if half == "a<=b" else 1.0 / g
        k = rr.kalker_coefficients(aob, 0.25)
        assert np.all(k.status == 0)
        for i, name in enumerate(("c11", "c22", "c23", "c33")):
            want = tab[g0][i] + t * (tab[g1][i] - tab[g0][i])
            # interpolation is C0 + frac (C1 - C0) in C; the parabola at nu = 0.25 is
            # 1/(1/C1); g through 1/(1/g) for the a >= b half: a few ulp -> 1e-12
            np.testing.assert_allclose(getattr(k, name), want, rtol=1e-12,
                                       err_msg=f"{half} {name} g in [{g0}, {g1}]")


@pytest.mark.parametrize("half", ["a<=b", "a>=b"])
def test_parabola_in_inverse_c_over_nu(half):
    """At a node g, 1/C is the parabola through the three tabulated nu."""
    nus = np.linspace(0.0, 0.49, 12)
    tabs = [table(half, v) for v in (0.0, 0.25, 0.5)]
    for g in sorted(tabs[0]):
        aob = g if half == "a<=b" else 1.0 / g
        k = rr.kalker_coefficients(aob, nus)
        for i, name in enumerate(("c11", "c22", "c23", "c33")):
            inv = [1.0 / t[g][i] for t in tabs]
            lagrange = (inv[0] * (nus - 0.25) * (nus - 0.5) / 0.125
                        - inv[1] * nus * (nus - 0.5) / 0.0625
                        + inv[2] * nus * (nus - 0.25) / 0.125)
            # same Lagrange form, different operation order: 1e-12
            np.testing.assert_allclose(getattr(k, name), 1.0 / lagrange, rtol=1e-12,
                                       err_msg=f"{half} {name} g={g}")


def test_small_g_asymptotes_are_finite_and_positive():
    """Below g = 0.1 Kalker's asymptotes take over: finite, positive, and C11, C22
    of the a >> b half keep growing as g falls (they scale like 1/(g ln(1/g)))."""
    g = np.geomspace(1e-4, 0.099, 40)
    for aob in (g, 1.0 / g):
        k = rr.kalker_coefficients(aob, 0.28)
        for c in (k.c11, k.c22, k.c23, k.c33):
            assert np.all(np.isfinite(c)) and np.all(c > 0)
    long = rr.kalker_coefficients(1.0 / g, 0.28)
    assert np.all(np.diff(long.c11) < 0) and np.all(np.diff(long.c22) < 0)


def test_c33_continuations_below_g_one_tenth():
    """CONTACT has no C33 asymptote.  a << b: strip theory's pi^2/(16 (1 - nu) g)
    plus the constant that meets the table at g = 0.1; a >> b: the table's value
    at g = 0.1, held (rr_kalker.h)."""
    g = np.geomspace(1e-6, 0.0999, 30)
    for nu in (0.0, 0.1, 0.25, 0.28, 0.4, NU_HALF):
        k0 = rr.kalker_coefficients(0.1, nu).c33
        k1 = rr.kalker_coefficients(10.0, nu).c33
        lead = np.pi ** 2 / (16 * (1 - nu))
        # the same closed form, other grouping: a few ulp of lead / g -> 1e-13
        np.testing.assert_allclose(rr.kalker_coefficients(g, nu).c33,
                                   lead / g + (k0 - lead / 0.1), rtol=1e-13)
        assert np.all(rr.kalker_coefficients(1.0 / g, nu).c33 == k1)
        # the leading term alone is within 5.5 % of the table at g = 0.1 (measured
        # 3.9 % at nu = 0, 5.4 % at nu = 0.5): the strip limit fits the table
        assert abs(lead / 0.1 / k0 - 1) < 0.055, nu


@pytest.mark.parametrize("half", ["a<=b", "a>=b"])
@pytest.mark.parametrize("nu", [0.0, 0.1, 0.25, 0.28, 0.4, NU_HALF])
def test_c33_continuous_at_g_one_tenth(half, nu):
    g = np.array([0.1 * (1 - 1e-12), 0.1 * (1 - 1e-9), 0.1])
    k = rr.kalker_coefficients(g if half == "a<=b" else 1.0 / g, nu)
    # both continuations meet the table by construction; C33 ~ 1/g moves by 1e-9
    # over the step of 1e-9 in g: 2e-9
    np.testing.assert_allclose(k.c33, k.c33[-1], rtol=2e-9)


@pytest.mark.parametrize("nu", [0.0, 0.25, 0.28, NU_HALF])
def test_c33_positive_and_decreasing_in_a_over_b(nu):
    """Spin resistance falls as the ellipse lengthens in the rolling direction:
    strictly where the table and the a << b continuation apply, flat beyond
    a/b = 10 (held)."""
    aob = np.geomspace(1e-4, 1e4, 4001)
    c = rr.kalker_coefficients(aob, nu).c33
    assert np.all(np.isfinite(c)) and np.all(c > 0)
    d = np.diff(c)
    assert np.all(d[aob[1:] < 10.0] < 0) and np.all(d <= 0)


def test_c33_between_tabulated_nu_nearly_monotone():
    """The parabola in 1/C over nu can bend C33 up slightly where the nu = 0.5
    column is small (a/b near 10): measured at most 0.98 % (nu = 0.085)."""
    aob = np.geomspace(1e-3, 1e3, 20001)
    worst = 0.0
    for nu in np.linspace(0.0, 0.5, 101):
        c = rr.kalker_coefficients(aob, nu).c33
        worst = max(worst, float(np.max(c / np.minimum.accumulate(c) - 1)))
    assert worst < 0.015


def test_linear_theory_spin_moment_against_the_table():
    """rr_linear's moment at every node of the C33 file: pure spin gives
    -G c^4 C33 cphi, pure lateral creepage G c^3 C23 cy, with the files' numbers."""
    # b a power of two: a / b is the node's a/b exactly (1 ulp below g = 0.1 the
    # asymptotes of C11, C22, C23 would take over, with their jump)
    G, cphi, cy, b = 8.2e10, 0.4, 1e-3, 2.0 ** -8
    creep = {(r["table_half"], float(r["g"]), float(r["nu"])): r for r in ROWS}
    for r in C33_ROWS:
        aob, nu = a_over_b(r), float(r["nu"])
        a = aob * b
        ab = a * b
        f = rr.creep_forces(0.0, 0.0, cphi, a=a, b=b, N=1e4, mu=0.3, G=G, nu=nu,
                            method="linear")
        # a node: C33 exact up to 1/(1/C), then a few roundings -> 1e-12
        assert f.mz == pytest.approx(-G * ab * ab * float(r["C33"]) * cphi, rel=1e-12), r
        c23 = float(creep[(r["table_half"], float(r["g"]), nu)]["C23"])
        f = rr.creep_forces(0.0, cy, 0.0, a=a, b=b, N=1e4, mu=0.3, G=G, nu=nu,
                            method="linear")
        assert f.mz == pytest.approx(G * ab * np.sqrt(ab) * c23 * cy, rel=1e-12), r


def test_broadcasting():
    k = rr.kalker_coefficients(0.5, 0.28)
    assert all(type(v) is float for v in (k.c11, k.c22, k.c23, k.c33))
    assert type(k.status) is int and k.status == 0

    aob = np.array([[0.3], [1.0], [4.0]])
    nu = np.array([0.0, 0.1, 0.25, 0.4])
    kb = rr.kalker_coefficients(aob, nu)
    for v in (kb.c11, kb.c22, kb.c23, kb.c33, kb.status):
        assert v.shape == (3, 4)
    for i in range(3):
        for j in range(4):
            ks = rr.kalker_coefficients(float(aob[i, 0]), float(nu[j]))
            # each element is the same C computation as the scalar call: bitwise
            assert (kb.c11[i, j], kb.c22[i, j], kb.c23[i, j], kb.c33[i, j]) == \
                (ks.c11, ks.c22, ks.c23, ks.c33)

    # default nu broadcasts; a 0-d array behaves like a scalar
    assert rr.kalker_coefficients(np.linspace(0.2, 5, 7)).c11.shape == (7,)
    assert type(rr.kalker_coefficients(np.float64(2.0)).c11) is float
