#!/usr/bin/env python3
"""Writes docs/results.md: the figures that matter, from the benchmarks in tests/bench and the bout scripts, run now
on this machine, with the date, the machine and the build.

  python3 scripts/results.py                 # every figure (about five minutes on two cores); writes docs/results.md
  python3 scripts/results.py --short -o F.md # each step in a minimal form (under a minute): checks the script runs

  [--build DIR] (default build/)  [--kumite PATH] (default DIR/bin/kumite)  [-o PATH]

What it runs: `kumite bake` on data/annotations/reference.json (timed; the database every other step uses),
bvh_parse_bench, database_open_bench, retrieval_bench, adaptation_bench, mir_bench, player_bench,
python_step_bench.py, xr_frame_bench under scripts/with_monado.sh (left out, and said so, when no OpenXR runtime can
be had), `kumite adapt` on a punch and a kick, a headless `kumite play` bout, scripts/hit_rates.py and
scripts/real_opponents.py, every one with its default settings. Progress lines go to stderr. A step that fails or
prints what is not one JSON document stops the run with exit status 1 and a message naming it; the page is written
to a temporary beside the output and renamed only when every step succeeded.
"""
import argparse
import datetime
import glob
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

import bout_inputs

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


class Failure(Exception):
    """A step that failed: the message says which and why."""


def progress(text):
    print(f"results: {text}", file=sys.stderr, flush=True)


def tail(text, lines=15):
    return "\n".join(text.strip().splitlines()[-lines:])


def run(name, command, env=None, want_json=True, timeout=None):
    """Runs a step from the repository's root; its stdout as JSON (or text), and the seconds it took."""
    progress(f"{name}: {' '.join(command)}")
    started = time.monotonic()
    try:
        done = subprocess.run(command, cwd=ROOT, env=env, capture_output=True, text=True, timeout=timeout)
    except (OSError, subprocess.TimeoutExpired) as error:
        raise Failure(f"{name} could not run: {error}")
    seconds = time.monotonic() - started
    if done.returncode != 0:
        raise Failure(f"{name} failed (exit status {done.returncode}): {' '.join(command)}\n{tail(done.stderr or done.stdout)}")
    if not want_json:
        return done.stdout, seconds
    try:
        document = json.loads(done.stdout)
    except ValueError as error:
        raise Failure(f"{name} printed something that is not one JSON document ({error}); it began: {done.stdout[:300]!r}")
    if not isinstance(document, dict):
        raise Failure(f"{name} printed JSON that is not an object: {done.stdout[:300]!r}")
    return document, seconds


def get(name, document, *path):
    """document[path[0]][path[1]]...; a missing key is the step's failure, not a KeyError."""
    value = document
    for key in path:
        try:
            value = value[key]
        except (KeyError, IndexError, TypeError):
            raise Failure(f"{name}: its output has no {'.'.join(str(k) for k in path)}")
    return value


def number(name, document, *path):
    value = get(name, document, *path)
    if not isinstance(value, (int, float)) or isinstance(value, bool):
        raise Failure(f"{name}: {'.'.join(str(k) for k in path)} is not a number ({value!r})")
    return value


# ---- formatting -----------------------------------------------------------------------------------------------------

def f(value, digits=1):
    if value is None:
        return "-"
    return f"{value:,.{digits}f}"


def pct(value, digits=1):
    return "-" if value is None else f"{100.0 * value:.{digits}f}%"


def ci(interval):
    return "-" if not interval else f"{100.0 * interval[0]:.1f}-{100.0 * interval[1]:.1f}%"


def count_rate(part, whole):
    return f"{part}/{whole} ({pct(part / whole)})" if whole else f"{part}/0"


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    lines += ["| " + " | ".join(str(cell) for cell in row) + " |" for row in rows]
    return "\n".join(lines)


def quantile(values, q):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(q * len(ordered)))] if ordered else None


# ---- the machine and the build --------------------------------------------------------------------------------------

def cmake_cache(build):
    values = {}
    try:
        with open(os.path.join(build, "CMakeCache.txt")) as lines:
            for line in lines:
                if ":" in line and "=" in line and not line.startswith(("//", "#")):
                    key, _, value = line.rstrip("\n").partition("=")
                    values[key.split(":")[0]] = value
    except OSError:
        raise Failure(f"{build}/CMakeCache.txt: cannot read it (build with scripts/build.sh first, or give --build DIR)")
    return values


def cpu_model():
    try:
        with open("/proc/cpuinfo") as lines:
            for line in lines:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def command_line_of(command):
    try:
        return subprocess.run(command, capture_output=True, text=True).stdout.strip().splitlines()[0]
    except (OSError, IndexError):
        return "?"


