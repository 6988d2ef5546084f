"""pytest for kumite.Store (bindings/python/store_binding.cpp), `kumite progress --json` and `kumite export` read by
pandas. The store is made the way a trainer makes one: `kumite train --headless` twice on a short drill, with a
simulated trainee. KUMITE_EXE is the command line (ctest sets it)."""
import json
import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import kumite

SOURCE = pathlib.Path(os.environ.get("KUMITE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
KUMITE = os.environ.get("KUMITE_EXE", str(SOURCE / "build" / "bin" / "kumite"))
GOLDEN = SOURCE / "data" / "golden" / "golden-v2.kdb"

DRILL = """name = "reaction check"
[[part]]
name = "jabs and crosses"
attacks = ["punch right straight high", "punch left straight high", "kick right front middle"]
order = "in turn"
cadence_s = 2.5
count = 6
seed = 1
difficulty = "person"
"""

FLAGS = {"complete", "own", "countered", "defended"}


def kumite_run(*arguments):
    return subprocess.run([KUMITE, *map(str, arguments)], capture_output=True, text=True)


@pytest.fixture(scope="module")
def store(tmp_path_factory):
    """Two sessions of the drill by "Ada L" (the second countering every blow) and one by "Ben"."""
    folder = tmp_path_factory.mktemp("store")
    drill = folder / "reaction-check.toml"
    drill.write_text(DRILL)
    path = folder / "training.sqlite"
    for trainee, tracker in (("Ada L", "simulate:cover:0.3"), ("Ada L", "simulate:counter"), ("Ben", "simulate:slip:0.2")):
        done = kumite_run("train", GOLDEN, "--headless", "--trainee", trainee, "--drill", drill, "--store", path, "--tracker", tracker)
        assert done.returncode == 0, done.stderr
    return path


def test_store_reads_the_trainees_and_sessions(store):
    s = kumite.Store(str(store))
    assert s.path == str(store)
    trainees = s.trainees()
    assert list(trainees.columns) == ["trainee_id", "trainee", "sessions", "last_utc"]
    assert dict(zip(trainees.trainee, trainees.sessions)) == {"Ada L": 2, "Ben": 1}
    sessions = s.sessions(trainee="Ada L")
    assert len(sessions) == 2
    assert list(sessions.columns[:2]) == ["session_id", "trainee"]
    assert (sessions.trainee == "Ada L").all() and (sessions.drill == "reaction check").all()
    assert sessions.complete.dtype == bool and sessions.complete.all()
    assert sessions.session_id.dtype == np.int64 and sessions.attacks.dtype == np.int64
    assert sessions.duration_s.dtype == np.float64 and (sessions.duration_s > 10).all()
    assert len(s.sessions()) == 3


def test_store_attacks_have_the_responses_typed(store):
    s = kumite.Store(str(store))
    sessions = s.sessions(trainee="Ada L")
    attacks = s.attacks(trainee="Ada L")
    assert len(attacks) == sessions.attacks.sum() > 0
    for column in ("session_id", "trainee", "seq", "command", "kind", "height", "result", "response", "response_time_s", "quality", "countered", "counter_landed"):
        assert column in attacks.columns
    assert attacks.response_time_s.dtype == np.float64
    assert attacks.command.dtype == object and attacks.countered.dtype == bool and attacks.own.dtype == bool
    # A blow not answered has no time (NaN), an answered one a time.
    unanswered = attacks.response == "none"
    assert attacks.response_time_s[unanswered].isna().all()
    assert attacks.response_time_s[~unanswered].notna().all()
    assert set(attacks.quality) <= {"in_time", "late", "none"}
    # One session's rows alone, and each session's median as `kumite progress --json` gives it.
    first = int(sessions.session_id.iloc[0])
    one = s.attacks(session=first)
    assert len(one) == sessions.attacks.iloc[0] and (one.session_id == first).all()
    progress = json.loads(kumite_run("progress", "Ada L", "--store", store, "--json").stdout)
    assert [p["session_id"] for p in progress["sessions"]] == list(sessions.session_id)
    for p in progress["sessions"]:
        times = attacks.response_time_s[(attacks.session_id == p["session_id"]) & (attacks.response_time_s >= 0)]
        if len(times):
            assert p["response_time_s"]["median"] == pytest.approx(times.median())
            assert p["response_time_s"]["p25"] == pytest.approx(times.quantile(0.25))
        else:
            assert p["response_time_s"]["median"] is None
    assert progress["comparisons"][0]["drill"] == "reaction check" and progress["comparisons"][0]["reaction_test"]


def test_store_user_strikes(store):
    s = kumite.Store(str(store))
    strikes = s.user_strikes(trainee="Ada L")
    assert len(strikes) == s.sessions(trainee="Ada L").user_strikes.sum() > 0
    assert list(strikes.columns[:2]) == ["session_id", "trainee"]
    assert strikes.defended.dtype == bool and strikes.outcome.dtype == object
    assert strikes.peak_speed_mps.dtype == np.float64
    # No rows: the columns still, typed as pandas types an empty file's (object), flags bool.
    none = s.user_strikes(trainee="Ben")
    assert len(none) == 0 and list(none.columns) == list(strikes.columns) and none.defended.dtype == bool


def test_store_without_pandas_gives_numpy_arrays(store, monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)  # `import pandas` raises ImportError
    attacks = kumite.Store(str(store)).attacks(trainee="Ben")
    assert isinstance(attacks, dict)
    assert attacks["response_time_s"].dtype == np.float64
    assert attacks["command"].dtype == object and attacks["countered"].dtype == bool
    assert attacks["session_id"].dtype == np.int64
    assert len({len(column) for column in attacks.values()}) == 1
    assert set(attacks["trainee"]) == {"Ben"}


def test_store_errors_say_what(store, tmp_path):
    s = kumite.Store(str(store))
    with pytest.raises(kumite.Error, match='no trainee "Zed".*Ada L, Ben'):
        s.attacks(trainee="Zed")
    with pytest.raises(kumite.Error, match="no session 999"):
        s.user_strikes(session=999)
    with pytest.raises(kumite.Error):
        kumite.Store(str(tmp_path / "none.sqlite"))
    (tmp_path / "not.sqlite").write_text("not a store")
    with pytest.raises(kumite.Error):
        kumite.Store(str(tmp_path / "not.sqlite"))


def test_store_path_defaults_to_kumite_store(store, monkeypatch):
    monkeypatch.setenv("KUMITE_STORE", str(store))
    assert kumite.Store().path == str(store)


def test_progress_page_and_its_errors(store, tmp_path):
    page = tmp_path / "ada.html"
    done = kumite_run("progress", "Ada L", "--store", store, "-o", page)
    assert done.returncode == 0, done.stderr
    html = page.read_text()
    # A point a session with answers timed (the countering session has none).
    numbers = json.loads(kumite_run("progress", "Ada L", "--store", store, "--json").stdout)
    timed = [p for p in numbers["sessions"] if p["response_time_s"]["n"] > 0]
    trend = html[html.index('id="trend-response-time"'):]
    trend = trend[:trend.index("</svg>")]
    assert trend.count('class="median-point"') == len(timed) > 0
    for p in timed:
        assert f'data-session-id="{p["session_id"]}" data-attack="all" data-median-s="{p["response_time_s"]["median"]:.4f}"' in trend
    unknown = kumite_run("progress", "Zed", "--store", store, "-o", tmp_path / "zed.html")
    assert unknown.returncode == 1 and "Ada L, Ben" in unknown.stderr
    assert not (tmp_path / "zed.html").exists()
    assert kumite_run("progress", "Ada L", "--store", store).returncode == 2  # neither -o nor --json


@pytest.mark.parametrize("table", ["sessions", "attacks", "user_strikes"])
def test_export_reads_in_pandas_as_is(store, tmp_path, table):
    pd = pytest.importorskip("pandas")
    expected = kumite.Store(str(store)).__getattribute__(table)()
    for suffix, read in ((".csv", pd.read_csv), (".json", pd.read_json)):
        out = tmp_path / (table + suffix)
        done = kumite_run("export", "--store", store, "--table", table, "-o", out)
        assert done.returncode == 0, done.stderr
        frame = read(out)
        assert list(frame.columns) == list(expected.columns), suffix
        assert len(frame) == len(expected) > 0
        for column in expected.columns:
            want, got = expected[column], frame[column]
            if column in FLAGS:  # 0 and 1 in the file
                assert got.dtype == np.int64 and (got.astype(bool) == want).all(), (suffix, column)
            elif want.dtype == object and want.fillna("").eq("").all():
                # Text empty in every row: pandas cannot tell it from a missing number (read with dtype=str to keep it text).
                assert got.isna().all() or got.fillna("").eq("").all(), (suffix, column)
            elif want.dtype == object:
                assert got.dtype == object and (got.fillna("") == want.fillna("")).all(), (suffix, column)
            else:
                # read_json turns a float column whose values are all whole into int64; read_csv keeps the type.
                whole = suffix == ".json" and want.dtype == np.float64 and got.dtype == np.int64
                assert got.dtype == want.dtype or whole, (suffix, column, got.dtype, want.dtype)
                assert np.allclose(got.to_numpy(float), want.to_numpy(float), equal_nan=True), (suffix, column)
