#!/usr/bin/env python3
"""The Python package's call overhead (issue 30): `antkit.check_stc` on a 1024 x 1024 sub-cell
map's offline tour (1 048 576 positions, an (n, 2) int32 numpy array) against the same check in
C++ (antkit_bench's BM_CheckStc1024: testing::check_stc on the tour in memory), both measured in
this one run, each the fastest of N repeats.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/python_overhead.py \
        build/release/bench/antkit_bench [N]
"""
import json
import subprocess
import sys
import time

import numpy as np

import antkit


def main() -> None:
    bench = sys.argv[1]
    repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 10
    m = antkit.Map.from_array(np.ones((1024, 1024), dtype=bool))
    path = antkit.stc(m, "offline", start=(0, 0)).path
    python_s = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        r = antkit.check_stc(m, path, start=(0, 0))
        python_s.append(time.perf_counter() - t0)
        assert r.ok and r.covered == 1024 * 1024
    out = subprocess.run(
        [bench, "--benchmark_filter=^BM_CheckStc1024$", "--benchmark_format=json",
         f"--benchmark_repetitions={repeats}", "--benchmark_report_aggregates_only=false"],
        check=True, capture_output=True, text=True,
    ).stdout
    runs = [b for b in json.loads(out)["benchmarks"] if b.get("run_type") == "iteration"]
    cpp_s = min(b["real_time"] for b in runs) / 1000.0  # reported in ms
    py = min(python_s)
    print(f"positions: {len(path)}")
    print(f"C++    testing::check_stc   {cpp_s * 1000:8.2f} ms (fastest of {len(runs)})")
    print(f"Python antkit.check_stc     {py * 1000:8.2f} ms (fastest of {repeats})")
    print(f"Python / C++: {py / cpp_s:.3f}  (overhead {1000 * (py - cpp_s):.2f} ms per call, "
          f"{1e9 * (py - cpp_s) / len(path):.1f} ns per position)")


if __name__ == "__main__":
    main()
