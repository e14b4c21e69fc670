from ._result import Report
from ._types import Number
from typing import Sequence

__all__ = ['green', 'GreenResult']

class GreenResult(Report): ...

def green(*, at: str | Sequence[Number] | None = None, cells: str | Sequence[tuple[Number, Number]] | None = None, constants: bool = False, digits: int | None = None, c1: Number | None = None, c2: Number | None = None, poisson: Number | None = None) -> GreenResult: ...
