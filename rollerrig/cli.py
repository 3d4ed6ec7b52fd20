"""Command-line entry point: ``rollerrig simulate``, ``rollerrig fmu``,
``rollerrig exact-table``, ``rollerrig stability`` (also ``python -m
rollerrig``).

Exit status: 0 the run finished (its warnings, if any, on stderr), 1 the
run stopped early (its outputs are still written), 2 bad input (one message
on stderr naming the option or the path, no traceback, nothing run or
written).  Every output path is checked before the work
(rollerrig._files.check_output): a regular file or a new path only, never
through a symbolic link, never a directory, a device or a FIFO.
"""
from __future__ import annotations

import argparse
import os
import re
import sys
import time
import warnings
from typing import (TYPE_CHECKING, Any, Callable, Dict, List, Mapping, NoReturn, Optional, Sequence,
                    Tuple, Union, cast)

from ._errors import RollerRigError, RollerRigWarning
from ._files import OutputPathError, PathArg, check_output, make_folder
from ._typing import F64Array
from ._version import __version__

if TYPE_CHECKING:
    from .rig.result import RigResult

PROG = "rollerrig simulate"

#: simulate's keywords and the options that set them: an error about one names the option
_OPTION_OF = {"duration": "--duration", "dt": "--dt", "method": "--method",
              "record_every": "--record-every"}


class _Refused(Exception):
    """Bad input: the message for stderr, exit status 2."""


class _Parser(argparse.ArgumentParser):
    """argparse's parser whose errors are one line "<prog>: <message>",
    exit status 2, without the usage block (main prints the line)."""

    commands: Dict[str, "_Parser"]      #: name -> the command's parser (build_parser's)

    def error(self, message: str) -> NoReturn:
        raise _Refused(f"{self.prog}: {message}")


def _prepare_out(path: str) -> Optional[str]:
    """Create the output folder (and prove it is a directory) before
    anything is run; returns the outermost folder it made (None if it was
    there), for _unmake."""
    made: Optional[str] = None
    up = os.path.abspath(path)
    while not os.path.lexists(up):
        made, up = up, os.path.dirname(up)
    try:
        make_folder(path, what="--out")
    except OutputPathError as e:
        raise _Refused(str(e)) from None
    return made


def _unmake(path: str, made: Optional[str]) -> None:
    """Remove the folders _prepare_out made for a run that was refused
    (only while empty): bad input leaves nothing behind."""
    if made is None:
        return
    folder = os.path.abspath(path)
    while os.path.commonpath([folder, made]) == made:
        try:
            os.rmdir(folder)
        except OSError:
            return
        folder = os.path.dirname(folder)


def _checked_output(path: PathArg, what: str, suffix: Optional[str] = None) -> str:
    try:
        return check_output(path, what=what, suffix=suffix)
    except OutputPathError as e:
        raise _Refused(str(e)) from None


def _load_scenario(path: Optional[str], method: Optional[str] = None,
                   patch: Optional[str] = None) -> Optional[Dict[str, Dict[str, Any]]]:
    """The scenario file's parameters, checked as rollerrig.fmu.check_scenario
    does for both commands: every problem at once, then the rig built from
    them (with --method, --patch if given)."""
    from .fmu import check_scenario
    if path is None and patch is None:
        return None
    try:
        return check_scenario(path, source="--scenario" if path else "--patch", method=method,
                              patch=patch)[0]
    except RollerRigError as e:
        raise _Refused(str(e)) from None


def _figures() -> Optional[str]:
    """None when the figures can be drawn (files only: no window, whatever
    the environment's default backend), else why not."""
    from ._optional import require
    try:
        require("matplotlib", "rollerrig simulate's figures", "plot").use("Agg")
    except ImportError as e:
        return str(e)
    return None


