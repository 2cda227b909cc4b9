# Stubs of the extension module (python/src/*.rs). The documented API is asperity/__init__.py.
from typing import Any, Callable, Dict, List, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

__version__: str

Progress = Optional[Callable[[Dict[str, Any]], Any]]

class SceneCore:
    @property
    def preset_name(self) -> str: ...
    def replace(self, changes: Dict[str, Any]) -> SceneCore: ...
    def with_map(
        self,
        heights: npt.NDArray[np.float64],
        size_m: float,
        periodic: bool = ...,
        qmin: Optional[float] = ...,
        qmax: Optional[float] = ...,
        source: str = ...,
    ) -> SceneCore: ...
    def summary(self) -> Dict[str, Any]: ...
    def fields(self) -> Dict[str, Any]: ...

def scene_from_preset(name_or_path: str) -> SceneCore: ...
def scene_new(fields: Dict[str, Any]) -> SceneCore: ...
def options_check(
    sigma_points: int = ...,
    sigma_max: Optional[float] = ...,
    rtol: Optional[float] = ...,
    adhesion_steps: Optional[float] = ...,
    adhesion_points: Optional[float] = ...,
    adhesion_tol: Optional[float] = ...,
) -> None: ...
def evaluate(
    scene: SceneCore,
    sigma_points: int = ...,
    sigma_max: Optional[float] = ...,
    rtol: Optional[float] = ...,
    adhesion_steps: Optional[float] = ...,
    adhesion_points: Optional[float] = ...,
    adhesion_tol: Optional[float] = ...,
    progress: Progress = ...,
) -> Dict[str, Any]: ...
def sweep(
    scene: SceneCore, values: Sequence[float], over: str = ..., progress: Progress = ..., cycle: bool = ...
) -> Dict[str, Any]: ...
def cycle(scene: SceneCore, from_: float, to: float, points: int = ..., progress: Progress = ...) -> Dict[str, Any]: ...
def gfmd(
    scene: SceneCore,
    heights: Optional[npt.NDArray[np.float64]] = ...,
    size_m: Optional[float] = ...,
    grid: Optional[int] = ...,
    seed: int = ...,
    tolerance: float = ...,
    max_iterations: Optional[int] = ...,
    bins: Optional[int] = ...,
    method: str = ...,
    rescale: bool = ...,
    progress: Progress = ...,
) -> Dict[str, Any]: ...
def gfmd_cycle(
    scene: SceneCore,
    from_: float,
    to: float,
    points: int = ...,
    heights: Optional[npt.NDArray[np.float64]] = ...,
    size_m: Optional[float] = ...,
    grid: Optional[int] = ...,
    seed: int = ...,
    tolerance: float = ...,
    max_iterations: Optional[int] = ...,
    bins: Optional[int] = ...,
    method: str = ...,
    rescale: bool = ...,
    progress: Progress = ...,
    cycle: bool = ...,
) -> Dict[str, Any]: ...
def read_surface(path: Union[str, Any], size: Optional[float] = ..., height_unit: Optional[str] = ...) -> Dict[str, Any]: ...
def psd(
    heights: npt.NDArray[np.float64],
    size_m: float,
    periodic: bool = ...,
    bins_per_decade: float = ...,
    source: str = ...,
) -> Dict[str, Any]: ...
def _panic(where_: str) -> None: ...
def _sleep(seconds: float, progress: Progress = ...) -> float: ...
def gauge(
    scene: SceneCore,
    fit: str,
    reference: str = ...,
    reference_csv: Optional[str] = ...,
    from_: Optional[float] = ...,
    to: Optional[float] = ...,
    points: Optional[int] = ...,
    observables: Optional[List[str]] = ...,
    progress: Progress = ...,
) -> Dict[str, Any]: ...
def generate_surface(
    grid: int,
    size_m: float,
    hurst: float,
    rolloff_wavelength_m: Optional[float],
    short_wavelength_m: Optional[float],
    rms_gradient: Optional[float],
    rms_height_m: Optional[float],
    seed: int,
    periodic: bool,
) -> Dict[str, Any]: ...
def write_surface(heights: npt.NDArray[np.float64], size_m: float, path: str) -> None: ...
def allowed(key: str, name: str) -> Optional[Dict[str, Any]]: ...

ADHESION_RESOLUTION_MAX: float
