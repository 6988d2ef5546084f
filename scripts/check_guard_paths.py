#!/usr/bin/env python3
"""The user's guard, checked from outside: recorded people replayed as the user, the fighter on several
characters, a punch or kick ordered every 2 s. Each bout writes the fighter's motion (--record BVH), the user as
tracked (--record-user CSV: head, hands and the elbows the guard used) and its events. This script finds, on its
own, what each strike's path met first, frame by frame from the recording: the fighter's fist (a 5 cm sphere 8 cm
past the wrist along the forearm) or foot (likewise past the ankle along the shin) swept against the user's gloves
(10 cm spheres around the hands), forearms (5 cm capsules from the wrist, 8 cm back from the hand, to the elbow),
head (11 cm) and trunk (a 15 cm capsule 0.30-0.70 m under the head). Then it compares with what the bout said:

  - of the strikes whose path met a glove or forearm before the head or trunk, the share reported blocked;
  - of the strikes reported hit, the share whose path met a glove or forearm first;
  - the deepest any fist or foot went into the glove that blocked it, from the block to the strike's end (and over
    the recovery after it, reported).

  check_guard_paths.py KUMITE DB.kdb|ANNOTATIONS.json MOCAP_ROOT [--boxers a.bvh,...] [--characters a,b]
                       [--duration S] [--set name=value ...] [--json OUT] [--bars]

--bars asserts: >= 95% of the strikes that met the guard first reported blocked, <= 2% of the hits through the
guard, no fist or foot more than 1.5 cm into the glove that blocked it (a glove's padding gives more than that), to
the strike's end nor over the 0.3 s after, and the events consistent (a blocked strike names a glove or forearm and
is no hit).
"""
import argparse
import concurrent.futures
import json
import math
import os
import subprocess
import sys
import tempfile

import bout_inputs

GLOVE, FOREARM, HEAD, TRUNK, FIST = 0.10, 0.05, 0.11, 0.15, 0.05
PAST_WRIST = 0.08
SUBSTEPS = 24  # the path between two frames, sampled (not solved: an independent reading)
DEFAULT_BOXERS = ["snu-boxing/boxman_blocking_dir.bvh", "snu-boxing/boxman_stand_dir_straight_right.bvh",
                  "snu-boxing/boxman_ducking_dir.bvh", "snu-boxing/boxman_hited_dir.bvh",
                  "snu-boxing/boxman_stand_dir_hook_right_near.bvh", "snu-boxing/boxman_stand_dir_upper_left.bvh",
                  "snu-boxing/boxman_stand_dir_upper_right.bvh", "snu-boxing/boxman_stand_dir_zap_right.bvh",
                  "cmu14-boxing/box-1.bvh", "cmu14-boxing/box-2.bvh", "cmu14-boxing/box-3.bvh"]
DEFAULT_CHARACTERS = ["brawler", "giant", "kid", "runner", "scout"]


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def lerp(a, b, s):
    return [x + s * (y - x) for x, y in zip(a, b)]


def to_segment(p, a, b):
    ab = sub(b, a)
    length2 = dot(ab, ab)
    u = 0.0 if length2 < 1e-18 else max(0.0, min(1.0, dot(sub(p, a), ab) / length2))
    return math.dist(p, lerp(a, b, u))


def user_parts(row):
    """name -> (distance function of a point), from one line of the user's track."""
    head = row[1:4]
    parts = {"head": lambda p: math.dist(p, head) - HEAD,
             "trunk": lambda p: to_segment(p, [head[0], head[1] - 0.30, head[2]], [head[0], head[1] - 0.70, head[2]]) - TRUNK}
    for side, name in ((0, "left"), (1, "right")):
        hand, elbow = row[4 + 3 * side: 7 + 3 * side], row[10 + 3 * side: 13 + 3 * side]
        if any(math.isnan(v) for v in hand):
            continue
        parts["glove_" + name] = (lambda h: lambda p: math.dist(p, h) - GLOVE)(hand)
        if len(row) >= 16 and not any(math.isnan(v) for v in elbow):
            back = sub(elbow, hand)
            length = math.sqrt(dot(back, back)) or 1.0
            wrist = [h + PAST_WRIST * b / length for h, b in zip(hand, back)]
            parts["forearm_" + name] = (lambda w, e: lambda p: to_segment(p, w, e) - FOREARM)(wrist, elbow)
    return parts


