"""The provenance section of the combined report: the code version, the scenario
configurations and seeds and the package versions, read from each paper's
``results/<slug>/<scenario>/provenance.json`` (the wall times stay in ``benchmarks/*.tsv``:
a report that copied them would differ from run to run)."""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from pipeline.provenance import git_describe
from pipeline.report.model import Paragraph, Section, Table
from pipeline.report.scoreboard import plural

__all__ = ["ProvenanceInputs", "provenance_section"]


@dataclass(frozen=True)
class ProvenanceInputs:
    """One paper's results folder (``results/<slug>``) and scenario folder."""

    slug: str
    results: Path
    scenarios_dir: Path


def _under(root: Path, p: str | Path) -> Path:
    p = Path(p)
    return p if p.is_absolute() else root / p


def _fmt_seed(prov: Mapping[str, Any]) -> str:
    parts = []
    for key in ("seed", "seeds"):
        v = prov.get(key)
        if isinstance(v, Mapping):
            parts += [f"{k}={v[k]}" for k in sorted(v)]
        elif v is not None:
            parts.append(f"{key}={v}")
    return ", ".join(parts) or "none"


def _config_now(path: Path) -> str:
    """sha256 of the scenario file as parsed now (pipeline.config.sha256_of)."""
    from pipeline.config import sha256_of
    from pipeline.report.published import SAFE_LOADER

    if not path.is_file():
        return "file absent"
    with path.open(encoding="utf-8") as fh:
        return sha256_of(yaml.load(fh, Loader=SAFE_LOADER))


def _scenario_dirs(rdir: Path) -> list[Path]:
    return (
        sorted(
            (d for d in rdir.iterdir() if d.is_dir() and (d / "provenance.json").is_file()),
            key=lambda d: (d.name != "paper", d.name),
        )
        if rdir.is_dir()
        else []
    )


def provenance_section(papers: Sequence[ProvenanceInputs], root: Path) -> Section:
    """Code version, scenario configs and seeds and package versions of every paper's runs
    (``results/<slug>/<scenario>/provenance.json``)."""
    runs: list[list[str]] = []
    hl: list[int] = []
    pkgs: dict[str, dict[str, list[str]]] = {}
    describes: dict[str, int] = {}
    schemes: dict[str, list[str]] = {}
    for p in papers:
        for d in _scenario_dirs(p.results):
            prov = json.loads((d / "provenance.json").read_text(encoding="utf-8"))
            sha = str(prov.get("config_sha256", ""))
            file = prov.get("scenario_file") or f"{p.scenarios_dir.name}/{d.name}.yaml"
            scen_path = (
                _under(root, file)
                if prov.get("scenario_file")
                else (p.scenarios_dir / f"{d.name}.yaml")
            )
            now = _config_now(scen_path)
            same = "yes" if sha and now == sha else "no"
            if same == "no":
                hl.append(len(runs))
            desc = str(prov.get("git_describe", ""))
            describes[desc] = describes.get(desc, 0) + 1
            runs.append([p.slug, d.name, desc, sha[:16], same, _fmt_seed(prov)])
            scheme = str(prov.get("seed_scheme") or "not recorded")
            schemes.setdefault(p.slug, [])
            if scheme not in schemes[p.slug]:
                schemes[p.slug].append(scheme)
            for name, version in (prov.get("packages") or {}).items():
                pkgs.setdefault(str(name), {}).setdefault(str(version), []).append(
                    f"{p.slug}/{d.name}"
                )
    git = Section(
        "provenance-code",
        "Code version",
        [
            Paragraph(
                f"This report was built at git describe {git_describe(root)}. The scenario "
                "results were computed at: "
                + ", ".join(f"{k or 'unknown'} ({plural(n, 'run')})" for k, n in describes.items())
                + "."
                if describes
                else f"This report was built at git describe {git_describe(root)}."
            )
        ],
    )
    scen = Section(
        "provenance-scenarios",
        "Scenario configurations and seeds",
        [
            Paragraph(
                "config sha256: the hash recorded in the scenario's provenance.json (canonical "
                "JSON of the parsed scenario file; the full hash is in that file); 'matches "
                "file now': whether the scenario file in config/ still hashes to it. Seeds: the master seed of the "
                "scenario's random streams (numpy SeedSequence, spawned per scenario and trial)."
            ),
            Table(
                columns=[
                    "paper",
                    "scenario",
                    "git describe",
                    "config sha256 (first 16 hex digits)",
                    "matches file now",
                    "seeds",
                ],
                rows=runs,
                caption="Scenario runs (results/<paper>/<scenario>/provenance.json)",
                highlight=hl,
            ),
            Table(
                columns=["paper", "seed scheme"],
                rows=[[slug, s] for slug, ss in schemes.items() for s in ss],
                caption="How each paper derives its random streams",
            ),
        ],
    )
    from pipeline.provenance import package_versions

    here = package_versions(tuple(sorted(set(pkgs) - {"python"})))
    prow = []
    for name in sorted(pkgs, key=lambda n: (n != "python", n)):
        versions = pkgs[name]
        if len(versions) == 1:
            recorded = next(iter(versions))
        else:
            recorded = "; ".join(f"{v} ({len(w)} runs)" for v, w in sorted(versions.items()))
        prow.append([name, recorded, here.get(name, "")])
    packages = Section(
        "provenance-packages",
        "Package versions",
        [
            Table(
                columns=["package", "recorded in the results", "this report's build"],
                rows=prow,
                caption="Package versions",
            )
        ],
    )
    wall = Section(
        "provenance-wall-time",
        "Wall time",
        [
            Paragraph(
                "The wall time of every workflow job is in the Snakemake benchmark files "
                "results/<paper>/benchmarks/<job>.tsv; it is not copied here, so that this "
                "report is the same byte for byte whenever the results are."
            )
        ],
    )
    return Section(
        "provenance",
        "Provenance",
        [
            Paragraph(
                "Every results file records the code version, the scenario's config hash, the "
                "package versions and the seeds; they are collected here."
            )
        ],
        [git, scen, packages, wall],
    )
