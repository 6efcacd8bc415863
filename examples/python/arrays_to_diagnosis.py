"""From arrays to a diagnosed model, with the documented Python API only.

A first-order system with an output offset that nobody declares is
measured (numpy arrays, noise of known RMS). The script
  1. fits a linear model without offset (lpvid.fit_linear) -> "before";
  2. diagnoses it on the estimation record with a separate test record
     (lpvid.diagnose): the residual is traced to the missing offset, which
     is added and re-fitted -> "after", with certified bounds;
  3. compares both models on the test record (lpvid.compare);
  4. verifies every certificate exactly (lpvid.verify), also after saving
     and loading one;
  5. checks that no folder was left behind, and (with --ctrl-c) that a
     Ctrl-C stops a running diagnose and leaves nothing.
With a folder argument the figures are saved there as PNG.

Usage: python3 arrays_to_diagnosis.py [--ctrl-c] [FIGURE_DIR]
Exit code 0 when every step gave the expected answer.
"""

import os
import signal
import sys
import tempfile
import threading
import time

import numpy as np

import lpvid

OFFSET, NOISE = 0.8, 0.02


def measure(n, seed):
    """x+ = 0.7 x + 0.5 u, y = x + OFFSET + noise (the offset undeclared)."""
    rng = np.random.default_rng(seed)
    u = np.repeat(rng.uniform(-1, 1, n // 5 + 1), 5)[:n]  # held steps: the offset is visible at low frequency
    x, y = 0.0, np.empty(n)
    for k in range(n):
        y[k] = x
        x = 0.7 * x + 0.5 * u[k]
    return u, y + OFFSET + NOISE * rng.standard_normal(n)


def leftovers():
    return sorted(n for n in os.listdir(tempfile.gettempdir()) if n.startswith("lpvid-"))


def ctrl_c_during_diagnose(u, y, model):
    """Sends SIGINT to this process 2 s into a diagnose; returns the seconds
    from the signal to the KeyboardInterrupt."""
    sent = {}

    def interrupt():
        sent["at"] = time.monotonic()
        os.kill(os.getpid(), signal.SIGINT)

    # A program started in the background by a non-interactive shell inherits
    # SIGINT as ignored, and Python then installs no KeyboardInterrupt handler:
    # install Python's own for this step, so the launcher cannot decide it.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    threading.Timer(2.0, interrupt).start()
    try:
        lpvid.diagnose(model=model, u=u, y=y, quiet=True)
    except KeyboardInterrupt:
        return time.monotonic() - sent["at"]
    finally:
        signal.signal(signal.SIGINT, previous)
    raise SystemExit("the diagnose ended before the Ctrl-C: nothing was measured")


def main(argv):
    check_ctrl_c = "--ctrl-c" in argv
    figures = [a for a in argv if not a.startswith("--")]
    before_run = leftovers()
    u, y = measure(300, 1)
    u_test, y_test = measure(200, 2)

    before = lpvid.fit_linear(u=u, y=y, order=1)
    print(f"1. fit_linear: {before}")

    d = lpvid.diagnose(model=before, u=u, y=y, test=(u_test, y_test), max_effects=1, quiet=True)
    print(f"2. diagnose: effects {[e.get('kind') for e in d.effects]}; test RMS {d.rms_before:.4f} -> "
          f"{d.rms_after:.4f} (fit {d.fit_before:.1f} -> {d.fit_after:.1f} %); certified delta <= {d.delta:.3g}, "
          f"dmax <= {d.dmax:.3g}, {len(d.certificates)} certificates")
    assert d.rms_after < 0.5 * d.rms_before, "the offset was not found"

    c = lpvid.compare(models={"before": before, "after": d.model}, u=u_test, y=y_test, quiet=True)
    for s in c.scores:
        print(f"3. compare: {s.name:7s} RMS {s.rms:.4f}  fit {s.fit_percent:.1f} %")
    assert c.score("after").rms < c.score("before").rms

    ok = [bool(lpvid.verify(cert)) for cert in d.certificates]
    with tempfile.TemporaryDirectory() as keep:
        saved = d.certificates[0].save(os.path.join(keep, "after.cert.json"))
        ok.append(bool(lpvid.Certificate.load(saved).verify()))
    print(f"4. verify: {sum(ok)} of {len(ok)} certificates hold (checked in exact rational arithmetic)")
    assert all(ok)

    if figures:
        os.makedirs(figures[0], exist_ok=True)
        for name, fig in {**d.plot(), **c.plot()}.items():
            fig.savefig(os.path.join(figures[0], f"{name}.png"), dpi=100)
        print(f"   figures in {figures[0]}")

    if check_ctrl_c:
        seconds = ctrl_c_during_diagnose(u, y, before)
        print(f"5. Ctrl-C during diagnose: stopped {seconds:.2f} s after the signal")
        assert seconds < 2.0, "Ctrl-C took longer than 2 s"
    assert leftovers() == before_run, f"folders left behind: {sorted(set(leftovers()) - set(before_run))}"
    print("   no folder left behind")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
