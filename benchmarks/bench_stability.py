"""Speed of the lateral stability analysis (issue 25): rollerrig.stability's
eigenvalues at 100 speeds (goal: under 1 s), one rollerrig.linearize (the
plant; the sampled closed loop on the rollers, on track and under creepage
control), the 30-speed bifurcation diagram (goal: under a minute), and the
same work against one second of the rig in time, side by side in one run.

    python benchmarks/bench_stability.py

Timings are the best of five repeats (time.perf_counter, wall; process
CPU time beside), every case in the same process and minute.
"""
import time

import numpy as np

import rollerrig as rr

GOAL_100_SPEEDS_S = 1.0
SOFT = {"suspension": {"kx_N_per_m": 2e4, "ky_N_per_m": 2e4}}


def best(f, repeats=5):
    wall, cpu = [], []
    for _ in range(repeats):
        w, c = time.perf_counter(), time.process_time()
        f()
        wall.append(time.perf_counter() - w)
        cpu.append(time.process_time() - c)
    return min(wall), min(cpu)


def main():
    speeds = np.linspace(1.0, 100.0, 100)
    cases = {
        "stability, 100 speeds, rollers (default)": lambda: rr.stability(speeds),
        "stability, 100 speeds, track (soft, with its critical speed)":
            lambda: rr.stability(speeds, SOFT, track=True),
        "linearize, one speed (with the rig's build)": lambda: rr.linearize(roller_speed=5.0),
        "linearize, closed loop, rollers (settling included)":
            lambda: rr.linearize(closed_loop=True),
        "linearize, closed loop, track": lambda: rr.linearize(track=True, closed_loop=True),
        "linearize, closed loop, creepage control 0.02":
            lambda: rr.linearize(closed_loop=True, creepage_target=0.02),
        "hunting, 30 speeds, track (soft): the bifurcation diagram":
            lambda: rr.hunting(np.arange(130.0, 40.0, -3.0), SOFT, track=True),
        "simulate, 1 s of the paper's scenario (reference)":
            lambda: rr.simulate(duration=1.0, targets=[0.02], target_times=[0.0]),
    }
    rows = {name: best(f, 1 if name.startswith("hunting") else 3 if "closed" in name else 5)
            for name, f in cases.items()}
    ref = rows["simulate, 1 s of the paper's scenario (reference)"][0]
    print(f"{'case':<64} {'wall [s]':>9} {'cpu [s]':>9} {'/ simulate 1 s':>15}")
    for name, (w, c) in rows.items():
        print(f"{name:<64} {w:9.3f} {c:9.3f} {w / ref:15.2f}")
    w = rows["stability, 100 speeds, rollers (default)"][0]
    h = rows["hunting, 30 speeds, track (soft): the bifurcation diagram"][0]
    print(f"goal: a bifurcation diagram over 30 speeds under 60 s: "
          f"{'met' if h < 60 else 'NOT met'} ({h:.1f} s, one thread)")
    print(f"goal: 100 speeds under {GOAL_100_SPEEDS_S:g} s: "
          f"{'met' if w < GOAL_100_SPEEDS_S else 'NOT met'} ({w:.3f} s)")


if __name__ == "__main__":
    main()
