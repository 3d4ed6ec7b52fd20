"""Command-line entry point: ``rollerrig simulate`` (also ``python -m rollerrig``)."""
import argparse
import csv
import os
import sys
import time

from ._version import __version__


def _simulate(args):
    from . import rig
    from ._errors import RollerRigError

    try:
        params = rig.load_parameters(args.scenario) if args.scenario else None
    except (OSError, ValueError) as e:        # missing file, TOML syntax (a ValueError)
        print(f"rollerrig simulate: --scenario: {e}", file=sys.stderr)
        return 2
    kw = {}
    if args.method:
        kw["method"] = args.method
    try:
        t0 = time.perf_counter()
        res = rig.simulate(duration=args.duration, dt=args.dt, params=params,
                           progress=not args.quiet and sys.stderr.isatty(), **kw)
        wall = time.perf_counter() - t0
    except (RollerRigError, OSError, ValueError) as e:
        print(f"rollerrig simulate: {e}", file=sys.stderr)
        return 2
    simulated = len(res) * res.dt
    run = res.wall["run"]
    print(f"rollerrig {__version__}: {simulated:g} s simulated in {run:.3f} s "
          f"(real-time factor {simulated / run:.0f}; set-up {res.wall['setup']:.3f} s, "
          f"all {wall:.2f} s), dt = {res.dt * 1e3:g} ms, "
          f"{res.params['contact']['creep_method'] if not args.method else args.method}")
    print(res.table())
    os.makedirs(args.out, exist_ok=True)
    path = os.path.join(args.out, "rig_history.csv")
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(rig.RECORD_FIELDS)
        w.writerows(res.records.tolist())
    print(f"wrote {path}")
    try:
        from .plot import plot_run
        for p in plot_run(res, args.out):
            print(f"wrote {p}")
    except ImportError:
        print("matplotlib is not importable: no figures (it is a dependency of rollerrig; "
              "pip install matplotlib)")
    if res.status < 0:
        print(f"rollerrig simulate: {res.message}", file=sys.stderr)
        return 1
    return 0


def build_parser():
    parser = argparse.ArgumentParser(
        prog="rollerrig",
        description="Real-time simulation of a scaled railway roller rig.",
    )
    parser.add_argument("--version", action="version", version="%(prog)s " + __version__)
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    p = sub.add_parser("simulate", help="run the seed paper's braking scenario",
                       description="Run the roller rig: by default the seed paper's scenario "
                       "(roller at 5 m/s, braking under creepage control to 0.04, 0.015, "
                       "0.02, 0.03) on the default parameters; print a table per target and "
                       "write the time histories (CSV) and the figures (PNG).")
    p.add_argument("--scenario", metavar="TOML", help="parameter file overriding the defaults "
                   "(the layout of rollerrig/data/rig_default.toml; any subset of it)")
    p.add_argument("--duration", type=float, help="simulated time [s]")
    p.add_argument("--dt", type=float, help="control sample time and step [s] (default 0.004)")
    p.add_argument("--method", help="creep-force method: fastsim, fastsim_blended, "
                   "modified_fastsim, polach, linear")
    p.add_argument("--out", default="rollerrig-out", help="output folder (default "
                   "./rollerrig-out)")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(func=_simulate)
    return parser


def main(argv=None):
    parser = build_parser()
    args = parser.parse_args(argv)
    func = getattr(args, "func", None)
    if func is None:
        parser.print_help()
        return 0
    return func(args)


if __name__ == "__main__":
    sys.exit(main())