def machine_section(cache, mode_text):
    compiler = cache.get("CMAKE_CXX_COMPILER", "c++")
    build_type = cache.get("CMAKE_BUILD_TYPE", "?")
    flags = cache.get(f"CMAKE_CXX_FLAGS_{build_type.upper()}", "")
    commit = command_line_of(["git", "-C", ROOT, "rev-parse", "--short=12", "HEAD"])
    changed = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--untracked-files=no"], capture_output=True, text=True).stdout.strip()
    memory = None
    try:
        memory = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") / 2**30
    except (ValueError, OSError):
        pass
    rows = [("generated", datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC") + f" ({mode_text})"),
            ("CPU", cpu_model()),
            ("cores", str(os.cpu_count())),
            ("load at the start (1-minute average)", f"{os.getloadavg()[0]:.2f}"),
            ("memory", f"{memory:.1f} GiB" if memory else "?"),
            ("system", f"{platform.system()} {platform.release()}"),
            ("compiler", command_line_of([compiler, "--version"])),
            ("build type", f"{build_type} ({flags.strip()})" if flags.strip() else build_type),
            ("commit", commit + (" with uncommitted changes in the working tree" if changed else ""))]
    return table(["", ""], rows)


# ---- the steps ------------------------------------------------------------------------------------------------------

class Context:
    def __init__(self, args):
        self.args = args
        self.short = args.short
        self.build = os.path.abspath(args.build)
        self.bin = os.path.join(self.build, "bin")
        self.kumite = os.path.abspath(args.kumite or os.path.join(self.bin, "kumite"))
        self.cache = cmake_cache(self.build)
        self.mocap = self.find_mocap()
        self.env = dict(os.environ, KUMITE_MOCAP_ROOT=self.mocap)
        self.work = None
        self.db = None
        self.notes = []  # what could not be measured, and why

    def find_mocap(self):
        candidates = [os.environ.get("KUMITE_MOCAP_ROOT"), self.cache.get("KUMITE_MOCAP_ROOT"), os.path.join(ROOT, "data", "mocap"),
                      os.path.join(os.path.dirname(ROOT), "shared", "mocap")]
        for folder in candidates:
            if folder and os.path.isdir(os.path.join(folder, "cmu14-boxing")):
                return os.path.abspath(folder)
        raise Failure("no captures found (KUMITE_MOCAP_ROOT, data/mocap, ../shared/mocap): run scripts/fetch_mocap.sh")

    def binary(self, name):
        path = os.path.join(self.bin, name)
        if not os.access(path, os.X_OK):
            raise Failure(f"{path}: not built (build with scripts/build.sh, or give --build DIR)")
        return path


def bake(ctx):
    annotations = os.path.join(ROOT, "data", "annotations", "reference.json")
    ctx.db = os.path.join(ctx.work, "reference.kdb")
    _, seconds = run("kumite bake", [ctx.kumite, "bake", annotations, "-o", ctx.db, "--mocap-root", ctx.mocap], env=ctx.env, want_json=False)
    info, _ = run("kumite db-info", [ctx.kumite, "db-info", ctx.db, "--json"], env=ctx.env)
    jobs = os.cpu_count() or 1
    return {"seconds": seconds, "jobs": jobs, "clips": number("db-info", info, "clips"), "poses": number("db-info", info, "poses"),
            "clusters": number("db-info", info, "clusters"), "bytes": number("db-info", info, "bytes"),
            "open_us": number("db-info", info, "open_us")}


# What the page reads of each benchmark's JSON (the first entry of each list): checked as soon as it has run, so that a
# benchmark whose output changed fails the run naming it.
NEEDS = {
    "bvh_parse_bench": [("repeats",), ("files", 0, "file"), ("files", 0, "bytes"), ("files", 0, "frames"), ("files", 0, "throughput_mb_s", "median"),
                        ("files", 0, "serial", "throughput_mb_s", "median"), ("files", 0, "baseline", "throughput_mb_s"),
                        ("files", 0, "speedup_vs_baseline")],
    "database_open_bench": [("databases", 1, "database"), ("databases", 0, "bytes"), ("databases", 0, "poses"), ("databases", 0, "open_us", "median"),
                            ("databases", 0, "open_us", "p99"), ("databases", 0, "baseline", "name"), ("databases", 0, "baseline", "us", "median"),
                            ("databases", 0, "speedup_vs_baseline"), ("databases", 0, "verify_us", "median")],
    "retrieval_bench": [("characters",), ("databases", 0, "clips"), ("databases", 0, "poses"), ("databases", 0, "queries"),
                        ("databases", 0, "fast_us", "p99"), ("databases", 0, "exhaustive_us", "p99"), ("databases", 0, "speedup_median"),
                        ("databases", 0, "agreement"), ("databases", 0, "fast_path_allocations")],
    "adaptation_bench": [("frame_cost_us", "baseline_plain_decode", "p99"), ("frame_cost_us_least_of_3", "baseline_plain_decode", "p99"),
                         ("overall", "strikes"), ("overall", "contact_within_1cm_rate"), ("overall", "contact_error_m", "p99"),
                         ("overall", "joint_limit_violations"), ("overall", "bone_length_error_m_max"), ("allocations_per_frame",)],
    "mir_bench": [("sources", 0, "source"), ("sources", 0, "characters", 0, "name"), ("sources", 0, "characters", 0, "encode_decode_us", "p99"),
                  ("sources", 0, "characters", 0, "baseline_us", "median"), ("sources", 0, "characters", 0, "ratio_to_baseline"),
                  ("sources", 0, "characters", 0, "allocations_per_frame")],
    "player_bench": [("seconds",), ("fighters", "1", "frame_time_us", "max"), ("fighters", "1", "frames_over_16_7_ms"),
                     ("fighters", "1", "baseline_guard_only_frame_time_us", "p99"), ("fighters", "1", "baseline_planning_in_frame", "slowest_frame_us"),
                     ("fighters", "1", "baseline_planning_in_frame", "frames_over_16_7_ms"), ("fighters", "1", "allocations")],
    "python_step_bench": [("frames",), ("python_step_us", "p99"), ("python_step_us", "mean"), ("baseline_cpp_step_us", "mean"), ("python_over_cpp",)],
    "store_bench": [("store", "sessions"), ("store", "attacks_per_session"), ("store", "trainees"), ("store", "bytes"), ("store", "generation_s"),
                    ("list", "time", "median_s"), ("list", "time", "p99_s"), ("trainee", "sessions"), ("trainee", "attacks"),
                    ("trainee", "time", "median_s"), ("trainee", "time", "p99_s"), ("baseline", "name"), ("baseline", "time", "median_s"),
                    ("session_writer_add", "median_us"), ("session_writer_add", "p99_us")],
    "store_commands_bench": [("sessions", "median_s"), ("sessions", "p99_s"), ("progress", "median_s"), ("progress", "p99_s"),
                             ("baseline_start", "median_s")],
    "train_store_bench": [("runs",), ("with_store", "median_of_p99_us"), ("no_store_baseline", "median_of_p99_us"), ("p99_ratio",)],
    "xr_frame_bench": [("seconds",), ("runtime",), ("results", 0, "fighters"), ("results", 0, "frame_work_us", "p99"), ("results", 0, "render_us", "median"),
                       ("results", 0, "frames_submitted"), ("results", 0, "frames_waited"), ("results", 0, "baseline", "p99")],
}


def bench_run(name, command, env):
    document, _ = run(name, command, env=env)
    for path in NEEDS[name]:
        get(name, document, *path)
    return document


def benchmarks(ctx):
    s, env = ctx.short, ctx.env
    out = {"bvh_parse": bench_run("bvh_parse_bench", [ctx.binary("bvh_parse_bench"), "--repeats", "3" if s else "30"], env),
           "database_open": bench_run("database_open_bench", [ctx.binary("database_open_bench"), ctx.db, "--repeats", "10" if s else "200",
                                                              "--scale", "2" if s else "10"], env),
           "retrieval": bench_run("retrieval_bench", [ctx.binary("retrieval_bench"), ctx.db, "--targets", "10" if s else "1000"], env),
           "adaptation": bench_run("adaptation_bench", [ctx.binary("adaptation_bench"), ctx.db, "--targets", "4" if s else "200"], env),
           "mir": bench_run("mir_bench", [ctx.binary("mir_bench"), "--repeats", "2" if s else "200"] + (["--character", "brawler"] if s else []), env),
           "player": bench_run("player_bench", [ctx.binary("player_bench"), ctx.db, "--fighters", "1,10" if s else "1,10,100,200",
                                                "--seconds", "2" if s else "20"], env)}
    # The module is built for one interpreter (Debian's python3): the build records which.
    python = ctx.cache.get("KUMITE_PYTHON") or sys.executable
    python_env = dict(env, PYTHONPATH=os.path.join(ctx.build, "python"), PYTHONDONTWRITEBYTECODE="1")
    out["python_step"] = bench_run("python_step_bench", [python, os.path.join(ROOT, "tests", "bench", "python_step_bench.py"), ctx.db,
                                                         "2" if s else "60"], python_env)
    out["xr"] = xr_frames(ctx)
    # The training store: at scale, its commands as whole processes, and a drill's frames with and without it.
    out["store"] = bench_run("store_bench", [ctx.binary("store_bench")] + (["--sessions", "500", "--repeats", "2"] if s else ["--repeats", "20"]), env)
    out["store_commands"] = bench_run("store_commands_bench", [python, os.path.join(ROOT, "tests", "bench", "store_commands_bench.py"), ctx.kumite,
                                                               ctx.binary("store_bench"), "--runs", "2" if s else "20"], env)
    out["train_store"] = bench_run("train_store_bench", [python, os.path.join(ROOT, "tests", "bench", "train_store_bench.py"), ctx.kumite, ctx.db,
                                                         "--runs", "1" if s else "9"], env)
    return out


def xr_frames(ctx):
    bench = os.path.join(ctx.bin, "xr_frame_bench")
    if not os.access(bench, os.X_OK):
        ctx.notes.append("The headset's frame cost is not measured: xr_frame_bench was not built (no OpenXR loader when the build "
                         "was configured).")
        return None
    progress("scripts/build_monado.sh (Monado, the OpenXR runtime: built once, then cached)")
    monado = subprocess.run([os.path.join(ROOT, "scripts", "build_monado.sh")], cwd=ROOT, capture_output=True, text=True)
    if monado.returncode != 0:
        reason = tail(monado.stderr, 1) or f"exit status {monado.returncode}"
        ctx.notes.append(f"The headset's frame cost is not measured: no OpenXR runtime could be had ({reason}).")
        progress(f"no OpenXR runtime, the headset's frame cost left out: {reason}")
        return None
    command = [os.path.join(ROOT, "scripts", "with_monado.sh"), "--monado", monado.stdout.strip(), bench, ctx.kumite,
               "--seconds", "2" if ctx.short else "20", "--fighters", "1" if ctx.short else "1,4"]
    document = bench_run("xr_frame_bench", command, ctx.env)
    for entry in get("xr_frame_bench", document, "results"):
        if entry.get("error") or entry.get("exit_status", 0) != 0 or "frame_work_us" not in entry:
            raise Failure(f"xr_frame_bench: a run failed: {json.dumps(entry)[:400]}")
    return document


def adapt_strikes(ctx):
    rows = []
    for command, target in (("punch", "0,1.45,0.75"), ("kick", "0,1.0,0.9")):
        report = os.path.join(ctx.work, f"adapt_{command}.json")
        run(f"kumite adapt {command}", [ctx.kumite, "adapt", ctx.db, "--character", "brawler", "--target", target, "--command", command,
                                        "--record", os.path.join(ctx.work, f"adapt_{command}.bvh"), "--report", report],
            env=ctx.env, want_json=False)
        document = load_json(f"kumite adapt {command}", report)
        rows.append({"command": command, "target": target, "contact_error_m": number("kumite adapt", document, "contact_error_m"),
                     "reachable": get("kumite adapt", document, "reachable"),
                     "frame_cost_us": get("kumite adapt", document, "frame_cost_us")})
    return rows


def load_json(name, path):
    try:
        with open(path) as stream:
            return json.load(stream)
    except (OSError, ValueError) as error:
        raise Failure(f"{name}: cannot read its report {path}: {error}")



def play_bout(ctx):
    """One fighter against the wandering simulated user, an order every 2 s: the frame time kumite play reports."""
    seconds = 10 if ctx.short else 60
    orders, report = os.path.join(ctx.work, "bout.orders"), os.path.join(ctx.work, "bout.json")
    bout_inputs.orders_every_2s(orders, seconds)
    run("kumite play", [ctx.kumite, "play", ctx.db, "--headless", "--duration", str(seconds), "--tracker", "simulate:wander",
                        "--character", "brawler", "--commands", f"script:{orders}", "--seed", "1", "--report", report],
        env=ctx.env, want_json=False)
    document = load_json("kumite play", report)
    get("kumite play", document, "frame_time_us", "p99")
    document["seconds"] = seconds
    return document


def hit_rates(ctx):
    command = [sys.executable, os.path.join(ROOT, "scripts", "hit_rates.py"), "--db", ctx.db, "--kumite", ctx.kumite]
    if ctx.short:
        command += ["--seconds", "10", "--users", "still", "--aims", "predicted", "--characters", "brawler"]
    document, _ = run("hit_rates.py", command, env=ctx.env)
    get("hit_rates.py", document, "hit_rates")
    return document


def real_opponents(ctx):
    events = os.path.join(ctx.work, "opponents")
    if ctx.short:
        opponents = os.path.join(ctx.mocap, "cmu14-boxing", "box-1.bvh")
        extra = ["--characters", "brawler", "--max-seconds", "10", "--jobs", "1"]
    else:
        opponents = ",".join([os.path.join(ctx.mocap, "cmu14-boxing", "box-*.bvh"), os.path.join(ctx.mocap, "hachaj-kata", "*.bvh")])
        extra = ["--jobs", str(os.cpu_count() or 1)]
    command = [sys.executable, os.path.join(ROOT, "scripts", "real_opponents.py"), "--db", ctx.db, "--kumite", ctx.kumite,
               "--opponents", opponents, "--events", events] + extra
    document, _ = run("real_opponents.py", command, env=ctx.env)
    document["max_seconds"] = 10 if ctx.short else 60  # real_opponents.py's --max-seconds (its default in the full run)
    for key in ("hits", "strikes", "defended", "would_land", "on_course", "on_course_blocks_too", "speed_at_contact_mps", "fastest_by_move"):
        get("real_opponents.py", document, "overall", key)
    # From the bouts' events: each strike's speed at contact by what was ordered, each of the people's blows' peak speed.
    contact, blows = {}, []
    for path in sorted(glob.glob(os.path.join(events, "*.jsonl"))):
        with open(path) as lines:
            for line in lines:
                event = json.loads(line)
                if event.get("type") == "strike" and "effector_speed_at_contact_mps" in event:
                    contact.setdefault(event.get("command", "?"), []).append(event["effector_speed_at_contact_mps"])
                elif event.get("type") == "user_strike_end" and "peak_speed_mps" in event:
                    blows.append(event["peak_speed_mps"])
    if not blows or not contact:
        raise Failure(f"real_opponents.py: its bouts' events ({events}) hold no strikes or no blows of the people")
    document["contact_speeds"], document["blow_speeds"] = contact, blows
    return document


# ---- the page -------------------------------------------------------------------------------------------------------

def strikes_section(rates, opponents, bout):
    lines = ["## The fighter's strikes", ""]
    overall = opponents["overall"]
    characters = list(dict.fromkeys(row["character"] for row in opponents["bouts"]))
    rows = [(f"recorded people ({opponents['aim']} aim)", count_rate(overall["hits"], overall["strikes"]), ci(overall.get("hit_rate_ci95")), "-")]
    for user, by_aim in rates["hit_rates"].items():
        for aim, row in by_aim.items():
            to_contact = row.get("order_to_contact_s", {})
            rows.append((f"simulated `{user}` ({aim} aim)", count_rate(row["hits"], row["strikes"]), "-",
                         f"{f(to_contact.get('median'), 2)} / {f(to_contact.get('p90'), 2)}"))
    lines += [f"Strikes that hit the user's head, an order every 2 s (punch and kick, sides alternating): {rates['seconds']:g} s "
              "bouts against simulated users (`scripts/hit_rates.py`; `walk:V` walks at V m/s, `dodge` moves 0.25 s after each "
              "order, `dodge-seen` 0.25 s after the strike begins), and the recorded people's captures, each bout as long as "
              f"its capture up to {opponents['max_seconds']:g} s (`scripts/real_opponents.py`). Characters: "
              f"{', '.join(characters)}. The recorded people's gloves and forearms block the strikes whose path meets them "
              "first (the user's guard; the simulated users have no hands in the way).", "",
              table(["against", "hits / strikes", "95% interval", "order to contact, median / p90 (s)"], rows), ""]
    blows = opponents["blow_speeds"]
    rows = []
    for kind, speeds in sorted(opponents["contact_speeds"].items()):
        rows.append((kind, len(speeds), f(statistics.median(speeds), 2), f(quantile(speeds, 0.1), 2), f(quantile(speeds, 0.9), 2),
                     f(max(speeds), 2)))
    rows.append(("the recorded people's blows (peak hand speed)", len(blows), f(statistics.median(blows), 2), f(quantile(blows, 0.1), 2),
                 f(quantile(blows, 0.9), 2), f(max(blows), 2)))
    lines += ["Speed of the striking hand or foot at contact (m/s), by what was ordered, in the bouts against the recorded "
              "people, beside the speed of the real strikes in those bouts: the people's own blows at the fighter (their "
              "hand's peak speed).", "",
              table(["strikes", "count", "median", "p10", "p90", "max"], rows), ""]
    by_kind = bout.get("effector_speed_at_contact_by_kind_mps", {})
    if by_kind:
        lines += [f"Against the wandering simulated user ({bout['seconds']} s, brawler): "
                  + ", ".join(f"{kind} median {f(v['median'], 2)} m/s ({v['count']})" for kind, v in sorted(by_kind.items())) + ".", ""]
    return lines


def blows_section(opponents, mocap):
    overall = opponents["overall"]
    bouts = opponents["bouts"]
    seen = sum(row["user_seen"] for row in bouts)
    landed = sum(row["landed"] for row in bouts)
    on_course, strict = overall["on_course"], overall["on_course_blocks_too"]
    lines = ["## The person's blows", "",
             f"Recorded people replayed as the user ({len(opponents['per_opponent'])} captures, {len(bouts)} bouts, "
             f"{opponents['distance_m']} m from the fighter, their head and hands tracked): their blows at the fighter. "
             "A blow *would land* when it met the head or chest or was blocked or slipped; *defended* is blocked or slipped, "
             "of those; *slips on course* counts a slip only where the hand would have hit without it; *on course* counts a "
             "block too only where the hand's path went on to the head or chest.", "",
             table(["blows", "count", "rate", "95% interval"],
                   [("seen", seen, "-", "-"),
                    ("would land", overall["would_land"], "-", "-"),
                    ("landed", landed, pct(landed / overall["would_land"]) if overall["would_land"] else "-", "-"),
                    ("defended", overall["defended"], pct(overall["defended_rate"]), ci(overall.get("defended_rate_ci95"))),
                    ("defended, slips on course", f"{on_course['defended']}/{on_course['would_land']}", pct(on_course["defended_rate"]),
                     ci(on_course.get("defended_rate_ci95"))),
                    ("defended, on course", f"{strict['defended']}/{strict['would_land']}", pct(strict["defended_rate"]),
                     ci(strict.get("defended_rate_ci95")))]), ""]
    rows = [(os.path.relpath(opponent, mocap) if os.path.isabs(opponent) else opponent, count_rate(t["hits"], t["strikes"]),
             count_rate(t["defended"], t["would_land"])) for opponent, t in sorted(opponents["per_opponent"].items())]
    lines += ["By person (all characters):", "", table(["capture", "fighter's hits", "blows defended"], rows), ""]
    warning = overall.get("warning_of_blows_that_would_land")
    if warning and warning.get("count"):
        approach = warning["approach_s"]
        lines += [f"Warning the {warning['count']} blows that would land gave: the hand closed on what it met for "
                  f"{f(approach['p10'], 2)} / {f(approach['p50'], 2)} / {f(approach['p90'], 2)} s (p10 / p50 / p90); "
                  f"{pct(warning['share_approach_at_least_0_2_s'])} gave at least 0.2 s.", ""]
    return lines


def speed_section(opponents):
    fastest = opponents["overall"]["fastest_by_move"]
    bars, character = {}, None
    for row in opponents["bouts"]:
        if character is None or row["character"] == "brawler":
            by_move = row.get("motion", {}).get("by_move", {})
            if by_move:
                character = row["character"]
                bars = {move: entry.get("library", {}) for move, entry in by_move.items()}
            if character == "brawler":
                break
    rows = []
    for move, best in sorted(fastest.items()):
        bar = bars.get(move, {})
        rows.append((move, f"{f(best['wrist_mps'], 2)} ({f(bar.get('wrist_mps'), 1)})", f"{f(best['ankle_mps'], 2)} ({f(bar.get('ankle_mps'), 1)})",
                     f"{f(best['elbow_radps'], 1)} ({f(bar.get('elbow_radps'), 1)})", f"{f(best.get('elbow_mps'), 2)} ({f(bar.get('elbow_mps'), 1)})",
                     f"{f(best['knee_radps'], 1)} ({f(bar.get('knee_radps'), 1)})",
                     f(best["max_over_library"], 3), best["over_library"]))
    return ["## Human speed", "",
            "The fighter's fastest joints in each kind of move over every bout against the recorded people, and in brackets "
            f"the library's fastest for that kind (the bar the speed limit holds it to, on the {character}): wrists and ankles "
            "in m/s, elbow and knee bend rates in rad/s, the elbow's own travel (its swing about the shoulder) in m/s, measured "
            "and not held yet (docs/design.md); the largest ratio of any joint to its bar, and the bouts where one "
            "went over it by more than 0.1%.", "",
            table(["move", "wrist", "ankle", "elbow bend", "elbow travel", "knee", "most over the library's", "bouts over"], rows), ""]


def distance_section(opponents):
    by_character = {}
    for row in opponents["bouts"]:
        distance = row.get("motion", {}).get("distance_between_strikes", {})
        if distance.get("frames"):
            by_character.setdefault(row["character"], []).append(distance)
    rows = []
    for character, values in by_character.items():
        med = lambda key: statistics.median(v[key] for v in values)
        rows.append((character, len(values), f(med("median_m"), 2), f(med("p5_m"), 2), f(med("p95_m"), 2), f(med("median_legs"), 2),
                     f(med("p5_legs"), 2), f(med("p95_legs"), 2)))
    return ["## Distance kept", "",
            "The distance from the fighter to the user's head between strikes, in the bouts against the recorded people: "
            "each bout's median, 5th and 95th percentile, the median of those over the bouts (metres, and leg lengths of "
            "the character).", "",
            table(["character", "bouts", "median (m)", "p5 (m)", "p95 (m)", "median (legs)", "p5 (legs)", "p95 (legs)"], rows), ""]


def frame_section(bench, bout):
    player = bench["player"]
    rows = []
    for count, entry in sorted(player["fighters"].items(), key=lambda item: int(item[0])):
        t, base = entry["frame_time_us"], entry["baseline_guard_only_frame_time_us"]
        planning = entry["baseline_planning_in_frame"]
        rows.append((count, f(t["mean"]), f(t["p99"]), f(t["max"]), entry["frames_over_16_7_ms"], f(base["mean"]), f(base["p99"]),
                     f"{f(planning['slowest_frame_us'])} ({planning['frames_over_16_7_ms']})", entry["allocations"]))
    lines = ["## Frame cost", "",
             f"`player_bench`: fighters stepped at 60 Hz on one thread for {player['seconds']:g} s against a wandering user, every "
             "fighter ordered to strike every second (all at once), microseconds per frame. Baselines from the same run: the "
             "same fighters never ordered (guard and steps only), and every fighter planning its strike in its order's frame "
             "(the slowest frame, and the frames over 16.7 ms).", "",
             table(["fighters", "mean", "p99", "max", "frames over 16.7 ms", "baseline guard only: mean", "p99",
                    "baseline planning in frame: max (over 16.7 ms)", "allocations"], rows), ""]
    t = bout["frame_time_us"]
    lines += [f"`kumite play --headless` ({bout['seconds']} s, one brawler against the wandering user, an order every 2 s): "
              f"frame time mean {f(t['mean'])} µs, p99 {f(t['p99'])} µs, max {f(t['max'])} µs, {bout.get('missed_frames', 0)} missed frames.", ""]
    xr = bench["xr"]
    if xr:
        rows = []
        for entry in xr["results"]:
            size = "x".join(str(v) for v in entry.get("view_size_px", [])) or "?"
            threads = str(entry.get("software_raster_threads"))
            raster = "kumite's own thread" if threads == "0" else f"{threads} threads" + (" (Mesa's default)" if entry.get("before") else "")
            work, render = entry["frame_work_us"], entry["render_us"]
            base = entry.get("baseline", {})
            rows.append((entry["fighters"], size, raster, f(work["median"]), f(work["p99"]), f(render["median"]),
                         f"{entry['frames_submitted']}/{entry['frames_waited']}", f(base.get("median_or_mean")), f(base.get("p99"))))
        lines += [f"The headset (`xr_frame_bench`, {xr['seconds']:g} s a run, {xr['runtime']}, on one core): microseconds from "
                  "xrWaitFrame's return to xrEndFrame's (the bout stepped, the scene built, both eyes drawn); baseline: the same "
                  "bout headless, per 60 Hz step.", "",
                  table(["fighters", "view (px per eye)", "software rasteriser", "frame work median", "p99", "drawing median",
                         "frames submitted / waited", "baseline median", "baseline p99"], rows), ""]
    else:
        lines += ["The headset's frame cost: not measured in this run (below, \"Not measured\").", ""]
    py = bench["python_step"]
    lines += [f"Stepping a bout from Python (`python_step_bench`, {py['frames']} frames, one fighter, an order every second): "
              f"mean {f(py['python_step_us']['mean'])} µs, median {f(py['python_step_us']['median'])} µs, p99 "
              f"{f(py['python_step_us']['p99'])} µs a frame; baseline, the same bout stepped in C++: mean "
              f"{f(py['baseline_cpp_step_us']['mean'])} µs (Python's mean {f(py['python_over_cpp'], 2)} times it).", ""]
    return lines


def retrieval_section(bench, adapted):
    lines = ["## Retrieval and adaptation", ""]
    retrieval = bench["retrieval"]
    rows = []
    for db in retrieval["databases"]:
        fast, full = db["fast_us"], db["exhaustive_us"]
        rows.append((f"{db['clips']} clips, {db['poses']:,} poses", db["queries"], f(fast["median"]), f(fast["p99"]), f(full["median"]),
                     f(full["p99"]), f(db["speedup_median"]), pct(db["agreement"]), db["fast_path_allocations"]))
    lines += [f"`retrieval_bench`: one query per random target around each of the {retrieval['characters']} characters, a "
              "random order (semantics, side, kind, height), one thread, microseconds; baseline: the exhaustive search "
              "(every start of every clip of the order) in the same run. Agreement: the same clip and start, or a score "
              "within 1%.", "",
              table(["database", "queries", "median", "p99", "baseline median", "baseline p99", "speed-up", "agreement",
                     "allocations"], rows), ""]
    adaptation = bench["adaptation"]
    costs, least = adaptation["frame_cost_us"], adaptation["frame_cost_us_least_of_3"]
    rows = []
    for regime in sorted(costs):
        rows.append((regime.replace("_", " "), f(costs[regime]["median"]), f(costs[regime]["p99"]), f(least[regime]["median"]),
                     f(least[regime]["p99"])))
    overall = adaptation["overall"]
    lines += [f"`adaptation_bench`: {overall['strikes']} strikes at random reachable targets (punches and kicks, the five "
              f"characters), every frame from the start to the recovery, microseconds a frame by how the target was reached; "
              "baseline: the same clip frame decoded plainly (no blend, no pins, no IK). The least of three runs of each "
              "frame leaves out the machine's interruptions.", "",
              table(["frame", "median", "p99", "least of 3: median", "p99"], rows), "",
              f"Contact within 1 cm of the target: {pct(overall['contact_within_1cm_rate'])} (contact error median "
              f"{f(1000 * overall['contact_error_m']['median'], 2)} mm, p99 {f(1000 * overall['contact_error_m']['p99'], 2)} mm), "
              f"{overall['joint_limit_violations']} joint-limit violations, largest bone-length error "
              f"{overall['bone_length_error_m_max']:.2g} m, {adaptation['allocations_per_frame']:g} allocations a frame.", ""]
    rows = [(a["command"], a["target"], f(1000 * a["contact_error_m"], 2), "yes" if a["reachable"] else "no",
             f(a["frame_cost_us"].get("median")), f(a["frame_cost_us"].get("p99"))) for a in adapted]
    lines += ["`kumite adapt` on the brawler (target in metres, world):", "",
              table(["order", "target", "contact error (mm)", "reachable", "frame median (µs)", "p99 (µs)"], rows), ""]
    mir = bench["mir"]
    rows = []
    for source in mir["sources"]:
        for character in source["characters"]:
            rows.append((os.path.basename(source["source"]), character["name"], f(character["encode_decode_us"]["median"], 2),
                         f(character["encode_decode_us"]["p99"], 2), f(character["baseline_us"]["median"], 2),
                         f(character["ratio_to_baseline"], 2), f"{character['allocations_per_frame']:g}"))
    lines += ["The morphology-independent representation (`mir_bench`): encode and decode, microseconds a frame; baseline: "
              "rotations copied by joint name and forward kinematics on the target, same run.", "",
              table(["capture", "character", "median", "p99", "baseline median", "ratio", "allocations a frame"], rows), ""]
    return lines


def parse_section(bench, baked):
    lines = ["## Parse, open and bake", ""]
    rows = []
    for entry in bench["bvh_parse"]["files"]:
        rows.append((os.path.basename(entry["file"]), f(entry["bytes"] / 1e6, 1), entry["frames"], f(entry["throughput_mb_s"]["median"]),
                     f(entry["serial"]["throughput_mb_s"]["median"]), f(entry["baseline"]["throughput_mb_s"]),
                     f(entry["speedup_vs_baseline"])))
    lines += [f"BVH parse (`bvh_parse_bench`, the largest capture, in memory, {bench['bvh_parse']['repeats']} runs): MB/s; "
              "baseline: every whitespace token through `std::istringstream >> double`, same run.", "",
              table(["capture", "MB", "frames", "median (default threads)", "one thread", "baseline", "speed-up"], rows), ""]
    rows = []
    for db in bench["database_open"]["databases"]:
        rows.append((db["database"], f(db["bytes"] / 1e6, 1), f"{db['poses']:,}", f(db["open_us"]["median"]), f(db["open_us"]["p99"]),
                     f(db["baseline"]["us"]["median"]), f(db["speedup_vs_baseline"]), f(db["verify_us"]["median"])))
    lines += ["Opening a database (`database_open_bench`: map and structure), microseconds; baseline: "
              f"{bench['database_open']['databases'][0]['baseline']['name']}, same run; verify: every value and the content "
              "hash (`db-info --verify`).", "",
              table(["database", "MB", "poses", "open median", "open p99", "baseline median", "speed-up", "verify median"], rows), ""]
    lines += [f"Bake (`kumite bake data/annotations/reference.json`, {baked['jobs']} threads): {baked['clips']} clips, "
              f"{baked['poses']:,} poses, {baked['clusters']} clusters, {f(baked['bytes'] / 1e6, 1)} MB in {f(baked['seconds'], 1)} s "
              f"({f(baked['clips'] / baked['seconds'], 1)} clips/s, {f(baked['poses'] / baked['seconds'], 0)} poses/s).", ""]
    return lines


def training_section(bench):
    store, commands, frames = bench["store"], bench["store_commands"], bench["train_store"]
    lines = ["## The training store", ""]
    lines += [f"A generated store (`store_bench`) of {store['store']['sessions']:,} sessions of {store['store']['attacks_per_session']} attacks "
              f"over {store['store']['trainees']} trainees, {f(store['store']['bytes'] / 1e6, 1)} MB, written in "
              f"{f(store['store']['generation_s'], 1)} s; seconds, on a warm page cache.", ""]
    rows = [("every session listed (`StoreReader::sessions`)", f(store["list"]["time"]["median_s"], 3), f(store["list"]["time"]["p99_s"], 3)),
            (f"one trainee's {store['trainee']['sessions']} sessions and {store['trainee']['attacks']:,} attacks", f(store["trainee"]["time"]["median_s"], 3),
             f(store["trainee"]["time"]["p99_s"], 3)),
            (f"baseline: {store['baseline']['name']}", f(store["baseline"]["time"]["median_s"], 3), "")]
    lines += [table(["read", "median", "p99"], rows), ""]
    rows = [("`kumite sessions`", f(commands["sessions"]["median_s"], 3), f(commands["sessions"]["p99_s"], 3), "0.2"),
            ("`kumite progress NAME` (page written)", f(commands["progress"]["median_s"], 3), f(commands["progress"]["p99_s"], 3), "1"),
            ("baseline: `kumite --version`", f(commands["baseline_start"]["median_s"], 3), "", "")]
    lines += ["The commands as whole processes on a store of 10,000 sessions (`store_commands_bench.py`), seconds:", "",
              table(["command", "median", "p99", "bar"], rows), ""]
    lines += [f"A session's rows are queued from the frame loop ({f(store['session_writer_add']['median_us'], 2)} µs median, "
              f"{f(store['session_writer_add']['p99_us'], 1)} µs p99 a row) and committed by a thread. A drill's frame time p99 with the store: "
              f"{f(frames['with_store']['median_of_p99_us'])} µs, against {f(frames['no_store_baseline']['median_of_p99_us'])} µs with `--no-store` "
              f"(ratio {f(frames['p99_ratio'], 2)}, the bar 1.10; `train_store_bench.py`, 600 of the reaction test's attacks headless, median of {frames['runs']} "
              "runs each).", ""]
    return lines


def page(ctx, sections, seconds):
    mode = "short mode: few iterations, one opponent, short bouts; a check that the script runs, not figures to quote" \
        if ctx.short else "full run"
    lines = ["# kumite: results", "",
             "Figures measured by one script on the machine below. Regenerate them with", "",
             "```", "python3 scripts/results.py", "```", "",
             f"(after `scripts/build.sh`; the run that wrote this page took {seconds / 60.0:.1f} minutes; `--short -o FILE` runs "
             "every step in a minimal form and writes FILE). Every benchmark's baseline is measured in the same run.", "",
             machine_section(ctx.cache, mode), ""]
    for section in sections:
        lines += section
    lines += ["## Not measured", ""]
    lines += [f"- {note}" for note in ctx.notes] or ["Everything above was measured in this run."]
    lines += [""]
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--short", action="store_true", help="every step in a minimal form (a couple of minutes)")
    parser.add_argument("-o", "--output", default=None, help="the page to write (default docs/results.md; --short needs one)")
    parser.add_argument("--build", default=os.path.join(ROOT, "build"), help="the build folder (default build/)")
    parser.add_argument("--kumite", default=None, help="the kumite executable (default BUILD/bin/kumite)")
    args = parser.parse_args()
    if args.short and not args.output:
        parser.error("--short writes a page not to keep: give -o PATH")
    output = os.path.abspath(args.output or os.path.join(ROOT, "docs", "results.md"))
    started = time.monotonic()
    try:
        ctx = Context(args)
        if not os.access(ctx.kumite, os.X_OK):
            raise Failure(f"{ctx.kumite}: not built (build with scripts/build.sh, or give --kumite PATH)")
        with tempfile.TemporaryDirectory(prefix="kumite-results-") as work:
            ctx.work = work
            baked = bake(ctx)
            bench = benchmarks(ctx)
            adapted = adapt_strikes(ctx)
            bout = play_bout(ctx)
            rates = hit_rates(ctx)
            opponents = real_opponents(ctx)
            try:
                sections = [strikes_section(rates, opponents, bout), blows_section(opponents, ctx.mocap), speed_section(opponents),
                            distance_section(opponents), frame_section(bench, bout), retrieval_section(bench, adapted),
                            parse_section(bench, baked), training_section(bench)]
            except (KeyError, TypeError, IndexError, ZeroDivisionError, statistics.StatisticsError) as error:
                raise Failure(f"a step's output lacks what the page needs: {type(error).__name__} {error}")
        text = page(ctx, sections, time.monotonic() - started)
    except Failure as failure:
        print(f"results: {failure}", file=sys.stderr)
        return 1
    os.makedirs(os.path.dirname(output), exist_ok=True)
    temporary = tempfile.NamedTemporaryFile("w", dir=os.path.dirname(output), prefix=".results-", suffix=".md", delete=False)
    with temporary:
        temporary.write(text)
    os.chmod(temporary.name, 0o644)
    os.replace(temporary.name, output)
    progress(f"wrote {output} in {(time.monotonic() - started) / 60.0:.1f} minutes")
    return 0


if __name__ == "__main__":
    sys.exit(main())
