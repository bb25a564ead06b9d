"""Frames m_N, m_i, s and the Coriolis-theorem motion equations (eqs. 1-11, 13-14).

Frames (section 2 of the paper)
-------------------------------
* ``n``: geodetic navigation frame, axis 3 along the plumb line; ``m_N`` ("mass navigation
  frame"): axis 1 north, axis 3 along the mass attraction (up), axis 2 west (N, W, U).
  Both are built here from their defining axes, in NWU order, as ``NWU * mat_ne`` (NED of
  :func:`derivations.frames.mat_ne` with axes 2 and 3 reversed).
* ``m_i``: m_N turned by ``psi`` about axis 3; ``s`` (platform): m_i turned by ``phi_y``
  about axis 2, then by ``phi_x`` about axis 1.

The paper's ``C_k(a)`` (eq. 2) are the active elementary rotations, i.e. the transposes of
the frame rotations ``rot_x/rot_y/rot_z`` of :mod:`derivations.frames`;
``^{mN}_s C = C3(psi) C2(phi_y) C1(phi_x)`` is therefore ``mat_tn(psi, phi_y, phi_x).T``
(a 3-2-1 sequence), eq. 2.

Rate notation (Titterton's, which eqs. 8-11 use): ``omega_ab`` is the rate of frame b
relative to frame a, so ``^s omega_is = [p, q, r]`` is the platform's inertial rate. The
transport (Coriolis) theorem then reads ``D_a r = D_b r + omega_ab x r`` with D_a the time
derivative seen from frame a, written in the paper as
``D_s r = D_i r + omega_si x r`` (eq. 8).
"""

from __future__ import annotations

import functools

import sympy as sp

from derivations import frames
from derivations.memo import derivation
from derivations.platform_drift import symbols as s
from derivations.platform_drift.approx import derivative_symbols, taylor
from derivations.trig import pythagorean_reduce

__all__ = [
    "NWU",
    "C1",
    "C2",
    "C3",
    "mat_nwu_e",
    "mat_mN_n",
    "plumb_deflection",
    "mat_mN_s",
    "mat_mi_s",
    "mat_s_mN",
    "transport_rate_mN",
    "earth_rate_mN",
    "azimuth_rate_mi",
    "velocity_at_rest_mN",
    "coriolis_theorem",
    "position_rates_s",
    "velocity_equation_general",
    "velocity_rates_s",
    "radius_rate_s",
    "position_from_tilts",
]

NWU = sp.diag(1, -1, -1)  # NED -> north, west, up


def C1(a: sp.Expr) -> sp.Matrix:
    """Paper's C_1(a) (eq. 2): active rotation about axis 1 = ``rot_x(a).T``."""
    return frames.rot_x(a).T


def C2(a: sp.Expr) -> sp.Matrix:
    """Paper's C_2(a) (eq. 2): active rotation about axis 2 = ``rot_y(a).T``."""
    return frames.rot_y(a).T


def C3(a: sp.Expr) -> sp.Matrix:
    """Paper's C_3(a) (eq. 2): active rotation about axis 3 = ``rot_z(a).T``."""
    return frames.rot_z(a).T


def mat_nwu_e(lat: sp.Expr, lon: sp.Expr) -> sp.Matrix:
    """Earth-fixed to a north-west-up frame at latitude ``lat``, longitude ``lon``."""
    return NWU * frames.mat_ne(lat, lon)


def mat_mN_n(lat_mass: sp.Expr = s.lat, alpha_t: sp.Expr = s.alpha_T) -> sp.Matrix:
    """``^{mN}_n C`` (eq. 1) from the frames' defining axes.

    m_N is NWU at the mass latitude ``lat_mass`` (axis 3 along the mass attraction, radial
    for a spherical mass model); n is NWU at the plumb (geodetic) latitude
    ``lat_mass + alpha_T``. Both share the west axis, so the result is a rotation about
    axis 2 by alpha_T; the longitude drops out.
    """
    lon = sp.Symbol("ell", real=True)
    m = mat_nwu_e(lat_mass, lon) * mat_nwu_e(lat_mass + alpha_t, lon).T
    # the angle sums expanded, then sin**2 = 1 - cos**2 (exact): the latitude and longitude
    # drop out (simplify gave the same matrix, immutable, at 60 times the CPU time)
    return sp.ImmutableMatrix(m.applyfunc(lambda e: pythagorean_reduce(sp.expand_trig(e))))


