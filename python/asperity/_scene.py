"""The scene: a validated set of inputs of Persson theory (asperity's ``Scene``).

Units are in the argument names: lengths in m (``system_size_m``, ``range_m``), E* in Pa
(``contact_modulus_pa``), γ_s in J/m² (``surface_energy_j_m2``). The load is reduced,
p* = p/(E*ḡ) (``pressure``), and the slab thickness is reduced by the roll-off wave number,
t·q_r (``thickness_qr``; ``math.inf`` or ``"inf"`` for a semi-infinite body) [S-4].
"""

from __future__ import annotations

import math
from typing import Any, Dict, Optional, Tuple, Union, overload

import numpy as np

import os

from . import _args as a
from . import _native
from ._errors import InputError

__all__ = ["Scene", "Surface", "as_map", "size_in_metres"]

Number = Union[int, float]
ModelArg = Union[int, str]


class Surface:
    """A height map: ``map`` (m, shape (n_y, n_x), rows along y) with x side ``size_m`` (m).

    It also reads as a SurfaceTopography ``Topography``: ``heights()`` has shape (n_x, n_y)
    (index [x, y]), ``physical_sizes`` is (L_x, L_y) and ``is_periodic`` says whether the map
    is periodic, so it goes wherever heights go. A generated map
    (:func:`asperity.generate_surface`) also has its ``rms_height_m`` and ``rms_gradient``
    (None for others).
    """

    def __init__(self, heights: Any, size_m: float, source: str = "heights", *, periodic: bool = False) -> None:
        self.map = np.ascontiguousarray(np.asarray(heights, dtype=float))
        if self.map.ndim == 1:
            self.map = self.map.reshape(1, -1)
        self.size_m = float(size_m)
        self.source = source
        self.periodic = bool(periodic)
        self.rms_height_m: Optional[float] = None
        self.rms_gradient: Optional[float] = None

    @property
    def is_periodic(self) -> bool:
        """Whether the map is periodic (a generated periodic map; SurfaceTopography's name)."""
        return self.periodic

    def write(self, path: Union[str, "os.PathLike[str]"]) -> None:
        """Writes the map (library ``asperity::surface::writers``) in the format of ``path``'s
        extension: .txt .asc .dat (a text matrix stating its side), .xyz, .npy, .gsf (f32);
        heights and lengths in m; every format :func:`asperity.read_surface` reads back."""
        if not isinstance(path, (str, os.PathLike)):
            raise a.refuse("output", path, "a file name ending in .txt, .asc, .dat, .xyz, .npy or .gsf")
        try:
            _native.write_surface(self.map, self.size_m, os.fspath(path))
        except InputError as e:
            # the library names the map; what is wrong is the file name given
            allowed = e.allowed or "a file name ending in .txt, .asc, .dat, .xyz, .npy or .gsf"
            raise a.refuse("output", os.fspath(path), allowed) from None

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


def size_in_metres(size: Any, unit_m: float = 1.0, name: str = "size") -> float:
    """A map's side given in a unit of ``unit_m`` metres, in m, in the CLI's ``--size`` range
    (1e-12 m <= size <= 1000 m)."""
    v = a.number(size, name) * unit_m
    r = _native.allowed("surface.system_size_m", name)
    if r is None or not (r["lo"] <= v <= r["hi"]):
        allowed = r["describe"] + " (in m)" if r else "a length > 0"
        raise a.refuse(name, size, allowed, "surface.system_size_m")
    return v


