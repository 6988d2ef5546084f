#!/usr/bin/env python3
"""Recordings with the body open in Blender: `kumite adapt --record OUT.glb` for every character with a body (a punch
and a kick each side at reachable targets), imported with Blender's own glTF importer (scripts/blender_gltf_joints.py),
must show a skinned mesh and the effector joint at the report's contact frame within --tolerance of the target; the
action must hold one key per recorded frame. Then `kumite play --record OUT.glb` on each character: the action holds
as many frames as the bout. Exit 77 (skipped) without Blender.

usage: check_record_glb_in_blender.py --kumite KUMITE (--database DB.kdb | --annotations A.json --mocap-root DIR)
                                      --characters DIR [--tolerance 0.01]
"""
import argparse
import json
import os
import shutil
import struct
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
JOINTS = os.path.join(HERE, "..", "scripts", "blender_gltf_joints.py")
sys.path.insert(0, HERE)
from check_adapt_in_blender import CASES, add_database_arguments, database_in  # noqa: E402  the same orders and targets as the BVH check


def glb_frame_rate(path):
    """Frames per second of a kumite recording: from its animation's time accessor (count and max)."""
    data = open(path, "rb").read()
    length = struct.unpack("<I", data[12:16])[0]
    gltf = json.loads(data[20:20 + length])
    times = gltf["accessors"][gltf["animations"][0]["samplers"][0]["input"]]
    return (times["count"] - 1) / times["max"][0] if times["max"][0] > 0 else 30.0


def blender_import(glb, out_json, frames=()):
    command = ["blender", "-b", "--factory-startup", "--python-exit-code", "1", "--python", JOINTS, "--", glb, out_json, "--fps", str(glb_frame_rate(glb))]
    if frames:
        command += ["--frames", ",".join(str(f) for f in frames)]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return json.load(open(out_json))


def distance(a, b):
    return sum((x - y) ** 2 for x, y in zip(a, b)) ** 0.5


def main():
    parser = argparse.ArgumentParser()
    add_database_arguments(parser)
    parser.add_argument("--tolerance", type=float, default=0.01)
    args = parser.parse_args()
    if not shutil.which("blender"):
        print("blender not installed: skipped")
        return 77
    failures, checked = 0, 0
    characters = sorted({f.rsplit(".", 1)[0] for f in os.listdir(args.characters) if f.endswith(".glb")})
    with tempfile.TemporaryDirectory() as work:
        args.database = database_in(args, work)
        for character in characters:
            for command, side, target in CASES:
                stem = os.path.join(work, f"{character}_{command}_{side}")
                subprocess.run([args.kumite, "adapt", args.database, "--character", character, "--characters-dir", args.characters,
                                "--target", ",".join(map(str, target)), "--command", command, "--side", side,
                                "--record", stem + ".glb", "--report", stem + ".json"], check=True, stdout=subprocess.DEVNULL)
                report = json.load(open(stem + ".json"))
                if not report["reachable"]:
                    print(f"{character} {command} {side}: target out of reach, not checked")
                    continue
                frame = report["contact_frame"]
                blender = blender_import(stem + ".glb", stem + ".blender.json", [frame])
                seen = blender["posed"][str(frame)][report["effector"]]
                error = distance(seen, target)
                keys = max(a["keys"] for a in blender["actions"].values())
                skinned = any(m["skinned"] and m["polygons"] > 0 for m in blender["meshes"])
                ok = error <= args.tolerance and keys == report["frames"] and skinned
                checked += 1
                failures += not ok
                print(f"{character} {command} {side}: {report['effector']} at frame {frame} is {error * 1000:.4f} mm from the target in"
                      f" Blender (kumite: {report['contact_error_m'] * 1000:.3f} mm); {keys} keys for {report['frames']} frames;"
                      f" skinned mesh {'yes' if skinned else 'NO'} {'ok' if ok else 'FAIL'}")
            # A bout recorded with the body: as many animation frames as the bout stepped.
            script, stem = os.path.join(work, "orders.txt"), os.path.join(work, f"{character}_bout")
            open(script, "w").write("0.5 punch\n2.0 kick\n")
            subprocess.run([args.kumite, "play", args.database, "--headless", "--character", character, "--characters-dir", args.characters,
                            "--tracker", "simulate:still", "--commands", "script:" + script, "--duration", "4",
                            "--record", stem + ".glb", "--report", stem + ".json"], check=True, stdout=subprocess.DEVNULL)
            report = json.load(open(stem + ".json"))
            blender = blender_import(stem + ".glb", stem + ".blender.json")
            keys = max(a["keys"] for a in blender["actions"].values())
            frames = max(a["frames"] for a in blender["actions"].values())
            skinned = any(m["skinned"] and m["polygons"] > 0 for m in blender["meshes"])
            ok = keys == report["frames"] and frames == report["frames"] and skinned
            checked += 1
            failures += not ok
            print(f"{character} bout: {report['frames']} frames played, Blender's action spans {frames} frames with {keys} keys;"
                  f" skinned mesh {'yes' if skinned else 'NO'} {'ok' if ok else 'FAIL'}")
    print(f"{checked} glTF recordings checked in Blender, {failures} failed")
    return 1 if failures or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