def plumb_deflection(
    R: sp.Expr = s.R, omega_e: sp.Expr = s.omega_e, lat: sp.Expr = s.lat, g: sp.Expr = s.g
) -> sp.Expr:
    """Exact alpha_T (eq. 1) for a spherical mass model: angle from mass-up to plumb-up.

    Plumb gravity = mass attraction - omega x (omega x r); in m_N, r = [0, 0, R] and
    omega_ie = [omega_e cos(lat), 0, omega_e sin(lat)]. Plumb-up leans north by
    atan(R omega_e^2 sin cos / (g - R omega_e^2 cos^2)).
    """
    w = earth_rate_mN(omega_e, lat)
    r_vec = sp.Matrix([0, 0, R])
    plumb_up = -(sp.Matrix([0, 0, -g]) - w.cross(w.cross(r_vec)))
    plumb_up = sp.expand(sp.expand_trig(plumb_up))  # (simplify first gave the same)
    assert plumb_up[1] == 0
    return sp.atan2(plumb_up[0], plumb_up[2])


def mat_s_mN(psi: sp.Expr = s.psi, phi_y: sp.Expr = s.phi_y, phi_x: sp.Expr = s.phi_x):
    """``^s_{mN} C``: m_N -> s, the 3-2-1 sequence psi, phi_y, phi_x (frames.mat_tn)."""
    return frames.mat_tn(psi, phi_y, phi_x)


def mat_mN_s(psi: sp.Expr = s.psi, phi_y: sp.Expr = s.phi_y, phi_x: sp.Expr = s.phi_x):
    """``^{mN}_s C = C3(psi) C2(phi_y) C1(phi_x)`` (eq. 2)."""
    return mat_s_mN(psi, phi_y, phi_x).T


def mat_mi_s(phi_y: sp.Expr = s.phi_y, phi_x: sp.Expr = s.phi_x) -> sp.Matrix:
    """``^{m_i}_s C = C2(phi_y) C1(phi_x)`` (eq. 3): m_i is m_N turned by psi about axis 3."""
    return mat_s_mN(0, phi_y, phi_x).T


def earth_rate_mN(omega_e: sp.Expr = s.omega_e, lat: sp.Expr = s.lat) -> sp.Matrix:
    """``^{mN} omega_ie = NWU [omega^{EI}]^N`` (eq. 4): [omega_e cos, 0, omega_e sin]."""
    return NWU * frames.earth_rate_n(omega_e, lat)


def velocity_at_rest_mN(
    omega_e: sp.Expr = s.omega_e, lat: sp.Expr = s.lat, R: sp.Expr = s.R
) -> sp.Matrix:
    """Inertial velocity of a vehicle at rest, in m_N: omega_ie x [0, 0, R] (eq. 8 with
    D_e r = 0): [0, -omega_e R cos(lat), 0], i.e. omega_e R cos(lat) toward the east."""
    return earth_rate_mN(omega_e, lat).cross(sp.Matrix([0, 0, R]))


@derivation
def transport_rate_mN() -> sp.Matrix:
    """``^{mN} omega_{e mN}`` (eq. 4) from Poisson's equation on ``NWU mat_ne(lat(t), lon(t))``."""
    la, lo = sp.Function("phi_i")(s.t), sp.Function("lambda")(s.t)
    w = frames.angular_velocity_from_dcm(mat_nwu_e(la, lo), s.t)
    return sp.simplify(derivative_symbols(w, {la: (s.lat, s.lat_dot), lo: (s.lon, s.lon_dot)}))


@derivation
def azimuth_rate_mi() -> sp.Matrix:
    """``^{mi} omega_{mN mi}`` (eq. 4): rate of m_i relative to m_N, [0, 0, psi_dot]."""
    ps = sp.Function("psi")(s.t)
    w = frames.angular_velocity_from_dcm(frames.rot_z(ps), s.t)
    return derivative_symbols(w, {ps: (s.psi, s.psi_dot)})


