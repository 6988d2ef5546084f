#!/usr/bin/env python3
"""A soak run of `kumite play`: realtime, N minutes, a DTrack stream from a local sender (one 6d body walking slowly
about the room at 60 Hz), an order every 2 s and a character switch every 30 s. Samples the player's resident memory
every 2 s and prints one JSON document: resident memory after the warm-up (the first minute, or a third of a shorter
run) and at the end, the growth between them, missed frames, strikes and tracker counts. Resident memory is VmRSS,
and apart its anonymous part (RssAnon: heap and stacks, what a leak grows) and its file-backed part (RssFile: the
executable and the mapped database, whose pages come in as the bout first reads them: opening maps the file and
reads no pose).

usage: scripts/soak.py [--minutes N] [--kumite build/bin/kumite] [--database DB.kdb] [--max-growth-kb K]
With --max-growth-kb the exit status is 1 when anonymous resident memory grew more than K KB after the warm-up.
Without --database the player uses its default database (kumite play with no DB).
"""
import argparse
import json
import math
import os
import socket
import subprocess
import sys
import tempfile
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def free_udp_port():
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def send_dtrack(port, stop):
    """One 6d body (id 1) walking a slow circle 1.5 m in front of the fighter, 60 datagrams a second."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as sender:
        frame, start = 0, time.monotonic()
        while not stop.is_set():
            t = time.monotonic() - start
            x, z = 300.0 * math.sin(0.2 * t), 1500.0 + 300.0 * math.cos(0.2 * t)
            datagram = f"fr {frame}\r\nts {t:.6f}\r\n6d 1 [1 1.000][{x:.3f} 1650.000 {z:.3f} 0 0 0][1 0 0 0 1 0 0 0 1]\r\n"
            sender.sendto(datagram.encode(), ("127.0.0.1", port))
            frame += 1
            time.sleep(max(0.0, start + frame / 60.0 - time.monotonic()))


def resident_kb(pid):
    """(VmRSS, RssAnon, RssFile) in KB, or None once the process is gone."""
    fields = {}
    try:
        with open(f"/proc/{pid}/status") as status:
            for line in status:
                name = line.split(":")[0]
                if name in ("VmRSS", "RssAnon", "RssFile"):
                    fields[name] = int(line.split()[1])
    except OSError:
        return None
    if len(fields) != 3:
        return None
    return fields["VmRSS"], fields["RssAnon"], fields["RssFile"]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--minutes", type=float, default=30.0)
    parser.add_argument("--kumite", default=os.path.join(HERE, "..", "build", "bin", "kumite"))
    parser.add_argument("--database")
    parser.add_argument("--max-growth-kb", type=float)
    args = parser.parse_args()
    seconds = args.minutes * 60.0
    warm_up = min(60.0, seconds / 3.0)
    port = free_udp_port()
    with tempfile.TemporaryDirectory() as work:
        script = os.path.join(work, "orders.txt")
        with open(script, "w") as orders:
            characters = ["brawler", "giant", "runner", "scout", "kid"]
            t, n = 2.0, 0
            while t < seconds:
                orders.write(f"{t:.1f} {['punch', 'kick', 'punch left', 'kick right'][n % 4]}\n")
                if n % 15 == 14:
                    orders.write(f"{t + 1.0:.1f} character {characters[(n // 15) % len(characters)]}\n")
                t, n = t + 2.0, n + 1
        report = os.path.join(work, "report.json")
        command = [args.kumite, "play"] + ([args.database] if args.database else []) + [
            "--tracker", f"dtrack:{port}", "--commands", f"script:{script}", "--headless", "--realtime",
            "--duration", str(seconds), "--report", report]
        stop = threading.Event()
        sender = threading.Thread(target=send_dtrack, args=(port, stop), daemon=True)
        sender.start()
        player = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        began, samples = time.monotonic(), []
        while player.poll() is None:
            kb = resident_kb(player.pid)
            if kb is not None:
                samples.append((time.monotonic() - began, kb))
            time.sleep(2.0)
        stop.set()
        errors = player.stderr.read()
        if player.returncode != 0:
            print(f"soak: kumite play failed ({player.returncode}): {errors}", file=sys.stderr)
            return 2
        played = json.load(open(report))
    after_warm_up = [kb for t, kb in samples if t >= warm_up]
    none = (0, 0, 0)
    start_kb = after_warm_up[0] if after_warm_up else (samples[0][1] if samples else none)
    end_kb = samples[-1][1] if samples else none
    result = {
        "minutes": args.minutes,
        "warm_up_s": warm_up,
        "resident_kb_after_warm_up": start_kb[0],
        "resident_kb_at_end": end_kb[0],
        "resident_growth_kb": end_kb[0] - start_kb[0],
        "resident_kb_max": max((kb[0] for _, kb in samples), default=0),
        "anonymous_kb_after_warm_up": start_kb[1],
        "anonymous_growth_kb": end_kb[1] - start_kb[1],
        "file_backed_kb_after_warm_up": start_kb[2],
        "file_backed_growth_kb": end_kb[2] - start_kb[2],
        "samples": len(samples),
        "frames": played["frames"],
        "missed_frames": played["missed_frames"],
        "orders": played["orders"],
        "strikes": played["strikes"],
        "hits": played["hits"],
        "tracker_packets": played["tracker_packets"],
        "tracker_rejected": played["tracker_rejected"],
        "frame_time_us": played["frame_time_us"],
    }
    print(json.dumps(result, indent=2))
    if args.max_growth_kb is not None and result["anonymous_growth_kb"] > args.max_growth_kb:
        print(f"soak: anonymous resident memory grew {result['anonymous_growth_kb']} KB after the warm-up, more than "
              f"{args.max_growth_kb}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
