"""Attitude kinematics from the gyros: DCM, Euler angles, quaternion, third DCM row.

Eqs. 1-8 and 13-15 of the paper, derived from the 3-2-1 Euler parametrisation of
``C_b^n`` (:func:`derivations.frames.mat_tn` transposed) and Poisson's equation; nothing
is copied from the paper (``audit.py`` compares).

* eq. 1: d/dt C_b^n = C_b^n Omega_nb^b, with Omega = skew(omega_nb^b) (eq. 2);
* eq. 3: omega_ib^b = omega_ie^b + omega_en^b + omega_nb^b (addition of angular velocities);
* eq. 4: Euler-angle rates from the body rate;
* eq. 5: quaternion rates q_dot = 1/2 q (x) [0, omega];
* eq. 6: the third row of C_b^n in Euler angles and in the quaternion;
* eqs. 7, 13: c_dot = C(3,:) Omega, i.e. c_dot = -omega x c;
* eq. 8: the row has unit norm;
* eqs. 14-15: c_dot = k gamma c - Omega c with gamma = 1 - c^T c, whose norm obeys
  n_dot = 2 k (1 - n) n (n = c^T c): n = 1 is attracting at rate 2k.

>>> import sympy as sp
>>> from derivations.altimeter_attitude import symbols as s
>>> third_row_euler().T
Matrix([[-sin(theta), sin(phi)*cos(theta), cos(phi)*cos(theta)]])
>>> sp.simplify(norm_dynamics() - 2 * s.k * (1 - sp.Symbol("n")) * sp.Symbol("n"))
0
"""

from __future__ import annotations

import sympy as sp

from derivations.altimeter_attitude import symbols as s
from derivations.frames import angular_velocity_from_dcm, mat_ne, mat_tn, rot_z, skew
from derivations.memo import derivation

__all__ = [
    "mat_nb",
    "euler_functions",
    "rate_symbols",
    "body_rate_from_euler",
    "dcm_rate",
    "euler_rates",
    "quaternion_dcm",
    "quaternion_from_euler",
    "quaternion_rates",
    "third_row_euler",
    "third_row_quaternion",
    "euler_from_third_row",
    "third_row_rates",
    "normalisation_error",
    "normalised_third_row_rates",
    "norm_dynamics",
    "third_row_rotation",
    "flight_path_direction",
    "climb_rate",
    "angular_velocity_addition",
]

phi_dot, theta_dot, psi_dot = sp.symbols("phi_dot theta_dot psi_dot", real=True)
#: speed V, flight-path angle gam (climbing positive) and heading chi of the truth profile
speed, flight_path, heading = sp.symbols("V gam chi", real=True)


def mat_nb(phi: sp.Expr = s.phi, theta: sp.Expr = s.theta, psi: sp.Expr = s.psi) -> sp.Matrix:
    """C_b^n (body -> NED) of the 3-2-1 sequence: the transpose of ``mat_tn``."""
    return mat_tn(psi, theta, phi).T


def euler_functions() -> tuple[sp.Function, sp.Function, sp.Function]:
    """phi(t), theta(t), psi(t) as undefined functions of time."""
    return tuple(sp.Function(n, real=True)(s.t) for n in ("phi", "theta", "psi"))


def rate_symbols() -> dict[sp.Expr, sp.Symbol]:
    """Replacement of Euler angles/derivatives of time by plain symbols."""
    ph, th, ps = euler_functions()
    return {
        ph.diff(s.t): phi_dot,
        th.diff(s.t): theta_dot,
        ps.diff(s.t): psi_dot,
        ph: s.phi,
        th: s.theta,
        ps: s.psi,
    }


def _plain(expr):
    """Derivatives first, then the functions themselves."""
    reps = rate_symbols()
    derivs = {k: v for k, v in reps.items() if isinstance(k, sp.Derivative)}
    funcs = {k: v for k, v in reps.items() if not isinstance(k, sp.Derivative)}
    # xreplace: exact replacement of these atoms, what subs gave here without its search for
    # patterns (on the long unsimplified rates of angular_velocity_addition, most of the time)
    return expr.xreplace(derivs).xreplace(funcs)


