"""FMI co-simulation units of the rig (rollerrig fmu, rollerrig/fmu.py): FMPy
validates them; with the default inputs FMPy's run is rollerrig.simulate()'s,
bit for bit; a friction input through FMPy is the same adhesion schedule in
simulate; two instances in one process are independent; bad input (unknown
names and value references, parameters out of range, a step that is not a
whole number of samples, calls out of order) gives an FMI error status and a
log message, never a crash; FMU states get, set, serialize.

Each FMU is built once per module (the core's objects cached between the
builds).  The C unit under the adapters has its own tests (csrc/tests/test_fmu.c).
"""
import os
import shutil
import subprocess
import zipfile

import numpy as np
import pytest

import rollerrig as rr
from rollerrig import cli, fmu, rig
from rollerrig._units import DIMENSIONLESS, cf_unit
from test_units import pint_problems

fmpy = pytest.importorskip("fmpy", reason="the test extra installs FMPy")
from fmpy import read_model_description, simulate_fmu  # noqa: E402
from fmpy.fmi1 import FMICallException  # noqa: E402
from fmpy.simulation import instantiate_fmu  # noqa: E402
from fmpy.validation import validate_fmu  # noqa: E402

pytestmark = pytest.mark.slow     # FMUs compiled and run by FMPy

T = 0.004
REC = list(rig.RECORD_FIELDS)
REAL_OUT = [n for n in REC if n not in ("time", "sample_status")]


def _toolchain():
    try:
        fmu.core_c_dirs()
        fmu.find_compiler()
    except fmu.FmuBuildError as e:
        pytest.skip(str(e))


@pytest.fixture(scope="module")
def cache():
    """The core's objects, compiled once per session (conftest.py)."""
    _toolchain()
    return os.environ["ROLLERRIG_FMU_CACHE"]


@pytest.fixture(scope="module")
def fmus(tmp_path_factory, cache):
    """{2: path, 3: path} of the FMUs of the default parameters."""
    d = tmp_path_factory.mktemp("fmus")
    return {v: fmu.build_fmu(d / f"rig{v}.fmu", fmi_version=v, cache_dir=cache)
            for v in fmu.FMI_VERSIONS}


@pytest.fixture(scope="module")
def unzipped(fmus, tmp_path_factory):
    out = {}
    for v, path in fmus.items():
        out[v] = tmp_path_factory.mktemp(f"unzipped{v}")
        with zipfile.ZipFile(path) as z:
            z.extractall(out[v])
    return out


@pytest.fixture(scope="module")
def reference():
    """rollerrig.simulate() of the default parameters."""
    return rr.simulate().records


def _bits_differ(res, ref, rows=None):
    """The record fields whose FMPy column is not ref's, bit for bit."""
    bad = []
    for i, name in enumerate(REC):
        if name == "time":
            continue
        got = np.asarray(res[name][1:], dtype=float)
        want = ref[:len(got), i] if rows is None else ref[rows, i]
        if got.shape != want.shape or not np.array_equal(got.view(np.uint64),
                                                          want.view(np.uint64)):
            bad.append(name)
    return bad


def _clock(k):
    """The rig's clock at sample k: T added k times, as the C rig does."""
    t = 0.0
    for _ in range(k):
        t += T
    return t


class _Log:
    """A logger for FMPy: FMI 2's and FMI 3's signatures; the messages kept."""

    def __init__(self, version):
        self.messages = []
        self.version = version

    def __call__(self, *args):
        message = args[-1]
        self.messages.append(message.decode() if isinstance(message, bytes) else message)

    def text(self):
        return "\n".join(self.messages)


def _instance(unzipdir, log=None):
    md = read_model_description(str(unzipdir))
    return md, instantiate_fmu(str(unzipdir), md, "CoSimulation", logger=log)


def _vr(md):
    return {v.name: v.valueReference for v in md.modelVariables}


def _get(f, version, vrs):
    return np.array(f.getReal(vrs) if version == 2 else f.getFloat64(vrs))


def _initialise(f, version, start=0.0):
    if version == 2:
        f.setupExperiment(startTime=start)
        f.enterInitializationMode()
    else:
        f.enterInitializationMode(startTime=start)
    f.exitInitializationMode()


