"""``inertial-repro``: one command for running the papers' methods on your own data.

Each paper package that offers subcommands declares them in a light ``commands.py`` (a
``COMMANDS`` dict of :class:`Command`, importing nothing but this module), found on disk like
the paper plug-ins themselves; this dispatcher names no paper. It parses only the subcommand
name: the subcommand's module (and numpy, pandas, ...) is imported only when that subcommand
runs, so ``inertial-repro --help`` stays cheap. Everything after the subcommand name goes to
that module's ``main(argv, prog)``, whose ``--help`` documents the input format.

>>> c = Command("pkg.mod", "what it does")
>>> c.module, c.summary
('pkg.mod', 'what it does')
>>> build_parser({"demo": c}).parse_args(["demo", "in.csv", "--out", "o.csv"]).args
['in.csv', '--out', 'o.csv']
>>> build_parser({"demo": c}).format_usage()
'usage: inertial-repro [-h] SUBCOMMAND ...\\n'
"""

from __future__ import annotations

import argparse
import importlib
import sys
import textwrap
from dataclasses import dataclass
from pathlib import Path

__all__ = ["Command", "PROG", "build_parser", "commands", "main"]

PROG = "inertial-repro"
PACKAGE = Path(__file__).resolve().parent


@dataclass(frozen=True)
class Command:
    """A subcommand: the module whose ``main(argv, prog)`` runs it, and a one-line summary."""

    module: str
    summary: str


def commands() -> dict[str, Command]:
    """Every paper package's ``commands.COMMANDS``, in package order; a name used twice is an error.

    >>> all(isinstance(c, Command) for c in commands().values())
    True
    """
    found: dict[str, Command] = {}
    for path in sorted(PACKAGE.glob("*/commands.py")):
        module = importlib.import_module(f"{__package__}.{path.parent.name}.commands")
        for name, command in module.COMMANDS.items():
            if name in found:
                raise RuntimeError(f"subcommand {name!r} declared twice (again in {path})")
            found[name] = command
    return found


def build_parser(table: dict[str, Command]) -> argparse.ArgumentParser:
    """The top-level parser: a subcommand name of ``table``, then the subcommand's arguments."""
    width = max(map(len, table), default=0)
    listing = "\n".join(
        textwrap.fill(
            c.summary,
            width=92,
            initial_indent=f"  {name:<{width}}  ",
            subsequent_indent=" " * (width + 4),
        )
        for name, c in table.items()
    )
    first = next(iter(table), "SUBCOMMAND")
    parser = argparse.ArgumentParser(
        prog=PROG,
        description=f"Run the reproduced papers' methods on your own data.\n\n"
        f"subcommands:\n{listing}",
        epilog=f"'{PROG} SUBCOMMAND --help' documents that subcommand's input format, frames "
        f"and units,\nwith a worked example (for example '{PROG} {first} --help').",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument(
        "command", metavar="SUBCOMMAND", choices=list(table), help=f"one of: {', '.join(table)}"
    )
    parser.add_argument("args", nargs=argparse.REMAINDER, help="arguments of the subcommand")
    return parser


def main(argv: list[str] | None = None) -> int:
    """Parse the subcommand name and hand the rest of ``argv`` to its module's ``main``.

    An unknown subcommand (or none) is a usage error: exit status 2, the usage on stderr.
    """
    argv = sys.argv[1:] if argv is None else list(argv)
    table = commands()
    args = build_parser(table).parse_args(argv)
    module = importlib.import_module(table[args.command].module)
    return int(module.main(args.args, prog=f"{PROG} {args.command}"))


if __name__ == "__main__":
    raise SystemExit(main())
