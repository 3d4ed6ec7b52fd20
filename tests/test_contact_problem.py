"""The contact problem as every method's input (issue 24, item 1), as Python
sees it: which methods take a problem on a grid, the rig's reason for
refusing a method, and messages that name the argument the C core blames
(its problem check's report, rr_creep_blame, or the C function itself),
never one guessed from rules restated in Python."""
import numpy as np
import pytest

import rollerrig as rr
from rollerrig import _core

CASE = dict(a=6e-3, b=4e-3, N=1e4, mu=0.3)
BOWL = 50.0 * ((np.arange(15) - 7) * 1e-3)[None, :] ** 2 + \
    80.0 * ((np.arange(15) - 7) * 1e-3)[:, None] ** 2


def test_the_registry_says_which_patch_each_method_takes():
    """Only the exact theory takes an undeformed distance on a grid; the
    others the Hertz ellipse (the descriptor's takes_grid)."""
    assert {m for m, info in rr.METHODS.items() if info.takes_grid} == {"exact"}
    # in_loop is about the work of a case, not a workspace: exact iterates
    assert {m for m, info in rr.METHODS.items() if not info.in_loop} == {"exact"}


def test_the_rig_refuses_the_exact_theory_for_its_iterations():
    """Was: "in a workspace of its own"; a workspace is no reason now (the
    rig owns one), an unbounded iteration is."""
    with pytest.raises(rr.RollerRigError, match=r"iteratively to a tolerance .* no bound on "
                                                r"its work"):
        rr.simulate(method="exact")


@pytest.mark.parametrize("call, culprit", [
    # the problem's check names the member: the call's argument, alone
    (lambda: rr.creep_forces(1e-3, **dict(CASE, a=-1.0)), "a = -1.0"),
    (lambda: rr.creep_forces(1e-3, **CASE, G=0.0), "G = 0.0"),
    (lambda: rr.creep_forces(1e-3, **CASE, nu=0.6), "nu = 0.6"),
    (lambda: rr.creep_forces(1e-3, **dict(CASE, mu=np.inf)), "mu = inf"),
    (lambda: rr.creep_forces(1e-3, **CASE, speed=-1.0), "speed = -1.0"),
    (lambda: rr.creep_forces(1e-3, **CASE, speed=1.0, friction=rr.FallingFriction(B=-1.0)),
     "friction.B = -1.0"),
    # what a method asks of a valid problem: falling friction at rest
    (lambda: rr.creep_forces(1e-3, **CASE, friction=rr.FallingFriction()), "speed = 0.0"),
    # outside exact_table's range: a/b, or nu, alone (was a, b and nu)
    (lambda: rr.creep_forces(1e-3, **dict(CASE, a=0.06, b=0.001), method="exact_table"),
     "a = 0.06"),
    (lambda: rr.creep_forces(1e-3, **CASE, nu=0.3, method="exact_table"), "nu = 0.3"),
    # a grid problem's h (was every number but h)
    (lambda: rr.exact_solve(np.where(BOWL > 0.005, np.nan, BOWL), dx=1e-3, dy=1e-3, N=5e4,
                            mu=0.3), "h"),
    (lambda: rr.exact_solve(BOWL, dx=1e-3, dy=1e-3, N=5e4, mu=0.3, y0=np.inf), "y0 = inf"),
    (lambda: rr.exact_field(1e-3, **dict(CASE, b=-1.0), nx=8, ny=8), "b = -1.0"),
    # no one member (an overflow): the values whose own change clears it
    (lambda: rr.creep_forces(1e300, **dict(CASE, a=1e12), method="linear"),
     "cx = 1e+300, a = 1000000000000.0"),
    (lambda: rr.exact_solve(BOWL, dx=1e-3, dy=1e-3, N=5e4, mu=0.3, cx=1e-3, cphi=0.5,
                            x0=1e308), "x0 = 1e+308"),
    # calls whose C function reports no member: found by the function itself
    (lambda: rr.hertz(1.0, -0.3, 1e4), "B = -0.3"),
    (lambda: rr.hertz(1.0, 0.3, 1e4, nu=0.7), "nu = 0.7, nu2 = 0.7"),
    (lambda: rr.hertz(1.0, 0.3, 1e4, E2=-1.0), "E2 = -1.0"),
    (lambda: rr.kalker_coefficients(1.0, 0.6), "nu = 0.6"),
])
def test_a_failed_case_names_only_the_argument_at_fault(call, culprit):
    with pytest.raises(rr.RollerRigError) as e:
        call()
    func = str(e.value).split(":")[0]
    assert str(e.value).startswith(f"{func}: {culprit}: "), str(e.value)


