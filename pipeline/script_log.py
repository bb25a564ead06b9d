"""A Snakemake script's output in its log file, and its failure on the console in one line.

Scripts used to point ``sys.stderr`` at the log file and leave it there: when the script
failed, Python printed the traceback after the file was closed, and the user saw only
"lost sys.stderr". :func:`logged` restores both streams, writes the traceback to the log and
the error itself, with the log's path, to the console.

The workflow keeps the previous version of every output while its job runs and restores it if
the job fails (``kept`` in ``pipeline/rules/common.smk``: Snakemake's ``update`` flag), so an
output a script forgot to write would look fresh. ``logged(log, written=outputs)`` fails the
job when one of ``outputs`` was not replaced (same inode and modification time as before) or
is missing at the end.

>>> import io, tempfile, pathlib
>>> log = pathlib.Path(tempfile.mkdtemp()) / "x.log"
>>> with logged(log):
...     print("into the log")
>>> log.read_text()
'into the log\\n'
>>> out = log.with_name("out.txt")
>>> with logged(log, written=[out]):
...     pass
Traceback (most recent call last):
...
SystemExit: 1
"""

from __future__ import annotations

import contextlib
import os
import sys
import traceback
from collections.abc import Iterable, Iterator
from pathlib import Path
from typing import TextIO

__all__ = ["logged"]


def _state(path: Path) -> tuple[int, int] | None:
    try:
        st = os.stat(path)
    except FileNotFoundError:
        return None
    return st.st_ino, st.st_mtime_ns


def not_written(before: dict[Path, tuple[int, int] | None]) -> list[str]:
    """The paths of ``before`` (path -> state before the job) missing now or not replaced."""
    return [str(p) for p, old in before.items() if (new := _state(p)) is None or new == old]


@contextlib.contextmanager
def logged(path: str | Path, written: Iterable[str | Path] = ()) -> Iterator[TextIO]:
    """stdout and stderr into ``path`` while the block runs (it gets the open log); on an
    exception, its traceback into the log, ``error: <message> (details: <path>)`` on the
    console, and exit status 1. ``written``: outputs the block must replace (or create)."""
    out, err = sys.stdout, sys.stderr
    before = {Path(p): _state(Path(p)) for p in written}
    with open(path, "w", encoding="utf-8") as log:
        sys.stdout = sys.stderr = log
        try:
            yield log
            stale = not_written(before)
            if stale:
                raise SystemExit(
                    f"the step did not write its output(s) {', '.join(stale)} (the previous "
                    "version, if any, is kept)"
                )
        except SystemExit as exc:
            if exc.code in (0, None):
                raise
            message = str(exc.code)
            print(message, file=log)
            failure = message
        except Exception as exc:  # noqa: BLE001 - reported, then the script exits 1
            traceback.print_exc(file=log)
            failure = f"{type(exc).__name__}: {exc}"
        else:
            return
        finally:
            sys.stdout, sys.stderr = out, err
    print(f"error: {failure} (details: {path})", file=sys.stderr)
    raise SystemExit(1)
