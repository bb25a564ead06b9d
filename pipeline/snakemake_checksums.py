"""Snakemake's records of finished jobs with each input file hashed once per file version.

When a job ends, Snakemake writes one metadata record per output (``persistence.finished``,
``.snakemake/metadata``), and each record holds the SHA-256 of every input of the job that is
no larger than its checksum limit. The hashes are not shared: a job with N outputs and M inputs
hashes N x M files, and the code inputs (the modules a step imports, about a hundred a job) are
hashed again for every job. In a full run from nothing that is ~10,200 hashes in Snakemake's
own process (~0.9 CPU-s, measured with cProfile; a figures job alone, ~20 outputs x ~150
inputs, ~3,000), done between a job's end and the next job's start on that core.

:func:`known_checksums` memoises ``checksum`` of a local file for as long as the file is the
same version: the key is the path and the arguments, and the file's device, inode, size and
modification time (ns) read by one ``stat``; a file rewritten or replaced gets a new key, hence
a new hash. Storage files, an explicit algorithm and ``force`` go to Snakemake's method as
before, as do files that cannot be stat'ed. The records hold the same checksums (the same
bytes hashed the same way).
"""

from __future__ import annotations

import inspect
import os
from typing import Any

__all__ = ["known_checksums"]


def known_checksums(io_class: type) -> bool:
    """Make ``io_class.checksum`` (Snakemake's ``_IOFile``, a coroutine) reuse the checksum of a
    local file already hashed in this process while its stat is unchanged. Returns whether the
    class was patched (False: it has no such coroutine).

    >>> import asyncio, hashlib, pathlib, tempfile
    >>> class File(str):
    ...     hashed = []
    ...     is_storage = False
    ...     @property
    ...     def file(self):
    ...         return str(self)
    ...     async def checksum(self, threshold=None, force=False, algorithm=None):
    ...         File.hashed.append(str(self))
    ...         return hashlib.sha256(pathlib.Path(self).read_bytes()).hexdigest()[:8]
    >>> known_checksums(File)
    True
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "a.txt"
    >>> _ = path.write_text("one")
    >>> [asyncio.run(File(path).checksum(10_000)) for _ in range(3)]
    ['7692c3ad', '7692c3ad', '7692c3ad']
    >>> len(File.hashed)
    1
    >>> _ = path.write_text("two!")  # a new version (other size and time): hashed again
    >>> asyncio.run(File(path).checksum(10_000)), len(File.hashed)
    ('a97b629a', 2)
    """
    checksum = getattr(io_class, "checksum", None)
    if not inspect.iscoroutinefunction(checksum):
        return False
    known: dict[tuple, Any] = {}

    async def memo_checksum(
        self: Any, threshold: int | None = None, force: bool = False, algorithm: Any = None
    ) -> str | None:
        if force or algorithm is not None or self.is_storage:
            return await checksum(self, threshold, force, algorithm)
        try:
            st = os.stat(self.file)
        except OSError:
            return await checksum(self, threshold, force, algorithm)
        key = (self.file, threshold, st.st_dev, st.st_ino, st.st_size, st.st_mtime_ns)
        if key not in known:
            known[key] = await checksum(self, threshold, force, algorithm)
        return known[key]

    io_class.checksum = memo_checksum
    return True
