"""The rig in time on the non-Hertzian contact (issue 24): the paper's
scenario's real-time factor, C loop (Rig.run over the schedule), with
contact.patch = "hertz" and "nonhertz" side by side (interleaved repeats),
on the measured pair and S1002/UIC60; the table's build at the default
settings (contact.nonhertz_*), timed once.

    python benchmarks/bench_rig_nonhertz.py            # the rig_nonhertz section of RESULTS.md
    python benchmarks/bench_rig_nonhertz.py --tables DIR   # reuse DIR/<pair>.npz (built
                                                           # and saved there if missing)
    python benchmarks/bench_rig_nonhertz.py --quick    # a narrow coarse table, 2 s: a smoke run

The build is printed apart; the loop's timing holds the rig's build
outside (each repeat a fresh rig, the table shared).
"""
import datetime
import os
import sys
import time
import warnings

import rollerrig as rr

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _bench_common import (bench_args, command_text, compiler_version,  # noqa: E402
                           interleaved, load_average, log, machine_info, machine_line, publish)

DATA = os.path.join(os.path.dirname(rr.__file__), "data")
PAIRS = [("measured pair", "measured", os.path.join(DATA, "rig_measured_pair.toml")),
         ("S1002 on UIC60", "s1002_uic60", os.path.join(DATA, "rig_s1002_uic60.toml"))]
QUICK = {"nonhertz_half_range_m": 8e-5, "nonhertz_elements": 16}


#: what the table above does not show, measured once (2026-12-05, commit of this
#: script's block; the commands named), kept beside the figures
NOTES = """Notes (measured on this branch, not by this script):

- Instructions (load-independent; valgrind --tool=callgrind on examples/rig_paper.c, the
  measured pair with the default table, the samples from 15.2 to 17.2 s): Hertz 39.4 k, nonhertz
  64.0 k instructions a sample (ratio 0.62, as the timed ratio under load: 0.57-0.61).  Per
  wheel rr_nonhertz_wheel_law takes 18.5 k: two rows, one pass of the vertical balance each
  (seeded from the rig's previous evaluation, rr_wheel_contact.nh_tz; before: two passes on the
  first row), two rr_exact_table_forces calls (5.8 k), five load sums per row's secant on the
  lowering (1.9 k), the correction (1.3 k).  On a free machine (the table above, load average
  about 1) the nonhertz loop runs 577-578x real time, 0.59-0.62 of the Hertz loop's 925-975x
  (an earlier run the same hour: 545-574x against 923-929x):
  the issue's 250x, not its 1000x goal (that machine, 2026-12-05).
- Stop 37 (2026-12-06, this machine): the lowering's secant starts between two load nodes in
  (N cos delta)^(2/3) and takes their slope for its first step, to 1e-6 of the load (the
  balance it serves settles to 1e-4): 2 to 2.25 load sums a row where 4 were taken; the
  calibration's Kalker coefficients passed to the exact table, which no longer checks the
  built-in table at each call; the integrator's test of the Jacobian's finiteness vectorised.
  Instructions a sample (callgrind on Rig.run, the whole scenario): measured pair 55.9 k ->
  50.2 k, S1002/UIC60 52.5 k -> 49.2 k, Hertz 34.2 k -> 33.4 k; rr_nonhertz_wheel_law 15.2 k ->
  12.7 k a wheel.  The two builds taking turns (best of 7, Rig.run alone, 09:07 UTC, load
  about 1): measured pair 928-935x -> 1048-1071x, S1002/UIC60 925-933x -> 1042-1044x.  The
  forces moved by 2.6e-6 mu N at most (3000 random states, both pairs, both wheels), the
  targets reached by under 4e-5.  Over the issue's 1000x goal on this machine, on both pairs.
- Stop 38 (2026-12-06, this machine): each row moves with the state's own vertical and roll
  rates (rr_rig_kinematics_rates_at; one more table lookup a wheel): 50.16 k -> 50.88 k
  instructions a sample over Rig.run (the measured pair, callgrind); in turn with the build
  before, best of 7: the measured pair 1028 / 1066x -> 1023 / 1040x, S1002 1033 / 1022x ->
  1014 / 1008x.  The table above is this script's run after it.  Then the slopes at y were
  looked up once a sample for both wheels: 50.48 k (the history bit for bit).
- Accuracy in the loop (tests/test_rig_nonhertz.py): on the cone's elliptic gap the nonhertz
  rig's fx history stays within 0.015 mu0 (N_left + N_right) of the Hertz rig with the exact
  table (measured max 0.0093, p95 4e-5; FASTSIM against the same reference 0.0091, p95 2e-5:
  the maxima are the target switches' transients); the paper's targets held within 5 % on
  both pairs.  The flange excursion (rig_flange_excursion.toml, the default table) runs on the
  nonhertz contact too: y reaches 2.040 mm (Hertz 2.046), the left wheel's load 701 N at the
  flange (Hertz 618), the lateral creep force up to 205 N (Hertz 187).  Paper scenario, nonhertz (40 elements) against Hertz + FASTSIM:
  the hold windows' adhesion equal within 2e-4 (both saturate at the falling law), the fx
  history within 0.04 mu0 N (transients at the target switches), p95 0.001.
- A coarser table: 24 elements across against 40, the paper's scenario's fx history within
  0.005 mu0 N (max; p95 0.002) on both pairs, the build about half as long; the default stays
  40 (the per-state accuracy against the exact theory, RESULTS.md's nonhertz block, was
  measured at 40).
- The default table's build (+-2.5 mm, rows 0.04 mm apart, a quarter of that near the rigid
  contact point's jumps, 40 elements): the measured pair 396 rows (its left side ends at
  +2.047 mm, where the exact theory's largest node fails in deep flange contact: warned),
  S1002/UIC60 358 rows; 33 and 30 s on free cores (two threads; the table above).  Richardson
  is off at the rig's scale: its half-size elements do not fit the exact solver's grid at the
  lightest node (rr_nonhertz_row: RR_ERR_WORKSPACE).  The flange patches' narrowed grids
  (nh-flange) had given the square ones their sizes too, which set the profile samples a tenth
  of an element apart, finer than a row's workspace holds at the lightest node: the default
  table failed at the centre (fixed, tests/test_rig_nonhertz.py builds it).
"""


