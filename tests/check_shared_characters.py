#!/usr/bin/env python3
"""Third-party humanoids as users bring them (../shared/characters: control rigs, IK rigs with detached feet, FBX
exports scaled 100, .gltf + .bin without neck or clavicles, a file saved in an animation pose): each one is read,
a right punch and a right kick at targets inside its reach (from its own rest skeleton) land within --tolerance
with bones exact and the support foot planted, the `--record OUT.glb` recording shows the effector on the target in
Blender's importer and the `--record OUT.bvh` one read back by kumite, and a short bout against a still user plays and hits. Exit 77 (skipped) without the folder or
Blender.

usage: check_shared_characters.py --kumite KUMITE (--database DB.kdb | --annotations A.json --mocap-root DIR)
                                  --characters-root DIR [--capture FILE.bvh] [--tolerance 0.01]
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from check_adapt_in_blender import add_database_arguments, database_in  # noqa: E402
from check_record_glb_in_blender import blender_import, distance  # noqa: E402


def kumite_json(kumite, *args):
    return json.loads(subprocess.run([kumite, *args, "--json"], check=True, capture_output=True, text=True).stdout)


def reachable_targets(kumite, character):
    """A right punch target at 60% of the arm's length straight ahead of the right shoulder, a right kick target
    at 75% of the leg's length ahead of the right hip, a little below it: inside reach whatever the proportions."""
    info = kumite_json(kumite, "inspect", character)
    rest = kumite_json(kumite, "positions", character)["frames"]["0"]
    at = lambda part: rest[info["joint_names"].index(info["body_map"][part])]
    shoulder, elbow, wrist = at("upper_arm_r"), at("forearm_r"), at("hand_r")
    hip, knee, ankle = at("thigh_r"), at("shin_r"), at("foot_r")
    arm = distance(shoulder, elbow) + distance(elbow, wrist)
    leg = distance(hip, knee) + distance(knee, ankle)
    return {"punch": [shoulder[0] * 0.5, shoulder[1] * 0.98, 0.6 * arm], "kick": [hip[0], hip[1] * 0.9, 0.75 * leg]}, info