def run_bout(job):
    kumite, database, mocap, boxer, character, duration, settings, work = job
    stem = f"{os.path.splitext(os.path.basename(boxer))[0]}-{character}"
    orders = bout_inputs.orders_every_2s(os.path.join(work, stem + ".orders"), duration)
    events, record, user = (os.path.join(work, stem + ext) for ext in (".jsonl", ".bvh", ".csv"))
    command = [kumite, "play", database, "--tracker", f"capture:{os.path.join(mocap, boxer)}:1.2", "--character", character,
               "--aim", "predicted", "--commands", f"script:{orders}", "--headless", "--duration", str(duration),
               "--events", events, "--record", record, "--record-user", user]
    for setting in settings:
        command += ["--set", setting]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    info = json.loads(subprocess.run([kumite, "inspect", record, "--json"], check=True, capture_output=True, text=True).stdout)
    positions = json.loads(subprocess.run([kumite, "positions", record, "--all", "--json"], check=True, capture_output=True, text=True).stdout)
    lines = [json.loads(line) for line in open(events)]
    track = [[float(x) for x in line.split(",")] for line in open(user) if not line.startswith("#")]
    return stem, judge(positions, info, lines, track)


def judge(positions, info, lines, track):
    names, body_map, fps = positions["joint_names"], info["body_map"], info["fps"]
    frames = [positions["frames"][k] for k in sorted(positions["frames"], key=int)]

    def point(frame, limb, side):
        joints = ("hand_", "forearm_") if limb == "arm" else ("foot_", "shin_")
        end = frames[frame][names.index(body_map[joints[0] + side])]
        middle = frames[frame][names.index(body_map[joints[1] + side])]
        along = sub(end, middle)
        length = math.sqrt(dot(along, along)) or 1.0
        return [e + PAST_WRIST * a / length for e, a in zip(end, along)]

    for e in lines:
        if e["type"] == "strike":
            assert (e["result"] == "blocked") == ("blocked_by" in e), f"a strike at {e['t']} s: result {e['result']}, blocked_by {e.get('blocked_by')}"
            assert e["result"] != "blocked" or (not e.get("hit", False) and e["blocked_by"].startswith(("glove_", "forearm_"))), \
                f"a blocked strike at {e['t']} s told otherwise"
    strikes = []
    starts = [e["t"] for e in lines if e["type"] == "order_performed"]
    ends = [e["t"] for e in lines if e["type"] == "strike_end"]
    for e in lines:
        if e["type"] != "strike" or e.get("kind") in ("knee", "elbow") or e.get("command") not in ("punch", "kick"):
            continue
        start = max((t for t in starts if t <= e["t"]), default=None)
        end = min((t for t in ends if t >= e["t"]), default=None)
        if start is None or end is None:
            continue
        limb, side = ("arm" if e["command"] == "punch" else "leg"), ("l" if e["clip_side"] == "left" else "r")
        first, first_frame = None, None
        last = min(len(frames), len(track)) - 1
        f0, f1 = int(round(start * fps)), min(last, int(round(end * fps)))
        previous = point(f0, limb, side)
        for frame in range(f0 + 1, f1 + 1):
            now = point(frame, limb, side)
            parts = user_parts(track[frame])
            for k in range(1, SUBSTEPS + 1):
                p = lerp(previous, now, k / SUBSTEPS)
                touched = [name for name, gap in parts.items() if gap(p) <= FIST]
                if touched:
                    first = min(touched, key=lambda name: parts[name](p))
                    break
            previous = now
            if first:
                first_frame = frame
                break
        # How deep the fist or foot goes into the glove that blocked it, to the strike's end and 0.3 s past it; past
        # the end, how much of that depth the fighter's own limb made (its motion towards the glove's centre) rather
        # than the glove coming on.
        deepest, deepest_after, fighter_after = 0.0, 0.0, 0.0
        blocked_by = e.get("blocked_by", "")
        if blocked_by.startswith("glove_"):
            glove = 0 if blocked_by == "glove_left" else 1
            end_frame, made_by_fighter = int(round(end * fps)), 0.0
            for frame in range(int(round(e["t"] * fps)), min(last, int(round((end + 0.3) * fps))) + 1):
                centre = track[frame][4 + 3 * glove: 7 + 3 * glove]
                depth = GLOVE + FIST - math.dist(point(frame, limb, side), centre)
                if frame <= end_frame:
                    deepest = max(deepest, depth)
                    continue
                before = point(frame - 1, limb, side)
                away = sub(before, track[frame - 1][4 + 3 * glove: 7 + 3 * glove])
                length = math.sqrt(dot(away, away))
                if length > 1e-9:  # the limb's own step towards the glove it was at, this frame
                    made_by_fighter = max(0.0, made_by_fighter - dot(sub(point(frame, limb, side), before), away) / length)
                if depth > deepest_after:
                    deepest_after, fighter_after = depth, min(depth, made_by_fighter) if depth > 0 else 0.0
        strikes.append({"t": e["t"], "command": e["command"], "result": e["result"], "blocked_by": blocked_by,
                        "path_first": first or "nothing", "path_first_t": first_frame / fps if first_frame else None,
                        "deepest_in_glove_m": deepest, "deepest_after_end_m": deepest_after,
                        "deepest_after_end_by_fighter_m": fighter_after})
    return strikes


