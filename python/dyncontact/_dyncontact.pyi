from typing import Any, Callable, List, Optional

__all__ = ["InvalidParameterError", "NumericalError", "wedge", "impact", "set_num_threads", "get_num_threads", "VERSION", "RUN_MAX_DIGITS", "MAX_DIGITS"]

MAX_DIGITS: int
RUN_MAX_DIGITS: int
VERSION: str

class InvalidParameterError(ValueError):
    parameter: str

class NumericalError(ArithmeticError): ...

def wedge(argv: List[str], progress: Optional[Callable[[float], Any]] = None) -> str: ...
def impact(argv: List[str], progress: Optional[Callable[[float], Any]] = None) -> str: ...
def set_num_threads(n: int) -> None: ...
def get_num_threads() -> int: ...
