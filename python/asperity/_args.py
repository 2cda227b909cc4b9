"""Every argument of every function converted by one rule, before the library sees it.

A number, a count, a seed, a flag, a choice or a list is checked for its type and, where the
library has one, against its range in the library's range table (``asperity::limits``, the
same ranges the CLI states for its flags). What does not fit raises :class:`InputError` (a
``ValueError``) naming the argument, the value as given (shortened) and what is allowed, e.g.
``invalid seed = -1: allowed a whole number 0 <= seed <= 18446744073709551615`` — never a bare
``OverflowError``, an ``IndexError`` or a ``TypeError`` that does not name the argument.
"""

from __future__ import annotations

import math
import numbers
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple

import numpy as np

from . import _native
from ._errors import InputError

__all__ = ["shown", "refuse", "number", "count", "seed", "flag", "choice", "numbers_list", "callback", "text_list"]

#: The longest value an error message repeats; longer ones are cut with "...".
SHOWN_MAX = 40


def fmt_value(v: float) -> str:
    """A float as the library's messages write it (``asperity::error::fmt_value``): the
    shortest round-trip digits between 1e-4 and 1e6 (``0.5``, ``100``), else scientific
    (``1e300``, ``1.5e-7``); ``inf``, ``-inf``, ``NaN``."""
    if math.isnan(v):
        return "NaN"
    if math.isinf(v):
        return "inf" if v > 0 else "-inf"
    if v == 0 or 1e-4 <= abs(v) < 1e6:
        return str(int(v)) if v.is_integer() else repr(v)
    mantissa, exp = np.format_float_scientific(v, unique=True, trim="-").split("e")
    return f"{mantissa}e{int(exp)}"


def shown(x: Any) -> str:
    """``x`` as a message shows it: a float as :func:`fmt_value`, anything else its ``repr``,
    cut to :data:`SHOWN_MAX` characters (a 300-digit int reads ``1000...000``)."""
    if isinstance(x, (float, np.floating)):
        return fmt_value(float(x))
    try:
        r = repr(x)
    except Exception:  # a repr that fails still names its type
        r = f"<{type(x).__name__}>"
    if len(r) > SHOWN_MAX:
        half = (SHOWN_MAX - 3) // 2
        r = r[:half] + "..." + r[-half:]
    return r


def refuse(name: str, x: Any, allowed: str, key: Optional[str] = None) -> InputError:
    """The :class:`InputError` of argument ``name`` given ``x`` where ``allowed`` is allowed."""
    value = shown(x)
    return InputError(f"invalid {name} = {value}: allowed {allowed}", field=name, value=value, allowed=allowed, key=key or name)


_RANGES: Dict[Tuple[str, str], Optional[Dict[str, Any]]] = {}


def _range(key: str, name: str) -> Optional[Dict[str, Any]]:
    """The range of the library field ``key`` described about ``name`` (cached)."""
    k = (key, name)
    if k not in _RANGES:
        _RANGES[k] = _native.allowed(key, name)
    return _RANGES[k]


def _inside(r: Dict[str, Any], x: float) -> bool:
    lo, hi = r["lo"], r["hi"]
    ok_lo = (x > -math.inf) if lo is None else (x >= lo if r["lo_inclusive"] else x > lo)
    ok_hi = (x < math.inf) if hi is None else (x <= hi if r["hi_inclusive"] else x < hi)
    return bool(ok_lo and ok_hi and (not r["whole"] or float(x).is_integer()))


def _is_real(x: Any) -> bool:
    return isinstance(x, numbers.Real) and not isinstance(x, (bool, np.bool_))


def number(x: Any, name: str, key: Optional[str] = None, *, allowed: str = "a finite number") -> float:
    """``x`` as a float: a real number (not a bool), finite, inside the range of the library
    field ``key`` where given (the field's named values, e.g. ``inf`` for t·q_r, allowed)."""
    r = _range(key, name) if key else None
    what = r["describe"] if r else allowed
    if not _is_real(x):
        raise refuse(name, x, what, key)
    try:
        v = float(x)
    except OverflowError:  # an int beyond the largest double
        raise refuse(name, x, what, key) from None
    if r is not None:
        if math.isinf(v) and "inf" in r["named"] and v > 0:
            return v
        if not _inside(r, v):
            raise refuse(name, x, what, key)
    elif not math.isfinite(v):
        raise refuse(name, x, what, key)
    return v


