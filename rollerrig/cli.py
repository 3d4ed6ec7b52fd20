"""Command-line entry point: ``rollerrig simulate``, ``rollerrig fmu`` (also ``python -m
rollerrig``).

Exit status: 0 the run finished (its warnings, if any, on stderr), 1 the
run stopped early (its outputs are still written), 2 bad input (a message on
stderr naming the option, no traceback, nothing run).
"""
import argparse
import os
import sys
import tempfile
import time
import warnings

from ._version import __version__

PROG = "rollerrig simulate"


class _Refused(Exception):
    """Bad input: the message for stderr, exit status 2."""


def _prepare_out(path):
    """Create the output folder and prove it is a writable directory (a
    temporary file made and removed in it), before anything is run."""
    if os.path.exists(path) and not os.path.isdir(path):
        raise _Refused(f"--out {path}: not a directory")
    try:
        os.makedirs(path, exist_ok=True)
    except OSError as e:
        raise _Refused(f"--out {path}: cannot create the folder: {e.strerror or e}") from None
    if not os.path.isdir(path):
        raise _Refused(f"--out {path}: not a directory")
    try:
        fd, probe = tempfile.mkstemp(dir=path, prefix=".rollerrig-probe-")
        os.close(fd)
        os.remove(probe)
    except OSError as e:
        raise _Refused(f"--out {path}: cannot write in the folder: {e.strerror or e}") \
            from None


def _load_scenario(rig, path):
    """The scenario file's parameters, checked (every problem at once)."""
    if path is None:
        return None
    source = f"--scenario {path}"
    try:
        params = rig._read_parameter_file(path)
    except rig._Problems as p:
        raise _Refused(str(rig._error(source, p.problems))) from None
    try:
        rig.check_parameters(params, source=source)
    except ValueError as e:                  # RollerRigError
        raise _Refused(str(e)) from None
    return params


def _simulate(args):
    from . import rig
    from ._errors import RollerRigError, RollerRigWarning

    try:
        params = _load_scenario(rig, args.scenario)
        _prepare_out(args.out)
    except _Refused as e:
        print(f"{PROG}: {e}", file=sys.stderr)
        return 2
    kw = {"method": args.method} if args.method else {}
    t0 = time.perf_counter()
    res = error = None
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", RollerRigWarning)
        try:
            res = rig.simulate(duration=args.duration, dt=args.dt, params=params,
                               record_every=args.record_every,
                               progress=not args.quiet and sys.stderr.isatty(), **kw)
        except RollerRigError as e:
            error = e
    for w in caught:
        print(f"{PROG}: warning: {_unprefixed(w.message)}", file=sys.stderr)
    if error is not None:
        print(f"{PROG}: {_unprefixed(error)}", file=sys.stderr)
        return 2
    wall = time.perf_counter() - t0
    run = res.wall["run"]
    print(f"rollerrig {__version__}: {res.duration:g} s simulated in {run:.3f} s "
          f"(real-time factor {res.duration / run:.0f}; set-up {res.wall['setup']:.3f} s, "
          f"all {wall:.2f} s), dt = {res.dt * 1e3:g} ms"
          f"{f', one sample in {res.record_every} recorded' if res.record_every > 1 else ''}"
          f", {res.method}")
    print(res.table())
    written, failure = [], None
    try:
        written.append(res.to_csv(os.path.join(args.out, "rig_history.csv")))
        from ._optional import require
        # files only: no window, whatever the environment's default backend
        require("matplotlib", "rollerrig simulate's figures", "plot").use("Agg")
        from .plot import plot_run
        written += plot_run(res, args.out)
    except OSError as e:
        failure = (f"--out {args.out}: cannot write the outputs"
                   f"{f' ({e.filename})' if e.filename else ''}: {e.strerror or e}")
    except ImportError as e:
        print(f"{PROG}: no figures: {e}", file=sys.stderr)
    for path in written:
        print(f"wrote {path}")
    if failure:
        print(f"{PROG}: {failure}", file=sys.stderr)
        return 2
    if res.status < 0:
        print(f"{PROG}: {res.message}", file=sys.stderr)
        return 1
    if res.status > 0:
        print(f"{PROG}: warning: {res.message}", file=sys.stderr)
    return 0


def _unprefixed(message):
    """A message of rollerrig.simulate without its "simulate: " (the command
    line names itself)."""
    text = str(message)
    return text[len("simulate: "):] if text.startswith("simulate: ") else text


def _positive_int(text):
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be an integer >= 1, got {text!r}") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be an integer >= 1, got {text!r}")
    return value


def _shape(text):
    try:
        shape = tuple(int(v) for v in text.split(","))
    except ValueError:
        shape = ()
    if len(shape) != 4 or min(shape) < 4:
        raise argparse.ArgumentTypeError(f"four node counts >= 4 like 17,11,19,21, got {text!r}")
    return shape


