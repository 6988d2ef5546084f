"""A drill's frame time with the training store against the same drill with --no-store (the baseline, in the same
run): the reaction test's attacks, 600 of them 0.8-1.6 s apart (about 12 minutes of frames, so that a run's p99
stands on 430 frames, not a reaction test's 55), headless against a simulated trainee who covers, the two
alternated --runs times (default 9). Headless bouts step as fast as they can,
so the store's thread commits while frames are computed back to back: harsher than the room's 60 Hz. Prints JSON:
per mode (after one warm-up run of each, not counted) the frame time's p99 and mean (microseconds) of each run and their medians, and the ratio of the p99s'
medians (the bar: at most 1.10).

    /usr/bin/python3 tests/bench/train_store_bench.py KUMITE [DB.kdb] [--runs N]
"""
import argparse
import json
import os
import pathlib
import statistics
import subprocess
import tempfile

SOURCE = pathlib.Path(__file__).resolve().parents[2]


DRILL = """name = "the reaction test's attacks, 600 of them"
[[part]]
name = "single attacks"
attacks = ["punch right straight high", "punch left straight high", "punch left hook high", "punch right straight middle", "kick right front middle"]
cadence_s = [0.8, 1.6]
count = 600
difficulty = "person"
"""


def drill_run(kumite, database, work, store, index):
    report = os.path.join(work, f"report{index}.json")
    drill = os.path.join(work, "drill.toml")
    if not os.path.exists(drill):
        with open(drill, "w") as out:
            out.write(DRILL)
    command = [kumite, "train", database, "--headless", "--trainee", "bench", "--drill", drill,
               "--tracker", "simulate:cover:0.25", "--report", report]
    command += ["--store", store] if store else ["--no-store"]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(report) as f:
        frame = json.load(f)["frame_time_us"]
    return frame["p99"], frame["mean"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("kumite")
    parser.add_argument("database", nargs="?", default=str(SOURCE / "data" / "golden" / "golden-v2.kdb"))
    parser.add_argument("--runs", type=int, default=9)
    args = parser.parse_args()
    runs = {"with_store": [], "no_store_baseline": []}
    with tempfile.TemporaryDirectory() as work:
        store = os.path.join(work, "bench.sqlite")
        drill_run(args.kumite, args.database, work, store, -1)  # warm-up, not counted: the first run pays for cold caches
        drill_run(args.kumite, args.database, work, None, -2)
        for run in range(args.runs):
            for mode in (("with_store", "no_store_baseline") if run % 2 == 0 else ("no_store_baseline", "with_store")):
                runs[mode].append(drill_run(args.kumite, args.database, work, store if mode == "with_store" else None, len(runs[mode]) + 10 * run))
    result = {}
    for mode, values in runs.items():
        result[mode] = {"frame_p99_us": [v[0] for v in values], "frame_mean_us": [v[1] for v in values],
                        "median_of_p99_us": statistics.median(v[0] for v in values), "median_of_mean_us": statistics.median(v[1] for v in values)}
    result["p99_ratio"] = result["with_store"]["median_of_p99_us"] / result["no_store_baseline"]["median_of_p99_us"]
    result["runs"] = args.runs
    print(json.dumps(result, indent=1))


if __name__ == "__main__":
    main()
