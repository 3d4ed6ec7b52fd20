"""Inputs that once crashed, hung, or returned a non-finite number with a
success status, each reproduced here (they fail on the code before the fix).

The rule: no finite input, however extreme, gives a non-finite output with a
success status; an output that cannot be computed is NaN with a negative
status and a message that names the argument.  Rig objects: one user at a
time, and none before a successful __init__.
"""
import os
import signal
import subprocess
import textwrap
import threading

import numpy as np
import pytest

import rollerrig as rr
from _options import own
from rollerrig import _core

from _child import run_python, start_python

RANGE = -12          # RR_ERR_RANGE: inputs too extreme for a representable result


def _finite_or_failed(status, *outputs):
    """Every element: status >= 0 with finite outputs, or status < 0 with NaN."""
    status = np.asarray(status)
    for out in outputs:
        out = np.asarray(out)
        assert np.all(np.isfinite(out[status >= 0])), "success with a non-finite output"
        assert np.all(np.isnan(out[status < 0])), "failure without NaN"


# ---------------------------------------------------------------- contact core

def test_fastsim_tiny_semi_axis_is_an_error_not_nan():
    f = rr.creep_forces(0.0068, 0.001, 0.094, a=2.2e-308, b=0.0068, N=1e4, mu=0.3,
                        errors="ignore")
    assert f.status == RANGE and np.isnan(f.fx)
    with pytest.raises(rr.RollerRigError, match=r"a = 2\.2e-308.*too extreme"):
        rr.creep_forces(0.0068, 0.001, 0.094, a=2.2e-308, b=0.0068, N=1e4, mu=0.3)


def test_linear_theory_overflow_is_an_error_not_minus_inf():
    f = rr.creep_forces(1e300, 0, 0, a=1e12, b=0.0068, N=1e4, mu=0.3, method="linear",
                        errors="ignore")
    assert f.status == RANGE and np.isnan(f.fx)
    with pytest.raises(rr.RollerRigError, match=r"cx = 1e\+300"):
        rr.creep_forces(1e300, 0, 0, a=1e12, b=0.0068, N=1e4, mu=0.3, method="linear")


def test_hertz_with_huge_curvatures_is_computed():
    """a = b = 0, p0 = inf, delta = NaN before; the answer is representable:
    a sphere of radius R = 1/(2A), a^3 = 3 N R / (4 E*), delta = a^2 / R."""
    h = rr.hertz(1e300, 1e300, 1e4)
    estar = 2.1e11 / (2.0 * (1.0 - 0.28 ** 2))
    a = (3.0 * 1e4 * 0.5e-300 / (4.0 * estar)) ** (1.0 / 3.0)
    # the elliptic-integral route at k = 1 against the closed form: 1e-13
    assert h.a == pytest.approx(a, rel=1e-13) and h.b == pytest.approx(a, rel=1e-13)
    assert h.delta == pytest.approx(a * a * 2e300, rel=1e-12)
    assert h.p0 == pytest.approx(1.5e4 / (np.pi * a * a), rel=1e-12)


def test_hertz_beyond_the_double_range_is_an_error():
    h = rr.hertz(1e300, 1e300, 1e300, E=1e-290, errors="ignore")
    assert h.status == RANGE and np.isnan(h.p0)


def test_kalker_coefficients_at_extreme_ratios():
    k = rr.kalker_coefficients(1e-308)          # c23 = inf before: 16/g overflowed
    assert k.status == 0 and np.isfinite(k.c23) and k.c23 > 0 and np.isfinite(k.c33)
    k = rr.kalker_coefficients(5e-324, errors="ignore")  # C33 ~ 1/g: not representable
    assert k.status == RANGE and np.isnan(k.c23) and np.isnan(k.c33)
    k = rr.kalker_coefficients(1e300, errors="ignore")   # C23 ~ g^(-3/2): not representable
    assert k.status == RANGE and np.isnan(k.c11)


