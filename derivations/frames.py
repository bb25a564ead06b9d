"""Frames, rotation matrices, gravity and Earth rate, derived symbolically.

Conventions (shared by every paper of this project)
---------------------------------------------------
* Frames. ``E`` Earth-fixed (z along the spin axis), ``N`` local navigation
  frame NED (x north, y east, z down), and the papers' own body/table frames.
* Rotation matrices follow the papers' notation ``[T]^{AB}``: the matrix that
  maps coordinates in frame B to coordinates in frame A, ``v^A = [T]^{AB} v^B``.
  In code it is written ``mat_ab`` (pyins style), so ``mat_tn`` maps N to T.
* Elementary frame rotations (passive, "the new frame is turned by ``a`` about
  axis k of the old one") are ``rot_x``, ``rot_y``, ``rot_z``. The 3-2-1 Euler
  sequence (yaw ``psi``, pitch ``theta``, roll ``phi``) gives
  ``mat_tn = rot_x(phi) * rot_y(theta) * rot_z(psi)``.
* Angles are radians everywhere inside derivations and code; degrees only at
  the edges (config, tables, plots).
* Angular velocity ``omega^{AB}`` is the rate of frame A relative to frame B;
  ``skew(w)`` is the cross-product matrix, ``skew(w) * v == w x v``.

Examples
--------
>>> import sympy as sp
>>> psi, theta, phi = sp.symbols("psi theta phi", real=True)
>>> sp.simplify(mat_tn(psi, theta, phi) * mat_tn(psi, theta, phi).T) == sp.eye(3)
True
>>> lat, Om = sp.symbols("lambda Omega", real=True)
>>> earth_rate_n(Om, lat).T
Matrix([[Omega*cos(lambda), 0, -Omega*sin(lambda)]])
"""

from __future__ import annotations

import sympy as sp

from derivations.trig import pythagorean_reduce

__all__ = [
    "rot_x",
    "rot_y",
    "rot_z",
    "mat_tn",
    "mat_ne",
    "skew",
    "unskew",
    "gravity_n",
    "earth_rate_e",
    "earth_rate_n",
    "angular_velocity_from_dcm",
    "euler_rate_map",
    "transport_rate_n",
    "latlon_rates",
    "transport_rate_n_velocity",
]


def rot_x(a: sp.Expr) -> sp.Matrix:
    """Frame rotation by ``a`` about x: ``[[1, 0, 0], [0, c, s], [0, -s, c]]``."""
    c, s = sp.cos(a), sp.sin(a)
    return sp.Matrix([[1, 0, 0], [0, c, s], [0, -s, c]])


def rot_y(a: sp.Expr) -> sp.Matrix:
    """Frame rotation by ``a`` about y: ``[[c, 0, -s], [0, 1, 0], [s, 0, c]]``."""
    c, s = sp.cos(a), sp.sin(a)
    return sp.Matrix([[c, 0, -s], [0, 1, 0], [s, 0, c]])


def rot_z(a: sp.Expr) -> sp.Matrix:
    """Frame rotation by ``a`` about z: ``[[c, s, 0], [-s, c, 0], [0, 0, 1]]``.

    This is the paper's table matrix ``[T]^{BT}`` with ``a = tau``.
    """
    c, s = sp.cos(a), sp.sin(a)
    return sp.Matrix([[c, s, 0], [-s, c, 0], [0, 0, 1]])


def mat_tn(psi: sp.Expr, theta: sp.Expr, phi: sp.Expr) -> sp.Matrix:
    """``[T]^{TN}`` of the 3-2-1 sequence: yaw ``psi``, then pitch ``theta``, then roll ``phi``."""
    # [T]^{TN} = R1(phi) R2(theta) R3(psi)
    return rot_x(phi) * rot_y(theta) * rot_z(psi)


def mat_ne(lat: sp.Expr, lon: sp.Expr) -> sp.Matrix:
    """``[T]^{NE}``: Earth-fixed to NED at geodetic latitude ``lat`` and longitude ``lon``.

    Turn E by ``lon`` about z, then by ``-(lat + pi/2)`` about the new y axis:
    x then points north, z down.
    """
    return rot_y(-(lat + sp.pi / 2)) * rot_z(lon)


def skew(w: sp.Matrix) -> sp.Matrix:
    """Cross-product matrix: ``skew(w) * v == w.cross(v)``."""
    return sp.Matrix([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])


def unskew(m: sp.Matrix) -> sp.Matrix:
    """Inverse of :func:`skew` (reads the vector off a skew-symmetric matrix)."""
    return sp.Matrix([m[2, 1], m[0, 2], m[1, 0]])


def gravity_n(g: sp.Expr) -> sp.Matrix:
    """Plumb-bob gravity in NED: ``[g]^N = [0, 0, g]`` (mass attraction plus centrifugal)."""
    return sp.Matrix([0, 0, g])


def earth_rate_e(omega_ie: sp.Expr) -> sp.Matrix:
    """Earth rate in the Earth-fixed frame: ``[omega^{EI}]^E = [0, 0, Omega]``."""
    return sp.Matrix([0, 0, omega_ie])


def earth_rate_n(omega_ie: sp.Expr, lat: sp.Expr) -> sp.Matrix:
    """Earth rate in NED, derived as ``[T]^{NE} [omega^{EI}]^E``.

    The longitude drops out, which the derivation shows rather than assumes.
    """
    lon = sp.Symbol("ell", real=True)
    w = sp.simplify(mat_ne(lat, lon) * earth_rate_e(omega_ie))
    assert not w.has(lon)
    return w