def body_rate_from_euler() -> sp.Matrix:
    """omega_nb^b in terms of the Euler angles and their rates (Poisson's equation).

    C_n^b = mat_tn is [T]^{BN}; ``angular_velocity_from_dcm`` gives [omega^{BN}]^B.
    """
    return sp.Matrix(_body_rate_from_euler())


@derivation
def _body_rate_from_euler() -> sp.ImmutableMatrix:
    ph, th, ps = euler_functions()
    w = angular_velocity_from_dcm(mat_tn(ps, th, ph), s.t)
    return sp.ImmutableMatrix(sp.simplify(_plain(w)))


@derivation
def dcm_rate() -> sp.Matrix:
    """d/dt C_b^n in terms of the Euler angles and their rates (left side of eq. 1)."""
    ph, th, ps = euler_functions()
    return _plain(mat_nb(ph, th, ps).diff(s.t))


def euler_rates() -> sp.Matrix:
    """eq. 4: [phi_dot, theta_dot, psi_dot] from omega_nb^b = [wx, wy, wz].

    Solves body_rate_from_euler() = omega for the three rates (computed once per process:
    the solve and simplification take seconds and every model function needs them).
    """
    return sp.Matrix(_euler_rates())


@derivation
def _euler_rates() -> sp.ImmutableMatrix:
    w = body_rate_from_euler()
    sol = sp.solve(list(w - s.omega), [phi_dot, theta_dot, psi_dot], dict=True)[0]
    return sp.ImmutableMatrix([sp.simplify(sol[r]) for r in (phi_dot, theta_dot, psi_dot)])


def quaternion_dcm(q: sp.Matrix = s.q) -> sp.Matrix:
    """C_b^n of the unit quaternion q = [a, b, c, d] (scalar first, body -> NED).

    The rotation v -> q (x) v (x) q*, written out: (a^2 - |v|^2) I + 2 v v^T + 2 a [v x].
    """
    a, v = q[0], sp.Matrix(q[1:])
    return (a**2 - (v.T * v)[0]) * sp.eye(3) + 2 * v * v.T + 2 * a * skew(v)


def _qmul(p: sp.Matrix, r: sp.Matrix) -> sp.Matrix:
    """Hamilton product p (x) r of scalar-first quaternions."""
    p0, pv = p[0], sp.Matrix(p[1:])
    r0, rv = r[0], sp.Matrix(r[1:])
    vec = p0 * rv + r0 * pv + pv.cross(rv)
    return sp.Matrix([p0 * r0 - (pv.T * rv)[0], *vec])


def quaternion_from_euler(phi=s.phi, theta=s.theta, psi=s.psi) -> sp.Matrix:
    """q_b^n of the 3-2-1 sequence: q_z(psi) (x) q_y(theta) (x) q_x(phi)."""

    def axis(angle, i):
        v = [0, 0, 0]
        v[i] = sp.sin(angle / 2)
        return sp.Matrix([sp.cos(angle / 2), *v])

    return _qmul(_qmul(axis(psi, 2), axis(theta, 1)), axis(phi, 0))


def quaternion_rates(q: sp.Matrix = s.q, omega: sp.Matrix = s.omega) -> sp.Matrix:
    """eq. 5: q_dot = 1/2 q (x) [0, omega_nb^b] (body rate in body axes multiplies on the right)."""
    return sp.expand(_qmul(q, sp.Matrix([0, *omega])) / 2)


@derivation
def third_row_euler() -> sp.Matrix:
    """eq. 6 (Euler form): C_b^n(3,:)^T; yaw drops out."""
    return sp.simplify(mat_nb().row(2).T)


def third_row_quaternion() -> sp.Matrix:
    """eq. 6 (quaternion form): the third row of :func:`quaternion_dcm`."""
    return sp.expand(quaternion_dcm().row(2).T)


def euler_from_third_row(c: sp.Matrix = s.c) -> sp.Matrix:
    """Roll and pitch from c = C_b^n(3,:): phi = atan2(c2, c3), theta = atan2(-c1, |(c2, c3)|).

    Inverse of eq. 6 for |theta| < 90 deg. The atan2 form of pitch (rather than -asin c1) is
    unchanged by a scale error of c, so a filter whose c is not exactly unit reads the
    same angles.
    """
    return sp.Matrix([sp.atan2(c[1], c[2]), sp.atan2(-c[0], sp.sqrt(c[1] ** 2 + c[2] ** 2))])


