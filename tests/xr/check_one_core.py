#!/usr/bin/env python3
"""kumite play --xr allowed one core keeps Mesa's software rasteriser in its own thread (LP_NUM_THREADS=0: workers
on one core only take turns with the thread that waits for them); a user's own LP_NUM_THREADS is kept; with more
cores Mesa's default stands. The report says which (xr.cores_allowed, xr.software_raster_threads)."""
import json
import os
import subprocess
import sys

kumite, folder = sys.argv[1], sys.argv[2]
os.makedirs(folder, exist_ok=True)
one_core = min(os.sched_getaffinity(0))


def run(name, environment, cores):
    report = os.path.join(folder, name + ".json")
    if os.path.exists(report):
        os.remove(report)
    env = {k: v for k, v in os.environ.items() if k != "LP_NUM_THREADS"} | environment
    done = subprocess.run([kumite, "play", "--xr", "--headless", "--duration", "1", "--report", report], env=env,
                          capture_output=True, text=True, timeout=60, preexec_fn=lambda: os.sched_setaffinity(0, cores))
    assert done.returncode == 0, f"{name}: exit status {done.returncode}:\n{done.stderr[-3000:]}"
    xr = json.load(open(report))["xr"]
    print(name, {k: xr[k] for k in ("cores_allowed", "software_raster_threads", "frames_submitted", "errors")})
    assert xr["errors"] == 0 and xr["frames_submitted"] > 0, xr
    return xr


xr = run("one_core", {}, {one_core})
assert xr["cores_allowed"] == 1 and xr["software_raster_threads"] == "0", xr
xr = run("users_own", {"LP_NUM_THREADS": "3"}, {one_core})
assert xr["software_raster_threads"] == "3", xr
if len(os.sched_getaffinity(0)) > 1:
    xr = run("all_cores", {}, os.sched_getaffinity(0))
    assert xr["cores_allowed"] > 1 and xr["software_raster_threads"] == "mesa default", xr
print("one core: the drawing in kumite's thread; the user's value kept; more cores: Mesa's default")
