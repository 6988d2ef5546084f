#!/usr/bin/env python3
"""Training over weeks, from outside: twelve stored sessions whose response time falls, and sessions killed mid-way.

  progress  Twelve sessions of the reaction test (data/drills/reaction-test.toml) by one simulated trainee, stored one
            by one in a fresh store: the trainee answers every blow a set time after the fighter leaves its guard,
            from 0.40 s in the first session to 0.25 s in the twelfth, by covering, slipping or stepping back in turn.
            `kumite progress` must give each session's median response time within --tolerance (0.03 s) of what was
            set, and write the page (-o PAGE.html to keep it).
  kill      --kills times (20): a session started and killed (SIGKILL) at a random moment after it is stored (a long
            drill of 3000 attacks, headless, so that the kill falls among many commits). Every
            earlier session's rows (the session, its attacks, its strikes) must be equal before and after; the killed
            one incomplete, its attacks the first ones of the same seeded session run to the end (what was committed);
            PRAGMA integrity_check ok every time.

  check_training.py KUMITE DB.kdb|ANNOTATIONS.json MOCAP_ROOT progress|kill [-o PAGE.html] [--kills N] [--json OUT]
"""
import argparse
import json
import os
import random
import sqlite3
import subprocess
import sys
import tempfile
import time

import bout_inputs

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DRILL = os.path.join(ROOT, "data", "drills", "reaction-test.toml")
ANSWERS = ["cover", "slip", "step-back"]


KILL_DRILL = """name = "a long drill to kill"
[[part]]
name = "single attacks"
attacks = ["punch right straight high", "punch left straight high", "punch left hook high", "kick right front middle"]
cadence_s = [0.8, 1.6]
count = 3000
difficulty = "person"
"""


def train(kumite, database, store, trainee, tracker, drill=DRILL):
    return [kumite, "train", database, "--headless", "--trainee", trainee, "--drill", drill, "--store", store, "--tracker", tracker]


def set_time(session, sessions=12):
    return 0.40 + (0.25 - 0.40) * session / (sessions - 1)


