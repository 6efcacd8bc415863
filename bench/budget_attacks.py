#!/usr/bin/env python3
"""Certificates that would keep lpvid-verify busy for a long time, to time
its total work budget (--max-total-work, --max-records; docs/exit_codes.md,
"The total work of a check"). Every file is written into DIR (use /tmp: the
big ones are tens of MB).

    python3 bench/budget_attacks.py class LEAVES ORDER DIR
        DIR/class_LEAVES_ORDER.json: a class lower bound over a box of the
        SISO model's three output corrections, a tree of LEAVES leaves, each
        a compact dual point of horizon ORDER (on DIR/class_ORDER.csv).
    python3 bench/budget_attacks.py records COUNT ROWS DIR
        DIR/records_COUNT.json: COUNT records of ROWS rows each, all windows
        of one data file DIR/records_COUNT.csv (COUNT*ROWS rows).
    python3 bench/budget_attacks.py long ROWS RECORDS DIR
        DIR/long_ROWS_RECORDS.json: RECORDS records of ROWS rows each (one:
        "data"), form "delta" on the last 16 rows, the model started from
        x0 = [1, 1]: the exact simulation's numbers grow with k over every row.
The claims are not true; what is timed is how long the verifier takes to say so.
"""
import hashlib
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fabricated_dual import MODEL, lcg  # noqa: E402


def write_data(path, n, seed):
    r = lcg(seed)
    text = "u,y\n" + "".join("%s,%s\n" % ("1" if k == 0 else next(r), next(r)) for k in range(n))
    with open(path, "w") as f:
        f.write(text)
    return hashlib.sha256(text.encode()).hexdigest()


def write_json(path, cert):
    with open(path, "w") as f:
        json.dump(cert, f, separators=(",", ":"))


def primal(reference, horizon):
    cert = {"format": "lpvid-certificate/1", "claim": "consistent"}
    cert.update(reference)
    cert.update({"model": MODEL, "toeplitz_mode": "signal", "noise_normalisation": "rms", "delta2": "0.01",
                 "dmax2": "0.01", "form": "delta", "delta_taps": [[0]], "delta_horizon": horizon})
    return cert


def class_tree(leaves, order, g):
    """Preorder: a balanced tree over parameter 0, LEAVES leaves."""
    def leaf():
        return {"leaf": {"epsilon": "1", "horizon": order, "sigma": "1", "g": [[0] for _ in range(order)],
                         "taps": [[0] for _ in range(order)], "t": "1", "mu": "1", "u_exponent": -51, "x": "1e30",
                         "u_floor": "0.5"}}

    def tree(count):
        if count == 1:
            return [leaf()]
        return [{"split": 0}] + tree(count // 2) + tree(count - count // 2)
    return tree(leaves)


def attack_class(leaves, order, folder):
    data = os.path.join(folder, "class_%d.csv" % order)
    sha = write_data(data, order, order)
    names = ["C[1](1,1)", "C[1](1,2)", "D[1](1,1)"]
    cert = {"format": "lpvid-certificate/1", "claim": "class_lower_bound",
            "data": {"file": os.path.basename(data), "sha256": sha}, "model": MODEL, "toeplitz_mode": "signal",
            "noise_normalisation": "rms", "objective": "min_dmax", "delta2": "0.2025", "lower_bound": "0",
            "form": "dual_delta_path",
            "class": {"unknowns": {"correction": True, "offset": False, "x0": False}, "parameters": names, "free": [],
                      "center": ["0"] * 3, "radius": ["1/100"] * 3, "horizon": order,
                      "nodes": class_tree(leaves, order, lcg(order + 1))}}
    write_json(os.path.join(folder, "class_%d_%d.json" % (leaves, order)), cert)


def attack_records(count, rows, folder):
    data = os.path.join(folder, "records_%d.csv" % count)
    sha = write_data(data, count * rows, count)
    records = [{"file": os.path.basename(data), "sha256": sha, "rows": [k * rows, (k + 1) * rows]} for k in range(count)]
    write_json(os.path.join(folder, "records_%d.json" % count), primal({"records": records}, rows))


def attack_long(rows, count, folder):
    """The model starts from x0 = [1, 1] and u is zero but on the last TAIL
    rows: z = 0.1*u vanishes before them, so the Delta horizon (and the (C1)
    check) stays short while the state's digits grow over every row."""
    tail = 16
    data = os.path.join(folder, "long_%d.csv" % rows)
    r = lcg(rows)
    text = "u,y\n" + "".join("%s,%s\n" % (next(r) if k >= rows - tail else "0", next(r)) for k in range(rows))
    with open(data, "w") as f:
        f.write(text)
    reference = {"file": os.path.basename(data), "sha256": hashlib.sha256(text.encode()).hexdigest()}
    cert = primal({"data": reference} if count == 1 else {"records": [reference] * count}, tail)
    cert["model"] = dict(MODEL, x0=["1", "1"])
    write_json(os.path.join(folder, "long_%d_%d.json" % (rows, count)), cert)


if __name__ == "__main__":
    if len(sys.argv) == 5 and sys.argv[1] in ("class", "records", "long"):
        os.makedirs(sys.argv[4], exist_ok=True)
        run = {"class": attack_class, "records": attack_records, "long": attack_long}[sys.argv[1]]
        run(int(sys.argv[2]), int(sys.argv[3]), sys.argv[4])
    else:
        sys.exit(__doc__)
