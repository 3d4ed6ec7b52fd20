"""Shared strategies and checks of the property-based suite (tests/test_properties_*.py).

The rule every public numeric function must keep (issue 11): no finite
input, however extreme, gives a non-finite output with a success status; an
output that cannot be computed is NaN with a negative status, and a call on
scalars raises RollerRigError naming the function and the argument.
"""
import faulthandler
import math
import os
import re
import subprocess

import numpy as np
import pytest
from hypothesis import settings, strategies as st

import _hypothesis_profiles  # noqa: F401  (registers and loads the profiles)
from _child import run_python

# failing examples are printed with numpy's repr: the shortest digits that
# give back the same double, so a printed case reproduces exactly
np.set_printoptions(floatmode="unique")
import rollerrig as rr

def examples(factor, **overrides):
    """Settings with `factor` times the profile's examples per test (deadline,
    derandomize and the rest from the profile, unless overridden)."""
    return settings(max_examples=max(1, int(round(factor * settings.default.max_examples))),
                    **overrides)


# ---------------------------------------------------------------- hang guards

@pytest.fixture(autouse=True)
def watchdog():
    """A hang detector for every test: if a test has not finished after far more
    than it ever needs, faulthandler prints every thread's stack and ends the
    run (a C loop that never returns holds no Python frame a signal could
    interrupt; faulthandler's own thread still fires).  Not a speed check."""
    limit = 600.0 * max(1.0, settings.default.max_examples / _hypothesis_profiles.CI_EXAMPLES)
    faulthandler.dump_traceback_later(limit, exit=True)
    yield
    faulthandler.cancel_dump_traceback_later()


def _limit_memory(limit=4 * 2 ** 30):
    """In the child: at most 4 GB of address space, so that a call that tries
    to allocate without bound fails there instead of taking the machine."""
    import resource
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))


def run_isolated(code, timeout=30.0):
    """Run `code` in a fresh Python (at most 4 GB); fail the test if it does
    not return within `timeout` seconds (a hang) or dies on a signal (a
    crash).  Returns the CompletedProcess (stdout, stderr, returncode)
    otherwise."""
    try:
        proc = run_python(["-c", code], capture_output=True, text=True,
                          timeout=timeout, env={**os.environ, "PYTHONFAULTHANDLER": "1"},
                          preexec_fn=_limit_memory)
    except subprocess.TimeoutExpired:
        pytest.fail(f"did not return within {timeout:g} s (hang):\n{code}")
    if proc.returncode < 0:
        pytest.fail(f"crashed with signal {-proc.returncode}:\n{code}\n{proc.stderr[-2000:]}")
    return proc


# ---------------------------------------------------------------- values

NAN, INF = math.nan, math.inf
#: the corners of the double range, and the non-finite values
SPECIAL = (0.0, -0.0, 5e-324, -5e-324, 2.2250738585072014e-308, 1e-300, 1e-30, 1e30,
           1e300, -1e300, 1.7976931348623157e308, -1.7976931348623157e308, NAN, INF, -INF)

#: the whole finite double range, subnormals and 1e300 included
any_finite = st.floats(allow_nan=False, allow_infinity=False)
#: anything a float can be: every finite double, the corners, NaN and the infinities
wild = st.one_of(any_finite, st.sampled_from(SPECIAL), st.floats())


class Plausible:
    """A physically plausible range, as a map from u in [0, 1] (numpy arrays).

    The plausible values of a case come from one binary draw (cheap: each
    Hypothesis draw costs about a millisecond here, and a case has ten
    arguments); Hypothesis's own float strategy, where its cleverness pays,
    draws the wild ones.  u = 0 and u = 1, the ends of the range, come up in
    one value of six."""

    def __init__(self, fn, text):
        self.fn, self.text = fn, text

    def __call__(self, u):
        return self.fn(np.asarray(u, dtype=float))

    def __repr__(self):
        return self.text

    @property
    def strategy(self):
        """The range as a strategy of single floats."""
        def value(u):       # a named function: failing examples print the number
            return float(self(u))
        return st.floats(0.0, 1.0).map(value)


def log_uniform(lo, hi):
    """Positive values spread evenly in log between lo and hi."""
    a, b = math.log(lo), math.log(hi)
    return Plausible(lambda u: np.exp(a + (b - a) * u), f"log_uniform({lo}, {hi})")


def uniform(lo, hi):
    return Plausible(lambda u: lo + (hi - lo) * u, f"uniform({lo}, {hi})")


