#!/usr/bin/env python3
"""The player's viewer under Xvfb: `kumite play` without --headless opens the window, steps the bout in real time
for a few seconds with two orders, saves a screenshot and exits. The report must say the viewer ran and the
strikes happened; the screenshot must show the fighter (enough pixels of a saturated colour: the body's, or the
capsules') and the HUD. Then three brawlers' skinned bodies (one mesh upload) against their capsules at the same
camera ({"bodies": false}): the bodies must cover far more pixels, and stay inside the capsules' outline grown by a quarter of its height (a skinning error
shows as a spike across the screen). Then the wall-screen view: head-coupled from the simulated user's eyes, stereo
side by side: the fighter must be in both halves.

usage: check_play_viewer.py KUMITE DB.kdb OUTPUT_DIR      (exit 77: skipped when xvfb-run is not installed)
"""
import json, os, shutil, struct, subprocess, sys, zlib


def read_png(path):
    """Decodes an 8-bit RGB or RGBA, non-interlaced PNG (what Qt writes) into rows of (r, g, b) tuples."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour in (2, 6) and interlace == 0, f"unexpected PNG format {depth} {colour} {interlace}"
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        filter_type = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if filter_type == 1: line[i] = (line[i] + a) & 255
            elif filter_type == 2: line[i] = (line[i] + b) & 255
            elif filter_type == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif filter_type == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        previous = line
    return rows


def is_fighter(pixel):
    """Bodies and capsules are saturated colours; the background, grid, head sphere and HUD text are greys."""
    return max(pixel) - min(pixel) > 45


def fighter_pixels(rows, columns=None):
    """The fighter's pixels between the HUD's top and bottom lines: their count and bounding box."""
    columns = columns or slice(0, len(rows[0]))
    count, box = 0, [10 ** 6, 10 ** 6, -1, -1]
    for y, row in enumerate(rows[80:len(rows) - 50], start=80):
        for x, pixel in enumerate(row[columns], start=columns.start):
            if is_fighter(pixel):
                count += 1
                box = [min(box[0], x), min(box[1], y), max(box[2], x), max(box[3], y)]
    return count, box


def main():
    kumite, database, out = sys.argv[1:4]
    if shutil.which("xvfb-run") is None:
        print("skipped: xvfb-run is not installed (scripts/setup.sh --test installs it)")
        return 77
    os.makedirs(out, exist_ok=True)
    script, shot, report = os.path.join(out, "orders.txt"), os.path.join(out, "viewer.png"), os.path.join(out, "viewer_report.json")
    open(script, "w").write("0.5 punch\n2.0 kick right\n")
    for path in (shot, report):
        if os.path.exists(path): os.remove(path)
    command = ["xvfb-run", "-a", "-s", "-screen 0 1280x720x24", kumite, "play", database, "--commands", "script:" + script,
               "--duration", "3.5", "--screenshot", shot, "--report", report]
    result = subprocess.run(command, capture_output=True, text=True, timeout=120)
    print(result.stdout, result.stderr)
    assert result.returncode == 0, f"kumite play exited {result.returncode}"
    summary = json.load(open(report))
    print(json.dumps(summary))
    assert summary["viewer"] is True, "the viewer did not open"
    assert summary["orders"] == 2 and summary["strikes"] >= 1, "the orders did not produce strikes"
    assert summary["frames"] >= 3.5 * 60 * 0.9, "the bout did not step at 60 Hz in the window"
    rows = read_png(shot)
    height, width = len(rows), len(rows[0])
    fighter, _ = fighter_pixels(rows)
    # The HUD: near-white text in the top-left corner.
    hud = sum(1 for row in rows[:60] for (r, g, b) in row[:500] if r > 200 and g > 200 and b > 200)
    print(f"screenshot {width}x{height}: {fighter} fighter pixels, {hud} HUD pixels")
    assert fighter > 2000, "the fighter is not visible in the screenshot"
    assert hud > 200, "the HUD is not visible in the screenshot"

    # The skinned body against the capsules, same character, camera and still user; three fighters share one
    # upload of the brawler's mesh.
    counts, uploads = {}, {}
    for bodies in (True, False):
        config, picture = os.path.join(out, f"bodies_{bodies}.json"), os.path.join(out, f"bodies_{bodies}.png")
        summary_path = os.path.join(out, f"bodies_{bodies}_report.json")
        open(config, "w").write(json.dumps({"bodies": bodies}))
        command = ["xvfb-run", "-a", "-s", "-screen 0 1280x720x24", kumite, "play", database, "--character", "brawler", "--fighters", "3",
                   "--tracker", "simulate:still", "--viewer-config", config, "--duration", "2", "--screenshot", picture,
                   "--report", summary_path]
        result = subprocess.run(command, capture_output=True, text=True, timeout=120)
        assert result.returncode == 0, f"kumite play ({'bodies' if bodies else 'capsules'}) exited {result.returncode}: {result.stderr}"
        counts[bodies] = fighter_pixels(read_png(picture))
        uploads[bodies] = json.load(open(summary_path))["viewer_drawing"]["body_meshes_uploaded"]
    print(f"body meshes uploaded for three brawlers: {uploads[True]} (capsules only: {uploads[False]})")
    assert uploads[True] == 1 and uploads[False] == 0, "three fighters of one character should share one mesh upload"
    (body, body_box), (capsules, capsule_box) = counts[True], counts[False]
    grow = (capsule_box[3] - capsule_box[1]) // 4
    inside = (body_box[0] >= capsule_box[0] - grow and body_box[1] >= capsule_box[1] - grow and
              body_box[2] <= capsule_box[2] + grow and body_box[3] <= capsule_box[3] + grow)
    print(f"skinned body: {body} pixels in {body_box}; capsules: {capsules} pixels in {capsule_box}; ratio {body / max(capsules, 1):.2f}")
    assert body > 1.4 * capsules, "the skinned body does not cover far more pixels than the capsules"
    assert inside, "the skinned body reaches far outside its skeleton's outline (a skinning spike)"

    wall, wall_shot = os.path.join(out, "wall.json"), os.path.join(out, "wall.png")
    open(wall, "w").write(json.dumps({"camera": "head_coupled", "stereo": "side_by_side", "screen": {
        "lower_left": [-1.5, 0.0, -0.5], "lower_right": [1.5, 0.0, -0.5], "upper_left": [-1.5, 2.25, -0.5]}}))
    command = ["xvfb-run", "-a", "-s", "-screen 0 1280x720x24", kumite, "play", database, "--tracker", "simulate:still",
               "--viewer-config", wall, "--duration", "2", "--screenshot", wall_shot]
    result = subprocess.run(command, capture_output=True, text=True, timeout=120)
    print(result.stdout, result.stderr)
    assert result.returncode == 0, f"kumite play (head-coupled) exited {result.returncode}"
    rows = read_png(wall_shot)
    half = len(rows[0]) // 2
    left, _ = fighter_pixels(rows, slice(0, half))
    right, _ = fighter_pixels(rows, slice(half, len(rows[0])))
    print(f"head-coupled stereo: {left} fighter pixels in the left eye's half, {right} in the right eye's")
    assert left > 1000 and right > 1000, "the fighter is not in both eyes' views"
    return 0


if __name__ == "__main__":
    sys.exit(main())
