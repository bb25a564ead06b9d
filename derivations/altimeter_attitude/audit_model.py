"""Equation audit of the altimeter-attitude paper, eqs. 24-33 (section 5 and the filter): the linear
model with multiplicative noise, its discretisation and the Kalman filter of eq. 31.
"""

from __future__ import annotations

import sympy as sp

from derivations.altimeter_attitude import model as md
from derivations.altimeter_attitude import multiplicative_noise as mn
from derivations.altimeter_attitude import printed as P
from derivations.altimeter_attitude import symbols as s
from derivations.altimeter_attitude.audit_appendix import appendix_setting, expect
from derivations.altimeter_attitude.audit_sensors import subs_vec
from derivations.checks import Check

__all__ = ["checks"]


# ---------------------------------------------------------------- section 5: the linear model


def _eqs_24_to_30() -> list[Check]:
    out = [
        Check(
            "24",
            printed=P.PRINTED["24"],
            derived=md.vertical_velocity_rate(),
            if_match="third row of eq. 9 with the Coriolis/transport term dropped, C_3j = c_j",
        ),
        Check(
            "25",
            printed=P.PRINTED["25"],
            derived=md.altitude_rate(),
            if_match="h up, V_d down: h = -p_D",
        ),
    ]
    mm = md.model_matrices()
    out.append(
        Check(
            "26.A",
            printed=P.PRINTED["26.A"],
            derived=mm["A"],
            if_match="Jacobian of the rhs of eqs. 14, 24, 25 (gamma kept as a symbol, as the paper "
            "does); the attitude block is k gamma I - [omega_tilde x]",
        )
    )
    out.append(
        Check(
            "26.B",
            printed=P.PRINTED["26.B"],
            derived=mm["B"],
            if_match="gravity enters only V_d_dot (eq. 24)",
        )
    )
    sign_note = (
        "sign convention for w: the printed C(x) is the negative of the derived one for noise added to the sensor "
        "outputs (omega_tilde = omega + n_w, f_tilde = f + n_a, as the text says): omega = "
        "omega_tilde - n_w gives c_dot = ... + n_w x c = ... - [c x] n_w, and V_d_dot = ... - "
        "c^T n_a. With w defined as truth minus output it matches. The sign of w is immaterial: "
        "w and -w have the same distribution, and C enters the filter only through G Q G^T and "
        "Gamma (Q kron P) Gamma^T, both quadratic in C. A sign convention for w (a notation "
        "slip), not an error"
    )
    out.append(
        Check(
            "26.C",
            printed=P.PRINTED["26.C"],
            derived=mm["C"],
            discrepancy="notation",
            if_differs=sign_note + ". The '+' joining C(x) w to eq. 26 is lost in the OCR (read "
            "from eq. 28)",
        )
    )
    out.append(
        Check(
            "27",
            printed=P.PRINTED["27"],
            derived=md.measurement_matrix(),
            if_match="z = h + v: the altimeter measures the fifth state",
        )
    )
    out.append(
        Check(
            "28",
            printed=P.PRINTED["28"],
            derived=md.state_rhs(),
            discrepancy="notation",
            if_differs="sign convention for w, as eq. 26.C (same judgement): differs only by the "
            "sign of the noise term; "
            + sign_note[len("sign convention for w: ") :]
            + ". A x + B g match (u = g, from the text after eq. 29)",
        )
    )
    ds = md.discretisation_series(order=3)

    def first_order(m: sp.Matrix) -> sp.Matrix:
        return m.applyfunc(lambda e: sp.series(e, s.dt, 0, 2).removeO())

    def coeff(m: sp.Matrix, p: int) -> sp.Matrix:
        return m.applyfunc(lambda e: sp.expand(e).coeff(s.dt, p))

    sub29 = {
        **subs_vec(P.Fk, first_order(ds["F"])),
        **subs_vec(P.Lk, ds["L1"]),
        **subs_vec(P.Gk, ds["G1"]),
        P.uk: s.g,
    }
    out.append(
        Check(
            "29",
            printed=P.PRINTED["29"].xreplace(sub29),
            derived=s.x + s.dt * md.state_rhs(),
            if_match="definition of the discrete model; checked at first order: with the derived "
            "F = I + A dt, L = dt B, G = dt C(x) (eq. 30 truncated) and u_k = g it is the Euler "
            "step x + dt x_dot of eq. 28. w_k is then the per-sample sensor noise (sigma per "
            "sample), a modelling choice of the paper",
        )
    )
    a_dt = P.PRINTED["26.A"] * s.dt
    exp_series = sum(
        (a_dt**j / sp.factorial(j) for j in range(4)),
        sp.zeros(5, 5),
    )
    out.append(
        Check(
            "30.F",
            printed=exp_series,
            derived=ds["F"],
            if_match="F_k = exp(int A dt) is exact only when A(t) commutes with itself over the "
            "step; for A held at its t_k value (built from the sensor outputs at t_k, as the "
            "filter does) int A dt = A dt and F_k = exp(A dt). Checked as the dt^3 Taylor "
            "polynomial of exp(A dt) with the printed A against the derived ZOH series I + A int_0^dt "
            "exp(A s) ds (order 3). For A(t) varying within the step the Magnus series adds "
            "1/2 int int [A(t1), A(t2)] = O(dt^3), so exp(int A dt) is then a (second-order) "
            "approximation",
        )
    )
    g2 = coeff(ds["G"], 2)
    out.append(
        Check(
            "30.G",
            printed=P.PRINTED["30.G"],
            derived=-ds["G1"],
            if_match="first-order truncation of the exact G = int_0^dt exp(A s) ds C(x), compared "
            "in the paper's sign convention for w (the derived G1 = dt C(x) negated; the sign "
            "itself is the 26.C difference, counted there once). The dropped dt^2 term is A C(x) "
            f"dt^2/2; e.g. its h row (derived sign) is dt^2 * {list(g2.row(4))}: the accelerometer "
            "noise reaches the altitude within the step, which dt C(x) (zero h row) leaves out; "
            f"its V_d row is dt^2 * {list(g2.row(3))} (gyro noise through f_tilde)",
        )
    )
    out.append(
        Check(
            "30.L",
            printed=P.PRINTED["30.L"],
            derived=ds["L1"],
            if_match="first-order truncation; with A held over the step the exact L = int_0^dt "
            f"exp(A s) ds B = {list(ds['L'])} (the series terminates: A^2 B = 0): L = dt B drops "
            "the -g dt^2/2 altitude change of the gravity input within the step",
        )
    )
    return out


