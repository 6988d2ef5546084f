"""Type stubs for the kumite module (bindings/python/kumite_module.cpp). Arrays are float64, metres, Y up."""
from typing import Any, Optional, Sequence

import numpy as np
import numpy.typing as npt

__version__: str

class Error(RuntimeError):
    """kumite's errors: the message says what and where (file:line for a bad file)."""

class Capture:
    """A motion capture (BVH) in metres, read as kumite reads it."""
    def __init__(self, path: str, unit: Optional[str] = None, fps: Optional[float] = None, strict: bool = False) -> None: ...
    @property
    def path(self) -> str: ...
    @property
    def joint_names(self) -> list[str]: ...
    @property
    def parents(self) -> list[int]: ...
    @property
    def frame_count(self) -> int: ...
    @property
    def fps(self) -> Optional[float]: ...
    @property
    def unit(self) -> str: ...
    @property
    def height_m(self) -> float: ...
    @property
    def warnings(self) -> list[str]: ...
    def positions(self, frames: Optional[Sequence[int]] = None) -> npt.NDArray[np.float64]:
        """(frames, joints, 3) world positions in metres."""
    def body_map(self) -> dict[str, str]:
        """Body part ('hand_l', 'head', ...) -> joint name."""

class Database:
    """A motion database (.kdb), memory-mapped and validated."""
    def __init__(self, path: str) -> None: ...
    @property
    def path(self) -> str: ...
    @property
    def strike_count(self) -> int: ...
    def query(self, character: str, target: Sequence[float], command: str, side: Optional[str] = None, kind: Optional[str] = None,
              height: Optional[str] = None, characters_dir: Optional[str] = None) -> dict[str, Any]:
        """The strike retrieval picks: the keys of `kumite query --json`."""
    def adapt(self, character: str, target: Sequence[float], command: str, side: Optional[str] = None, kind: Optional[str] = None,
              height: Optional[str] = None, lead: int = 6, characters_dir: Optional[str] = None) -> tuple[npt.NDArray[np.float64], dict[str, Any]]:
        """(positions (frames, joints, 3), report with the keys of `kumite adapt --report`)."""

def bake(annotations: str, output: str, mocap_root: Optional[str] = None, fps: Optional[float] = None, jobs: int = 0) -> dict[str, Any]:
    """Bakes an annotation file into a motion database; returns a summary."""

class Bout:
    """Fighters against one user, stepped by the caller."""
    def __init__(self, database: Database, character: Optional[str] = None, characters_dir: Optional[str] = None,
                 tracker: Optional[str] = None, fighters: int = 1, aim: str = "latched", defence: bool = True, seed: int = 1,
                 rate_hz: float = 60.0) -> None: ...
    def set_user(self, head: Optional[Sequence[float]], left_hand: Optional[Sequence[float]] = None,
                 right_hand: Optional[Sequence[float]] = None) -> None: ...
    def command(self, line: str) -> None: ...
    def step(self, t_s: float) -> None: ...
    def events(self) -> list[dict[str, Any]]: ...
    @property
    def fighter_count(self) -> int: ...
    @property
    def now_s(self) -> float: ...
    def joint_names(self, fighter: int = 0) -> list[str]: ...
    def parents(self, fighter: int = 0) -> list[int]: ...
    def positions(self, fighter: int = 0) -> npt.NDArray[np.float64]: ...
    def world_transforms(self, fighter: int = 0) -> npt.NDArray[np.float64]: ...
    def _step_loop_us(self, start_s: float, frames: int, head: Sequence[float]) -> float: ...

class Store:
    """The training store (SQLite) that `kumite train` writes, read-only. Each table comes as a pandas DataFrame, or as a
    dict of numpy arrays (column name -> array) when pandas is not installed: the columns of `kumite export`; flags
    (complete, own, countered, defended) bool; integers int64; other numbers float64 with NaN for a missing value
    (response_time_s of a blow not answered); text object (None for a missing value). Raises kumite.Error with the
    store's message: a missing or damaged file, an unknown trainee (naming the ones there are) or session."""
    def __init__(self, path: Optional[str] = None) -> None:
        """path None: $KUMITE_STORE, else ~/.local/share/kumite/training.sqlite."""
    @property
    def path(self) -> str: ...
    def trainees(self) -> Any:
        """trainee_id, trainee, sessions, last_utc."""
    def sessions(self, trainee: Optional[str] = None) -> Any:
        """session_id, trainee, drill, ..., started_utc, duration_s, complete, attacks, user_strikes, ...; oldest first."""
    def attacks(self, trainee: Optional[str] = None, session: Optional[int] = None) -> Any:
        """session_id, trainee, seq, t_s, ..., command, kind, height, result, response, response_time_s (s), quality, ..."""
    def user_strikes(self, trainee: Optional[str] = None, session: Optional[int] = None) -> Any:
        """session_id, trainee, seq, t_s, ..., hand, outcome, defended, peak_speed_mps (m/s)."""
