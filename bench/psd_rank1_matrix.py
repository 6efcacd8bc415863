#!/usr/bin/env python3
"""Writes M = v v^T + s * 10^-e * I (s = -1 or +1) for `lpvid-verify psd`.

The hard cases for the exact decision: with s = -1 the matrix is NOT_PSD (for x with
x.v = 0, x^T M x = -10^-e |x|^2 < 0) but every floating-point view of it is
the rank-1 matrix v v^T, so the filter finds no negative direction and the
full exact path needs thousands of primes; with s = +1 it is PD (v v^T is PSD
and 10^-e I is PD) for the same reason out of the filter's reach.

    python3 bench/psd_rank1_matrix.py --n 2000 --sign -1 --out /tmp/M.txt
    python3 bench/psd_rank1_matrix.py --n 2000 --v random --seed 1 --out /tmp/M.txt

v: "mod17" (v_i = (i mod 17) + 1, i 0-based) or "random" (short decimals
d.dd in [0.01, 9.99], fixed seed). With "mod17", fl(M) = v v^T exactly and
the filter's Cholesky meets an exact zero pivot whose direction is an exact
witness; with "random", fl(v_i v_j) carries rounding errors far above
10^-e, so no floating direction survives the exact check (the hard case). Entries are exact decimals (the file
format of verify/psd/rational_matrix_io.h); the diagonal v_i^2 + s 10^-e is
written with all e fractional digits.
"""
import argparse
import random
from fractions import Fraction as F


def decimal(x, digits):
    """Exact decimal text of the rational x whose denominator divides 10^digits."""
    scaled = x * 10**digits
    assert scaled.denominator == 1, x
    n = scaled.numerator
    sign = "-" if n < 0 else ""
    n = abs(n)
    if digits == 0:
        return sign + str(n)
    whole, frac = divmod(n, 10**digits)
    frac_text = str(frac).rjust(digits, "0").rstrip("0")
    return sign + str(whole) + ("." + frac_text if frac_text else "")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, default=2000)
    ap.add_argument("--exponent", type=int, default=50, help="e in 10^-e (default 50)")
    ap.add_argument("--sign", type=int, choices=(-1, 1), default=-1)
    ap.add_argument("--v", choices=("mod17", "random"), default="mod17")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    if a.v == "mod17":
        v = [F(i % 17 + 1) for i in range(a.n)]
    else:
        rng = random.Random(a.seed)
        v = [F(rng.randint(1, 999), 100) for _ in range(a.n)]
    shift = a.sign * F(1, 10**a.exponent)
    digits = max(a.exponent, 4)  # v_i v_j has at most 4 decimals
    with open(a.out, "w") as f:
        f.write(f"# M = v v^T {'-' if a.sign < 0 else '+'} 1e-{a.exponent} I, n = {a.n}, v = {a.v}"
                f"{' seed ' + str(a.seed) if a.v == 'random' else ''}"
                f" ({'NOT_PSD' if a.sign < 0 else 'PD'} by construction)\n")
        for i in range(a.n):
            row = [v[i] * v[j] for j in range(a.n)]
            row[i] += shift
            f.write(" ".join(decimal(x, digits if j == i else 4) for j, x in enumerate(row)) + "\n")


if __name__ == "__main__":
    main()
