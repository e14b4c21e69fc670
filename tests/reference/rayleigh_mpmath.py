"""Reference values for the Rayleigh root m_R = c_R/c1, independent of the Rust code.

Solves R(xi) = 4 - K^2 |p1| |p2| = 0 on (0, m) directly (K = 2 - xi^2/m^2,
|p_k| = (1 - xi^2/m_k^2)^(-1/2)) with mpmath at 100 digits and prints 80 digits.
Run: python3 tests/reference/rayleigh_mpmath.py > tests/reference/rayleigh.txt
"""
from mpmath import mp, mpf, sqrt, findroot

mp.dps = 100


def m_r(m):
    def r(x):
        k = 2 - x * x / (m * m)
        return 4 * sqrt((1 - x * x) * (1 - x * x / (m * m))) - k * k
    # bracket just below m (R > 0 on (0, m_R), < 0 on (m_R, m))
    return findroot(r, (mpf("0.5") * m, m * (1 - mpf(10) ** -6)), solver="anderson")


cases = [("paper", mpf(1000) / mpf("1870.83")), ("m0.5", mpf("0.5")), ("m0.3", mpf("0.3"))]
for name, m in cases:
    print(name, mp.nstr(m, 80), mp.nstr(m_r(m), 80))
