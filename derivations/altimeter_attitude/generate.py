"""Generate ``pipeline/generated/altimeter_attitude.py`` from the derivations.

Run ``python -m derivations.altimeter_attitude.generate``; ``--check`` exits non-zero if the
committed file is stale. Where the printed equation differs from the derivation (eq. 11's
roll; the sign of C(x) in eq. 26 is immaterial; see the audit), the derived form is generated.
Matrices are returned flattened row by row; :mod:`pipeline.altimeter_attitude.model`
reshapes them.
"""

from __future__ import annotations

from pathlib import Path

import sympy as sp

from derivations.altimeter_attitude import complementary as cf
from derivations.altimeter_attitude import kinematics as kin
from derivations.altimeter_attitude import leveling as lev
from derivations.altimeter_attitude import model
from derivations.altimeter_attitude import multiplicative_noise as mn
from derivations.altimeter_attitude import symbols as s
from derivations.codegen import GeneratedFunction, generate_main, render_module

OUTPUT = Path(__file__).resolve().parents[2] / "pipeline" / "generated" / "altimeter_attitude.py"

NAMES = {s.dt: "dt", s.F_norm: "f_norm"}

HEADER = """Numeric code of the IMU + altimeter attitude paper, generated from derivations/altimeter_attitude.

Regenerate: python -m derivations.altimeter_attitude.generate
Conventions: SI units, angles in rad, rates in rad/s; NED navigation frame, g down positive;
c = [C31, C32, C33] is the third row of C_b^n (body -> NED); x = [c1, c2, c3, V_d, h] with
V_d down and h up; omegat_*, ft_* are the gyro and accelerometer outputs. Every function
broadcasts its arguments; matrices are returned flattened row by row."""


#: Generated functions the pipeline does not call, with the reason (DESIGN.md invariant 1).
AUDIT_ONLY = {
    "euler_noise_jacobian": (
        "d(UKF model)/d[n_w, n_a]; the filters take it through euler_process_noise "
        "(dt^2 J Sigma J^T), generated from the same derivation"
    ),
    "leveling_angles": (
        "eq. 11 as derived, for the audit; levelling runs through accel_third_row (eq. 17-b) "
        "and euler_from_third_row, equal to it when ||f|| = g"
    ),
}


def _fn(name, args, exprs, doc) -> GeneratedFunction:
    return GeneratedFunction(
        name, tuple(args), exprs, doc, NAMES, audit_only=AUDIT_ONLY.get(name, "")
    )


def _flat(m: sp.Matrix) -> tuple[sp.Expr, ...]:
    return tuple(m)


