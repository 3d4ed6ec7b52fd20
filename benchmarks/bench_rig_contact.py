#!/usr/bin/env python3
"""Speed of the contact evaluation of the rig's wheelset on its rollers (issue 3).

    python benchmarks/bench_rig_contact.py            # full run (about 2-3 minutes)
    python benchmarks/bench_rig_contact.py --quick    # smoke run with small sizes

Measures on this machine, in one run (see benchmarks/README.md):

1. the C kernels alone: benchmarks/bench_rig.c, compiled here into a
   temporary directory, builds the default rig's wheel/roller pair
   (rollerrig/data/rig_default.toml) and its contact table, and times with
   clock_gettime, best of several passes, over random realistic states: the
   direct contact search, the direct wheelset solve, the table build, the
   table lookup, Hertz, the creepages, rr_rig_kinematics and the whole
   evaluation rr_rig_contact with FASTSIM 20x20, FASTSIM 10x10, Polach and
   linear theory (and FASTSIM 20x20 with the friction at the rigid slip
   speed, for comparison); from these the share of geometry in the whole
   evaluation;
2. the Python batched call rollerrig.rig_contact(table, ...) on the same
   states, taking turns with the C kernel built with the extension's own
   compiler flags: us per wheel and the batch overhead; and that the two
   agree.

Writes its Markdown report as the "rig_contact" section of
benchmarks/RESULTS.md (full run), benchmarks/out/RESULTS-quick.md (--quick)
or --out PATH, leaving the other sections of that file (bench_contact.py's)
as they are, and prints it.  Timing is reported, never asserted: the exit
status is 0 whether or not a goal is met.
"""
import datetime
import json
import math
import os
import subprocess
import sys
import tempfile
import time
import tomllib

import numpy as np

import rollerrig as rr

from _bench_common import (ROOT, CProgram, CpuMonitor, command_text, conditions_lines,
                           extension_flags, fmt, interleaved, load_average, log, machine_info,
                           kernel_report_head, report_path, timed, verdict, write_section,
                           bench_args)

# Goals of issue 3 (compared in the report; nothing is asserted).
GOAL_LOOKUP_US = 0.2            # table lookup: <= 0.2 us (per wheel)
GOAL_WHOLE_US = 5.0             # whole contact evaluation, FASTSIM 20x20: <= 5 us per wheel
GOAL_GEOMETRY_SHARE = 0.10      # geometry: <= 10 % of the whole evaluation
PAPER_GEOMETRY_SHARE = 0.70     # the seed paper: geometry 70 % of its contact model's time

PLAIN_FLAGS = ["-O3", "-std=c99", "-Wall", "-Wextra", "-pedantic", "-Werror"]

SIZES = {
    # states: timed states (every item but the two direct searches); search /
    # solve: states of rr_contact_search / rr_wheelset_contact (35 / 600 us
    # each); Python calls: py_repeats for FASTSIM, py_repeats_cheap for the
    # rest; check: states compared between C and Python.
    "full": dict(states=100_000, search=10_000, solve=1_000, c_repeats=3, py_repeats=3,
                 py_repeats_cheap=5, check=2_000),
    "quick": dict(states=5_000, search=500, solve=50, c_repeats=2, py_repeats=2,
                  py_repeats_cheap=3, check=500),
}

# bench_rig.c's method keys: label, rig_contact keywords
METHODS = [
    ("fastsim20", "FASTSIM 20x20", dict(method="fastsim", nx=20, ny=20)),
    ("fastsim10", "FASTSIM 10x10", dict(method="fastsim", nx=10, ny=10)),
    ("polach", "Polach", dict(method="polach")),
    ("linear", "linear theory", dict(method="linear")),
    ("fastsim20_rigid", "FASTSIM 20x20, friction at the rigid slip speed",
     dict(method="fastsim", nx=20, ny=20, slip_speed="rigid")),
]

TOML = os.path.join(ROOT, "rollerrig", "data", "rig_default.toml")


# ------------------------------------------------------------------ the rig

# the benchmark's roller profile spans +-20 mm (bench_rig.c ROLLER_HALF; the former
# roller.width_m / 2, a key that acted on nothing and left the parameters)
ROLLER_HALF_WIDTH = 0.020


