"""The rig's parameters, record fields and per-wheel block are declared once
in C (csrc/rig/rr_rig_params.c) and exported; everything else follows."""
import math

import numpy as np
import pytest

import rollerrig as rr
from rollerrig import _core, rig
from rollerrig.rig import DEFAULTS_PATH, PARAMETERS, RETIRED, defaults_toml

try:
    import tomllib
except ImportError:                                     # Python < 3.11
    import tomli as tomllib


def test_the_shipped_defaults_file_is_generated_from_the_c_table():
    """rig_default.toml is the C declaration written out (rig.write_defaults)."""
    with open(DEFAULTS_PATH, encoding="utf-8") as fh:
        assert fh.read() == defaults_toml(), \
            "rig_default.toml is stale: run python -c 'import rollerrig.rig; " \
            "rollerrig.rig.write_defaults()'"
    with open(DEFAULTS_PATH, "rb") as fh:
        assert tomllib.load(fh) == rr.default_parameters()


def test_every_row_is_complete_and_its_text_is_its_value():
    names = [p.name for p in PARAMETERS]
    assert len(set(names)) == len(names)
    for p in PARAMETERS:
        assert p.origin and p.name.count(".") == 1, p.name
        assert p.type in ("real", "int", "flag", "choice", "list"), p.name
        if p.creep:
            continue
        if p.type in ("real", "int"):
            assert float(p.text) == p.default, p.name
            assert rig.params._in_range(p.name, p.default)
            assert not rig.params._in_range(p.name, math.nan)
        if p.type == "list":
            assert list(tomllib.loads(f"v = {p.text}")["v"]) == list(p.default), p.name
        if p.type == "choice":
            assert p.default in p.choices
    assert not set(names) & set(RETIRED)


def test_each_creep_row_declares_the_option_it_sets():
    """The creep rows' option is a column of the C declaration (issue 23), not
    the name cut at its first '_' (which would make fastsim_slip_speed set
    'slip' and break on a family with an '_' in it): the file's keys, the C
    rig and the FMU all read that column."""
    declared = {p.name: p.option for p in PARAMETERS if p.option}
    assert declared == {"contact.fastsim_nx": "nx", "contact.fastsim_ny": "ny",
                        "contact.fastsim_slip_speed": "slip_speed", "contact.polach_kA": "kA",
                        "contact.polach_kS": "kS"}
    assert all(p.option is None for p in PARAMETERS
               if not p.creep or p.name == "contact.creep_method")
    assert all(any(o in m.options for m in rr.METHODS.values()) for o in declared.values())
    assert rig.params._FILE_OPTIONS == {k.split(".", 1)[1]: o for k, o in declared.items()}


PARAM, NONFINITE, RANGE = -9, -1, -12      # statuses (csrc/util/rr_common.h)


def _c_values(P):
    """{"section.key": value} of merged parameters' rig rows, as the binding takes them."""
    return {p.name: P[p.name.split(".")[0]][p.name.split(".")[1]] for p in PARAMETERS
            if not p.creep}


@pytest.mark.parametrize("params", [
    {"wheelset": {"mass_kg": math.nan}, "roller": {"radius_m": -0.1},
     "integration": {"table_rows": 2.5}},
    {"scenario": {"targets": [0.01, 0.02]}},
    {"scenario": {"target_start_s": [0.0, 5.0, 3.0, 15.0]}},
    {"scenario": {"duration_s": 10.0, "target_start_s": [0.0, 2.0, 4.0, 12.0]}},
    {"adhesion": {"schedule_times_s": [0.0, 2.0, 1.0], "schedule_mu0": [0.3, 0.2]}},
    {"adhesion": {"schedule_times_s": [0.0, 1.0], "schedule_mu0": [0.3, 0.2],
                  "schedule_polach_A": [0.5]}},
    {"adhesion": {"patch_length_m": 2.0}},
    {"scenario": {"targets": [0.5, 2.0], "target_start_s": [0.0]}},
    {"scenario": {"drive_mode": "coasting", "targets": [0.1, True]},
     "integration": {"linear_first_stage": 1}, "wheelset": {"conicity": "x"}},
    {"wheelset": {"spin_inertia_kg_m2": 1.5e308},
     "wheelset_drive": {"drive_inertia_kg_m2": 1.5e308}},
])
def test_a_parameter_set_is_judged_by_the_c_report(params):
    """rig_config_report (rr_rig_config_report, issue 23): every problem of a
    parameter set with its key, status, rule, other key and bounds, in one
    call; check_parameters says each of them (but for the rules a run judges
    at its sample time) in one sentence that starts with its key and names
    the other, in the report's order, and writes none of the rules again."""
    P, problems = rig.params._parameter_problems(params)
    report = [r for r in _core.rig_config_report(_c_values(P))
              if r[2] not in rig.params._RUN_RULES]
    assert report and len(problems) == len(report), (problems, report)
    for sentence, (key, status, rule, other, entry, value, lo, hi) in zip(problems, report):
        assert sentence.split(" ", 1)[0] == key and (other is None or other in sentence)
        assert status in (PARAM, NONFINITE, RANGE) and rule in (
            "range", "count", "increasing", "nondecreasing", "before", "circumference", "sum")


