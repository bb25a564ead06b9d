"""Appendix A and eqs. 31-33: mean and covariance of y = F x + G(x) w with G linear in x.

Given E w = 0, E w w^T = Q, E x = xhat, cov x = P, w independent of x (eq. 2a), and
G(x) w = (sum_i w_i G_ci) x (eqs. 3a-4a, G_ci x = G(x) e_i, eq. 33):

    E y = F xhat                                                           (eqs. 5a-6a)
    P_y = F P F^T + G(xhat) Q G(xhat)^T + Gamma (Q kron P) Gamma^T          (eq. 13a)

with Gamma = [G_c1 ... G_cm] (eq. 32). The proof here is symbolic: the expectation
operator :func:`expect` acts on polynomials in the error e = x - xhat and the noise w by
replacing monomials with their moments (E e = 0, E e e^T = P, E w = 0, E w w^T = Q, e and w
independent), so no step of the paper's argument is taken on trust. :func:`covariance_identity`
checks the result for fully symbolic P, Q, F, xhat and G_ci of a chosen size, and for the
paper's own G(x) = dt C(x) of eq. 26 (5 x 6) with fully symbolic P (5x5) and Q (6x6).

>>> res = covariance_identity(n=2, m=2)
>>> res["difference"] == sp.zeros(2, 2)
True
"""

from __future__ import annotations

import itertools

import sympy as sp

from derivations.memo import derivation

__all__ = [
    "Setting",
    "generic_setting",
    "paper_setting",
    "expect",
    "gamma_matrix",
    "mean_identity",
    "covariance_identity",
    "kalman_update",
    "paper_gamma_term",
]


class Setting:
    """Symbols of one Appendix-A problem: sizes n (state), m (noise) and the matrices."""

    def __init__(self, n: int, m: int, gci: list[sp.Matrix], tag: str = "") -> None:
        self.n, self.m = n, m
        self.xhat = sp.Matrix(sp.symbols(f"xhat{tag}_1:{n + 1}", real=True))
        self.e = sp.Matrix(sp.symbols(f"e{tag}_1:{n + 1}", real=True))  # x - xhat
        self.w = sp.Matrix(sp.symbols(f"w{tag}_1:{m + 1}", real=True))
        self.F = sp.Matrix(n, n, lambda i, j: sp.Symbol(f"F{tag}_{i + 1}{j + 1}", real=True))
        self.P = _symmetric(f"P{tag}", n)
        self.Q = _symmetric(f"Q{tag}", m)
        self.Gc = gci

    def G(self, x: sp.Matrix) -> sp.Matrix:
        """G(x), column i = G_ci x (eq. 33)."""
        return sp.Matrix.hstack(*[g * x for g in self.Gc])

    @property
    def x(self) -> sp.Matrix:
        return self.xhat + self.e  # eq. 9a


def _symmetric(name: str, n: int) -> sp.Matrix:
    return sp.Matrix(
        n, n, lambda i, j: sp.Symbol(f"{name}_{min(i, j) + 1}{max(i, j) + 1}", real=True)
    )


def generic_setting(n: int = 2, m: int = 2) -> Setting:
    """Every entry of every G_ci a free symbol: G is a general linear map of x."""
    gci = [
        sp.Matrix(n, n, lambda r, c, i=i: sp.Symbol(f"G{i + 1}_{r + 1}{c + 1}", real=True))
        for i in range(m)
    ]
    return Setting(n, m, gci)


def paper_setting() -> Setting:
    """The paper's problem: G(x) = dt C(x) of eq. 26 (n = 5, m = 6)."""
    from derivations.altimeter_attitude import model
    from derivations.altimeter_attitude import symbols as s

    gci = [s.dt * g for g in model.noise_columns()]
    return Setting(5, 6, gci, tag="p")


def expect(expr: sp.Expr, st: Setting) -> sp.Expr:
    """E[expr] for a polynomial in e (zero mean, cov P) and w (zero mean, cov Q), independent.

    Supports monomials of degree <= 2 in e and <= 2 in w (all the appendix needs); a higher
    degree raises ValueError, since it would need moments the appendix does not assume.
    """
    e_syms, w_syms = list(st.e), list(st.w)
    poly = sp.Poly(sp.expand(expr), *e_syms, *w_syms)
    total = sp.S.Zero
    n = len(e_syms)
    for powers, coeff in poly.terms():
        pe, pw = powers[:n], powers[n:]
        total += coeff * _moment(pe, st.P) * _moment(pw, st.Q)
    return total