def _exact_table(args):
    from ._errors import RollerRigError
    from .exact_table import DEFAULT_SHAPE, build_exact_table
    client = None
    if args.dask:
        try:
            import distributed
        except ImportError:
            print("rollerrig exact-table: --dask needs dask.distributed "
                  '(pip install "rollerrig[distributed]")', file=sys.stderr)
            return 2
        client = distributed.Client(args.dask)
    try:
        table = build_exact_table(args.shape or DEFAULT_SHAPE, nu=args.nu, nx=args.nx,
                                  workers=args.workers, client=client,
                                  progress=not args.quiet)
    except RollerRigError as e:
        print(f"rollerrig exact-table: {e}", file=sys.stderr)
        return 2
    finally:
        if client is not None:
            client.close()
    table.write_c(args.out)
    if args.npz:
        table.save(args.npz)
    print(f"wrote {args.out}: {'x'.join(map(str, table.shape))} nodes, nu = {table.nu}, "
          f"exact theory from {table.nx} and {2 * table.nx} elements across")
    return 0


def _fmu(args):
    from .fmu import build_fmu
    from ._errors import RollerRigError
    try:
        build_fmu(args.out, scenario=args.scenario, fmi_version=args.fmi, quiet=False)
    except RollerRigError as e:
        text = str(e)
        print(text if text.startswith("rollerrig fmu") else f"rollerrig fmu: {text}",
              file=sys.stderr)
        return 2
    except OSError as e:
        print(f"rollerrig fmu: cannot write {args.out}: {e.strerror or e}", file=sys.stderr)
        return 2
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
                       "write the time histories (CSV) and the figures (PNG).  Exit status "
                       "0: done, 1: the run stopped early, 2: bad input.")
    p.add_argument("--scenario", metavar="TOML", help="parameter file overriding the defaults "
                   "(the layout of rollerrig/data/rig_default.toml; any subset of it)")
    p.add_argument("--duration", type=float, help="simulated time [s] (default the "
                   "scenario's duration_s, 20); the scenario's target start times are kept "
                   "when they fall inside it, otherwise scaled to it (with a warning)")
    p.add_argument("--dt", type=float, help="control sample time and step [s] (default 0.004)")
    p.add_argument("--method", help="creep-force method: fastsim, fastsim_blended, "
                   "modified_fastsim, polach, linear")
    p.add_argument("--record-every", type=_positive_int, default=1, metavar="K",
                   help="record every K-th sample only (long runs: the records are capped "
                   "at 1 GiB)")
    p.add_argument("--out", default="rollerrig-out", help="output folder, created if needed "
                   "(default ./rollerrig-out); its rig_history.csv, rig_creepage.png and "
                   "rig_force.png are replaced")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(func=_simulate)
    p = sub.add_parser("exact-table", help="build the exact-theory table (method exact_table)",
                       description="Build the table of method exact_table with the library's "
                       "exact theory (rollerrig/exact_table.py) and write it as C source; "
                       "the shipped one is csrc/contact/rr_exact_table_data.c (reinstall to "
                       "use a new one).  About 40 CPU minutes at the defaults.")
    p.add_argument("out", help="the C file to write")
    p.add_argument("--shape", type=_shape, default=None,
                   help="nodes along log(a/b), alpha, theta, u (default the shipped "
                   "table's, 21,13,23,21)")
    p.add_argument("--nu", type=float, default=0.28, help="Poisson's ratio (default 0.28)")
    p.add_argument("--nx", type=_positive_int, default=27, help="elements across of the "
                   "coarser grid of the Richardson pair (default 27: 27 and 54)")
    p.add_argument("--workers", type=_positive_int, help="threads (default: all cores)")
    p.add_argument("--dask", metavar="ADDRESS", help="build on the Dask scheduler at ADDRESS")
    p.add_argument("--npz", metavar="FILE", help="also save the table as .npz")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(func=_exact_table)
    p = sub.add_parser("fmu", help="write an FMI co-simulation unit (FMU) of the rig",
                       description="Write an FMI 2.0 or 3.0 co-simulation FMU of the rig: its "
                       "modelDescription.xml (every parameter, the control modes, inputs and "
                       "outputs), a binary for this platform compiled with the system C "
                       "compiler ($CC, cc, gcc or clang) and the C sources.  With its default "
                       "inputs it runs the scenario as rollerrig simulate does.  Exit status "
                       "0: written, 2: bad input or no compiler (a message on stderr).")
    p.add_argument("out", metavar="OUT.fmu", help="the FMU to write (replaced if it exists); "
                   "its name gives the modelIdentifier")
    p.add_argument("--scenario", metavar="TOML", help="parameter file overriding the defaults "
                   "(the layout of rollerrig/data/rig_default.toml): the FMU's start values")
    p.add_argument("--fmi", type=int, choices=(2, 3), default=2,
                   help="FMI version: 2 (FMI 2.0, the default) or 3 (FMI 3.0)")
    p.set_defaults(func=_fmu)
    return parser


def main(argv=None):
    parser = build_parser()
    args = parser.parse_args(argv)
    func = getattr(args, "func", None)
    if func is None:
        parser.print_help()
        return 0
    try:
        return func(args)
    except BrokenPipeError:
        # the reader of stdout went away (rollerrig simulate | head): no
        # traceback; stdout to devnull so that the exit's flush stays quiet
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1


if __name__ == "__main__":
    sys.exit(main())
