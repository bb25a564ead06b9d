"""Command-line helpers of the subcommands (``inertial-repro flight-log``, ``north-finding``):
bounded number options, one-line argparse errors and the ``--out`` check (made before any
compute).

>>> number("--gravity", 9.7, 9.9, True)("9.81")
9.81
>>> number("--gravity", 9.7, 9.9, True)("nan")
Traceback (most recent call last):
...
argparse.ArgumentTypeError: --gravity = 'nan': must be a number in (9.7, 9.9]
"""

from __future__ import annotations

import argparse
import math
import os
import re
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any, NoReturn

__all__ = ["Parser", "count", "number", "option", "out_problem"]


def number(
    name: str, lo: float, hi: float, lo_open: bool = False, hi_open: bool = False
) -> Callable[[str], float]:
    """An argparse type: a finite number in [lo, hi] (open at ``lo`` if lo_open, at ``hi`` if
    hi_open), named in errors."""
    interval = f"{'(' if lo_open else '['}{lo:g}, {hi:g}{')' if hi_open else ']'}"

    def parse(text: str) -> float:
        try:
            value = float(text)
        except ValueError:
            value = math.nan
        ok = (
            math.isfinite(value)
            and (value > lo if lo_open else value >= lo)
            and (value < hi if hi_open else value <= hi)
        )
        if not ok:
            raise argparse.ArgumentTypeError(f"{name} = {text!r}: must be a number in {interval}")
        return value

    return parse


def count(name: str, lo: int, hi: int) -> Callable[[str], int]:
    """An argparse type: a whole number in [lo, hi], named in errors.

    >>> count("--trial", 0, 10**6)("1e8")
    Traceback (most recent call last):
    ...
    argparse.ArgumentTypeError: --trial = '1e8': must be a whole number in [0, 1000000]
    """

    def parse(text: str) -> int:
        try:
            value = int(text.strip())
        except ValueError:
            value = None
        if value is None or not lo <= value <= hi:
            raise argparse.ArgumentTypeError(
                f"{name} = {text!r}: must be a whole number in [{lo}, {hi}]"
            )
        return value

    return parse


def option(
    parser: Any, name: str, lo: float, hi: float, help: str, lo_open: bool = True, **kw: Any
) -> None:
    parser.add_argument(name, type=number(name, lo, hi, lo_open), help=help, **kw)


class Parser(argparse.ArgumentParser):
    """argparse with one-line errors: ``error: --option = 'value': what is allowed``."""

    def error(self, message: str) -> NoReturn:  # type: ignore[override]
        message = re.sub(r"^argument ([^:]+): (?=\1 = )", "", message)
        message = re.sub(r"^argument ([^:]+): ", r"\1: ", message)
        if message.startswith("unrecognized arguments"):
            known = sorted({s for a in self._actions for s in a.option_strings if s != "-h"})
            message += f"; allowed options: {', '.join(known)}"
        print(f"error: {message} (see --help)", file=sys.stderr)
        raise SystemExit(2)


def out_problem(out: Path, log: Path, what: str = "the input log") -> str | None:
    """Why ``out`` cannot be written, or None (checked before any compute); ``log`` is the
    input it must not overwrite (``what`` names it)."""
    if out.is_dir():
        return f"--out = {out}: is a directory; give the CSV file to write"
    if out.exists() and log.exists() and out.resolve() == log.resolve():
        return f"--out = {out}: is {what}; give another file"
    parent = out.parent
    while not parent.exists() and parent != parent.parent:
        parent = parent.parent
    if not parent.is_dir():
        return f"--out = {out}: {parent} is not a directory"
    if not os.access(parent, os.W_OK | os.X_OK) or (out.exists() and not os.access(out, os.W_OK)):
        return f"--out = {out}: not writable (no write permission in {parent})"
    return None
