"""The rig on real profiles (issue 24 item 2): the contact table's build time
per profile pair (C, rr_rig_table_build_profiles, from the points) and the
paper's scenario's real-time factor on the cone beside S1002/UIC60 and the
measured pair (the table built once, outside the timing: simulate reuses it).

    python benchmarks/bench_rig_profiles.py            # the rig_profiles section of RESULTS.md
    python benchmarks/bench_rig_profiles.py --quick    # a smoke run into benchmarks/out/

Timings are the best of several repeats (time.perf_counter), side by side in
one run.
"""
import datetime
import os
import sys
import warnings

import rollerrig as rr
from rollerrig import _core
from rollerrig.rig import real_profiles

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _bench_common import (best_time, bench_args, command_text, compiler_version,  # noqa: E402
                           load_average, log,
                           machine_info, machine_line, publish)

DATA = os.path.join(os.path.dirname(rr.__file__), "data")
PAIRS = [("cone on crowned cylinder (default)", None),
         ("S1002 on UIC60", os.path.join(DATA, "rig_s1002_uic60.toml")),
         ("measured pair", os.path.join(DATA, "rig_measured_pair.toml"))]


def table_build(P):
    """Seconds of one C build of P's table (the points read once before)."""
    W, R, I = P["wheelset"], P["roller"], P["integration"]
    import math
    numbers = (float(W["wheel_radius_m"]), float(R["radius_m"]),
               float(W["profile_half_width_m"]), math.atan(float(W["conicity"])),
               float(R["crown_radius_m"]), float(W["contact_half_spacing_m"]),
               float(I["table_half_range_m"]), int(I["table_rows"]))
    points = real_profiles.profile_points(P)
    if points is None:
        return lambda: _core.rig_table(*numbers)
    scales = (float(W["profile_scale"]), float(R["profile_scale"]), float(R["gauge_m"]))
    return lambda: _core.rig_profile_table(numbers, scales, points)


def main(argv=None):
    args = bench_args(__doc__, argv, repeats=5)
    args.command = command_text(argv)
    repeats = 1 if args.quick else args.repeats
    duration = 2.0 if args.quick else 20.0
    rows = []
    load = load_average()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rr.RollerRigWarning)      # the rollers' folds
        for label, scenario in PAIRS:
            P = rr.rig.params._parameters("bench", scenario) if scenario else \
                rr.default_parameters()
            t_table = best_time(table_build(P), repeats)
            rr.simulate(params=scenario, duration=duration)           # the table cached
            t_run = best_time(lambda: rr.simulate(params=scenario, duration=duration), repeats)
            res = rr.simulate(params=scenario, duration=duration)
            # the C loop alone (rig.run over the schedule: no records' Python side)
            rig_, Q, _ = rr.build_rig(scenario)
            S = Q["scenario"]
            refs = rr.rig.schedule(Q, duration, 0.004, S["targets"],
                                   [x * duration / S["duration_s"] for x in S["target_start_s"]],
                                   S["roller_speed_m_s"])

            rigs = [rr.build_rig(scenario)[0] for _ in range(repeats)]
            t_loop = best_time(lambda: rigs.pop().run(*refs), repeats)
            rows.append((label, int(P["integration"]["table_rows"]), t_table, duration / t_run,
                         duration / t_loop, res.status,
                         [round(r["reached"], 5) for r in res.summary()]))
            log(f"{label}: table {t_table * 1e3:.1f} ms, {duration / t_run:.0f} x real time "
                f"(C loop {duration / t_loop:.0f})")
    info = machine_info(compiler_version())
    L = ["## The rig on real profiles (bench_rig_profiles.py)", ""]
    if args.quick:
        L += ["**Quick smoke run (--quick): a 2 s scenario, one repeat.**", ""]
    L += [f"- date: {datetime.datetime.now().isoformat(timespec='seconds')}",
          f"- command: `{args.command}`", machine_line(info),
          f"- load average at the start {load}, at the end {load_average()} (other work on "
          f"the machine slows every row alike: compare the rows, not the runs)",
          f"- the paper's scenario ({duration:g} s, 4 ms samples, FASTSIM 20x20, TR-BDF2); "
          f"best of {repeats}; the table built once before the timed runs (its build "
          f"timed apart: the C build from the points, the points read and referenced once)",
          "", "| pair | table rows | table build [ms] | x real time, simulate() | x real "
          "time, C loop (Rig.run) | status | targets reached |",
          "|---|---|---|---|---|---|---|"]
    for label, n, tt, rtf, rtf_c, st, reached in rows:
        L.append(f"| {label} | {n} | {tt * 1e3:.1f} | {rtf:.0f} | {rtf_c:.0f} | {st} | "
                 f"{reached} |")
    return publish(args, "rig_profiles", L)


if __name__ == "__main__":
    sys.exit(main())
