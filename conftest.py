"""Collection settings for the whole repository (pytest reads this before tests/conftest.py).

``--doctest-modules`` (pyproject.toml) imports every ``.py`` file under the test paths to find its
doctests. Importing must have no side effects, so files that cannot be imported as plain modules
are not collected:

- ``pipeline/scripts/``: Snakemake ``script:`` files. Snakemake injects the ``snakemake`` object
  into their globals and their top level runs the step (opens ``snakemake.log[0]`` for writing),
  so a plain import fails with a NameError; they have no doctests. The step logic they call
  lives in importable modules, whose doctests do run.

Notebooks (``notebooks/*.ipynb``) are not Python modules for pytest; tests/<slug>/test_notebook_<slug>.py
execute them.
"""

collect_ignore = ["pipeline/scripts"]