def test_a_rule_between_creep_options_is_the_registrys():
    """Polach's kS <= kA is the registry's method check (rr_polach.c), not
    written again for the file: the sentence names both keys and the rule
    as the registry words it."""
    P, problems = rig.params._parameter_problems({"contact": {"polach_kA": 0.5,
                                                              "polach_kS": 0.9}})
    assert problems == ["contact.polach_kS must satisfy 0 < kS <= kA <= 1 (method 'polach'), "
                        "got contact.polach_kA = 0.5, contact.polach_kS = 0.9"]
    assert rig.params._parameter_problems({"contact": {"polach_kA": 0.5,
                                                       "polach_kS": 0.5}})[1] == []


def test_the_report_reads_choice_names_whole():
    """A choice's name with a NUL inside is not its head (rr_rig_param_choice
    read 'braking' in 'braking\\0x'), and a str UTF-8 cannot hold is no
    name, not an exception; a key with a NUL inside is no row."""
    for bad in ("braking\0x", "\ud800", "braking "):
        assert _core.rig_config_report({"scenario.drive_mode": bad}) == [
            ("scenario.drive_mode", PARAM, "range", None, -1,
             pytest.approx(math.nan, nan_ok=True), 0.0, 1.0)]
        with pytest.raises(rr.RollerRigError, match="scenario.drive_mode must be 'braking' or "
                                                    "'traction'"):
            rig.check_parameters({"scenario": {"drive_mode": bad}})
    with pytest.raises(ValueError, match="not a rig parameter"):
        _core.rig_config_report({"wheelset.mass_kg\0x": 1.0})


def test_the_c_report_carries_what_the_messages_need():
    bad = _core.rig_config_report({"scenario.targets": [0.01, 0.02],
                                   "adhesion.patch_length_m": 2.0, "wheelset.mass_kg": -1.0,
                                   "integration.table_rows": 2.5})
    assert bad == [
        ("wheelset.mass_kg", PARAM, "range", None, -1, -1.0, 0.0, math.inf),
        ("integration.table_rows", PARAM, "range", None, -1, 2.5, 2.0, 100000.0),
        ("scenario.target_start_s", PARAM, "count", "scenario.targets", -1, 4.0,
         pytest.approx(math.nan, nan_ok=True), 2.0),
        # (a count's lo: 0 where none would do too, NaN where not)
        ("adhesion.patch_length_m", PARAM, "circumference", "roller.radius_m", -1,
         2.0, pytest.approx(math.nan, nan_ok=True), 2 * math.pi * 0.16)]
    # the drives' loops, as rig_speed_loops gives them, and the inertias' sum
    cp = {"scenario.control_sample_time_s": 0.02}
    loops = [(key, entry, value, lo, hi) for key, _, rule, _, entry, value, lo, hi
             in _core.rig_config_report(cp) if rule == "loop"]
    assert loops == [("scenario.control_sample_time_s", k, rho, lo, hi)
                     for k, (stable, rho, lo, hi) in enumerate(_core.rig_speed_loops(cp))
                     if not stable] and len(loops) == 2
    assert _core.rig_config_report({"wheelset.spin_inertia_kg_m2": 1.5e308,
                                    "wheelset_drive.drive_inertia_kg_m2": 1.5e308}) == [
        ("wheelset.spin_inertia_kg_m2", RANGE, "sum",
         "wheelset_drive.drive_inertia_kg_m2", -1, math.inf,
         pytest.approx(math.nan, nan_ok=True), pytest.approx(math.nan, nan_ok=True))]
    times = {"adhesion.schedule_times_s": [0.0, 1.0], "adhesion.schedule_mu0": [0.3],
             "adhesion.schedule_polach_A": [0.3]}
    assert [(key, lo) for key, _, rule, _, _, _, lo, _ in _core.rig_config_report(times)] == [
        ("adhesion.schedule_mu0", pytest.approx(math.nan, nan_ok=True)),
        ("adhesion.schedule_polach_A", 0.0)]
    assert _core.rig_config_report({}) == []
    for unknown in ({"wheelset.mass": 1.0}, {"contact.fastsim_nx": 20}):
        with pytest.raises(ValueError, match="not a rig parameter"):
            _core.rig_config_report(unknown)


