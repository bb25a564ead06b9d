"""Symbols of the IMU + altimeter attitude paper, named as the paper names them.

==================  ==============================================================
symbol              meaning (paper's notation)
==================  ==============================================================
t                   time (s)
phi, theta, psi     roll, pitch, yaw (3-2-1 Euler angles of C_b^n)
C11 .. C33          elements of C_b^n (body -> NED), eq. 2
c1, c2, c3          the third row of C_b^n, c = [C31 C32 C33]^T (eq. 13; zeta_1..3 of
                    the symbol list, c1..c3 in eq. 26)
a, b, cq, d         quaternion q_b^n = [a b c d]^T, scalar first (eq. 5); ``cq`` because
                    the paper's ``c`` clashes with the DCM row vector
wx, wy, wz          omega_nb^b, body rate relative to NED (eqs. 2-4, 7)
wtx, wty, wtz       gyro outputs after Earth-rate compensation (omega tilde, eq. 26)
fx, fy, fz          specific force f^b (true, eqs. 10-12, 24)
ftx, fty, ftz       accelerometer outputs (f tilde, eq. 26)
nwx .. naz          gyro and accelerometer white noise, w = [n_w; n_a] (eq. 26)
g                   gravity magnitude, g^n = [0, 0, g] (NED, down positive)
V_d, h              velocity down and altitude up (eqs. 24-25)
k, gamma            normalisation gain and error gamma = 1 - c^T c (eqs. 14-15)
k_p, k_i, omega_c   PI gains and cut-off of the complementary filter (eqs. 18-21)
xi                  damping ratio (eq. 20)
s                   Laplace variable (eqs. 18-19)
dt                  sample interval t_{k+1} - t_k (eqs. 29-30)
==================  ==============================================================

Vectors are sympy column matrices; ``c``, ``x`` (the state of eq. 26) and ``w`` are
built here so that every module uses the same objects.
"""

from __future__ import annotations

import sympy as sp

t = sp.Symbol("t", real=True)
phi, theta, psi = sp.symbols("phi theta psi", real=True)
C11, C12, C13, C21, C22, C23, C31, C32, C33 = sp.symbols(
    "C11 C12 C13 C21 C22 C23 C31 C32 C33", real=True
)
c1, c2, c3 = sp.symbols("c1 c2 c3", real=True)
a, b, cq, d = sp.symbols("a b c_q d", real=True)
wx, wy, wz = sp.symbols("omega_x omega_y omega_z", real=True)
wtx, wty, wtz = sp.symbols("omegat_x omegat_y omegat_z", real=True)
fx, fy, fz = sp.symbols("f_x f_y f_z", real=True)
ftx, fty, ftz = sp.symbols("ft_x ft_y ft_z", real=True)
nwx, nwy, nwz, nax, nay, naz = sp.symbols("n_wx n_wy n_wz n_ax n_ay n_az", real=True)
g = sp.Symbol("g", positive=True)
V_d, h = sp.symbols("V_d h", real=True)
k = sp.Symbol("k", positive=True)
gamma = sp.Symbol("gamma", real=True)
k_p, k_i, omega_c, xi = sp.symbols("k_p k_i omega_c xi", positive=True)
s = sp.Symbol("s")
dt = sp.Symbol("Delta_t", positive=True)
F_norm = sp.Symbol("f_norm", positive=True)  # ||f^b|| (eq. 17-b)

c = sp.Matrix([c1, c2, c3])
x = sp.Matrix([c1, c2, c3, V_d, h])  # state of eq. 26
omega = sp.Matrix([wx, wy, wz])
omega_t = sp.Matrix([wtx, wty, wtz])
f_b = sp.Matrix([fx, fy, fz])
f_t = sp.Matrix([ftx, fty, ftz])
n_w = sp.Matrix([nwx, nwy, nwz])
n_a = sp.Matrix([nax, nay, naz])
w = sp.Matrix([nwx, nwy, nwz, nax, nay, naz])  # noise vector of eq. 26
mat_C = sp.Matrix([[C11, C12, C13], [C21, C22, C23], [C31, C32, C33]])  # C_b^n, eq. 2
q = sp.Matrix([a, b, cq, d])
