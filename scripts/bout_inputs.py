"""What the checks of a bout against a user give `kumite play`: a database (baked from annotations when given
those), and the supervisor's orders, a punch or kick every 2 s."""
import os
import subprocess


def database(kumite, given, mocap, work):
    """`given` as it is (a .kdb), or baked into `work` from it (annotations .json)."""
    if not given.endswith(".json"):
        return given
    baked = os.path.join(work, "ref.kdb")
    subprocess.run([kumite, "bake", given, "-o", baked, "--mocap-root", mocap], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return baked


def orders_every_2s(path, duration):
    """A command script: from 1 s on, every 2 s, punch and kick in turn, left twice then right twice."""
    with open(path, "w") as out:
        t, n = 1.0, 0
        while t < duration - 1.0:
            out.write(f"{t:.2f} {'punch' if n % 2 == 0 else 'kick'} {'left' if (n // 2) % 2 == 0 else 'right'}\n")
            t, n = t + 2.0, n + 1
    return path
