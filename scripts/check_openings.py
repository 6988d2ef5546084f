#!/usr/bin/env python3
"""Aiming at what the user's guard leaves open (user_guard.aim_at_openings): bouts against people who cover up — a
simulated user holding a high guard (`simulate:high-guard`) and recorded boxers (snu-boxing's boxman_blocking_dir,
cmu14's box-1) — on three characters, a punch or kick ordered every 2 s with the height left open, the user's guard
on; once aiming at the openings, once at the head alone (aim_at_openings = false). Prints the strikes that landed
both ways and where they aimed; fails unless aiming at the openings lands more over all.

  check_openings.py KUMITE DB.kdb|ANNOTATIONS.json MOCAP_ROOT [--characters a,b] [--duration S] [--json OUT]
"""
import collections
import concurrent.futures
import json
import os
import subprocess
import sys
import tempfile

import bout_inputs

USERS = ["simulate:high-guard", "capture:{mocap}/snu-boxing/boxman_blocking_dir.bvh:1.2", "capture:{mocap}/cmu14-boxing/box-1.bvh:1.2"]


def bout(job):
    kumite, database, tracker, character, duration, openings, orders, events = job
    subprocess.run([kumite, "play", database, "--tracker", tracker, "--character", character, "--aim", "predicted", "--commands", f"script:{orders}",
                    "--headless", "--duration", str(duration), "--events", events, "--set", "user_guard.enabled=true",
                    "--set", f"user_guard.aim_at_openings={'true' if openings else 'false'}"], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    strikes = [e for e in map(json.loads, open(events)) if e["type"] == "strike"]
    return {"strikes": len(strikes), "hits": sum(e["result"] == "hit" for e in strikes), "blocked": sum(e["result"] == "blocked" for e in strikes),
            "hits_by_part": dict(collections.Counter(e["target_part"] for e in strikes if e["result"] == "hit"))}


def main():
    parser = bout_inputs.parser(__doc__, 60.0)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        database = bout_inputs.database(args.kumite, args.database, args.mocap, work)
        orders = bout_inputs.orders_every_2s(os.path.join(work, "orders.txt"), args.duration)
        cases = [(user.format(mocap=args.mocap), character, openings) for user in USERS for character in args.characters.split(",") for openings in (False, True)]
        jobs = [(args.kumite, database, tracker, character, args.duration, openings, orders, os.path.join(work, f"{i}.jsonl"))
                for i, (tracker, character, openings) in enumerate(cases)]
        with concurrent.futures.ProcessPoolExecutor(os.cpu_count() or 2) as pool:
            results = list(pool.map(bout, jobs))
    totals = {False: collections.Counter(), True: collections.Counter()}
    rows = []
    for (tracker, character, openings), result in zip(cases, results):
        totals[openings].update({"strikes": result["strikes"], "hits": result["hits"], "blocked": result["blocked"]})
        rows.append({"user": tracker, "character": character, "aim_at_openings": openings, **result})
        print(f"{os.path.basename(tracker):40s} {character:8s} {'openings' if openings else 'head    '}  {result['hits']:2d} of {result['strikes']:2d} landed, "
              f"{result['blocked']:2d} blocked by the user  {result['hits_by_part']}")
    share = {o: totals[o]["hits"] / max(1, totals[o]["strikes"]) for o in (False, True)}
    print(f"check_openings: at the head alone {totals[False]['hits']} of {totals[False]['strikes']} landed ({100 * share[False]:.0f}%), "
          f"{totals[False]['blocked']} blocked; aiming at the openings {totals[True]['hits']} of {totals[True]['strikes']} ({100 * share[True]:.0f}%), "
          f"{totals[True]['blocked']} blocked")
    if args.json:
        with open(args.json, "w") as out:
            json.dump({"bouts": rows, "landed_share": {"head_alone": share[False], "openings": share[True]}}, out, indent=1)
    assert share[True] > share[False], "aiming at the openings landed no more than at the head alone"
    return 0


if __name__ == "__main__":
    sys.exit(main())
