#!/usr/bin/env python3
"""Compact dual certificates with t or mu moved by a few ulps.

A verifier built elsewhere (another compiler, SIMD width or BLAS) rebuilds
the compact dual's U = mu (t I - T T^T)^-1 with other last bits
(docs/dual_certificates.md, "Portable acceptance"). Moving the stored t or mu
by k units in the last place of their doubles moves U at least as much as
such a rebuild typically does (a floating inverse of the nearly singular
t I - T T^T errs along its top eigenvector, like a change of t), so a builder
whose certificates survive these moves leaves a portable margin.

For each certificate (form dual_delta_path) and each move (t or mu by
+-1, +-2, +-4 ulps) a copy is written next to it and checked with
`lpvid-verify certificate`; the table counts the copies it rejects.

    python3 bench/ulp_moved_duals.py build/lpvid-verify C1.json C2.json ...
    python3 bench/ulp_moved_duals.py build/lpvid-verify C.json -- --max-dual-order 3200

Arguments after "--" are passed to `lpvid-verify certificate` (its limits).
"""
import json
import math
import os
import subprocess
import sys
from fractions import Fraction


def moved(text, ulps):
    """The exact rational of the double nearest `text`, moved by `ulps` ulps."""
    d = float(Fraction(text))
    step = math.inf if ulps > 0 else 0.0
    for _ in range(abs(ulps)):
        d = math.nextafter(d, step)
    f = Fraction(d)
    return f"{f.numerator}/{f.denominator}" if f.denominator != 1 else str(f.numerator)


def check(verify, path, extra):
    run = subprocess.run([verify, "certificate", path] + extra, capture_output=True, text=True)
    return run.returncode, (run.stdout + run.stderr).strip().splitlines()[-1:] or [""]


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    args = sys.argv[2:]
    extra = args[args.index("--") + 1:] if "--" in args else []
    verify, certs = sys.argv[1], args[:args.index("--")] if "--" in args else args
    total = rejected = 0
    print(f"{'certificate':40s} {'moves':>5s} {'rejected':>8s}  first rejection")
    for cert in certs:
        with open(cert) as f:
            c = json.load(f)
        if c.get("form") != "dual_delta_path":
            print(f"{os.path.basename(cert):40s} (form {c.get('form')}: skipped)")
            continue
        bad, first = 0, ""
        moves = 0
        for key in ("t", "mu"):
            for ulps in (-4, -2, -1, 1, 2, 4):
                m = json.loads(json.dumps(c))
                m["dual"][key] = moved(c["dual"][key], ulps)
                out = os.path.join(os.path.dirname(os.path.abspath(cert)),
                                   f".moved_{key}_{ulps:+d}_" + os.path.basename(cert))
                with open(out, "w") as f:
                    json.dump(m, f)
                code, last = check(verify, out, extra)
                os.remove(out)
                moves += 1
                if code != 0:
                    bad += 1
                    first = first or f"{key} {ulps:+d}: exit {code} {last[0][:80]}"
        total += moves
        rejected += bad
        print(f"{os.path.basename(cert):40s} {moves:5d} {bad:8d}  {first}")
    print(f"rejected {rejected} of {total}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