def rig_parameters():
    """The default rig's values from rig_default.toml, under bench_rig.c's
    names (its "params" JSON)."""
    with open(TOML, "rb") as fh:
        t = tomllib.load(fh)
    ws, ro, co, sc = t["wheelset"], t["roller"], t["contact"], t["scenario"]
    it = t.get("integration", {})
    return dict(r0=ws["wheel_radius_m"], conicity=ws["conicity"],
                wheel_half_width=ws["profile_half_width_m"], R0=ro["radius_m"],
                crown_radius=ro["crown_radius_m"],
                # the rig's roller profile spans the wheel's (rig.build._rig_table)
                roller_half_width=ws["profile_half_width_m"],
                half_spacing=ws["contact_half_spacing_m"],
                roller_half_spacing=ws["contact_half_spacing_m"],
                E=co["youngs_modulus_Pa"], nu=co["poisson_ratio"], mu0=sc["mu0"],
                A=co["polach_A"], B=co["polach_B_s_per_m"], kA=co["polach_kA"],
                kS=co["polach_kS"], vmin=co["min_rolling_speed_m_s"],
                fastsim_n=co["fastsim_nx"], fastsim_ny=co["fastsim_ny"],
                roller_speed=sc["roller_speed_m_s"], creep_method=co["creep_method"],
                friction_law=co["friction_law"],
                fastsim_slip_speed=co.get("fastsim_slip_speed", "local"),
                # the time step's table; bench_rig.c's defaults where the TOML has none
                table_rows=it.get("table_rows", 161),
                table_half_range=it.get("table_half_range_m", 0.008),
                table_from_toml="table_rows" in it and "table_half_range_m" in it)


def check_parameters(toml, params):
    """Differences between bench_rig.c's built-in values and the TOML's."""
    bad = []
    if toml["roller_half_spacing"] != toml["half_spacing"]:
        bad.append("roller and wheelset contact half-spacings differ in the TOML")
    if toml["fastsim_ny"] != toml["fastsim_n"]:
        bad.append("fastsim_nx != fastsim_ny in the TOML")
    if toml["creep_method"] != "fastsim" or toml["friction_law"] != "polach_falling":
        bad.append(f"TOML creep method {toml['creep_method']!r}, friction law "
                   f"{toml['friction_law']!r}")
    for key, v in params.items():
        if key in toml and not math.isclose(v, toml[key], rel_tol=1e-12):
            bad.append(f"{key}: bench_rig.c {v!r}, TOML {toml[key]!r}")
    return bad


def rig_geometry(p):
    """The pair bench_rig.c builds (rr_rig_table_build), as a RigGeometry:
    the rig's own profiles, Profile.conical and Profile.cylinder, whose
    points and not-a-knot splines are the same C (rig.build._rig_table's)."""
    n, hw = p["wheel_knots"], p["wheel_half_width"]
    wheel = rr.Profile.conical(math.atan(p["conicity"]), (-hw, hw), r0=p["r0"], n=n)
    roller = rr.Profile.cylinder((-hw, hw), crown_radius=p["crown_radius"], n=n)
    return rr.RigGeometry(wheel=wheel, roller=roller, wheel_radius=p["r0"],
                          roller_radius=p["R0"], wheel_y=p["half_spacing"],
                          roller_y=p["half_spacing"])


def read_dump(path):
    """bench_rig --dump FILE: the states, the C table, FASTSIM 20x20 outputs."""
    raw = np.fromfile(path, dtype=np.float64)
    n, ncheck, rows = raw[:3].view(np.int64)
    y0, dy = raw[3:5]
    tlen = len(raw) - 5 - 10 * n - 17 * ncheck       # rr_contact_table_len(rows)
    table = raw[5:5 + tlen]
    cols = raw[5 + tlen:]
    names = ("x", "y", "yaw", "vx", "vy", "yaw_rate", "spin", "roller_spin", "N_left",
             "N_right")
    states = {k: cols[i * n:(i + 1) * n] for i, k in enumerate(names)}
    out = cols[10 * n:].reshape(17, ncheck)
    fields = ("cx", "cy", "cphi", "a", "b", "fx", "fy", "mz")
    c_out = dict(status=out[0],
                 left={f: out[1 + i] for i, f in enumerate(fields)},
                 right={f: out[9 + i] for i, f in enumerate(fields)})
    return dict(n=int(n), ncheck=int(ncheck), rows=int(rows), y0=y0, dy=dy, table=table,
                states=states, c_out=c_out)


# --------------------------------------------------------------- C kernels

