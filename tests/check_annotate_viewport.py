#!/usr/bin/env python3
"""kumite-annotate's viewport through OpenGL under Xvfb (the offscreen tests cover the QPainter path): the window
screenshot of the Bandai kick capture must show the skeleton (light grey capsules), the trajectory and box
(green) and the contact point (red).

usage: check_annotate_viewport.py KUMITE_ANNOTATE CAPTURE.bvh OUTPUT_DIR   (exit 77: skipped without xvfb-run)
"""
import os, shutil, subprocess, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_play_viewer import read_png  # noqa: E402


def main():
    annotate, capture, out = sys.argv[1:4]
    if shutil.which("xvfb-run") is None:
        print("skipped: xvfb-run is not installed (scripts/setup.sh --test installs it)")
        return 77
    if not os.path.exists(capture):
        print(f"skipped: {capture} is absent (scripts/fetch_mocap.sh)")
        return 77
    os.makedirs(out, exist_ok=True)
    shot = os.path.join(out, "annotate_gl.png")
    if os.path.exists(shot): os.remove(shot)
    env = dict(os.environ)
    env.pop("QT_QPA_PLATFORM", None)
    result = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1600x1000x24", annotate, capture, "--screenshot", shot],
                            capture_output=True, text=True, timeout=120, env=env)
    print(result.stdout, result.stderr)
    assert result.returncode == 0, f"kumite-annotate exited {result.returncode}"
    rows = read_png(shot)
    # The viewport is the window's upper left (docks right and below): count the skeleton there only, under the
    # light grey of the widgets.
    viewport = [row[:int(len(row) * 0.6)] for row in rows[40:int(len(rows) * 0.6)]]
    grey = sum(1 for row in viewport for (r, g, b) in row if 170 < r < 235 and abs(r - g) < 15 and abs(g - b) < 20)
    green = sum(1 for row in rows for (r, g, b) in row if g > 150 and g > r + 60 and g > b + 60)
    red = sum(1 for row in rows for (r, g, b) in row if r > 150 and r > g + 80 and r > b + 80)
    print(f"{len(rows[0])}x{len(rows)}: {grey} skeleton, {green} trajectory/box, {red} contact pixels")
    assert grey > 800, "the skeleton is not in the viewport"
    assert green > 300, "the trajectory and box are not in the viewport"
    assert red > 100, "the contact point is not in the viewport"
    return 0


if __name__ == "__main__":
    sys.exit(main())
