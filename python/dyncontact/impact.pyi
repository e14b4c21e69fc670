from . import _progress
from ._result import Report, RunResult as RunResult
from ._types import Number
from typing import Sequence

__all__ = ['run', 'edge', 'RunResult', 'EdgeResult']

class EdgeResult(Report): ...

def run(*, profile: str, striker: str = 'rigid', mass_ratio: float | None = None, v0_over_c1: float | None = None, driven: str | None = None, law: str | None = None, end: Number | str | None = None, c1: Number | None = None, c2: Number | None = None, poisson: Number | None = None, length: float | None = None, dx: float | None = None, kappa: float | None = None, levels: int | None = None, edge_cell: str | None = None, pressure_at: str | Sequence[Number] | None = None, digits: int | None = None, force: bool = False, memory_limit_gib: float | None = None, progress: _progress.Progress = False) -> RunResult: ...
def edge(*, speed_over_c1: str | Sequence[Number] | Number, law: str | None = None, c1: Number | None = None, c2: Number | None = None, poisson: Number | None = None) -> EdgeResult: ...
