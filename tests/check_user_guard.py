#!/usr/bin/env python3
"""The user's guard in the fight (user_guard.enabled): the fighter against a recorded boxer (CMU subject 14's box-1,
gloves up), a punch or kick every 2 s. Read from outside, from what the bout wrote (its events, the fighter's
recording and the user's track): strikes the user's glove or forearm met first are told blocked, never hit; and
while a strike blocked by a glove is still under way (to its strike_end), the fighter's fist stays out of that
glove (its centre 8 cm past the wrist, a 5 cm fist against a 10 cm glove, 3 cm of give: the stop holds the wrist,
and the fist turns about it by a little).

  check_user_guard.py KUMITE ANNOTATIONS.json MOCAP_ROOT
"""
import json
import math
import os
import subprocess
import sys
import tempfile


def main():
    kumite, annotations, mocap = sys.argv[1:4]
    boxer = os.path.join(mocap, "cmu14-boxing", "box-1.bvh")
    with tempfile.TemporaryDirectory() as work:
        database = os.path.join(work, "ref.kdb")
        subprocess.run([kumite, "bake", annotations, "-o", database, "--mocap-root", mocap], check=True, stdout=subprocess.DEVNULL)
        orders = os.path.join(work, "orders.txt")
        with open(orders, "w") as out:
            t, n = 1.0, 0
            while t < 29.0:
                out.write(f"{t:.2f} {'punch' if n % 2 == 0 else 'kick'} {'left' if (n // 2) % 2 == 0 else 'right'}\n")
                t, n = t + 2.0, n + 1
        events, record, user = (os.path.join(work, name) for name in ("bout.jsonl", "bout.bvh", "user.csv"))
        subprocess.run([kumite, "play", database, "--tracker", f"capture:{boxer}:1.2", "--character", "brawler", "--aim", "predicted",
                        "--commands", f"script:{orders}", "--headless", "--duration", "30", "--set", "user_guard.enabled=true",
                        "--events", events, "--record", record, "--record-user", user], check=True, stdout=subprocess.DEVNULL)
        info = json.loads(subprocess.run([kumite, "inspect", record, "--json"], check=True, capture_output=True, text=True).stdout)
        positions = json.loads(subprocess.run([kumite, "positions", record, "--all", "--json"], check=True, capture_output=True, text=True).stdout)
        lines = [json.loads(line) for line in open(events)]
        track = [[float(x) for x in line.split(",")] for line in open(user) if not line.startswith("#")]
    names, body_map, fps = positions["joint_names"], info["body_map"], info["fps"]
    frames = [positions["frames"][k] for k in sorted(positions["frames"], key=int)]

    def fist(frame, side):
        wrist = frames[frame][names.index(body_map["hand_" + side])]
        elbow = frames[frame][names.index(body_map["forearm_" + side])]
        along = [w - e for w, e in zip(wrist, elbow)]
        length = math.sqrt(sum(a * a for a in along)) or 1.0
        return [w + 0.08 * a / length for w, a in zip(wrist, along)]

    strikes = [e for e in lines if e["type"] == "strike"]
    blocked = [e for e in strikes if e["result"] == "blocked"]
    assert len(strikes) >= 12, f"only {len(strikes)} strikes"
    assert all(not e.get("hit", False) and e["blocked_by"].startswith(("glove_", "forearm_")) for e in blocked), "a blocked strike told otherwise"
    assert all("blocked_by" not in e for e in strikes if e["result"] != "blocked")
    assert len(blocked) >= 3, f"only {len(blocked)} of {len(strikes)} strikes blocked by a boxer in guard"
    ends = [e["t"] for e in lines if e["type"] == "strike_end"]
    deepest, checked = 0.0, 0
    for e in blocked:
        if not e["blocked_by"].startswith("glove_"):
            continue
        glove = 0 if e["blocked_by"] == "glove_left" else 1
        side = "l" if e["clip_side"] == "left" else "r"
        end = min((t for t in ends if t >= e["t"]), default=e["t"])
        for frame in range(int(round(e["t"] * fps)), min(len(frames), len(track), int(round(end * fps)) + 1)):
            centre = track[frame][4 + 3 * glove: 7 + 3 * glove]
            deepest = max(deepest, 0.15 - math.dist(fist(frame, side), centre))
            checked += 1
    print(f"check_user_guard: {len(blocked)} of {len(strikes)} strikes blocked by the user; over {checked} frames of strikes "
          f"a glove blocked, the fist at most {deepest * 100:.1f} cm inside it")
    assert deepest <= 0.03, f"the fist went {deepest * 100:.1f} cm into the glove that blocked it"
    return 0


if __name__ == "__main__":
    sys.exit(main())
