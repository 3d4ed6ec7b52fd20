"""Helpers shared by the benchmark scripts (bench_contact.py, bench_rig_contact.py).

Timing (best of repeats, measurements taking turns), the machine's state
during a run (load, other processes' CPU use, a fixed calibration workload),
building a C benchmark program from benchmarks/ with the core's sources,
number formatting, and writing a script's report as one section of a shared
Markdown file (benchmarks/RESULTS.md), between

    <!-- begin NAME -->
    ...
    <!-- end NAME -->

markers, so that each script replaces its own section and leaves the others'.
"""
import gc
import glob
import math
import os
import platform
import shlex
import subprocess
import sys
import time

import numpy as np

import rollerrig

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def log(msg):
    print(msg, file=sys.stderr, flush=True)


# -------------------------------------------------------------------- timing

def calibration():
    """A fixed pure-Python workload (about 20 ms), timed best of 3 before and
    after every section: if the machine gets slower during the run (another
    process, another virtual machine on the host, a lower clock), this
    time grows even though the code has not changed."""
    def work():
        x = 0
        for i in range(400_000):
            x += i * i % 7
        return x
    return best_time(work, 3)


def best_time(fn, repeats):
    """Best wall time of `repeats` calls of fn() (garbage collector off)."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        best = math.inf
        for _ in range(repeats):
            t0 = time.perf_counter()
            fn()
            best = min(best, time.perf_counter() - t0)
    finally:
        if enabled:
            gc.enable()
    return best


def interleaved(fns, repeats):
    """Best time of each function over `repeats` rounds, the functions taking
    turns within a round so that a slow spell of the machine hits them all
    alike.  Each function returns its own elapsed time in seconds."""
    best = [math.inf] * len(fns)
    enabled = gc.isenabled()
    gc.disable()
    try:
        for _ in range(repeats):
            for k, fn in enumerate(fns):
                best[k] = min(best[k], fn())
    finally:
        if enabled:
            gc.enable()
    return best


def timed(fn):
    def run():
        t0 = time.perf_counter()
        fn()
        return time.perf_counter() - t0
    return run


# ------------------------------------------------------- C benchmark programs

def extension_flags():
    """The flags setuptools compiles rollerrig._core with: Python's CFLAGS and
    CCSHARED (sysconfig), then setup.py's UNIX_COMPILE_ARGS (last wins), read
    from setup.py itself so that the two cannot drift apart."""
    import ast
    import sysconfig
    flags = shlex.split(sysconfig.get_config_var("CFLAGS") or "") \
        + shlex.split(sysconfig.get_config_var("CCSHARED") or "")
    with open(os.path.join(ROOT, "setup.py")) as fh:
        tree = ast.parse(fh.read())
    ours = next(ast.literal_eval(node.value) for node in tree.body
                if isinstance(node, ast.Assign)
                and any(getattr(t, "id", None) == "UNIX_COMPILE_ARGS" for t in node.targets))
    return [f for f in flags if f.startswith(("-O", "-f", "-D", "-m", "-g"))] \
        + list(ours)


class CProgram:
    """benchmarks/SOURCE compiled with csrc/*/rr_*.c into `tmpdir`, with
    `plain` flags (`flags` None) or with other flags.  `error` is None if it
    built; `command_text` is the command as the reports quote it."""

    def __init__(self, tmpdir, source, plain, flags=None, name=None):
        self.tmpdir = tmpdir
        self.exe = os.path.join(tmpdir, name or os.path.splitext(source)[0])
        cc = os.environ.get("CC", "cc")
        sources = sorted(glob.glob(os.path.join("csrc", "*", "rr_*.c")))
        opts = list(plain) if flags is None else list(flags)
        self.command = [cc] + opts + ["-I", "csrc", os.path.join("benchmarks", source)] \
            + sources + ["-lm", "-o", self.exe]
        self.error = None
        try:
            proc = subprocess.run(self.command, cwd=ROOT, capture_output=True, text=True)
            if proc.returncode != 0:
                self.error = proc.stderr.strip() or f"{cc} exited with {proc.returncode}"
        except OSError as exc:
            self.error = str(exc)
        self.cc_version = compiler_version(cc)
        self.command_text = shlex.join([cc] + opts + ["-I", "csrc", f"benchmarks/{source}"]) \
            + " csrc/*/rr_*.c -lm"

    @property
    def ok(self):
        return self.error is None


