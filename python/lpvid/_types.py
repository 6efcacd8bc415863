"""The types of the package's arguments, for type hints and documentation.

- ArrayLike: a numpy array, a list, a pandas Series or DataFrame; 1-D is one
  channel, 2-D is samples × channels.
- ModelLike: an lpvid.Model, a model dict (format lpvid-model/1) or the path
  of a model file.
- ExactNumber: a bound or a number given exactly: an int, a float (taken as
  the double it is), a fractions.Fraction or exact text such as "1/100".
- Rows: a window of rows (begin, end), 0-based, end exclusive.
- Progress: a function called with each progress line.
"""

import os
from fractions import Fraction
from typing import TYPE_CHECKING, Any, Callable, Dict, Mapping, Sequence, Tuple, Union

if TYPE_CHECKING:  # pragma: no cover
    from .model import Model

try:
    from numpy.typing import ArrayLike
except ImportError:  # pragma: no cover  (numpy < 1.20)
    ArrayLike = Any

PathLike = Union[str, "os.PathLike[str]"]
ModelLike = Union["Model", Dict[str, Any], PathLike]
ModelsLike = Union[ModelLike, Sequence[ModelLike], Mapping[str, ModelLike]]
ExactNumber = Union[int, float, Fraction, str]
Rows = Tuple[int, int]
Progress = Callable[[str], None]
Signals = Union[Tuple[ArrayLike, ArrayLike], Tuple[ArrayLike, ArrayLike, ArrayLike], Mapping[str, ArrayLike]]
Data = Union[PathLike, Sequence[PathLike], Mapping[str, ArrayLike], Any]

__all__ = ["ArrayLike", "PathLike", "ModelLike", "ModelsLike", "ExactNumber", "Rows", "Progress", "Signals", "Data"]