def test_polach_with_spin_stays_on_the_friction_limit():
    """The issue's case gave |F| = 1.012 mu N; 48 such points on this grid."""
    f = rr.creep_forces(0.0, -0.0019, 0.38, a=0.01, b=0.001, N=1e4, mu=0.5, method="polach",
                        kA=1.0, kS=0.4)
    assert np.hypot(f.fx, f.fy) == pytest.approx(5e3, rel=1e-14)
    cy, cphi = np.meshgrid(np.linspace(-0.01, 0.01, 401), np.linspace(-1.0, 1.0, 401))
    f = rr.creep_forces(0.0, cy, cphi, a=0.01, b=0.001, N=1e4, mu=0.5, method="polach",
                        kA=1.0, kS=0.4)
    ratio = np.hypot(f.fx, f.fy) / 5e3
    assert ratio.max() <= 1.0 + 1e-14       # rounding of the rescaled sum
    assert ratio.max() > 0.99               # the grid does reach the limit


@pytest.mark.parametrize("method", ["fastsim", "fastsim_blended", "modified_fastsim",
                                    "polach"])
def test_every_frictional_method_keeps_the_friction_limit_at_extremes(method):
    rng = np.random.default_rng(11)
    n = 4000
    cx, cy = rng.normal(0, 0.05, n), rng.normal(0, 0.05, n)
    cphi = rng.normal(0, 5.0, n)
    a = 10 ** rng.uniform(-4, -1, n)
    b = a * 10 ** rng.uniform(-1.5, 1.5, n)
    f = rr.creep_forces(cx, cy, cphi, a=a, b=b, N=1e4, mu=0.4, **own(method, nx=12, ny=12))
    assert np.all(f.status >= 0)
    assert np.all(np.hypot(f.fx, f.fy) <= 0.4e4 * (1 + 1e-12))


def test_incompressible_body_is_accepted():
    """Kalker's table has nu = 0.5; an incompressible body is physical."""
    k = rr.kalker_coefficients(0.1, 0.5)
    assert k.c11 == 4.85 and k.c22 == 2.53 and k.c23 == 0.731   # Table E.3, g = 0.1
    assert k.c33 == 11.7
    assert rr.hertz(0.8, 0.28, 1e5, nu=0.5).status == 0
    f = rr.creep_forces(1e-3, 0.0, 0.0, a=6e-3, b=6e-3, N=1e4, mu=0.3, nu=0.5)
    assert f.status == 0 and np.isfinite(f.fx)
    with pytest.raises(rr.RollerRigError, match="nu = 0.5000000000000001"):
        rr.creep_forces(1e-3, a=6e-3, b=6e-3, N=1e4, mu=0.3, nu=float(np.nextafter(0.5, 1)))


def test_binding_refuses_integers_outside_the_c_range():
    """method = 2**32 + 1 was taken as FASTSIM (the C int wrapped to 1).  The
    binding now takes methods by name: a number is refused whatever it is."""
    args = [np.array([v]) for v in (1e-3, 0, 0, 6e-3, 6e-3, 1e4, 0.3, 8.2e10, 0.28, 0, 1, 0)]
    with pytest.raises(ValueError, match="method must be one of 'linear', .*got 4294967297"):
        _core.creep_forces(*args, method=2 ** 32 + 1)
    with pytest.raises(ValueError, match="nx must be an integer"):
        _core.creep_forces(*args, method="fastsim", nx=2 ** 40)
    with pytest.raises(ValueError, match="nx must be an integer"):
        _core.creep_forces(*args, method="fastsim", nx=True)
    with pytest.raises(ValueError, match=r"nx must be an integer in \[1, 4096\], got 4294967297"):
        _core.creep_forces(*args, method="fastsim", nx=2 ** 32 + 1)


# ------------------------------------------------------------------ the rig contact

@pytest.fixture(scope="module")
def table():
    return rr.contact_table(rr.RigGeometry.standard(), -0.006, 0.006, 121)


@pytest.mark.parametrize("extra, culprit", [
    (dict(E=1e300), r"E = 1e\+300"), (dict(vy=1e300), r"vy = 1e\+300")])
def test_rig_contact_extremes_are_errors_naming_the_argument(table, extra, culprit):
    kw = dict(spin=5 / 0.46, roller_spin=5 / 0.46 * 0.999, N_left=1e4, N_right=1e4)
    kw.update(extra)
    c = rr.rig_contact(table, errors="ignore", **kw)
    assert c.status < 0 and np.isnan(c.left.fx) and np.isnan(c.right.force).all()
    with pytest.raises(rr.RollerRigError, match=culprit):
        rr.rig_contact(table, **kw)


