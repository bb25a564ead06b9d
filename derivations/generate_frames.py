"""Generate ``pipeline/generated/frames.py`` (shared frames and Earth) from derivations/frames.py.

Run ``python -m derivations.generate_frames``; ``--check`` exits non-zero if the committed file
is stale. Every paper's numeric code takes its rotation matrices, Euler-rate map, skew
matrices, Earth rate and transport rate from the generated module, never from a re-typed copy.
Matrices and vectors are returned as arrays whose trailing axes are (3, 3) or (3,).
"""

from __future__ import annotations

from pathlib import Path

import sympy as sp

from derivations import frames
from derivations.codegen import GeneratedFunction, generate_main, render_module

OUTPUT = Path(__file__).resolve().parents[1] / "pipeline" / "generated" / "frames.py"

HEADER = """Frames and Earth (shared by every paper), generated from derivations/frames.py.

Regenerate: python -m derivations.generate_frames
Conventions: NED navigation frame; mat_ab maps coordinates in frame B to frame A; 3-2-1 Euler
angles (yaw psi, pitch theta, roll phi) in rad; rates in rad/s. Every function broadcasts its
arguments; a matrix is returned with trailing axes (3, 3), a vector with a trailing axis (3,)."""

psi, theta, phi, a = sp.symbols("psi theta phi a", real=True)
phi_dot, theta_dot, psi_dot = sp.symbols("phi_dot theta_dot psi_dot", real=True)
lat, lon, omega_ie, rho = sp.symbols("lat lon omega_ie rho", real=True)
lat_dot, lon_dot, v_n, v_e = sp.symbols("lat_dot lon_dot v_n v_e", real=True)
w1, w2, w3 = sp.symbols("w1 w2 w3", real=True)


def _matrix(name, args, m: sp.Matrix, doc: str, cse: bool = True) -> GeneratedFunction:
    shape = (m.rows, m.cols) if m.cols > 1 else (m.rows,)
    return GeneratedFunction(name, tuple(args), tuple(m), doc, shape=shape, cse=cse)


def functions() -> list[GeneratedFunction]:
    """The generated functions, each built by derivations/frames.py."""
    return [
        _matrix(
            "rot_z",
            (a,),
            frames.rot_z(a),
            "Frame rotation by a about z: [[c, s, 0], [-s, c, 0], [0, 0, 1]] (its transpose is\n"
            "    the active rotation by a).",
        ),
        _matrix(
            "mat_tn",
            (psi, theta, phi),
            frames.mat_tn(psi, theta, phi),
            "[T]^{TN} of the 3-2-1 sequence, rot_x(phi) rot_y(theta) rot_z(psi): NED -> body.\n"
            "    Its transpose (swapaxes(-1, -2)) is C_b^n.",
        ),
        _matrix(
            "mat_ne",
            (lat, lon),
            frames.mat_ne(lat, lon),
            "[T]^{NE}: Earth-fixed (or inertial, with the inertial longitude) -> NED at latitude\n"
            "    lat and longitude lon; its rows are the north, east and down axes.",
        ),
        _matrix(
            "body_rate_from_euler_rates",
            (theta, phi, phi_dot, theta_dot, psi_dot),
            frames.euler_rate_map(theta, phi) * sp.Matrix([phi_dot, theta_dot, psi_dot]),
            "Euler-rate map of the 3-2-1 sequence: [omega^{TN}]^T = E(theta, phi) [phi_dot,\n"
            "    theta_dot, psi_dot], from Poisson's equation on mat_tn.",
        ),
        _matrix(
            "skew",
            (w1, w2, w3),
            frames.skew(sp.Matrix([w1, w2, w3])),
            "Cross-product matrix [w x]: skew(w) @ v == cross(w, v).",
        ),
        _matrix(
            "earth_rate_e",
            (omega_ie,),
            frames.earth_rate_e(omega_ie),
            "Earth rate in the Earth-fixed (or inertial) frame, z along the spin axis: [0, 0, omega_ie].",
        ),
        _matrix(
            "earth_rate_n",
            (omega_ie, lat),
            frames.earth_rate_n(omega_ie, lat),
            "Earth rate in NED, [T]^{NE} [0, 0, omega_ie] = omega_ie [cos lat, 0, -sin lat].",
        ),
        _matrix(
            "transport_rate_n",
            (lat, lat_dot, lon_dot),
            frames.transport_rate_n(lat, lat_dot, lon_dot),
            "[omega^{NE}]^N = [lon_dot cos lat, -lat_dot, -lon_dot sin lat] (Poisson's equation\n"
            "    on mat_ne); with the inertial longitude rate it is the inertial rate of NED.",
        ),
        _matrix(
            "latlon_rates",
            (v_n, v_e, lat, rho),
            frames.latlon_rates(v_n, v_e, lat, rho),
            "[lat_dot, lon_dot] = [v_n / rho, v_e / (rho cos lat)] at constant radius rho.",
            cse=False,
        ),
        _matrix(
            "transport_rate_n_velocity",
            (v_n, v_e, lat, rho),
            frames.transport_rate_n_velocity(v_n, v_e, lat, rho),
            "[omega^{NE}]^N = [v_e, -v_n, -v_e tan lat] / rho: transport_rate_n of latlon_rates.",
            cse=False,
        ),
    ]


def source() -> str:
    """Source text of the generated module."""
    return render_module(functions(), HEADER)


def main(argv: list[str] | None = None) -> int:
    return generate_main(source, OUTPUT, "derivations.generate_frames", argv)


if __name__ == "__main__":
    raise SystemExit(main())
