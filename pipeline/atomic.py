"""Atomic writes: a reader never sees a half-written results file.

Each writer puts the content in a temporary file in the destination directory
and renames it over the target (``os.replace`` is atomic on POSIX).

numpy and pandas are imported by the CSV writer only (:func:`write_csv`): a step that writes
text, bytes or JSON does not pay for them (~0.6 s of CPU per process), nor does one that writes
a table of strings (:func:`write_text_csv`, the bytes ``write_csv`` writes for it).
"""

from __future__ import annotations

import csv
import io
import json
import os
import tempfile
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    import pandas as pd

__all__ = [
    "write_atomic",
    "write_text",
    "write_bytes",
    "write_csv",
    "write_csv_parts",
    "write_text_csv",
    "write_json",
]


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def write_atomic(path: str | os.PathLike[str], write: Callable[[Path], None]) -> Path:
    """Call ``write(tmp_path)``, fsync, and rename the temporary file to ``path``.

    The file gets the permissions a plain ``open(path, "w")`` would (0666 minus umask).
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    os.close(fd)
    try:
        write(Path(tmp))
        with open(tmp, "rb") as fh:
            os.fsync(fh.fileno())
        os.chmod(tmp, 0o666 & ~_umask())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def write_text(path: str | os.PathLike[str], text: str) -> Path:
    """Write a text file atomically."""
    return write_atomic(path, lambda p: p.write_text(text, encoding="utf-8"))


def write_bytes(path: str | os.PathLike[str], data: bytes) -> Path:
    """Write a binary file atomically."""
    return write_atomic(path, lambda p: p.write_bytes(data))


def _formatted(frame: pd.DataFrame) -> pd.DataFrame:
    """``frame`` with every float64 column as the strings ``to_csv(float_format="%.17g")``
    writes (NaN as an empty field; other float dtypes are left to that ``float_format``),
    formatted in one pass per column rather than value by value through pandas' formatter
    (the same bytes, several times faster).

    >>> import pandas as pd
    >>> f = pd.DataFrame({"x": [0.1, float("nan"), -0.0, 1e300, float("inf")], "n": range(5)})
    >>> kw = dict(index=False, lineterminator="\\n")
    >>> kw["float_format"] = "%.17g"
    >>> _formatted(f).to_csv(**kw) == f.to_csv(**kw)
    True
    >>> g = pd.concat([f, f]).set_axis(["x", "x"], axis=1)  # repeated index and names
    >>> _formatted(g).to_csv(**kw) == g.to_csv(**kw), g["x"].dtypes.tolist()
    (True, [dtype('float64'), dtype('int64')])
    """
    import numpy as np
    import pandas as pd

    out = frame.copy(deep=False)
    for loc, dtype in enumerate(frame.dtypes):
        if dtype != np.float64:
            continue
        values = frame.iloc[:, loc].to_numpy()
        text = [f"{v:.17g}" for v in values.tolist()]
        for i in np.flatnonzero(np.isnan(values)).tolist():
            text[i] = ""
        # by position (repeated names or index labels are fine), kept as object (no inference)
        out.isetitem(loc, pd.Series(text, index=frame.index, dtype=object))
    return out


#: what makes the csv module quote a field (QUOTE_MINIMAL, delimiter ",", line end "\n")
_NEEDS_QUOTES = ',"\r\n'


def _needs_quotes(text: str) -> bool:
    """Whether ``text`` holds a character of :data:`_NEEDS_QUOTES` (four substring searches:
    ~50 times faster than a regular expression on a column of 300,000 fields).

    >>> [_needs_quotes(t) for t in ("a b", "a,b", 'a"b', "a\\rb", "a\\nb", "")]
    [False, True, True, True, True, False]
    """
    return any(ch in text for ch in _NEEDS_QUOTES)


def _plain_text(values: pd.Series) -> list[str] | None:
    """A column's fields as ``to_csv`` writes them when none needs quoting: int64 and bool
    values as ``str`` gives them, strings as they are; None for any other column (floats of
    other widths, missing values, other objects, a field with a comma, quote or line end)."""
    import numpy as np
    import pandas as pd

    dtype = values.dtype
    if dtype == np.int64 or dtype == np.bool_:
        return list(map(str, values.tolist()))
    if dtype != np.dtype(object) and not isinstance(dtype, pd.StringDtype):
        return None
    text = values.tolist()
    if not set(map(type, text)) <= {str} or _needs_quotes("\x00".join(text)):
        return None
    return text


def _csv_text(frame: pd.DataFrame) -> str | None:
    """The text ``frame.to_csv(index=False, lineterminator="\\n")`` writes, joined directly
    when every column is plain (:func:`_plain_text`) and there are two or more (the csv module
    quotes an empty field alone on its row); None otherwise. It takes about half the CPU of
    pandas' writer (every reference CSV, mc_trials_judged.csv's ~300,000 rows included).

    >>> import pandas as pd
    >>> f = pd.DataFrame({"n": [1, -2], "ok": [True, False], "s": ["a b", ""], "x": ["0.5", ""]})
    >>> _csv_text(f) == f.to_csv(index=False, lineterminator="\\n")
    True
    >>> _csv_text(f.assign(s=["a,b", ""])) is None, _csv_text(f[["n"]]) is None
    (True, True)
    """
    if frame.shape[1] < 2:
        return None
    names = [c if isinstance(c, str) else None for c in frame.columns]
    if any(n is None for n in names) or _needs_quotes("\x00".join(names)):
        return None
    columns = []
    for loc in range(frame.shape[1]):
        text = _plain_text(frame.iloc[:, loc])
        if text is None:
            return None
        columns.append(text)
    lines = [",".join(names), *map(",".join, zip(*columns, strict=True))]
    return "\n".join(lines) + "\n"


def _frame_text(frame: pd.DataFrame) -> str:
    """The CSV text of an already :func:`_formatted` frame, header line first."""
    text = _csv_text(frame)
    if text is None:
        text = frame.to_csv(index=False, float_format="%.17g", lineterminator="\n")
    return text


def _write_frame(path: Path, frame: pd.DataFrame) -> None:
    with open(path, "w", encoding="utf-8", newline="") as fh:
        fh.write(_frame_text(frame))


def write_csv_parts(
    path: str | os.PathLike[str], parts: Sequence[pd.DataFrame], columns: list[str]
) -> Path:
    """:func:`write_csv` of the parts' rows one after the other, formatted and written part by
    part: one part's text is in memory at a time, not the whole table's (the north-finding
    paper's mc_trials_judged.csv, 23 MB of text, took ~240 MB and ~0.6 CPU-s as one table).
    The same bytes as ``write_csv(path, pd.concat(parts, ignore_index=True), columns)`` when
    the parts' columns have the same dtypes; otherwise that is what is written.

    >>> import pandas as pd, tempfile
    >>> a = pd.DataFrame({"x": [0.1, float("nan")], "n": [1, 2], "s": ["a", "b,c"]})
    >>> b = pd.DataFrame({"x": [1e300], "n": [3], "s": ["d"]})
    >>> d = Path(tempfile.mkdtemp())
    >>> whole = write_csv(d / "w.csv", pd.concat([a, b], ignore_index=True), ["s", "x", "n"])
    >>> write_csv_parts(d / "p.csv", [a, b], ["s", "x", "n"]).read_bytes() == whole.read_bytes()
    True
    >>> c = b.astype({"n": float})  # another dtype: written from the concatenated table
    >>> whole = write_csv(d / "w.csv", pd.concat([a, c], ignore_index=True), ["s", "x", "n"])
    >>> write_csv_parts(d / "p.csv", [a, c], ["s", "x", "n"]).read_bytes() == whole.read_bytes()
    True
    """
    import pandas as pd

    for part in parts:
        missing = [c for c in columns if c not in part.columns]
        if missing:
            raise ValueError(f"{path}: missing contract columns {missing}")
    dtypes = {tuple(part[columns].dtypes) for part in parts}
    if len(dtypes) != 1:  # no parts, or parts whose concatenation changes a column's dtype
        frame = pd.concat(parts, ignore_index=True) if parts else pd.DataFrame(columns=columns)
        return write_csv(path, frame, columns)

    def write(target: Path) -> None:
        with open(target, "w", encoding="utf-8", newline="") as fh:
            for i, part in enumerate(parts):
                text = _frame_text(_formatted(part[columns]))
                fh.write(text if i == 0 else text[text.index("\n") + 1 :])

    return write_atomic(path, write)


def write_csv(path: str | os.PathLike[str], frame: pd.DataFrame, columns: list[str]) -> Path:
    """Write ``frame[columns]`` as CSV atomically; fails if a contract column is missing.
    Floats are written with ``%.17g`` (round-trip exact), NaN as an empty field."""
    missing = [c for c in columns if c not in frame.columns]
    if missing:
        raise ValueError(f"{path}: missing contract columns {missing}")
    return write_atomic(path, lambda p: _write_frame(p, _formatted(frame[columns])))


def write_text_csv(
    path: str | os.PathLike[str], rows: list[dict[str, str]], columns: list[str]
) -> Path:
    """Write ``rows`` (every field a string) as CSV atomically, with the bytes
    :func:`write_csv` writes for the same table as a DataFrame of strings (pandas' ``to_csv``
    writes such a table with the csv module, QUOTE_MINIMAL, line end ``"\\n"``), without
    importing pandas; fails if a row lacks a column or a field is not a string.

    >>> import pandas as pd, tempfile
    >>> rows = [{"a": "x,y", "b": 'say "hi"'}, {"a": "", "b": "two\\nlines"}]
    >>> d = Path(tempfile.mkdtemp())
    >>> frame = pd.DataFrame(rows, columns=["a", "b"])
    >>> write_text_csv(d / "t.csv", rows, ["a", "b"]).read_bytes() == write_csv(
    ...     d / "p.csv", frame, ["a", "b"]).read_bytes()
    True
    """
    bad = [c for row in rows for c in columns if type(row.get(c)) is not str]
    if bad:
        raise ValueError(f"{path}: column {bad[0]!r} missing or not a string")
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(columns)
    writer.writerows([row[c] for c in columns] for row in rows)
    return write_text(path, buffer.getvalue())


def write_json(path: str | os.PathLike[str], data: Any) -> Path:
    """Write JSON atomically (sorted keys, stable output)."""
    return write_text(path, json.dumps(data, indent=2, sort_keys=True) + "\n")