def compiler_version(cc=None):
    cc = cc or os.environ.get("CC", "cc")
    try:
        out = subprocess.run([cc, "--version"], capture_output=True, text=True)
        return out.stdout.splitlines()[0] if out.stdout else cc
    except OSError:
        return "(no C compiler)"


# ------------------------------------------------------- the machine's state

class CpuMonitor:
    """CPU time used by other processes while a section ran, from /proc/stat
    (all CPUs' busy time) minus this process's own (and its children's).
    On a shared machine this tells whether a figure was measured on a quiet
    machine: 0 is quiet, 1.0 means another process kept one core busy."""

    def __init__(self):
        self.sections = []
        calibration()                 # warm-up, not recorded
        try:
            self.tick = os.sysconf("SC_CLK_TCK")
            self._busy()
        except (OSError, ValueError, AttributeError):
            self.tick = None

    def _busy(self):
        with open("/proc/stat") as fh:
            fields = [int(v) for v in fh.readline().split()[1:9]]
        user, nice, system, _idle, _iowait, irq, softirq, steal = fields
        return (user + nice + system + irq + softirq + steal) / self.tick

    def _snap(self):
        t = os.times()
        own = t.user + t.system + t.children_user + t.children_system
        return time.perf_counter(), own, self._busy() if self.tick else math.nan

    def section(self, name, fn, *args):
        cal0 = calibration()
        w0, own0, busy0 = self._snap()
        result = fn(*args)
        w1, own1, busy1 = self._snap()
        cal1 = calibration()
        wall = w1 - w0
        own = (own1 - own0) / wall
        other = max(0.0, (busy1 - busy0) - (own1 - own0)) / wall
        self.sections.append(dict(name=name, wall=wall, own=own, other=other,
                                  cal=(cal0, cal1)))
        return result


def load_average():
    return tuple(round(x, 2) for x in os.getloadavg())


def code_state():
    """The commit measured, and whether the C core or the package differ from it."""
    try:
        head = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT,
                              capture_output=True, text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "status", "--porcelain", "--", "csrc", "rollerrig"],
                               cwd=ROOT, capture_output=True, text=True,
                               check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "not a git checkout"
    return f"commit {head}" + (" with uncommitted changes in csrc/ or rollerrig/"
                               if dirty else "")


def machine_info(cc_version):
    model = "unknown"
    try:
        with open("/proc/cpuinfo") as fh:
            for line in fh:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    try:
        affinity = len(os.sched_getaffinity(0))
    except AttributeError:
        affinity = os.cpu_count()
    return dict(nproc=affinity, cpu_count=os.cpu_count(), cpu=model,
                python=platform.python_version(), numpy=np.__version__,
                rollerrig=getattr(rollerrig, "__version__", "?"), cc=cc_version,
                code=code_state(),
                platform=platform.platform())


def machine_line(info):
    return (f"- machine: {info['nproc']} cores available (os.cpu_count {info['cpu_count']}), "
            f"CPU {info['cpu']}; {info['platform']}")


def kernel_report_head(title, args, info, date, elapsed, kernel, kernel_ext):
    """The opening lines of a report that times a C kernel (built twice:
    plain and with the extension's flags) beside the Python binding."""
    L = [f"# {title}", ""]
    if args.quick:
        L += ["**Quick smoke run (--quick): small sizes, figures indicative only.**", ""]
    L.append(f"- date: {date}")
    L.append(f"- command: `{args.command}` (total {elapsed:.0f} s)")
    L.append(machine_line(info))
    L.append(f"- python {info['python']}, numpy {info['numpy']}, rollerrig {info['rollerrig']}; "
             f"C kernel built with `{kernel.command_text}` ({info['cc']}), and again "
             f"with the extension's flags: `{kernel_ext.command_text}`")
    L.append(f"- code: {info['code']}; the C kernel is compiled from the working tree, the "
             "binding is the extension as last built (\"C = Python\" below checks that "
             "they agree)")
    return L


