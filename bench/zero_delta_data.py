#!/usr/bin/env python3
"""The SISO example of bench/README.md, "invalidate --delta 0": an LPV first-order system
y[k+1] = (0.5 + 0.2 rho[k]) y[k] + u[k], rho = sin(0.1 k), u ~ N(0, 1) (seed 1), plus noise of
standard deviation 0.01; the model is the generating one without an uncertainty key.

    python3 bench/zero_delta_data.py DIR [N]      # DIR/data.csv (N rows, default 200), DIR/model.json

Then `lpvid invalidate --data DIR/data.csv --model DIR/model.json --delta 0` answers in closed form
(docs/dual_certificates.md, "The delta = 0 lower end"). Needs numpy.
"""
import json
import os
import sys

import numpy as np


def main(argv):
    if len(argv) not in (2, 3):
        print(__doc__, file=sys.stderr)
        return 2
    out, n = argv[1], int(argv[2]) if len(argv) == 3 else 200
    os.makedirs(out, exist_ok=True)
    rng = np.random.default_rng(1)
    u = rng.standard_normal(n)
    rho = np.sin(0.1 * np.arange(n))
    y = np.zeros(n)
    for k in range(n - 1):
        y[k + 1] = (0.5 + 0.2 * rho[k]) * y[k] + u[k]
    y += 0.01 * rng.standard_normal(n)
    with open(os.path.join(out, "data.csv"), "w") as f:
        f.write("u,y,rho\n" + "".join(f"{a!r},{b!r},{c!r}\n" for a, b, c in zip(u, y, rho)))
    model = {"format": "lpvid-model/1", "states": 1, "inputs": 1, "outputs": 1, "scheduling": ["rho"],
             "columns": {"u": ["u"], "y": ["y"]},
             "initial": {"A": [{"basis": "1", "value": [[0.5]]}, {"basis": "rho", "value": [[0.2]]}],
                         "B": [{"basis": "1", "value": [[1]]}], "C": [{"basis": "1", "value": [[1]]}]}}
    with open(os.path.join(out, "model.json"), "w") as f:
        json.dump(model, f)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
