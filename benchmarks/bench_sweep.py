"""Speed of a parameter sweep (issue 5): one million FASTSIM 20x20
evaluations with rr.sweep, serially, on 1 and 2 threads (scaling
efficiency), and on a local Dask cluster (overhead against threads), with
one direct broadcast rr.creep_forces call as the reference.

    python benchmarks/bench_sweep.py            # writes the sweep section of RESULTS.md
    python benchmarks/bench_sweep.py --quick    # 1e5 cases: a smoke run into benchmarks/out/

The grid: cx 1000 (-0.01 to 0.01) x mu 100 (0.1 to 0.5) x N 10 (500 to
5000 N), with cy = 1e-3, spin 0, a = b = 6 mm, FASTSIM 20x20 (rect grid,
parabolic bound, Coulomb friction).  The runs take turns within each of 3
rounds (best of 3 each); the Dask clusters are started before the timing,
their start-up time reported separately.  Every backend's result must be
bitwise the reference call's.  Timing is reported, never asserted: the exit
status is 0 whether or not a goal is met.
"""
import datetime
import logging
import os
import sys
import time
import warnings

import numpy as np

import rollerrig as rr
from rollerrig.analysis.sweep import CHUNK_CASES

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _bench_common import (CpuMonitor, code_state, command_text,  # noqa: E402
                           compiler_version, conditions_lines, fmt, interleaved,
                           load_average, log, machine_info, machine_line, verdict,
                           bench_args, publish)

GOAL_EFFICIENCY = 0.9      # 2-thread scaling efficiency t1 / (2 t2)
REPEATS = 3
FIXED = dict(cy=1e-3, cphi=0.0, a=6e-3, b=6e-3, method="fastsim", nx=20, ny=20)
FIELDS = ("fx", "fy", "mz", "status")


def make_grid(quick):
    return {"cx": np.linspace(-0.01, 0.01, 100 if quick else 1000),
            "mu": np.linspace(0.1, 0.5, 100),
            "N": np.linspace(500.0, 5000.0, 10)}


def machine_busy():
    """All CPUs' busy time so far, in seconds (from /proc/stat), or None."""
    try:
        with open("/proc/stat") as fh:
            f = [int(v) for v in fh.readline().split()[1:9]]
        return (f[0] + f[1] + f[2] + f[5] + f[6] + f[7]) / os.sysconf("SC_CLK_TCK")
    except (OSError, ValueError, IndexError):
        return None


class Run:
    """One way of computing the grid; __call__ times one run, keeps the first
    result for the bitwise check, and the machine's CPU/wall of the best run."""

    def __init__(self, label, fn, slots=None):
        self.label, self.fn, self.slots = label, fn, slots
        self.result = None
        self.best = np.inf
        self.cores = None

    def __call__(self):
        b0 = machine_busy()
        t0 = time.perf_counter()
        res = self.fn()
        wall = time.perf_counter() - t0
        b1 = machine_busy()
        if self.result is None:
            self.result = {f: np.asarray(res[f]) for f in FIELDS}
        if wall < self.best:
            self.best = wall
            self.cores = None if b0 is None or b1 is None else (b1 - b0) / wall
        return wall


def start_dask(processes):
    """A local cluster of 2 workers x 1 thread and its client; start-up seconds
    (until both workers are up)."""
    from distributed import Client, LocalCluster
    logging.getLogger("distributed").setLevel(logging.ERROR)
    t0 = time.perf_counter()
    with warnings.catch_warnings():
        # the second cluster's scheduler finds the first's HTTP port taken
        warnings.filterwarnings("ignore", message="Port .* is already in use")
        cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=processes,
                               dashboard_address=None, silence_logs=logging.ERROR)
        client = Client(cluster, set_as_default=False)
        client.wait_for_workers(2)
    return cluster, client, time.perf_counter() - t0


def worker_cpu(clusters):
    """CPU seconds used so far by the Dask worker processes (processes=True
    clusters; in-process workers count as this process's own)."""
    total = 0.0
    for cluster, client, _ in clusters.values():
        if cluster.processes:
            for user, system in client.run(lambda: tuple(os.times()[:2])).values():
                total += user + system
    return total