# ---------------------------------------------------------------- eqs. 31-33: the filter


def _eqs_31_to_33() -> list[Check]:
    out = []
    st = appendix_setting()
    # eq. 31, prediction: mean and covariance of F x + L u + G(x) w by expectation
    y = st.F * st.x + P.L_a * P.u_a + st.G(st.x) * st.w
    out.append(
        Check(
            "31.xpred",
            printed=P.PRINTED["31.xpred"],
            derived=expect(y, st),
            if_match="E[F x + L u + G(x) w] with E x = x_hat, E w = 0, x and w independent, on "
            "the appendix's n = m = 2 instance (general F, G_c1, G_c2)",
        )
    )
    ybar = expect(y, st)
    out.append(
        Check(
            "31.Ppred",
            printed=P.PRINTED["31.Ppred"],
            derived=expect((y - ybar) * (y - ybar).T, st),
            if_match="E[(y - E y)(y - E y)^T] computed from the moments of eq. 2a on the n = m = 2 "
            "instance (fully symbolic F, G_c1, G_c2, P, Q, x_hat): it is eq. 13a with x_hat = "
            "x_hat_{k-1|k-1}, P = P_{k-1|k-1}, Q = Q_{k-1}; the L u term cancels",
        )
    )
    upd = mn.kalman_update(P.P_pred, P.H, P.R_k)
    typo = (
        "error of the paper: one subscript, but in both the gain and the covariance update, "
        "P_{k-1|k-1} where the innovation covariance uses the predicted P_{k|k-1}, "
        "H P_{k|k-1} H^T + R_k (derived as the minimum-variance gain, multiplicative_noise."
        "kalman_update); as printed it would mix two time steps"
    )
    out.append(
        Check(
            "31.K",
            printed=P.PRINTED["31.K"],
            derived=upd["K"],
            discrepancy="repeated_slip",
            if_differs=typo,
        )
    )
    out.append(
        Check(
            "31.P",
            printed=P.PRINTED["31.P"],
            derived=upd["P"],
            discrepancy="repeated_slip",
            if_differs=typo + "; with P_{k|k-1} inside the inverse the printed form equals the "
            "derived (I - K H) P_{k|k-1}. The pipeline uses the derived update",
        )
    )
    # eq. 31, state update: the linear update x = M x_pred + K z is unbiased for every x
    # (x_pred = x - e, z = H x + v, E e = E v = 0) only if M = I - K H
    M = sp.Matrix(5, 5, lambda i, j: sp.Symbol(f"M_{i + 1}{j + 1}", real=True))
    bias = (M + P.K * P.H - sp.eye(5)) * s.x  # E[M x_pred + K z] - x
    sol = sp.solve(list(bias.jacobian(s.x)), list(M), dict=True)[0]
    out.append(
        Check(
            "31.x",
            printed=P.PRINTED["31.x"],
            derived=M.xreplace(sol) * P.x_pred + P.K * P.z_k,
            if_match="the linear update x = M x_pred + K z (z = H x + v) is unbiased for every x "
            "only if M = I - K H (solved), i.e. x_pred + K (z - H x_pred)",
        )
    )
    # eq. 32 on the paper's own G(x) = dt C(x): Gamma (Q kron P) Gamma^T = E[G(e) w w^T G(e)^T]
    sp_ = mn.paper_setting()
    gam = sp.Matrix.hstack(*sp_.Gc)  # the printed definition [G_c1 ... G_c6]
    ge = sp_.G(sp_.e) * sp_.w
    pg = mn.paper_gamma_term()
    out.append(
        Check(
            "32",
            printed=gam * sp.kronecker_product(sp_.Q, sp_.P) * gam.T,
            derived=expect(ge * ge.T, sp_),
            if_match="Gamma = [G_c1 ... G_c6] (a definition) does what eq. 31 needs: with G_ci of "
            "the paper's G(x) = dt C(x) (5x6), fully symbolic P (5x5) and Q (6x6), Gamma (Q kron "
            "P) Gamma^T equals E[G(x - x_hat) w w^T G^T(x - x_hat)] computed from the moments. "
            "For Q = diag(sigma_g^2 I3, sigma_a^2 I3) it is dt^2 diag(sigma_g^2 (tr P_cc I3 - "
            "P_cc), sigma_a^2 tr P_cc, 0) (multiplicative_noise.paper_gamma_term, difference "
            f"{'zero' if pg['difference'] == sp.zeros(5, 5) else 'NONZERO'})",
        )
    )
    C26 = P.PRINTED["26.C"]
    cols = [C26[:, i] for i in range(C26.shape[1])]
    out.append(
        Check(
            "33",
            printed=sp.Matrix.vstack(*cols),
            derived=sp.Matrix.vstack(*[c.jacobian(s.x) * s.x for c in cols]),
            if_match="constant G_ci with G_ci x = G(x) e_i exist because the printed C(x) is "
            "linear and homogeneous in x: each column equals its Jacobian times x (G_ci = dt "
            "Jacobian; the derived G_ci are their negatives, the 26.C sign). The text's 'G_ci in "
            "R^{5x6}' is a typo: G_ci x with x in R^5 and G(x) e_i in R^5 needs G_ci in R^{5x5}",
        )
    )
    return out


def checks() -> list[Check]:
    """The checks of this section, in equation order."""
    return [
        *_eqs_24_to_30(),
        *_eqs_31_to_33(),
    ]
