"""The one verdict engine (DESIGN.md, invariant 3): published-values format, kinds, claims.

* :mod:`pipeline.verdicts.published`: load and validate ``config/published/<slug>.yaml``;
* :mod:`pipeline.verdicts.printed`: printed precision (rounding or truncation);
* :mod:`pipeline.verdicts.kinds`: the rules of ``exact``, ``approximate``, ``statistical``;
* :mod:`pipeline.verdicts.claims`: the claim registry a paper package fills;
* :mod:`pipeline.verdicts.engine`: one row per item (per curve) and claim -> verdicts.csv.

Nothing here names a paper: a paper package supplies how to find the reproduced value of an
item in its results and its claim predicates.
"""

from pipeline.verdicts.claims import ClaimRegistry, ClaimResult
from pipeline.verdicts.engine import verdict_table, write_verdicts
from pipeline.verdicts.kinds import NOISE_FREE_AGREES, Found
from pipeline.verdicts.published import load_published, published_items

__all__ = [
    "NOISE_FREE_AGREES",
    "ClaimRegistry",
    "ClaimResult",
    "Found",
    "load_published",
    "published_items",
    "verdict_table",
    "write_verdicts",
]
