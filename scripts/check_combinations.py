#!/usr/bin/env python3
"""Combinations against users who answer: does the first blow draw the guard, and the second land where it left?

For each user and character, two bouts of the same length and cadence (an order every 3 s):
  singles      the combinations' blows thrown alone (the jab, the cross, the hook, the jab to the body, in turn);
  combinations one-two, jab-hook, jab-body-head in turn (`combo NAME`).
Users: simulated ones who cover each blow 0.15 or 0.25 s after the fighter leaves its guard (they put a glove on the
first blow's way and hold it there 0.75 s), one who holds a high guard, and the recorded boxer who covers
(snu-boxing/boxman_blocking_dir, replayed as the user). Prints, per user, the share of single blows that landed and
of the combinations' first and second blows; --min-gain X fails unless, over the covering users, the second blows
land at least X (a share, 0-1) more often than single blows do.

  check_combinations.py KUMITE DB.kdb|ANNOTATIONS.json MOCAP_ROOT [--characters a,b] [--duration S] [--json OUT]
                        [--min-gain X]
"""
import collections
import concurrent.futures
import json
import os
import subprocess
import tempfile

import bout_inputs

USERS = ["simulate:cover:0.15", "simulate:cover:0.25", "simulate:high-guard", "capture:{mocap}/snu-boxing/boxman_blocking_dir.bvh:1.2"]
COVERING = ("simulate:cover:0.15", "simulate:cover:0.25")
SINGLES = ["punch right straight high", "punch left straight high", "punch left hook high", "punch right straight middle"]
COMBINATIONS = ["combo one-two", "combo jab-hook", "combo jab-body-head"]


def bout(job):
    kumite, database, tracker, character, duration, orders, events = job
    subprocess.run([kumite, "play", database, "--tracker", tracker, "--character", character, "--aim", "predicted", "--commands",
                    f"script:{orders}", "--headless", "--duration", str(duration), "--events", events],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    strikes = [json.loads(line) for line in open(events) if '"type":"strike"' in line]
    tally = collections.Counter()
    for s in strikes:
        group = "single" if "combination" not in s else ("first" if s["blow"] == 1 else "second")
        tally[group] += 1
        tally[group + "_hit"] += s["result"] == "hit"
    return tally


def main():
    parser = bout_inputs.parser(__doc__, 30.0)
    parser.add_argument("--min-gain", type=float, default=None)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        database = bout_inputs.database(args.kumite, args.database, args.mocap, work)
        singles = bout_inputs.orders_every(os.path.join(work, "singles.txt"), SINGLES, args.duration, 3.0, 1.5)
        combos = bout_inputs.orders_every(os.path.join(work, "combinations.txt"), COMBINATIONS, args.duration, 3.0, 1.5)
        jobs, keys = [], []
        for user in USERS:
            tracker = user.format(mocap=args.mocap)
            for character in args.characters.split(","):
                for name, orders in (("singles", singles), ("combinations", combos)):
                    stem = f"{len(jobs)}"
                    jobs.append((args.kumite, database, tracker, character, args.duration, orders, os.path.join(work, stem + ".jsonl")))
                    keys.append(user)
        with concurrent.futures.ProcessPoolExecutor(os.cpu_count() or 2) as pool:
            results = list(pool.map(bout, jobs))
    by_user = collections.defaultdict(collections.Counter)
    for user, tally in zip(keys, results):
        by_user[user].update(tally)
    share = lambda t, g: t[g + "_hit"] / t[g] if t[g] else None
    rows = {}
    for user in USERS:
        t = by_user[user]
        rows[user] = {g: {"strikes": t[g], "hits": t[g + "_hit"], "share": share(t, g)} for g in ("single", "first", "second")}
        print(f"{user.split('/')[-1]:28s} singles {t['single_hit']:3d}/{t['single']:3d}  first blows {t['first_hit']:3d}/{t['first']:3d}  "
              f"second blows {t['second_hit']:3d}/{t['second']:3d}")
    covering = collections.Counter()
    for user in COVERING:
        covering.update(by_user[user])
    gain = (share(covering, "second") or 0.0) - (share(covering, "single") or 0.0)
    print(f"check_combinations: against the covering users, single blows land {100 * (share(covering, 'single') or 0):.0f}%, "
          f"combinations' second blows {100 * (share(covering, 'second') or 0):.0f}% (gain {100 * gain:+.0f} points)")
    if args.json:
        with open(args.json, "w") as out:
            json.dump({"users": rows, "covering_gain": gain}, out, indent=1)
    assert covering["second"] > 0, "no second blows thrown"
    if args.min_gain is not None:
        assert gain >= args.min_gain, f"second blows land only {100 * gain:+.0f} points more than single blows"


if __name__ == "__main__":
    main()
