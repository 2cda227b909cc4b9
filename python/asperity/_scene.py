"""The scene: a validated set of inputs of Persson theory (asperity's ``Scene``).

Units are in the argument names: lengths in m (``system_size_m``, ``range_m``), E* in Pa
(``contact_modulus_pa``), γ_s in J/m² (``surface_energy_j_m2``). The load is reduced,
p* = p/(E*ḡ) (``pressure``), and the slab thickness is reduced by the roll-off wave number,
t·q_r (``thickness_qr``; ``math.inf`` or ``"inf"`` for a semi-infinite body) [S-4].
"""

from __future__ import annotations

import math
from typing import Any, Dict, Optional, Tuple, Union

import numpy as np

from . import _native
from ._errors import InputError

__all__ = ["Scene", "Surface", "as_map"]

Number = Union[int, float]
ModelArg = Union[int, str]


class Surface:
    """A height map: ``map`` (m, shape (n_y, n_x), rows along y) with x side ``size_m`` (m).

    It also reads as a SurfaceTopography ``Topography``: ``heights()`` has shape (n_x, n_y)
    (index [x, y]) and ``physical_sizes`` is (L_x, L_y), so it goes wherever heights go.
    """

    def __init__(self, heights: Any, size_m: float, source: str = "heights") -> None:
        self.map = np.ascontiguousarray(np.asarray(heights, dtype=float))
        if self.map.ndim == 1:
            self.map = self.map.reshape(1, -1)
        self.size_m = float(size_m)
        self.source = source

    def heights(self) -> np.ndarray:
        """Heights in m indexed [x, y] (the SurfaceTopography convention)."""
        return self.map.T

    @property
    def physical_sizes(self) -> Tuple[float, float]:
        """(L_x, L_y) in m."""
        ny, nx = self.map.shape
        return (self.size_m, self.size_m * ny / nx)

    @property
    def spacing_m(self) -> float:
        """Δa = L_x/n_x (m)."""
        return self.size_m / int(self.map.shape[1])

    def __repr__(self) -> str:
        ny, nx = self.map.shape
        return f"Surface({nx} x {ny}, L = {self.size_m:.4g} m, source={self.source!r})"


def as_map(heights: Any, size: Optional[float]) -> Tuple[np.ndarray, float, str]:
    """(map (n_y, n_x) in m, x side in m, name) of a numpy array with ``size``, or of anything
    with ``.heights()`` and ``.physical_sizes`` (a SurfaceTopography Topography: heights
    indexed [x, y], its L_x unless ``size`` is given)."""
    source = "heights"
    if hasattr(heights, "heights") and callable(heights.heights) and hasattr(heights, "physical_sizes"):
        source = str(getattr(heights, "source", None) or type(heights).__name__)
        sizes = heights.physical_sizes
        arr = np.asarray(heights.heights(), dtype=float)
        arr = arr.reshape(1, -1) if arr.ndim == 1 else arr.T
        if size is None:
            size = float(sizes[0]) if isinstance(sizes, (tuple, list, np.ndarray)) else float(sizes)
    else:
        try:
            arr = np.asarray(heights, dtype=float)
        except (TypeError, ValueError):
            raise InputError(
                f"invalid heights = {type(heights).__name__}: allowed a 2-D array of heights in m",
                field="heights",
                value=type(heights).__name__,
                allowed="a 2-D array of heights in m",
            ) from None
        if arr.ndim == 1:
            arr = arr.reshape(1, -1)
    if arr.ndim != 2:
        raise InputError(
            f"invalid heights = an array of shape {arr.shape}: allowed a 2-D array (rows along y)",
            field="heights",
            value=f"shape {arr.shape}",
            allowed="a 2-D array (rows along y)",
        )
    if size is None:
        raise InputError(
            "invalid size = None: allowed the map's x side in metres (or an object with physical_sizes)",
            field="size",
            value="None",
            allowed="the map's x side in metres",
        )
    return np.ascontiguousarray(arr), float(size), source


