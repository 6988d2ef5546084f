#!/usr/bin/env python3
"""Seeded bouts, fingerprinted: a fixed set of headless `kumite play` runs (simulated users of every kind, recorded
opponents as the user, a replayed head-and-hands track, captured blocks with and without the speed limit, a
character switch mid-bout, 200 fighters) whose events (JSONL) and recording (BVH) are hashed. Run it before and
after a change that must not change behaviour (a restructuring): the fingerprints must be the same.

  scripts/bout_fingerprints.py --save before.json            # on the old build
  scripts/bout_fingerprints.py --compare before.json         # on the new one: exit 1 on any difference
  scripts/bout_fingerprints.py --compare before.json --keep /tmp/after   # keep the files to diff them

Options: --kumite PATH (default build/bin/kumite), --db DB.kdb (default: the reference annotations baked into a
temporary file), --only NAME,... (a subset), --jobs N (default 2). A headless bout's events carry nothing measured on
the wall clock, so the same binary gives the same bytes every run; the report's frame times are not hashed.
"""
import argparse
import concurrent.futures
import hashlib
import json
import os
import shutil
import subprocess
import sys
import tempfile

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
mocap = os.path.join(os.path.dirname(root), "shared", "mocap")
demo = os.path.join(root, "data", "bouts", "demo.txt")
repertoire = os.path.join(root, "data", "bouts", "repertoire.txt")
boxer = os.path.join(mocap, "cmu14-boxing", "box-1.bvh")
kata = os.path.join(mocap, "hachaj-kata")


def orders_every(path, seconds, period=2.0):
    """An order every `period` s, punch and kick alternately, sides alternating (as scripts/real_opponents.py)."""
    with open(path, "w") as out:
        t, n = 1.0, 0
        while t < seconds - 1.0:
            out.write(f"{t:.2f} {'punch' if n % 2 == 0 else 'kick'} {'left' if (n // 2) % 2 == 0 else 'right'}\n")
            t += period
            n += 1
    return path


def bouts(work):
    """name -> the `kumite play` arguments after the database (--headless, --events and --record are added)."""
    dense = orders_every(os.path.join(work, "dense.orders"), 30.0, 1.0)
    every2 = orders_every(os.path.join(work, "every2.orders"), 30.0)
    first_kata = sorted(f for f in os.listdir(kata) if f.endswith(".bvh"))[0] if os.path.isdir(kata) else None
    table = {
        "still_demo": ["--tracker", "simulate:still", "--commands", f"script:{demo}", "--duration", "30"],
        "wander_repertoire": ["--tracker", "simulate:wander", "--commands", f"script:{repertoire}", "--duration", "40", "--seed", "3"],
        "walk_predicted": ["--tracker", "simulate:walk:1.0", "--aim", "predicted", "--commands", f"script:{demo}", "--duration", "30"],
        "dodge_dense": ["--tracker", "simulate:dodge", "--commands", f"script:{dense}", "--duration", "30", "--seed", "2",
                        "--character", "giant"],
        "punch_synthesized": ["--tracker", "simulate:punch", "--commands", f"script:{every2}", "--duration", "30", "--character", "kid"],
        "punch_captured": ["--tracker", "simulate:punch", "--commands", f"script:{every2}", "--duration", "30", "--set", "defence.captured_blocks=true"],
        "punch_captured_limited": ["--tracker", "simulate:punch", "--duration", "30", "--set", "defence.captured_blocks=true",
                                   "--set", "defence.block_clip_max_speed_ratio=1",
                                   "--character", "scout"],
        "counter_no_defence": ["--tracker", "simulate:counter", "--commands", f"script:{dense}", "--duration", "30", "--no-defence",
                               "--set", "variety_recent=0", "--character", "runner"],
        "boxer_predicted": ["--tracker", f"capture:{boxer}:1.2", "--aim", "predicted", "--commands", f"script:{every2}",
                            "--duration", "30", "--set", "defence.captured_blocks=true"],
        "boxer_close_latched": ["--tracker", f"capture:{boxer}:1.0", "--commands", f"script:{dense}", "--duration", "30",
                                "--character", "brawler"],
        "fighters_200": ["--tracker", "simulate:wander", "--fighters", "200", "--commands", f"script:{every2}", "--duration", "8"],
    }
    if first_kata:
        table["kata_captured"] = ["--tracker", f"capture:{os.path.join(kata, first_kata)}:1.3", "--commands", f"script:{every2}",
                                  "--duration", "30", "--set", "defence.captured_blocks=true", "--aim", "predicted"]
    return table


