#!/usr/bin/python3
"""Prints the coefficients of the cube-root seed polynomial in core/getme/elements/cube_root.h.

CubeRoot (cube_root.h) seeds one Halley step with P(m − 1.5) ≈ ∛m on m ∈ [1, 2). P is the
least-squares fit, in the monomial basis, of ∛m at Chebyshev nodes of [1, 2) (close to the minimax
polynomial). Run it to check or change the constants; it also prints the seed's largest relative
error on a fine grid, which the Halley step cubes (cube_root.h says why that is enough).
"""
import numpy as np

DEGREE = 6
NODES = 256

k = np.arange(NODES)
m = 1.5 + 0.5 * np.cos(np.pi * (k + 0.5) / NODES)
coefficients = np.polynomial.polynomial.polyfit(m - 1.5, np.cbrt(m), DEGREE)
grid = np.linspace(1.0, 2.0, 1_000_001)
seed = np.polynomial.polynomial.polyval(grid - 1.5, coefficients)
print("max relative error of the seed: %.3g" % np.max(np.abs(seed / np.cbrt(grid) - 1.0)))
for c in coefficients:
    print("%.17g," % c)
