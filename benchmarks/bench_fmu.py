"""The rig's FMU (issue 15): the cost of a co-simulation step against the
rig's own step, and the cost of building an FMU.

    python benchmarks/bench_fmu.py [--quick] [--out PATH] [--repeats 10]

- Build: `rollerrig fmu` of the default parameters, FMI 2.0 and 3.0, the
  first from scratch (every C file compiled) and the second with the core's
  objects cached (rollerrig.fmu.build_fmu's cache_dir); FMPy's validation of
  both.
- C: benchmarks/bench_fmu.c, compiled with the FMU's flags and the core's
  sources, dlopens the FMI 2.0 FMU's binary and times, in one process, the
  paper's scenario (5000 samples of 4 ms) stepped by rr_rig_schedule +
  rr_rig_step (the rig's own step, as examples/rig_paper.c) and by
  fmi2DoStep of 1 sample, of 8 samples, and of 1 sample followed by
  fmi2GetReal of the 27 real record outputs; the runs take turns, best of
  --repeats each; the FMU's final record is checked bitwise against the
  rig's.  Goal: the FMI layer's overhead (fmi2DoStep of one sample over
  rr_rig_step) at most 10 % of the step.
- FMPy: the same scenario through FMPy (FMI 2.0): a Python loop of
  fmu.doStep alone, of doStep and getReal of the record's outputs, and
  fmpy.simulate_fmu at a 4 ms output interval (it reads and records all 102
  outputs every step); rr.simulate() for comparison.  The runs take turns,
  best of --repeats.
Writes section "fmu" of benchmarks/RESULTS.md.
"""
import datetime
import os
import shlex
import subprocess
import sys
import tempfile
import time
import zipfile
from pathlib import Path

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import _bench_common as bc  # noqa: E402
import numpy as np  # noqa: E402
import rollerrig as rr  # noqa: E402
from rollerrig import fmu, rig  # noqa: E402

T = 0.004
GOAL_OVERHEAD = 0.10


def build(tmp):
    """(paths, build times [s]): the FMI 2 FMU from scratch, the FMI 3 FMU
    with the core cached (and the FMI 2 one again, cached)."""
    cache = tmp / "cache"
    t0 = time.perf_counter()
    fmu2 = fmu.build_fmu(tmp / "rig.fmu", fmi_version=2, cache_dir=cache)
    t1 = time.perf_counter()
    fmu3 = fmu.build_fmu(tmp / "rig3.fmu", fmi_version=3, cache_dir=cache)
    t2 = time.perf_counter()
    fmu.build_fmu(tmp / "rig_again.fmu", fmi_version=2, cache_dir=cache)
    t3 = time.perf_counter()
    return (fmu2, fmu3), {"FMI 2.0, from scratch": t1 - t0, "FMI 3.0, core cached": t2 - t1,
                          "FMI 2.0, core cached": t3 - t2}


def c_harness(tmp, fmu2, samples, rounds):
    """The harness's best ns per sample of each run, and its build command."""
    unzipped = tmp / "unzipped"
    with zipfile.ZipFile(fmu2) as z:
        z.extractall(unzipped)
    plat, ext = fmu._platform_dir(2)
    binary = unzipped / "binaries" / plat / ("rig" + ext)
    import fmpy
    guid = fmpy.read_model_description(str(fmu2)).guid
    cc = fmu.find_compiler()
    flags = [f for f in fmu.CFLAGS if not f.startswith("-fvisibility")]
    sources = sorted(str(p) for p in Path(bc.ROOT, "csrc").glob("*/rr_*.c"))
    exe = tmp / "bench_fmu"
    cmd = cc + flags + ["-I", os.path.join(bc.ROOT, "csrc"),
                        os.path.join(HERE, "bench_fmu.c")] + sources + ["-ldl", "-lm", "-o",
                                                                        str(exe)]
    subprocess.run(cmd, check=True)
    out = subprocess.run([str(exe), str(binary), guid, str(samples), str(rounds)],
                         capture_output=True, text=True, check=True).stdout
    ns = {line.split()[0]: float(line.split()[1]) for line in out.splitlines()
          if not line.startswith("samples")}
    text = shlex.join(cc + flags + ["-I", "csrc", "benchmarks/bench_fmu.c"]) \
        + " csrc/*/rr_*.c -ldl -lm"
    return ns, text


def fmpy_runs(fmu2, samples, repeats):
    """Seconds per sample of the FMPy runs and of rr.simulate()."""
    import fmpy
    from fmpy.simulation import instantiate_fmu
    tmp = fmpy.extract(str(fmu2))
    md = fmpy.read_model_description(tmp)
    vr = {v.name: v.valueReference for v in md.modelVariables}
    outs = [vr[n] for n in rig.RECORD_FIELDS if n not in ("time", "sample_status")]
    duration = samples * T
    f = instantiate_fmu(tmp, md, "CoSimulation")

    def loop(read):
        def run():
            f.reset()
            f.setupExperiment(startTime=0.0)
            f.enterInitializationMode()
            f.exitInitializationMode()
            t0 = time.perf_counter()
            step, get = f.doStep, f.getReal
            for k in range(samples):
                step(k * T, T)
                if read:
                    get(outs)
            return time.perf_counter() - t0
        return run

    def simulate_fmu():
        t0 = time.perf_counter()
        fmpy.simulate_fmu(tmp, stop_time=duration, output_interval=T, model_description=md)
        return time.perf_counter() - t0

    def simulate():
        res = rr.simulate(duration=duration) if samples != 5000 else rr.simulate()
        return res.wall["run"]
    rr.simulate()                               # the table built outside the timing
    names = ["FMPy: doStep alone", "FMPy: doStep + getReal of 27 outputs",
             "fmpy.simulate_fmu (4 ms, all outputs recorded)", "rr.simulate() (the C loop)"]
    best = bc.interleaved([loop(False), loop(True), simulate_fmu, simulate], repeats)
    f.terminate()
    f.freeInstance()
    return dict(zip(names, [b / samples for b in best]))