def _simulate(args: argparse.Namespace) -> int:
    from .rig.run import simulate

    no_figures = _figures()
    names = ["rig_history.csv"] + ([] if no_figures else ["rig_creepage.png", "rig_force.png"])
    paths = [os.path.join(args.out, name) for name in names]
    made: Optional[str] = None
    kw = {"method": args.method} if args.method else {}
    t0 = time.perf_counter()
    res: Optional[RigResult] = None
    error: Optional[RollerRigError] = None
    # the scenario's warnings and the run's, printed once each if it runs
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", RollerRigWarning)
        try:
            params = _load_scenario(args.scenario, args.method, args.patch)
            made = _prepare_out(args.out)
            for path in paths:
                _checked_output(path, "--out")
        except _Refused as e:
            _unmake(args.out, made)
            print(f"{PROG}: {e}", file=sys.stderr)
            return 2
        try:
            res = simulate(duration=args.duration, dt=args.dt, params=params,
                           record_every=args.record_every,
                           progress=None if not args.quiet and sys.stderr.isatty() else False, **kw)
        except RollerRigError as e:
            error = e
        if res is not None and args.scenario is not None:
            from .rig.result import scenario_record
            res.scenario = scenario_record(args.scenario)  # for the CSV's header
    if error is not None:                  # nothing was run: its warnings are moot
        _unmake(args.out, made)
        print(f"{PROG}: {_as_option(error)}", file=sys.stderr)
        return 2
    assert res is not None                 # simulate returned: error is None
    _print_warnings(PROG, caught, _as_option)
    wall = time.perf_counter() - t0
    assert res.wall is not None            # a run's: simulate times it
    run = res.wall["run"]
    print(f"rollerrig {__version__}: {res.duration:g} s simulated in {run:.3f} s "
          f"(real-time factor {res.duration / run:.0f}; set-up {res.wall['setup']:.3f} s, "
          f"all {wall:.2f} s), dt = {res.dt * 1e3:g} ms"
          f"{f', one sample in {res.record_every} recorded' if res.record_every > 1 else ''}"
          f", {res.method}")
    print(res.table())
    written: List[Union[str, "os.PathLike[str]"]] = []
    failure: Optional[str] = None
    try:
        written.append(res.to_csv(paths[0]))
        if not no_figures:
            from .plot import plot_run
            written += plot_run(res, args.out)
    except OutputPathError as e:           # checked again: something was put there meanwhile
        failure = f"--out {e.path}: {e.reason}"
    except OSError as e:
        failure = (f"--out {e.filename or args.out}: cannot write it: "
                   f"{e.strerror or e}")
    if no_figures:
        print(f"{PROG}: no figures: {no_figures}", file=sys.stderr)
    for done in written:
        print(f"wrote {done}")
    if failure:
        print(f"{PROG}: {failure}", file=sys.stderr)
        return 2
    if res.status < 0:
        print(f"{PROG}: {res.message}", file=sys.stderr)
        return 1
    if res.status > 0:
        print(f"{PROG}: warning: {res.message}", file=sys.stderr)
    return 0


def _as_option(message: object, prefix: str = "simulate: ",
               options: Mapping[str, str] = _OPTION_OF) -> str:
    """A message of rollerrig.simulate as the command line's: without its
    "simulate: " (the command names itself), the keyword it is about
    named as the option the user typed (duration -> --duration)."""
    text = str(message)
    text = text[len(prefix):] if text.startswith(prefix) else text
    # the message's first word, and each listed problem's ("N problems:\n  dt = ...")
    return re.sub(r"^(  )?(\w+)", lambda m: (m[1] or "") + options.get(m[2], m[2]), text,
                  flags=re.M)


def _positive_int(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be an integer >= 1, got {text!r}") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be an integer >= 1, got {text!r}")
    return value


def _shape(text: str) -> Tuple[int, ...]:
    try:
        shape = tuple(int(v) for v in text.split(","))
    except ValueError:
        shape = ()
    if len(shape) != 4 or min(shape) < 4:
        raise argparse.ArgumentTypeError(f"four node counts >= 4 like 17,11,19,21, got {text!r}")
    return shape


def _nu(text: str) -> float:
    try:
        value: Optional[float] = float(text)
    except ValueError:
        value = None
    if value is None or not 0.0 <= value <= 0.5:
        raise argparse.ArgumentTypeError(f"Poisson's ratio must be in [0, 0.5], got {text!r}")
    return value