# ------------------------------------------------------------------ the FMU as a file

@pytest.mark.parametrize("version", fmu.FMI_VERSIONS)
def test_fmpy_validation_lists_no_problem(fmus, version):
    assert validate_fmu(str(fmus[version])) == []


@pytest.mark.parametrize("version", fmu.FMI_VERSIONS)
def test_contents_binary_sources_and_exports(fmus, unzipped, version):
    plat, ext = fmu._platform_dir(version)
    ident = f"rig{version}"
    binary = unzipped[version] / "binaries" / plat / (ident + ext)
    assert binary.is_file()
    sources = unzipped[version] / "sources"
    c_files = sorted(p.relative_to(sources).as_posix() for p in sources.rglob("*.c"))
    assert "fmu_start.c" in c_files and "rig/rr_rig.c" in c_files \
        and f"fmi{version}_cs.c" in c_files and "fmu/rr_fmu.c" in c_files
    assert not (sources / "tests").exists()
    md = read_model_description(str(unzipped[version]))
    # FMI 2's <SourceFiles>, FMI 3's buildDescription.xml: every C file of sources/
    files = md.buildConfigurations[0].sourceFileSets[0].sourceFiles
    assert sorted(files) == c_files
    assert (unzipped[version] / "documentation" / "licenses" / "license.txt").is_file()
    nm = shutil.which("nm")
    if nm:
        out = subprocess.run([nm, "-D", "--defined-only", str(binary)], capture_output=True,
                             text=True).stdout
        exported = {line.split()[-1] for line in out.splitlines()
                    if line.split() and line.split()[-2] in ("T", "W")}
        assert exported and all(s.startswith(f"fmi{version}") for s in exported), exported
        assert len(exported) == (34 if version == 2 else 75)


def test_variables_come_from_the_declarations(unzipped):
    md = read_model_description(str(unzipped[2]))
    by_name = {v.name: v for v in md.modelVariables}

    def unit(declared, v):
        """The FMU's unit of a declaration's: the package's spelling ("-" is
        "1"), on a real only (FMI has none for the other types)."""
        return (cf_unit(declared) or None) if v.type == "Real" else None
    for p in rig.PARAMETERS:
        names = [p.name] if p.type != "list" else \
            [f"{p.name}[{k + 1}]" for k in range(len(p.default))]
        for k, n in enumerate(names):
            v = by_name[n]
            assert v.causality == "parameter" and v.unit == unit(p.unit, v), n
            default = rig.params._default_value(p)
            if p.type == "list":
                assert float(v.start) == default[k], n
            elif p.type == "choice" or p.creep and isinstance(default, str):
                assert [i.name for i in v.declaredType.items if i.value == v.start] \
                    == [default], n
            elif p.type == "flag":
                assert v.start == ("true" if default else "false"), n
            else:
                assert float(v.start) == float(default), n
    for name, declared, meaning in rig.RECORD:
        if name == "time":
            continue
        v = by_name[name]
        assert v.causality == "output" and v.description == meaning \
            and v.unit == unit(declared, v), name
    assert by_name["sample_status"].type == "Integer"
    assert by_name["mu"].causality == "input" and float(by_name["mu"].start) == 0.4
    assert by_name["scenario.mu0"].variability == "tunable"
    assert by_name["wheelset.mass_kg"].variability == "fixed"
    assert md.defaultExperiment.stepSize == "0.004" and md.defaultExperiment.stopTime == "20"


