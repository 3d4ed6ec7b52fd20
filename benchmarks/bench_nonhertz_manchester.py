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
right).  The method has no yaw (its planes are the zero-yaw ones): the
yaw's lateral creepage, cy = yaw (ours -yaw, the frames' z opposite), is
given as a lateral slip vy = yaw V of the wheelset (no roll rate); the yaw's
shift of the contact point along x (flange contact: r tan(delta) yaw, up to
about 4 mm here) and its spin are left out, so this is the method on the
benchmark's geometry less yaw's geometric effect.  Hertz: rig_contact with
the yaw itself (its first-order yaw law) and the same vertical loads.
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
from rollerrig.geometry.nonhertz import nonhertz_wheel, nonhertz_locate

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
    t0 = time.perf_counter()
    tab = rr.nonhertz_table(g, -10.4e-3, 0.4e-3, dy=2e-4, Fz=FZ, mu_ref=MU, E=E, nu=NU)
    build = time.perf_counter() - t0
    ct = rr.contact_table(g, -0.011, 0.001, 241)
    roller_spin = V / a.R
    rows = []
    for i in range(C["side"].size):
        y = -C["y_ws_mm"][i] * 1e-3
        side = C["side"][i]
        spin = -C["vpitch_rad_s"][i]
        vy = C["yaw_rad"][i] * V
        t = tab.side(side)
        st, k, w = nonhertz_locate(t, y)
        mot = []
        for j in (k, k + 1):
            yr, z0, roll0 = t.rows[j, 0], t.rows[j, 2], t.rows[j, 3]
            mot.append(((0.0, yr, z0), (0.0, vy, 0.0),
                        (0.0, spin * np.cos(roll0), spin * np.sin(roll0))))
        st, res, pts = nonhertz_wheel(t, y, FZ, MU, roller_spin, *mot)
        if st < 0:
            print(f"# nonhertz failed at {C['y_ws_mm'][i]} mm {side}: {st}", file=sys.stderr)
            continue
        ref = np.array([-C["Fx_N"][i], C["Fy_N"][i], C["Fz_N"][i]])
        F = np.array(res["force"])
        h = getattr(rr.rig_contact(ct, y=y, yaw=-C["yaw_rad"][i], spin=spin,
                                   roller_spin=roller_spin, mu=MU, E=E, nu=NU, Fz_left=FZ,
                                   Fz_right=FZ), side)
        rows.append(dict(y_mm=C["y_ws_mm"][i], side=side, patches=len(pts),
                         nonhertz=float(np.linalg.norm(F - ref) / (MU * res["N"])),
                         hertz=float(np.linalg.norm(h.force - ref) / (MU * float(h.N))),
                         F=[round(v, 1) for v in F], ref=[round(v, 1) for v in ref]))
    for r in rows:
        print(json.dumps(r))
    nh = np.array([r["nonhertz"] for r in rows])
    hz = np.array([r["hertz"] for r in rows])
    tread = np.array([r["y_mm"] < 6.25 or r["side"] == "left" for r in rows])
    print(json.dumps(dict(cases=len(rows), build_s=round(build, 1),
                          nonhertz_p95_max=(round(float(np.percentile(nh, 95)), 4),
                                            round(float(nh.max()), 4)),
                          nonhertz_median=round(float(np.median(nh)), 4),
                          hertz_p95_max=(round(float(np.percentile(hz, 95)), 4),
                                         round(float(hz.max()), 4)),
                          nonhertz_without_flange_p95_max=(
                              round(float(np.percentile(nh[tread], 95)), 4),
                              round(float(nh[tread].max()), 4)))))


if __name__ == "__main__":
    main()
