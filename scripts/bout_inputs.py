"""What the checks of a bout against a user give `kumite play`: a database (baked from annotations when given
those), and the supervisor's orders, a punch or kick every 2 s; and the arguments they take."""
import argparse
import os
import subprocess


def parser(doc, duration):
    """The arguments every check of bouts takes: KUMITE DB MOCAP_ROOT, --characters, --duration, --json."""
    parser = argparse.ArgumentParser(description=doc.split("\n\n")[0])
    parser.add_argument("kumite")
    parser.add_argument("database")
    parser.add_argument("mocap")
    parser.add_argument("--characters", default="brawler,kid,giant")
    parser.add_argument("--duration", type=float, default=duration)
    parser.add_argument("--json")
    return parser


def database(kumite, given, mocap, work):
    """`given` as it is (a .kdb), or baked into `work` from it (annotations .json)."""
    if not given.endswith(".json"):
        return given
    baked = os.path.join(work, "ref.kdb")
    subprocess.run([kumite, "bake", given, "-o", baked, "--mocap-root", mocap], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return baked


def orders_every(path, lines, duration, gap_s, end_margin_s=1.0):
    """A command script: from 1 s on, every gap_s, the lines in turn, until end_margin_s before the end."""
    with open(path, "w") as out:
        t, n = 1.0, 0
        while t < duration - end_margin_s:
            out.write(f"{t:.2f} {lines[n % len(lines)]}\n")
            t, n = t + gap_s, n + 1
    return path


def orders_every_2s(path, duration):
    """A command script: from 1 s on, every 2 s, punch and kick in turn, left twice then right twice."""
    return orders_every(path, ["punch left", "kick left", "punch right", "kick right"], duration, 2.0)