def _pair_nx(text: str) -> int:
    """--nx: the coarser grid of the Richardson pair; the finer one, 2 nx,
    within the exact solver's range (the registry's), checked before the build."""
    from ._binding import METHODS
    hi = METHODS["exact"].options["nx"].hi
    assert hi is not None                  # an int option has a range
    most = hi // 2
    value = _positive_int(text)
    if value > most:
        raise argparse.ArgumentTypeError(f"must be an integer from 1 to {most} (the finer grid "
                                         f"of the pair, 2 nx, at most {2 * most}), got {text!r}")
    return value


def _dask_client(address: str) -> Any:
    """A client of the Dask scheduler at `address`, or _Refused naming it:
    reached first by a bare connection (within dask's connect timeout,
    distributed.comm.timeouts.connect), so that a scheduler that cannot be
    reached is one line, not a client's traceback."""
    try:
        import asyncio
        import importlib
        # optional and untyped: imported as modules, their names Any
        distributed = importlib.import_module("distributed")
        connect = importlib.import_module("distributed.comm").connect
    except ImportError:
        raise _Refused(f"--dask {address}: needs dask.distributed "
                       f'(pip install "rollerrig[distributed]")') from None

    async def reach() -> None:
        comm = await connect(address)
        await comm.close()
    try:
        asyncio.run(reach())
        return distributed.Client(address)
    except (OSError, ValueError, TypeError) as e:
        raise _Refused(f"--dask {address}: cannot reach the scheduler: {e}") from None


def _exact_table(args: argparse.Namespace) -> int:
    from .analysis.exact_table import DEFAULT_SHAPE, build_exact_table
    name = "rollerrig exact-table"
    client = None
    try:
        _checked_output(args.out, "", suffix=".c")
        if args.npz is not None:
            _checked_output(args.npz, "--npz", suffix=".npz")
        if args.dask is not None:
            client = _dask_client(args.dask)
    except _Refused as e:
        print(f"{name}: {e}", file=sys.stderr)
        return 2
    try:
        table = build_exact_table(args.shape or DEFAULT_SHAPE, nu=args.nu, nx=args.nx,
                                  workers=args.workers, client=client,
                                  progress=None if not args.quiet else False)
    except RollerRigError as e:
        print(f"{name}: {_as_option(e, 'build_exact_table: ', {'nx': '--nx'})}",
              file=sys.stderr)
        return 2
    finally:
        if client is not None:
            client.close()
    failed: List[str] = []                 # each output tried: one lost keeps the other
    for write, path in ((table.save, args.npz), (table.write_c, args.out)):
        try:
            if path is not None:
                write(path)
        except OutputPathError as e:       # checked again: something was put there meanwhile
            failed.append(f"{e.path}: {e.reason}")
        except OSError as e:
            failed.append(f"{e.filename or path}: cannot write it: {e.strerror or e}")
    if failed:
        print(f"{name}: {'; '.join(failed)}", file=sys.stderr)
        return 2
    print(f"wrote {args.out}: {'x'.join(map(str, table.shape))} nodes, nu = {table.nu}, "
          f"exact theory from {table.nx} and {2 * table.nx} elements across"
          f"{f'; and {args.npz}' if args.npz is not None else ''}")
    return 0


def _print_warnings(prog: str, caught: Sequence[warnings.WarningMessage],
                    text: Callable[[Union[Warning, str]], str] = str) -> None:
    """The RollerRigWarnings caught, each once, one line "<prog>: warning: ..."."""
    for message in dict.fromkeys(text(w.message) for w in caught):
        print(f"{prog}: warning: {message}", file=sys.stderr)


