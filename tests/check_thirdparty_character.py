#!/usr/bin/env python3
"""A character kumite did not make: Blender builds a humanoid with VRM/VRoid bone names, in an A-pose, Z up, in
centimetres under a 0.01 armature scale (scripts/blender_make_humanoid.py) and exports it with its own glTF
exporter. kumite must then read it (all 21 body parts), retarget a capture onto it, adapt strikes and play a bout
with it, passed as a path everywhere (--character FILE.glb):
  - bones exact (bone_length_error_m <= 0.1 mm) in retarget and adapt;
  - feet planted: adapt's support-foot drift <= 1 mm and no support foot lifted;
  - strike contact <= 1 cm for targets inside reach; in Blender, the recorded .glb shows the effector there too;
  - the repertoire bout (data/bouts/repertoire.txt) against a still user hits >= 90%.
Exit 77 (skipped) without Blender.

usage: check_thirdparty_character.py --kumite KUMITE --annotations A.json --mocap-root DIR --bout FILE
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
MAKE = os.path.join(HERE, "..", "scripts", "blender_make_humanoid.py")
sys.path.insert(0, HERE)
from check_adapt_in_blender import CASES  # noqa: E402
from check_record_glb_in_blender import blender_import, distance  # noqa: E402


def run_json(command):
    return json.loads(subprocess.run(command, check=True, capture_output=True, text=True).stdout)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--kumite", required=True)
    parser.add_argument("--annotations", required=True)
    parser.add_argument("--mocap-root", required=True)
    parser.add_argument("--bout", required=True)
    args = parser.parse_args()
    if not shutil.which("blender"):
        print("blender not installed: skipped")
        return 77
    failures = []

    def check(ok, what):
        print(("ok   " if ok else "FAIL ") + what)
        if not ok:
            failures.append(what)

    with tempfile.TemporaryDirectory() as work:
        character = os.path.join(work, "vroid_fighter.glb")
        subprocess.run(["blender", "-b", "--factory-startup", "--python-exit-code", "1", "--python", MAKE, "--", character], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        database = os.path.join(work, "db.kdb")
        subprocess.run([args.kumite, "bake", args.annotations, "-o", database, "--mocap-root", args.mocap_root], check=True,
                       stdout=subprocess.DEVNULL)

        inspect = run_json([args.kumite, "inspect", character, "--json"])
        parts = inspect["body_map"] if isinstance(inspect.get("body_map"), dict) else {}
        check(len(parts) == 21, f"inspect: {len(parts)} of 21 body parts found in the VRoid names, height {inspect.get('height_m', 0):.3f} m")

        capture = os.path.join(args.mocap_root, "bandai-namco-1", "dataset-1_kick_normal_001.bvh")
        for output in ("retargeted.bvh", "retargeted.glb"):
            report = run_json([args.kumite, "retarget", capture, "--character", character, "-o", os.path.join(work, output), "--json"])
            check(report["bone_length_error_m"] <= 1e-4,
                  f"retarget -o {output}: bone length error {report['bone_length_error_m']:.2e} m, foot drift {report['foot_drift_m'] * 1000:.1f} mm")

        for command, side, target in CASES:
            stem = os.path.join(work, f"{command}_{side}")
            subprocess.run([args.kumite, "adapt", database, "--character", character, "--target", ",".join(map(str, target)),
                            "--command", command, "--side", side, "--record", stem + ".glb", "--report", stem + ".json"],
                           check=True, stdout=subprocess.DEVNULL)
            report = json.load(open(stem + ".json"))
            what = (f"adapt {command} {side}: {report['reach']}, contact error {report['contact_error_m'] * 1000:.3f} mm, bone error"
                    f" {report['bone_length_error_m']:.1e} m, support-foot drift {report['foot_drift_m'] * 1000:.3f} mm")
            planted = report["foot_drift_m"] <= 1e-3 and not report["support_foot_lifted"]
            check(report["bone_length_error_m"] <= 1e-4 and planted and (not report["reachable"] or report["contact_error_m"] <= 0.01), what)
            if report["reachable"]:
                frame = report["contact_frame"]
                seen = blender_import(stem + ".glb", stem + ".blender.json", [frame])["posed"][str(frame)][report["effector"]]
                error = distance(seen, target)
                check(error <= 0.01, f"  Blender: {report['effector']} at frame {frame} is {error * 1000:.3f} mm from the target")

        bout = os.path.join(work, "bout.json")
        recording = os.path.join(work, "bout.glb")
        subprocess.run([args.kumite, "play", database, "--headless", "--character", character, "--tracker", "simulate:still",
                        "--commands", "script:" + args.bout, "--duration", "85", "--report", bout, "--record", recording],
                       check=True, stdout=subprocess.DEVNULL)
        report = json.load(open(bout))
        check(report["strikes"] > 0 and report["hits"] >= 0.9 * report["strikes"],
              f"play the repertoire: {report['hits']} hits of {report['strikes']} strikes, {report['joint_limit_violations']} joint-limit violations")
        blender = blender_import(recording, os.path.join(work, "bout.blender.json"), [0, report["frames"] - 1])
        keys = max(a["keys"] for a in blender["actions"].values())
        hips = [blender["posed"][str(f)]["J_Bip_C_Hips"] for f in (0, report["frames"] - 1)]
        check(keys == report["frames"] and all(abs(h[1] - 0.96) < 0.2 for h in hips),
              f"  Blender: the bout's recording has {keys} keys for {report['frames']} frames, the hips at {hips[-1][1]:.2f} m at the end")
    print(f"{len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