def test_a_batch_names_the_first_failed_element_by_the_c_report():
    f = rr.creep_forces([1e-3, 1e-3, 1e-3], **dict(CASE, N=[1e4, 1e4, -5.0]), errors="ignore")
    assert list(f.status) == [0, 0, -2]
    with pytest.warns(rr.RollerRigWarning, match=r"creep_forces: N = -5.0 at index \(2,\): "
                                                 r"normal load not positive"):
        rr.creep_forces([1e-3, 1e-3, 1e-3], **dict(CASE, N=[1e4, 1e4, -5.0]))


@pytest.mark.parametrize("name, value, code", [
    ("a", -1.0, -3), ("N", 0.0, -2), ("mu", -0.1, -5), ("nu", 0.7, -4), ("cy", np.nan, -1),
    ("speed", -2.0, -7), ("b", 1e-320, -12)])
def test_creep_blame_maps_the_c_member_to_the_argument(name, value, code):
    """_core.creep_blame: rr_creep_blame of one case, the binding's map from
    the problem's members to creep_forces' arguments."""
    opts = _core.check_creep_options("t", dict(method="fastsim"))
    case = dict(cx=1e-3, cy=0.0, cphi=0.0, a=6e-3, b=4e-3, N=1e4, mu=0.3, G=8.2e10,
                nu=0.28, speed=1.0, A=1.0, B=0.0)
    case[name] = value
    values = list(case.values())
    assert _core.creep_forces1(opts, *values)[3] == code
    assert _core.creep_blame(opts, *values, code) == name
    # a status the problem does not give (a success, another error): none
    assert _core.creep_blame(opts, *values, 0) is None
    assert _core.creep_blame(opts, *values, -14) is None


def test_exact_solve_takes_the_grid_problem_of_the_registry():
    """exact_solve's grid problem goes through the method's own path
    (rr_exact_problem_from): the forces are the registry method's on the
    ellipse where h is Hertz's gap on the ellipse's grid (to the rounding of
    the gap, computed by the solver or given), and a field too."""
    a, b, N = 6e-3, 4e-3, 1e4
    e = rr.exact_field(1e-3, 2e-4, 0.2, a=a, b=b, N=N, mu=0.3, nx=12, ny=12)
    A, B = None, None
    pb = _core.exact_hertz_problem(*[np.array([float(v)]) for v in
                                     (1e-3, 2e-4, 0.2, a, b, N, 0.3, 8.2e10, 0.28, 0.0, 1.0,
                                      0.0)], method="exact", nx=12, ny=12)
    A, B = pb[7], pb[8]
    x, y = e.x[0], e.y[:, 0]
    g = rr.exact_solve(A * x[None, :] ** 2 + B * y[:, None] ** 2, dx=x[1] - x[0],
                       dy=y[1] - y[0], x0=x[0], y0=y[0], N=N, mu=0.3, cx=1e-3, cy=2e-4,
                       cphi=0.2)
    # the same solver on the same gap but for its last bits (h given against
    # h computed inside): the forces to 1e-9 of mu N
    assert g.fx == pytest.approx(e.fx, abs=1e-9 * 0.3 * N)
    assert g.fy == pytest.approx(e.fy, abs=1e-9 * 0.3 * N)
    assert g.mz == pytest.approx(e.mz, abs=1e-9 * 0.3 * N * a)
    assert np.array_equal(g.contact, e.contact)
