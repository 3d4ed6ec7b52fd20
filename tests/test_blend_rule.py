"""Blended FASTSIM's blend_rule (issue 14): CONTACT's rule and the library's
former one, against CONTACT's blended FASTSIM and against the exact theory.

CONTACT (m_hertz.f90, simpflex) blends L1, L2, L3 towards one flexibility
with the weight w = min(1, f/3), f = |(xi, eta)| / |(xi_ch, eta_ch)|,
xi_ch = mu N/(G c^2 C11), eta_ch = mu N/(G c^2 C22): spin does not enter the
weight (it does enter the single flexibility).  blend_rule="contact" is
that; "spin" weighs each creepage by its own characteristic one, spin too
(f = |(xi/xi_ch, eta/eta_ch, phi/phi_ch)|).
"""
import numpy as np
import pytest

import rollerrig as rr
from reference_cases import read_columns

CASES = read_columns("contact_exact_cases.csv")
MUN = CASES["mu"] * CASES["N"]
SPIN = CASES["has_spin"] > 0


def _forces(method, **opts):
    d = CASES
    return rr.creep_forces(d["xi"], d["eta"], d["phi"], a=d["a"], b=d["b"], N=d["N"],
                           mu=d["mu"], G=d["G"], nu=d["nu"], method=method, errors="raise",
                           **opts)


def _errors(f, key):
    dF = np.hypot(f.fx - CASES[key + "_Fx"], f.fy - CASES[key + "_Fy"]) / MUN
    dM = np.abs(f.mz - CASES[key + "_Mz"]) / (MUN * CASES["c"])
    return dF, dM


# CONTACT's FASTSIM runs: 45 elements across each semi-axis diameter on its
# potential contact area, parabolic bound (B=3): the library's rect grid,
# 45 x 45, has the same element centres
CONTACT_GRID = dict(nx=45, ny=45, grid="rect", bound="parabolic")


def test_the_option():
    o = rr.METHODS["fastsim_blended"].options["blend_rule"]
    assert o.type == "choice" and o.choices == ("contact", "spin")
    assert o.default == "contact"
    # the other FASTSIM variants have no such option
    assert "blend_rule" not in rr.METHODS["fastsim"].options
    assert "blend_rule" not in rr.METHODS["modified_fastsim"].options
    case = dict(cx=1e-3, cy=5e-4, cphi=0.5, a=6e-3, b=4e-3, N=1e4, mu=0.3)
    with pytest.raises(rr.RollerRigError, match="blend_rule"):
        rr.creep_forces(**case, method="fastsim_blended", blend_rule="kalker")
    with pytest.raises(rr.RollerRigError, match="blend_rule"):
        rr.creep_forces(**case, method="fastsim", blend_rule="contact")
    default = rr.creep_forces(**case, method="fastsim_blended")
    contact = rr.creep_forces(**case, method="fastsim_blended", blend_rule="contact")
    spin = rr.creep_forces(**case, method="fastsim_blended", blend_rule="spin")
    assert (default.fx, default.fy, default.mz) == (contact.fx, contact.fy, contact.mz)
    assert spin.fy != contact.fy


def test_contact_rule_is_contacts_blended_fastsim():
    # Side by side: plain FASTSIM against CONTACT's plain FASTSIM (fs45, the
    # no-blend library) and CONTACT's rule against CONTACT's blended FASTSIM
    # as shipped (fsb45), both on CONTACT's grid.  Measured (300 cases):
    #   plain vs fs45:            p95 0.0098, max 0.0162 muN; no spin max 1.2e-4
    #   rule "contact" vs fsb45:  p95 0.0096, max 0.0160 muN; no spin max 1.2e-4
    #   rule "spin" vs fsb45:     p95 0.038,  max 0.056 muN;  no spin p95 0.025
    # The blended match is the plain one: what is left is the grid
    # convention of the spin cases (both FASTSIMs' spin term), not the blend.
    # Tolerance: 0.012 muN at p95 (plain's 0.0098 plus 20 %), and no more
    # than plain's own p95 + 0.001; without spin 5e-4 (the coefficients'
    # and printed digits' level, 4x the measured 1.2e-4).
    plain, _ = _errors(_forces("fastsim", **CONTACT_GRID), "fs45")
    contact, contact_m = _errors(_forces("fastsim_blended", blend_rule="contact",
                                         **CONTACT_GRID), "fsb45")
    spin, _ = _errors(_forces("fastsim_blended", blend_rule="spin", **CONTACT_GRID), "fsb45")
    p95 = np.percentile(contact, 95)
    assert p95 < 0.012, p95
    assert p95 <= np.percentile(plain, 95) + 0.001, (p95, np.percentile(plain, 95))
    assert contact[~SPIN].max() < 5e-4, contact[~SPIN].max()
    # the moment too: measured p95 0.0021, max 0.0082 muN c (plain vs fs45 the same)
    assert np.percentile(contact_m, 95) < 0.004 and contact_m.max() < 0.012
    # the discrepancy was the rule: the former one stays far off
    assert np.percentile(spin, 95) > 0.03


def _p95(e):
    return float(np.percentile(e, 95))


def test_the_exact_theory_prefers_contacts_rule():
    # The default is the rule nearer the exact theory.  Measured at 30 x 30,
    # |dF|/(muN) p95 contact / spin:
    #   CONTACT's exact, 45 across (ex45):   0.042 / 0.053 (no spin 0.035 / 0.041)
    #   CONTACT's test table (3220 cases):   0.078 / 0.084
    #   own exact, 3000 cases (Richardson 27/54): 0.045 / 0.061
    #   own exact here, 300 cases, Richardson 15/30: 0.041 / 0.066
    # Mz p95 contact / spin: ex45 0.068 / 0.076, own 0.081 / 0.091.
    opts = dict(nx=30, ny=30)
    fc, mc = _errors(_forces("fastsim_blended", blend_rule="contact", **opts), "ex45")
    fs, ms = _errors(_forces("fastsim_blended", blend_rule="spin", **opts), "ex45")
    assert _p95(fc) < _p95(fs) and _p95(fc[SPIN]) < _p95(fs[SPIN])
    assert _p95(fc[~SPIN]) < _p95(fs[~SPIN])
    assert _p95(mc) < _p95(ms)
    table = {r: rr.reference.score("fastsim_blended", blend_rule=r, **opts)
             for r in ("contact", "spin")}
    assert table["contact"].overall["p95"] < table["spin"].overall["p95"]
    assert table["contact"].overall["median"] < table["spin"].overall["median"]
    own = rr.reference.own_exact_cases(n=300, seed=20261203, nx=15)
    s = {r: rr.reference.score("fastsim_blended", cases=own, blend_rule=r, **opts)
         for r in ("contact", "spin")}
    for level in (0.0, 0.5, 1.0):       # |psi| classes: no spin, up to 0.5, up to 1
        assert s["contact"].by_spin[level]["p95"] < s["spin"].by_spin[level]["p95"], level
    assert s["contact"].mz_overall["p95"] < s["spin"].mz_overall["p95"]
    assert rr.METHODS["fastsim_blended"].options["blend_rule"].default == "contact"