def as_map(heights: Any, size: Any, *, size_unit: float = 1.0) -> Tuple[np.ndarray, float, str, bool]:
    """(map (n_y, n_x) in m, x side in m, name, periodic) of a numpy array with ``size`` (in
    units of ``size_unit`` metres), or of anything with ``.heights()`` and ``.physical_sizes``
    (a SurfaceTopography Topography: heights indexed [x, y], its L_x unless ``size`` is given,
    its ``is_periodic`` where it has one). A masked array is refused: its mask would be
    ignored."""
    source = "heights"
    periodic = False
    if hasattr(heights, "heights") and callable(heights.heights) and hasattr(heights, "physical_sizes"):
        source = str(getattr(heights, "source", None) or type(heights).__name__)
        periodic = bool(getattr(heights, "is_periodic", False))
        sizes = heights.physical_sizes
        raw = heights.heights()
        if np.ma.isMaskedArray(raw):
            raise _masked()
        arr = _floats(raw)
        arr = arr.reshape(1, -1) if arr.ndim == 1 else arr.T
        if size is None:
            try:
                size = float(sizes[0]) if isinstance(sizes, (tuple, list, np.ndarray)) else float(sizes)
            except (TypeError, ValueError, IndexError):
                raise a.refuse("heights", heights, "physical_sizes of lengths in m") from None
    else:
        if np.ma.isMaskedArray(heights):
            raise _masked()
        arr = _floats(heights)
        if arr.ndim == 1:
            arr = arr.reshape(1, -1)
    if arr.ndim != 2:
        raise InputError(
            f"invalid heights = an array of shape {arr.shape}: allowed a 2-D array (rows along y)",
            field="heights",
            value=f"shape {arr.shape}",
            allowed="a 2-D array (rows along y)",
        )
    bad = np.argwhere(~np.isfinite(arr))
    if bad.size:
        i, j = (int(k) for k in bad[0])
        allowed = "finite heights (fill or cut out the missing points first)"
        raise InputError(
            f"invalid heights = {a.fmt_value(float(arr[i, j]))} at row {i}, column {j}: allowed {allowed}",
            field="heights",
            value=f"{a.fmt_value(float(arr[i, j]))} at row {i}, column {j}",
            allowed=allowed,
        )
    if size is None:
        raise InputError(
            "invalid size = None: allowed the map's x side in metres (or an object with physical_sizes)",
            field="size",
            value="None",
            allowed="the map's x side in metres",
        )
    return np.ascontiguousarray(arr), size_in_metres(size, size_unit), source, periodic


def _floats(heights: Any) -> np.ndarray:
    """``heights`` as an array of floats (real numbers only)."""
    allowed = "a 2-D array of real heights"
    if isinstance(heights, (str, bytes)) or np.iscomplexobj(heights):
        raise a.refuse("heights", heights, allowed)
    try:
        return np.asarray(heights, dtype=float)
    except (TypeError, ValueError, OverflowError):
        raise a.refuse("heights", type(heights).__name__, allowed) from None


def _masked() -> InputError:
    allowed = "a plain array (a mask is not honoured: fill it first, e.g. np.ma.filled(a, a.mean()))"
    return InputError(
        f"invalid heights = a masked array: allowed {allowed}", field="heights", value="a masked array", allowed=allowed
    )


#: The range-table key of each number a scene takes.
_KEYS = {
    "system_size_m": "surface.system_size_m",
    "rolloff_wavelength_m": "surface.rolloff_wavelength_m",
    "short_wavelength_m": "surface.short_wavelength_m",
    "hurst": "surface.hurst",
    "rms_gradient": "surface.rms_gradient",
    "rms_height_m": "surface.rms_height_m",
    "contact_modulus_pa": "material.contact_modulus_pa",
    "surface_energy_j_m2": "adhesion.surface_energy_j_m2",
    "range_m": "adhesion.range_m",
    "pressure": "load.pressure",
    "thickness_qr": "load.thickness_qr",
    "c1": "model.c1",
    "c2": "model.c2",
    "alpha": "model.alpha",
    "k_griffith": "model.k_griffith",
    "fudge_gamma": "model.fudge_gamma",
}


def _checked(fields: Dict[str, Any]) -> Dict[str, Any]:
    """The keyword arguments of a scene, each converted by the rule of :mod:`asperity._args`
    (numbers through the range table; ``thickness_qr`` may also be ``"inf"``; ``model`` a
    number or a name; ``cap`` a bool); unknown names pass to the extension, which raises
    ``TypeError`` naming them."""
    out: Dict[str, Any] = {}
    for k, v in fields.items():
        if k == "thickness_qr" and isinstance(v, str):
            out[k] = v
        elif k in _KEYS:
            out[k] = a.number(v, k, _KEYS[k])
        elif k == "cap":
            out[k] = a.flag(v, k)
        elif k == "model":
            if isinstance(v, (bool, np.bool_)) or not isinstance(v, (str, int, np.integer)):
                raise a.refuse(k, v, "1, 2, 3, 4, 5, custom, yp08 or xu24")
            out[k] = v if isinstance(v, str) else int(v)
        else:
            out[k] = v
    return out


