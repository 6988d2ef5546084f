#!/usr/bin/env python3
"""kumite play --xr whose runtime vanishes mid-session (the vanishing_runtime_layer answers XR_ERROR_INSTANCE_LOST
after KUMITE_VANISH_AFTER_FRAMES frames): the bout ends there, within seconds, not at its 30 s; the report says so
(ended_by runtime_lost, the frames waited and submitted, the error counted) and the events end with bout_end."""
import json
import os
import subprocess
import sys

kumite, folder = sys.argv[1], sys.argv[2]
os.makedirs(folder, exist_ok=True)
report, events = os.path.join(folder, "report.json"), os.path.join(folder, "events.jsonl")
for path in (report, events):
    if os.path.exists(path):
        os.remove(path)
after = int(os.environ.get("KUMITE_VANISH_AFTER_FRAMES", "40"))
run = subprocess.run([kumite, "play", "--xr", "--duration", "30", "--report", report, "--events", events],
                     capture_output=True, text=True, timeout=100)
lost = [line for line in run.stderr.splitlines() if "runtime was lost" in line]
print("exit", run.returncode, lost)
assert run.returncode == 0, f"exit status {run.returncode}:\n{run.stderr[-3000:]}"
assert lost, "no message that the runtime was lost"
xr = json.load(open(report))["xr"]
print({k: xr[k] for k in ("ended_by", "frames_waited", "frames_submitted", "errors", "error_messages", "states")})
assert xr["ended_by"] == "runtime_lost", xr["ended_by"]
# The frame waited last was in flight when the runtime went: it could not be begun, so not submitted.
assert xr["frames_waited"] == after and xr["frames_submitted"] == after - 1, (xr["frames_waited"], xr["frames_submitted"])
assert xr["errors"] >= 1 and "XR_ERROR_INSTANCE_LOST" in xr["error_messages"][0], xr["error_messages"]
assert "focused" in xr["states"]
lines = [json.loads(line) for line in open(events)]
assert lines[-1]["type"] == "bout_end", lines[-1]["type"]
assert lines[-1]["t"] < 10.0, f"the bout ran on to {lines[-1]['t']} s after the runtime was lost"
print(f"runtime lost after {after} frames: bout ended at {lines[-1]['t']:.2f} s, report and events written")
