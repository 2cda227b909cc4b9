"""asperity: Persson's contact-mechanics theory of randomly rough, adhesive, elastic contacts
(as amended and gauged in Wang & Müser, "Gauging Persson theory on adhesion", Tribol. Lett. 65
(2017), cited [S-n] for its equation n), with slabs of finite thickness and the mean gap, and
a GFMD brute-force reference to check it against. numpy in and out.

Units: inputs in SI with the unit in the name (``contact_modulus_pa``, ``range_m``,
``surface_energy_j_m2``); stresses reduced by E*ḡ (p* = p/(E*ḡ), σ* = σ/(E*ḡ)); slab
thickness as t·q_r (``math.inf``: semi-infinite); gaps relative to h_rms where ``_rel``.

Example::

    import asperity
    scene = asperity.Scene.preset("system-2").replace(thickness_qr=0.5, pressure=0.005)
    r = asperity.evaluate(scene)
    print(r.a_r, r.mean_gap_rel, r.pr.sigma.shape)
    sw = asperity.sweep(scene, np.geomspace(1e-3, 0.1, 20))

Functions: :func:`evaluate`, :func:`sweep` (:func:`sweep_thickness`, :func:`sweep_gamma`),
:func:`cycle` (the theory's load cycle through tension to pull-off), :func:`gfmd`,
:func:`gfmd_cycle` (GFMD's), :func:`gfmd_sweep` (a one-way GFMD load sweep), :func:`psd`, :func:`read_surface`,
:func:`generate_surface`, :func:`gauge`. Errors (each an :class:`AsperityError`): :class:`InputError`
(a ValueError naming the argument, its value and the allowed range), :class:`NotConverged`,
:class:`InternalError`;
warnings :class:`UnitWarning` and :class:`ResolutionWarning`. See docs/python.md in the repository.
"""

from __future__ import annotations

from . import _api, _errors, _native, _results
from ._api import *  # noqa: F401,F403 (the functions, each in _api.__all__)
from ._errors import *  # noqa: F401,F403 (the exceptions and warnings)
from ._results import *  # noqa: F401,F403 (the result classes)
from ._scene import Scene, Surface

__version__: str = _native.__version__

__all__ = ["Scene", "Surface"]
__all__ += _api.__all__
__all__ += _results.__all__
__all__ += _errors.__all__
