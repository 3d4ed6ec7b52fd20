"""The Manchester contact benchmark, case A-2.2 (S1002 on UIC60 1:40, 10 kN per
wheel, mu 0.3, 2 m/s, 21 lateral shifts 0-10 mm with yaw 2.4 mrad/mm), by the
fast non-Hertzian method with the rail as a roller of (nearly) infinite
radius, against CONTACT's exact theory (tests/data/manchester_a22_exact_
totals.csv: each wheel's total force), beside today's single Hertz ellipse.

    python benchmarks/bench_nonhertz_manchester.py [--R 1e4]

The placement is RigGeometry.standard()'s (the benchmark's track: gauge
1435 mm at 14 mm depth, back-to-back 1360 mm, nominal radius 460 mm) with
roller_radius R (default 10 km: the rail's curvature along x, 1/R, is 2e-4
of the wheel's).  The rig frame's y is the benchmark's -y_ws (its y points
right).  The yaw (ours -yaw: the frames' z are opposite) turns each patch's frame by
the rig's first-order law (rr_rig_contact.h: the contact point leads the
wheel centre by sigma r tan(delta) yaw on a rail), as it does the Hertzian
contact's; "hertz_vy" is the Hertzian contact with the yaw's lateral slip
alone (vy = yaw V, no yaw): what the yaw's geometry is worth at the flange.
CONTACT's forces are on the rail in track coordinates (x forward, y right,
z down): on the wheel in the rig frame that is (-Fx, Fy, Fz).  |dF| / (mu N)
with N the method's own normal load (the reference file has none).
"""
import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

import rollerrig as rr

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))
from reference_cases import read_columns  # noqa: E402

V, MU, FZ, G, NU = 2.0, 0.3, 1e4, 8.2e10, 0.28


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--R", type=float, default=1e4)
    a = ap.parse_args()
    C = read_columns("manchester_a22_exact_totals.csv")
    E = 2 * G * (1 + NU)
    g = rr.RigGeometry.standard(roller_radius=a.R)
    cache = ROOT / "benchmarks" / "out" / "nonhertz" / f"table_manchester_R{a.R:g}.npz"
    t0 = time.perf_counter()
    if cache.exists():
        tab = rr.NonHertzTable.load(cache)
    else:
        tab = rr.nonhertz_table(g, -10.4e-3, 0.4e-3, dy=2e-4, Fz=FZ, mu_ref=MU, E=E, nu=NU)
        cache.parent.mkdir(parents=True, exist_ok=True)
        tab.save(cache)
    build = time.perf_counter() - t0
    ct = rr.contact_table(g, -0.011, 0.001, 241)
    roller_spin = V / a.R
    rows = []
    for i in range(C["side"].size):
        y = -C["y_ws_mm"][i] * 1e-3
        side = C["side"][i]
        spin = -C["vpitch_rad_s"][i]
        vy = C["yaw_rad"][i] * V
        yaw = -C["yaw_rad"][i]           # the rig frame's Z is the benchmark's -z
        c = getattr(rr.rig_contact(ct, y=y, yaw=yaw, spin=spin, roller_spin=roller_spin, mu=MU,
                                   E=E, nu=NU, Fz_left=FZ, Fz_right=FZ, patch="nonhertz",
                                   nonhertz=tab), side)
        res, pts = dict(force=c.force, N=c.N), c.patches
        ref = np.array([-C["Fx_N"][i], C["Fy_N"][i], C["Fz_N"][i]])
        F = np.array(res["force"])
        h = getattr(rr.rig_contact(ct, y=y, yaw=yaw, spin=spin,
                                   roller_spin=roller_spin, mu=MU, E=E, nu=NU, Fz_left=FZ,
                                   Fz_right=FZ), side)
        # Hertz with the yaw's lateral slip alone (as the non-Hertzian run
        # above): how much of the flange's error is yaw's left-out geometry
        hv = getattr(rr.rig_contact(ct, y=y, vy=vy, spin=spin, roller_spin=roller_spin, mu=MU,
                                    E=E, nu=NU, Fz_left=FZ, Fz_right=FZ), side)
        rows.append(dict(y_mm=C["y_ws_mm"][i], side=side, patches=len(pts),
                         nonhertz=float(np.linalg.norm(F - ref) / (MU * res["N"])),
                         hertz=float(np.linalg.norm(h.force - ref) / (MU * float(h.N))),
                         hertz_vy=float(np.linalg.norm(hv.force - ref) / (MU * float(hv.N))),
                         F=[round(v, 1) for v in F], ref=[round(v, 1) for v in ref]))
    for r in rows:
        print(json.dumps(r))
    nh = np.array([r["nonhertz"] for r in rows])
    hz = np.array([r["hertz"] for r in rows])
    # "without flange": the right wheel's flange root and flange (from 5 mm)
    tread = np.array([r["y_mm"] < 4.75 or r["side"] == "left" for r in rows])
    print(json.dumps(dict(cases=len(rows), build_s=round(build, 1),
                          nonhertz_p95_max=(round(float(np.percentile(nh, 95)), 4),
                                            round(float(nh.max()), 4)),
                          nonhertz_median=round(float(np.median(nh)), 4),
                          hertz_p95_max=(round(float(np.percentile(hz, 95)), 4),
                                         round(float(hz.max()), 4)),
                          hertz_yaw_as_slip_p95_max=(
                              round(float(np.percentile([r["hertz_vy"] for r in rows], 95)), 4),
                              round(float(max(r["hertz_vy"] for r in rows)), 4)),
                          hertz_without_flange_p95_max=(
                              round(float(np.percentile(hz[tread], 95)), 4),
                              round(float(hz[tread].max()), 4)),
                          nonhertz_without_flange_p95_max=(
                              round(float(np.percentile(nh[tread], 95)), 4),
                              round(float(nh[tread].max()), 4)))))


if __name__ == "__main__":
    main()
