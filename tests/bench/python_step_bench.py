"""Stepping a bout from Python against stepping it in C++ (the baseline, measured in the same run): one fighter
fed a still user 1.3 m away, an order every second, 60 s of frames. Prints JSON: per-frame microseconds (median,
p99, mean) of each, and the ratio of the means.

    PYTHONPATH=build/python /usr/bin/python3 tests/bench/python_step_bench.py [DB.kdb] [SECONDS]
"""
import json
import pathlib
import statistics
import sys
import time

import kumite

SOURCE = pathlib.Path(__file__).resolve().parents[2]


def quantile(values, q):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(q * len(ordered)))]


def main():
    database = kumite.Database(sys.argv[1] if len(sys.argv) > 1 else str(SOURCE / "data" / "golden" / "golden-v2.kdb"))
    seconds = int(sys.argv[2]) if len(sys.argv) > 2 else 60
    head = [0.0, 1.65, 1.3]
    from_python = kumite.Bout(database, character="brawler", seed=1)
    in_cpp = kumite.Bout(database, character="brawler", seed=1)
    python_us, cpp_chunk_us = [], []
    orders = ["punch", "kick"]
    for second in range(seconds):
        for bout in (from_python, in_cpp):
            bout.command(orders[second % 2])
        for frame in range(60):
            started = time.perf_counter_ns()
            from_python.set_user(head)
            from_python.step(second + frame / 60)
            python_us.append((time.perf_counter_ns() - started) / 1000)
        cpp_chunk_us.append(in_cpp._step_loop_us(second, 60, head) / 60)
    python_mean, cpp_mean = statistics.fmean(python_us), statistics.fmean(cpp_chunk_us)
    print(json.dumps({
        "benchmark": "python_step",
        "frames": len(python_us),
        "python_step_us": {"median": quantile(python_us, 0.5), "p99": quantile(python_us, 0.99), "mean": python_mean},
        "baseline_cpp_step_us": {"median_of_second_means": quantile(cpp_chunk_us, 0.5), "p99_of_second_means": quantile(cpp_chunk_us, 0.99), "mean": cpp_mean},
        "python_over_cpp": python_mean / cpp_mean,
    }, indent=2))


if __name__ == "__main__":
    main()
