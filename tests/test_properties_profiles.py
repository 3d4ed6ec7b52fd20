"""Property-based tests of the profiles: the Profile constructor and its
named constructors, evaluation (z_at, slope, second_derivative, curvature),
Profile.from_points and read_profile (issue 11).

Run:  python -m pytest tests/test_properties_profiles.py          (profile "ci")
      HYPOTHESIS_PROFILE=long python -m pytest tests/test_properties_*.py
      (see tests/_hypothesis_profiles.py)

A profile that is accepted must evaluate to finite numbers everywhere on
[y_min, y_max] and to NaN outside; whatever is refused is refused with a
RollerRigError naming the argument (or the file and line).
"""
import os
import tempfile
import warnings

import numpy as np
import pytest
from hypothesis import example, given, strategies as st

import rollerrig as rr
from rollerrig import RollerRigError, RollerRigWarning
from rollerrig.geometry.profiles import DATA_DIR
from _properties import (BAD_TYPES, _units, any_finite, uniform, assert_names_argument, examples,
                         log_uniform, watchdog, wild)

assert watchdog  # the autouse hang detector, imported to take effect here

EVALUATIONS = ("z_at", "slope", "second_derivative", "curvature")
SHIPPED = ("MBench_S1002_v3.prw", "MBench_UIC60_v3.prr", "left-wheel-v1-pre-dry.whl",
           "left-roller-v1-pre-dry.ban")
TMP = tempfile.mkdtemp(prefix="rollerrig-prop-")


def assert_evaluates(p, extra=()):
    """Finite z, slope, z'' and curvature at every node, at the midpoints and at
    `extra` points inside; NaN outside and at NaN; z exact at the nodes (the
    last one is the end of the last piece: rounding)."""
    y = p.y
    inside = np.concatenate([y, 0.5 * (y[1:] + y[:-1]),
                             [v for v in extra if p.y_min <= v <= p.y_max]])
    for name in EVALUATIONS:
        v = getattr(p, name)(inside)
        assert np.all(np.isfinite(v)), f"{p!r}.{name} not finite at {inside[~np.isfinite(v)]}"
    np.testing.assert_array_equal(p.z_at(y[:-1]), p.z[:-1])
    span = p.y_max - p.y_min
    outside = np.array([p.y_min - 1e-9 * span - 1e-300, p.y_max + span, -np.inf, np.inf,
                        np.nan])
    for name in EVALUATIONS:
        assert np.all(np.isnan(getattr(p, name)(outside))), name


@st.composite
def node_arrays(draw, wild_gaps=True):
    """Strictly increasing y [m], gaps from 10 um to 10 mm and at least 2 mm
    wide; if wild_gaps, up to three gaps far smaller (down to the
    subnormals); z within +-50 mm.  (Gaps and heights from one binary draw:
    forty points would cost eighty float draws.)"""
    n = draw(st.integers(4, 40))
    u = _units(draw(st.binary(min_size=8 * n, max_size=8 * n)), 2 * n)
    gaps = log_uniform(1e-5, 1e-2)(u[:n - 1])
    gaps *= max(1.0, 2e-3 / gaps.sum())
    if wild_gaps:
        for i in draw(st.lists(st.integers(0, n - 2), max_size=3)):
            gaps[i] = draw(st.sampled_from((5e-324, 1e-300, 1e-30, 1e-18, 1e-15, 1e-12)))
    y0 = draw(st.floats(-0.5, 0.5))
    y = y0 + np.concatenate([[0.0], np.cumsum(gaps)])
    z = uniform(-0.05, 0.05)(u[n:])
    return y, z


smoothings = st.one_of(st.none(), log_uniform(1e-4, 0.1).strategy, wild)


@examples(10)
@given(nodes=node_arrays(), kind=st.sampled_from(("wheel", "rail")),
       bc=st.sampled_from((None, "natural", "not-a-knot")), smoothing=smoothings)
@example(nodes=(np.array([0.0, 1e-300, 0.001, 0.002, 0.003]),
                np.array([0.0, 0.0, 0.001, 0.0, 0.0])), kind="rail", bc=None, smoothing=None)
@example(nodes=(np.linspace(-0.02, 0.02, 9), np.zeros(9)), kind="rail", bc=None,
         smoothing=1e100)
@example(nodes=(np.array([0.0, 0.0065638, 0.0065638 + 1e-12, 0.0075]), np.full(4, -0.05)),
         kind="wheel", bc=None, smoothing=0.25)          # a singular smoothing system: NaN
