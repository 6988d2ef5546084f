#!/usr/bin/env python3
"""Cross-check kumite's BVH writer + forward kinematics against Blender's BVH importer.

    python3 scripts/check_blender_import.py [--kumite build/bin/kumite] [--tolerance 1e-4]
        [--frames 30] [--no-last] [--original] [--blender blender] [--jobs 1] FILE.bvh...

For each FILE:
  1. kumite convert FILE TMP.bvh                         (kumite's reader + writer)
  2. blender -b --factory-startup --python scripts/blender_bvh_positions.py -- TMP.bvh OUT.json
     --frame-list F                                     (Blender's importer, file units)
  3. kumite positions TMP.bvh --frames F --json           (kumite's reader + FK, metres)
  4. both in metres (Blender's output times kumite inspect's unit_scale_m of TMP.bvh);
     max joint distance over the compared frames / height_m (kumite inspect) must be
     <= --tolerance.
F = the first --frames frames (default 30) plus the last frame (unless --no-last); --all
compares every frame (slow on long captures).

With --original the same comparison is also made on FILE itself (Blender on the original
file vs kumite positions of the original): a mismatch only after conversion points at the
writer, a mismatch on the original too at the reader / FK (or at Blender).

One line per file (PASS/FAIL, max relative error, where it occurs), then exactly
"N passed, M failed".  Exit status: 0 all passed, 1 some failed, 2 usage error,
77 when Blender (or kumite) is not available (so a test harness can report "skipped").
"""

import argparse
import concurrent.futures
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
BLENDER_SCRIPT = os.path.join(HERE, "blender_bvh_positions.py")
SKIP = 77


class CheckError(Exception):
    pass


def run(cmd, timeout):
    for attempt in range(3):
        try:
            p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               timeout=timeout, text=True, errors="replace")
            break
        except subprocess.TimeoutExpired:
            raise CheckError("timed out after %ss: %s" % (timeout, " ".join(cmd)))
        except OSError as e:
            # e.g. the binary is being relinked by a concurrent build (EACCES / ETXTBSY)
            if attempt == 2:
                raise CheckError("cannot run %s: %s" % (cmd[0], e))
            time.sleep(2.0)
    if p.returncode != 0:
        tail = (p.stderr.strip() or p.stdout.strip()).splitlines()[-6:]
        raise CheckError("exit %d: %s\n      %s" % (p.returncode, " ".join(cmd),
                                                  "\n      ".join(tail)))
    return p.stdout


def kumite_json(kumite, args, timeout):
    out = run([kumite] + args + ["--json"], timeout)
    try:
        return json.loads(out)
    except ValueError as e:
        raise CheckError("kumite %s: bad JSON (%s)" % (args[0], e))


def norm_name(n):
    return "_".join(str(n).split())


def compare(bvh, tmpdir, tag, opts):
    """Blender vs kumite on one BVH file. Returns a result dict."""
    info = kumite_json(opts.kumite, ["inspect", bvh], opts.timeout)
    scale = float(info["unit_scale_m"])
    height = float(info["height_m"])
    n = int(info["frames"])
    if n <= 0:
        raise CheckError("%s has no frames" % bvh)
    if opts.all:
        frames = list(range(n))
    else:
        frames = list(range(min(opts.frames, n)))
        if not opts.no_last and (n - 1) not in frames:
            frames.append(n - 1)
    flist = ",".join(str(f) for f in frames)

    out_json = os.path.join(tmpdir, "%s.blender.json" % tag)
    cmd = [opts.blender, "-b", "--factory-startup", "--python", BLENDER_SCRIPT, "--",
           bvh, out_json, "--frame-list", flist]
    t0 = time.time()
    run(cmd, opts.timeout)
    t_blender = time.time() - t0
    with open(out_json, encoding="utf-8") as fh:
        bl = json.load(fh)

    kargs = ["positions", bvh, "--all"] if opts.all else ["positions", bvh, "--frames", flist]
    km = kumite_json(opts.kumite, kargs, opts.timeout)

    kn, bn = km["joint_names"], bl["joint_names"]
    if len(kn) != len(bn):
        raise CheckError("joint count differs: kumite %d, blender %d" % (len(kn), len(bn)))
    renamed = [(a, b) for a, b in zip(kn, bn) if norm_name(a) != norm_name(b)]
    if renamed:
        raise CheckError("joint order/names differ, first: kumite %r vs blender %r" % renamed[0])
    if bl.get("frame_count") != n:
        # Not fatal (header vs actual rows), but worth knowing.
        sys.stderr.write("note: %s: kumite reports %d frames, Blender read %s motion rows\n"
                         % (bvh, n, bl.get("frame_count")))

    worst = (-1.0, None, None, None, None)  # dist, frame, joint, kumite_m, blender_m
    for f in frames:
        kf = km["frames"].get(str(f))
        bf = bl["frames"].get(str(f))
        if kf is None or bf is None:
            raise CheckError("frame %d missing (kumite %s, blender %s)"
                             % (f, kf is not None, bf is not None))
        for j, (kp, bp) in enumerate(zip(kf, bf)):
            bpm = [c * scale for c in bp]
            d = math.sqrt(sum((a - b) ** 2 for a, b in zip(kp, bpm)))
            if not (d <= worst[0]):  # also catches NaN
                worst = (d, f, kn[j], kp, bpm)
    rel = worst[0] / height if height > 0 else float("inf")
    return {"rel": rel, "dist_m": worst[0], "frame": worst[1], "joint": worst[2],
            "kumite_m": worst[3], "blender_m": worst[4], "frames": len(frames),
            "joints": len(kn), "unit": info.get("unit"), "scale": scale, "height_m": height,
            "t_blender": t_blender}


