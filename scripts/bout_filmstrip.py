#!/usr/bin/env python3
"""Frames of a bout around each strike's contact, to judge by eye: the fighter (from `kumite play --record`), the
user's head and hands as the tracker gave them (`--record-user`), the target aimed at and the hit point's path.
One row per strike: frames from 0.3 s before the contact to 0.1 s after (--offsets), seen from the side (the fighter's
right; the user to the right) above and from the top below (--views side,front,top: any of them, in that order;
--zoom: half the width seen, metres). For the user's strikes, the fighter's blocking arm is drawn in purple.

  scripts/bout_filmstrip.py --fighter F.bvh --user U.csv --events E.jsonl [--strikes 0,1,2] [--types strike,user_strike]
                            [--views side,top] [--zoom 1.1] [--kumite build/bin/kumite] -o OUT.png

Needs numpy and matplotlib (Debian: python3-numpy, python3-matplotlib).
"""
import argparse
import json
import os
import subprocess
import sys

import numpy as np

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BONES = [("pelvis", "spine"), ("spine", "chest"), ("chest", "neck"), ("neck", "head"),
         ("chest", "clavicle_l"), ("clavicle_l", "upper_arm_l"), ("upper_arm_l", "forearm_l"), ("forearm_l", "hand_l"),
         ("chest", "clavicle_r"), ("clavicle_r", "upper_arm_r"), ("upper_arm_r", "forearm_r"), ("forearm_r", "hand_r"),
         ("pelvis", "thigh_l"), ("thigh_l", "shin_l"), ("shin_l", "foot_l"), ("foot_l", "toe_l"),
         ("pelvis", "thigh_r"), ("thigh_r", "shin_r"), ("shin_r", "foot_r"), ("foot_r", "toe_r")]
OFFSETS_S = (-0.3, -0.2, -0.1, 0.0, 0.1)


