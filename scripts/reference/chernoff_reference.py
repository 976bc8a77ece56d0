#!/usr/bin/python3
"""Reference values for the tests of shockgas/compare/airy.cpp and shockgas/compare/chernoff.cpp.

Writes three tables into tests/compare/data/ (or the directory given):

  airy_reference.csv      Ai(z) and Ai'(z) at complex z from SciPy (scipy.special.airy,
                          the AMOS library): rings |z| = r over all arguments, so that
                          every method of airy.cpp and every switch between them is crossed.
  chernoff_g_reference.csv  g(x) of Chernoff's density f(z) = g(z) g(-z) / 2 at 30 digits
                          with mpmath: the inverse Fourier transform of
                          2^(1/3) / Ai(i 2^(-1/3) s), written as the contour integral
                              g(x) = 2^(2/3)/pi int_0^inf Re[exp(-2^(1/3) x u) / Ai(u)] dy,
                              u = c + i y,
                          on lines c that airy.cpp / chernoff.cpp do not use (c = -1 for
                          x < 0, which needs no residue, and c = 1.1 * 2^(2/3) x^2 + 0.3 for
                          x >= 0), with mpmath's own Airy function and quadrature.
  cluster_mass_reference.csv  the mass-weighted cluster velocity density P_mass(u) of
                          cluster_velocity_law.hpp from scripts/reference/exact_laws.py (SciPy's
                          Airy function and zeros, the zero sum with the density of the
                          far zeros instead of a small-mu expansion).

Run with Debian's Python (it has numpy, scipy and mpmath); about 4 minutes:
    /usr/bin/python3 scripts/reference/chernoff_reference.py [out_dir]
"""
import os
import sys

import mpmath as mp
import numpy as np
from scipy.special import airy

RINGS = [0.3, 0.99, 1.01, 2.0, 4.0, 6.0, 8.9, 9.1, 12.0, 20.0, 40.0]
ANGLES = 24  # per ring, from -pi to pi
G_POINTS = [-6, -4.5, -3.5, -3, -2.5, -2, -1.5, -1, -0.7, -0.4, -0.2, -0.05, 0,
            0.05, 0.2, 0.4, 0.7, 1, 1.5, 2, 2.5, 3, 3.5, 4.5, 6]


def write_airy(path):
    z = np.array([r * np.exp(1j * th) for r in RINGS
                  for th in np.linspace(-np.pi, np.pi, ANGLES + 1)])
    ai, aip, _, _ = airy(z)
    with open(path, "w") as f:
        f.write("# re_z,im_z,re_ai,im_ai,re_aip,im_aip  (scipy.special.airy %s)\n" % __import__("scipy").__version__)
        for zz, a, ap in zip(z, ai, aip):
            f.write("%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n" % (zz.real, zz.imag, a.real, a.imag, ap.real, ap.imag))


def g_reference(x):
    mp.mp.dps = 40
    x = mp.mpf(x)
    k = mp.cbrt(2)
    c = mp.mpf(-1) if x < 0 else mp.mpf("1.1") * k * k * x * x + mp.mpf("0.3")

    def integrand(y):
        u = mp.mpc(c, y)
        return mp.re(mp.exp(-k * x * u) / mp.airyai(u))

    # |1/Ai(c + iy)| ~ exp(-(sqrt 2/3) y^(3/2)): negligible (< 1e-40 of the peak) past y_end.
    y_end = 30 + 4 * abs(float(c)) ** 0.5
    edges = mp.linspace(0, y_end, 61)
    return k * k / mp.pi * mp.quad(integrand, edges)


def write_g(path):
    with open(path, "w") as f:
        f.write("# x,g(x)  (mpmath %s, 40 digits)\n" % mp.__version__)
        for x in G_POINTS:
            f.write("%s,%s\n" % (repr(float(x)), mp.nstr(g_reference(x), 20)))


U_POINTS = [-2.5, -1.5, -0.7, 0, 0.3, 0.5, 1, 1.5, 2, 2.5, 3]


def write_cluster(path):
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import exact_laws
    with open(path, "w") as f:
        f.write("# u,P_mass(u)  (scripts/reference/exact_laws.py, scipy %s)\n" % __import__("scipy").__version__)
        for u in U_POINTS:
            f.write("%s,%.15g\n" % (repr(float(u)), exact_laws.cluster_mass_density(u)))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "tests", "compare", "data")
    os.makedirs(out, exist_ok=True)
    write_airy(os.path.join(out, "airy_reference.csv"))
    write_g(os.path.join(out, "chernoff_g_reference.csv"))
    write_cluster(os.path.join(out, "cluster_mass_reference.csv"))


if __name__ == "__main__":
    main()
