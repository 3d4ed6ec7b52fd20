"""The non-Hertzian contact's table build and run time (issue 24 item 3).

    python benchmarks/bench_nonhertz_table.py build [--pair miniprof|s1002] [--dy 2e-4]
        the full sweep's table, -8 to +8 mm, both sides: rows, wall time
        (2 threads), saved to benchmarks/out/nonhertz/table_<pair>.npz
    python benchmarks/bench_nonhertz_table.py sweep [--pair miniprof] [--table T.npz]
            [--baseline B.npz] [--y-lo -7.9e-3] [--y-hi 7.9e-3]
        accuracy on the saved table (or T) against rig_exact (n = 80), both sides,
        -7.9 to +7.9 mm every 0.5 mm (half-way between rows), four creepages;
        with --baseline a second table judged on the same references (before /
        after a change, side by side in one run)
    python benchmarks/bench_nonhertz_table.py speed [--pair miniprof] [--states 2000]
        per wheel in C: rr_nonhertz_wheel against Hertz + FASTSIM 20 x 20 on the
        same random states (bench_nonhertz_speed.c), on the saved table

The states: y uniform over the table's rows (within +-6 mm), Fz 45-75 kN,
braking creepage 0-2 % (the wheelset's spin), lateral speed +-0.02 m/s,
the rollers at 5.587 rad/s, mu 0.4.
"""
import argparse
import json
import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

import rollerrig as rr

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "out" / "nonhertz"


def geometry(pair):
    return (rr.RigGeometry.measured_pair() if pair == "miniprof"
            else rr.RigGeometry.standard(roller_radius=0.8001))


def build(pair, dy, y_lo=-8e-3, y_hi=8e-3, workers=2):
    g = geometry(pair)
    t0, c0 = time.perf_counter(), time.process_time()
    tab = rr.nonhertz_table(g, y_lo, y_hi, dy=dy, Fz=61163.0, mu_ref=0.52, workers=workers)
    wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    load = os.getloadavg()[0]
    OUT.mkdir(parents=True, exist_ok=True)
    tab.save(OUT / f"table_{pair}.npz")
    rows = tab.left.rows.shape[0] + tab.right.rows.shape[0]
    print(json.dumps(dict(pair=pair, dy=dy, rows_left=tab.left.rows.shape[0],
                          rows_right=tab.right.rows.shape[0], wall_s=round(wall, 1),
                          cpu_s=round(cpu, 1), cpu_s_per_row=round(cpu / rows, 3),
                          wall_on_2_free_cores_s=round(cpu / 2, 1),
                          load_average=round(load, 2))))


def speed(pair, n_states, repeats=31, seed=1):
    g = geometry(pair)
    tab = rr.NonHertzTable.load(OUT / f"table_{pair}.npz")
    side = tab.left
    ct = rr.contact_table(g, -0.0085, 0.0085, 341)
    rng = np.random.default_rng(seed)
    lo, hi = max(side.y[0], -6e-3), min(side.y[-1], 6e-3)
    rs = 5.587302
    rec = []
    for _ in range(n_states):
        y = rng.uniform(lo, hi)
        Fz = rng.uniform(45e3, 75e3)
        k = rr.rig_contact(ct, y=y, spin=12.4, roller_spin=rs, kinematics_only=True)
        spin = 12.43 * (1 - rng.uniform(0, 0.02))
        vy = rng.uniform(-0.02, 0.02)
        st, i, w = rr.geometry.nonhertz.nonhertz_locate(side, y)
        kk = rr.rig_contact(ct, y=side.y[[i, i + 1]], vy=vy, spin=spin, roller_spin=rs,
                            kinematics_only=True)
        mot = [np.concatenate([kk.pose.c[:, j], kk.pose.v[:, j], kk.pose.w[:, j]])
               for j in range(2)]
        h = rr.rig_contact(ct, y=y, vy=vy, spin=spin, roller_spin=rs, Fz_left=Fz,
                           Fz_right=Fz, mu=0.4).left
        rec.append(np.concatenate([[y, Fz, 0.4, rs, 1e-3], mot[0], mot[1],
                                   [h.cx, h.cy, h.cphi, h.a, h.b, h.N]]))
    data = np.concatenate([[side.rows.shape[0], *side.head], side.rows.ravel(), [n_states],
                           np.array(rec).ravel()])
    OUT.mkdir(parents=True, exist_ok=True)
    f = OUT / f"speed_{pair}.bin"
    data.astype("<f8").tofile(f)
    exe = OUT / "bench_nonhertz_speed"
    srcs = [str(p) for p in sorted((ROOT / "csrc").glob("*/rr_*.c"))]
    subprocess.run(["cc", "-O2", "-std=c99", "-I", str(ROOT / "csrc"),
                    str(ROOT / "benchmarks" / "bench_nonhertz_speed.c"), *srcs, "-lm", "-o",
                    str(exe)], check=True)
    out = subprocess.run([str(exe), str(f), str(repeats)], check=True, capture_output=True,
                         text=True).stdout
    r = json.loads(out)
    r["pair"] = pair
    print(json.dumps(r))