@pytest.mark.parametrize("version", fmu.FMI_VERSIONS)
def test_every_real_has_a_defined_unit_pint_reads(unzipped, version):
    # issue 26, item 4: every real carries a unit, dimensionless ones the
    # package's "1" (never empty), each defined in <UnitDefinitions> with base
    # units (written by the C side) that pint's reading of the unit agrees with
    pint = pytest.importorskip("pint")
    md = read_model_description(str(unzipped[version]))
    reals = [v for v in md.modelVariables if v.type in ("Real", "Float64")]
    assert len(reals) > 150
    assert [v.name for v in reals if not v.unit] == []
    assert [v.name for v in md.modelVariables if v not in reals and v.unit] == []
    defined = {u.name: u.baseUnit for u in md.unitDefinitions}
    assert {v.unit for v in reals} == set(defined)     # each one used is defined, no other
    assert pint_problems([(f"FMI {version} {v.name}", v.unit) for v in reals]) == []
    ureg = pint.UnitRegistry()
    for name, base in defined.items():
        root = ureg.Quantity(1.0, name).to_root_units()      # in gram, metre, second, radian
        exps = dict(root.unit_items())
        assert base is not None and (base.kg, base.m, base.s, base.rad) == tuple(
            exps.pop(k, 0) for k in ("gram", "meter", "second", "radian")) and not exps, name
        assert base.factor == 1.0 and base.offset == 0.0 \
            and root.magnitude == pytest.approx(1000.0 ** base.kg, rel=1e-12), name
    by_name = {v.name: v for v in md.modelVariables}
    for name in ("creepage", "scenario.mu0", "left.cx", "encoder.roller_count"):
        assert by_name[name].unit == DIMENSIONLESS, name


def test_docs_list_the_variables(unzipped):
    xml = (unzipped[2] / "modelDescription.xml").read_text(encoding="utf-8")
    if not fmu.DOCS_PATH.is_file():
        pytest.skip("docs/ not in this tree")
    assert fmu.DOCS_PATH.read_text(encoding="utf-8") == fmu.docs_text(xml), \
        "docs/fmu.md is stale: rollerrig.fmu.write_docs('rig.fmu') from an FMU of the defaults"


# ------------------------------------------------------------------ runs

@pytest.mark.parametrize("version", fmu.FMI_VERSIONS)
def test_default_run_is_simulate_bit_for_bit(fmus, reference, version):
    # one sample per communication step, and FMPy's own interval (8 samples)
    res = simulate_fmu(str(fmus[version]), output_interval=T)
    assert len(res) == 5001 and _bits_differ(res, reference) == []
    assert np.max(np.abs(res["time"][1:] - reference[:, 0])) < 1e-9
    if version == 2:
        res = simulate_fmu(str(fmus[version]))
        assert len(res) == 626
        assert _bits_differ(res, reference, rows=slice(7, None, 8)) == []


@pytest.mark.parametrize("version", fmu.FMI_VERSIONS)
def test_friction_input_is_the_adhesion_schedule(fmus, version):
    # mu 0.4 -> 0.15 -> 0.4, steps at sample instants (the rig's clock, which
    # the schedule is read at): FMPy holds a discrete input exactly
    t1, t2 = _clock(300), _clock(900)
    signal = np.array([(0.0, 0.4), (t1, 0.4), (t1, 0.15), (t2, 0.15), (t2, 0.4), (6.0, 0.4)],
                      dtype=[("time", float), ("mu", float)])
    res = simulate_fmu(str(fmus[version]), stop_time=6.0, output_interval=T,
                       start_values={"control.mu_source": 1}, input=signal)
    ref = rr.simulate(params={"adhesion": {"schedule_times_s": [0.0, t1, t1, t2, t2],
                                           "schedule_mu0": [0.4, 0.4, 0.15, 0.15, 0.4]}}
                      ).records
    assert len(res) == 1501 and _bits_differ(res, ref) == []
    mu = np.asarray(res["mu_left"][1:])
    assert mu[299] == 0.4 and mu[300] == 0.15 and mu[899] == 0.15 and mu[900] == 0.4
    # and the friction does act: the creep force follows it
    assert np.max(np.abs(res["fx"][350:900])) < 0.16 * 2 * 530


def test_drive_references_from_inputs(fmus):
    """control modes torque / speed: the inputs reach the drives."""
    res = simulate_fmu(str(fmus[2]), stop_time=0.4, output_interval=T,
                       start_values={"control.wheelset_mode": 3, "wheelset_torque_ref": -15.0,
                                     "control.roller_mode": 1, "roller_speed_ref": 30.0})
    assert np.all(res["torque_ref_wheelset"][1:] == -15.0)
    assert np.all(np.isnan(res["w_ref"][1:]))
    assert abs(res["roller_spin"][-1] - 30.0) < 0.5