def _fmu(args: argparse.Namespace) -> int:
    from .fmu import build_fmu
    name = "rollerrig fmu"
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", RollerRigWarning)
        try:
            _checked_output(args.out, "", suffix=".fmu")
            _load_scenario(args.scenario)
        except _Refused as e:
            print(f"{name}: {e}", file=sys.stderr)
            return 2
    _print_warnings(name, caught)
    try:
        with warnings.catch_warnings():       # the same scenario, checked again: said above
            warnings.simplefilter("ignore", RollerRigWarning)
            build_fmu(args.out, scenario=args.scenario, fmi_version=args.fmi, quiet=False)
    except OutputPathError as e:           # checked again: something was put there meanwhile
        print(f"{name}: {e.path}: {e.reason}", file=sys.stderr)
        return 2
    except RollerRigError as e:            # no compiler, a failed compile
        text = str(e)
        print(text if text.startswith(name) else f"{name}: {text}", file=sys.stderr)
        return 2
    except OSError as e:
        print(f"{name}: {e.filename or args.out}: cannot write it: {e.strerror or e}",
              file=sys.stderr)
        return 2
    return 0


# ------------------------------------------------ rollerrig stability (issue 25)

def _speed_range(text: str) -> F64Array:
    """--speeds LO:HI:N (N speeds from LO to HI [m/s], evenly) or a comma list."""
    import numpy as np
    speeds: F64Array
    try:
        if ":" in text:
            lo, hi, n = text.split(":")
            speeds = np.linspace(float(lo), float(hi), int(n))
        else:
            speeds = np.array([float(v) for v in text.split(",")])
    except ValueError:
        speeds = np.zeros(0)
    if speeds.size == 0 or not np.all(np.isfinite(speeds)) or np.any(speeds <= 0) \
            or np.any(np.diff(speeds) <= 0):
        raise argparse.ArgumentTypeError(f"increasing speeds > 0 [m/s] as LO:HI:N or "
                                         f"v1,v2,..., got {text!r}")
    return speeds


def _stability(args: argparse.Namespace) -> int:
    from .analysis.stability import Mode, stability
    name = "rollerrig stability"
    try:
        st = stability(args.speeds, args.scenario, track=args.track)
    except RollerRigError as e:
        text = str(e).replace("stability: speeds", "--speeds").replace("stability: params",
                                                                        "--scenario")
        print(text if text.startswith(name) else f"{name}: {text}", file=sys.stderr)
        return 2
    where = "track" if st.track else "rollers"
    print(f"# the plant's modes against speed on the {where} (rollerrig.stability)")
    print(f"{'speed [m/s]':>12} {'max Re [1/s]':>14} {'min damping':>12} "
          f"{'least damped [Hz]':>18}")
    for V, mr, md, modes in zip(st.speeds, st.max_real, st.min_damping, st.modes):
        top = next((m for m in modes if not m.neutral), None)
        print(f"{V:12.4g} {mr:14.6g} {md:12.5g} "
              f"{top.frequency_hz if top else float('nan'):18.5g}")
    if st.critical_speed == st.critical_speed:
        m = cast(Mode, st.critical_mode)   # the Mode at a critical speed (not NaN)
        print(f"critical speed: {st.critical_speed:.6g} m/s ({m.frequency_hz:.4g} Hz, "
              f"{', '.join(m.dominant)})")
    else:
        print(f"critical speed: none in {st.speeds[0]:g} to {st.speeds[-1]:g} m/s")
    return 0


def _add_stability(sub: "argparse._SubParsersAction[_Parser]") -> None:
    p = sub.add_parser("stability", help="the wheelset's eigenvalues and critical speed",
                       description="Linearise the rig's plant at its steady state at each "
                       "speed (rollerrig.stability; docs/lateral_dynamics.md), print the "
                       "largest real part, the least damping ratio and the least damped "
                       "mode's frequency per speed, and the linear critical speed.  Exit "
                       "status 0: done, 2: bad input.")
    p.add_argument("--speeds", type=_speed_range, default=_speed_range("5:100:20"),
                   metavar="LO:HI:N", help="roller (or track) speeds [m/s]: N from LO to HI, "
                   "or a comma list (default 5:100:20)")
    p.add_argument("--track", action="store_true", help="the same wheelset on tangent track")
    p.add_argument("--scenario", metavar="TOML", help="parameter file overriding the defaults")
    p.set_defaults(func=_stability)