def test_profile_accepted_evaluates_finite(nodes, kind, bc, smoothing):
    y, z = nodes
    try:
        p = rr.Profile(y, z, kind=kind, bc=bc, smoothing=smoothing)
    except RollerRigError as e:
        assert_names_argument(e, "Profile", ("y", "z", "kind", "bc", "smoothing", "index"))
        return
    assert_evaluates(p)


@examples(5)
@given(y=st.lists(wild, min_size=0, max_size=12), z=st.lists(wild, min_size=0, max_size=12),
       kind=st.sampled_from(("wheel", "rail", "roller", None)))
@example(y=[], z=[], kind="wheel")
def test_profile_from_any_arrays_is_valid_or_named(y, z, kind):
    try:
        p = rr.Profile(y, z, kind=kind)
    except RollerRigError as e:
        assert_names_argument(e, "Profile", ("y", "z", "kind", "index"))
        return
    assert_evaluates(p)


@examples(5)
@given(nodes=node_arrays(wild_gaps=False), bc=st.sampled_from(("natural", "not-a-knot")))
@example(nodes=(np.array([0.5, 0.5039954219855185, 0.5040054219855185, 0.50896349206128]),
                np.array([-0.05, -0.05, -0.049609369016252104, -0.05])),
         bc="not-a-knot")                        # intervals 1e-5 beside 4e-3
def test_profile_mirror_is_mirror_image(nodes, bc):
    """mirrored() is the mirror image y -> -y: the spline through mirrored
    points is the mirrored spline, up to the rounding of its slope solve,
    which eliminates the mirrored system from the other end (measured 3e-14
    of the profile's scale |z| + |z'| width; allowed 1e-11, and 1e-12 times
    the ratio of the longest interval to the shortest beyond 10: the
    not-a-knot end rows are not diagonally dominant, and their rounding
    grows with that ratio, 1e-11 measured at 400)."""
    y, z = nodes
    p = rr.Profile(y, z, kind="rail", bc=bc)
    m = p.mirrored()
    t = np.linspace(p.y_min, p.y_max, 41)[1:-1]
    zp, sp, _ = p.evaluate(t)
    h = np.diff(np.asarray(y, dtype=float))
    tol = 1e-12 * max(10.0, float(np.max(h) / np.min(h)))
    scale = np.max(np.abs(z)) + np.max(np.abs(sp)) * (p.y_max - p.y_min)
    assert np.max(np.abs(m.z_at(-t) - zp)) <= tol * scale
    assert np.max(np.abs(m.slope(-t) + sp)) * (p.y_max - p.y_min) <= tol * scale


PROFILES = {"s1002": rr.Profile.s1002(), "uic60": rr.Profile.uic60(),
            "conical": rr.Profile.conical(0.05), "cylinder": rr.Profile.cylinder(),
            "crowned": rr.Profile.cylinder(crown_radius=0.3)}


@examples(5)
@given(name=st.sampled_from(sorted(PROFILES)),
       y=st.one_of(wild, st.lists(wild, max_size=6), st.floats(-0.1, 0.1),
                   st.lists(st.floats(-0.1, 0.1), max_size=6)))
def test_evaluation_anywhere(name, y):
    """Any number or list of numbers: finite inside [y_min, y_max], NaN outside."""
    p = PROFILES[name]
    arr = np.asarray(y, dtype=float)
    inside = (arr >= p.y_min) & (arr <= p.y_max)
    for f in EVALUATIONS:
        v = getattr(p, f)(y)
        assert np.shape(v) == arr.shape
        assert np.all(np.isfinite(np.asarray(v)[inside])) and np.all(np.isnan(
            np.asarray(v)[~inside])), (f, y, v)


@examples(1)
@given(name=st.sampled_from(sorted(PROFILES)), bad=st.sampled_from(sorted(BAD_TYPES)),
       f=st.sampled_from(EVALUATIONS + ("evaluate",)))
def test_evaluation_wrong_types_named(name, bad, f):
    with pytest.raises(RollerRigError) as exc:
        getattr(PROFILES[name], f)(BAD_TYPES[bad])
    assert_names_argument(exc.value, f"Profile.{f}", ["y"])


ranges = st.one_of(st.tuples(st.floats(-0.1, -1e-3), st.floats(1e-3, 0.1)),
                   st.tuples(wild, wild), st.just((0.0, 0.0)), wild, st.none())
counts = st.one_of(st.integers(4, 300), st.integers(-5, 5), st.sampled_from((True, 4.0, "9")))


@examples(5)
@given(alpha=st.one_of(st.floats(-0.3, 0.3), wild), y_range=ranges,
       r0=st.one_of(st.none(), log_uniform(0.05, 1.0).strategy, wild), n=counts)