#: The largest count the extension takes (a 64-bit signed integer).
COUNT_MAX = 2**63 - 1


def _whole(x: Any) -> Optional[int]:
    """``x`` as an int if it is a whole number (an int, a numpy integer, a whole float)."""
    if isinstance(x, (bool, np.bool_)):
        return None
    if isinstance(x, numbers.Integral):
        return int(x)
    if isinstance(x, numbers.Real):
        v = float(x)
        if math.isfinite(v) and v.is_integer():
            return int(v)
    return None


def count(x: Any, name: str, key: Optional[str] = None, *, lo: int = 1, hi: Optional[int] = None) -> int:
    """``x`` as an int: a whole number inside the range of the library field ``key`` (else
    ``lo <= x <= hi``)."""
    r = _range(key, name) if key else None
    what = r["describe"] if r else (f"a whole number {lo} <= {name}" + (f" <= {hi}" if hi is not None else ""))
    if (r is None and hi is None) or (r is not None and r["hi"] is None):
        # the extension's counts are 64-bit
        what += f" (at most {COUNT_MAX})"
    n = _whole(x)
    if n is None or n > COUNT_MAX:
        raise refuse(name, x, what, key)
    ok = _inside(r, float(n)) if r is not None else (n >= lo and (hi is None or n <= hi))
    if not ok:
        raise refuse(name, x, what, key)
    return n


def seed(x: Any, name: str = "seed") -> int:
    """A seed: a whole number 0 <= seed <= 2⁶⁴−1 (the CLI's ``--seed``)."""
    what = f"a whole number 0 <= {name} <= {2**64 - 1}"
    n = _whole(x)
    if n is None or not 0 <= n <= 2**64 - 1:
        raise refuse(name, x, what, "gfmd.seed")
    return n


def flag(x: Any, name: str) -> bool:
    """``x`` as a bool: True or False (a numpy bool too), nothing else."""
    if isinstance(x, (bool, np.bool_)):
        return bool(x)
    raise refuse(name, x, "True or False")


def choice(x: Any, name: str, choices: Sequence[str]) -> str:
    """``x`` as one of ``choices`` (a string)."""
    if isinstance(x, str) and x in choices:
        return x
    allowed = ", ".join(choices[:-1]) + " or " + choices[-1] if len(choices) > 1 else choices[0]
    raise refuse(name, x, allowed)


def numbers_list(x: Any, name: str, key: Optional[str] = None, *, missing: bool = False) -> List[float]:
    """``x`` as a non-empty list of finite numbers (a sequence or a 1-D array; each inside the
    range of ``key`` where given; NaN for a missing value where ``missing``)."""
    what = "a non-empty list of finite numbers" + (" (NaN: missing)" if missing else "")
    if isinstance(x, (str, bytes)) or np.ma.isMaskedArray(x):
        raise refuse(name, x, what)
    try:
        arr = np.asarray(x, dtype=float)
    except (TypeError, ValueError, OverflowError):
        raise refuse(name, x, what) from None
    if arr.ndim != 1 or arr.size == 0 or not np.all(np.isfinite(arr) | (missing & np.isnan(arr))):
        raise refuse(name, x, what)
    out = [float(v) for v in arr]
    if key:
        for v in out:
            number(v, name, key)
    return out


def text_list(x: Any, name: str, allowed: str) -> List[str]:
    """``x`` as a list of strings (one string, or a sequence of them)."""
    if isinstance(x, str):
        return [x]
    if isinstance(x, (list, tuple)) and x and all(isinstance(t, str) for t in x):
        return list(x)
    raise refuse(name, x, allowed)


def callback(x: Any, name: str = "progress") -> Optional[Callable[..., Any]]:
    """``x`` as a callable or None."""
    if x is None:
        return None
    if callable(x):
        f: Callable[..., Any] = x
        return f
    raise refuse(name, x, "a callable taking a dict, or None")
