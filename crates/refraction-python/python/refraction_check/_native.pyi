# Type stubs of the Rust module (src/module.rs); the docs are the functions' own.
from typing import Any, Dict, List, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

__version__: str

#: Anything numpy's asarray takes: NumPy arrays, Dr.Jit arrays, torch tensors on the CPU,
#: lists and tuples (None for a call that logged nothing), numbers.
ArrayLike = Any

def check(
    api: Optional[str] = None,
    *,
    inside: Optional[float] = None,
    outside: Optional[float] = None,
    normal: Union[str, ArrayLike, None] = None,
    convention: Union[str, Sequence[Optional[str]], None] = None,
    precision: Union[str, Sequence[Optional[str]], None] = None,
    renderer: Optional[str] = None,
    **fields: ArrayLike,
) -> Checked: ...

class Checked:
    @property
    def ok(self) -> npt.NDArray[np.bool_]: ...
    @property
    def codes(self) -> npt.NDArray[np.str_]: ...
    @property
    def mistakes(self) -> List[List[str]]: ...
    @property
    def summary(self) -> Dict[str, Any]: ...
    @property
    def answers(self) -> List[Optional[Dict[str, Any]]]: ...
    @property
    def errors(self) -> List[Optional[str]]: ...
    @property
    def tally(self) -> Dict[str, int]: ...
    @property
    def diagnosis(self) -> List[str]: ...
    @property
    def verdict(self) -> Optional[str]: ...
    def __len__(self) -> int: ...
    def _repr_html_(self) -> str: ...