def summarise(strikes):
    guard = [s for s in strikes if s["path_first"].startswith(("glove_", "forearm_"))]
    hits = [s for s in strikes if s["result"] == "hit"]
    return {"strikes": len(strikes),
            "path_met_guard_first": len(guard),
            "of_those_reported_blocked": sum(s["result"] == "blocked" for s in guard),
            "reported_blocked": sum(s["result"] == "blocked" for s in strikes),
            "reported_hit": len(hits),
            "hit_with_guard_first": sum(s["path_first"].startswith(("glove_", "forearm_")) for s in hits),
            "deepest_in_glove_m": max((s["deepest_in_glove_m"] for s in strikes), default=0.0),
            "deepest_after_end_m": max((s["deepest_after_end_m"] for s in strikes), default=0.0),
            "deepest_after_end_by_fighter_m": max((s["deepest_after_end_by_fighter_m"] for s in strikes), default=0.0)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("kumite")
    parser.add_argument("database")
    parser.add_argument("mocap")
    parser.add_argument("--boxers", default=",".join(DEFAULT_BOXERS))
    parser.add_argument("--characters", default=",".join(DEFAULT_CHARACTERS))
    parser.add_argument("--duration", type=float, default=60.0)
    parser.add_argument("--set", action="append", default=[], dest="settings")
    parser.add_argument("--json")
    parser.add_argument("--bars", action="store_true")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        database = bout_inputs.database(args.kumite, args.database, args.mocap, work)
        jobs = [(args.kumite, database, args.mocap, boxer, character, args.duration, args.settings, work)
                for boxer in args.boxers.split(",") for character in args.characters.split(",")]
        with concurrent.futures.ProcessPoolExecutor(args.jobs) as pool:
            results = dict(pool.map(run_bout, jobs))
    every = [s for strikes in results.values() for s in strikes]
    total = summarise(every)
    for stem, strikes in sorted(results.items()):
        s = summarise(strikes)
        print(f"{stem:48s} {s['strikes']:3d} strikes, guard first {s['path_met_guard_first']:2d} (blocked {s['of_those_reported_blocked']:2d}), "
              f"hit {s['reported_hit']:2d} (guard first {s['hit_with_guard_first']}), deepest {s['deepest_in_glove_m'] * 100:.1f} cm "
              f"(after the end {s['deepest_after_end_m'] * 100:.1f})")
    blocked_share = total["of_those_reported_blocked"] / max(1, total["path_met_guard_first"])
    through_share = total["hit_with_guard_first"] / max(1, total["reported_hit"])
    total.update({"blocked_share": blocked_share, "hit_through_guard_share": through_share})
    print(f"check_guard_paths: {total['strikes']} strikes; the path met the guard first for {total['path_met_guard_first']}, "
          f"{total['of_those_reported_blocked']} of them reported blocked ({100 * blocked_share:.1f}%); "
          f"{total['reported_hit']} reported hit, {total['hit_with_guard_first']} with the guard first ({100 * through_share:.1f}%); "
          f"deepest in the blocking glove {100 * total['deepest_in_glove_m']:.1f} cm to the strike's end, "
          f"{100 * total['deepest_after_end_m']:.1f} cm over the 0.3 s after (of it made by the fighter's limb moving in: "
          f"{100 * total['deepest_after_end_by_fighter_m']:.1f} cm)")
    if args.json:
        with open(args.json, "w") as out:
            json.dump({"total": total, "bouts": results}, out, indent=1)
    if args.bars:
        assert blocked_share >= 0.95, f"only {100 * blocked_share:.1f}% of the strikes that met the guard first were reported blocked"
        assert through_share <= 0.02, f"{100 * through_share:.1f}% of the hits went through the guard"
        assert total["reported_blocked"] >= 1, "no strike was blocked"
        assert total["deepest_in_glove_m"] <= 0.015, f"a fist went {100 * total['deepest_in_glove_m']:.1f} cm into the glove that blocked it"
        assert total["deepest_after_end_m"] <= 0.015, \
            f"a fist went {100 * total['deepest_after_end_m']:.1f} cm into the glove that blocked it after the strike's end"
    return 0


if __name__ == "__main__":
    sys.exit(main())
