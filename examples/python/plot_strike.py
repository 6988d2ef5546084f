"""Draws an adapted strike's hit trajectory with matplotlib: the fist (or foot) from the guard to the contact and
back, seen from the side and from above, the target marked.

    python3 plot_strike.py DB.kdb OUT.png [CHARACTER] [COMMAND] [X,Y,Z]
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import kumite  # noqa: E402


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    database = kumite.Database(sys.argv[1])
    character = sys.argv[3] if len(sys.argv) > 3 else "brawler"
    command = sys.argv[4] if len(sys.argv) > 4 else "punch"
    target = [float(v) for v in sys.argv[5].split(",")] if len(sys.argv) > 5 else [0.0, 1.45, 0.6]
    positions, report = database.adapt(character, target, command)
    bout = kumite.Bout(database, character=character)  # only for the joint names of the character
    effector = bout.joint_names().index(report["effector"])
    path = positions[:, effector]  # (frames, 3), metres
    contact = report["contact_frame"]

    figure, (side, top) = plt.subplots(1, 2, figsize=(10, 4.5))
    for axes, (a, b), names in ((side, (2, 1), ("z forward (m)", "y up (m)")), (top, (0, 2), ("x (m)", "z forward (m)"))):
        axes.plot(path[:, a], path[:, b], "-", color="#0072B2", label=f"{report['effector']} path")
        axes.plot(path[:contact + 1, a], path[:contact + 1, b], ".", color="#0072B2", markersize=4)
        axes.plot(target[a], target[b], "x", color="#D55E00", markersize=12, mew=3, label="target")
        axes.plot(path[contact, a], path[contact, b], "o", mfc="none", color="#009E73", markersize=12, label="contact")
        axes.set_xlabel(names[0])
        axes.set_ylabel(names[1])
        axes.set_aspect("equal")
        axes.grid(alpha=0.3)
    side.legend(loc="best")
    figure.suptitle(f"{command} on {character}: {report['clip']}, contact error {report['contact_error_m'] * 100:.1f} cm, "
                    f"overshoot {report['overshoot_m'] * 100:.1f} cm")
    figure.tight_layout()
    figure.savefig(sys.argv[2], dpi=100)
    print(f"wrote {sys.argv[2]}: {len(path)} frames, contact at frame {contact}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