def main():
    args = bc.bench_args(__doc__, repeats=10)
    repeats = 2 if args.quick else args.repeats
    samples = 1000 if args.quick else 5000
    args.command = bc.command_text(None)
    t0 = time.time()
    load0 = bc.load_average()
    mon = bc.CpuMonitor()
    import fmpy
    from fmpy.validation import validate_fmu
    with tempfile.TemporaryDirectory(prefix="bench-fmu-") as tmp:
        tmp = Path(tmp)
        bc.log("building the FMUs ...")
        (fmu2, fmu3), build_times = mon.section("build", build, tmp)
        problems = {v: validate_fmu(str(p)) for v, p in ((2, fmu2), (3, fmu3))}
        sizes = {v: p.stat().st_size for v, p in ((2, fmu2), (3, fmu3))}
        bc.log("the C harness ...")
        ns, harness_cmd = mon.section("C", c_harness, tmp, fmu2, samples, repeats)
        bc.log("FMPy ...")
        py = mon.section("FMPy", fmpy_runs, fmu2, samples, repeats)
    load1 = bc.load_average()
    info = bc.machine_info(bc.compiler_version())
    step = ns["rr_rig_step"]
    overhead = (ns["fmi2DoStep_1"] - step) / step
    L = ["# The rig's FMU: doStep against the rig's own step (issue 15)", ""]
    if args.quick:
        L += ["**Quick smoke run (--quick): figures indicative only.**", ""]
    L += [f"- date: {datetime.date.today()}",
          f"- command: `{args.command}` (total {time.time() - t0:.0f} s)",
          bc.machine_line(info),
          f"- python {info['python']}, numpy {info['numpy']}, FMPy {fmpy.__version__}, "
          f"rollerrig {info['rollerrig']}; {info['cc']}; code: {info['code']}"]
    L += bc.conditions_lines(load0, load1, mon)
    L += ["", "## Goal", "", "| goal | measured | target | result |", "| --- | --- | --- | --- |",
          f"| the FMI layer's overhead: fmi2DoStep of one 4 ms sample over rr_rig_step, from "
          f"C | {overhead:+.1%} ({ns['fmi2DoStep_1'] - step:+.0f} ns on {step:.0f} ns) | "
          f"<= {GOAL_OVERHEAD:.0%} of the step | {bc.verdict(overhead <= GOAL_OVERHEAD)} |",
          "", "## From C, one process (benchmarks/bench_fmu.c)", "",
          f"The paper's scenario from its start, {samples} samples of 4 ms, the runs taking "
          f"turns, best of {repeats}; the FMU's binary dlopen'ed, the rig compiled into the "
          f"harness with the FMU's flags: `{harness_cmd}`.  The FMU's final record equals the "
          f"rig's bit for bit.", "",
          "| run | per 4 ms sample [us] | over rr_rig_step |", "| --- | --- | --- |"]
    labels = {"rr_rig_step": "rr_rig_schedule + rr_rig_step (the rig's own step)",
              "fmi2DoStep_1": "fmi2DoStep, 1 sample per call",
              "fmi2DoStep_8": "fmi2DoStep, 8 samples per call",
              "fmi2DoStep_1_GetReal_28": "fmi2DoStep of 1 sample + fmi2GetReal of 27 outputs"}
    for key, label in labels.items():
        rel = "" if key == "rr_rig_step" else f"{(ns[key] - step) / step:+.1%}"
        L.append(f"| {label} | {ns[key] / 1e3:.2f} | {rel} |")
    L += ["", "## From Python through FMPy (FMI 2.0)", "",
          f"The same {samples} samples; the FMU loaded once, reset before each run.", "",
          "| run | per 4 ms sample [us] | over rr_rig_step in C | real-time factor |",
          "| --- | --- | --- | --- |"]
    for label, per in py.items():
        L.append(f"| {label} | {per * 1e6:.2f} | {(per * 1e9 - step) / step:+.0%} | "
                 f"{T / per:.0f} |")
    L += ["", "The Python side's cost is the ctypes call (and FMPy's recording): the FMU's own "
          "work per sample is the C figure above.", "",
          "## Building and validating", "",
          "| FMU | build time [s] |", "| --- | --- |"]
    for label, t in build_times.items():
        L.append(f"| {label} | {t:.1f} |")
    L += ["", f"FMU sizes: FMI 2.0 {sizes[2] / 2**20:.1f} MiB, FMI 3.0 {sizes[3] / 2**20:.1f} "
          f"MiB (the exact-theory table's data is most of both).  FMPy's validation "
          f"(`fmpy.validation.validate_fmu`): FMI 2.0 "
          f"{len(problems[2])} problems, FMI 3.0 {len(problems[3])} problems"
          + ("." if not (problems[2] or problems[3])
             else ": " + "; ".join(problems[2] + problems[3]))]
    return bc.publish(args, "fmu", L)


if __name__ == "__main__":
    sys.exit(main())
