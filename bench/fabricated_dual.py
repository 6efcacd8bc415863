#!/usr/bin/env python3
"""Hostile compact dual certificates ("dual_delta_path") for timing
lpvid-verify's limits (bench/README.md, "Hostile compact dual certificates").

    python3 bench/fabricated_dual.py rows N DIR
        DIR/fab_N.csv (N rows of a SISO record) and DIR/fab_N.json: a
        fabricated lower-bound certificate on it (zero taps, t = mu = 1,
        so U = I): about 25 bytes per row, yet it makes the verifier rebuild
        an N x N matrix U in floating point.
    python3 bench/fabricated_dual.py floor CERT OUT VALUE
        CERT with dual.u_floor replaced by VALUE; "mu/t" is mu/t exactly, a
        lower bound of lambda_min(mu*(t*I - T*T^T)^-1), and "mu/t:EPS" is
        mu/t*(1 - EPS): so close below lambda_min(U) that the floating filter
        cannot prove U - u_floor*I PSD and the exact elimination decides.
The claims are not true; what is timed is how long the verifier takes to say so.
"""
import hashlib
import json
import os
import re
import sys
from fractions import Fraction

MODEL = {
    "format": "lpvid-model/1", "states": 2, "inputs": 1, "outputs": 1, "scheduling": [],
    "columns": {"u": ["u"], "y": ["y"], "rho": []},
    "initial": {"A": [{"basis": "1", "value": [[0, 1], ["-0.12", "0.7"]]}],
                "B": [{"basis": "1", "value": [[0], [1]]}],
                "C": [{"basis": "1", "value": [["0.25", "0.5"]]}], "D": []},
    "correction": {"basis": ["1"]},
    "uncertainty": {"structure": "additive", "weight": "0.1"},
}


def lcg(seed):
    """Deterministic values in (-1, 1) with 4 decimals."""
    x = seed
    while True:
        x = (1103515245 * x + 12345) % 2**31
        yield "%.4f" % (2.0 * x / 2**31 - 1.0)


def rows(n, folder):
    os.makedirs(folder, exist_ok=True)
    data = os.path.join(folder, "fab_%d.csv" % n)
    r = lcg(n)
    text = "u,y\n" + "".join("%s,%s\n" % ("1" if k == 0 else next(r), next(r)) for k in range(n))
    with open(data, "w") as f:
        f.write(text)
    g = lcg(n + 1)
    cert = {
        "format": "lpvid-certificate/1", "claim": "lower_bound",
        "data": {"file": os.path.basename(data), "sha256": hashlib.sha256(text.encode()).hexdigest()},
        "model": MODEL, "toeplitz_mode": "signal", "noise_normalisation": "rms",
        "objective": "min_dmax", "delta2": "0.2025", "lower_bound": "0", "form": "dual_delta_path",
        "dual": {"horizon": n, "sigma": "1", "g": [[next(g)] for _ in range(n)], "t": "1", "mu": "1",
                 "u_exponent": -51, "x": "1e30", "u_floor": "0.5", "taps": [[0] for _ in range(n)]},
    }
    with open(os.path.join(folder, "fab_%d.json" % n), "w") as f:
        json.dump(cert, f, separators=(",", ":"))


def floor(src, out, value):
    text = open(src).read()
    if value.startswith("mu/t"):
        dual = json.loads(text)["dual"]
        q = Fraction(dual["mu"]) / Fraction(dual["t"])
        if ":" in value:
            q *= 1 - Fraction(value.split(":")[1])
        value = "%d/%d" % (q.numerator, q.denominator)
    text, count = re.subn(r'"u_floor": *"[^"]*"', '"u_floor": "%s"' % value, text)
    if count != 1:
        sys.exit("no dual.u_floor in " + src)
    with open(out, "w") as f:
        f.write(text)


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "rows":
        rows(int(sys.argv[2]), sys.argv[3])
    elif len(sys.argv) == 5 and sys.argv[1] == "floor":
        floor(sys.argv[2], sys.argv[3], sys.argv[4])
    else:
        sys.exit(__doc__)
