"""Symbols of the north-finding paper, named as the paper names them.

=========  ==========================================================
symbol     meaning (paper's notation)
=========  ==========================================================
psi        yaw / azimuth psi (rad)
theta      pitch theta (rad)
phi        roll phi (rad)
lam        geodetic latitude lambda (rad)
Omega      Earth rate omega^{EI} (rad/s)
g          magnitude of plumb-bob gravity (m/s^2)
tau        table angle tau of frame B about z_T (rad)
l          lever arm of the sensor along x_B (m)
w, w_dot   table rate omega and angular acceleration omega-dot
S, b       scale factor S = 1 + sf and bias b of the single sensor
sf         scale-factor error
MA_ij      misalignment of the sensor on axis i towards axis j (rad)
=========  ==========================================================

Readings: ``ax_<deg>`` is the accelerometer on x_B at table angle <deg>,
``ay_<deg>`` the same sensor mounted on y_B, ``az`` the sensor turned into z_B;
``wx_<deg>``, ``wz`` likewise for the gyro; ``wx_max`` the largest gyro reading
found by turning the table (azimuth method 3).
"""

from __future__ import annotations

import sympy as sp

psi, theta, phi, lam = sp.symbols("psi theta phi lambda", real=True)
Omega, g = sp.symbols("Omega g", positive=True)
tau, l, w, w_dot = sp.symbols("tau l omega omega_dot", real=True)
t = sp.Symbol("t", real=True)
S, b, sf = sp.symbols("S b sf", real=True)
MA_xy, MA_xz, MA_yx, MA_yz, MA_zx, MA_zy = sp.symbols(
    "MA_xy MA_xz MA_yx MA_yz MA_zx MA_zy", real=True
)

# accelerometer readings
ax_0, ax_90, ax_180, ax_270 = sp.symbols("ax_0 ax_90 ax_180 ax_270", real=True)
ay_0, ay_90, ay_180, ay_270 = sp.symbols("ay_0 ay_90 ay_180 ay_270", real=True)
az = sp.Symbol("az", real=True)
a_tau = sp.Symbol("a_tau", real=True)  # reading at an arbitrary tau

# gyro readings
wx_0, wx_90, wx_180, wx_270 = sp.symbols("wx_0 wx_90 wx_180 wx_270", real=True)
wz = sp.Symbol("wz", real=True)
w_tau = sp.Symbol("w_tau", real=True)  # reading at an arbitrary tau
wx_max = sp.Symbol("wx_max", positive=True)

# bias-free accelerometer components of levelling method 5 (eqs. 29, 31)
a1, a2, a3 = sp.symbols("a_1 a_2 a_3", real=True)

# normalised bias-free readings of azimuth methods 4-6 (eqs 56, 69)
om1, om2, om3 = sp.symbols("omega_1 omega_2 omega_3", real=True)

# generic coefficients of a sin(x) + b cos(x) = c (eqs 41, 43)
ca, cb, cc = sp.symbols("a b c", real=True)

# unknowns solved for by the levelling methods
s_theta, c_theta_s_phi = sp.symbols("s_theta cth_sphi", real=True)

ANGLES = (psi, theta, phi)