def functions() -> list[GeneratedFunction]:
    """The generated functions, each derived in derivations/altimeter_attitude."""
    mats = model.model_matrices()
    gamma = sp.Matrix.hstack(*model.noise_columns())
    c_euler = kin.third_row_euler()
    euler_c = kin.euler_from_third_row()
    inputs = (*s.omega_t, *s.f_t)
    lvec = model.input_vectors()
    fpd = kin.flight_path_direction()
    rot = kin.third_row_rotation(grouped=True)
    assert rot["check"], "Rodrigues' formula does not solve eq. 13"
    pg = mn.paper_gamma_term()
    pcc = pg["P"][:3, :3]
    pcc_args = [pcc[i, j] for i in range(3) for j in range(i, 3)]
    return [
        _fn(
            "model_matrix_a",
            (*inputs, s.k, s.gamma),
            _flat(mats["A"]),
            "Eq. 26: the 5 x 5 system matrix A (row by row) of x = [c1, c2, c3, V_d, h] for\n"
            "    gyro outputs omegat, accelerometer outputs ft, gain k and gamma = 1 - c^T c.",
        ),
        _fn(
            "noise_matrix_c",
            tuple(s.c),
            _flat(mats["C"]),
            "Eq. 26: the 5 x 6 noise matrix C(x) (row by row) for w = [n_w, n_a], with the\n"
            "    sensor model omegat = omega + n_w, ft = f + n_a (the negative of the printed\n"
            "    matrix; the sign of w is immaterial for the covariances).",
        ),
        _fn(
            "input_matrix_b",
            (),
            _flat(lvec["B"]),
            "Eq. 26: the input vector B of x_dot = A x + B g + C(x) w (gravity drives V_d).",
        ),
        _fn(
            "input_vector_exact",
            (s.dt,),
            _flat(lvec["exact"]),
            "Eq. 30: L = int_0^dt exp(A s) ds B of the exact zero-order hold (the series stops:\n"
            "    A^2 B = 0), independent of the IMU outputs and gamma.",
        ),
        _fn(
            "input_vector_first_order",
            (s.dt,),
            _flat(lvec["first_order"]),
            "Eq. 30 as the paper discretises: L = dt B (first order in dt).",
        ),
        _fn(
            "vertical_transition",
            (s.dt,),
            _flat(model.block_structure()["vertical_transition"]),
            "Eq. 30: exp(V dt) (2 x 2, row by row) of the constant (V_d, h) block V of eq. 26's A,\n"
            "    the lower-right block of F = exp(A dt) (A is block lower triangular).",
        ),
        _fn(
            "gamma_term_closed",
            (*pcc_args, *pg["variances"], s.dt),
            (*_flat(pg["closed"][:3, :3]), pg["closed"][3, 3]),
            "Eq. 31's Gamma (Q kron P) Gamma^T for G = dt C(x) of eq. 26 and Q = diag(sigma_g2 I3,\n"
            "    sigma_a2 I3), in closed form from the c block P_cc of P (upper triangle P_11 ..\n"
            "    P_33): its c block (3 x 3, row by row), then its (V_d, V_d) entry; every other\n"
            "    entry is 0. Equal to the literal Kronecker form of eqs. 32-33 (a test).",
        ),
        _fn(
            "noise_gamma",
            (),
            _flat(gamma),
            "Eqs. 32-33: Gamma = [G_c1 ... G_c6] (5 x 30, row by row), G_ci x = C(x) e_i.",
        ),
        _fn(
            "normalisation_error",
            tuple(s.c),
            kin.normalisation_error(summed=True),
            "Eq. 15: gamma = 1 - c^T c, summed as (c1^2 + c3^2) + c2^2 (the rounding of\n"
            "    numpy's einsum over a 3-vector).",
        ),
        _fn(
            "third_row_from_euler",
            (s.phi, s.theta),
            _flat(c_euler),
            "Eq. 6: c = C_b^n(3,:) = [-sin theta, sin phi cos theta, cos phi cos theta].",
        ),
        _fn(
            "euler_from_third_row",
            tuple(s.c),
            _flat(euler_c),
            "Inverse of eq. 6: (phi, theta) = (atan2(c2, c3), atan2(-c1, sqrt(c2^2 + c3^2)));\n"
            "    independent of the norm of c.",
        ),
        _fn(
            "euler_jacobian_third_row",
            tuple(s.c),
            _flat(euler_c.jacobian(s.c)),
            "d(phi, theta)/dc (2 x 3, row by row): maps a covariance of c to roll/pitch.",
        ),
        _fn(
            "euler_model_rhs",
            (s.phi, s.theta, s.V_d, s.h, *inputs, s.g),
            _flat(model.euler_model_rhs()),
            "UKF model (eqs. 4, 6, 24, 25): d/dt [phi, theta, V_d, h] for sensor outputs.",
        ),
        _fn(
            "euler_noise_jacobian",
            (s.phi, s.theta),
            _flat(model.euler_noise_jacobian()),
            "d(UKF model)/d[n_w, n_a] (4 x 6, row by row): sensor noise to state rates.",
        ),
        _fn(
            "euler_process_noise",
            (s.phi, s.theta, s.dt, *sp.symbols("sigma_g2 sigma_a2", positive=True)),
            _flat(model.euler_process_noise()),
            "dt^2 J Sigma J^T (4 x 4, row by row): per-step process noise of the UKF/EKF model\n"
            "    for per-sample gyro/accelerometer variances sigma_g2, sigma_a2.",
        ),
        _fn(
            "euler_state_jacobian",
            (s.phi, s.theta, *inputs),
            _flat(model.euler_state_jacobian()),
            "d(UKF model)/d[phi, theta, V_d, h] (4 x 4, row by row), for the EKF comparison.",
        ),
        _fn(
            "accel_third_row",
            tuple(s.f_t),
            _flat(
                lev.third_row_from_accel_unit()
                .subs(dict(zip(s.f_b, s.f_t, strict=True)))
                .subs(s.F_norm, sp.sqrt(sum(fi**2 for fi in s.f_t)))
            ),
            "Eq. 17-b: c_a = -f / ||f||, the accelerometer estimate of c (cruise assumption).",
        ),
        _fn(
            "leveling_angles",
            (*s.f_t, s.g),
            _flat(lev.leveling_angles().subs(dict(zip(s.f_b, s.f_t, strict=True)))),
            "Eq. 11 as derived from eq. 10: phi = atan2(-f_y, -f_z), theta = asin(f_x / g)\n"
            "    (the printed atan2(f_y, f_z) is off by 180 deg).",
        ),
        GeneratedFunction(
            "third_row_rotation",
            rot["args"],
            tuple(rot["c_next"]),
            "Eq. 13 over one step with omega held: c rotated by a about the unit axis k\n"
            "    (a k = -omega dt), c cos a + (k x c) sin a + k (k . c)(1 - cos a) (Rodrigues),\n"
            "    summed in the order of numpy's np.cross and np.sum.",
            {**NAMES, **{sym: f"c{i + 1}" for i, sym in enumerate(rot["args"][3:6])}},
        ),
        _fn(
            "flight_path_direction",
            (kin.flight_path, kin.heading),
            _flat(sp.Matrix.vstack(*fpd.values())),
            "Truth trajectory: u = v^n / V = [cos gam cos chi, cos gam sin chi, -sin gam] (the x\n"
            "    axis after yaw chi and pitch gam), then du/dgam, then du/dchi (9 values).",
        ),
        _fn(
            "climb_rate",
            (kin.speed, kin.flight_path),
            kin.climb_rate(),
            "Truth trajectory, eq. 25: h_dot = -V_d = V sin gam.",
        ),
        _fn(
            "pi_gains",
            (s.omega_c, s.xi),
            _flat(cf.gains()),
            "Eq. 20: (k_i, k_p) = (omega^2, 2 xi omega) of the PI complementary filter.",
        ),
    ]


def source() -> str:
    """Source text of the generated module."""
    return render_module(functions(), HEADER)


def main(argv: list[str] | None = None) -> int:
    return generate_main(source, OUTPUT, "derivations.altimeter_attitude.generate", argv)


if __name__ == "__main__":
    raise SystemExit(main())