class RigBench(CProgram):
    def __init__(self, tmpdir, flags=None, name="bench_rig"):
        super().__init__(tmpdir, "bench_rig.c", PLAIN_FLAGS, flags, name)

    def run(self, sz, *extra):
        args = ["--states", str(sz["states"]), "--search-states", str(sz["search"]),
                "--solve-states", str(sz["solve"]), "--check-states", str(sz["check"]),
                "--table-rows", str(sz["table_rows"]),
                "--table-half-range", repr(sz["table_half_range"])]
        proc = subprocess.run([self.exe] + args + [str(a) for a in extra], capture_output=True,
                              text=True)
        if proc.returncode != 0:
            raise RuntimeError(f"bench_rig failed: {proc.stderr.strip()}")
        return json.loads(proc.stdout)


def c_section(kernel, sz):
    res = kernel.run(sz, "--repeats", sz["c_repeats"])
    log(f"  C kernel: {json.dumps(res['us'])}")
    return res


# ------------------------------------------------------------------ Python

def rig_kwargs(toml):
    return dict(mu=toml["mu0"], friction=rr.FallingFriction(A=toml["A"], B=toml["B"]),
                E=toml["E"], nu=toml["nu"], vmin=toml["vmin"])


def method_kwargs(kw, toml):
    """A method's options: Polach's reduction factors from the parameters (the
    other methods have none: the registry refuses options a method lacks)."""
    return dict(kw, kA=toml["kA"], kS=toml["kS"]) if kw["method"] == "polach" else kw


def python_section(kernel_ext, sz, toml, params, dump):
    g = rig_geometry(params)
    y_lo = dump["y0"]
    y_hi = dump["y0"] + dump["dy"] * (dump["rows"] - 1)
    t0 = time.perf_counter()
    table = rr.contact_table(g, y_lo, y_hi, dump["rows"])
    t_build = time.perf_counter() - t0
    ctab = dump["table"]
    table_diff = float(np.max(np.abs(table.data.ravel() - ctab) / np.maximum(1.0, np.abs(ctab))))
    states = dump["states"]
    common = rig_kwargs(toml)

    # agreement on the first `check` states, FASTSIM 20x20
    k = dump["ncheck"]
    first = {name: v[:k] for name, v in states.items()}
    res = rr.rig_contact(table, **first, **common, method="fastsim", nx=20, ny=20,
                         errors="ignore")
    c_out = dump["c_out"]
    worst = dict(force=0.0, creepage=0.0, ellipse=0.0)
    for side, w in (("left", res.left), ("right", res.right)):
        c = c_out[side]
        N = first[f"N_{side}"]
        worst["force"] = max(worst["force"], float(np.max(np.hypot(w.fx - c["fx"], w.fy - c["fy"])
                                                          / (toml["mu0"] * N))))
        for f in ("cx", "cy"):
            worst["creepage"] = max(worst["creepage"], float(np.max(np.abs(getattr(w, f) - c[f]))))
        for f in ("a", "b"):
            worst["ellipse"] = max(worst["ellipse"],
                                   float(np.max(np.abs(getattr(w, f) / c[f] - 1.0))))
    status_same = bool(np.array_equal(res.status.astype(float), c_out["status"]))

    # timing: the batched call over all states, taking turns with the kernel
    # built with the extension's flags
    rows = []
    specs = [("kinematics", "rr_rig_kinematics (kinematics_only=True)",
              dict(method="fastsim", nx=20, ny=20, kinematics_only=True))] \
        + [(f"contact_{key}", label, kw) for key, label, kw in METHODS]
    n = dump["n"]
    for item, label, kw in specs:
        kw = method_kwargs(kw, toml)
        log(f"  {label}: Python batched on {n} states, C kernel (extension's flags) ...")

        last = {}

        def call(kw=kw, last=last):
            last["res"] = rr.rig_contact(table, **states, **common, **kw, errors="ignore")
        rr.rig_contact(table, **{k: v[:100] for k, v in states.items()}, **common, **kw,
                       errors="ignore")               # warm-up
        fns = [timed(call)]
        if kernel_ext.ok:
            def run_c(item=item):
                out = kernel_ext.run(sz, "--only", item, "--repeats", 1)
                return out["us"][item] * 1e-6 * n
            fns.append(run_c)
        repeats = sz["py_repeats"] if kw["method"] == "fastsim" and "kinematics_only" not in kw \
            else sz["py_repeats_cheap"]
        times = interleaved(fns, repeats)
        rows.append(dict(item=item, label=label, py_us=times[0] / n * 1e6,
                         ext_us=times[1] / n * 1e6 if kernel_ext.ok else None, repeats=repeats,
                         not_ok=int(np.count_nonzero(last["res"].status != 0))))
    return dict(rows=rows, build_s=t_build, table_diff=table_diff, worst=worst,
                status_same=status_same, check=k)


