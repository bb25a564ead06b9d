"""Equation audit of the altimeter-attitude paper: every numbered equation, printed vs derived.

``python -m derivations.altimeter_attitude.audit --out results/altimeter_attitude/equation_audit.csv``

Each check pairs ``printed.PRINTED[eq]`` (the seed text, transcribed literally) with the
expression derived in ``kinematics``, ``leveling``, ``complementary``, ``model`` and
``multiplicative_noise``. The status is computed by :func:`derivations.checks.run_check`;
the judgement texts below (``if_differs``) say what is correct and whether the difference
looks like a typo of the paper or an artefact of the OCR text. Both sides are put in the
same symbols first: where the paper writes a quantity as a symbol (omega_ie^b, gamma, C_3j,
c_g, ...) the check substitutes the derived expression and says so in the note.

Eq. 31's prediction and Appendix A (1a-13a) hold for any F, G(x) linear in x, Q, P; they
are checked on the appendix's instance of ``printed.py`` (n = 2 states, m = 2 noises, every
entry of F, G_c1, G_c2, P, Q, x_hat a free symbol), where the expectations are computed by
:func:`multiplicative_noise.expect` from the moments of eq. 2a, and eq. 32 on the paper's own
G(x) = dt C(x) (n = 5, m = 6). Where an appendix step prints an expectation with no closed
form, the printed side keeps that expectation (computed the same way) and the check is on the
printed closed-form terms. The pipeline always uses the derived form.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import sympy as sp

from derivations.altimeter_attitude import complementary as cf
from derivations.altimeter_attitude import kinematics as kin
from derivations.altimeter_attitude import leveling as lv
from derivations.altimeter_attitude import model as md
from derivations.altimeter_attitude import multiplicative_noise as mn
from derivations.altimeter_attitude import printed as P
from derivations.altimeter_attitude import symbols as s
from derivations.checks import AuditRow, Check, audit_main, run_audit
from derivations.checks import audit_frame as checks_audit_frame
from derivations.frames import earth_rate_n, mat_tn

__all__ = ["checks", "audit_rows", "audit_frame", "main"]

MISSING = "missing from the seed text (OCR): "
ROW3 = (s.C31, s.C32, s.C33)


def _subs_vec(symbols, values) -> dict:
    """{symbol_i: value_i} for two equally long sequences."""
    return dict(zip(list(symbols), list(values), strict=True))


def _appendix_setting() -> mn.Setting:
    """The n = m = 2 instance of printed.py as a :class:`multiplicative_noise.Setting`.

    F, P, Q, x_hat and G_c1, G_c2 are printed.py's own matrices; the error e = x - x_hat and
    the noise w are the Setting's symbols (w_1, w_2 coincide with printed's ``w_a``).
    """
    st = mn.Setting(2, 2, [P.Gc1, P.Gc2])
    st.F, st.P, st.Q, st.xhat = P.F_a, P.P_a, P.Q_a, P.xhat_a
    return st


def _offsets(expr: sp.Expr, symbols: list[sp.Symbol]) -> str:
    """The distinct values of ``expr`` at seeded points in (0.15, 1.3), as a multiple of pi."""
    rng = np.random.default_rng(0)
    f = sp.lambdify(symbols, expr, "numpy")
    values = {round(float(f(*rng.uniform(0.15, 1.3, len(symbols)))) / np.pi, 12) for _ in range(40)}
    names = {-1.0: "-pi", 1.0: "pi", 0.0: "0"}
    return ", ".join(names.get(v, f"{v:g} pi") for v in sorted(values))


def _expect(m: sp.Matrix, st: mn.Setting) -> sp.Matrix:
    return m.applyfunc(lambda v: sp.expand(mn.expect(v, st)))


# ---------------------------------------------------------------- section 2: gyros


def _eqs_1_to_8() -> list[Check]:
    out = []
    w_nb = kin.body_rate_from_euler()
    to_euler = {**_subs_vec(s.mat_C, kin.mat_nb()), **_subs_vec(s.omega, w_nb)}
    out.append(
        Check(
            "1",
            printed=P.PRINTED["1"].xreplace(to_euler),
            derived=kin.dcm_rate(),
            if_match="OCR reading: the dot of d/dt C_b^n is lost and the right-hand C prints "
            "superscript m for n (C_b^m); read Cdot_b^n = C_b^n Omega_nb^b. Checked in Euler "
            "angles: C_b^n = mat_nb(phi, theta, psi), omega_nb^b from Poisson's equation, against "
            "the time derivative of mat_nb",
        )
    )
    out.append(
        Check(
            "2",
            printed=P.PRINTED["2"].xreplace(_subs_vec(s.omega, w_nb)),
            derived=kin.mat_nb().T * kin.dcm_rate(),
            if_match="Omega_nb^b = C_n^b Cdot_b^n is the cross-product matrix [omega_nb^b x] "
            "(signs as printed); the C_b^n matrix printed with it is the definition of C11..C33",
        )
    )
    # eq. 3: the three parts computed separately (Earth rate and transport rate in NED,
    # resolved in b; omega_nb^b from the Euler angles) against omega_ib^b of the composed
    # C_b^i = C_e^i C_n^e C_b^n (kinematics.angular_velocity_addition)
    om_e = sp.Symbol("Omega_e", positive=True)
    lat, lon, lat_dot, lon_dot = sp.symbols("L l L_dot l_dot", real=True)
    mat_bn = mat_tn(s.psi, s.theta, s.phi)
    w_en_n = sp.Matrix([lon_dot * sp.cos(lat), -lat_dot, -lon_dot * sp.sin(lat)])
    parts = {
        **_subs_vec(P.w_ie_b, mat_bn * earth_rate_n(om_e, lat)),
        **_subs_vec(P.w_en_b, mat_bn * w_en_n),
        **_subs_vec(s.omega, w_nb),
    }
    w_ib, _ = kin.angular_velocity_addition()
    out.append(
        Check(
            "3",
            printed=P.PRINTED["3"].xreplace(parts),
            derived=w_ib,
            if_match="printed sum with omega_ie^b = C_n^b Omega_e [cos L, 0, -sin L], omega_en^b = "
            "C_n^b [l_dot cos L, -L_dot, -l_dot sin L] (NED, latitude L, longitude l) and "
            "omega_nb^b from the Euler rates, against omega_ib^b of the composed C_b^i = C_e^i "
            "C_n^e C_b^n by Poisson's equation (numerically, at random angles, rates and t)",
        )
    )
    out.append(
        Check(
            "4",
            printed=P.PRINTED["4"],
            derived=kin.euler_rates(),
            if_match="'tg' is tan; singular at theta = +-90 deg (sampled in (0.15, 1.3))",
        )
    )
    out.append(
        Check(
            "5",
            printed=P.PRINTED["5"],
            derived=kin.quaternion_rates(),
            if_match="q_dot = 1/2 q (x) [0, omega_nb^b], scalar-first q = [a b c d] (c read c_q)",
        )
    )
    out.append(
        Check(
            "6.euler",
            printed=P.PRINTED["6.euler"].T,
            derived=kin.third_row_euler(),
            if_match="third row of C_b^n = mat_tn(psi, theta, phi)^T; yaw drops out",
        )
    )
    out.append(
        Check(
            "6.quat",
            printed=P.PRINTED["6.quat"].T,
            derived=kin.third_row_quaternion(),
            if_match="third row of the rotation v -> q (x) v (x) q* (c read c_q)",
        )
    )
    out.append(
        Check(
            "7",
            printed=P.PRINTED["7"],
            derived=kin.third_row_rates(sp.Matrix(ROW3)),
            if_match="third row of eq. 1: d/dt C(3,:) = C(3,:) Omega",
        )
    )
    out.append(
        Check(
            "8",
            printed=P.PRINTED["8"].xreplace(_subs_vec(ROW3, kin.third_row_euler())),
            derived=sp.S.Zero,
            if_match="with C_3j of eq. 6 (Euler form): the row of an orthogonal matrix has unit "
            "norm; eq. 7 preserves it (c . (omega x c) = 0)",
        )
    )
    return out


# ---------------------------------------------------------------- section 3: accelerometers


def _eqs_9_to_12() -> list[Check]:
    out = []
    nav = lv.navigation_symbols()
    sub9 = {
        P.V_d: nav["V"][2],
        **_subs_vec(P.w_ie_n, nav["w_ie"]),
        **_subs_vec(P.w_en_n, nav["w_en"]),
    }
    out.append(
        Check(
            "9",
            printed=P.PRINTED["9"].xreplace(sub9),
            derived=lv.velocity_rate(),
            if_match="adopted, not derived: the paper cites the NED ground-speed equation "
            "(Titterton & Weston, eq. 3.16) and leveling.velocity_rate writes it down; checked "
            "that the printed form is that equation (V_e^n = [V_N, V_E, V_D], Earth and transport "
            "rates in NED, g^n = [0, 0, g]). The Coriolis theorem behind it is derived in the "
            "platform_drift paper, not here",
        )
    )
    f10 = lv.specific_force_level()
    out.append(
        Check(
            "10",
            printed=P.PRINTED["10"],
            derived=f10,
            if_match="-C_n^b g^n with C_b^n of the 3-2-1 angles; valid when V_dot + (2 omega_ie + "
            "omega_en) x V = 0 (the condition |(||f^b|| - g)| < epsilon is text)",
        )
    )
    on_f10 = _subs_vec(s.f_b, f10)
    roll = P.PRINTED["11.phi"].xreplace(on_f10)
    offsets = _offsets(roll - s.phi, [s.phi, s.theta, s.g])
    out.append(
        Check(
            "11.phi",
            printed=roll,
            derived=s.phi,
            if_differs="differs: with eq. 10's f_y = -g cos(theta) sin(phi), f_z = -g cos(theta) "
            "cos(phi), atan2(f_y, f_z) = atan2(-sin(phi), -cos(phi)) = phi - pi (mod 2 pi) for "
            f"cos(theta) > 0 (computed: the residual is {offsets} at the sampled phi, theta in "
            "(0.15, 1.3)); the correct form is atan2(-f_y, -f_z) (leveling.leveling_angles). A "
            "sign slip of the paper (not the OCR: both arguments are legible)",
        )
    )
    out.append(
        Check(
            "11.theta",
            printed=P.PRINTED["11.theta"].xreplace(on_f10),
            derived=s.theta,
            if_match="asin(f_x / g) with f_x = g sin(theta) of eq. 10 returns theta for |theta| "
            "< 90 deg",
        )
    )
    out.append(
        Check(
            "12",
            printed=P.PRINTED["12"],
            derived=lv.total_acceleration(),
            if_match="F_t^n = V_dot + (2 omega_ie + omega_en) x V (definition, first member) "
            "equals C_b^n f^b + g^n by eq. 9",
        )
    )
    return out


# ---------------------------------------------------------------- section 4: c and the PI filter


def _eqs_13_to_23() -> list[Check]:
    out = [
        Check(
            "13",
            printed=P.PRINTED["13"],
            derived=kin.third_row_rates(),
            if_match="eq. 7 in vector form: c_dot = Omega^T c = -omega x c",
        )
    ]
    gamma_c = 1 - (s.c.T * s.c)[0, 0]
    out.append(
        Check(
            "14",
            printed=P.PRINTED["14"].xreplace({s.gamma: gamma_c}),
            derived=kin.normalised_third_row_rates(),
            if_match="gamma of eq. 15 substituted. Norm dynamics (n = c^T c), computed: n_dot = "
            f"{kin.norm_dynamics()}: n = 1 is attracting at rate 2k for k > 0 (the rotation "
            "part drops out)",
        )
    )
    feedback = kin.normalised_third_row_rates() - kin.third_row_rates()
    out.append(
        Check(
            "15",
            printed=P.PRINTED["15"],
            derived=sp.factor(feedback[0] / (s.k * s.c1)),
            if_match="gamma read off the derived eq. 14 (feedback k gamma c): the normalisation "
            "error, zero on the unit sphere of eq. 8",
        )
    )
    out.append(
        Check(
            "15.b",
            printed=P.PRINTED["15.b"],
            derived=lv.specific_force_level_dcm().xreplace(_subs_vec(ROW3, s.c)),
            if_match="the second equation numbered 15: -C_n^b g^n = -g C_b^n(3,:)^T = -g c "
            "(C_3j written c_j)",
        )
    )
    out.append(
        Check(
            "16",
            not_checkable=MISSING + "the Fig. 1 loop equation numbered 16 is not in the "
            "transcription; the loop s c_m = s c_g + (k_p + k_i/s)(c_a - c_m) is reconstructed "
            "from Fig. 1 and eq. 18 (complementary.output_transfer)",
        )
    )
    out.append(
        Check(
            "17.a",
            printed=P.PRINTED["17.a"],
            derived=lv.third_row_from_accel(),
            if_match="eq. 15.b solved for c ('17-alef' of the Persian numbering)",
        )
    )
    out.append(
        Check(
            "17.b",
            printed=P.PRINTED["17.b"],
            derived=lv.third_row_from_accel_unit(),
            if_match="the unit vector along eq. 17-a ('17-be'); ||f^b|| written f_norm",
        )
    )
    loop = {P.c_g: cf.c_g, P.c_a: cf.c_a}
    out.append(
        Check(
            "18",
            printed=P.PRINTED["18"].xreplace(loop),
            derived=cf.output_transfer(),
            if_match="c_m solved from the Fig. 1 loop s c_m = s c_g + (k_p + k_i/s)(c_a - c_m), "
            "per component of c",
        )
    )
    out.append(
        Check(
            "19",
            printed=P.PRINTED["19"].xreplace(loop),
            derived=cf.steady_state(),
            if_match="final value for constant c_g, c_a: the gyro solution is high-passed out",
        )
    )
    out.append(
        Check(
            "20",
            printed=P.PRINTED["20"],
            derived=cf.gains(),
            if_match="denominator of eq. 18 matched to s^2 + 2 xi omega s + omega^2 (the cut-off "
            "omega read omega_c)",
        )
    )
    ov = cf.step_overshoot()
    ov1 = cf.step_overshoot(1.0)
    out.append(
        Check(
            "21",
            printed=P.PRINTED["21"],
            derived=cf.gains_xi_0707(),
            if_match="xi = 0.707 read as 1/sqrt(2). The claim that this xi is chosen so that "
            "'the error has no overshoot' is wrong, computed (complementary.step_overshoot): the "
            f"second-order step response at xi = 0.707 overshoots "
            f"{ov['second_order_overshoot_pct']:.1f} %, and the c_a -> c_m response of eq. 18, "
            f"whose numerator k_p s + k_i adds a zero, {ov['pi_loop_overshoot_pct']:.1f} % "
            f"({ov1['pi_loop_overshoot_pct']:.1f} % even at xi = 1). xi = 0.707 is the "
            "maximally flat (Butterworth) choice; the gain formula itself is right",
        )
    )
    for key in ("22", "23"):
        out.append(
            Check(
                key,
                not_checkable=MISSING + f"equation {key} (the discrete Fig. 1 loop) is not in the "
                "transcription; the filter of Fig. 1 is implemented from eq. 18",
            )
        )
    return out


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
        "the printed C(x) is the negative of the derived one for noise added to the sensor "
        "outputs (omega_tilde = omega + n_w, f_tilde = f + n_a, as the text says): omega = "
        "omega_tilde - n_w gives c_dot = ... + n_w x c = ... - [c x] n_w, and V_d_dot = ... - "
        "c^T n_a. With w defined as truth minus output it matches. The sign of w is immaterial: "
        "w and -w have the same distribution, and C enters the filter only through G Q G^T and "
        "Gamma (Q kron P) Gamma^T, both quadratic in C. A notation slip, not an error"
    )
    out.append(
        Check(
            "26.C",
            printed=P.PRINTED["26.C"],
            derived=mm["C"],
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
            if_differs="differs only by the sign of the noise term, as eq. 26.C (same judgement): "
            + sign_note
            + ". A x + B g match (u = g, from the text after eq. 29)",
        )
    )
    ds = md.discretisation_series(order=3)

    def first_order(m: sp.Matrix) -> sp.Matrix:
        return m.applyfunc(lambda e: sp.series(e, s.dt, 0, 2).removeO())

    def coeff(m: sp.Matrix, p: int) -> sp.Matrix:
        return m.applyfunc(lambda e: sp.expand(e).coeff(s.dt, p))

    sub29 = {
        **_subs_vec(P.Fk, first_order(ds["F"])),
        **_subs_vec(P.Lk, ds["L1"]),
        **_subs_vec(P.Gk, ds["G1"]),
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
    st = _appendix_setting()
    # eq. 31, prediction: mean and covariance of F x + L u + G(x) w by expectation
    y = st.F * st.x + P.L_a * P.u_a + st.G(st.x) * st.w
    out.append(
        Check(
            "31.xpred",
            printed=P.PRINTED["31.xpred"],
            derived=_expect(y, st),
            if_match="E[F x + L u + G(x) w] with E x = x_hat, E w = 0, x and w independent, on "
            "the appendix's n = m = 2 instance (general F, G_c1, G_c2)",
        )
    )
    ybar = _expect(y, st)
    out.append(
        Check(
            "31.Ppred",
            printed=P.PRINTED["31.Ppred"],
            derived=_expect((y - ybar) * (y - ybar).T, st),
            if_match="E[(y - E y)(y - E y)^T] computed from the moments of eq. 2a on the n = m = 2 "
            "instance (fully symbolic F, G_c1, G_c2, P, Q, x_hat): it is eq. 13a with x_hat = "
            "x_hat_{k-1|k-1}, P = P_{k-1|k-1}, Q = Q_{k-1}; the L u term cancels",
        )
    )
    upd = mn.kalman_update(P.P_pred, P.H, P.R_k)
    typo = (
        "typo of the paper: the innovation covariance uses the predicted covariance P_{k|k-1}, "
        "H P_{k|k-1} H^T + R_k (derived as the minimum-variance gain, multiplicative_noise."
        "kalman_update); the printed P_{k-1|k-1} would mix two time steps"
    )
    out.append(Check("31.K", printed=P.PRINTED["31.K"], derived=upd["K"], if_differs=typo))
    out.append(
        Check(
            "31.P",
            printed=P.PRINTED["31.P"],
            derived=upd["P"],
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
            derived=_expect(ge * ge.T, sp_),
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


# ---------------------------------------------------------------- appendix A


def _appendix() -> list[Check]:
    out = [
        Check(
            "1a",
            not_checkable="definition of the quantity whose moments the appendix computes, y_k = "
            "F_k x_k + G(x_k) w_k (eq. 29 without L u, which only shifts the mean)",
        ),
        Check(
            "2a",
            not_checkable="assumptions, not derivable: E w = 0, E x = x_hat, E w w^T = Q, "
            "cov x = P, with w independent of x (stated in the text after 2a); they are the "
            "moments multiplicative_noise.expect uses",
        ),
    ]
    st = _appendix_setting()
    x, w = P.x_a, st.w
    gw = st.G(x) * w
    out.append(
        Check(
            "3a",
            printed=P.PRINTED["3a"],
            derived=gw,
            if_match="identity: w = sum_i w_i e_i",
        )
    )
    out.append(
        Check(
            "4a",
            printed=P.PRINTED["4a"],
            derived=gw,
            if_match="identity: G(x) e_i = G_ci x (eq. 33) and w_i scalar, so G(x) w = (sum_i w_i "
            "G_ci) x",
        )
    )
    mean = mn.mean_identity(st)
    out.append(
        Check(
            "5a",
            printed=P.PRINTED["5a"],
            derived=mean["E_Gw"],
            if_match="E[G(x) w] from the moments (x and w independent, E w = 0)",
        )
    )
    out.append(
        Check(
            "6a",
            printed=P.PRINTED["6a"],
            derived=mean["E_y"],
            if_match="printed '(7-a)' and cited as 6-a; F_x read F_k",
        )
    )
    # eq. 7a: the algebraic expansion of (y - y_hat)(y - y_hat)^T, with z = G(x) w kept as a
    # vector (the expansion does not depend on its structure) and e = x - x_hat
    e = st.e
    z = sp.Matrix(sp.symbols("z_1:3", real=True))
    F = st.F
    printed7 = F * e * e.T * F.T + F * e * z.T + z * e.T + z * z.T
    y, yhat = F * (st.xhat + e) + z, F * st.xhat
    out.append(
        Check(
            "7a",
            printed=printed7,
            derived=(y - yhat) * (y - yhat).T,
            if_differs="typo: the third term E[G(x) w (x - x_hat)^T] lacks its F^T (it is the "
            "transpose of the second term F E[(x - x_hat) w^T G^T(x)], i.e. E[G(x) w (x - "
            "x_hat)^T] F^T). Compared before the expectation, with z = G(x) w and e = x - x_hat; "
            "the term is zero in expectation anyway (w independent of x, zero mean), so eq. 8a "
            "is unaffected",
        )
    )
    ci = mn.covariance_identity(setting=st)
    out.append(
        Check(
            "8a",
            printed=P.PRINTED["8a.FPF"] + ci["E_GwwG"],
            derived=ci["cov"],
            if_match="F P F^T printed; its E[G(x) w w^T G^T(x)] has no printed closed form and is "
            "computed by expectation on both sides: the cross terms of 7a vanish",
        )
    )
    out.append(
        Check(
            "9a",
            printed=P.PRINTED["9a"],
            derived=x,
            if_match="identity (the substitution x = x_hat + e behind 10a)",
        )
    )
    ghat, gerr = st.G(st.xhat), st.G(e)
    ww = w * w.T
    printed10 = ghat * ww * ghat.T + _expect(
        ghat * ww * gerr.T + gerr * ww * ghat.T + gerr * ww * gerr.T, st
    )
    out.append(
        Check(
            "10a",
            printed=printed10,
            derived=ci["E_GwwG"],
            if_differs="typo: the expectation is missing on the first term; as printed it is the "
            "random G(x_hat) w w^T G^T(x_hat), whose expectation G(x_hat) Q G^T(x_hat) the "
            "derivation has (residual G(x_hat)(w w^T - Q) G^T(x_hat)). The split by linearity of "
            "G (G(x) = G(x_hat) + G(x - x_hat)) is right, and 11a uses the expectation",
        )
    )
    out.append(
        Check(
            "11a",
            printed=P.PRINTED["11a.GQG"] + ci["E_GewwGe"],
            derived=ci["E_GwwG"],
            if_match="the mixed terms of 10a vanish (w independent of the zero-mean error); "
            "E[G(x - x_hat) w w^T G^T(x - x_hat)] has no printed closed form here (it is 12a) and "
            "is computed by expectation",
        )
    )
    out.append(
        Check(
            "12a",
            printed=(P.PRINTED["12a.2"], P.PRINTED["12a.2.gamma"]),
            derived=(ci["E_GewwGe"], ci["E_GewwGe"]),
            if_match="both closed forms of the second '(12-a)' line, sum_ij G_ci Q_ij P G_cj^T and "
            "Gamma (Q kron P) Gamma^T, equal E[G(x - x_hat) w w^T G^T(x - x_hat)] computed from "
            "the moments (the first '(12-a)' line, expectations only, is the route). Not stored: "
            "the garbled middle member sum_ij G_ci [Q kron P] G_cj^T (n x n times mn x mn, "
            "dimensionally inconsistent); the first line prints x without subscript",
        )
    )
    out.append(
        Check(
            "13a",
            printed=P.PRINTED["13a"],
            derived=ci["cov"],
            if_differs="typo: the transpose on the second G(x_hat) is missing (eq. 31 has it, "
            "G(x_hat) Q G^T(x_hat)); for the paper's 5x6 G the printed product G Q G is not even "
            "defined. With the transpose the result matches the covariance computed by "
            "expectation (multiplicative_noise.covariance_identity)",
        )
    )
    return out


def checks() -> list[Check]:
    """All checks, in equation order."""
    return [
        *_eqs_1_to_8(),
        *_eqs_9_to_12(),
        *_eqs_13_to_23(),
        *_eqs_24_to_30(),
        *_eqs_31_to_33(),
        *_appendix(),
    ]


def audit_rows() -> list[AuditRow]:
    """Run the whole audit."""
    return run_audit(checks())


def audit_frame() -> pd.DataFrame:
    """The audit as a DataFrame with the contract columns."""
    return checks_audit_frame(checks())


def main(argv: list[str] | None = None) -> int:
    return audit_main(checks, __doc__, argv)


if __name__ == "__main__":
    raise SystemExit(main())
