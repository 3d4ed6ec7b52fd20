"""Every unit string the package writes is CF / UDUNITS ("1" dimensionless,
never the C tables' "-") and pint parses it (pint from the test extra;
skipped without it): a history's fields, its CSV header, DataFrame and
Dataset attributes, the sweeps' attributes, the fits' parameters, the
regression references.  The CSV's header carries the run's record, and
pandas and numpy still read the table; a CSV written before the header
(no '#' lines, or "-" units) still reads."""
import numpy as np
import pytest

import rollerrig as rr
from rollerrig import rig
from rollerrig._csv import read_table
from rollerrig._units import cf_unit, read_unit
from rollerrig.analysis import fit, sweep
from rollerrig.testing import CREEP_UNITS, creep_curve_fields, write_reference


@pytest.fixture(scope="module")
def res():
    return rr.simulate(duration=0.2, targets=[0.04, 0.02])


def _table_units(tmp_path, res):
    path = res.to_csv(tmp_path / "h.csv")
    names, units, meta, rows = read_table(path)
    return units


def _written(res, tmp_path):
    """(where, unit) of every unit string the package writes."""
    out = [(f"RECORD_UNITS[{k}]", u) for k, u in rig.RECORD_UNITS.items()]
    out += [(f"to_csv units[{k}]", u) for k, u in _table_units(tmp_path, res).items()]
    pytest.importorskip("pandas")
    out += [(f"to_dataframe attrs[{k}]", u) for k, u in res.to_dataframe().attrs["units"].items()]
    pytest.importorskip("xarray")
    ds = res.to_xarray()
    out += [(f"to_xarray {k}", v.attrs["units"]) for k, v in ds.variables.items()]
    out += [(f"to_xarray attrs {k}", v) for k, v in ds.attrs.items() if k.endswith("_units")]
    grid = {"cx": np.linspace(0, 0.01, 3), "mu": [0.2, 0.3]}
    fixed = dict(cy=0.0, cphi=0.0, a=3e-3, b=3e-3, N=1e3)
    for name, g, kw in (("creep_forces", grid, fixed),
                        ("hertz", {"A": [1.0, 2.0], "B": [1.0]}, {"N": 1e3}),
                        ("kalker_coefficients", {"a_over_b": [0.5, 1.0]}, {"nu": 0.28})):
        ds = rr.sweep(name, g, progress=False, **kw)
        out += [(f"sweep({name}) {k}", v.attrs["units"]) for k, v in ds.variables.items()
                if "units" in v.attrs]
    ds = rr.sweep_rig({"scenario.mu0": [0.3, 0.4]}, duration=0.2, targets=[0.04],
                      progress=False)
    out += [(f"sweep_rig {k}", v.attrs["units"]) for k, v in ds.variables.items()
            if "units" in v.attrs]
    out += [(f"sweep.UNITS[{k}]", u) for k, u in sweep.UNITS.items()]
    out += [(f"fit.PARAMETER_UNITS[{k}]", u) for k, u in fit.PARAMETER_UNITS.items()]
    out += [(f"testing.CREEP_UNITS[{k}]", u) for k, u in CREEP_UNITS.items()]
    out += [(f"PARAMETERS {p.name}", cf_unit(p.unit)) for p in rig.PARAMETERS if p.unit]
    out += [(f"WHEEL_FIELDS {n}", cf_unit(u)) for n, _, u, _ in rig.contact.WHEEL_FIELDS]
    return out


def test_no_unit_written_is_the_c_tables_dash(res, tmp_path):
    written = _written(res, tmp_path)
    assert len(written) > 200
    assert [w for w in written if w[1] in ("-", "")] == []


def pint_problems(written):
    """What pint does not parse of (where, unit) pairs: one line each (pint
    skipped without it).  The FMU's units are checked with it too
    (test_fmu.py: its modelDescription.xml is written by the C side)."""
    pint = pytest.importorskip("pint")
    ureg = pint.UnitRegistry()
    bad = []
    for where, unit in written:
        try:
            ureg.Quantity(1.0, unit)
        except Exception as e:               # pint's errors have no common base
            bad.append(f"{where}: pint does not parse {unit!r}: {e}")
    return bad


def test_pint_parses_every_unit_written(res, tmp_path):
    assert pint_problems(_written(res, tmp_path)) == []


def test_pint_problems_can_fail():
    pytest.importorskip("pint")
    bad = pint_problems([("a", "N m"), ("b", "-"), ("c", "1"), ("d", "kg m^^2")])
    assert [line.split(":")[0] for line in bad] == ["b", "d"]