def signed(lo, hi):
    """Magnitudes log-uniform in [lo, hi], either sign, and zero (a tenth)."""
    mag = log_uniform(lo, hi)

    def fn(u):
        w = np.clip((np.abs(2.0 * u - 1.0) - 0.1) / 0.9, 0.0, 1.0)
        return np.where(np.abs(2.0 * u - 1.0) < 0.1, 0.0, np.sign(u - 0.5) * mag(w))
    return Plausible(fn, f"signed({lo}, {hi})")


def or_zero(p):
    """p, or zero (a fifth)."""
    return Plausible(lambda u: np.where(u < 0.2, 0.0, p(np.clip((u - 0.2) / 0.8, 0, 1))),
                     f"or_zero({p!r})")


def _units(raw, n):
    """n values u in [0, 1] from 4 bytes each: 0 or 1 for one in six, else
    24 bits uniform."""
    b = np.frombuffer(raw, dtype=np.uint8)[:4 * n].reshape(n, 4).astype(np.int64)
    u = ((b[:, 1] << 16) | (b[:, 2] << 8) | b[:, 3]) / float(2 ** 24 - 1)
    return np.where(b[:, 0] < 21, 0.0, np.where(b[:, 0] > 234, 1.0, u))


#: values of the wrong type for a numeric argument
BAD_TYPES = {
    "complex array": np.array([1e-3 + 1e-4j, 2e-3]),
    "complex": 1e-3 + 1e-4j,
    "str array": np.array(["1e-3", "2e-3"]),
    "str": "0.001",
    "object array": np.array([1e-3, 2e-3], dtype=object),
    "bool array": np.array([True, False]),
    "bool": True,
    "None": None,
    "list of str": ["1e-3", "2e-3"],
}


@st.composite
def batches(draw, spec, max_size=8, wild_share=3, min_size=1, scalars=True):
    """Arguments as 1-D arrays of one length n, each element plausible (spec:
    {name: Plausible}); some arguments left as scalars that broadcast (if
    `scalars`).  In one example of `wild_share` (never if 0), one to three
    elements of the arguments are drawn from `wild` instead."""
    n = draw(st.integers(min_size, max_size))
    names = list(spec)
    k = len(names)
    u = _units(draw(st.binary(min_size=4 * n * k + k, max_size=4 * n * k + k)), n * k)
    raw_scalar = draw(st.binary(min_size=k, max_size=k)) if scalars else bytes(k)
    out = {}
    for j, name in enumerate(names):
        col = np.array(spec[name](u[j * n:(j + 1) * n]), dtype=float).reshape(n)
        out[name] = col
    if wild_share and draw(st.integers(0, wild_share - 1)) == 0:
        for i, name in draw(st.lists(st.tuples(st.integers(0, n - 1), st.sampled_from(names)),
                                     min_size=1, max_size=3)):
            out[name][i] = draw(wild)
    for j, name in enumerate(names):
        if raw_scalar[j] >= 192 and n > 0:
            out[name] = float(out[name][0])        # a scalar broadcast over the batch
    if not any(isinstance(v, np.ndarray) for v in out.values()):
        out[names[0]] = np.array([out[names[0]]])  # a batch call needs one array
    return out


@st.composite
def cases(draw, spec, wild_share=4):
    """One set of scalar arguments: plausible (spec: {name: Plausible}); in one
    example of `wild_share` (never if 0), one to three of them from `wild`."""
    b = draw(batches(spec, max_size=1, min_size=1, wild_share=wild_share, scalars=False))
    return {k: float(np.asarray(v).reshape(-1)[0]) for k, v in b.items()}


# The exact solver has its own checks (test_exact.py): Coulomb friction only,
# milliseconds a case, not a time-loop method (the rig refuses it).
METHODS = tuple(m for m in rr.METHODS if m != "exact")
FRICTIONAL = tuple(m for m in METHODS if m != "linear")
# the methods the rig steps with (not the linear theory: no friction limit);
# the rig's default parameters have falling friction: the Coulomb-only methods
# (fastrip) are refused there, and tested with Coulomb friction on their own
RIG_METHODS = tuple(m for m in rr.rig.RIG_METHODS if not rr.METHODS[m].coulomb_only)
FASTSIMS = ("fastsim", "fastsim_blended", "modified_fastsim")
_TABLE = rr.exact_table.builtin_table()


def table_refuses(method, status, a, b, nu):
    """Where method "exact_table" rightly refuses (RR_ERR_TABLE): its table
    holds one nu and a/b in [0.1, 10] only.  A mask like status."""
    aob = np.asarray(a, float) / np.asarray(b, float)
    with np.errstate(all="ignore"):
        outside = ((np.abs(np.asarray(nu, float) - _TABLE.nu) > 1e-9)
                   | ~((aob >= 0.1 * (1 - 1e-12)) & (aob <= 10.0 * (1 + 1e-12))))
    return (method == "exact_table") & (np.asarray(status) == -14) & outside


