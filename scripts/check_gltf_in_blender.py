#!/usr/bin/env python3
"""Imports glTF characters with Blender's own glTF importer and checks that each has an armature and a skinned
mesh and that kumite's rest joint positions equal Blender's within --tolerance of the standing height.

    python3 scripts/check_gltf_in_blender.py [--kumite build/bin/kumite] [--tolerance 1e-4] FILE.glb...

One line per file (PASS/FAIL and the largest relative difference), then "N passed, M failed". Exit status 0 when
all pass, 1 otherwise, 77 when Blender is not installed (a test harness reports it skipped).
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))


def kumite_joints(kumite, path):
    positions = json.loads(subprocess.run([kumite, "positions", path, "--json"], check=True, capture_output=True, text=True).stdout)
    names = positions["joint_names"]
    frame = positions["frames"]["0"]
    inspect = json.loads(subprocess.run([kumite, "inspect", path, "--json"], check=True, capture_output=True, text=True).stdout)
    return dict(zip(names, frame)), inspect["height_m"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--kumite", default=os.path.join(HERE, "..", "build", "bin", "kumite"))
    parser.add_argument("--blender", default="blender")
    parser.add_argument("--tolerance", type=float, default=1e-4)
    parser.add_argument("files", nargs="+")
    args = parser.parse_args()
    if not shutil.which(args.blender):
        print("blender not installed: skipped")
        return 77
    passed = failed = 0
    with tempfile.TemporaryDirectory() as work:
        for path in args.files:
            out = os.path.join(work, "joints.json")
            subprocess.run([args.blender, "-b", "--factory-startup", "--python", os.path.join(HERE, "blender_gltf_joints.py"), "--", path, out],
                           check=True, capture_output=True, text=True)
            blender = json.load(open(out))
            ours, height = kumite_joints(args.kumite, path)
            problems = []
            if not blender["joints"]:
                problems.append("no armature")
            if not any(mesh["skinned"] and mesh["groups"] > 0 for mesh in blender["meshes"]):
                problems.append("no skinned mesh")
            worst, where = 0.0, ""
            for name, position in ours.items():
                if name not in blender["joints"]:
                    problems.append("joint %s missing in Blender" % name)
                    continue
                error = math.dist(position, blender["joints"][name]) / height
                if error > worst:
                    worst, where = error, name
            if worst > args.tolerance:
                problems.append("joint %s differs by %.2e of the height" % (where, worst))
            ok = not problems
            passed, failed = passed + ok, failed + (not ok)
            print("%s %s: %d joints, %d mesh vertices, max difference %.2e of the height%s" % (
                "PASS" if ok else "FAIL", path, len(ours), sum(m["vertices"] for m in blender["meshes"]), worst,
                "" if ok else " (" + "; ".join(problems[:3]) + ")"))
    print("%d passed, %d failed" % (passed, failed))
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