def test_two_instances_in_one_process_are_independent(unzipped):
    md, a = _instance(unzipped[2])
    _, b = _instance(unzipped[2])
    vr = _vr(md)
    outs = [vr[n] for n in REAL_OUT]
    b.setReal([vr["scenario.mu0"]], [0.3])
    for f in (a, b):
        _initialise(f, 2)
    ra, rb = [], []
    for k in range(300):
        a.doStep(k * T, T)
        b.doStep(k * T, T)
        ra.append(_get(a, 2, outs))
        rb.append(_get(b, 2, outs))
    for f in (a, b):
        f.terminate()
        f.freeInstance()
    alone = simulate_fmu(str(unzipped[2]), stop_time=300 * T, output_interval=T,
                         start_values={"scenario.mu0": 0.3})
    alone = np.array([[alone[n][k + 1] for n in REAL_OUT] for k in range(300)])
    ref = rr.simulate(duration=300 * T, targets=[0.04], target_times=[0.0]).records
    ref = ref[:, [REC.index(n) for n in REAL_OUT]]
    assert np.array_equal(np.array(rb).view(np.uint64), alone.view(np.uint64))
    assert np.array_equal(np.array(ra).view(np.uint64), ref.view(np.uint64))
    mu = REAL_OUT.index("mu_left")
    assert ra[-1][mu] == 0.4 and rb[-1][mu] == 0.3


@pytest.mark.parametrize("version", fmu.FMI_VERSIONS)
def test_fmu_state_get_set_serialize_reproduce_a_run(unzipped, version):
    md, f = _instance(unzipped[version])
    vr = _vr(md)
    outs = [vr[n] for n in REAL_OUT] + [vr["encoder.wheelset_count"], vr["left.N"]]
    _initialise(f, version)
    for k in range(100):
        f.doStep(k * T, T)
    state = f.getFMUState()
    blob = f.serializeFMUState(state)

    def run(g):
        rows = []
        for k in range(100, 300):
            g.doStep(k * T, T)
            rows.append(_get(g, version, outs))
        return np.array(rows)
    first = run(f)
    f.setFMUState(state)
    again = run(f)
    f.freeFMUState(state)
    assert np.array_equal(first.view(np.uint64), again.view(np.uint64))
    # the bytes in a fresh instance, never initialised
    _, g = _instance(unzipped[version])
    restored = g.deserializeFMUState(blob)
    g.setFMUState(restored)
    g.freeFMUState(restored)
    elsewhere = run(g)
    assert np.array_equal(first.view(np.uint64), elsewhere.view(np.uint64))
    # bytes that are not a state: refused with a message
    log = _Log(version)
    _, h = _instance(unzipped[version], log)
    with pytest.raises(FMICallException):
        h.deserializeFMUState(blob[:-1] + bytes([blob[-1] ^ 1]) + b"x")
    assert "a state of this FMU is" in log.text()
    for x in (f, g, h):
        x.freeInstance()


def test_tunable_and_fixed_parameters_while_stepping(unzipped):
    log = _Log(2)
    md, f = _instance(unzipped[2], log)
    vr = _vr(md)
    _initialise(f, 2)
    f.doStep(0.0, 2 * T)
    f.setReal([vr["scenario.mu0"]], [0.25])
    f.doStep(2 * T, T)
    assert f.getReal([vr["mu_left"]]) == [0.25]
    with pytest.raises(FMICallException):
        f.setReal([vr["wheelset.mass_kg"]], [15.0])
    assert "wheelset.mass_kg is a fixed parameter" in log.text()
    f.freeInstance()


# ------------------------------------------------------------------ bad input

@pytest.mark.parametrize("version", fmu.FMI_VERSIONS)
def test_unknown_variable_names_and_value_references(fmus, unzipped, version):
    with pytest.raises(Exception, match="no.such.variable"):
        simulate_fmu(str(fmus[version]), stop_time=0.1, start_values={"no.such.variable": 1.0})
    log = _Log(version)
    md, f = _instance(unzipped[version], log)
    with pytest.raises(FMICallException):
        f.setReal([123456], [1.0]) if version == 2 else f.setFloat64([123456], [1.0])
    assert "unknown value reference 123456" in log.text()
    with pytest.raises(FMICallException):
        f.getInteger([_vr(md)["fx"]]) if version == 2 else f.getInt32([_vr(md)["fx"]])
    assert "fx (value reference 206) is of type" in log.messages[-1]
    if version == 3:
        with pytest.raises(FMICallException):
            f.getFloat32([_vr(md)["fx"]])
        assert "is of type Float64, not Float32" in log.messages[-1]
    f.freeInstance()