def check_file(path, opts):
    t0 = time.time()
    tmpdir = tempfile.mkdtemp(prefix="kumite_chk_")
    results = {}
    try:
        src = os.path.abspath(path)
        if not os.path.isfile(src):
            raise CheckError("no such file: %s" % path)
        conv = os.path.join(tmpdir, "converted.bvh")
        run([opts.kumite, "convert", src, conv], opts.timeout)
        results["converted"] = compare(conv, tmpdir, "converted", opts)
        if opts.original:
            results["original"] = compare(src, tmpdir, "original", opts)
        ok = all(r["rel"] <= opts.tolerance for r in results.values())
        return path, ok, results, None, time.time() - t0
    except CheckError as e:
        return path, False, results, str(e), time.time() - t0
    finally:
        if opts.keep_tmp:
            sys.stderr.write("kept %s\n" % tmpdir)
        else:
            shutil.rmtree(tmpdir, ignore_errors=True)


def fmt_vec(v):
    return "(%s)" % ", ".join("%.6f" % c for c in v)


def report(path, ok, results, err, secs, opts):
    parts = []
    for tag in ("converted", "original"):
        r = results.get(tag)
        if r is None:
            continue
        parts.append("%s max_rel=%.3e (%.3g mm, joint %s, frame %s)"
                     % (tag, r["rel"], r["dist_m"] * 1000.0, r["joint"], r["frame"]))
    line = "%s %s: %s" % ("PASS" if ok else "FAIL", path,
                          "; ".join(parts) if parts else "")
    if err:
        line += (" " if parts else "") + "error: " + err
    line += " [%d frames, %.1fs]" % (max([r["frames"] for r in results.values()] or [0]), secs)
    print(line, flush=True)
    if (not ok or opts.verbose) and results:
        for tag, r in results.items():
            if r["rel"] > opts.tolerance or opts.verbose:
                print("    %s: joint %s frame %s kumite %s m, blender %s m (unit %s, %.6g m/unit,"
                      " height %.4f m)" % (tag, r["joint"], r["frame"], fmt_vec(r["kumite_m"]),
                                           fmt_vec(r["blender_m"]), r["unit"], r["scale"],
                                           r["height_m"]), flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("files", nargs="+", metavar="FILE.bvh")
    ap.add_argument("--kumite", default=None,
                    help="kumite binary (default: build/bin/kumite of this repo, else PATH)")
    ap.add_argument("--blender", default="blender", help="Blender executable (default: blender)")
    ap.add_argument("--tolerance", type=float, default=1e-4,
                    help="max distance / skeleton height (default 1e-4)")
    ap.add_argument("--frames", type=int, default=30, help="first N frames to compare (default 30)")
    ap.add_argument("--no-last", action="store_true", help="do not add the last frame")
    ap.add_argument("--all", action="store_true", help="compare every frame")
    ap.add_argument("--original", action="store_true",
                    help="also compare Blender vs kumite on the original (unconverted) file")
    ap.add_argument("--jobs", "-j", type=int, default=1, help="files checked in parallel")
    ap.add_argument("--timeout", type=float, default=900, help="per-command timeout, seconds")
    ap.add_argument("--keep-tmp", action="store_true")
    ap.add_argument("--verbose", "-v", action="store_true")
    opts = ap.parse_args()

    blender = shutil.which(opts.blender)
    if not blender:
        print("Blender not found (%r is not on PATH): cannot cross-check, skipping." % opts.blender)
        return SKIP
    opts.blender = blender
    if opts.kumite is None:
        cand = os.path.join(REPO, "build", "bin", "kumite")
        opts.kumite = cand if os.path.isfile(cand) else (shutil.which("kumite") or cand)
    kpath = opts.kumite if os.sep in opts.kumite else shutil.which(opts.kumite)
    if not kpath or not os.path.isfile(kpath) or not os.access(kpath, os.X_OK):
        print("kumite binary not found: %s (build it first)" % opts.kumite)
        return SKIP
    opts.kumite = os.path.abspath(kpath)
    if not os.path.isfile(BLENDER_SCRIPT):
        print("missing %s" % BLENDER_SCRIPT)
        return 2

    t0 = time.time()
    passed = failed = 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, opts.jobs)) as ex:
        futs = [ex.submit(check_file, f, opts) for f in opts.files]
        for fut in futs:  # in argument order
            path, ok, results, err, secs = fut.result()
            report(path, ok, results, err, secs, opts)
            if ok:
                passed += 1
            else:
                failed += 1
    print("total %.1fs" % (time.time() - t0))
    print("%d passed, %d failed" % (passed, failed))
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