def _moment(powers: tuple[int, ...], cov: sp.Matrix) -> sp.Expr:
    """E of prod z_i^p_i for a zero-mean vector with covariance cov, degree <= 2."""
    degree = sum(powers)
    if degree == 0:
        return sp.S.One
    if degree == 1:
        return sp.S.Zero
    if degree == 2:
        idx = [i for i, p in enumerate(powers) for _ in range(p)]
        return cov[idx[0], idx[1]]
    raise ValueError(f"moment of degree {degree} needs more than the mean and covariance")


#: a monomial in e and w: (powers of e_1..e_n, powers of w_1..w_m)
_Monomial = tuple[tuple[int, ...], tuple[int, ...]]


def _by_monomial(expr: sp.Expr, st: Setting) -> dict[_Monomial, sp.Expr]:
    """``expr`` expanded and grouped by its monomial in e and w: ``{(powers of e, powers of w):
    coefficient}`` (the coefficient free of e and w; ValueError if ``expr`` is not a polynomial
    in them, as :func:`expect` fails on it).

    >>> st = generic_setting(2, 2)
    >>> e1, w2 = st.e[0], st.w[1]
    >>> sorted(_by_monomial(3 * e1**2 * w2 + st.F[0, 0] * e1**2 * w2 + st.xhat[0], st).items())
    [(((0, 0), (0, 0)), xhat_1), (((2, 0), (0, 1)), F_11 + 3)]
    >>> _by_monomial(sp.sin(e1), st)
    Traceback (most recent call last):
    ...
    ValueError: sin(e_1) is not a polynomial in e and w (its factor sin(e_1))
    """
    where = {v: (0, i) for i, v in enumerate(st.e)} | {v: (1, i) for i, v in enumerate(st.w)}
    groups: dict[_Monomial, list[sp.Expr]] = {}
    for term in sp.Add.make_args(sp.expand(expr)):
        powers, rest = ([0] * st.n, [0] * st.m), []
        for factor in sp.Mul.make_args(term):
            base, exp = factor.as_base_exp()
            if base in where and exp.is_Integer and exp > 0:
                kind, i = where[base]
                powers[kind][i] += int(exp)
            elif where.keys().isdisjoint(factor.free_symbols):
                rest.append(factor)
            else:
                raise ValueError(f"{expr} is not a polynomial in e and w (its factor {factor})")
        groups.setdefault((tuple(powers[0]), tuple(powers[1])), []).append(sp.Mul(*rest))
    return {key: sp.Add(*coeffs) for key, coeffs in groups.items()}


def _expected_outer(u: sp.Matrix, st: Setting) -> sp.Matrix:
    """E[u u^T], each entry expanded: the same matrix as ``(u * u.T).applyfunc(lambda v:
    sp.expand(expect(v, st)))``, from the moments of the products of u's monomials in e and w
    instead of the expansion of each product u_i u_j (and a :class:`sp.Poly` of it), and the
    lower triangle as the mirror of the upper (u_i u_j = u_j u_i). Both are the expanded
    polynomial, which SymPy writes in one canonical form: the same expressions. The paper's
    setting (n = 5, m = 6), three such matrices: covariance_identity 1.17 -> ~0.3 CPU-s
    (tests/altimeter_attitude/test_derivations_altimeter_attitude.py compares both ways)."""
    terms = [_by_monomial(v, st) for v in u]

    def entry(i: int, j: int) -> sp.Expr:
        total = []
        for (pe1, pw1), c1 in terms[i].items():
            for (pe2, pw2), c2 in terms[j].items():
                pe = tuple(a + b for a, b in zip(pe1, pe2, strict=True))
                pw = tuple(a + b for a, b in zip(pw1, pw2, strict=True))
                moment = _moment(pe, st.P) * _moment(pw, st.Q)
                if moment != 0:
                    total.append(c1 * c2 * moment)
        return sp.expand(sp.Add(*total))

    k = len(u)
    upper = {(i, j): entry(i, j) for i in range(k) for j in range(i, k)}
    return sp.Matrix(k, k, lambda i, j: upper[min(i, j), max(i, j)])


def gamma_matrix(st: Setting) -> sp.Matrix:
    """eq. 32: Gamma = [G_c1 G_c2 ... G_cm] (n x n m)."""
    return sp.Matrix.hstack(*st.Gc)


def mean_identity(st: Setting) -> dict[str, sp.Matrix]:
    """eqs. 5a-6a: E[G(x) w] = 0 and E[F x + G(x) w] = F xhat."""
    z = st.G(st.x) * st.w
    y = st.F * st.x + z
    return {
        "E_Gw": z.applyfunc(lambda v: expect(v, st)),
        "E_y": y.applyfunc(lambda v: expect(v, st)),
        "F_xhat": st.F * st.xhat,
    }