def _nonhertz_error(ct, tab, kw, side, ref, y):
    """|dF| / (mu N) of the nonhertz wheel on table tab, NaN where it fails."""
    try:
        nh = getattr(rr.rig_contact(ct, patch="nonhertz", nonhertz=tab, errors="ignore", **kw),
                     side)
        if nh.status < 0:
            raise rr.RollerRigError("the vertical balance has no solution")
    except rr.RollerRigError as e:
        print(f"# nonhertz failed at y = {y:.4f} {side} (the reference did not): {e}",
              file=sys.stderr)
        return np.nan
    return np.linalg.norm(nh.force - ref.force) / (kw["mu"] * ref.N)


def sweep(pair, y_lo=-7.9e-3, y_hi=7.9e-3, step=5e-4, n_ref=80, table=None, baseline=None):
    """Both sides from y_lo to y_hi every step (offset 0.1 mm from the 0.2 mm
    rows: half-way between two), creepage targets cx 0.0005, 0.002, 0.006 at
    the rigid contact point and one with lateral slip (vy 0.01 m/s), Fz
    61.163 kN, mu 0.52: |dF| / (mu N) of nonhertz and of Hertz (FASTSIM 20 x
    20) against rig_exact (n = n_ref); table: the table's file (default the
    build's), baseline: a second table's, judged on the same references."""
    g = geometry(pair)
    tab = rr.NonHertzTable.load(table or OUT / f"table_{pair}.npz")
    base = rr.NonHertzTable.load(baseline) if baseline else None
    ct = rr.contact_table(g, -0.0085, 0.0085, 341)
    rs, Fz, mu = 5.587302, 61163.0, 0.52
    out = []
    for y in np.arange(y_lo, y_hi + 1e-9, step):
        w = rr.wheelset_contact(g, y)
        for side in ("left", "right"):
            p = getattr(w, side)
            for target, vy in ((5e-4, 0.0), (2e-3, 0.0), (6e-3, 0.0), (1e-3, 0.01)):
                spin = rs * float(p.R[0]) / float(p.r[0]) * (1 - target)
                kw = dict(y=y, vy=vy, spin=spin, roller_spin=rs, mu=mu, Fz_left=Fz,
                          Fz_right=Fz)
                try:
                    ref = rr.rig_exact(g, y, side=side, Fz=Fz, mu=mu, spin=spin,
                                       roller_spin=rs, vy=vy, table=ct, n=n_ref)
                except rr.RollerRigError as e:
                    print(f"# reference failed at y = {y:.4f} {side}: {e}", file=sys.stderr)
                    continue
                e = _nonhertz_error(ct, tab, kw, side, ref, y)
                eb = _nonhertz_error(ct, base, kw, side, ref, y) if base else np.nan
                hz = getattr(rr.rig_contact(ct, **kw), side)
                out.append((y, side == "left", e,
                            np.linalg.norm(hz.force - ref.force) / (mu * ref.N), eb, target,
                            vy))
    a = np.array(out)
    OUT.mkdir(parents=True, exist_ok=True)
    np.save(OUT / f"sweep_{pair}.npy", a)
    res = dict(pair=pair, cases=int(np.isfinite(a[:, 2]).sum()),
               nonhertz_failed_where_reference_did_not=int(np.isnan(a[:, 2]).sum()))
    cols = [("nonhertz", 2), ("hertz_fastsim", 3)] + ([("baseline", 4)] if base else [])
    for name, col in cols:
        v = a[np.isfinite(a[:, col]), col]
        res[name] = (round(float(np.percentile(v, 95)), 4), round(float(v.max()), 4))
        k = np.nanargmax(a[:, col])
        res[f"worst_{name}"] = dict(y_mm=round(float(a[k, 0]) * 1e3, 2),
                                    side="left" if a[k, 1] else "right",
                                    cx_target=float(a[k, 5]), vy=float(a[k, 6]))
    if base:
        res["baseline_failed"] = int(np.isnan(a[:, 4]).sum())
    print(json.dumps(res))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("what", choices=("build", "speed", "sweep"))
    ap.add_argument("--pair", default="miniprof", choices=("miniprof", "s1002"))
    ap.add_argument("--dy", type=float, default=2e-4)
    ap.add_argument("--states", type=int, default=2000)
    ap.add_argument("--table", help="sweep: the table's .npz (default the build's)")
    ap.add_argument("--baseline", help="sweep: a second table's .npz, on the same references")
    ap.add_argument("--y-lo", type=float, default=-7.9e-3)
    ap.add_argument("--y-hi", type=float, default=7.9e-3)
    a = ap.parse_args()
    if a.what == "build":
        build(a.pair, a.dy)
    elif a.what == "sweep":
        sweep(a.pair, a.y_lo, a.y_hi, table=a.table, baseline=a.baseline)
    else:
        speed(a.pair, a.states)


if __name__ == "__main__":
    main()
