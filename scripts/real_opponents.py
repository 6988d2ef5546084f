#!/usr/bin/env python3
"""Bouts against recorded people: every opponent capture as the tracked user (`--tracker capture:FILE`, head and
both hands, 1.2 m in front of the fighter, facing it) for the capture's length, an order every 2 s (punch and kick
alternately, sides alternating), for each character. Prints a table per opponent x character on stderr and one
JSON document on stdout: strikes and hits, orders performed / queued / expired / ignored, and the opponent's
strikes at the fighter (seen, blocked, slipped, landed, missed; `overall.on_course`: slips counted only where the hand
would have hit without them; `overall.on_course_blocks_too`: blocks too, only where the hand's path after the forearm
went on to the head or chest). The overall hit and defended rates come with their
95% Wilson intervals (`hit_rate_ci95`, `defended_rate_ci95`): two settings whose rates differ by less than that may
differ by chance (the order of blows, a strike a frame later), not by what was changed.

  scripts/real_opponents.py [--db DB.kdb] [--opponents GLOB,...] [--characters kid,scout,brawler,runner,giant]
                            [--aim predicted] [--distance 1.2 | --distance 1.1,1.2,1.3] [--order-delay 0 | --order-delay 0,0.1,0.2]
                            [--max-seconds 60] [--jobs 2]

Default opponents: ../shared/mocap/cmu14-boxing/box-*.bvh (shadow boxing) and ../shared/mocap/hachaj-kata/*.bvh
(kata stepping towards the fighter).
"""
import argparse
import concurrent.futures
import glob
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
shared = os.path.join(os.path.dirname(root), "shared", "mocap")
DEFAULT_OPPONENTS = ",".join([os.path.join(shared, "cmu14-boxing", "box-*.bvh"), os.path.join(shared, "hachaj-kata", "*.bvh")])


def capture_seconds(kumite, path):
    info = json.loads(subprocess.run([kumite, "inspect", path, "--json"], check=True, capture_output=True, text=True).stdout)
    return info["duration_s"]


def bout(args, work, opponent, seconds, character, distance, delay):
    name = f"{os.path.basename(os.path.dirname(opponent))}_{os.path.basename(opponent)}_{character}"
    if len(args.distances) > 1:
        name += f"_{distance:g}m"
    if len(args.delays) > 1:
        name += f"_{delay:g}s"
    script = os.path.join(work, name + ".orders")
    with open(script, "w") as out:
        t, n = 1.0 + delay, 0
        while t < seconds - 1.0:
            out.write(f"{t:.2f} {'punch' if n % 2 == 0 else 'kick'} {'left' if (n // 2) % 2 == 0 else 'right'}\n")
            t += 2.0
            n += 1
    report = os.path.join(work, name + ".json")
    command = [args.kumite, "play"] + ([args.db] if args.db else []) + [
        "--headless", "--duration", f"{seconds:.3f}", "--tracker", f"capture:{opponent}:{distance}", "--character", character,
        "--commands", f"script:{script}", "--aim", args.aim, "--seed", "1", "--report", report] + args.play_args.split()
    events = os.path.join(args.events or work, name + ".jsonl")
    command += ["--events", events]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"real_opponents: {' '.join(command)} failed: {done.stderr.strip()}")
    # The speed at contact of every strike, by what was ordered (punch, kick, ...), pooled over the bouts; the warning
    # each blow of the opponent that would have landed gave (it met the head or chest, or a forearm and went on to them).
    contact, warnings, seen_at, blocked = {}, [], {}, {}
    with open(events) as f:
        for line in f:
            event = json.loads(line)
            kind = event.get("type")
            if kind == "strike":
                contact.setdefault(event.get("command", "?"), []).append(event.get("effector_speed_at_contact_mps", 0.0))
            elif kind == "user_strike":
                seen_at[event["hand"]] = event["t"]
            elif kind == "user_strike_end":
                seen_s = seen_at.pop(event["hand"], None)
                warning = [event.get("approach_s", 0.0), event["t"] - seen_s if event.get("detected") and seen_s is not None else 0.0]
                if event["outcome"] == "hit_by_user":
                    warnings.append(warning)
                elif event["outcome"] == "blocked":
                    blocked[event["hand"]] = warning
            elif kind == "user_strike_course":
                warning = blocked.pop(event["hand"], None)
                if warning and event.get("on_course"):
                    warnings.append(warning)
    result = json.load(open(report))
    result["contact_speeds"] = contact
    result["warnings"] = warnings
    return result