def build_parser() -> _Parser:
    from ._binding import METHODS
    rig_methods = [name for name, m in METHODS.items() if m.in_rig]
    parser = _Parser(
        prog="rollerrig",
        description="Real-time simulation of a scaled railway roller rig.",
    )
    parser.add_argument("--version", action="version", version="%(prog)s " + __version__)
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    parser.commands = sub.choices          # name -> the command's parser
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
    p.add_argument("--method", choices=rig_methods, metavar="METHOD",
                   help=f"creep-force method of the rig: {', '.join(rig_methods)} "
                   f"(default the scenario's contact.creep_method)")
    p.add_argument("--patch", choices=("hertz", "nonhertz"), help="the contact's patch "
                   "(contact.patch; default the scenario's, hertz): nonhertz builds the "
                   "non-Hertzian contact's table of the rig's pair first (about 30 s on 2 "
                   "cores) unless contact.nonhertz_table names a saved one")
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
                       "exact theory (rollerrig/analysis/exact_table.py) and write it as C source; "
                       "the shipped one is csrc/contact/rr_exact_table_data.c (reinstall to "
                       "use a new one).  About 40 CPU minutes at the defaults.")
    p.add_argument("out", metavar="OUT.c", help="the C file to write (a new path or a "
                   "regular file, replaced; checked before the build)")
    p.add_argument("--shape", type=_shape, default=None,
                   help="nodes along log(a/b), alpha, theta, u (default the shipped "
                   "table's, 21,13,23,21)")
    p.add_argument("--nu", type=_nu, default=0.28, help="Poisson's ratio (default 0.28)")
    p.add_argument("--nx", type=_pair_nx, default=27, help="elements across of the "
                   "coarser grid of the Richardson pair (default 27: 27 and 54)")
    p.add_argument("--workers", type=_positive_int, help="threads (default: all cores)")
    p.add_argument("--dask", metavar="ADDRESS", help="build on the Dask scheduler at ADDRESS")
    p.add_argument("--npz", metavar="FILE.npz", help="also save the table as .npz (written "
                   "first)")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(func=_exact_table)
    p = sub.add_parser("fmu", help="write an FMI co-simulation unit (FMU) of the rig",
                       description="Write an FMI 2.0 or 3.0 co-simulation FMU of the rig: its "
                       "modelDescription.xml (every parameter, the control modes, inputs and "
                       "outputs), a binary for this platform compiled with the system C "
                       "compiler ($CC, cc, gcc or clang) and the C sources.  With its default "
                       "inputs it runs the scenario as rollerrig simulate does.  Exit status "
                       "0: written, 2: bad input or no compiler (a message on stderr).")
    p.add_argument("out", metavar="OUT.fmu", help="the FMU to write: a new path or a regular "
                   "file, replaced; its name gives the modelIdentifier")
    p.add_argument("--scenario", metavar="TOML", help="parameter file overriding the defaults "
                   "(the layout of rollerrig/data/rig_default.toml): the FMU's start values")
    p.add_argument("--fmi", type=int, choices=(2, 3), default=2,
                   help="FMI version: 2 (FMI 2.0, the default) or 3 (FMI 3.0)")
    p.set_defaults(func=_fmu)
    _add_stability(sub)
    return parser


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Run the command line with `argv` (default sys.argv[1:]); returns the
    exit status (0, 1 or 2; --help and --version exit through SystemExit)."""
    parser = build_parser()
    try:
        args, extra = parser.parse_known_args(argv)
        if extra:                          # named by the command's own parser
            parser.commands.get(args.command, parser).error(
                f"unrecognized arguments: {' '.join(extra)}")
    except _Refused as e:
        print(e, file=sys.stderr)
        return 2
    func = getattr(args, "func", None)
    if func is None:
        parser.print_help()
        return 0
    try:
        status: int = func(args)
        return status
    except BrokenPipeError:
        # the reader of stdout went away (rollerrig simulate | head): no
        # traceback; stdout to devnull so that the exit's flush stays quiet
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1


if __name__ == "__main__":
    sys.exit(main())
