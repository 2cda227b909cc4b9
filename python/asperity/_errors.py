"""The exceptions of asperity: the library's typed errors, raised by every function. Each is an
:class:`AsperityError` (``except asperity.AsperityError`` catches them all) and the standard
exception it stands for:

- :class:`InputError` (a :class:`ValueError`): bad input, raised before any work starts. It
  names the argument (``.field``, the keyword of :class:`asperity.Scene` or of the function),
  the value as given (``.value``) and what is allowed (``.allowed``, in words), e.g.
  ``invalid thickness_qr = -1: allowed 1e-6 <= thickness_qr <= 1e12, or inf``.
- :class:`NotConverged` (a :class:`RuntimeError`): a solver missed its tolerance; ``.solver``
  names it and ``.reason`` gives the numbers.
- :class:`InternalError` (a :class:`RuntimeError`): a bug (a Rust panic); please report it.

Warnings (``warnings.warn``, one line each; filter them by category):

- :class:`UnitWarning`: a map's h_rms or ḡ lies outside any physical range for the units
  stated (heights in nm passed as m, a side in µm passed as m);
- :class:`ResolutionWarning`: adhesive GFMD on a grid that under-resolves the attraction
  ((γ_s/E*)·Δa/ρ² above 0.25), the CLI's note.

Both are :class:`AsperityWarning` (a ``UserWarning``).

A computation interrupted with Ctrl-C raises :class:`KeyboardInterrupt`; an exception raised by
a ``progress`` callback stops the computation and propagates unchanged.
"""

from __future__ import annotations

from typing import Optional

__all__ = ["AsperityError", "InputError", "NotConverged", "InternalError", "AsperityWarning", "UnitWarning", "ResolutionWarning"]


class AsperityError(Exception):
    """The base of every error asperity raises."""


class InputError(AsperityError, ValueError):
    """Bad input: ``field`` (the argument's name), ``value`` (as given), ``allowed`` (in words).

    ``key`` is the library's canonical key of the field (the preset's dotted path, e.g.
    ``load.thickness_qr``). Fields are None where the error concerns a combination (e.g. a
    model of the literature on an adhesive scene).
    """

    def __init__(
        self,
        message: str,
        field: Optional[str] = None,
        value: Optional[str] = None,
        allowed: Optional[str] = None,
        key: Optional[str] = None,
    ) -> None:
        super().__init__(message)
        self.field = field
        self.value = value
        self.allowed = allowed
        self.key = key


class NotConverged(AsperityError, RuntimeError):
    """A numerical method did not reach its tolerance: ``solver`` and ``reason``."""

    def __init__(self, message: str, solver: Optional[str] = None, reason: Optional[str] = None) -> None:
        super().__init__(message)
        self.solver = solver
        self.reason = reason


class InternalError(AsperityError, RuntimeError):
    """A Rust panic inside asperity (a bug), with its message."""


class AsperityWarning(UserWarning):
    """The base of asperity's warnings."""


class UnitWarning(AsperityWarning):
    """A map's h_rms or ḡ outside any physical range for the units stated: most likely the
    heights or the side are in another unit (``height_unit``, ``size_unit``)."""


class ResolutionWarning(AsperityWarning):
    """Adhesive GFMD on a grid too coarse for the attraction's range ((γ_s/E*)·Δa/ρ² above the
    library's limit): the contact area is then too large; refine the grid."""