def test_record_and_wheel_fields_come_from_c():
    assert rig.RECORD_FIELDS == tuple(r[0] for r in _core.RIG_RECORD)
    assert len(rig.RECORD_FIELDS) == _core.REC_COUNT
    assert sum(w for _, w, _, _ in _core.RIG_WHEEL_FIELDS) == 35
    from rollerrig.rig.contact import WheelContact
    assert WheelContact._fields[:-1] == tuple(f[0] for f in _core.RIG_WHEEL_FIELDS)


def test_binding_takes_declared_names_and_refuses_the_rest():
    P = rr.default_parameters()
    table = rig.build._geometry(P)
    opts = rig.build._creep_options("t", P, None, None, None, {})
    for bad, msg in (({"wheelset.mass": 1.0}, "not a rig parameter"),
                     ({"contact.fastsim_nx": 20}, "creep-force option"),
                     ({"wheelset.mass_kg": -1.0}, "wheelset.mass_kg = -1.0"),
                     ({"integration.method": "rk4"}, "integration.method = 'rk4'"),
                     ({"integration.table_rows": 2.5}, "integration.table_rows = 2.5"),
                     ({"scenario.targets": [0.1, math.nan]}, "scenario.targets"),
                     ({"scenario.targets": [0.1]}, "scenario.target_start_s")):
        with pytest.raises(ValueError, match=msg):
            _core.Rig(table.data, table.y0, table.dy, bad, opts, 10.0)


def test_schedule_is_the_c_schedule():
    """rig.schedule is rr_rig_schedule (C, the paper program's rule); held here
    against the rule written with numpy: the target of the last start time
    <= k T, NaN before the first."""
    P = rr.default_parameters()
    S = P["scenario"]
    roller, xi = rig.schedule(P, S["duration_s"], S["control_sample_time_s"], S["targets"],
                              S["target_start_s"], S["roller_speed_m_s"])
    k = np.arange(roller.size)
    idx = np.searchsorted(S["target_start_s"], k * S["control_sample_time_s"], "right") - 1
    assert np.array_equal(xi, np.asarray(S["targets"])[idx])
    assert np.all(roller == S["roller_speed_m_s"] / P["roller"]["radius_m"])
    # a late first start, samples from the middle, start times between samples
    targets, starts, dt = [0.01, 0.03, 0.02], [0.0105, 0.02, 0.0333], 0.004
    roller, xi = rig.schedule(P, 0.1, dt, targets, starts, 5.0, first=2, stop=20)
    t = np.arange(2, 20) * dt
    idx = np.searchsorted(starts, t, "right") - 1
    want = np.where(idx >= 0, np.asarray(targets)[np.clip(idx, 0, None)], np.nan)
    assert np.array_equal(xi, want, equal_nan=True) and np.isnan(xi[0])
    with pytest.raises(ValueError, match="targets must have 1 to 256"):
        rig.schedule(P, 1.0, dt, [0.01] * 257, [0.0] * 257, 5.0)


# ------------------------------------------------------------------ what the rig cannot start with