@st.composite
def creep_options(draw, methods=METHODS, max_grid=24):
    """A valid set of options of one method (grids small: a call stays well
    under a millisecond; the largest grids have their own test)."""
    method = draw(st.sampled_from(methods))
    opts = dict(method=method)
    if method in FASTSIMS:
        opts.update(nx=draw(st.integers(1, max_grid)), ny=draw(st.integers(1, max_grid)),
                    bound=draw(st.sampled_from(tuple(rr.BOUNDS))),
                    grid=draw(st.sampled_from(("rect", "strips"))),
                    slip_speed=draw(st.sampled_from((None, "local", "rigid"))))
    if method == "modified_fastsim":
        # k0 below ~1e-297 makes the flexibility overflow (the forces would be
        # subnormal): RR_ERR_RANGE, not a plausible value
        opts.update(k0=draw(st.floats(1e-3, 1.0)),
                    alpha_inf=draw(st.floats(0.0, 1.0)), beta=draw(st.floats(0.0, 10.0)))
    if method == "fastrip":
        opts.update(nx=draw(st.integers(1, max_grid)), ny=draw(st.integers(1, max_grid)),
                    flex=draw(st.sampled_from(("kalker", "blended"))),
                    geometry=draw(st.sampled_from(("ellipse", "contact"))),
                    k0=draw(st.floats(1e-3, 1.0)), alpha_inf=draw(st.floats(0.0, 1.0)),
                    beta=draw(st.floats(0.0, 10.0)))
    if method == "polach":
        kA = draw(st.floats(0.0, 1.0, exclude_min=True))
        opts.update(kA=kA, kS=draw(st.floats(0.0, kA, exclude_min=True)))
    return opts


def subset(args, idx):
    """The arguments of the elements idx (scalars stay scalars)."""
    return {k: (v[idx] if isinstance(v, np.ndarray) and v.ndim else v) for k, v in args.items()}


# ---------------------------------------------------------------- checks

def _word(name):
    return rf"(?<![\w.]){re.escape(name)}(?![\w])"


def assert_names_argument(err, prefixes, names):
    """err (a RollerRigError) starts with the function's name and names one of
    the call's arguments; a message that blames NaN or infinite input is only
    true if some input was."""
    msg = str(err)
    prefixes = (prefixes,) if isinstance(prefixes, str) else tuple(prefixes)
    assert any(msg.startswith(p + ":") for p in prefixes), \
        f"message does not start with {' or '.join(prefixes)}: {msg!r}"
    assert any(re.search(_word(n), msg) for n in names), \
        f"message names none of the arguments {sorted(names)}: {msg!r}"


def assert_truthful(err, values):
    """A message saying 'input is NaN or infinite' needs a non-finite input."""
    if rr.status_message(-1) in str(err):
        nums = [np.asarray(v, dtype=float) for v in values
                if isinstance(v, (int, float, np.ndarray)) and not isinstance(v, bool)]
        assert any(not np.all(np.isfinite(v)) for v in nums), \
            f"says NaN or infinite input, but every input is finite: {err}"


def assert_finite(fields, where=""):
    for name, v in fields.items():
        v = np.asarray(v, dtype=float)
        assert np.all(np.isfinite(v)), f"{where}{name} = {v!r} not finite with a success status"


def assert_batch_consistent(fields, status, where=""):
    """Element by element: status >= 0 and every output finite, or status < 0
    and every output NaN.  fields: {name: array shaped like status, or (3,) +
    its shape for vectors}."""
    status = np.asarray(status)
    assert status.dtype == np.int8, f"{where}status dtype {status.dtype}"
    ok = status >= 0
    for name, v in fields.items():
        v = np.asarray(v, dtype=float)
        okb = np.broadcast_to(ok, v.shape)
        bad_ok = okb & ~np.isfinite(v)
        bad_err = ~okb & ~np.isnan(v)
        assert not bad_ok.any(), (f"{where}{name} not finite where status >= 0: "
                                  f"{v[bad_ok][:4]} with status {status[ok][:4]}")
        assert not bad_err.any(), f"{where}{name} not NaN where status < 0: {v[bad_err][:4]}"


def assert_same(r1, r2, where=""):
    """Equal bitwise, NaN == NaN."""
    for k, (x, y) in enumerate(zip(r1, r2)):
        np.testing.assert_array_equal(np.asarray(x), np.asarray(y), err_msg=f"{where}[{k}]")
