"""Kalker's creep coefficients: the table nodes, linear interpolation in g, the
parabola in 1/C over nu, broadcasting."""
import numpy as np
import pytest

import rollerrig as rr
from reference_cases import read_csv

ROWS = read_csv("kalker_creep_coefficients.csv")[1]
# nu = 0.5 (incompressible) is the table's third column and accepted
NU_HALF = 0.5


def a_over_b(row):
    """a/b of a table row from its exact g (the a_over_b column is rounded, 3.333)."""
    g = float(row["g"])
    return g if row["table_half"] == "a<=b" else 1.0 / g


def table(half, nu):
    """{g: (C11, C22, C23)} of one half of the table at one tabulated nu."""
    return {float(r["g"]): (float(r["C11"]), float(r["C22"]), float(r["C23"]))
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


def test_nu_half_is_accepted_and_above_it_refused():
    """An incompressible body is physical: Kalker's table has nu = 0.5."""
    k = rr.kalker_coefficients(0.5, 0.5)
    assert (k.c11, k.c22, k.c23) == (4.83, 3.14, 1.07)       # Table E.3, a/b = 0.5
    with pytest.raises(rr.RollerRigError, match="nu = 0.5000000000000001"):
        rr.kalker_coefficients(1.0, float(np.nextafter(0.5, 1.0)))


def test_row_g_one_is_shared():
    """a/b = 1 is the last row of both halves: both give the same values."""
    for nu in (0.0, 0.25, NU_HALF):
        lo = rr.kalker_coefficients(1.0, nu)
        hi = rr.kalker_coefficients(np.nextafter(1.0, 2.0), nu)
        # 1 ulp of a/b moves g by 1e-16 and C by less than 1e-14
        np.testing.assert_allclose([lo.c11, lo.c22, lo.c23], [hi.c11, hi.c22, hi.c23],
                                   rtol=1e-14)


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
        for i, name in enumerate(("c11", "c22", "c23")):
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
        for i, name in enumerate(("c11", "c22", "c23")):
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
        for c in (k.c11, k.c22, k.c23):
            assert np.all(np.isfinite(c)) and np.all(c > 0)
    long = rr.kalker_coefficients(1.0 / g, 0.28)
    assert np.all(np.diff(long.c11) < 0) and np.all(np.diff(long.c22) < 0)


def test_broadcasting():
    k = rr.kalker_coefficients(0.5, 0.28)
    assert all(type(v) is float for v in (k.c11, k.c22, k.c23))
    assert type(k.status) is int and k.status == 0

    aob = np.array([[0.3], [1.0], [4.0]])
    nu = np.array([0.0, 0.1, 0.25, 0.4])
    kb = rr.kalker_coefficients(aob, nu)
    for v in (kb.c11, kb.c22, kb.c23, kb.status):
        assert v.shape == (3, 4)
    for i in range(3):
        for j in range(4):
            ks = rr.kalker_coefficients(float(aob[i, 0]), float(nu[j]))
            # each element is the same C computation as the scalar call: bitwise
            assert (kb.c11[i, j], kb.c22[i, j], kb.c23[i, j]) == (ks.c11, ks.c22, ks.c23)

    # default nu broadcasts; a 0-d array behaves like a scalar
    assert rr.kalker_coefficients(np.linspace(0.2, 5, 7)).c11.shape == (7,)
    assert type(rr.kalker_coefficients(np.float64(2.0)).c11) is float