def test_rig_contact_at_standstill_with_a_tiny_vmin(table):
    """spin = roller_spin = 0, vmin = 1e-300 gave NaN forces: no slip, no force."""
    c = rr.rig_contact(table, spin=0.0, roller_spin=0.0, N_left=1e4, N_right=1e4,
                       vmin=1e-300)
    assert c.status == 0
    assert c.left.fx == 0.0 and c.left.fy == 0.0 and np.all(np.isfinite(c.left.force))


def test_rig_contact_random_extremes_never_lie(table):
    rng = np.random.default_rng(3)
    n = 3000
    big = lambda: rng.choice([-1, 1], n) * 10.0 ** rng.uniform(-300, 300, n)
    c = rr.rig_contact(table, x=big() * 1e-300, y=rng.uniform(-0.007, 0.007, n), yaw=big(),
                       vx=big(), vy=big(), yaw_rate=big(), spin=big(), roller_spin=big(),
                       N_left=np.abs(big()), N_right=np.abs(big()), errors="ignore")
    for side in (c.left, c.right):
        _finite_or_failed(side.status, side.fx, side.fy, side.mz, side.cx, side.a)
        _finite_or_failed(side.status, *side.force, *side.moment)


# ---------------------------------------------------------------- geometry, profiles

def test_search_options_are_checked_before_the_core():
    g = rr.RigGeometry.standard()
    for n in (2 ** 31 - 1, 2 ** 31, 2, 1.5, True):
        with pytest.raises(rr.RollerRigError, match="nsamples must be an integer from 3"):
            rr.wheelset_contact(g, 0.0, nsamples=n)
    with pytest.raises(rr.RollerRigError, match="nsamples"):
        rr.contact_table(g, -0.006, 0.006, 11, nsamples=2 ** 31 - 1)
    with pytest.raises(rr.RollerRigError, match="nsamples"):
        rr.equivalent_conicity(g, 0.003, nsamples=2 ** 31 - 1)
    with pytest.raises(rr.RollerRigError, match="two_point_tol"):
        rr.wheelset_contact(g, 0.0, two_point_tol=-1.0)
    with pytest.raises(rr.RollerRigError, match="spacing"):
        rr.contact_table(g, -1e308, 1e308, 3)


def _run_child(code, timeout):
    """Run code in a fresh interpreter; (returncode, output)."""
    proc = run_python(["-c", textwrap.dedent(code)],
                      stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                      timeout=timeout)
    return proc.returncode, proc.stdout


def test_core_search_with_int_max_samples_returns_at_once():
    """It looped on i <= INT_MAX (signed overflow: a hang).  In a child
    process, so that a regression fails instead of hanging the suite."""
    code, out = _run_child("""
        import numpy as np, rollerrig as rr
        from rollerrig import _core
        g = rr.RigGeometry.standard()
        try:
            _core.wheelset_contact(*g._arrays(), g._params(), np.zeros(1), 2**31 - 1, 1e-4, 2e-3)
        except ValueError as e:
            print("refused:", e)
    """, timeout=120)
    assert code == 0 and "refused: wheelset_contact: nsamples must be an integer" in out, out


@pytest.mark.skipif(not hasattr(signal, "SIGINT") or os.name != "posix", reason="POSIX signals")
@pytest.mark.parametrize("call", [
    "rr.contact_table(g, -0.006, 0.006, 100000, nsamples=100000)",
    "rr.wheelset_contact(g, np.zeros(100000), nsamples=100000)",
    "rr.equivalent_conicity(g, 0.003, nsamples=100000, dy=1e-7, y_span=0.005)",
    # the rig's table built in C (rig.build._rig_table): 100000 rows, about a minute
    "rr._core.rig_table(0.092, 0.16, 0.015, 0.0499584, 0.06, 0.15, 0.008, 100000)"])
