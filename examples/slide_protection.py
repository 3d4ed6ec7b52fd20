"""Wheel-slide protection in the loop: braking through a low-adhesion patch.

The wheelset is braked with a torque demand worth an adhesion of 0.25
while the rollers (the "track") keep 5 m/s; from 1.5 s to 3.5 s the
friction falls from 0.4 to 0.1 (wet, contaminated rail) and comes back.
Three controllers of the wheelset's drive meet it:

- no protection: the demand is applied as it is: in the patch the wheel
  slides and locks, and stays locked after it (the falling friction at a
  locked wheel's slip speed, 0.17, is less than the demand);
  the drive acts as a friction brake (brake below), which holds a locked
  wheel at rest rather than driving it backward;
- the paper's creepage controller (eq. 13-16) holding a creepage of 0.02;
- SlideProtection below, written as a user writes one: the demand is
  applied until the wheel slides; then the torque is dumped, held, and
  re-applied, from the encoders alone (slip against the roller speed,
  the wheel's deceleration).

    python examples/slide_protection.py [output folder]

writes slide_protection.png (creepage and braking force of the three) and
prints the largest creepage of each; tests/test_slide_protection.py runs
the same scenario.
"""
import math
import os
import sys

import numpy as np

import rollerrig as rr

#: the scenario: 5 s at the paper's 4 ms sample, the patch in the middle
DURATION = 5.0
PATCH = (1.5, 3.5)
ADHESION = {"adhesion": {"schedule_times_s": [PATCH[0], PATCH[0], PATCH[1], PATCH[1]],
                         "schedule_mu0": [0.4, 0.1, 0.1, 0.4]}}
#: the brake demand [N m]: an adhesion of 0.25 on both wheels (static loads
#: 2 x 521.6 N, wheel radius 0.092 m), from 0.2 s on
DEMAND = 0.25 * 2 * 521.6 * 0.092
BRAKE_FROM = 0.2


def brake(torque, s, w_stop=0.5):
    """The wheelset drive as a friction brake: the torque [N m] opposes the
    wheel's rotation and fades out below w_stop [rad/s], so that a locked
    wheel stays locked instead of being driven backward by a motor."""
    return {"wheelset_torque": -abs(torque) * max(-1.0, min(1.0, s.wheelset_speed / w_stop))}


class SlideProtection:
    """Wheel-slide protection of the dump / hold / re-apply kind, on the
    encoders alone.  Each sample it estimates the slip from the wheel's
    and the roller's speeds (eq. 16's estimate, > 0 braking) and the
    wheel's deceleration from its encoder, and scales the brake demand by
    a factor in [0, 1]:
      dump     slip above slip_on, or deceleration above decel_max: the
               factor falls at dump_rate per second
      hold     slip between slip_off and slip_on: the factor stays
      re-apply slip below slip_off: the factor rises at apply_rate per
               second back to 1
    The thresholds are those of the kind of a railway WSP: slide detected
    at a few per cent of slip or a deceleration above what adhesion allows."""

    def __init__(self, demand, start=0.0, slip_on=0.05, slip_off=0.02, decel_max=4.0,
                 dump_rate=8.0, apply_rate=3.0):
        self.demand, self.begin = demand, start
        self.slip_on, self.slip_off, self.decel_max = slip_on, slip_off, decel_max
        self.dump_rate, self.apply_rate = dump_rate, apply_rate

    def start(self, info):
        self.dt, self.r = info.dt, info.wheel_radius
        self.factor, self.last = 1.0, None

    def __call__(self, s):
        v = s.wheelset_speed * self.r                           # wheel surface speed [m/s]
        decel = 0.0 if self.last is None else (self.last - v) / self.dt
        self.last = v
        if s.t < self.begin:
            return None                                         # not braking yet
        if s.xi_est > self.slip_on or decel > self.decel_max:
            self.factor = max(0.0, self.factor - self.dump_rate * self.dt)
        elif s.xi_est < self.slip_off:
            self.factor = min(1.0, self.factor + self.apply_rate * self.dt)
        return brake(self.demand * self.factor, s)


def unprotected(s):
    """The demand as it is, from BRAKE_FROM on."""
    return None if s.t < BRAKE_FROM else brake(DEMAND, s)


def runs():
    """{name: RigResult} of the three controllers in the patch."""
    common = dict(duration=DURATION, params=ADHESION)
    return {
        "no protection": rr.simulate(controller=unprotected, targets=[0.0], **common),
        "creepage controller, 0.02": rr.simulate(targets=[0.0, 0.02],
                                                 target_times=[0.0, BRAKE_FROM], **common),
        "slide protection (this example)": rr.simulate(
            controller=SlideProtection(DEMAND, start=BRAKE_FROM), targets=[0.0], **common),
    }


def figure(results, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8, 6.4), sharex=True)
    for name, res in results.items():
        ax1.plot(res.time, res.creepage, lw=0.9, label=name)
        ax2.plot(res.time, -res.fx, lw=0.9, label=name)
    res = next(iter(results.values()))
    ax2.plot(res.time, res.mu_left * res.normal_load_left + res.mu_right * res.normal_load_right,
             "k:", lw=1, label="friction limit mu0(t) N")
    ax2.axhline(DEMAND / 0.092, color="grey", lw=0.8, ls="--",
                label="brake demand (as a force at the wheels)")
    for ax in (ax1, ax2):
        ax.axvspan(*PATCH, color="tab:blue", alpha=0.08)
        ax.grid(alpha=0.3)
    ax1.set(yscale="log", ylim=(1e-4, 3.0), ylabel="creepage cx [-] (2: locked)",
            title="Braking through a patch of mu0 0.1 (shaded) on the roller rig")
    ax1.legend(fontsize=8, loc="lower right")
    ax2.set(xlabel="time [s]", ylabel="braking force -fx [N]", ylim=(0, 480))
    ax2.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def main(outdir="."):
    os.makedirs(outdir, exist_ok=True)
    results = runs()
    for name, res in results.items():
        inside = (res.time > PATCH[0]) & (res.time < PATCH[1])
        after = res.time > PATCH[1] + 0.5
        print(f"{name:34s} largest creepage {np.max(res.creepage):.3f}, in the patch "
              f"{np.max(res.creepage[inside]):.3f}, after it {np.max(res.creepage[after]):.3f}; "
              f"mean braking force in the patch {np.mean(-res.fx[inside]):.0f} N")
    print("wrote", figure(results, os.path.join(outdir, "slide_protection.png")))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else ".")
