#!/usr/bin/python3
"""The exact velocity laws of Burgers turbulence from white noise, with SciPy.

A second implementation, independent of shockgas/compare/airy.cpp, shockgas/compare/chernoff.cpp and
shockgas/compare/cluster_velocity_law.cpp (which are the reference; the formulas and their
derivations are in shockgas/compare/chernoff.hpp, eulerian_velocity_law.hpp
and cluster_velocity_law.hpp), for plots and cross-checks:

  g(x)   = 2^(2/3)/pi int_0^inf Re[exp(-2^(1/3) x u) / Ai(u)] dy,  u = c + i y
           (+ the residue 2^(2/3) exp(-2^(1/3) a_1 x) / Ai'(a_1) when c < a_1),
  f(z)   = g(z) g(-z) / 2                               (Chernoff's density),
  P_mass(u) = 2 int_0^inf mu^2 K(mu) g(mu/2 + u) g(mu/2 - u) dmu,
  K(mu)  = sum_k exp(2^(1/3) a_k mu),
and in shockgas units z = (v - <v>) t^(1/3) = (4 D)^(1/3) u.

Here Ai comes from scipy.special.airye (AMOS), the zeros from scipy.special.ai_zeros,
K by the direct sum over 20000 zeros and the density of the rest (no small-mu
expansion), the integrals by the trapezoidal rule and Gauss-Legendre.

Run it to print a few values:  /usr/bin/python3 scripts/reference/exact_laws.py
"""
import numpy as np
from scipy.special import ai_zeros, airye, gamma, gammaincc

CBRT2 = 2.0 ** (1.0 / 3.0)
CBRT4 = CBRT2 * CBRT2
_ZEROS = ai_zeros(20000)
A, AIP_AT_ZEROS = _ZEROS[0], _ZEROS[3]  # a_k and Ai'(a_k)


def g(x, h=0.05):
    """Groeneboom's g by the contour integral through the saddle (x >= 0) or between
    the first two zeros of Ai (x < 0, with the residue at a_1)."""
    residue = 0.0
    if x >= 0:
        c = max(CBRT4 * x * x, 0.5)
    else:
        c = 0.5 * (A[0] + A[1])
        residue = CBRT4 * np.exp(-CBRT2 * x * A[0]) / AIP_AT_ZEROS[0]
    y = np.arange(0.0, 60.0, h)
    u = c + 1j * y
    # exp(-k x u) / Ai(u) = exp(-k x u + zeta) / airye(u), zeta = (2/3) u^(3/2)
    zeta = (2.0 / 3.0) * u ** 1.5
    integrand = np.real(np.exp(-CBRT2 * x * u + zeta) / airye(u)[0])
    weights = np.full_like(y, h)
    weights[0] = h / 2
    return residue + CBRT4 / np.pi * np.sum(weights * integrand)


def chernoff_density(z):
    return 0.5 * g(z) * g(-z)


def zero_sum(mu):
    """K(mu) = sum_k exp(2^(1/3) a_k mu): the first 20000 zeros, then the rest as an
    integral over their density dk = |a|^(1/2) d|a| / pi (DLMF 9.9.6), from the midpoint
    b between |a_20000| and |a_20001|: (1/pi) s^(-3/2) Gamma(3/2, s b), s = 2^(1/3) mu."""
    s = CBRT2 * mu
    b = -A[-1] + 0.5 * np.pi / np.sqrt(-A[-1])
    return np.sum(np.exp(s * A)) + s ** -1.5 * gamma(1.5) * gammaincc(1.5, s * b) / np.pi


def _mu_nodes(panels=26, points=16, v_max=3.25):
    x, w = np.polynomial.legendre.leggauss(points)
    width = v_max / panels
    v = np.concatenate([width * (p + 0.5 + 0.5 * x) for p in range(panels)])
    wv = np.tile(0.5 * width * w, panels)
    return v * v, wv * 2 * v  # mu and d mu weights


_MU, _WMU = _mu_nodes()
_K = np.array([zero_sum(m) for m in _MU])


def cluster_mass_density(u, g_of=None):
    """P_mass(u) in scaled units; g_of: a vectorised g (default: interpolation table)."""
    g_of = g_of or _g_table
    return 2.0 * np.sum(_WMU * _MU ** 2 * _K * g_of(_MU / 2 + u) * g_of(_MU / 2 - u))


_GRID = np.linspace(-8.0, 7.0, 1501)
_LOG_G = None


def _g_table(x):
    """g by cubic interpolation of ln g on a grid of 0.01 (relative error < 1e-9)."""
    global _LOG_G
    if _LOG_G is None:
        from scipy.interpolate import CubicSpline
        _LOG_G = CubicSpline(_GRID, np.log([g(t) for t in _GRID]))
    x = np.asarray(x, dtype=float)
    return np.where(x > _GRID[-1], 0.0, np.exp(_LOG_G(np.clip(x, _GRID[0], _GRID[-1]))))


def scale(D):
    return (4.0 * D) ** (1.0 / 3.0)


def eulerian_density(z, D):
    s = scale(D)
    return np.array([chernoff_density(t / s) / s for t in np.atleast_1d(z)])


def cluster_density(z, D):
    s = scale(D)
    return np.array([cluster_mass_density(t / s) / s for t in np.atleast_1d(z)])


if __name__ == "__main__":
    for z in (0.0, 0.5, 1.0, 2.0):
        print("f(%g) = %.12g   P_mass(%g) = %.12g" % (z, chernoff_density(z), z, cluster_mass_density(z)))