def angular_velocity_from_dcm(mat_ab: sp.Matrix, t: sp.Symbol, simplify: bool = True) -> sp.Matrix:
    """``[omega^{AB}]^A`` from the time derivative of ``[T]^{AB}(t)``.

    Poisson's equation for a frame A turning relative to B:
    d/dt [T]^{AB} = -[Omega^{AB}]^A [T]^{AB}, so
    [Omega^{AB}]^A = -(d/dt [T]^{AB}) [T]^{AB}^T.
    """
    omega_skew = -mat_ab.diff(t) * mat_ab.T
    w = unskew(omega_skew)
    # only the three elements unskew reads are simplified (element by element, as
    # ``sp.simplify`` of the whole matrix would, so the result is the same): the diagonal and
    # the mirrored elements are never used, and simplifying them took two thirds of the time.
    # Each is first reduced by sin**2 = 1 - cos**2 (exact, derivations.trig), which leaves the
    # few terms simplify would find from the long product (the same result, measured on every
    # caller of the three papers, at a tenth of the CPU time)
    return w.applyfunc(lambda e: sp.simplify(pythagorean_reduce(e))) if simplify else w


def euler_rate_map(theta: sp.Expr, phi: sp.Expr) -> sp.Matrix:
    """``E`` with ``[omega^{TN}]^T = E [phi_dot, theta_dot, psi_dot]`` for the 3-2-1 sequence.

    Derived from Poisson's equation on ``mat_tn(psi(t), theta(t), phi(t))``: the body rate
    is linear in the Euler rates, and ``E`` is its Jacobian with respect to them (it does not
    depend on ``psi``, which the derivation checks).
    """
    t = sp.Symbol("t", real=True)
    angles = [sp.Function(n, real=True)(t) for n in ("psi_", "theta_", "phi_")]
    w = angular_velocity_from_dcm(mat_tn(*angles), t)
    rates = sp.symbols("psi_dot_ theta_dot_ phi_dot_", real=True)
    w = w.subs({a.diff(t): r for a, r in zip(angles, rates, strict=True)})
    w = w.subs({angles[1]: theta, angles[2]: phi})
    assert not w.has(angles[0])
    e = w.jacobian([rates[2], rates[1], rates[0]])
    assert sp.simplify(e * sp.Matrix([rates[2], rates[1], rates[0]]) - w) == sp.zeros(3, 1)
    return sp.simplify(e)


def transport_rate_n(lat: sp.Expr, lat_dot: sp.Expr, lon_dot: sp.Expr) -> sp.Matrix:
    """``[omega^{NE}]^N``: rate of NED relative to E for latitude and longitude rates.

    Poisson's equation on ``[T]^{NE}(lat(t), lon(t))``; with the inertial longitude (longitude
    plus Earth rotation angle) in place of ``lon`` it is the inertial rate of NED.
    """
    t = sp.Symbol("t", real=True)
    la, lo = sp.Function("lat_", real=True)(t), sp.Function("lon_", real=True)(t)
    w = angular_velocity_from_dcm(mat_ne(la, lo), t)
    w = w.subs({la.diff(t): lat_dot, lo.diff(t): lon_dot}).subs(la, lat)
    assert not w.has(lo)
    return sp.simplify(w)


def latlon_rates(v_n: sp.Expr, v_e: sp.Expr, lat: sp.Expr, rho: sp.Expr) -> sp.Matrix:
    """``[lat_dot, lon_dot]`` of a point at constant radius ``rho`` moving at ``v_n``, ``v_e``.

    Solved from ``v^N = [T]^{NE} d/dt r^E`` with ``r^E = -rho * (down axis in E)``: the
    north and east components of the velocity the rates produce equal ``v_n`` and ``v_e``.
    """
    t = sp.Symbol("t", real=True)
    la, lo = sp.Function("lat_", real=True)(t), sp.Function("lon_", real=True)(t)
    m = mat_ne(la, lo)
    r_e = -rho * m.T[:, 2]
    # sin^2 = 1 - cos^2 (exact, derivations.trig): [rho lat', rho cos(lat) lon', 0], what
    # simplify gave at 40 times the CPU time
    v = (m * r_e.diff(t)).applyfunc(pythagorean_reduce)
    assert sp.simplify(v[2]) == 0
    rates = sp.symbols("lat_dot_ lon_dot_", real=True)
    v = v.subs({la.diff(t): rates[0], lo.diff(t): rates[1]}).subs(la, lat)
    sol = sp.solve([v[0] - v_n, v[1] - v_e], rates, dict=True)
    assert len(sol) == 1
    return sp.Matrix([sp.simplify(sol[0][r]) for r in rates])


def transport_rate_n_velocity(v_n: sp.Expr, v_e: sp.Expr, lat: sp.Expr, rho: sp.Expr) -> sp.Matrix:
    """``[omega^{NE}]^N`` in terms of the velocity: :func:`transport_rate_n` with
    :func:`latlon_rates` substituted, ``[v_e, -v_n, -v_e tan(lat)] / rho``."""
    lat_dot, lon_dot = latlon_rates(v_n, v_e, lat, rho)
    w = transport_rate_n(lat, lat_dot, lon_dot)
    return sp.simplify(w.applyfunc(lambda e: sp.simplify(sp.expand_trig(e)).rewrite(sp.tan)))
