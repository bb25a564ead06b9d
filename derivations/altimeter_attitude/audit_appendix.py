"""Equation audit of the altimeter-attitude paper, Appendix A (eqs. 1a-13a): the mean and covariance
of a model with multiplicative noise, on the appendix's n = m = 2 instance of ``printed.py``.
"""

from __future__ import annotations

import sympy as sp

from derivations.altimeter_attitude import multiplicative_noise as mn
from derivations.altimeter_attitude import printed as P
from derivations.checks import Check

__all__ = ["checks", "appendix_setting", "expect"]


def appendix_setting() -> mn.Setting:
    """The n = m = 2 instance of printed.py as a :class:`multiplicative_noise.Setting`.

    F, P, Q, x_hat and G_c1, G_c2 are printed.py's own matrices; the error e = x - x_hat and
    the noise w are the Setting's symbols (w_1, w_2 coincide with printed's ``w_a``).
    """
    st = mn.Setting(2, 2, [P.Gc1, P.Gc2])
    st.F, st.P, st.Q, st.xhat = P.F_a, P.P_a, P.Q_a, P.xhat_a
    return st


def expect(m: sp.Matrix, st: mn.Setting) -> sp.Matrix:
    """E[m] element by element, from the moments of ``st`` (eq. 2a), expanded."""
    return m.applyfunc(lambda v: sp.expand(mn.expect(v, st)))


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
    st = appendix_setting()
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
            discrepancy="wrong_term",
            if_differs="error of the paper: a whole factor is missing, the F^T of the third term E[G(x) w (x - "
            "x_hat)^T], legible in the seed text (it is the transpose of the second term F E[(x - "
            "x_hat) w^T G^T(x)], i.e. E[G(x) w (x - x_hat)^T] F^T). Compared before the expectation, "
            "with z = G(x) w and e = x - x_hat; the term is zero in expectation anyway (w "
            "independent of x, zero mean), so eq. 8a is unaffected",
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
    printed10 = ghat * ww * ghat.T + expect(
        ghat * ww * gerr.T + gerr * ww * ghat.T + gerr * ww * gerr.T, st
    )
    out.append(
        Check(
            "10a",
            printed=printed10,
            derived=ci["E_GwwG"],
            discrepancy="wrong_term",
            if_differs="error of the paper: an operator is missing, the expectation on the first term, in a "
            "bracket the seed text renders coherently (11a writes it with E(w w^T) inside); as "
            "printed it is the random G(x_hat) w w^T G^T(x_hat), whose expectation G(x_hat) Q "
            "G^T(x_hat) the derivation has (residual G(x_hat)(w w^T - Q) G^T(x_hat)). The split by "
            "linearity of G (G(x) = G(x_hat) + G(x - x_hat)) is right, and 11a uses the expectation",
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
            "the moments (the first '(12-a)' line, expectations only, is the route). Not compared: "
            "the middle member sum_ij G_ci [Q kron P] G_cj^T is undefined (n x n times mn x mn), "
            "so no status can be computed for it; the first line prints x without subscript",
        )
    )
    out.append(
        Check(
            "13a",
            printed=P.PRINTED["13a"],
            derived=ci["cov"],
            discrepancy="one_mark",
            if_differs="cannot tell from the text: one transpose, once, missing on the second G(x_hat), where "
            "eq. 31 prints G(x_hat) Q G^T(x_hat); for the paper's 5x6 G the printed product G Q G "
            "is not even defined. With the transpose the result matches the covariance computed by "
            "expectation (multiplicative_noise.covariance_identity)",
        )
    )
    return out


def checks() -> list[Check]:
    """The checks of this section, in equation order."""
    return [
        *_appendix(),
    ]