def main():
    parser = argparse.ArgumentParser()
    add_database_arguments(parser)
    parser.add_argument("--characters-root", required=True)
    parser.add_argument("--tolerance", type=float, default=0.01)
    parser.add_argument("--capture", help="a capture to retarget onto each character (bones must stay exact)")
    args = parser.parse_args()
    if not os.path.isdir(args.characters_root):
        print(f"{args.characters_root}: no such folder: skipped")
        return 77
    if not shutil.which("blender"):
        print("blender not installed: skipped")
        return 77
    files = sorted(os.path.join(folder, f) for folder, _, names in os.walk(args.characters_root) for f in names
                   if f.lower().endswith((".glb", ".gltf", ".vrm")))
    failures, checked = 0, 0
    with tempfile.TemporaryDirectory() as work:
        args.database = database_in(args, work)
        for character in files:
            name = os.path.splitext(os.path.basename(character))[0]
            targets, info = reachable_targets(args.kumite, character)
            print(f"{name}: {len(info['joint_names'])} joints, {info['height_m']:.2f} m, {len(info['warnings'])} warnings"
                  + "".join(f"\n  warning: {w}" for w in info["warnings"]))
            for command, target in targets.items():
                stem = os.path.join(work, f"{name}_{command}")
                subprocess.run([args.kumite, "adapt", args.database, "--character", character, "--target", ",".join(f"{v:.4f}" for v in target),
                                "--command", command, "--side", "right", "--record", stem + ".glb", "--report", stem + ".json"],
                               check=True, stdout=subprocess.DEVNULL)
                report = json.load(open(stem + ".json"))
                frame = report["contact_frame"]
                # The same strike recorded as BVH, read back by kumite: the effector where the .glb has it.
                subprocess.run([args.kumite, "adapt", args.database, "--character", character, "--target", ",".join(f"{v:.4f}" for v in target),
                                "--command", command, "--side", "right", "--record", stem + ".bvh"], check=True, stdout=subprocess.DEVNULL)
                # In metres, as kumite wrote it: BVH has no unit, and a 4.3 m robot's file reads as CMU's unit by height.
                positions = kumite_json(args.kumite, "positions", stem + ".bvh", "--frames", str(frame), "--unit", "m")
                bvh_error = distance(positions["frames"][str(frame)][positions["joint_names"].index(report["effector"])], target)
                blender = blender_import(stem + ".glb", stem + ".blender.json", [frame])
                seen = blender["posed"][str(frame)][report["effector"]]
                error = distance(seen, target)
                skinned = any(m["skinned"] and m["polygons"] > 0 for m in blender["meshes"])
                ok = (report["reachable"] and report["contact_error_m"] <= args.tolerance and error <= args.tolerance and skinned
                      and bvh_error <= args.tolerance
                      and report["bone_length_error_m"] < 1e-6 and report["foot_drift_m"] < 1e-3 and report["joint_limit_violations"] == 0)
                checked += 1
                failures += not ok
                print(f"  {command} right at {[round(v, 3) for v in target]}: {report['effector']} {report['contact_error_m'] * 1000:.3f} mm from"
                      f" the target (Blender: {error * 1000:.3f} mm, BVH: {bvh_error * 1000:.3f} mm), bones {report['bone_length_error_m']:.1e} m, foot drift"
                      f" {report['foot_drift_m']:.1e} m, {report['joint_limit_violations']} violations, skinned {'yes' if skinned else 'NO'}"
                      f" {'ok' if ok else 'FAIL'}")
            if args.capture:
                stem = os.path.join(work, f"{name}_retarget")
                subprocess.run([args.kumite, "retarget", args.capture, "--character", character, "-o", stem + ".bvh", "--report", stem + ".json"],
                               check=True, stdout=subprocess.DEVNULL)
                report = json.load(open(stem + ".json"))
                ok = report["bone_length_error_m"] < 1e-6
                checked += 1
                failures += not ok
                print(f"  retarget {os.path.basename(args.capture)}: {report['frames']} frames, bones {report['bone_length_error_m']:.1e} m,"
                      f" planted feet drift up to {report['foot_drift_m'] * 1000:.1f} mm, limb extension error {report['limb_extension_error']:.3f}"
                      f" {'ok' if ok else 'FAIL'}")
            # A bout: orders once the fighter has had time to close in on the still 1.65 m user (a chibi walks
            # slowly). The punch must land; whether a kick reaches that user's head or chest depends on the legs.
            script, stem = os.path.join(work, "orders.txt"), os.path.join(work, f"{name}_bout")
            open(script, "w").write("3.0 punch right\n6.0 kick right\n")
            subprocess.run([args.kumite, "play", args.database, "--headless", "--character", character, "--tracker", "simulate:still",
                            "--commands", "script:" + script, "--duration", "9", "--record", stem + ".glb", "--report", stem + ".json",
                            "--events", stem + ".jsonl"], check=True, stdout=subprocess.DEVNULL)
            report = json.load(open(stem + ".json"))
            outcomes = {}
            for line in open(stem + ".jsonl"):
                event = json.loads(line)
                if "contact_error_m" in event and "command" in event:
                    outcomes[event["command"]] = f"{event['contact_error_m'] * 1000:.0f} mm from the {event.get('target_part', 'head')}"
            ok = report["strikes"] == 2 and report["hits"] >= 1 and report["joint_limit_violations"] == 0 and "punch" in outcomes
            checked += 1
            failures += not ok
            print(f"  bout: {report['frames']} frames, {report['strikes']} strikes, {report['hits']} hits (punch {outcomes.get('punch', '-')},"
                  f" kick {outcomes.get('kick', '-')}) {'ok' if ok else 'FAIL'}")
    print(f"{checked} checks on {len(files)} third-party characters, {failures} failed")
    return 1 if failures or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