@example(alpha=1.5707963267948966, y_range=(-0.02, 0.02), r0=None, n=41)
@example(alpha=0.0, y_range=(-3.0, 0.0), r0=None, n=4)
def test_conical_profile(alpha, y_range, r0, n):
    try:
        p = rr.Profile.conical(alpha, y_range, r0=r0, n=n)
    except RollerRigError as e:
        assert_names_argument(e, "Profile.conical", ("alpha", "y_range", "r0", "n"))
        return
    assert_evaluates(p)
    # a straight line: slope -tan(alpha), curvature 0, up to the rounding of
    # the spline's slope solve (1e-9 of the slope's size)
    t = np.linspace(p.y_min, p.y_max, 17)
    tol = 1e-9 * max(1.0, abs(np.tan(alpha)))
    assert np.all(np.abs(p.slope(t) + np.tan(alpha)) <= tol)
    assert np.all(np.abs(p.curvature(t)) * (p.y_max - p.y_min) <= tol)


@examples(5)
@given(y_range=ranges, crown=st.one_of(st.none(), log_uniform(0.05, 1.0).strategy, wild),
       n=counts)
@example(y_range=(-0.02, 0.02), crown=1e300, n=4)
@example(y_range=(0.0, 5e-324), crown=None, n=4)      # named y[1], y[2]: not an argument
@example(y_range=(0.0, 1e-05), crown=None, n=4)        # named the profile's width: neither
def test_cylinder_profile(y_range, crown, n):
    try:
        p = rr.Profile.cylinder(y_range, crown_radius=crown, n=n)
    except RollerRigError as e:
        assert_names_argument(e, "Profile.cylinder", ("y_range", "crown_radius", "n"))
        return
    assert_evaluates(p)
    assert np.all(p.z >= 0.0)                  # the crown's top is z = 0, the rest below


@examples(1)
@given(name=st.sampled_from(("s1002", "uic60")), smoothing=smoothings)
@example(name="s1002", smoothing=1e75)
@example(name="s1002", smoothing=1e78)
def test_shipped_profiles_with_any_smoothing(name, smoothing):
    try:
        p = getattr(rr.Profile, name)(smoothing=smoothing)
    except RollerRigError as e:
        assert_names_argument(e, ("Profile", "read_profile"), ("smoothing",))
        return
    assert_evaluates(p)


# ------------------------------------------------------------------ from points

@st.composite
def point_lists(draw):
    """Points in any order: a plausible profile (mm or m), reversed, with a
    fold, duplicates, or wild values."""
    y, z = draw(node_arrays(wild_gaps=False))
    y, z = list(y), list(z)
    for _ in range(draw(st.integers(0, 3))):
        op = draw(st.sampled_from(("reverse", "fold", "duplicate", "wild", "drop")))
        i = draw(st.integers(0, len(y) - 1))
        if op == "reverse":
            y, z = y[::-1], z[::-1]
        elif op == "fold":                          # y steps back
            y.insert(i, y[i] - draw(st.floats(1e-6, 5e-3)))
            z.insert(i, z[i] + draw(st.floats(-5e-3, 5e-3)))
        elif op == "duplicate":
            y.insert(i, y[i])
            z.insert(i, z[i])
        elif op == "wild":
            (y if draw(st.booleans()) else z)[i] = draw(wild)
        elif len(y) > 1:
            del y[i], z[i]
    return y, z


@examples(10)
@given(points=point_lists(), kind=st.sampled_from(("wheel", "rail")),
       units=st.sampled_from(("m", "mm", "cm")), on_fold=st.sampled_from(("trim", "raise")),
       mirror_y=st.booleans(), mirror_z=st.booleans(), smoothing=smoothings)
@example(points=([0.0, 0.0006666666666666666, 0.0013333333333333333, 0.002], [-0.05] * 4),
         kind="wheel", units="m", on_fold="trim", mirror_y=False, mirror_z=False,
         smoothing=7.275431537835326e+77)
def test_from_points(points, kind, units, on_fold, mirror_y, mirror_z, smoothing):
    y, z = points
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RollerRigWarning)        # folds removed
        try:
            p = rr.Profile.from_points(y, z, kind=kind, units=units, on_fold=on_fold,
                                       mirror_y=mirror_y, mirror_z=mirror_z,
                                       smoothing=smoothing)
        except RollerRigError as e:
            assert_names_argument(e, ("Profile.from_points", "Profile"),
                                  ("y", "z", "point", "index", "units", "on_fold",
                                   "smoothing"))
            return
    assert_evaluates(p)


