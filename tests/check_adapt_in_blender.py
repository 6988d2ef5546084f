#!/usr/bin/env python3
"""Blender sees the effector at the target and not past it: for each character and a punch and a kick at reachable
targets, `kumite adapt` writes a BVH and a report; Blender's own BVH importer (scripts/blender_bvh_positions.py) gives
the effector joint's positions from just before the contact frame to the end. At the report's contact frame the
effector must lie within --tolerance metres of the target; in no later frame may it be more than --overshoot metres
past where it stopped, along the way it arrived (its own last frame before the contact, as Blender sees it).
Exit 77 (skipped) without Blender.

usage: check_adapt_in_blender.py --kumite KUMITE (--database DB.kdb | --annotations A.json --mocap-root DIR)
                                 --characters DIR [--tolerance 0.01]
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
POSITIONS = os.path.join(HERE, "..", "scripts", "blender_bvh_positions.py")
CASES = [  # command, side, target (m): in front of each character, between hip and head height
    ("punch", "left", (0.10, 0.95, 0.45)),
    ("punch", "right", (-0.05, 1.05, 0.50)),
    ("kick", "right", (-0.10, 0.80, 0.55)),
    ("kick", "left", (0.10, 0.75, 0.60)),
]


def norm(v):
    return sum(x * x for x in v) ** 0.5


def distance(a, b):
    return norm([x - y for x, y in zip(a, b)])


def add_database_arguments(parser):
    """--kumite, --database or --annotations with --mocap-root, --characters: shared by the Blender checks of adapt."""
    parser.add_argument("--kumite", required=True)
    parser.add_argument("--database")
    parser.add_argument("--annotations", help="bake these first (when no --database)")
    parser.add_argument("--mocap-root")
    parser.add_argument("--characters", required=True)


def database_in(args, work):
    """The --database, or the --annotations baked into `work`."""
    if args.database:
        return args.database
    database = os.path.join(work, "db.kdb")
    subprocess.run([args.kumite, "bake", args.annotations, "-o", database, "--mocap-root", args.mocap_root],
                   check=True, stdout=subprocess.DEVNULL)
    return database


def main():
    parser = argparse.ArgumentParser()
    add_database_arguments(parser)
    parser.add_argument("--tolerance", type=float, default=0.01)
    parser.add_argument("--overshoot", type=float, default=0.03)
    args = parser.parse_args()
    if not shutil.which("blender"):
        print("blender not installed: skipped")
        return 77
    failures = 0
    checked = 0
    with tempfile.TemporaryDirectory() as work:
        args.database = database_in(args, work)
        for file in sorted(os.listdir(args.characters)):
            if not file.endswith(".bvh"):
                continue
            character = file[:-4]
            for command, side, target in CASES:
                stem = os.path.join(work, f"{character}_{command}_{side}")
                subprocess.run([args.kumite, "adapt", args.database, "--character", character, "--characters-dir", args.characters,
                                "--target", ",".join(map(str, target)), "--command", command, "--side", side,
                                "--record", stem + ".bvh", "--report", stem + ".json"], check=True, stdout=subprocess.DEVNULL)
                report = json.load(open(stem + ".json"))
                if not report["reachable"]:
                    print(f"{character} {command} {side}: target out of reach, not checked")
                    continue
                inspect = json.loads(subprocess.run([args.kumite, "inspect", stem + ".bvh", "--json"], check=True,
                                                    capture_output=True, text=True).stdout)
                frame = report["contact_frame"]
                subprocess.run(["blender", "-b", "--factory-startup", "--python", POSITIONS, "--", stem + ".bvh",
                                stem + ".blender.json", "--frame-list", f"{max(0, frame - 2)}-{inspect['frames'] - 1}"], check=True,
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                blender = json.load(open(stem + ".blender.json"))
                joint = blender["joint_names"].index(report["effector"])
                scale = inspect["unit_scale_m"]

                def effector(f):
                    return [v * scale for v in blender["frames"][str(f)][joint]]

                seen = effector(frame)
                error = distance(seen, target)
                approach = report["approach_direction"]
                for back in (1, 2):
                    if frame - back >= 0:
                        arriving = [a - b for a, b in zip(seen, effector(frame - back))]
                        if norm(arriving) > 0.01:
                            approach = [v / norm(arriving) for v in arriving]
                            break
                past = max([sum((a - b) * u for a, b, u in zip(effector(f), seen, approach))
                            for f in range(frame + 1, inspect["frames"])] + [0.0])
                checked += 1
                status = "ok" if error <= args.tolerance and past <= args.overshoot else "FAIL"
                failures += status == "FAIL"
                print(f"{character} {command} {side}: {report['effector']} at frame {frame} is {error * 1000:.2f} mm from the target"
                      f" in Blender (kumite: {report['contact_error_m'] * 1000:.3f} mm), at most {past * 1000:.1f} mm past it"
                      f" afterwards (kumite: {report['overshoot_m'] * 1000:.1f} mm) {status}")
    print(f"{checked} adapted strikes checked in Blender, {failures} beyond {args.tolerance} m at the contact"
          f" or {args.overshoot} m past the target after it")
    return 1 if failures or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