@derivation
def coriolis_theorem() -> dict[str, sp.Matrix]:
    """Transport theorem (eq. 8) on a concrete motion, for the audit.

    s turns relative to i by 3-2-1 angles a(t), b(t), c(t); r has i-components X(t), Y(t),
    Z(t). Returns ``lhs = D ^s r`` (derivative of the s-components), ``D_i_r = ^s(D_i r)``,
    ``w_si = ^s omega_si = -^s omega_is`` (from Poisson's equation) and ``r_s``; derivatives
    are then replaced by symbols so that the audit can sample them.
    """
    a, b, c = (sp.Function(n)(s.t) for n in ("a", "b", "c"))
    X, Y, Z = (sp.Function(n)(s.t) for n in ("X", "Y", "Z"))
    mat_si = frames.mat_tn(a, b, c)
    r_i = sp.Matrix([X, Y, Z])
    r_s = mat_si * r_i
    lhs = r_s.diff(s.t)
    d_i = mat_si * r_i.diff(s.t)
    w_is = frames.angular_velocity_from_dcm(mat_si, s.t, simplify=False)
    mapping = {
        f: sp.symbols(f"{f.func.__name__}_0 {f.func.__name__}_1", real=True)
        for f in (a, b, c, X, Y, Z)
    }
    sub = functools.partial(derivative_symbols, mapping=mapping)
    return {"lhs": sub(lhs), "D_i_r": sub(d_i), "w_si": sub(-w_is), "r_s": sub(r_s)}


def position_rates_s() -> sp.Matrix:
    """Eq. 9: ``D ^s r = ^s v_iB + ^s omega_si x ^s r`` with omega_si = -[p, q, r].

    Eq. 8 applied to r_EB (E, the Earth's centre, is the inertial origin, so
    D_i r_EB = v_iB = [u, v, w] in s).
    """
    w_si = -sp.Matrix([s.p, s.q, s.r])
    return sp.Matrix([s.u, s.v, s.w]) + frames.skew(w_si) * sp.Matrix([s.x, s.y, s.z])


def velocity_equation_general() -> tuple[sp.Matrix, dict[str, sp.Matrix]]:
    """Eq. 10: ``D_s v_tB`` for a frame t turning at a constant rate omega_it.

    Generic vectors: r = r_EB, v = v_tB = D_t r, a = f + g = D_i D_i r (Newton),
    w = omega_it (constant), W = omega_st. Eq. 8 twice:
    D_i r = v + w x r;  D_i D_i r = D_i v + w x D_i r = (D_t v + w x v) + w x (v + w x r);
    hence D_t v = a - 2 w x v - w x (w x r), and D_s v = D_t v + omega_st x v.
    """
    vec = {n: sp.Matrix(sp.symbols(f"{n}1:4", real=True)) for n in ("r", "v", "a", "w", "W")}
    r_, v_, a_, w_, W_ = (vec[n] for n in ("r", "v", "a", "w", "W"))
    D_t_v = sp.Matrix(sp.symbols("Dtv1:4", real=True))
    D_i_r = v_ + w_.cross(r_)
    D_i_D_i_r = (D_t_v + w_.cross(v_)) + w_.cross(D_i_r)
    sol = sp.solve(list(D_i_D_i_r - a_), list(D_t_v), dict=True)[0]
    D_s_v = D_t_v.xreplace(sol) + W_.cross(v_)
    return sp.expand(D_s_v), vec


def velocity_rates_s() -> sp.Matrix:
    """Eq. 11: eq. 10 with t = i (omega_ii = 0, omega_si = -[p, q, r], v = [u, v, w], a = f + g)."""
    D_s_v, vec = velocity_equation_general()
    reps = {}
    for k, (vv, aa, ww) in enumerate(
        zip(
            (s.u, s.v, s.w),
            (s.f1 + s.g1, s.f2 + s.g2, s.f3 + s.g3),
            (-s.p, -s.q, -s.r),
            strict=True,
        )
    ):
        reps[vec["v"][k]] = vv
        reps[vec["a"][k]] = aa
        reps[vec["w"][k]] = 0
        reps[vec["W"][k]] = ww
    return sp.expand(D_s_v.xreplace(reps))


def radius_rate_s() -> sp.Matrix:
    """Inertial rate of the radius vector, ``r x v / |r|^2`` in s (behind eq. 13)."""
    r_vec = sp.Matrix([s.x, s.y, s.z])
    v_vec = sp.Matrix([s.u, s.v, s.w])
    return r_vec.cross(v_vec) / (s.x**2 + s.y**2 + s.z**2)


def radius_rate_level() -> sp.Matrix:
    """[omega_x, omega_y] of eq. 13: the radius-vector rate to first order in x, y, w.

    (x, y are small when the platform is nearly level, w, the inertial velocity along the
    radius, when the altitude is held.)
    """
    rate = radius_rate_s()
    return taylor(sp.Matrix([rate[0], rate[1]]), [s.x, s.y, s.w], 1)


def position_from_tilts(R_: sp.Expr = s.R_G) -> sp.Matrix:
    """Exact ``^s r_EB = ^s_{mN}C [0, 0, R]`` for tilts phi_x, phi_y (the geometry of eq. 14)."""
    return mat_s_mN() * sp.Matrix([0, 0, R_])
