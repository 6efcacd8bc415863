"""Exact numbers of reports and certificates ("0.0123", "1e-5", "p/q") as
fractions.Fraction, of any length.

An exact bound can have thousands of digits (at δ = 0 the smallest d_max² is
‖r‖²/(n·ny) exactly, with the data's and the model's denominators in it),
more than Python converts from text to int by default (4300 digits,
sys.get_int_max_str_digits). The digits are read here in pieces below that
limit, so nothing global is changed. (Printing such a Fraction meets the
same limit: float(x) or a Fraction's numerator.bit_length() are the ways
to look at one.)
"""

import decimal
from fractions import Fraction

_PIECE = 4000  # digits converted at a time, below the interpreter's limit


def _integer(text):
    """The integer of a decimal digit string with an optional sign."""
    text = text.strip()
    sign = -1 if text.startswith("-") else 1
    digits = text.lstrip("+-")
    if not digits.isdigit():
        raise ValueError(f"not an integer: {text[:40]!r}")
    n = 0
    for k in range(0, len(digits), _PIECE):
        piece = digits[k:k + _PIECE]
        n = n * 10 ** len(piece) + int(piece)
    return sign * n


def exact(text):
    """An exact number of a report or certificate as a Fraction (None for
    None): p/q, or a decimal with an optional exponent."""
    if text is None:
        return None
    s = str(text).strip()
    if "/" in s:
        p, q = s.split("/", 1)
        return Fraction(_integer(p), _integer(q))
    with decimal.localcontext() as context:
        context.traps[decimal.InvalidOperation] = True
        return Fraction(decimal.Decimal(s))
