#!/usr/bin/env python3
"""The same answer on every x86-64 CPU (ctest CpuVariants).

Libraries pick code paths by the CPU at run time: OpenBLAS its kernels
(OPENBLAS_CORETYPE forces one), glibc's libm its variants with and without
FMA/AVX2 (GLIBC_TUNABLES=glibc.cpu.hwcaps=-X masks a feature). lpvid's
choices and printed figures must not depend on them, nor on --threads. The
generated demo case (`lpvid generate effect-case --effect output_polynomial`,
scripts/demo.sh without measured data) is diagnosed under each variant
below; every report must equal the first one once timing fields are left
out, and the "after" model and every certificate must be byte for byte the
same. A variant whose CPU feature is missing on this machine (SkylakeX
without AVX-512) is skipped, saying so. lpvid pins OpenBLAS's kernels
(src/cli/blas_kernel.h); the test then runs SkylakeX once more with the pin
switched off and prints whether that differs (information, not a failure).

    python3 cpu_variants_test.py LPVID_EXE WORK_DIR
"""
import filecmp
import glob
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from reproducibility_test import first_difference, generate_case, strip_timing  # noqa: E402

NO_AVX512 = "glibc.cpu.hwcaps=-AVX512F,-AVX512VL,-AVX512BW,-AVX512DQ,-AVX512CD"
NO_AVX2_FMA = NO_AVX512 + ",-AVX2,-FMA,-FMA4"

# name, environment changes, --threads, CPU flag required
VARIANTS = [
    ("OPENBLAS_CORETYPE=Haswell, --threads 1", {"OPENBLAS_CORETYPE": "Haswell"}, 1, None),
    ("OPENBLAS_CORETYPE=SkylakeX", {"OPENBLAS_CORETYPE": "SkylakeX"}, 1, "avx512f"),
    ("OPENBLAS_CORETYPE=Sandybridge", {"OPENBLAS_CORETYPE": "Sandybridge"}, 1, "avx"),
    ("libm without AVX-512", {"GLIBC_TUNABLES": NO_AVX512}, 1, None),
    ("libm without AVX2 and FMA", {"GLIBC_TUNABLES": NO_AVX2_FMA}, 1, None),
    ("--threads 2", {}, 2, None),
]


def cpu_flags():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("flags"):
                    return set(line.split(":", 1)[1].split())
    except OSError:
        pass
    return set()


def main():
    exe, work = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    base = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    base.pop("GLIBC_TUNABLES", None)
    case = generate_case(exe, work, base, 400)
    flags = cpu_flags()
    runs = []
    for i, (name, env_changes, threads, flag) in enumerate(VARIANTS):
        if flag and flags and flag not in flags:
            print(f"  {name}: skipped (this CPU has no {flag})")
            continue
        d = f"{work}/v{i}"
        os.makedirs(d)
        cmd = [exe, "diagnose", "--data", case + "/est.csv", "--model", case + "/declared.json", "--test",
               case + "/test.csv", "--warmup", "10", "--max-effects", "2", "--max-windows", "2", "--threads",
               str(threads), "--report", d + "/r.report.json", "--model-out", d + "/after.json"]
        p = subprocess.run(cmd, env=dict(base, **env_changes), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        if p.returncode != 0:
            sys.exit(f"FAIL: diagnose under {name} exited {p.returncode}\n{p.stderr[-3000:]}")
        with open(d + "/r.report.json") as f:
            report = strip_timing(json.load(f), d)
        files = sorted(os.path.basename(c) for c in glob.glob(d + "/*.cert*.json")) + ["after.json"]
        runs.append((name, d, report, files))
        print(f"  {name}: ran", flush=True)
    ref_name, ref_dir, ref_report, ref_files = runs[0]
    if len(ref_files) < 2:
        sys.exit(f"FAIL: expected certificates beside the model, got {ref_files}")
    for name, d, report, files in runs[1:]:
        diff = first_difference(ref_report, report)
        if diff:
            sys.exit(f"FAIL: under {name} the report differs from {ref_name} (timing fields left out): {diff}")
        if files != ref_files:
            sys.exit(f"FAIL: under {name} the files differ: {files} vs {ref_files}")
        for c in files:
            if not filecmp.cmp(f"{ref_dir}/{c}", f"{d}/{c}", shallow=False):
                sys.exit(f"FAIL: {c} under {name} differs from {ref_name}")
    # Evidence that the pin matters (informational): the SkylakeX variant again with the pin
    # switched off (LPVID_BLAS_PINNED set: lpvid does not restart itself), on a CPU that has AVX-512.
    if "avx512f" in flags:
        d = f"{work}/unpinned"
        os.makedirs(d)
        subprocess.run([exe, "diagnose", "--data", case + "/est.csv", "--model", case + "/declared.json", "--test",
                        case + "/test.csv", "--warmup", "10", "--max-effects", "2", "--max-windows", "2", "--threads",
                        "1", "--report", d + "/r.report.json", "--model-out", d + "/after.json"],
                       env=dict(base, OPENBLAS_CORETYPE="SkylakeX", LPVID_BLAS_PINNED="1"),
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        try:
            with open(d + "/r.report.json") as f:
                diff = first_difference(ref_report, strip_timing(json.load(f), d))
        except (OSError, ValueError):
            diff = "no report"
        print("  without the pinned BLAS kernels, SkylakeX: " + (f"differs ({diff})" if diff else "the same"))
    print(f"PASS: {len(runs)} variants, reports equal without timing fields, {len(ref_files)} files byte for byte equal")


if __name__ == "__main__":
    main()
