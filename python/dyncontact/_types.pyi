from decimal import Decimal

Number = int | float | Decimal | str
