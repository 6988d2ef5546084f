"""pytest for the Python module `kumite` (bindings/python), run by ctest with the environment it sets:
KUMITE_EXE (the command line), KUMITE_MOCAP_ROOT, KUMITE_SOURCE_DIR. The module must be importable (PYTHONPATH)."""
import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import kumite

SOURCE = pathlib.Path(os.environ.get("KUMITE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
MOCAP = pathlib.Path(os.environ.get("KUMITE_MOCAP_ROOT", SOURCE / "data" / "mocap"))
KUMITE = os.environ.get("KUMITE_EXE", str(SOURCE / "build" / "bin" / "kumite"))
GOLDEN = SOURCE / "data" / "golden" / "golden-v2.kdb"


def run_json(*arguments):
    done = subprocess.run([KUMITE, *map(str, arguments)], check=True, capture_output=True, text=True)
    return json.loads(done.stdout)


def shared_captures():
    """One capture of every folder of the shared captures (the first by name), and the Frame Time 0 ones need fps."""
    if not MOCAP.is_dir():
        return []
    chosen = []
    for folder in sorted(p for p in MOCAP.iterdir() if p.is_dir()):
        files = sorted(folder.rglob("*.bvh"))
        if files:
            chosen.append(files[0])
    return chosen


@pytest.mark.parametrize("path", shared_captures(), ids=lambda p: p.parent.name)
def test_capture_positions_equal_the_command_line(path):
    try:
        capture = kumite.Capture(str(path))
    except kumite.Error:
        pytest.skip(f"{path.name} is one of the broken files: the command line refuses it too")
    frames = sorted({0, capture.frame_count // 2, capture.frame_count - 1})
    positions = capture.positions(frames)
    assert positions.shape == (len(frames), len(capture.joint_names), 3)
    assert positions.dtype == np.float64
    printed = run_json("positions", path, "--frames", ",".join(map(str, frames)), "--json")
    assert printed["joint_names"] == capture.joint_names
    for row, frame in enumerate(frames):
        expected = np.array(printed["frames"][str(frame)])
        assert np.abs(positions[row] - expected).max() <= 1e-9


def test_capture_reads_the_file_as_kumite_does():
    path = next(iter(shared_captures()), None)
    if path is None:
        pytest.skip("no shared captures")
    capture = kumite.Capture(str(path))
    inspected = run_json("inspect", path, "--json")
    assert capture.frame_count == inspected["frames"]
    assert len(capture.parents) == len(capture.joint_names) and capture.parents[0] == -1
    assert capture.positions().shape[0] == capture.frame_count
    parts = capture.body_map()
    assert {"pelvis", "head", "hand_l", "hand_r", "foot_l", "foot_r"} <= set(parts)
    assert set(parts.values()) <= set(capture.joint_names)


def test_a_malformed_file_raises_with_its_file_and_line(tmp_path):
    broken = tmp_path / "broken.bvh"
    broken.write_text("HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 3 Xposition Yposition\n}\nMOTION\nFrames: 1\nFrame Time: 0.03\n0 0 0\n")
    with pytest.raises(kumite.Error) as raised:
        kumite.Capture(str(broken))
    assert f"{broken}:6:" in str(raised.value)  # the channel list ends early: '}' on line 6
    with pytest.raises(kumite.Error, match="cannot open"):
        kumite.Capture(str(tmp_path / "missing.bvh"))
    if shared_captures():
        with pytest.raises(IndexError, match="out of range"):
            kumite.Capture(str(shared_captures()[0])).positions([10**9])


def test_adapt_reports_what_the_command_line_reports(tmp_path):
    database = kumite.Database(str(GOLDEN))
    positions, report = database.adapt("kid", [0.1, 0.8, 0.5], "kick")
    report_path = tmp_path / "kick.json"
    subprocess.run([KUMITE, "adapt", GOLDEN, "--character", "kid", "--target", "0.1,0.8,0.5", "--command", "kick", "--record",
                    tmp_path / "kick.bvh", "--report", report_path], check=True, capture_output=True)
    printed = json.loads(report_path.read_text())
    assert report["contact_error_m"] == printed["contact_error_m"]
    for key in printed:
        if key != "frame_cost_us":  # measured on the clock
            assert report[key] == printed[key], key
    assert positions.shape[0] == printed["frames"]
    # The effector at the contact frame is where the report says.
    effector = kumite.Capture(str(tmp_path / "kick.bvh")).joint_names.index(printed["effector"])
    assert np.abs(positions[printed["contact_frame"], effector] - np.array(printed["effector_at_contact"])).max() < 1e-6
    query = database.query("kid", [0.1, 0.8, 0.5], "kick")
    assert query["clip"] == report["clip"]
    with pytest.raises(kumite.Error, match="no 'dance' strikes"):
        database.adapt("kid", [0.1, 0.8, 0.5], "dance")
    with pytest.raises(ValueError):
        database.adapt("kid", [0.1, 0.8], "kick")


def test_bake_writes_what_the_command_line_writes(tmp_path):
    annotations = SOURCE / "data" / "annotations" / "golden.json"
    if not (MOCAP / "bandai-namco-1").is_dir():
        pytest.skip("no captures")
    summary = kumite.bake(str(annotations), str(tmp_path / "python.kdb"), mocap_root=str(MOCAP), jobs=2)
    assert summary["clips"] > 0
    subprocess.run([KUMITE, "bake", annotations, "-o", tmp_path / "cli.kdb", "--mocap-root", MOCAP, "--jobs", "2"], check=True, capture_output=True)
    assert (tmp_path / "python.kdb").read_bytes() == (tmp_path / "cli.kdb").read_bytes()
    with pytest.raises(kumite.Error):
        kumite.bake(str(tmp_path / "none.json"), str(tmp_path / "none.kdb"))
    assert not (tmp_path / "none.kdb").exists()


def test_a_bout_stepped_from_python():
    database = kumite.Database(str(GOLDEN))
    bout = kumite.Bout(database, character="brawler", seed=3)
    names = bout.joint_names()
    assert len(bout.parents()) == len(names) and bout.parents()[0] == -1
    bout.command("kick")
    seen = []
    for frame in range(180):
        bout.set_user([0.0, 1.65, 1.3], left_hand=[0.2, 1.4, 1.1])
        bout.step(frame / 60)
        seen += bout.events()
    assert any(event["type"] == "strike" for event in seen)
    assert all({"t", "type", "fighter"} <= set(event) for event in seen)
    transforms = bout.world_transforms()
    assert transforms.shape == (len(names), 4, 4)
    assert np.allclose(transforms[:, :3, 3], bout.positions())
    assert np.allclose(transforms[:, 3], [0, 0, 0, 1])
    rotation = transforms[1, :3, :3]
    assert np.allclose(rotation @ rotation.T, np.eye(3), atol=1e-9)
    with pytest.raises(kumite.Error, match="dance"):
        bout.command("dance")
    bout.set_user(None)  # not tracked: the fighter keeps its guard
    bout.step(3.0)
    simulated = kumite.Bout(database, tracker="simulate:wander")
    with pytest.raises(kumite.Error, match="tracker"):
        simulated.set_user([0, 1.6, 1])
    with pytest.raises(kumite.Error, match="unknown character"):
        kumite.Bout(database, character="nobody")


def resident_kib():
    for line in pathlib.Path("/proc/self/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1])
    raise RuntimeError("no VmRSS")


def test_a_thousand_opens_do_not_leak():
    path = next(iter(shared_captures()), None)
    paths = [str(path)] if path else []
    for _ in range(100):  # warm up: allocator pools, numpy's caches
        kumite.Database(str(GOLDEN))
        for p in paths:
            kumite.Capture(p).positions([0])
    before = resident_kib()
    for _ in range(1000):
        kumite.Database(str(GOLDEN))
        for p in paths:
            kumite.Capture(p).positions([0])
        try:
            kumite.Capture("/no/such.bvh")
        except kumite.Error:
            pass
    grown = resident_kib() - before
    print(f"resident memory after 1000 opens of the database and a capture: {grown:+d} KiB")
    assert grown < 4096


def test_the_example_plots_a_strike(tmp_path):
    example = SOURCE / "examples" / "python" / "plot_strike.py"
    env = dict(os.environ, MPLBACKEND="Agg")
    done = subprocess.run(["python3" if not os.path.exists("/usr/bin/python3") else "/usr/bin/python3", example, GOLDEN, tmp_path / "strike.png"],
                          env=env, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "strike.png").stat().st_size > 10000