@pytest.mark.parametrize("version", fmu.FMI_VERSIONS)
def test_out_of_range_parameter_start(fmus, version):
    log = _Log(version)
    with pytest.raises(FMICallException):
        simulate_fmu(str(fmus[version]), stop_time=0.1, validate=False, logger=log,
                     start_values={"wheelset.mass_kg": -1.0})
    assert "wheelset.mass_kg = -1 is out of range: it must be a number in (0, inf) kg" \
        in log.text()
    log = _Log(version)
    with pytest.raises(FMICallException):
        simulate_fmu(str(fmus[version]), stop_time=0.1, logger=log,
                     start_values={"integration.table_rows": 1})
    assert "integration.table_rows = 1 is out of range: it must be an integer in [2, 100000]" \
        in log.text()
    # values each in range, but not together: the start times out of order
    log = _Log(version)
    with pytest.raises(FMICallException):
        simulate_fmu(str(fmus[version]), stop_time=0.1, logger=log,
                     start_values={"scenario.target_start_s[2]": 12.0})
    assert "scenario.target_start_s" in log.text() and "ExitInitializationMode" in log.text()


@pytest.mark.parametrize("version", fmu.FMI_VERSIONS)
@pytest.mark.parametrize("name,value", [("creepage_ref", np.nan), ("mu", np.inf),
                                        ("roller_speed_ref", -np.inf),
                                        ("wheelset.mass_kg", np.nan), ("scenario.mu0", np.inf),
                                        ("scenario.targets[2]", np.nan)])
def test_non_finite_start_value(fmus, version, name, value):
    """NaN and infinities are no value of any parameter or input: a start
    value set before the initialisation gets an FMI error and a log message
    naming it (issue 22: creepage_ref = NaN was taken and the FMU initialised)."""
    log = _Log(version)
    with pytest.raises(FMICallException):
        simulate_fmu(str(fmus[version]), stop_time=0.1, validate=False, logger=log,
                     start_values={name: value})
    assert f"{name} = {value!r}: the value must be a finite number" in log.text(), log.text()


@pytest.mark.parametrize("version", fmu.FMI_VERSIONS)
def test_non_finite_input_while_stepping(unzipped, version):
    log = _Log(version)
    md, f = _instance(unzipped[version], log)
    vr = _vr(md)
    _initialise(f, version)
    f.doStep(0.0, T)
    for value in (np.nan, np.inf, -np.inf):
        with pytest.raises(FMICallException):
            (f.setReal if version == 2 else f.setFloat64)([vr["creepage_ref"]], [value])
        assert f"creepage_ref = {value!r}: the value must be a finite number" \
            in log.messages[-1]
    assert _get(f, version, [vr["creepage_ref"]])[0] == 0.04
    f.doStep(T, T)
    f.freeInstance()


def test_free_wheelset_mode(fmus):
    """control.wheelset_mode = free: no creepage target, the wheelset about
    free rolling (what creepage_ref = NaN gave before NaN was refused)."""
    res = simulate_fmu(str(fmus[2]), stop_time=0.4, output_interval=T,
                       start_values={"control.wheelset_mode": 4})
    assert np.all(np.isnan(res["xi_ref"][1:])) and np.all(np.isfinite(res["w_ref"][1:]))
    assert np.max(np.abs(res["creepage"][1:])) < 1e-3


@pytest.mark.parametrize("version", fmu.FMI_VERSIONS)
def test_step_not_a_whole_number_of_samples(fmus, version):
    log = _Log(version)
    with pytest.raises(FMICallException):
        simulate_fmu(str(fmus[version]), stop_time=0.1, output_interval=0.005, logger=log)
    assert ("the communication step 0.005 s is not a whole multiple of the control sample "
            "time 0.004 s") in log.text()


