"""Snakemake's own report (``reports/snakemake.html``) with its captions rendered once each:
:func:`cheaper_captions`, applied by :mod:`pipeline.run_snakemake` to the Snakemake version it
was written for, when the command line asks for a report.

Snakemake (9.27.1) renders the caption of every tagged output (46 here, from 9 caption files in
``reports/snakemake/``) in ``FileRecord.render``: it appends the link targets of every output
(~3.7 kB of reStructuredText) to the caption file's text, compiles that as a Jinja template
(``env.from_string``), renders it and hands the result to docutils' ``publish_parts``, which
builds its settings from scratch (an option parser of ~100 options, the config files read)
before parsing. All of it runs after the last job, in series. Many outputs share a rendered
caption (the 22 figures of one figure rule: 47 ``publish_parts`` calls, 27 distinct texts;
46 templates, 9 distinct).

Here the same work is done once per distinct input:

* a template is compiled once per source text (a compiled Jinja template renders any number of
  times; the context is passed to each render);
* ``publish_parts`` is memoised on its arguments (the parts are strings: each caller gets its
  own copy of the dictionary), and a call it does make gets a fresh deep copy of the settings
  docutils would build for it (built once per writer), instead of building them again.

The HTML is the same string for string: docutils and Jinja compute the same thing from the same
input (checked on the report's 47 captions in tests/shared/test_snakemake_captions.py). Measured
on those 47 captions, ``publish_parts`` took 0.243 CPU-s, 0.110 with this (medians of 5);
the Jinja compiles ~20 % of ``FileRecord.render`` in a py-spy profile of ``--report``.
"""

from __future__ import annotations

import copy
import functools
from collections.abc import Callable, Hashable
from typing import Any

__all__ = ["cached_templates", "cheaper_captions", "memoised_publish_parts"]


def _docutils_settings(writer: str) -> Any:
    """The settings ``docutils.core.publish_parts(..., writer_name=writer)`` builds for
    itself (``publish_programmatically``: the standalone reader, the reStructuredText parser,
    the configuration files, ``traceback`` on), built here once."""
    from docutils import io
    from docutils.core import Publisher

    publisher = Publisher(
        "standalone",
        "restructuredtext",
        writer,
        source_class=io.StringInput,
        destination_class=io.StringOutput,
    )
    publisher.process_programmatic_settings(None, None, None)
    return publisher.settings


def memoised_publish_parts(publish_parts: Callable[..., dict[str, str]]) -> Callable[..., Any]:
    """``publish_parts`` computed once per distinct call; a call with only a source and a
    writer name runs with a copy of that writer's settings built once. Any other call (other
    keywords, an unhashable argument) goes to ``publish_parts`` unchanged.

    >>> calls = []
    >>> def parts(source, writer_name="pseudoxml", settings=None):
    ...     calls.append(source)
    ...     return {"body": source.upper()}
    >>> cached = memoised_publish_parts(parts)
    >>> cached("a", writer_name="html"), cached("a", writer_name="html"), cached("b")
    ({'body': 'A'}, {'body': 'A'}, {'body': 'B'})
    >>> calls
    ['a', 'b']
    >>> first = cached("a", writer_name="html"); first["body"] = "changed"
    >>> cached("a", writer_name="html")["body"]
    'A'
    """
    done: dict[Hashable, dict[str, str]] = {}
    settings: dict[str, Any] = {}

    @functools.wraps(publish_parts)
    def cached(source: Any, *args: Any, **kwargs: Any) -> Any:
        try:
            key = (source, args, tuple(sorted(kwargs.items())))
            hash(key)
        except TypeError:
            return publish_parts(source, *args, **kwargs)
        if key not in done:
            writer = kwargs.get("writer_name") or kwargs.get("writer") or "pseudoxml"
            if not args and set(kwargs) <= {"writer_name"} and isinstance(writer, str):
                if writer not in settings:
                    settings[writer] = _docutils_settings(writer)
                # a deep copy: docutils writes into the settings of the call (_source ...)
                fresh = copy.deepcopy(settings[writer])
                done[key] = publish_parts(source, *args, settings=fresh, **kwargs)
            else:
                done[key] = publish_parts(source, *args, **kwargs)
        return dict(done[key])

    return cached


class _TemplateCache:
    """A Jinja environment whose ``from_string`` compiles each source once (everything else
    is the environment's own)."""

    def __init__(self, env: Any, compiled: dict[str, Any]):
        self._env = env
        self._compiled = compiled

    def from_string(self, source: Any, *args: Any, **kwargs: Any) -> Any:
        if args or kwargs or not isinstance(source, str):
            return self._env.from_string(source, *args, **kwargs)
        if source not in self._compiled:
            self._compiled[source] = self._env.from_string(source)
        return self._compiled[source]

    def __getattr__(self, name: str) -> Any:
        return getattr(self._env, name)


def cached_templates(record_class: type) -> bool:
    """Make ``record_class.render(self, env, ...)`` (Snakemake's ``FileRecord``) compile each
    caption template once per environment. Returns whether the class was patched.

    >>> class Env:
    ...     compiled = 0
    ...     def from_string(self, source):
    ...         Env.compiled += 1
    ...         return source.upper
    >>> class Record:
    ...     def render(self, env, caption):
    ...         self.caption = env.from_string(caption)()
    >>> cached_templates(Record)
    True
    >>> env, records = Env(), [Record(), Record()]
    >>> for r in records: r.render(env, "caption")
    >>> [r.caption for r in records], Env.compiled
    (['CAPTION', 'CAPTION'], 1)
    """
    render = getattr(record_class, "render", None)
    if not callable(render):
        return False
    per_env: dict[int, tuple[Any, dict[str, Any]]] = {}

    @functools.wraps(render)
    def cached_render(self: Any, env: Any, *args: Any, **kwargs: Any) -> Any:
        # keyed by the environment (kept alive with its templates, so its id stays its own)
        held = per_env.setdefault(id(env), (env, {}))
        return render(self, _TemplateCache(env, held[1]), *args, **kwargs)

    record_class.render = cached_render
    return True


def cheaper_captions(report_module: Any) -> bool:
    """Apply both to Snakemake's report module (``snakemake.report``): its ``publish_parts``
    and its ``FileRecord``. Returns whether both were found and patched."""
    publish_parts = getattr(report_module, "publish_parts", None)
    record_class = getattr(report_module, "FileRecord", None)
    if not callable(publish_parts) or record_class is None:
        return False
    if not cached_templates(record_class):
        return False
    report_module.publish_parts = memoised_publish_parts(publish_parts)
    return True