def conditions_lines(load0, load1, mon):
    """The report's lines on the machine's state during the run: load
    average, other processes' CPU use and the calibration workload per
    section."""
    L = [f"- load average (1, 5, 15 min) at start {load0}, at end {load1}"]
    if mon.tick:
        busy = ", ".join(f"{m['name']} {m['other']:.2f}" for m in mon.sections)
        L.append(f"- other processes' CPU use during each section, in cores (0 = quiet "
                 f"machine; from /proc/stat): {busy}")
    if mon.sections:
        ref = mon.sections[0]["cal"][0]
        cal = ", ".join(f"{m['name']} {m['cal'][0] / ref:.2f} / {m['cal'][1] / ref:.2f}"
                        for m in mon.sections)
        cals = [c for m in mon.sections for c in m["cal"]]
        spread = max(cals) / min(cals)
        L.append(f"- machine speed check: a fixed {ref * 1e3:.0f} ms pure-Python loop timed "
                 f"before / after each section, relative to the first: {cal}"
                 + (f" -- **the machine's speed varied by {spread:.2f}x during this run; "
                    "figures are less reliable**" if spread > 1.20
                    else " (steady within this machine's usual jitter)"))
    return L


# -------------------------------------------------------------- formatting

def fmt(x, digits=3):
    if x is None:
        return "n/a"
    if x == 0:
        return "0"
    ax = abs(x)
    if ax >= 1e5 or ax < 1e-3:
        return f"{x:.{digits - 1}e}"
    return f"{x:.{max(0, digits - 1 - int(math.floor(math.log10(ax))))}f}"


def verdict(ok):
    return "n/a" if ok is None else ("pass" if ok else "**miss**")


# ------------------------------------------------------------ command, output

def command_text(argv):
    """The command line as the report quotes it (the script relative to the
    repository root)."""
    script = os.path.relpath(os.path.abspath(sys.argv[0]), ROOT) \
        if os.path.abspath(sys.argv[0]).startswith(ROOT + os.sep) else sys.argv[0]
    return shlex.join(["python", script] + (sys.argv[1:] if argv is None else argv))


def report_path(args):
    """--out, else benchmarks/out/RESULTS-quick.md for --quick (a smoke run
    must not overwrite the real figures), else benchmarks/RESULTS.md."""
    if args.out:
        return os.path.abspath(args.out)
    if args.quick:
        return os.path.join(HERE, "out", "RESULTS-quick.md")
    return os.path.join(HERE, "RESULTS.md")


def _markers(name):
    return f"<!-- begin {name} -->", f"<!-- end {name} -->"


def write_section(path, name, text, legacy="contact"):
    """Write `text` as section `name` of the Markdown file at `path`: replace
    the section in place if the file has it, else append it; the other
    sections are left as they are.  A file without any section marker was
    written before there were sections (by bench_contact.py alone): its
    content is kept as section `legacy`."""
    begin, end = _markers(name)
    block = f"{begin}\n{text.strip()}\n{end}\n"
    try:
        with open(path) as fh:
            old = fh.read()
    except FileNotFoundError:
        old = ""
    if old.strip() and "<!-- begin " not in old:
        lb, le = _markers(legacy)
        old = f"{lb}\n{old.strip()}\n{le}\n"
    i = old.find(begin)
    j = old.find(end, i + len(begin)) if i >= 0 else -1
    if i >= 0 and j >= 0:
        rest = old[j + len(end):].lstrip("\n")
        new = old[:i] + block + ("\n" + rest if rest else "")
    else:
        new = old.rstrip("\n") + ("\n\n" if old.strip() else "") + block
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as fh:
        fh.write(new)


def bench_args(doc, argv=None, repeats=None):
    """The command line every benchmark script takes: --quick, --out (and
    --repeats, default `repeats`, where a script takes it)."""
    import argparse
    parser = argparse.ArgumentParser(description=doc.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="small sizes: a smoke run")
    parser.add_argument("--out", help="report path (default benchmarks/RESULTS.md, or "
                        "benchmarks/out/RESULTS-quick.md with --quick)")
    if repeats is not None:
        parser.add_argument("--repeats", type=int, default=repeats,
                            help=f"best of this many runs (default {repeats})")
    return parser.parse_args(argv)


def publish(args, name, lines):
    """Write the report `lines` as section `name` of the report file, print it."""
    path = report_path(args)
    write_section(path, name, "\n".join(lines))
    print("\n".join(lines))
    log(f"written {os.path.relpath(path)}")
    return 0