def measure(grid, clusters):
    ax = [grid["cx"][:, None, None], grid["mu"][None, :, None], grid["N"][None, None, :]]
    fixed = dict(FIXED)
    cy, cphi = fixed.pop("cy"), fixed.pop("cphi")

    def direct():
        r = rr.creep_forces(ax[0], cy, cphi, N=ax[2], mu=ax[1], **fixed)
        return r._asdict()

    def swept(client=None, **kw):
        if client is None:
            return lambda: rr.sweep("creep_forces", grid, progress=False, **kw, **FIXED)

        def run():
            # as_current: rr.sweep's as_completed() finds its loop through the
            # current client, not the one given (a non-default client fails)
            with client.as_current():
                return rr.sweep("creep_forces", grid, progress=False, client=client, **FIXED)
        return run

    runs = [Run("direct rr.creep_forces call (reference)", direct),
            Run("rr.sweep, serial", swept(backend="serial"), 1),
            Run("rr.sweep, threads, workers=1", swept(backend="threads", workers=1), 1),
            Run("rr.sweep, threads, workers=2", swept(backend="threads", workers=2), 2)]
    for label, (_, client, _) in clusters.items():
        runs.append(Run(f"rr.sweep, Dask {label}", swept(client=client), 2))

    # warm-up on a small grid (imports, the workers' first task), not timed
    small = {k: v[:4] for k, v in grid.items()}
    rr.sweep("creep_forces", small, progress=False, backend="serial", **FIXED)
    rr.sweep("creep_forces", small, progress=False, backend="threads", workers=2, **FIXED)
    for _, client, _ in clusters.values():
        with client.as_current():
            rr.sweep("creep_forces", small, progress=False, client=client, **FIXED)
    interleaved(runs, REPEATS)
    return runs


