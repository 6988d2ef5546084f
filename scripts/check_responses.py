#!/usr/bin/env python3
"""The user's answers to the fighter's blows (user_response events), checked where the truth is known: simulated
users who answer each strike a known time after the fighter leaves its guard (slip, cover, step-back at 0.15, 0.25
and 0.40 s), a punch or kick ordered every 2 s. For each blow: whether the measured moment of the user's first
defensive motion (response_s) is within 0.03 s of the moment the simulated user began to move (the strike's start
plus the delay: the bout's state event), and whether the kind is the one the user did (slip, block, step_back).
Then the recorded boxers replayed as the user (--tracker capture:), where nothing is known: the median response
time and the kinds, reported.

  check_responses.py KUMITE DB.kdb|ANNOTATIONS.json MOCAP_ROOT [--characters a,b] [--duration S] [--set NAME=VALUE]
                     [--json OUT] [--min-share X]

--min-share X fails when either share (time within 0.03 s, kind right) is under X.
"""
import collections
import concurrent.futures
import json
import os
import statistics
import subprocess
import sys
import tempfile

import bout_inputs

ANSWERS = {"slip": "slip", "cover": "block", "step-back": "step_back"}
DELAYS = (0.15, 0.25, 0.40)
BOXERS = ["snu-boxing/boxman_blocking_dir.bvh", "snu-boxing/boxman_stand_dir_straight_right.bvh", "cmu14-boxing/box-1.bvh"]


def bout(job):
    kumite, database, tracker, character, duration, settings, orders, events = job
    command = [kumite, "play", database, "--tracker", tracker, "--character", character, "--aim", "predicted",
               "--commands", f"script:{orders}", "--headless", "--duration", str(duration), "--events", events]
    for setting in settings:
        command += ["--set", setting]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return [json.loads(line) for line in open(events) if '"user_response"' in line]


def main():
    parser = bout_inputs.parser(__doc__, 30.0)
    parser.add_argument("--set", action="append", default=[], dest="settings")
    parser.add_argument("--min-share", type=float, default=0.0)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        database = bout_inputs.database(args.kumite, args.database, args.mocap, work)
        orders = bout_inputs.orders_every_2s(os.path.join(work, "orders.txt"), args.duration)
        simulated = [(answer, delay, character) for answer in ANSWERS for delay in DELAYS for character in args.characters.split(",")]
        jobs = [(args.kumite, database, f"simulate:{a}:{d}", c, args.duration, args.settings, orders, os.path.join(work, f"{a}-{d}-{c}.jsonl"))
                for a, d, c in simulated]
        jobs += [(args.kumite, database, f"capture:{os.path.join(args.mocap, b)}:1.2", c, args.duration, args.settings, orders,
                  os.path.join(work, f"{os.path.basename(b)}-{c}.jsonl")) for b in BOXERS for c in args.characters.split(",")]
        with concurrent.futures.ProcessPoolExecutor(os.cpu_count() or 2) as pool:
            results = list(pool.map(bout, jobs))
    rows, total = [], collections.Counter()
    for (answer, delay, character), responses in zip(simulated, results[:len(simulated)]):
        timed = sum(r["response_s"] is not None and abs(r["response_s"] - (r["began_s"] + delay)) <= 0.03 for r in responses)
        kinds = sum(r["response"] == ANSWERS[answer] for r in responses)
        total.update({"blows": len(responses), "timed": timed, "kind_right": kinds})
        wrong = collections.Counter(f"{r['response']} ({r['result']})" for r in responses if r["response"] != ANSWERS[answer])
        rows.append({"user": answer, "delay_s": delay, "character": character, "blows": len(responses), "timed": timed, "kind_right": kinds,
                     "wrong_kinds": dict(wrong)})
        print(f"{answer:9s} {delay:.2f} s {character:8s} {len(responses):3d} blows: within 0.03 s {timed:3d}, kind right {kinds:3d}  {dict(wrong) or ''}")
    recorded = [r for responses in results[len(simulated):] for r in responses]
    times = [r["response_time_s"] for r in recorded if r["response_time_s"] is not None]
    recorded_summary = {"blows": len(recorded), "median_response_time_s": statistics.median(times) if times else None,
                        "kinds": dict(collections.Counter(r["response"] for r in recorded)),
                        "quality": dict(collections.Counter(r["quality"] for r in recorded))}
    time_share = total["timed"] / max(1, total["blows"])
    kind_share = total["kind_right"] / max(1, total["blows"])
    print(f"check_responses: simulated answers, {total['blows']} blows: the moment within 0.03 s for {100 * time_share:.1f}%, the kind right "
          f"for {100 * kind_share:.1f}%; recorded boxers, {len(recorded)} blows: median response time "
          f"{recorded_summary['median_response_time_s']}, kinds {recorded_summary['kinds']}")
    if args.json:
        with open(args.json, "w") as out:
            json.dump({"simulated": rows, "time_share": time_share, "kind_share": kind_share, "recorded": recorded_summary}, out, indent=1)
    assert total["blows"] > 0, "no blows"
    assert time_share >= args.min_share, f"the moment within 0.03 s for only {100 * time_share:.1f}%"
    assert kind_share >= args.min_share, f"the kind right for only {100 * kind_share:.1f}%"
    return 0


if __name__ == "__main__":
    sys.exit(main())