def percentiles(values, points=(10, 50, 90)):
    """Nearest-rank percentiles of `values` (None when empty)."""
    ordered = sorted(values)
    if not ordered:
        return None
    return {f"p{p}": ordered[min(len(ordered) - 1, max(0, math.ceil(p / 100.0 * len(ordered)) - 1))] for p in points}


def wilson_95(successes, trials):
    """The 95% Wilson interval of a rate: how far two runs' rates may differ by chance alone (the blows and strikes of one
    run are not independent draws, so it is a lower bound on the spread)."""
    if not trials:
        return None
    z, p = 1.96, successes / trials
    centre = (p + z * z / (2 * trials)) / (1 + z * z / trials)
    half = z * ((p * (1 - p) / trials + z * z / (4 * trials * trials)) ** 0.5) / (1 + z * z / trials)
    return [centre - half, centre + half]


def numbers(text, flag, unit):
    """A flag's comma-separated numbers, or a clear exit."""
    try:
        return [float(value) for value in text.split(",")]
    except ValueError:
        sys.exit(f"real_opponents: {flag} takes {unit}, comma-separated (got {text})")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--db", default=None, help="database (default: kumite's default database)")
    parser.add_argument("--opponents", default=DEFAULT_OPPONENTS, help="comma-separated globs of BVH captures")
    parser.add_argument("--characters", default="kid,scout,brawler,runner,giant")
    parser.add_argument("--aim", default="predicted")
    parser.add_argument("--distance", default="1.2", help="metres from the fighter; several, comma-separated (1.1,1.2,1.3): "
                        "every bout at each, pooled (a single distance's blows move by chance by about ten)")
    parser.add_argument("--order-delay", default="0", help="every order this much later (s); several, comma-separated (0,0.1,0.2): "
                        "every bout with each, pooled (the same opponents met at other moments: the spread a setting has by chance)")
    parser.add_argument("--max-seconds", type=float, default=60.0, help="bouts last the capture's length, at most this")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--events", default=None, help="a folder to keep each bout's events in")
    parser.add_argument("--kumite", default=os.path.join(root, "build", "bin", "kumite"))
    parser.add_argument("--play-args", default="", help="more arguments for kumite play, e.g. '--set defence.captured_blocks=true'")
    args = parser.parse_args()
    args.distances = numbers(args.distance, "--distance", "metres")
    args.delays = numbers(args.order_delay, "--order-delay", "seconds")
    if any(d < 0.0 or d >= 2.0 for d in args.delays):
        sys.exit(f"real_opponents: --order-delay must be at least 0 and under the 2 s between orders (got {args.order_delay})")

    opponents = sorted(path for pattern in args.opponents.split(",") for path in glob.glob(pattern))
    if not opponents:
        sys.exit(f"real_opponents: no capture matches {args.opponents}")
    characters = args.characters.split(",")
    if args.events:
        os.makedirs(args.events, exist_ok=True)
    rows = []
    with tempfile.TemporaryDirectory() as work, concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        seconds = {opponent: min(args.max_seconds, capture_seconds(args.kumite, opponent)) for opponent in opponents}
        futures = {(opponent, character, distance, delay): pool.submit(bout, args, work, opponent, seconds[opponent], character, distance, delay)
                   for delay in args.delays for distance in args.distances for opponent in opponents for character in characters}
        for (opponent, character, distance, delay), future in futures.items():
            report = future.result()
            user = report["user_strikes"]
            orders = report.get("order_outcomes", {})
            rows.append({"opponent": os.path.relpath(opponent, shared) if opponent.startswith(shared) else opponent,
                         "character": character, "distance_m": distance, "order_delay_s": delay, "seconds": seconds[opponent],
                         "orders": report["orders"], "performed": orders.get("performed", report["strikes"]),
                         "queued": orders.get("queued", 0), "expired": orders.get("expired", 0),
                         "ignored": report["ignored_orders"], "strikes": report["strikes"], "hits": report["hits"],
                         "user_seen": user["seen"], "blocked": user["blocked"], "slipped": user["slipped"],
                         "slipped_on_course": user.get("slipped_on_course", user["slipped"]),
                         "blocked_on_course": user.get("blocked_on_course", user["blocked"]),
                         "blocks": user["blocks"], "slips": user.get("slips", 0), "block_clips": user.get("block_clips", 0),
                         "landed": user["hit_by_user"], "user_missed": user["missed"],
                         "by_fighter_state": user.get("by_fighter_state", {}),
                         "joint_limit_violations": report["joint_limit_violations"] + user["joint_limit_violations"],
                         "defence_foot_shift_m": user["foot_shift_m"],
                         "contact_speeds": report["contact_speeds"], "warnings": report["warnings"],
                         "overshoot_max_m": report.get("overshoot_m", {}).get("max", 0.0),
                         "motion": report.get("motion", {})})

    def rate(a, b):
        return a / b if b else None

    def fmt(a, b):
        return f"{a}/{b}" + (f" {100.0 * a / b:3.0f}%" if b else "     ")

    print(f"{'opponent':36s} {'character':9s} {'hits':>11s} {'orders(p/q/e/i)':>16s} {'defended':>11s} {'landed':>6s}", file=sys.stderr)
    for row in rows:
        would_land = row["blocked"] + row["slipped"] + row["landed"]
        print(f"{row['opponent']:36s} {row['character']:9s} {fmt(row['hits'], row['strikes']):>11s} "
              f"{row['orders']:3d}({row['performed']}/{row['queued']}/{row['expired']}/{row['ignored']}) "
              f"{fmt(row['blocked'] + row['slipped'], would_land):>11s} {row['landed']:6d}", file=sys.stderr)
    per_opponent = {}
    for row in rows:
        total = per_opponent.setdefault(row["opponent"], {"strikes": 0, "hits": 0, "defended": 0, "would_land": 0, "blocks": 0, "block_clips": 0})
        total["blocks"] += row["blocks"]
        total["block_clips"] += row["block_clips"]
        total["strikes"] += row["strikes"]
        total["hits"] += row["hits"]
        total["defended"] += row["blocked"] + row["slipped"]
        total["would_land"] += row["blocked"] + row["slipped"] + row["landed"]
    for total in per_opponent.values():
        total["hit_rate"] = rate(total["hits"], total["strikes"])
        total["defended_rate"] = rate(total["defended"], total["would_land"])
    overall = {key: sum(t[key] for t in per_opponent.values()) for key in ("strikes", "hits", "defended", "would_land", "blocks", "block_clips")}
    overall["captured_block_share"] = rate(overall["block_clips"], overall["blocks"])
    overall["hit_rate"] = rate(overall["hits"], overall["strikes"])
    overall["defended_rate"] = rate(overall["defended"], overall["would_land"])
    overall["hit_rate_ci95"] = wilson_95(overall["hits"], overall["strikes"])
    overall["defended_rate_ci95"] = wilson_95(overall["defended"], overall["would_land"])
    def defended_counting(blocked_key, slipped_key):
        """The defended rate with blocks and slips counted as `blocked_key` and `slipped_key` say."""
        counted = {"defended": sum(row[blocked_key] + row[slipped_key] for row in rows)}
        counted["would_land"] = counted["defended"] + sum(row["landed"] for row in rows)
        counted["defended_rate"] = rate(counted["defended"], counted["would_land"])
        counted["defended_rate_ci95"] = wilson_95(counted["defended"], counted["would_land"])
        return counted

    # The same, counting a slip only where the hand's path passed within the hit radius of where the head (chest) would
    # have been without it: a slip starts for any course within the threat radius, and one that would have missed anyway
    # is no blow defended. Stricter still: a block too only where the hand's path went on to the head or chest (a
    # forearm held in the guard also stops hands that would have passed wide).
    on_course = overall["on_course"] = defended_counting("blocked", "slipped_on_course")
    strict = overall["on_course_blocks_too"] = defended_counting("blocked_on_course", "slipped_on_course")
    worst_hits = min(per_opponent.items(), key=lambda item: item[1]["hit_rate"] if item[1]["hit_rate"] is not None else 2.0)
    worst_defence = min(per_opponent.items(), key=lambda item: item[1]["defended_rate"] if item[1]["defended_rate"] is not None else 2.0)
    print("per opponent:", file=sys.stderr)
    for opponent, total in per_opponent.items():
        print(f"  {opponent:36s} hits {fmt(total['hits'], total['strikes']):>11s}  defended {fmt(total['defended'], total['would_land']):>11s}",
              file=sys.stderr)
    interval = lambda ci: f" (95% {100 * ci[0]:.0f}-{100 * ci[1]:.0f}%)" if ci else ""
    print(f"overall: hits {fmt(overall['hits'], overall['strikes'])}{interval(overall['hit_rate_ci95'])}, "
          f"defended {fmt(overall['defended'], overall['would_land'])}{interval(overall['defended_rate_ci95'])}, "
          f"slips on course only {fmt(on_course['defended'], on_course['would_land'])}{interval(on_course['defended_rate_ci95'])}, "
          f"blocks too {fmt(strict['defended'], strict['would_land'])}{interval(strict['defended_rate_ci95'])}, "
          f"captured blocks {fmt(overall['block_clips'], overall['blocks'])}; "
          f"worst hits {worst_hits[0]}, worst defence {worst_defence[0]}", file=sys.stderr)
    # Motion: speed at contact by kind, the fastest joints by move against the library's, the distance kept.
    contact = {}
    for row in rows:
        for kind, speeds in row["contact_speeds"].items():
            contact.setdefault(kind, []).extend(speeds)
    overall["speed_at_contact_mps"] = {kind: {"median": statistics.median(v), "count": len(v)} for kind, v in sorted(contact.items())}
    fastest = {}
    for row in rows:
        for move, entry in row["motion"].get("by_move", {}).items():
            best = fastest.setdefault(move, {"wrist_mps": 0.0, "ankle_mps": 0.0, "elbow_radps": 0.0, "knee_radps": 0.0, "elbow_mps": 0.0, "over_library": 0, "max_over_library": 0.0, "held_back_frames": 0, "frames": 0})
            for joint in ("wrist_mps", "ankle_mps", "elbow_radps", "knee_radps", "elbow_mps"):
                best[joint] = max(best[joint], entry.get(joint, 0.0))
            # Over: more than the speed limit's tolerance (0.1%) above the bar.
            ratios = entry.get("over_library", {}).values()
            best["over_library"] += any(ratio > 1.001 for ratio in ratios)
            best["max_over_library"] = max([best["max_over_library"], *ratios])
            best["held_back_frames"] += entry.get("held_back_frames", 0)
            best["frames"] += entry.get("frames", 0)
    overall["fastest_by_move"] = fastest
    medians = [row["motion"]["distance_between_strikes"]["median_legs"] for row in rows if row["motion"].get("distance_between_strikes", {}).get("frames")]
    overall["distance_between_strikes_legs"] = {"median_of_bouts": statistics.median(medians) if medians else None, "bouts": len(medians)}
    overall["overshoot_max_m"] = max((row["overshoot_max_m"] for row in rows), default=0.0)
    # Where the blows that land get through: by what the fighter was doing when each ended.
    by_state = {}
    for row in rows:
        for state, counts in row["by_fighter_state"].items():
            total = by_state.setdefault(state, {"would_land": 0, "defended": 0, "landed": 0})
            total["defended"] += counts["blocked"] + counts["slipped"]
            total["landed"] += counts["hit_by_user"]
            total["would_land"] += counts["blocked"] + counts["slipped"] + counts["hit_by_user"]
    for total in by_state.values():
        total["defended_rate"] = rate(total["defended"], total["would_land"])
    overall["defended_by_fighter_state"] = by_state
    print("defended, by what the fighter was doing: " + ", ".join(
        f"{state} {fmt(t['defended'], t['would_land'])}" for state, t in sorted(by_state.items()) if t["would_land"]), file=sys.stderr)
    speeds = ", ".join(f"{kind} {v['median']:.1f} m/s ({v['count']})" for kind, v in overall["speed_at_contact_mps"].items())
    print(f"speed at contact (median): {speeds}; distance between strikes (median of bouts) "
          f"{overall['distance_between_strikes_legs']['median_of_bouts'] or 0:.2f} legs; overshoot max {overall['overshoot_max_m'] * 100:.1f} cm",
          file=sys.stderr)
    for move, best in sorted(fastest.items()):
        print(f"  {move:8s} fastest wrist {best['wrist_mps']:5.1f} m/s ankle {best['ankle_mps']:5.1f} m/s elbow {best['elbow_radps']:5.1f} rad/s {best['elbow_mps']:5.1f} m/s "
              f"knee {best['knee_radps']:5.1f} rad/s; at most {best['max_over_library']:.3f} of the library's, over it in {best['over_library']} bouts; "
              f"held back {best['held_back_frames']}/{best['frames']} frames", file=sys.stderr)
    def pooled_by(key, what):
        """The landed blows and hits of the bouts grouped by one setting of the run (a distance, an order delay)."""
        groups = {}
        for row in rows:
            total = groups.setdefault(f"{row[key]:g}", {"strikes": 0, "hits": 0, "would_land": 0, "landed": 0})
            total["strikes"] += row["strikes"]
            total["hits"] += row["hits"]
            total["landed"] += row["landed"]
            total["would_land"] += row["blocked"] + row["slipped"] + row["landed"]
        for total in groups.values():
            total["hit_rate"] = rate(total["hits"], total["strikes"])
            total["defended_rate"] = rate(total["would_land"] - total["landed"], total["would_land"])
        if len(groups) > 1:
            print(f"by {what}: " + ", ".join(f"{k} landed {t['landed']}/{t['would_land']}, hits {fmt(t['hits'], t['strikes'])}"
                                           for k, t in groups.items()), file=sys.stderr)
        return groups

    # How much warning the blows that would have landed gave (blocked on course or landed; slips meet nothing): how long
    # the hand had been closing on what it met (>= 0.5 m/s), and how long before that the defence saw it (fast and on
    # course). A person needs about 0.2 s from a cue to a move: blows with less warning are stopped by a guard already
    # in their way, by a reading earlier than the hand's own approach, or not at all.
    warnings = [w for row in rows for w in row.pop("warnings")]
    approach = [w[0] for w in warnings]
    overall["warning_of_blows_that_would_land"] = {
        "count": len(warnings), "approach_s": percentiles(approach), "seen_before_s": percentiles([w[1] for w in warnings]),
        "share_approach_at_least_0_2_s": rate(sum(a >= 0.2 for a in approach), len(approach))}
    if warnings:
        w = overall["warning_of_blows_that_would_land"]
        print(f"warning of the {len(warnings)} blows that would land (p10/p50/p90): approach "
              f"{w['approach_s']['p10']:.2f}/{w['approach_s']['p50']:.2f}/{w['approach_s']['p90']:.2f} s "
              f"({100 * w['share_approach_at_least_0_2_s']:.0f}% at least 0.2 s), seen "
              f"{w['seen_before_s']['p10']:.2f}/{w['seen_before_s']['p50']:.2f}/{w['seen_before_s']['p90']:.2f} s before", file=sys.stderr)
    overall["by_distance"] = pooled_by("distance_m", "distance (m)")
    overall["by_order_delay"] = pooled_by("order_delay_s", "order delay (s)")
    print(json.dumps({"aim": args.aim, "distance_m": args.distances[0] if len(args.distances) == 1 else args.distances,
                      "order_delay_s": args.delays[0] if len(args.delays) == 1 else args.delays, "order_every_s": 2.0, "overall": overall,
                      "per_opponent": per_opponent, "bouts": rows}, indent=2))


if __name__ == "__main__":
    main()
