"""A Snakemake script's output in its log file, and its failure on the console in one line.

Scripts used to point ``sys.stderr`` at the log file and leave it there: when the script
failed, Python printed the traceback after the file was closed, and the user saw only
"lost sys.stderr". :func:`logged` restores both streams, writes the traceback to the log and
the error itself, with the log's path, to the console.

>>> import io, tempfile, pathlib
>>> log = pathlib.Path(tempfile.mkdtemp()) / "x.log"
>>> with logged(log):
...     print("into the log")
>>> log.read_text()
'into the log\\n'
"""

from __future__ import annotations

import contextlib
import sys
import traceback
from collections.abc import Iterator
from pathlib import Path

__all__ = ["logged"]


@contextlib.contextmanager
def logged(path: str | Path) -> Iterator[None]:
    """stdout and stderr into ``path`` while the block runs; on an exception, its traceback
    into the log, ``error: <message> (details: <path>)`` on the console, and exit status 1."""
    out, err = sys.stdout, sys.stderr
    with open(path, "w", encoding="utf-8") as log:
        sys.stdout = sys.stderr = log
        try:
            yield
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