def with_gap(source, target, from_s, to_s):
    """The track in `source` without its samples from `from_s` to `to_s` (untracked there)."""
    with open(source) as f, open(target, "w") as out:
        for line in f:
            fields = line.split(",")
            try:
                if from_s <= float(fields[0]) < to_s:
                    continue
            except ValueError:
                pass
            out.write(line)
    return target


def run(kumite, db, name, arguments, out_dir, work):
    events, record, user = (os.path.join(out_dir, name + suffix) for suffix in (".jsonl", ".bvh", ".csv"))
    command = [kumite, "play", db, "--headless", "--events", events, "--record", record, "--record-user", user] + arguments
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"bout_fingerprints: {' '.join(command)} failed ({done.returncode}): {done.stderr.strip()}")
    digest = {}
    for label, path in (("events", events), ("record", record), ("user", user)):
        with open(path, "rb") as f:
            data = f.read()
        # The bout_start event names the database and the tracker's files: the temporary folder is not the bout.
        data = data.replace(work.encode(), b"<work>")
        digest[label] = hashlib.sha256(data).hexdigest()[:16]
        if label == "events":
            digest["event_lines"] = data.count(b"\n")
    return name, digest


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--kumite", default=os.path.join(root, "build", "bin", "kumite"))
    parser.add_argument("--db", default=None)
    parser.add_argument("--save", help="write the fingerprints here")
    parser.add_argument("--compare", help="compare with fingerprints saved before; exit 1 on a difference")
    parser.add_argument("--keep", help="keep the events, recordings and user tracks in this folder")
    parser.add_argument("--only", help="comma-separated bout names")
    parser.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    if not os.path.isfile(boxer):
        sys.exit(f"bout_fingerprints: {boxer} is missing (../shared/mocap beside the repository)")
    work = tempfile.mkdtemp(prefix="kumite_fingerprints_")
    try:
        db = args.db
        if not db:
            db = os.path.join(work, "reference.kdb")
            subprocess.run([args.kumite, "bake", os.path.join(root, "data", "annotations", "reference.json"), "-o", db],
                           check=True, capture_output=True)
        out_dir = args.keep or work
        os.makedirs(out_dir, exist_ok=True)
        table = bouts(work)
        if args.only:
            wanted = args.only.split(",")
            unknown = [n for n in wanted if n not in table]
            if unknown:
                sys.exit(f"bout_fingerprints: no bout named {', '.join(unknown)} (bouts: {', '.join(table)})")
            table = {n: table[n] for n in wanted}
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            results = dict(pool.map(lambda item: run(args.kumite, db, item[0], item[1], out_dir, work), table.items()))
            # The DTrack room's way in: a head-and-hands track replayed (t,x,y,z,...), here the one the recorded
            # boxer's bout wrote, with a gap cut into it so the fighter loses and finds the user again.
            if "boxer_close_latched" in results:
                replay = with_gap(os.path.join(out_dir, "boxer_close_latched.csv"), os.path.join(work, "replay.csv"), 12.0, 13.5)
                name, digest = run(args.kumite, db, "replay_boxer", ["--tracker", f"replay:{replay}", "--commands",
                                   f"script:{os.path.join(work, 'dense.orders')}", "--duration", "30", "--set", "defence.captured_blocks=true"],
                                   out_dir, work)
                results[name] = digest
                table[name] = []
        results = {name: results[name] for name in table}
        for name, digest in results.items():
            print(f"{name:24s} events {digest['events']} ({digest['event_lines']} lines)  record {digest['record']}  user {digest['user']}",
                  file=sys.stderr)
        if args.save:
            with open(args.save, "w") as f:
                json.dump(results, f, indent=1)
        if args.compare:
            with open(args.compare) as f:
                before = json.load(f)
            differ = [n for n in results if before.get(n) != results[n]]
            missing = [n for n in before if n not in results and not args.only]
            for n in differ:
                print(f"DIFFERENT {n}: before {before.get(n)}, now {results[n]}", file=sys.stderr)
            for n in missing:
                print(f"MISSING {n}: saved before, not run now", file=sys.stderr)
            if differ or missing:
                return 1
            print(f"bout_fingerprints: {len(results)} bouts byte-identical to {args.compare}", file=sys.stderr)
        if not args.save and not args.compare:
            json.dump(results, sys.stdout, indent=1)
            print()
        return 0
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
