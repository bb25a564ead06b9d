"""Code generation for the synthetic pendulum paper: writes pipeline/generated/pendulum.py.

``python -m derivations.pendulum.generate`` (``--check``: fail if the file is stale).
"""

from __future__ import annotations

from pathlib import Path

from derivations.pendulum.model import (
    g,
    l,
    period_first_order,
    period_small_angle,
    theta,
    theta0,
    theta_ddot,
)

from derivations.codegen import GeneratedFunction, generate_main, render_module

__all__ = ["functions", "source"]

OUTPUT = Path(__file__).resolve().parents[2] / "pipeline" / "generated" / "pendulum.py"
HEADER = (
    "Pendulum model, generated from derivations/pendulum (python -m derivations.pendulum.generate)."
)


def functions() -> list[GeneratedFunction]:
    return [
        GeneratedFunction(
            "angular_acceleration", (theta, l, g), theta_ddot(), "eq. 1: theta'' (rad/s^2)."
        ),
        GeneratedFunction("period_small_angle", (l, g), period_small_angle(), "eq. 3: T (s)."),
        GeneratedFunction(
            "period_first_order",
            (l, g, theta0),
            period_first_order(),
            "eq. 4 (derived form): T to second order in the amplitude (s).",
            {theta0: "theta0"},
        ),
    ]


def source() -> str:
    return render_module(functions(), HEADER)


if __name__ == "__main__":
    raise SystemExit(generate_main(source, OUTPUT, "derivations.pendulum.generate"))