@pytest.mark.slow    # children running second-long calls
def test_long_geometry_calls_notice_ctrl_c(call):
    """Each call below runs for minutes; Ctrl-C must stop it between chunks
    (the generous timeouts only catch a call that ignores the signal)."""
    child = start_python(["-c", textwrap.dedent(f"""
        import sys, numpy as np, rollerrig as rr
        g = rr.RigGeometry.standard()
        print("ready", flush=True)
        try:
            {call}
        except KeyboardInterrupt:
            print("interrupted", flush=True)
            sys.exit(3)
    """)], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        assert child.stdout.readline().strip() == "ready"
        threading.Event().wait(1.5)              # inside the C loop by now
        child.send_signal(signal.SIGINT)
        out, _ = child.communicate(timeout=60)
    finally:
        child.kill()
    assert child.returncode == 3 and "interrupted" in out, out


@pytest.mark.skipif(os.name != "posix", reason="FIFOs and /dev/zero")
def test_profile_path_that_is_not_a_regular_file(tmp_path):
    """A FIFO (which would block), a directory or a symlink to /dev/zero
    said 'no such file'."""
    fifo = tmp_path / "fifo.whl"
    os.mkfifo(fifo)
    (tmp_path / "dir.whl").mkdir()
    (tmp_path / "zero.whl").symlink_to("/dev/zero")
    (tmp_path / "dangling.whl").symlink_to(tmp_path / "nowhere.whl")
    cases = {"fifo.whl": "not a regular file", "dir.whl": "is a directory",
             "zero.whl": "not a regular file", "dangling.whl": "no such file",
             "missing.whl": "no such file"}
    for name, message in cases.items():
        with pytest.raises(rr.RollerRigError, match=message):
            rr.read_profile(tmp_path / name)


def test_shift_arguments_name_themselves(table):
    """Raw numpy messages before ('could not convert string', 'arg 3 with shape')."""
    with pytest.raises(rr.RollerRigError, match="ContactTable.lookup: y_ws must be real"):
        table.lookup("x")
    with pytest.raises(rr.RollerRigError, match="ContactTable.slopes: y_ws"):
        table.slopes(["a"])
    with pytest.raises(rr.RollerRigError, match="wheelset_contact: y_ws must be a number or a "
                                                "1-D array"):
        rr.wheelset_contact(rr.RigGeometry.standard(), np.zeros((2, 2)))
    with pytest.raises(rr.RollerRigError, match=r"linear_creepages: shapes do not broadcast: "
                                                r"y\(2,\), yaw\(3,\)"):
        rr.linear_creepages(table, y=[0, 0.001], yaw=[0, 0, 0], spin=1, roller_spin=1)


# --------------------------------------------------------------------- the Rig object

def _rig():
    return rr.build_rig()[0]


def test_uninitialised_rig_refuses_every_method():
    """Segfaults before: _core.Rig.__new__(_core.Rig).run(...)."""
    rig = _core.Rig.__new__(_core.Rig)
    calls = [lambda: rig.run(np.array([1.0]), np.array([0.0])), rig.advance, rig.record,
             lambda: rig.rhs(0.0, np.zeros(_core.RIG_NSTATE)),
             lambda: rig.jac(0.0, np.zeros(_core.RIG_NSTATE)),
             lambda: rig.sample(1.0, 0.0),
             lambda: rig.set_state(0.0, np.zeros(_core.RIG_NSTATE)),
             lambda: rig.t, lambda: rig.y, lambda: rig.status]
    for call in calls:
        with pytest.raises(RuntimeError, match="not initialised"):
            call()


def test_failed_reinit_leaves_the_rig_refusing():
    """A failed __init__ on a working rig then stepped with status 0 and
    non-finite records."""
    rig, P, table = rr.build_rig()
    rig = rig._core                              # the binding's object itself
    assert rig.sample(31.25, 0.02) == 0          # a target: every record field is set
    rec, st = rig.advance()
    assert st == 0 and np.all(np.isfinite(rec))
    with pytest.raises(ValueError):
        rig.__init__(table.data, table.y0, table.dy, {"mass": 1.0}, {}, 31.25)
    with pytest.raises(RuntimeError, match="not initialised"):
        rig.advance()


def _wait_until_busy(rig, thread):
    while thread.is_alive():
        try:
            rig.status
        except RuntimeError as e:
            assert "in use by another thread" in str(e)
            return True
    return False


def _long_run(rig, out, n=200_000):
    ref = np.full(n, 31.25)
    out.append(rig.run(ref, np.full(n, 0.02)))


def test_reinit_during_a_run_is_refused():
    """Re-initialising while another thread was in run() segfaulted (the
    run had released the GIL while init swapped its parameters and table)."""
    rig, P, table = rr.build_rig()
    rig = rig._core                              # the binding's object itself
    for _ in range(5):
        out = []
        t = threading.Thread(target=_long_run, args=(rig, out))
        t.start()
        seen = _wait_until_busy(rig, t)
        if seen:
            with pytest.raises(RuntimeError, match="in use by another thread"):
                rig.__init__(table.data, table.y0, table.dy, {}, {}, 31.25)
        t.join()
        rec, status = out[0]
        assert status == 0 and np.all(np.isfinite(rec))
        if seen:
            return
    pytest.fail("the run never overlapped the main thread")


def test_two_threads_cannot_run_one_rig_at_once():
    """They interleaved: spurious statuses -2/-3, NaN records, mixed clocks."""
    rig = _rig()
    for _ in range(5):
        out, errors = [], []

        def second():
            try:
                rig.run(np.full(10, 31.25), np.full(10, 0.02))
            except RuntimeError as e:
                errors.append(str(e))

        t = threading.Thread(target=_long_run, args=(rig, out))
        t.start()
        seen = _wait_until_busy(rig, t)
        if seen:
            t2 = threading.Thread(target=second)
            t2.start()
            t2.join()
        t.join()
        rec, status = out[0]
        assert status == 0 and np.all(np.isfinite(rec))
        assert np.all(np.diff(rec[:, 0]) > 0), "one clock, in order"
        if seen:
            assert errors and "in use by another thread" in errors[0]
            return
    pytest.fail("the runs never overlapped")


def test_profile_extremes():
    """smoothing = 1e300 raised a raw OverflowError; z_at far outside warned
    of an overflow on the way to its NaN."""
    y, z = [0, 1e-3, 2e-3, 3e-3], [0, 0, 1e-4, 0]
    with pytest.raises(rr.RollerRigError, match="smoothing is a wavelength"):
        rr.Profile(y, z, kind="wheel", smoothing=1e300)
    p = rr.Profile(y, z, kind="wheel")
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert np.isnan(p.z_at(1e300)) and np.isnan(p.curvature(-1e300))


def test_rig_run_reports_the_worst_status_of_the_whole_run():
    """run() returned the status of its last block of 256 samples only, so
    warnings early in a run were lost.  At an 8 ms sample (the controllers
    are tuned for 4 ms; the roller's loop is stable up to 8.3 ms) the end of
    the braking transient warns, free rolling after it does not."""
    rig = rr.build_rig(dt=0.008)[0]
    n = 3000
    rec, status = rig.run(np.full(n, 5 / 0.16), np.where(np.arange(n) < 200, 0.04, np.nan))
    warned = np.flatnonzero(rec[:, -1] > 0)
    assert warned.size and warned.max() < n - 256        # none in the last block
    assert status == 1


HUGE_INT = 10 ** 400        # an int no double holds: float() of it raises OverflowError


@pytest.mark.parametrize("call, name", [
    (lambda: rr.fit_polach(np.linspace(-0.01, 0.01, 9), np.linspace(-1e3, 1e3, 9),
                           a=HUGE_INT, b=4e-3, N=2e4, speed=10.0), "a"),
    (lambda: rr.hunting([10.0], settle=HUGE_INT), "settle"),
    (lambda: rr.linearize(roller_speed=HUGE_INT), "roller_speed"),
    (lambda: rr.equivalent_conicity(rr.RigGeometry.standard(), centre=HUGE_INT), "centre"),
])
def test_a_huge_integer_is_refused_by_name_not_overflowed(call, name):
    """A Python int beyond the double range, where a number is asked for: the
    library's error naming the argument, not Python's OverflowError from a
    float() or math.isfinite() of it (fit_polach's and hunting's own number
    checks raised it)."""
    with pytest.raises(rr.RollerRigError, match=name):
        call()