#: The fields of :meth:`Scene.replace` that rebuild the self-affine spectrum.
_SURFACE_FIELDS = ("system_size_m", "rolloff_wavelength_m", "short_wavelength_m", "hurst", "rms_gradient", "rms_height_m")


class _Input:
    """A read-only number of :class:`Scene`: its input of the attribute's name (a key of
    :meth:`Scene.fields`), as a float."""

    def __init__(self, doc: str) -> None:
        self.__doc__ = doc
        self.name = ""

    def __set_name__(self, owner: type, name: str) -> None:
        self.name = name

    @overload
    def __get__(self, scene: None, owner: type) -> "_Input": ...

    @overload
    def __get__(self, scene: "Scene", owner: type) -> float: ...

    def __get__(self, scene: Optional["Scene"], owner: type) -> Union["_Input", float]:
        return self if scene is None else float(scene.fields()[self.name])

    def __set__(self, scene: "Scene", value: Any) -> None:
        raise AttributeError(f"Scene.{self.name} is read-only: use replace({self.name}=...)")


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
        self._core = _native.scene_new(_checked(fields))

    @classmethod
    def _of(cls, core: "_native.SceneCore") -> "Scene":
        s = cls.__new__(cls)
        s._core = core
        return s

    @classmethod
    def preset(cls, name_or_path: Union[str, "os.PathLike[str]"]) -> "Scene":
        """The scene of a preset: a built-in name (``"system-1"``: the adhesionless
        contact-mechanics challenge; ``"system-2"``: the adhesive thin-slab system of [S] Figs.
        7-8), ``presets/NAME.toml`` under the working directory, or a TOML file's path.

        An explorer export reopens as the panel showed it, as ``asperity run --preset`` reads
        it: ``[load] branch = "unloading"`` makes :func:`asperity.evaluate` report the
        unloading branch inside a hysteresis window, and a ``[measured]`` section puts the scene
        on that map's PSD (its ``size_m``, ``height_unit``, ``periodic``, q range) or PSD
        table, so :func:`asperity.gfmd` runs on the map."""
        if not isinstance(name_or_path, (str, os.PathLike)):
            raise a.refuse("name_or_path", name_or_path, "a preset name or a TOML file's path")
        return cls._of(_native.scene_from_preset(os.fspath(name_or_path)))

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
        surface = [k for k in _SURFACE_FIELDS if k in fields]
        if surface and self._core.fields().get("spectrum") == "tabulated":
            k = surface[0]
            allowed = (
                "no surface field on a scene with a measured PSD (it would be dropped): to keep the measured "
                "surface leave the surface fields out; for a self-affine surface start from Scene.preset(...) "
                "or Scene(...) instead"
            )
            raise InputError(
                f"invalid {k} = {a.shown(fields[k])}: allowed {allowed}",
                field=k,
                value=a.shown(fields[k]),
                allowed=allowed,
            )
        return Scene._of(self._core.replace(_checked(fields)))

    def with_surface(
        self,
        heights: Any,
        size: Optional[float] = None,
        *,
        periodic: Optional[bool] = None,
        qmin: Optional[float] = None,
        qmax: Optional[float] = None,
    ) -> "Scene":
        """A copy whose spectrum is a measured map's PSD (the radial average [S-2], as
        ``--surface FILE`` gives it; a plane fit and a Hann window unless ``periodic``), cut to
        [qmin, qmax] (1/m). ``heights``: a 2-D array (m, rows along y) with ``size`` its x side
        in m, or a Topography-like object (its ``is_periodic`` unless ``periodic`` is given).
        :func:`asperity.gfmd` then runs on this map."""
        arr, l, source, topo_periodic = as_map(heights, size)
        per = topo_periodic if periodic is None else a.flag(periodic, "periodic")
        q_lo = None if qmin is None else a.number(qmin, "qmin", allowed="a wave number > 0 in 1/m")
        q_hi = None if qmax is None else a.number(qmax, "qmax", allowed="a wave number > 0 in 1/m")
        return Scene._of(self._core.with_map(arr, l, per, q_lo, q_hi, source))

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

    pressure = _Input("p* = p/(E*ḡ).")
    thickness_qr = _Input("t·q_r (``math.inf``: semi-infinite).")
    surface_energy_j_m2 = _Input("γ_s in J/m² (0: no adhesion).")
    range_m = _Input("ρ, the range of the adhesive interaction, in m.")
    contact_modulus_pa = _Input("E* = E/(1 − ν²) in Pa.")

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
