"""The rig in the loop (issue 15): the cost of a controller of the user's.

    python benchmarks/bench_loop.py [--quick] [--out PATH] [--repeats 5]

- Python: the paper's scenario (20 s at 4 ms) through rr.simulate with the
  rig's own controllers (the C loop), with rollerrig.rig.control's
  CreepageController (the same controller in Python: bit for bit the same
  history) and with a controller that returns None (the hook's own cost);
  the runs take turns, best of --repeats; real-time factors and the cost of
  the Python controller per sample.
- C: examples/rig_sil.c (a slide protection in C, rr_rig_read, rr_rig_write,
  rr_rig_advance) in its fixed-rate loop at 4 ms and 1 ms, in real time (5 s
  each), and free running: the step time's median, p99 and worst, each step
  timed with clock_gettime.
Writes section "loop" of benchmarks/RESULTS.md.
"""
import datetime
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import _bench_common as bc  # noqa: E402
import rollerrig as rr  # noqa: E402
from rollerrig.rig.control import CreepageController  # noqa: E402


def python_loop(repeats, duration):
    kw = dict(duration=duration) if duration else {}
    rr.simulate(**kw)                        # the table built once, outside the timing
    runs = {
        "rig's own controllers (C loop)": lambda: rr.simulate(**kw),
        "CreepageController in Python": lambda: rr.simulate(controller=CreepageController(),
                                                            **kw),
        "a controller returning None": lambda: rr.simulate(controller=lambda s: None, **kw),
    }
    names = list(runs)
    results = {}

    def timer(name):
        def run():
            res = runs[name]()
            results[name] = res
            return res.wall["run"]
        return run
    best = bc.interleaved([timer(n) for n in names], repeats)
    samples = results[names[0]].samples_run
    T = results[names[0]].dt
    base = best[0] / samples
    lines = ["| loop | run time [ms] | per sample [us] | real-time factor | above the C loop "
             "per sample [us] |", "|---|---|---|---|---|"]
    for name, t in zip(names, best):
        per = t / samples
        lines.append(f"| {name} | {t * 1e3:.1f} | {per * 1e6:.2f} | {T / per:.0f} | "
                     f"{(per - base) * 1e6:.2f} |")
    return samples, T, lines


def c_sil(quick):
    bc.log("building csrc/build/rig_sil")
    subprocess.run(["make", "-C", os.path.join(bc.ROOT, "csrc"), "sil"], check=True,
                   stdout=subprocess.DEVNULL)
    exe = os.path.join(bc.ROOT, "csrc", "build", "rig_sil")
    lines = ["| period | mode | steps | median [us] | p99 [us] | worst [us] | worst / period |",
             "|---|---|---|---|---|---|---|"]
    setup = ""
    modes = [("4", "free"), ("1", "free")] + ([] if quick else [("4", "sleep"), ("1", "sleep")])
    for period, mode in modes:
        out = subprocess.run([exe, period, mode], capture_output=True, text=True, check=True,
                             timeout=600).stdout
        setup = out.splitlines()[0]
        m = re.search(r"(\d+) steps of .* min ([\d.]+) us, median ([\d.]+) us, p99 ([\d.]+) us,"
                      r" max ([\d.]+) us", out)
        n, _, med, p99, worst = m.groups()
        mode_text = "fixed-rate (real time)" if mode == "sleep" else "free running"
        lines.append(f"| {period} ms | {mode_text} | {n} | {med} | {p99} | {worst} | "
                     f"{float(worst) / (float(period) * 1e3):.1%} |")
    return setup, lines


def main():
    args = bc.bench_args(__doc__, repeats=5)
    repeats = 2 if args.quick else args.repeats
    args.command = bc.command_text(None)
    t0 = time.time()
    load0 = bc.load_average()
    samples, T, py = python_loop(repeats, 2.0 if args.quick else None)
    setup, c = c_sil(args.quick)
    info = bc.machine_info(bc.compiler_version())
    L = ["# The rig in the loop: a controller of the user's (issue 15)", ""]
    if args.quick:
        L += ["**Quick smoke run (--quick): figures indicative only.**", ""]
    L += [f"- date: {datetime.date.today()}", f"- command: `{args.command}` "
          f"(total {time.time() - t0:.0f} s)", bc.machine_line(info),
          f"- code: {info['code']}; load average at start {load0}, at end "
          f"{bc.load_average()}", "",
          f"Python: rr.simulate of the paper's scenario ({samples} samples of "
          f"{T * 1e3:g} ms), the runs taking turns, best of "
          f"{repeats}.  The CreepageController run's history is the "
          "C loop's bit for bit (tests/test_controller.py), so the difference is the cost "
          "of calling a Python controller: reading the rig, building RigSignals, the call, "
          "checking its dict, writing the command.", ""] + py + [
          "", "C, software in the loop: `make -C csrc sil`; `csrc/build/rig_sil PERIOD MODE`, "
          "the slide protection of examples/rig_sil.c braking through the patch of mu0 0.1 "
          "(5 s), each step (read, controller, write, advance) timed with clock_gettime; "
          f"{setup}.", ""] + c
    return bc.publish(args, "loop", L)


if __name__ == "__main__":
    sys.exit(main())