def third_row_rates(c: sp.Matrix = s.c, omega: sp.Matrix = s.omega) -> sp.Matrix:
    """eqs. 7 and 13: c_dot = (C_b^n Omega)(3,:)^T = Omega^T c = -omega x c."""
    # eq. 1, third row: d/dt C(3,:) = C(3,:) Omega  ->  c_dot = Omega^T c
    return skew(omega).T * c


def normalisation_error(c: sp.Matrix = s.c, summed: bool = False) -> sp.Expr:
    """eq. 15: gamma = 1 - c^T c.

    ``summed=True`` keeps the summation order numpy's ``einsum('...i,...i')`` uses for a
    3-vector on x86-64 (two SIMD lanes: (c1^2 + c3^2) + c2^2), as unevaluated groups, so
    the generated function rounds like the einsum the filters used before it existed (near
    c^T c = 1 the order decides the last bits of gamma). Equal to the plain form:

    >>> sp.expand(normalisation_error(summed=True).doit() - normalisation_error())
    0
    """
    if not summed:
        return 1 - (c.T * c)[0]
    group = sp.UnevaluatedExpr
    # eq. 15 in the order (c1^2 + c3^2) + c2^2
    return 1 - group(group(c[0] ** 2 + c[2] ** 2) + c[1] ** 2)


def normalised_third_row_rates(c: sp.Matrix = s.c, omega: sp.Matrix = s.omega) -> sp.Matrix:
    """eq. 14: c_dot = k gamma c - Omega c, gamma from eq. 15."""
    return s.k * normalisation_error(c) * c + third_row_rates(c, omega)


def norm_dynamics() -> sp.Expr:
    """d/dt (c^T c) under eq. 14, written in n = c^T c: 2 k (1 - n) n.

    The rotation part drops out (c . (omega x c) = 0), so n = 1 is an equilibrium with
    linearised rate -2k: the normalisation error decays if k > 0.
    """
    n = sp.Symbol("n")
    cdot = normalised_third_row_rates()
    ndot = sp.expand(2 * (s.c.T * cdot)[0])
    return sp.factor(ndot.subs(s.c1**2, n - s.c2**2 - s.c3**2))


def third_row_rotation(grouped: bool = False) -> dict:
    """eq. 13 over one step with the rate held: c(t + dt) = exp(-[omega x] dt) c(t).

    With the rotation vector -omega dt = a k (|k| = 1, a >= 0), exp(a [k x]) = I + sin a [k x]
    + (1 - cos a) [k x]^2: R(a) = that matrix solves dR/da = [k x] R, R(0) = I (checked
    here for |k| = 1), so it is the exponential. Applied to c with [k x]^2 c = k (k . c) - c:

        c(t + dt) = c cos a + (k x c) sin a + k (k . c) (1 - cos a)          (Rodrigues)

    ``grouped=True`` returns that vector with the sums and products grouped as the
    complementary filter evaluated them before this function existed (numpy's np.cross and
    np.sum orders), so the generated function rounds the same. Returns the vector, its
    symbols (k, c, cos a, sin a) and the matrix check.

    >>> r = third_row_rotation()
    >>> r["check"]
    True
    """
    k = sp.Matrix(sp.symbols("k1:4", real=True))
    c = sp.Matrix(sp.symbols("cr1:4", real=True))
    a, cos_a, sin_a = sp.symbols("a cos_a sin_a", real=True)
    kx = skew(k)
    rot = sp.eye(3) + sp.sin(a) * kx + (1 - sp.cos(a)) * kx * kx

    def on_unit_sphere(e: sp.Expr) -> sp.Expr:  # e modulo |k|^2 - 1
        norm = k[0] ** 2 + k[1] ** 2 + k[2] ** 2 - 1
        return sp.reduced(sp.expand(e), [norm], k[2], k[1], k[0])[1]

    ode = (rot.diff(a) - kx * rot).applyfunc(on_unit_sphere)
    ok = ode == sp.zeros(3, 3) and rot.subs(a, 0) == sp.eye(3)
    trig = {sp.cos(a): cos_a, sp.sin(a): sin_a}
    # eq. 13 stepped: Rodrigues' formula, c cos a + (k x c) sin a + k (k . c) (1 - cos a)
    rodrigues = c * cos_a + k.cross(c) * sin_a + k * (k.T * c)[0] * (1 - cos_a)
    diff = (rot.subs(trig) * c - rodrigues).applyfunc(on_unit_sphere)
    ok = ok and diff == sp.zeros(3, 1)
    if grouped:
        g = sp.UnevaluatedExpr
        cross = k.cross(c).applyfunc(g)
        dot = g(g(k[0] * c[0] + k[1] * c[1]) + k[2] * c[2])
        rodrigues = sp.Matrix(
            [
                g(g(c[i] * cos_a) + g(cross[i] * sin_a)) + g(k[i] * dot) * g(1 - cos_a)
                for i in range(3)
            ]
        )
        ok = ok and (
            rodrigues.applyfunc(lambda e: e.doit())
            - (c * cos_a + k.cross(c) * sin_a + k * (k.T * c)[0] * (1 - cos_a))
        ).applyfunc(sp.expand) == sp.zeros(3, 1)
    return {"c_next": rodrigues, "args": (*k, *c, cos_a, sin_a), "check": bool(ok)}