def test_the_units_mean_what_the_fields_are(res):
    pint = pytest.importorskip("pint")
    ureg = pint.UnitRegistry()
    dims = {n: ureg.Quantity(1.0, u).dimensionality for n, u in rig.RECORD_UNITS.items()}
    assert dims["time"] == ureg.second.dimensionality
    assert dims["fx"] == ureg.newton.dimensionality
    assert dims["torque_roller"] == (ureg.newton * ureg.meter).dimensionality
    assert dims["roller_speed"] == (ureg.meter / ureg.second).dimensionality
    for n in ("creepage", "adhesion", "mu_left", "sample_status"):
        assert dims[n] == ureg.dimensionless.dimensionality, n


def test_cf_unit_and_old_spellings():
    assert cf_unit("-") == "1" and cf_unit(" - ") == "1" and cf_unit("") == ""
    assert cf_unit("N m s/rad") == "N m s/rad" and read_unit("-") == "1"


def test_the_csv_header_records_the_run_and_readers_still_read_it(tmp_path):
    scenario = tmp_path / "s.toml"
    scenario.write_text("[scenario]\nmu0 = 0.35\n[contact]\ncreep_method = \"polach\"\n")
    res = rr.simulate(duration=0.2, targets=[0.04], params=scenario)
    path = res.to_csv(tmp_path / "h.csv")
    names, units, meta, rows = read_table(path)
    import hashlib
    assert meta["rollerrig"] == rr.__version__ and meta["method"] == "polach"
    assert meta["scenario"] == str(scenario)
    assert meta["scenario_sha256"] == hashlib.sha256(scenario.read_bytes()).hexdigest()
    assert meta["changed_from_defaults"] == ('contact.creep_method = "polach"; '
                                             'scenario.mu0 = 0.35')
    assert units == rig.RECORD_UNITS and names == list(rig.RECORD_FIELDS)
    assert np.array_equal(np.array(rows), res.records, equal_nan=True)      # bit for bit
    back = np.genfromtxt(path, delimiter=",", names=True)
    assert back.dtype.names == rig.RECORD_FIELDS
    assert np.array_equal(back["fx"], res.fx)
    assert np.array_equal(np.loadtxt(path, delimiter=",", skiprows=1), res.records)
    pd = pytest.importorskip("pandas")
    frame = pd.read_csv(path, comment="#")
    assert list(frame.columns) == names and np.array_equal(frame["fx"].to_numpy(), res.fx)


def test_dataframe_and_dataset_carry_units_and_the_run(res):
    pytest.importorskip("pandas")
    df = res.to_dataframe()
    assert df.attrs["units"] == rig.RECORD_UNITS and df.attrs["units"]["creepage"] == "1"
    assert df.attrs["method"] == "fastsim" and df.attrs["rollerrig"] == rr.__version__
    assert df.attrs["scenario"] == "none: the default parameters"
    assert df.attrs["changed_from_defaults"] == "none"
    pytest.importorskip("xarray")
    ds = res.to_xarray()
    assert ds.creepage.attrs["units"] == "1" and ds.fx.attrs["units"] == "N"
    assert ds.attrs["rollerrig"] == rr.__version__ and ds.attrs["targets_units"] == "1"
    assert ds.attrs["duration_s"] == pytest.approx(0.2)


def test_a_table_written_before_its_header_still_reads(tmp_path):
    old = tmp_path / "old.csv"
    old.write_text("time,creepage\n0.004,0.001\n0.008,0.002\n")
    names, units, meta, rows = read_table(old)
    assert names == ["time", "creepage"] and units == {} and rows == [[0.004, 0.001],
                                                                       [0.008, 0.002]]
    dashed = tmp_path / "dashed.csv"
    dashed.write_text("time,creepage\n# units: s,-\n0.004,0.001\n")
    assert read_table(dashed)[1] == {"time": "s", "creepage": "1"}


def test_a_reference_in_long_form_carries_its_units(tmp_path):
    cx = np.linspace(0, 0.01, 3)
    fields, units = creep_curve_fields(cx, rr.creep_forces(cx, 0, 0, a=3e-3, b=3e-3, N=1e3,
                                                           mu=0.3))
    fields["grid"] = np.zeros((2, 2))
    units["grid"] = "m"
    _, csv_path = write_reference(str(tmp_path / "r"), fields, units)
    names, _, meta, rows = read_table(csv_path)
    assert names == ["field_number", "index_0", "index_1", "value"]
    assert "5 grid [m]" in meta["long form"] and len(rows) == 5 * 3 + 4
