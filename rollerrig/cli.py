"""Command-line entry point for ``rollerrig`` (subcommands to be added)."""
import argparse
import sys

from ._version import __version__


def build_parser():
    parser = argparse.ArgumentParser(
        prog="rollerrig",
        description="Real-time simulation of a scaled railway roller rig.",
    )
    parser.add_argument(
        "--version", action="version", version="%(prog)s " + __version__
    )
    # Subcommands are registered on this object as they are implemented;
    # each sets ``func`` via ``set_defaults(func=handler)``, where
    # ``handler(args)`` returns an exit code.
    parser.add_subparsers(dest="command", metavar="COMMAND")
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