class Scene:
    """A validated scene: the surface's spectrum, the material, adhesion, load, thickness and
    model of Persson theory with adhesion (Wang & Müser 2017, [S]).

    Build one from a preset (``Scene.preset("system-2")``) or from keywords::

        Scene(system_size_m=25.6e-6, rolloff_wavelength_m=12.8e-6, short_wavelength_m=0.1e-6,
              hurst=0.8, rms_gradient=1.0, contact_modulus_pa=25e6,
              surface_energy_j_m2=0.157, range_m=14.2e-9, pressure=0.005, thickness_qr=1.0,
              model=4)

    Self-affine spectrum C(q) ∝ q^(−2−2H) between q_r = 2π/λ_r and q_s = 2π/λ_s, flat
    (roll-off) from q_L = 2π/L to q_r [S-2], normalised by ``rms_gradient`` ḡ or by
    ``rms_height_m``; ``model`` 1-4 of [S-17] (W(a) = 1 − c₁(1 − a²) − c₂(1 − a⁴)), 5 (W(0)
    from the scene's γ̃_glo, gauged on asperity's GFMD set: docs/physics.md §3.6),
    ``"custom"`` with ``c1``, ``c2``, ``alpha`` (broadening ∝ W^α [S-15]), ``k_griffith``
    [S-8] and ``cap`` (σ_a ≤ γ_s/ρ), or ``"yp08"``/``"xu24"`` with ``fudge_gamma``.

    Every value is checked on construction: :class:`asperity.InputError` names the argument,
    its value and the allowed range. A scene never changes; :meth:`replace` returns a
    validated copy.
    """

    __slots__ = ("_core",)

    def __init__(
        self,
        *,
        system_size_m: float,
        rolloff_wavelength_m: float,
        short_wavelength_m: float,
        hurst: float,
        contact_modulus_pa: float,
        rms_gradient: Optional[float] = None,
        rms_height_m: Optional[float] = None,
        surface_energy_j_m2: float = 0.0,
        range_m: float = 1e-9,
        pressure: float = 0.01,
        thickness_qr: Union[float, str] = math.inf,
        model: ModelArg = 3,
        c1: Optional[float] = None,
        c2: Optional[float] = None,
        alpha: Optional[float] = None,
        k_griffith: Optional[float] = None,
        cap: Optional[bool] = None,
        fudge_gamma: Optional[float] = None,
    ) -> None:
        fields = {k: v for k, v in locals().items() if k not in ("self", "__class__") and v is not None}
        self._core = _native.scene_new(fields)

    @classmethod
    def _of(cls, core: "_native.SceneCore") -> "Scene":
        s = cls.__new__(cls)
        s._core = core
        return s

    @classmethod
    def preset(cls, name_or_path: str) -> "Scene":
        """The scene of a preset: a built-in name (``"system-1"``: the adhesionless
        contact-mechanics challenge; ``"system-2"``: the adhesive thin-slab system of [S] Figs.
        7-8), ``presets/NAME.toml`` under the working directory, or a TOML file's path."""
        return cls._of(_native.scene_from_preset(str(name_or_path)))

    def replace(
        self,
        *,
        pressure: Optional[float] = None,
        thickness_qr: Union[float, str, None] = None,
        surface_energy_j_m2: Optional[float] = None,
        range_m: Optional[float] = None,
        contact_modulus_pa: Optional[float] = None,
        model: Optional[ModelArg] = None,
        c1: Optional[float] = None,
        c2: Optional[float] = None,
        alpha: Optional[float] = None,
        k_griffith: Optional[float] = None,
        cap: Optional[bool] = None,
        fudge_gamma: Optional[float] = None,
        system_size_m: Optional[float] = None,
        rolloff_wavelength_m: Optional[float] = None,
        short_wavelength_m: Optional[float] = None,
        hurst: Optional[float] = None,
        rms_gradient: Optional[float] = None,
        rms_height_m: Optional[float] = None,
    ) -> "Scene":
        """A validated copy with the given inputs changed (None keeps one), as the CLI's
        flags change a preset: ``model="custom"`` keeps the current coefficients, ``c1`` ..
        ``cap`` imply a custom model, surface fields rebuild the self-affine spectrum.

        Raises :class:`asperity.InputError` naming the first value out of its range."""
        fields = {k: v for k, v in locals().items() if k not in ("self", "__class__") and v is not None}
        return Scene._of(self._core.replace(fields))

    def with_surface(
        self,
        heights: Any,
        size: Optional[float] = None,
        *,
        periodic: bool = False,
        qmin: Optional[float] = None,
        qmax: Optional[float] = None,
    ) -> "Scene":
        """A copy whose spectrum is a measured map's PSD (the radial average [S-2], as
        ``--surface FILE`` gives it; a plane fit and a Hann window unless ``periodic``), cut to
        [qmin, qmax] (1/m). ``heights``: a 2-D array (m, rows along y) with ``size`` its x side
        in m, or a Topography-like object. :func:`asperity.gfmd` then runs on this map."""
        arr, l, source = as_map(heights, size)
        return Scene._of(self._core.with_map(arr, l, periodic, qmin, qmax, source))

    def summary(self) -> Dict[str, Any]:
        """The resolved inputs: the ``scene`` object of ``asperity run --format json``
        (p*, p in Pa, t·q_r, t in m, γ_s, ρ, γ̃_glo [S-24], Tabor μ_T, E*, ḡ, h_rms, q_L, q_r,
        q_s, the model's coefficients) and ``preset``."""
        return self._core.summary()

    def fields(self) -> Dict[str, Any]:
        """The inputs under the names :class:`Scene` and :meth:`replace` take."""
        return self._core.fields()

    @property
    def preset_name(self) -> str:
        """The preset's name ("custom" for a scene built from keywords)."""
        return self._core.preset_name

    @property
    def pressure(self) -> float:
        """p* = p/(E*ḡ)."""
        return float(self.fields()["pressure"])

    @property
    def thickness_qr(self) -> float:
        """t·q_r (``math.inf``: semi-infinite)."""
        return float(self.fields()["thickness_qr"])

    @property
    def surface_energy_j_m2(self) -> float:
        """γ_s in J/m² (0: no adhesion)."""
        return float(self.fields()["surface_energy_j_m2"])

    @property
    def range_m(self) -> float:
        """ρ, the range of the adhesive interaction, in m."""
        return float(self.fields()["range_m"])

    @property
    def contact_modulus_pa(self) -> float:
        """E* = E/(1 − ν²) in Pa."""
        return float(self.fields()["contact_modulus_pa"])

    @property
    def model(self) -> str:
        """"1".."5", "custom", "yp08" or "xu24"."""
        return str(self.fields()["model"])

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Scene) and bool(self._core == other._core)

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        f = self.fields()
        return (
            f"Scene(preset={self.preset_name!r}, model={f['model']}, pressure={f['pressure']:.6g}, "
            f"thickness_qr={f['thickness_qr']}, surface_energy_j_m2={f['surface_energy_j_m2']}, "
            f"spectrum={f['spectrum']!r})"
        )