@pytest.fixture
def builds(monkeypatch):
    """The C rigs and contact tables built from here on (the table cache
    emptied first, so that each table is counted)."""
    built = {"rig": 0, "table": 0}
    real_rig, real_table = _core.Rig, _core.rig_table

    def counted(kind, real):
        def call(*args):
            built[kind] += 1
            return real(*args)
        return call
    monkeypatch.setattr(_core, "Rig", counted("rig", real_rig))
    monkeypatch.setattr(_core, "rig_table", counted("table", real_table))
    rig.build._rig_table.cache_clear()
    yield built
    rig.build._rig_table.cache_clear()


#: a scenario file's usual changes, none of them at fault
CHANGED = {"wheelset": {"yaw_inertia_kg_m2": 0.9}, "suspension": {"kx_N_per_m": 2e5},
           "contact": {"poisson_ratio": 0.29}}


def _with(**sections):
    params = {k: dict(v) for k, v in CHANGED.items()}
    for section, values in sections.items():
        params.setdefault(section, {}).update(values)
    return params


SHORT = {"duration_s": 0.002, "targets": [0.02], "target_start_s": [0.0]}


def test_a_rule_the_report_judges_is_said_before_anything_is_built(builds):
    """The inertias' sum (Iyy) overflowing, and a scenario's duration under
    one sample, are rules of the C report: named with their keys before a
    rig is built.  Before, the sum gave "rig_speed_loops: input is NaN or
    infinite" (no key), the duration one rebuild per changed value (5 rigs
    here) to find the culprit."""
    with pytest.raises(rr.RollerRigError) as e:
        rr.simulate(params=_with(wheelset={"spin_inertia_kg_m2": 1.5e308},
                                 wheelset_drive={"drive_inertia_kg_m2": 1.5e308}))
    assert str(e.value) == ("simulate: params: wheelset.spin_inertia_kg_m2 + "
                            "wheelset_drive.drive_inertia_kg_m2 must be a finite number (the "
                            "wheelset's inertia with its drive's), got 1.5e+308 + 1.5e+308")
    with pytest.raises(rr.RollerRigError) as e:
        rr.build_rig(_with(scenario=SHORT))
    assert str(e.value) == ("build_rig: scenario.duration_s = 0.002 s is shorter than one "
                            "sample (scenario.control_sample_time_s = 0.004 s)")
    with pytest.raises(rr.RollerRigError, match=r"^build_rig: scenario.duration_s = 0.002 s is "
                                                r"shorter than one sample \(dt = 0.004 s\)$"):
        rr.build_rig(_with(scenario=SHORT), dt=0.004)
    assert builds == {"rig": 0, "table": 0}
    # simulate's duration is the run's, as its dt is: the file's does not refuse it
    res = rr.simulate(duration=0.04, targets=[0.02], target_times=[0.0],
                      params={"scenario": SHORT})
    assert res.status >= 0 and len(res) == 10


def test_the_start_no_rule_predicts_is_searched_once_per_changed_value(builds):
    """What stays of the rebuilds (rollerrig.rig.build._culprits): values each
    in range that the start's evaluation cannot carry (the contact's
    RR_ERR_RANGE) are found by putting each changed value back alone: one rig
    per changed value the start reads.  A geometry with no contact table
    is searched among the changed geometry keys only, by their tables, with
    no rig (before: a rig and its table per changed value of any kind)."""
    with pytest.raises(rr.RollerRigError) as e:
        rr.build_rig(_with(wheelset={"mass_kg": 1e300}))
    assert str(e.value).startswith("build_rig: the rig cannot start with params "
                                   "wheelset.mass_kg = 1e+300: Rig: ")
    assert builds == {"rig": 1 + 4, "table": 1}
    rig.build._rig_table.cache_clear()
    builds.update(rig=0, table=0)
    with pytest.raises(rr.RollerRigError) as e:
        rr.build_rig(_with(wheelset={"wheel_radius_m": 1e300}))
    assert str(e.value).startswith("build_rig: the rig cannot start with params "
                                   "wheelset.wheel_radius_m = 1e+300: params: the rig's geometry")
    assert builds == {"rig": 0, "table": 2}
    rig.build._rig_table.cache_clear()
    builds.update(rig=0, table=0)
    # a given roller speed is the run's: named as the argument
    with pytest.raises(rr.RollerRigError, match=r"^build_rig: the rig cannot start with "
                                                r"roller_speed = 1.7e\+308: "):
        rr.build_rig(roller_speed=1.7e308)
    assert builds == {"rig": 2, "table": 1}