def chunks(total, slots):
    """The number of chunks of rr.sweep's default chunk size on `slots` workers."""
    chunk = max(1, min(CHUNK_CASES, -(-total // slots)))
    return -(-total // chunk)


def bitwise_equal(a, b):
    a, b = np.ascontiguousarray(a), np.ascontiguousarray(b)
    if a.shape != b.shape:
        return False
    if a.dtype.kind == "f" and b.dtype.kind == "f":
        return a.dtype == b.dtype and np.array_equal(a.view(np.uint8), b.view(np.uint8))
    return np.array_equal(a, b)


def main(argv=None):
    args = bench_args(__doc__, argv)
    date = datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds")
    grid = make_grid(args.quick)
    total = int(np.prod([v.size for v in grid.values()]))
    load0 = load_average()
    mon = CpuMonitor()

    clusters, dask_error = {}, None
    try:
        import distributed  # noqa: F401
    except ImportError as exc:
        dask_error = f"dask.distributed not installed ({exc})"
    if dask_error is None:
        for label, processes in (("2 worker processes x 1 thread (processes=True)", True),
                                 ("2 workers x 1 thread in this process (processes=False)",
                                  False)):
            log(f"starting a local Dask cluster: {label} ...")
            clusters[label] = start_dask(processes)
    log(f"{total} cases, {len(clusters) + 4} ways, best of {REPEATS} interleaved ...")
    try:
        cpu0 = worker_cpu(clusters)
        runs = mon.section("sweeps", measure, grid, clusters)
        # the Dask worker processes are this benchmark's, not other processes
        sec = mon.sections[-1]
        sec["other"] = max(0.0, sec["other"] - (worker_cpu(clusters) - cpu0) / sec["wall"])
    finally:
        for cluster, client, _ in clusters.values():
            client.close()
            cluster.close()
    load1 = load_average()

    ref = runs[0]
    same = {r.label: all(bitwise_equal(r.result[f], ref.result[f]) for f in FIELDS)
            for r in runs[1:]}
    by = {r.label: r for r in runs}
    serial = by["rr.sweep, serial"]
    t1 = by["rr.sweep, threads, workers=1"]
    t2 = by["rr.sweep, threads, workers=2"]
    eff = t1.best / (2 * t2.best)
    nchunks = chunks(total, 2)
    status_ok = int(np.count_nonzero(ref.result["status"] == 0))

    info = machine_info(compiler_version())
    L = ["# A sweep of FASTSIM 20x20 cases (issue 5)", "",
         f"- date: {date}", f"- command: `{command_text(argv)}`", machine_line(info),
         f"- python {sys.version.split()[0]}, numpy {np.__version__}, rollerrig "
         f"{rr.__version__}" + (f", dask.distributed {distributed.__version__}"
                                if dask_error is None else "") + f"; {code_state()}"]
    L += conditions_lines(load0, load1, mon)
    L += [f"- every time is the best of {REPEATS} runs (time.perf_counter), the runs taking "
          "turns within each round, all in this one run; Dask start-up excluded; the Dask "
          "worker processes' CPU time is not counted as other processes'."]
    L += ["", "## Goals", "", "| goal | measured | target | result |",
          "| --- | --- | --- | --- |",
          f"| 2-thread scaling efficiency, rr.sweep threads, t1 / (2 t2) | {eff:.2f} "
          f"({t1.best / t2.best:.2f}x) | >= {GOAL_EFFICIENCY:g} | "
          f"{verdict(eff >= GOAL_EFFICIENCY)} |",
          f"| all backends bitwise identical to the direct call (fx, fy, mz, status) | "
          f"{'yes' if all(same.values()) else 'no: ' + ', '.join(k for k, v in same.items() if not v)}"
          f" | identical | {verdict(all(same.values()))} |"]
    for label, (_, _, startup) in clusters.items():
        d = by[f"rr.sweep, Dask {label}"]
        L.append(f"| Dask {label} over threads workers=2 | {d.best / t2.best:.2f}x "
                 f"({(d.best - t2.best) * 1e3:+.0f} ms) | reported, no goal | n/a |")
    L += ["", "## The runs", "",
          f"{total:,} cases: cx {grid['cx'].size} ({grid['cx'][0]:g} to {grid['cx'][-1]:g}) "
          f"x mu {grid['mu'].size} ({grid['mu'][0]:g} to {grid['mu'][-1]:g}) x N "
          f"{grid['N'].size} ({grid['N'][0]:g} to {grid['N'][-1]:g} N); cy = {FIXED['cy']:g}, "
          f"spin 0, a = b = 6 mm, FASTSIM 20x20 (rect grid, parabolic bound, Coulomb "
          f"friction); {status_ok:,} of {total:,} cases status 0. rr.sweep with its default "
          f"chunk size (at most {CHUNK_CASES:,} cases, fewer when that keeps a worker idle) "
          "and progress=False; its time includes "
          "gathering the chunks and building the xarray.Dataset. The reference is one "
          "rr.creep_forces call on the axes broadcast against each other. Machine "
          "CPU/wall: all processes' CPU time (/proc/stat) over wall time of the best run, "
          "which counts the Dask worker processes (2.0 = both cores busy all along).", "",
          "| run | chunks | s | M cases/s | us per case | vs reference | machine CPU/wall | "
          "bitwise = reference |", "| --- | ---: | ---: | ---: | ---: | ---: | ---: | --- |"]
    for r in runs:
        cores = "n/a" if r.cores is None else f"{r.cores:.2f}"
        eq = "-" if r is ref else ("yes" if same[r.label] else "**no**")
        nch = "-" if r.slots is None else chunks(total, r.slots)
        L.append(f"| {r.label} | {nch} | {fmt(r.best)} | {fmt(total / r.best / 1e6)} | "
                 f"{fmt(r.best / total * 1e6)} | {r.best / ref.best:.2f}x | {cores} | {eq} |")
    L += ["", f"rr.sweep's own cost, serial against the direct call: "
          f"{(serial.best - ref.best) * 1e3:+.0f} ms ({(serial.best / ref.best - 1) * 100:+.1f} %)."
          f" Threads workers=1 against serial: {(t1.best / serial.best - 1) * 100:+.1f} %."]
    if clusters:
        L += ["", "## Dask", "",
              "A dask.distributed LocalCluster of 2 workers x 1 thread (dashboard off), "
              "started and its client connected before the timing; the same chunks as "
              "the threads, one task each, results gathered as they finish.", "",
              "| cluster | start-up s (excluded) | sweep s | over threads workers=2 | "
              "overhead per chunk ms |", "| --- | ---: | ---: | ---: | ---: |"]
        for label, (_, _, startup) in clusters.items():
            d = by[f"rr.sweep, Dask {label}"]
            L.append(f"| {label} | {fmt(startup)} | {fmt(d.best)} | "
                     f"{(d.best / t2.best - 1) * 100:+.1f} % | "
                     f"{fmt((d.best - t2.best) / nchunks * 1e3)} |")
    else:
        L += ["", f"Dask not measured: {dask_error}."]
    return publish(args, "sweep", L)


if __name__ == "__main__":
    sys.exit(main())
