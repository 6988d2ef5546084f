#!/usr/bin/env python3
"""kumite play fed by DTrack datagrams over loopback UDP, in real time: valid heads, malformed ones, NaN, a head
outside the room, and 2 s of silence. The player must keep stepping (no missed frame), count the bad datagrams,
strike at the head before the silence, hold during it (an order then is ignored for want of a head), and recover
when the datagrams come back.

usage: check_play_dtrack.py KUMITE ANNOTATIONS MOCAP_ROOT
"""
import json
import math
import os
import random
import socket
import subprocess
import sys
import tempfile
import time


def main():
    kumite, annotations, mocap = sys.argv[1:4]
    with tempfile.TemporaryDirectory() as work:
        database = os.path.join(work, "ref.kdb")
        subprocess.run([kumite, "bake", annotations, "-o", database, "--mocap-root", mocap], check=True, stdout=subprocess.DEVNULL)
        script = os.path.join(work, "orders.txt")
        with open(script, "w") as f:
            f.write("1.0 punch left\n3.5 kick\n5.5 punch\n")
        port = random.randint(20000, 60000)
        events = os.path.join(work, "events.jsonl")
        player = subprocess.Popen([kumite, "play", database, "--character", "brawler", "--tracker", f"dtrack:{port}:1",
                                   "--commands", "script:" + script, "--headless", "--duration", "7", "--events", events, "--json"],
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        time.sleep(0.3)
        sender = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        start = time.time()
        frame = 0
        sent_bad = 0
        while time.time() - start < 7.2:
            t = time.time() - start
            frame += 1
            if 2.0 < t < 4.0:
                time.sleep(1 / 60)
                continue
            if frame % 50 == 0:
                message, sent_bad = f"fr {frame}\n6d 1 [1 1.0][nan 1600 900][1 0 0 0 1 0 0 0 1]\n", sent_bad + 1
            elif frame % 70 == 0:
                message, sent_bad = f"fr {frame}\n6d 1 [1 1.0][9000 1600 900][1 0 0 0 1 0 0 0 1]\n", sent_bad + 1
            elif frame % 90 == 0:
                message, sent_bad = "garbage\x00\x01", sent_bad + 1
            else:
                message = f"fr {frame}\nts {t:.3f}\n6d 1 [1 1.000][{100 * math.sin(t):.1f} 1600.0 900.0][1 0 0 0 1 0 0 0 1]\n"
            sender.sendto(message.encode(), ("127.0.0.1", port))
            time.sleep(1 / 60)
        out, err = player.communicate(timeout=30)
        if player.returncode != 0:
            print(err)
            return 1
        report = json.loads(out)
        lines = [json.loads(line) for line in open(events)]
        types = [e["type"] for e in lines]
        print(json.dumps({k: report[k] for k in ["frames", "missed_frames", "orders", "strikes", "hits", "ignored_orders",
                                                  "tracker_packets", "tracker_rejected"]}))
        checks = {
            "every frame stepped": report["frames"] == 420,
            "bad datagrams counted": report["tracker_rejected"] >= sent_bad // 2,
            "a strike before the silence": report["strikes"] >= 1,
            "silence noticed": "tracker_lost" in types,
            "an order in the silence ignored": any(e["type"] == "ignored_order" and "no head" in e.get("why", "") for e in lines),
            "recovered": "tracker_back" in types and types.index("tracker_back") > types.index("tracker_lost"),
            "a strike after recovering": any(e["type"] == "strike" and e["t"] > 5.0 for e in lines),
        }
        for name, ok in checks.items():
            print(("ok   " if ok else "FAIL ") + name)
        return 0 if all(checks.values()) else 1


if __name__ == "__main__":
    sys.exit(main())
