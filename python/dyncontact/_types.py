"""Type aliases of the public calls."""

from __future__ import annotations

from decimal import Decimal
from typing import Union

#: A number as the calls take it: decimal text, a ``Decimal``, an ``int`` or a ``float``
#: (its shortest repr).
Number = Union[int, float, Decimal, str]