def params_of(scenario, **contact):
    P = rr.load_parameters(scenario)
    P["contact"] = {**P.get("contact", {}), **contact}
    return P


def main(argv=None):
    import argparse
    extra = argparse.ArgumentParser(add_help=False)
    extra.add_argument("--tables", help="folder of saved tables (<pair>.npz)")
    known, rest = extra.parse_known_args(argv)
    args = bench_args(__doc__, rest, repeats=5)
    args.command = command_text(argv)
    repeats = 1 if args.quick else args.repeats
    duration = 2.0 if args.quick else 20.0
    rows = []
    load = load_average()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rr.RollerRigWarning)
        for label, name, scenario in PAIRS:
            settings = QUICK if args.quick else {}
            P = params_of(scenario, patch="nonhertz", **settings)
            build_s = float("nan")
            path = os.path.join(known.tables, f"{name}.npz") if known.tables else None
            if path and os.path.isfile(path):
                P["contact"]["nonhertz_table"] = path
                nh = rr.rig_nonhertz_table(P)
            else:
                t0 = time.perf_counter()
                nh = rr.rig_nonhertz_table(P, path)
                build_s = time.perf_counter() - t0
                if path:
                    P["contact"]["nonhertz_table"] = path
            nrows = nh.left.rows.shape[0] + nh.right.rows.shape[0]
            H = params_of(scenario, patch="hertz")
            Q = rr.rig.check_parameters(P)
            S = Q["scenario"]
            refs = rr.rig.schedule(Q, duration, 0.004, S["targets"],
                                   [x * duration / S["duration_s"] for x in S["target_start_s"]],
                                   S["roller_speed_m_s"])

            def loop(params):
                def run():
                    rig_ = rr.build_rig(params)[0]
                    t0 = time.perf_counter()
                    rec, st = rig_.run(*refs)
                    dt = time.perf_counter() - t0
                    assert st >= 0, st
                    return dt
                return run
            t_h, t_n = interleaved([loop(H), loop(P)], repeats)
            res = rr.simulate(params=P, duration=duration)
            rows.append((label, nrows, build_s, duration / t_h, duration / t_n,
                         t_h / (duration / 0.004) * 1e6, t_n / (duration / 0.004) * 1e6,
                         res.status, [round(r["reached"], 5) for r in res.summary()]))
            log(f"{label}: hertz {duration / t_h:.0f} x, nonhertz {duration / t_n:.0f} x real "
                f"time ({nrows} rows; build {build_s:.1f} s)")
    info = machine_info(compiler_version())
    L = ["## The rig in time on the non-Hertzian contact (bench_rig_nonhertz.py)", ""]
    if args.quick:
        L += ["**Quick smoke run (--quick): a 2 s scenario, a narrow coarse table, one "
              "repeat.**", ""]
    L += [f"- date: {datetime.datetime.now().isoformat(timespec='seconds')}",
          f"- command: `{args.command}`", machine_line(info),
          f"- load average at the start {load}, at the end {load_average()} (the two patches "
          f"take turns in each repeat: compare them within a row)",
          f"- the paper's scenario ({duration:g} s, 4 ms samples, TR-BDF2, one contact "
          f"evaluation a step), C loop (Rig.run); best of {repeats}; Hertz with FASTSIM 20x20, "
          f"nonhertz with the table of contact.nonhertz_* "
          f"({'narrow, 16 elements' if args.quick else 'the defaults: +-2.5 mm, rows 0.04 mm apart, 40 elements'})",
          "", "| pair | table rows (both sides) | table build [s] | x real time, Hertz | "
          "x real time, nonhertz | us a sample, Hertz | us a sample, nonhertz | status | "
          "targets reached (nonhertz) |", "|---|---|---|---|---|---|---|---|---|"]
    for label, n, b, rh, rn, uh, un, st, reached in rows:
        built = f"{b:.1f}" if b == b else "(a saved file)"
        L.append(f"| {label} | {n} | {built} | {rh:.0f} | {rn:.0f} | {uh:.1f} | {un:.1f} | "
                 f"{st} | {reached} |")
    L += ["", NOTES]
    return publish(args, "rig_nonhertz", L)


if __name__ == "__main__":
    sys.exit(main())