@pytest.mark.parametrize("version", fmu.FMI_VERSIONS)
def test_calls_out_of_order_and_wrong_token(unzipped, version):
    log = _Log(version)
    md, f = _instance(unzipped[version], log)
    vr = _vr(md)
    with pytest.raises(FMICallException):
        f.doStep(0.0, T)
    assert "not allowed when the unit is instantiated" in log.messages[-1]
    with pytest.raises(FMICallException):
        _get(f, version, [vr["fx"]])
    assert "the output is known from the initialization mode on" in log.messages[-1]
    _initialise(f, version)
    with pytest.raises(FMICallException):
        f.doStep(0.008, T)
    assert "currentCommunicationPoint 0.008 s is not the unit's time 0 s" in log.messages[-1]
    f.doStep(0.0, T)
    with pytest.raises(FMICallException):
        f.exitInitializationMode()
    f.terminate()
    with pytest.raises(FMICallException):
        f.doStep(T, T)
    f.reset()
    _initialise(f, version)
    f.doStep(0.0, 3 * T)
    f.freeInstance()
    # a description of another build: the binary refuses its token
    md.guid = md.instantiationToken = "{not-this-one}"
    log = _Log(version)
    with pytest.raises(Exception):
        instantiate_fmu(str(unzipped[version]), md, "CoSimulation", logger=log)
    assert "is not this FMU's" in log.text()


# ------------------------------------------------------------------ the command

def test_command_with_a_scenario_file(tmp_path, cache, monkeypatch, capsys):
    scenario = tmp_path / "short.toml"
    scenario.write_text('[scenario]\nduration_s = 1.0\ntargets = [0.02, 0.01]\n'
                        'target_start_s = [0.0, 0.5]\nmu0 = 0.3\n'
                        '[contact]\ncreep_method = "polach"\n'
                        '[adhesion]\npatch_length_m = 0.2\n')
    out = tmp_path / "short.fmu"
    assert cli.main(["fmu", str(out), "--scenario", str(scenario), "--fmi", "3"]) == 0
    assert "wrote" in capsys.readouterr().out
    assert validate_fmu(str(out)) == []
    md = read_model_description(str(out))
    by_name = {v.name: v for v in md.modelVariables}
    assert float(by_name["scenario.mu0"].start) == 0.3 and "scenario.targets[3]" not in by_name
    assert md.defaultExperiment.stopTime == "1"
    res = simulate_fmu(str(out), output_interval=T)
    assert _bits_differ(res, rr.simulate(params=str(scenario)).records) == []


def test_command_refuses_bad_input(tmp_path, monkeypatch, capsys):
    bad = tmp_path / "bad.toml"
    bad.write_text("[wheelset]\nmass_kg = -1.0\n")
    assert cli.main(["fmu", str(tmp_path / "x.fmu"), "--scenario", str(bad)]) == 2
    err = capsys.readouterr().err
    assert err.startswith("rollerrig fmu: ") and "wheelset.mass_kg" in err
    assert cli.main(["fmu", str(tmp_path)]) == 2
    assert "is a directory" in capsys.readouterr().err
    (tmp_path / "file").write_text("")
    assert cli.main(["fmu", str(tmp_path / "file" / "x.fmu")]) == 2
    assert capsys.readouterr().err == (f"rollerrig fmu: {tmp_path / 'file' / 'x.fmu'}: "
                                       f"{tmp_path / 'file'} is not a directory\n")
    monkeypatch.setenv("CC", str(tmp_path / "no-such-cc"))
    assert cli.main(["fmu", str(tmp_path / "x.fmu")]) == 2
    assert "the C compiler $CC" in capsys.readouterr().err
    monkeypatch.delenv("CC")
    monkeypatch.setenv("PATH", str(tmp_path))
    with pytest.raises(fmu.FmuBuildError, match="no C compiler found"):
        fmu.build_fmu(tmp_path / "x.fmu")
    assert not (tmp_path / "x.fmu").exists()
    with pytest.raises(rr.RollerRigError, match="built for Coulomb friction"):
        fmu.build_fmu(tmp_path / "x.fmu", scenario={"contact": {"creep_method": "fastrip"}})
    with pytest.raises(rr.RollerRigError, match="fmi_version must be 2 or 3"):
        fmu.build_fmu(tmp_path / "x.fmu", fmi_version=1)