def flight_path_direction() -> dict[str, sp.Matrix]:
    """Direction of v^n for flight-path angle gam and heading chi, and its partials.

    The velocity points along the x axis of the frame reached from NED by yaw chi, then
    pitch gam (the 3-2-1 sequence with no roll): u = C(chi, gam, 0) e_x = [cos gam cos chi,
    cos gam sin chi, -sin gam]; v^n = V u, so a^n = V_dot u + V (du/dgam gam_dot + du/dchi
    chi_dot). The truth trajectory of the simulation (our model, not an equation of the
    paper).

    >>> flight_path_direction()["u"].T
    Matrix([[cos(chi)*cos(gam), sin(chi)*cos(gam), -sin(gam)]])
    """
    u = mat_nb(0, flight_path, heading)[:, 0]
    return {"u": u, "du_dgam": u.diff(flight_path), "du_dchi": u.diff(heading)}


def climb_rate() -> sp.Expr:
    """h_dot = -V_d (eq. 25) with V_d = V u_3 of :func:`flight_path_direction`: V sin gam."""
    return -speed * flight_path_direction()["u"][2]


def angular_velocity_addition() -> tuple[sp.Matrix, sp.Matrix]:
    """eq. 3: omega_ib^b computed from C_b^i = C_e^i C_n^e C_b^n, and the sum of the parts.

    Frames: i inertial, e Earth (turning at Omega_e about z), n NED at latitude L(t),
    longitude l(t), b body (Euler angles). Returns (omega_ib^b, omega_ie^b + omega_en^b +
    omega_nb^b), both in plain symbols (angles, rates), to be compared numerically.
    """
    om_e = sp.Symbol("Omega_e", positive=True)
    lat_f, lon_f = (sp.Function(n, real=True)(s.t) for n in ("L", "l"))
    ph, th, ps = euler_functions()
    mat_ei = rot_z(om_e * s.t)  # [T]^{EI}
    mat_ne_ = mat_ne(lat_f, lon_f)  # [T]^{NE}
    mat_bn = mat_tn(ps, th, ph)  # [T]^{BN}
    w_ib = angular_velocity_from_dcm(mat_bn * mat_ne_ * mat_ei, s.t, simplify=False)
    w_ie = mat_bn * mat_ne_ * angular_velocity_from_dcm(mat_ei, s.t, simplify=False)
    w_en = mat_bn * angular_velocity_from_dcm(mat_ne_, s.t, simplify=False)
    w_nb = angular_velocity_from_dcm(mat_bn, s.t, simplify=False)
    lat_dot, lon_dot, lat_s, lon_s = sp.symbols("L_dot l_dot L l", real=True)
    reps = {lat_f.diff(s.t): lat_dot, lon_f.diff(s.t): lon_dot}

    def plain(m):
        return _plain(m.xreplace(reps).xreplace({lat_f: lat_s, lon_f: lon_s}))

    return plain(w_ib), plain(w_ie + w_en + w_nb)
