"""Progress of long calls: ``progress=True`` draws a tqdm bar, ``progress=callable`` receives
the fraction done in [0, 1] (called from the calling thread, every 50 ms at most)."""

from __future__ import annotations

from typing import Any, Callable, Optional, Union

Progress = Union[bool, Callable[[float], Any], None]


class _Bar:
    """A tqdm bar driven by fractions."""

    def __init__(self, desc: str):
        from tqdm.auto import tqdm

        self._bar = tqdm(total=1000, desc=desc, leave=False)
        self._done = 0

    def __call__(self, fraction: float) -> None:
        n = int(round(1000 * min(max(fraction, 0.0), 1.0)))
        if n > self._done:
            self._bar.update(n - self._done)
            self._done = n

    def close(self) -> None:
        self._bar.close()


def callback(progress: Progress, desc: str) -> Optional[Callable[[float], Any]]:
    """The callable the extension calls, or ``None`` for no progress."""
    if progress is None or progress is False:
        return None
    if progress is True:
        return _Bar(desc)
    if callable(progress):
        return progress
    from ._args import _invalid

    raise _invalid("progress", f"invalid progress = {progress!r}: True, False or a callable")


def close(cb: Optional[Callable[[float], Any]]) -> None:
    """Closes a bar made by :func:`callback`."""
    if isinstance(cb, _Bar):
        cb.close()