def progress(args, database, work):
    store = os.path.join(work, "progress.sqlite")
    set_times = []
    for session in range(12):
        delay = round(set_time(session), 3)
        set_times.append(delay)
        tracker = f"simulate:{ANSWERS[session % 3]}:{delay}"
        subprocess.run(train(args.kumite, database, store, "simulated trainee", tracker), check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        print(f"session {session + 1:2d}: {tracker}", flush=True)
    page = args.output or os.path.join(work, "progress.html")
    out = subprocess.run([args.kumite, "progress", "simulated trainee", "--store", store, "-o", page, "--json"], check=True, capture_output=True, text=True)
    measured = json.loads(out.stdout)["sessions"]
    rows, worst = [], 0.0
    for session, entry in enumerate(measured):
        median = entry["response_time_s"]["median"]
        worst = max(worst, abs(median - set_times[session]))
        rows.append({"session": session + 1, "set_s": set_times[session], "median_s": median, "attacks": entry["attacks"]})
        print(f"session {session + 1:2d}: set {set_times[session]:.3f} s, measured median {median:.3f} s over {entry['attacks']} attacks")
    print(f"worst difference {worst:.3f} s (tolerance {args.tolerance} s); page {page}")
    ok = len(measured) == 12 and worst <= args.tolerance
    return ok, {"sessions": rows, "worst_difference_s": worst}


def rows_of(store, session_ids):
    """Every stored row of these sessions, as tuples."""
    db = sqlite3.connect(store)
    try:
        marks = ",".join("?" * len(session_ids))
        return {table: db.execute(f"SELECT * FROM {table} WHERE {key} IN ({marks}) ORDER BY 1", session_ids).fetchall()
                for table, key in (("sessions", "id"), ("attacks", "session_id"), ("user_strikes", "session_id"))}
    finally:
        db.close()


def integrity(store):
    db = sqlite3.connect(store)
    try:
        return db.execute("PRAGMA integrity_check").fetchone()[0]
    finally:
        db.close()


def attack_rows(store, session_id):
    db = sqlite3.connect(store)
    try:
        columns = [c[1] for c in db.execute("PRAGMA table_info(attacks)") if c[1] not in ("id", "session_id")]
        return db.execute(f"SELECT {','.join(columns)} FROM attacks WHERE session_id = ? ORDER BY seq", (session_id,)).fetchall()
    finally:
        db.close()


def session_ids(store):
    if not os.path.exists(store):
        return []
    db = sqlite3.connect(store)
    try:
        return [row[0] for row in db.execute("SELECT id FROM sessions ORDER BY id")]
    except sqlite3.OperationalError:  # not made yet
        return []
    finally:
        db.close()


def wait_for_session(store, sessions_before, process):
    """Polls until the store holds one more session (or the process ended); returns when."""
    deadline = time.monotonic() + 60.0
    while len(session_ids(store)) == sessions_before and process.poll() is None and time.monotonic() < deadline:
        time.sleep(0.01)
    return time.monotonic()


def kill(args, database, work):
    store = os.path.join(work, "kill.sqlite")
    tracker = "simulate:cover:0.25"
    drill = os.path.join(work, "long.toml")
    with open(drill, "w") as out:
        out.write(KILL_DRILL)
    # The whole session once, as the reference of what a killed one committed, and how long it runs once stored.
    process = subprocess.Popen(train(args.kumite, database, store, "full", tracker, drill), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    stored_at = wait_for_session(store, 0, process)
    process.wait()
    assert process.returncode == 0, "the full session failed"
    wall_s = time.monotonic() - stored_at
    full = attack_rows(store, session_ids(store)[-1])
    generator, results, ok = random.Random(args.seed), [], True
    for k in range(args.kills):
        before_ids = session_ids(store)
        before = rows_of(store, before_ids)
        process = subprocess.Popen(train(args.kumite, database, store, "killed", tracker, drill), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        # Once its session is in the store, a random moment of the rest of it.
        wait_for_session(store, len(before_ids), process)
        time.sleep(generator.uniform(0.0, 0.95 * wall_s))
        finished_first = process.poll() is not None
        process.kill()
        process.wait()
        after_ids = session_ids(store)
        new = [i for i in after_ids if i not in before_ids]
        same = rows_of(store, before_ids) == before
        check = integrity(store)
        complete, stored = None, []
        if new:
            db = sqlite3.connect(store)
            complete = bool(db.execute("SELECT complete FROM sessions WHERE id = ?", (new[0],)).fetchone()[0])
            db.close()
            stored = attack_rows(store, new[0])
        prefix = stored == full[:len(stored)]
        good = same and check == "ok" and len(new) == 1 and (finished_first or complete is False) and prefix
        ok = ok and good
        results.append({"kill": k + 1, "earlier_sessions_equal": same, "integrity_check": check, "killed_complete": complete,
                        "attacks_committed": len(stored), "attacks_in_full_session": len(full), "prefix_of_full_run": prefix,
                        "ended_before_the_kill": finished_first})
        print(f"kill {k + 1:2d}: earlier {len(before_ids)} sessions {'equal' if same else 'CHANGED'}, integrity {check}, "
              f"killed session {'complete' if complete else 'incomplete'} with {len(stored)}/{len(full)} attacks"
              f"{'' if prefix else ' NOT A PREFIX'}{' (it ended first)' if finished_first else ''}", flush=True)
    listed = subprocess.run([args.kumite, "sessions", "--store", store], check=True, capture_output=True, text=True).stdout
    incomplete_listed = listed.count("incomplete")
    print(f"kumite sessions lists {incomplete_listed} incomplete of {len(session_ids(store))}")
    ok = ok and incomplete_listed == sum(1 for r in results if r["killed_complete"] is False)
    return ok, {"full_session_wall_s": wall_s, "kills": results, "incomplete_listed": incomplete_listed}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("kumite")
    parser.add_argument("database")
    parser.add_argument("mocap")
    parser.add_argument("mode", choices=["progress", "kill"])
    parser.add_argument("-o", "--output")
    parser.add_argument("--kills", type=int, default=20)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--tolerance", type=float, default=0.03)
    parser.add_argument("--json")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        database = bout_inputs.database(args.kumite, args.database, args.mocap, work)
        ok, result = (progress if args.mode == "progress" else kill)(args, database, work)
    if args.json:
        with open(args.json, "w") as out:
            json.dump(result, out, indent=1)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
