#!/usr/bin/env python3
"""Hit rates per character, simulated user and aim mode: headless `kumite play` bouts with an order every 2 s
(punch and kick alternately, sides alternating), read from each bout's report. Prints one JSON document.

  scripts/hit_rates.py [--db DB.kdb] [--seconds 60] [--users still,walk:0.5,walk:1.2,dodge,dodge-seen] [--aims latched,predicted]
                       [--characters kid,scout,brawler,runner,giant] [--seed 1]

`dodge` dodges 0.25 s after each order, `dodge-seen` 0.25 s after the strike begins (what a person in the room sees):
the first is hit by the strikes whose contact comes late after their order (begun late, or held back on the way: each
row gives the median and 90th percentile from order to contact, `order_to_contact_s`), the second measures the strike
itself.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def order_to_contact_s(events_path):
    """Seconds from each order to its strike's contact (the strike event), from a bout's events."""
    times, order_s = [], None
    with open(events_path) as lines:
        for line in lines:
            event = json.loads(line)
            if event["type"] in ("order", "order_queued"):
                order_s = event["t"]
            elif event["type"] == "strike" and order_s is not None:
                times.append(event["t"] - order_s)
                order_s = None
    return times


def quantiles(values):
    ordered = sorted(values)
    pick = lambda q: ordered[min(len(ordered) - 1, int(q * len(ordered)))] if ordered else None
    return {"median": pick(0.5), "p90": pick(0.9), "count": len(ordered)}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--db", default=None, help="database (default: kumite's default database)")
    parser.add_argument("--seconds", type=float, default=60.0)
    parser.add_argument("--users", default="still,walk:0.5,walk:0.8,walk:1.2,dodge,dodge-seen")
    parser.add_argument("--aims", default="latched,predicted")
    parser.add_argument("--characters", default="kid,scout,brawler,runner,giant")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--kumite", default=os.path.join(root, "build", "bin", "kumite"))
    parser.add_argument("--play-args", default="", help="more arguments for kumite play, e.g. '--set keep_distance=false'")
    args = parser.parse_args()

    with tempfile.TemporaryDirectory() as work:
        script = os.path.join(work, "orders.txt")
        with open(script, "w") as out:
            t, n = 1.0, 0
            while t < args.seconds - 1.0:
                out.write(f"{t:.2f} {'punch' if n % 2 == 0 else 'kick'} {'left' if (n // 2) % 2 == 0 else 'right'}\n")
                t += 2.0
                n += 1
        table = {}
        for user in args.users.split(","):
            for aim in args.aims.split(","):
                row = {"strikes": 0, "hits": 0, "orders": 0, "performed": 0, "expired": 0, "by_character": {}}
                to_contact = []
                for character in args.characters.split(","):
                    report = os.path.join(work, "report.json")
                    events = os.path.join(work, "events.jsonl")
                    command = [args.kumite, "play"] + ([args.db] if args.db else []) + [
                        "--headless", "--duration", str(args.seconds), "--tracker", f"simulate:{user}", "--character", character,
                        "--commands", f"script:{script}", "--aim", aim, "--seed", str(args.seed), "--report", report, "--events", events] + args.play_args.split()
                    done = subprocess.run(command, capture_output=True, text=True)
                    if done.returncode != 0:
                        sys.exit(f"hit_rates: {' '.join(command)} failed: {done.stderr.strip()}")
                    figures = json.load(open(report))
                    row["strikes"] += figures["strikes"]
                    row["hits"] += figures["hits"]
                    row["orders"] += figures["orders"]
                    row["performed"] += figures["order_outcomes"]["performed"]
                    row["expired"] += figures["order_outcomes"]["expired"]
                    to_contact.extend(order_to_contact_s(events))
                    row["by_character"][character] = {"orders": figures["orders"], "strikes": figures["strikes"], "hits": figures["hits"],
                                                      "prediction_error_m": figures["prediction_error_m"]["median"]}
                row["hit_rate"] = row["hits"] / max(1, row["strikes"])
                row["order_to_contact_s"] = quantiles(to_contact)
                table.setdefault(user, {})[aim] = row
                print(f"{user:10s} {aim:9s} {row['hits']}/{row['strikes']} = {row['hit_rate']:.2f}; orders performed "
                      f"{row['performed']}/{row['orders']}, expired {row['expired']}; order to contact {row['order_to_contact_s']['median']:.2f} s "
                      f"(p90 {row['order_to_contact_s']['p90']:.2f})", file=sys.stderr)
    print(json.dumps({"seconds": args.seconds, "order_every_s": 2.0, "hit_rates": table}, indent=2))


if __name__ == "__main__":
    main()
