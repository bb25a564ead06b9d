"""Symbols of the stable-platform gyro-drift paper, named as the paper names them.

==============  ==================================================================
symbol          meaning (paper's notation)
==============  ==================================================================
t               time (s); navigation starts at t = 0 (0+), alignment ends at 0-
x, y, z         ^s r_EB: Earth centre to vehicle, in the platform frame s (eq. 5)
u, v, w         ^s v_iB: inertial velocity of the vehicle, in s (eq. 6)
p, q, r         ^s omega_is: inertial rate of the platform s, in s (eq. 7)
f1, f2, f3      specific force measured on the platform (f_i)
g1, g2, g3      mass-attraction gravity in s (g_i of the symbol list)
omega_x, _y     omega_x = -v/z, omega_y = u/z (eq. 13)
phi_x, phi_y    platform tilts about axes 1, 2 (eqs. 2, 14)
psi             azimuth of m_i (and of s) from m_N about axis 3 (eqs. 2-3)
lat, lon        latitude phi_i and longitude lambda in the mass navigation frame m_N
p_m, q_m, r_m   ^{m_i} omega_{i m_i}: inertial rate of m_i, in m_i (eq. 4)
omega_e         Earth rate
GM, R_G         gravitational constant times Earth mass; mean radius of the vehicle
R, g            radius of the vehicle (3rd component of ^{mN} r) and mass gravity g_i
alpha_T         angle between m_N and the geodetic frame n about axis 2 (eq. 1)
alpha           plumb-line deflection R omega_e^2 sin cos / g_i (eq. 21)
theta_F1, _F2   b_a1 / g_i, b_a2 / g_i (eq. 21)
b_a1, b_a2      accelerometer biases; b_g1..b_g3 gyro drifts; b_psi pick-off bias
k_sh, k_g       Schuler-like constant and gain mismatch (eq. 28); R_GMM = 1/(k_I k_G k_F)
==============  ==================================================================

Symbols with a ``_dot`` / ``_ddot`` suffix stand for time derivatives that the paper writes
with dots (the derivations differentiate functions of ``t`` and then replace the
derivatives by these symbols). Table 2 (appendix, Pitman) has its own symbols at the end.
"""

from __future__ import annotations

import sympy as sp

t = sp.Symbol("t", real=True)

# state and inputs of the motion equations (eqs. 5-11)
x, y, z = sp.symbols("x y z", real=True)
u, v, w = sp.symbols("u v w", real=True)
p, q, r = sp.symbols("p q r", real=True)
f1, f2, f3 = sp.symbols("f1 f2 f3", real=True)
g1, g2, g3 = sp.symbols("g1 g2 g3", real=True)
x_dot, y_dot, z_dot = sp.symbols("x_dot y_dot z_dot", real=True)
u_dot, v_dot, w_dot = sp.symbols("u_dot v_dot w_dot", real=True)
p_dot, q_dot, r_dot = sp.symbols("p_dot q_dot r_dot", real=True)

# algorithm variables (eqs. 13-16)
omega_x, omega_y = sp.symbols("omega_x omega_y", real=True)
omega_x_dot, omega_y_dot = sp.symbols("omega_x_dot omega_y_dot", real=True)
phi_x, phi_y, psi = sp.symbols("phi_x phi_y psi", real=True)
phi_x_dot, phi_y_dot, psi_dot = sp.symbols("phi_x_dot phi_y_dot psi_dot", real=True)
lat, lon = sp.symbols("phi_i lambda", real=True)
lat_dot, lon_dot = sp.symbols("phi_i_dot lambda_dot", real=True)
lat_ddot, lon_ddot = sp.symbols("phi_i_ddot lambda_ddot", real=True)
p_m, q_m, r_m = sp.symbols("p_m q_m r_m", real=True)

# constants
omega_e = sp.Symbol("omega_e", positive=True)
GM, R_G = sp.symbols("GM R_G", positive=True)
R, g = sp.symbols("R g_i", positive=True)

# end of alignment / start of navigation (eqs. 20-27)
alpha_T, alpha = sp.symbols("alpha_T alpha", real=True)
theta_F1, theta_F2 = sp.symbols("theta_F1 theta_F2", real=True)
b_a1, b_a2 = sp.symbols("b_a1 b_a2", real=True)
b_g1, b_g2, b_g3, b_psi = sp.symbols("b_g1 b_g2 b_g3 b_psi", real=True)
b_g1_dot, b_g2_dot = sp.symbols("b_g1_dot b_g2_dot", real=True)
r0m, r0p = sp.symbols("r_0m r_0p", real=True)  # r(0-), r(0+)
psi0 = sp.Symbol("psi_0", real=True)
d_r = sp.Symbol("d_r", real=True)

# error analysis (eqs. 28-36)
k_sh = sp.Symbol("k_sh", positive=True)
k_g, R_GMM = sp.symbols("k_g R_GMM", real=True)
k_I, k_G, k_F = sp.symbols("k_I k_G k_F", positive=True)
A, B, A2, B2 = sp.symbols("A B A' B'", real=True)  # eq. 30 constants (A', B' for phi_y)
Amp, W = sp.symbols(
    "A_3 W", real=True
)  # eq. 35: A = b_g3 omega_e cos(phi_i0), W = omega_e sin(phi_i0)
ca, cb, ca2, cb2 = sp.symbols("a b a' b'", real=True)  # eq. 36 coefficients

# Table 2 (Pitman's stable-platform error responses)
omega0, R0 = sp.symbols("omega_0 R_0", positive=True)
B_x, phi_y0, k_x, dV_x = sp.symbols("B_x phi_y0 k_x DeltaV_x", real=True)
eps_y, eps_z, eps_z_p = sp.symbols("epsilon_y epsilon_z epsilon_z'", real=True)
v_x, v_y, dxdot0, phi_z0, VI_c = sp.symbols("v_x v_y Deltaxdot_0 phi_z0 VI_c", real=True)

# unit vectors of the m_N frame: north, west, up (along mass attraction); see kinematics
TILTS = (phi_x, phi_y)
