"""Provenance recorded beside every results file: code version, config hash, packages, seeds."""

from __future__ import annotations

import importlib.metadata
import platform
import subprocess
from pathlib import Path
from typing import Any

__all__ = ["git_describe", "package_versions", "provenance"]

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("numpy", "scipy", "sympy", "pandas", "matplotlib", "snakemake", "jsonschema", "pyyaml")


def git_describe(root: Path = ROOT) -> str:
    """``git describe --always --dirty --tags`` of the repository at ``root``, or 'unknown'."""
    try:
        out = subprocess.run(
            ["git", "describe", "--always", "--dirty", "--tags"],
            cwd=root,
            capture_output=True,
            text=True,
            check=True,
            timeout=10,
        )
        return out.stdout.strip() or "unknown"
    except (OSError, subprocess.SubprocessError):
        return "unknown"


def package_versions(names: tuple[str, ...] = PACKAGES) -> dict[str, str]:
    """Installed versions of the packages that shape the results."""
    versions = {"python": platform.python_version()}
    for name in names:
        try:
            versions[name] = importlib.metadata.version(name)
        except importlib.metadata.PackageNotFoundError:
            versions[name] = "not installed"
    return versions


def provenance(**extra: Any) -> dict[str, Any]:
    """A provenance record; ``extra`` adds scenario, seeds, config hash and the like."""
    return {"git_describe": git_describe(), "packages": package_versions(), **extra}