@derivation
def covariance_identity(n: int = 2, m: int = 2, setting: Setting | None = None) -> dict:
    """eq. 13a, proved by expectation of the expanded outer product.

    Returns the covariance computed as E[(y - E y)(y - E y)^T], the appendix's closed form,
    their difference (the zero matrix if the appendix is right), and the intermediate
    quantities of eqs. 8a, 11a and 12a.
    """
    st = setting or generic_setting(n, m)
    y = st.F * st.x + st.G(st.x) * st.w
    ybar = st.F * st.xhat
    cov = _expected_outer(y - ybar, st)  # E[(y - ybar)(y - ybar)^T], expanded
    e_ggt = _expected_outer(st.G(st.x) * st.w, st)  # eq. 8a's second term
    e_gege = _expected_outer(st.G(st.e) * st.w, st)  # eq. 11a's second term
    double_sum = sp.zeros(st.n, st.n)  # eq. 12a: sum_ij G_ci Q_ij P G_cj^T
    for i, j in itertools.product(range(st.m), range(st.m)):
        double_sum += st.Gc[i] * st.Q[i, j] * st.P * st.Gc[j].T
    gam = gamma_matrix(st)
    kron_term = gam * sp.kronecker_product(st.Q, st.P) * gam.T
    closed = st.F * st.P * st.F.T + st.G(st.xhat) * st.Q * st.G(st.xhat).T + kron_term
    return {
        "setting": st,
        "cov": cov,
        "closed": closed,
        "difference": (cov - closed).applyfunc(sp.expand),
        "E_GwwG": e_ggt,
        "E_GewwGe": e_gege,
        "double_sum": double_sum.applyfunc(sp.expand),
        "kron_term": kron_term.applyfunc(sp.expand),
    }


@derivation
def kalman_update(P_pred: sp.Matrix, H: sp.Matrix, R: sp.Expr) -> dict[str, sp.Matrix]:
    """eq. 31, update: K = P_pred H^T (H P_pred H^T + R)^-1, P = (I - K H) P_pred.

    Derived as the linear minimum-variance update: K minimises trace of the posterior
    covariance (I - K H) P_pred (I - K H)^T + K R K^T; setting its gradient to zero gives K.
    """
    n = P_pred.shape[0]
    K_sym = sp.Matrix(sp.symbols(f"K_1:{n + 1}", real=True))
    post = (sp.eye(n) - K_sym * H) * P_pred * (sp.eye(n) - K_sym * H).T + K_sym * R * K_sym.T
    grad = [sp.diff(post.trace(), ki) for ki in K_sym]
    sol = sp.solve(grad, list(K_sym), dict=True)[0]
    K = sp.Matrix([sp.simplify(sol[ki]) for ki in K_sym])
    return {"K": K, "P": sp.simplify((sp.eye(n) - K * H) * P_pred)}


@derivation
def paper_gamma_term() -> dict[str, sp.Matrix]:
    """Gamma (Q kron P) Gamma^T of the paper's model in closed form (used by the filter).

    For G(x) = dt C(x) of eq. 26 and Q = diag(sigma_g^2 I3, sigma_a^2 I3), with P a general
    symmetric 5 x 5 matrix and P_cc its c block, the double sum of eq. 12a collapses to

        dt^2 [ sigma_g^2 (tr(P_cc) I3 - P_cc)   0                        0
               0                                 sigma_a^2 tr(P_cc)       0
               0                                 0                        0 ]

    (the gyro columns G_ci = [e_i x] on the c block give sum_i [e_i x] P [e_i x]^T =
    tr(P) I - P). Returns the literal Gamma (Q kron P) Gamma^T, the closed form and their
    difference (zero), and the symbols P, (sigma_g2, sigma_a2).
    """
    from derivations.altimeter_attitude import model
    from derivations.altimeter_attitude import symbols as s

    sg2, sa2 = sp.symbols("sigma_g2 sigma_a2", positive=True)
    P = _symmetric("P", 5)
    gci = [s.dt * g for g in model.noise_columns()]
    gam = sp.Matrix.hstack(*gci)
    Q = sp.diag(sg2, sg2, sg2, sa2, sa2, sa2)
    literal = (gam * sp.kronecker_product(Q, P) * gam.T).applyfunc(sp.expand)
    pcc = P[:3, :3]
    closed = sp.zeros(5, 5)
    closed[:3, :3] = s.dt**2 * sg2 * (pcc.trace() * sp.eye(3) - pcc)
    closed[3, 3] = s.dt**2 * sa2 * pcc.trace()
    return {
        "literal": literal,
        "closed": closed,
        "difference": (literal - closed).applyfunc(sp.expand),
        "P": P,
        "variances": (sg2, sa2),
    }