# ------------------------------------------------------------------ report

def report(args, info, load0, load1, date, params, toml, bad_params, c, py, kernel,
           kernel_ext, mon, elapsed, sz):
    us = c["us"]
    d = c["derived"]
    n = c["states"]
    placement = d["placement_wheelset_us"]
    py_by = {r["item"]: r for r in py["rows"]} if py else {}
    L = kernel_report_head("Contact evaluation on the rig (issue 3)", args, info, date,
                           elapsed, kernel, kernel_ext)
    L += conditions_lines(load0, load1, mon)
    L.append(f"- C kernel: best of {c['repeats']} passes (clock_gettime), the items taking "
             f"turns within a round; Python: best of {sz['py_repeats']} (FASTSIM) or "
             f"{sz['py_repeats_cheap']} (the rest) calls (time.perf_counter), each taking turns "
             "with one pass of the C kernel built with the extension's flags.")
    L.append("")
    L.append("The rig: rollerrig/data/rig_default.toml's conical 1:20 wheel "
             f"(r0 = {params['r0']} m, profile +-{params['wheel_half_width'] * 1e3:g} mm, "
             f"{params['wheel_knots']} knots) on a crowned roller (R0 = {params['R0']} m, crown "
             f"radius {params['crown_radius']} m, profile +-{params['roller_half_width'] * 1e3:g}"
             f" mm, {params['roller_knots']} knots), not-a-knot splines (rr_rig_table_build, as rr.simulate()), "
             f"contact half-spacing {params['half_spacing']} m; contact table of "
             f"{c['table']['rows']} rows over y = {c['table']['y0'] * 1e3:g} .. "
             f"{(c['table']['y0'] + c['table']['dy'] * (c['table']['rows'] - 1)) * 1e3:g} mm "
             f"(dy = {c['table']['dy'] * 1e3:g} mm), {params['nsamples']} search samples. "
             f"E = {params['E']:g} Pa, nu = {params['nu']}; falling friction mu0 = "
             f"{params['mu0']}, A = {params['A']}, B = {params['B']} s/m; vmin = "
             f"{params['vmin']} m/s; FASTSIM rect grid, parabolic bound, friction at each "
             f"element's local slip speed; Polach kA = {params['kA']}, kS = {params['kS']}. "
             + ("Every value as in the TOML." if not bad_params else
                "**Differs from the TOML: " + "; ".join(bad_params) + "**"))
    L.append("")
    L.append("Table size: " + ("the TOML's [integration] table_rows, table_half_range_m."
                               if toml["table_from_toml"] else
                               "bench_rig.c's default (the TOML has no [integration] "
                               "table_rows, table_half_range_m)."))
    L.append("")
    L.append(f"States: {n} uniform random (x +-1 mm, y +-3 mm, yaw +-2 mrad, vx, vy +-0.02 m/s, "
             "yaw rate +-0.1 rad/s, roller surface speed "
             f"{params['roller_speed']:g} m/s, wheelset spin for 0-5 % braking creepage, "
             f"N 400-700 N per wheel); the direct search on the first {c['search_states']}, "
             f"the direct wheelset solve on the first {c['solve_states']} (they cost far more).")
    L.append("")

    # goals: FASTSIM 20x20 as the rig runs it (rig_default.toml's fastsim_slip_speed)
    rig_slip = toml.get("fastsim_slip_speed", "local")
    f20 = d["fastsim20_rigid"] if rig_slip == "rigid" else d["fastsim20"]
    lookup_wheel = d["lookup_wheel_us"]
    goals = [("table lookup, per wheel (C)", f"{fmt(lookup_wheel)} us "
              f"({fmt(us['lookup'])} us per wheelset)", f"<= {GOAL_LOOKUP_US:g} us",
              lookup_wheel <= GOAL_LOOKUP_US),
             (f"whole contact evaluation, FASTSIM 20x20 ({rig_slip} slip speed, the rig's "
              "default), per wheel (C)",
              f"{fmt(f20['whole_wheel_us'])} us", f"<= {GOAL_WHOLE_US:g} us",
              f20["whole_wheel_us"] <= GOAL_WHOLE_US)]
    if py and rig_slip != "rigid":
        p20 = py_by["contact_fastsim20"]["py_us"] / 2
        goals.append(("whole contact evaluation, FASTSIM 20x20, per wheel (Python batched)",
                      f"{fmt(p20)} us", f"<= {GOAL_WHOLE_US:g} us", p20 <= GOAL_WHOLE_US))
    goals.append(("geometry share of the whole evaluation, FASTSIM 20x20",
                  f"{100 * f20['geometry_share']:.2f} %",
                  f"<= {100 * GOAL_GEOMETRY_SHARE:g} % (the paper: "
                  f"{100 * PAPER_GEOMETRY_SHARE:g} %)",
                  f20["geometry_share"] <= GOAL_GEOMETRY_SHARE))
    L.append("## Goals")
    L.append("")
    L.append("| goal | measured | target | result |")
    L.append("| --- | --- | --- | --- |")
    for gl in goals:
        L.append(f"| {gl[0]} | {gl[1]} | {gl[2]} | {verdict(gl[3])} |")
    L.append("")
    rigid = d["fastsim20_rigid"]["whole_wheel_us"]
    L.append(f"FASTSIM 20x20 with falling friction at each element's local slip speed (the "
             f"contact core's default with falling friction) costs "
             f"{fmt(d['fastsim20']['whole_wheel_us'])} us per wheel; "
             f"with one friction value at the rigid slip speed (slip_speed=\"rigid\") "
             f"{fmt(rigid)} us. Local slip solves for each slipping element's slip speed by "
             "Newton's method (rr_fastsim.c, falling_bound: an exp per iteration), and at "
             "0-5 % braking creepage nearly every element slips.")
    L.append("")

    # parts
    L.append("## The parts (C kernel)")
    L.append("")
    L.append("| part | C function | us per call | per | us per wheel |")
    L.append("| --- | --- | ---: | --- | ---: |")
    parts = [
        ("direct contact search of one wheel, at the table's pose", "rr_contact_search",
         us["search"], "wheel", us["search"]),
        ("direct wheelset solve (height and roll, both contacts)", "rr_wheelset_contact",
         us["wheelset"], "wheelset", us["wheelset"] / 2),
        (f"contact table build ({c['table']['rows']} rows)", "rr_contact_table_build",
         us["build"], "table", None),
        ("  the same, per row", "", d["build_row_us"], "row", None),
        ("table lookup with slopes, both wheels", "rr_contact_table_lookup", us["lookup"],
         "wheelset", lookup_wheel),
        ("Hertz ellipse", "rr_hertz", us["hertz"], "wheel", us["hertz"]),
        ("creepages", "rr_creepage", us["creepage"], "wheel", us["creepage"]),
        ("kinematics: lookup, placement, both creepages", "rr_rig_kinematics",
         us["kinematics"], "wheelset", us["kinematics"] / 2),
        ("contact placement = kinematics - lookup - 2 creepages", "(derived)", placement,
         "wheelset", placement / 2),
    ]
    for name, fn, v, per, pw in parts:
        L.append(f"| {name} | {fn} | {fmt(v)} | {per} | {fmt(pw)} |")
    L.append("")
    L.append("The contact placement is what rr_rig_kinematics does besides the lookup and "
             "the two rr_creepage calls: the model check, the wheelset's pose and rates, "
             "the turn and yaw shift of each contact point round the roller and its frame. "
             f"The table lookup replaces a direct wheelset solve "
             f"{us['wheelset'] / us['lookup']:.0f} times as costly.")
    L.append("")

    # whole evaluation
    L.append("## The whole evaluation, per creep-force method")
    L.append("")
    L.append("rr_rig_contact per wheelset (both wheels), here per wheel = per wheelset / 2. "
             "Geometry share = (table lookup + contact placement) / whole evaluation; "
             "kinematics share = rr_rig_kinematics (lookup + placement + both creepages) / "
             "whole evaluation. Creep forces and the rest = whole - kinematics - 2 Hertz "
             "(the creep-force method, the force and moment assembly). "
             "Python batched: rollerrig.rig_contact(table, ...) in one call on all "
             f"{n} states; batch overhead = Python batched - C kernel built with the "
             "extension's flags, per wheel.")
    L.append("")
    L.append("| method | C us/wheel | geometry share | kinematics share | "
             "creep forces and rest us/wheel | Python batched us/wheel | "
             "C, extension's flags us/wheel | batch overhead us/wheel | status != 0 |")
    L.append("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
    for key, label, _ in METHODS:
        dm = d[key]
        whole = us[f"contact_{key}"]
        rest = (whole - us["kinematics"] - 2 * us["hertz"]) / 2
        p = py_by.get(f"contact_{key}")
        pyw = None if p is None else p["py_us"] / 2
        extw = None if p is None or p["ext_us"] is None else p["ext_us"] / 2
        ov = None if pyw is None or extw is None else pyw - extw
        L.append(f"| {label} | {fmt(dm['whole_wheel_us'])} | "
                 f"{100 * dm['geometry_share']:.2f} % | {100 * dm['kinematics_share']:.2f} % | "
                 f"{fmt(rest)} | {fmt(pyw)} | {fmt(extw)} | {fmt(ov)} | "
                 f"{'n/a' if p is None else p['not_ok']} |")
    if py:
        p = py_by["kinematics"]
        pyw, extw = p["py_us"] / 2, (p["ext_us"] / 2 if p["ext_us"] is not None else None)
        ov = None if extw is None else pyw - extw
        L.append(f"| kinematics only (no Hertz, no forces) | {fmt(us['kinematics'] / 2)} | | | "
                 f"| {fmt(pyw)} | {fmt(extw)} | {fmt(ov)} | {p['not_ok']} |")
    L.append("")
    bad = {k: v for k, v in c["bad"].items() if v}
    L.append("Calls with an error status in the C kernel: "
             + (", ".join(f"{k} {v}" for k, v in bad.items()) if bad else "none") + ".")
    L.append("")

    # checks
    if py:
        w = py["worst"]
        agree = w["force"] <= 1e-9 and w["creepage"] <= 1e-12 and w["ellipse"] <= 1e-9 \
            and py["status_same"]
        L.append("## C = Python")
        L.append("")
        L.append(f"The Python side builds the same pair (Profile.conical, Profile.cylinder: "
                 f"the same C points and splines) and its table with rollerrig.contact_table in "
                 f"{py['build_s'] * 1e3:.0f} ms (C: {us['build'] * 1e-3:.0f} ms); largest "
                 f"difference from the C table {fmt(py['table_diff'])} (relative, at least "
                 f"absolute). On the first {py['check']} states with FASTSIM 20x20: "
                 f"|dF| / (mu N) <= {fmt(w['force'])}, |d cx|, |d cy| <= {fmt(w['creepage'])}, "
                 f"a and b within {fmt(w['ellipse'])} (relative), statuses "
                 f"{'equal' if py['status_same'] else '**differ**'}: "
                 f"{'agree' if agree else '**disagree**'}.")
        L.append("")
    return "\n".join(L)


def main(argv=None):
    args = bench_args(__doc__, argv)
    args.command = command_text(argv)
    out = report_path(args)
    sz = SIZES["quick" if args.quick else "full"]
    date = datetime.datetime.now().astimezone().isoformat(timespec="seconds")
    load0 = load_average()
    t_start = time.perf_counter()
    toml = rig_parameters()
    sz = dict(sz, table_rows=toml["table_rows"], table_half_range=toml["table_half_range"])

    with tempfile.TemporaryDirectory(prefix="rollerrig-bench-") as tmp:
        log("compiling bench_rig.c ...")
        mon = CpuMonitor()
        kernel = RigBench(tmp)
        kernel_ext = RigBench(tmp, extension_flags(), "bench_rig_ext")
        if not kernel.ok:
            log(f"bench_rig.c not built:\n{kernel.error}")
            return 1
        info = machine_info(kernel.cc_version)
        dump_path = os.path.join(tmp, "states.bin")
        first = kernel.run(sz, "--only", "lookup", "--repeats", 1, "--dump", dump_path)
        params = first["params"]
        bad_params = check_parameters(toml, params)
        dump = read_dump(dump_path)
        log("C kernel ...")
        c = mon.section("C kernel", c_section, kernel, sz)
        log("Python batched ...")
        py = mon.section("Python", python_section, kernel_ext, sz, toml, params, dump)

    load1 = load_average()
    text = report(args, info, load0, load1, date, params, toml, bad_params, c, py, kernel,
                  kernel_ext, mon, time.perf_counter() - t_start, sz)
    write_section(out, "rig_contact", text)
    print(text)
    log(f"written {os.path.relpath(out, os.getcwd())}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