def run_json(args):
    return json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--fighter", required=True)
    parser.add_argument("--user", required=True)
    parser.add_argument("--events", required=True)
    parser.add_argument("--strikes", default=None, help="indices of the strikes to draw (default: the first four)")
    parser.add_argument("--types", default="strike", help="event types to draw: strike (the fighter's), user_strike (the user's)")
    parser.add_argument("--kumite", default=os.path.join(root, "build", "bin", "kumite"))
    parser.add_argument("--offsets", default=",".join(str(o) for o in OFFSETS_S),
                        help="seconds from the contact of each column (default -0.3,-0.2,-0.1,0,0.1; a block wants a finer -0.15,...,0.05)")
    parser.add_argument("--views", default="side,top", help="side (the fighter's right), front (facing the fighter), top")
    parser.add_argument("--zoom", type=float, default=1.1, help="half the width seen around the middle, metres")
    parser.add_argument("-o", "--out", required=True)
    args = parser.parse_args()
    offsets = [float(o) for o in args.offsets.split(",")]
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    info = run_json([args.kumite, "inspect", args.fighter, "--json"])
    fps = info["fps"]
    names = info["joint_names"]
    parts = {part: names.index(joint) for part, joint in info["body_map"].items()}
    frames = run_json([args.kumite, "positions", args.fighter, "--all", "--json"])["frames"]
    fighter = np.array([frames[str(i)] for i in range(len(frames))])
    user = np.genfromtxt(args.user, delimiter=",", comments="#")
    types = args.types.split(",")
    events = [json.loads(line) for line in open(args.events)]
    chosen = [e for e in events if e["type"] in types]
    indices = [int(i) for i in args.strikes.split(",")] if args.strikes else list(range(min(4, len(chosen))))
    chosen = [chosen[i] for i in indices if i < len(chosen)]
    if not chosen:
        sys.exit("bout_filmstrip: no such events in " + args.events)

    # Per view, the horizontal and vertical axes on the page, in the frame of the row's event: forward (from the
    # fighter's pelvis towards the user's head, horizontal), the fighter's left (as the user sees it: to the right),
    # up. Side: forward right, up; front: the fighter's left right, up; top: the left right, forward up.
    view_axes = {"side": (0, 2), "front": (1, 2), "top": (1, 0)}
    views = [v for v in args.views.split(",") if v in view_axes] or ["side", "top"]
    zoom = args.zoom
    rows = len(views)
    fig, axes = plt.subplots(rows * len(chosen), len(offsets), figsize=(3.0 * len(offsets), 2.8 * rows * len(chosen)), squeeze=False)
    for row, event in enumerate(chosen):
        contact_s = event["t"] + (event.get("time_to_impact_s", 0.0) if event["type"] == "user_strike" else 0.0)
        effector = None
        if event["type"] == "strike":
            clip = event["clip"]
            segment = next((p for p in ("hand_l", "hand_r", "foot_l", "foot_r", "forearm_l", "forearm_r", "shin_l", "shin_r") if f"_{p}_" in clip), None)
            effector = parts.get(segment)
        target = np.array(event["target"]) if "target" in event else None
        blocking = None
        if event["type"] == "user_strike" and event.get("move") in ("synthesized", "block_clip", "block"):
            suffix = "_l" if event.get("arm") == "left" else "_r"
            blocking = {("upper_arm" + suffix, "forearm" + suffix), ("forearm" + suffix, "hand" + suffix)}
        # Each row centred between the fighter's hips and the user's head at the event (both move about the room).
        f0 = min(len(fighter) - 1, max(0, int(round(contact_s * fps))))
        u0 = user[np.argmin(np.abs(user[:, 0] - contact_s))]
        forward = u0[1:4] - fighter[f0, parts["pelvis"]]
        forward[1] = 0.0
        forward = forward / max(np.linalg.norm(forward), 1e-9)
        left = np.cross(np.array([0.0, 1.0, 0.0]), forward)
        frame = np.stack([forward, left, np.array([0.0, 1.0, 0.0])])  # rows: forward, left, up

        def page(point):
            return frame @ point
        centre = page(0.5 * (fighter[f0, parts["pelvis"]] + u0[1:4]))
        for column, offset in enumerate(offsets):
            t = contact_s + offset
            f = int(round(t * fps))
            if f < 0 or f >= len(fighter):
                continue
            u = user[np.argmin(np.abs(user[:, 0] - t))]
            head, hands = page(u[1:4]), u[4:10].reshape(2, 3)
            for view, name in enumerate(views):
                axis = axes[rows * row + view][column]
                h, v = view_axes[name]
                for a, b in BONES:
                    if a in parts and b in parts:
                        p, q = page(fighter[f, parts[a]]), page(fighter[f, parts[b]])
                        on = blocking is not None and (a, b) in blocking
                        axis.plot([p[h], q[h]], [p[v], q[v]], color="#CC79A7" if on else "#0072B2", lw=3 if on else 2)
                if effector is not None:
                    trail = fighter[max(0, f - int(0.4 * fps)):f + 1, effector] @ frame.T
                    axis.plot(trail[:, h], trail[:, v], color="#009E73", lw=1)
                axis.add_patch(plt.Circle((head[h], head[v]), 0.1, fill=False, color="#D55E00", lw=2))
                for hand in hands:
                    if np.all(np.isfinite(hand)):
                        axis.plot(page(hand)[h], page(hand)[v], "o", color="#E69F00", ms=6)
                if target is not None:
                    axis.plot(page(target)[h], page(target)[v], "x", color="#CC79A7", ms=10, mew=2)
                axis.set_aspect("equal")
                axis.set_xlim(centre[h] - zoom, centre[h] + zoom)
                if v == 2 and zoom >= 1.05:  # upright views: the whole height, or around the chest when zoomed in
                    axis.set_ylim(-0.05, 2.1)
                elif v == 2:
                    chest_y = fighter[f0, parts["chest"]][1]
                    axis.set_ylim(chest_y - zoom, chest_y + zoom)
                else:
                    axis.set_ylim(centre[v] - zoom, centre[v] + zoom)
                axis.set_xticks([])
                axis.set_yticks([])
                if view > 0:
                    axis.set_ylabel(name, fontsize=8)
                if view == 0:
                    label = f"{offset:+.2f} s" if offset else "contact"
                    if column == 0:
                        what = event.get("clip", event.get("hand", "")) + " " + event.get("result", event.get("move", ""))
                        label = f"t={event['t']:.2f} s {what}\n{label}"
                    axis.set_title(label, fontsize=8)
    fig.suptitle("fighter (blue; the blocking arm purple), user head (circle) and hands (dots), target (x), hit point path (green); views: "
                 + ", ".join(views), fontsize=9)
    fig.tight_layout()
    fig.savefig(args.out, dpi=80)


if __name__ == "__main__":
    main()