# ------------------------------------------------------------------ reading files

@examples(5)
@given(nodes=node_arrays(wild_gaps=False), kind=st.sampled_from(("wheel", "rail")),
       units=st.sampled_from(("m", "mm", "cm")))
def test_write_text_read_profile_round_trip(nodes, kind, units):
    p = rr.Profile(*nodes, kind=kind)
    path = os.path.join(TMP, "round_trip.txt")
    p.write_text(path, units=units)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RollerRigWarning)        # "other side's wheel?"
        q = rr.read_profile(path)
    assert q.kind == kind
    # 17 significant digits give the double back, but the unit conversion
    # rounds once each way: 1 ulp
    np.testing.assert_allclose(q.y, p.y, rtol=2.3e-16, atol=0)
    np.testing.assert_allclose(q.z, p.z, rtol=2.3e-16, atol=1e-300)


def _lines(name):
    with open(os.path.join(DATA_DIR, name), encoding="utf-8") as f:
        return f.read().splitlines()


SHIPPED_LINES = {name: _lines(name) for name in SHIPPED}
TOKENS = st.one_of(st.sampled_from(("", "x", "=", "nan", "inf", "-inf", "1e999", "9" * 400,
                                    "-" + "9" * 400, "0", "-0", "1", "1e-320", "2.5",
                                    "point.begin", "point.end", "spline.end", "header.begin",
                                    "'mm'", "XYPoints=3", "ColumnDef=Y,X", "[Section]", "!",
                                    "#", ",", ";", "\t", "\x00", "\u00e9")),
                   any_finite.map(repr), st.text(max_size=6))


@st.composite
def mutated_files(draw):
    """A shipped profile file with one to four lines changed, removed, repeated
    or the file cut short."""
    name = draw(st.sampled_from(SHIPPED))
    lines = list(SHIPPED_LINES[name])
    for _ in range(draw(st.integers(1, 4))):
        i = draw(st.integers(0, len(lines) - 1))
        op = draw(st.sampled_from(("token", "token", "token", "delete", "repeat", "cut",
                                   "swap")))
        if op == "token":
            fields = lines[i].replace("=", " = ").split()
            if fields:
                fields[draw(st.integers(0, len(fields) - 1))] = draw(TOKENS)
            else:
                fields = [draw(TOKENS)]
            lines[i] = " ".join(fields).replace(" = ", "=")
        elif op == "delete":
            del lines[i]
        elif op == "repeat":
            lines.insert(i, lines[i])
        elif op == "cut":
            lines = lines[:i]
        else:
            j = draw(st.integers(0, len(lines) - 1))
            lines[i], lines[j] = lines[j], lines[i]
        if not lines:
            break
    return os.path.splitext(name)[1], "\n".join(lines) + "\n"


def _read(ext, content, binary=False, **kw):
    path = os.path.join(TMP, "fuzz" + ext)
    with open(path, "wb" if binary else "w", **({} if binary else dict(encoding="utf-8"))) as f:
        f.write(content)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RollerRigWarning)
        try:
            p = rr.read_profile(path, **kw)
        except RollerRigError as e:
            assert_names_argument(e, "read_profile", [path])
            return None
    assert_evaluates(p)
    return p


@examples(5)
@given(file=mutated_files())
@example(file=(".prw", "header.begin\n type = 1\nheader.end\nspline.begin\n shift.y = 1"
               + "0" * 400 + "\n point.begin\n 0 0\n 1 1\n 2 0\n 3 1\n point.end\nspline.end\n"))
def test_read_profile_mutated_files(file):
    _read(*file)


@examples(2)
@given(ext=st.sampled_from((".txt", ".csv", ".dat", ".prw", ".prr", ".whl", ".ban")),
       content=st.binary(max_size=200))
def test_read_profile_any_bytes(ext, content):
    _read(ext, content, binary=True, **({"kind": "rail"} if ext in (".txt", ".csv", ".dat")
                                       else {}))


@examples(3)
@given(rows=st.lists(st.tuples(st.one_of(st.floats(-50, 50), wild),
                               st.one_of(st.floats(-20, 20), wild)), min_size=0, max_size=30),
       header=st.lists(st.sampled_from(("# kind = rail", "# kind = wheel", "# units = mm",
                                        "# units = m", "# units = furlong", "# bc = natural",
                                        "# bc = cubic", "y z", "# name = x")), max_size=3))
def test_read_profile_text_rows(rows, header):
    text = "\n".join(header + [f"{a!r} {b!r}" for a, b in rows]) + "\n"
    _read(".txt", text, kind=None if any("kind" in h for h in header) else "rail")

