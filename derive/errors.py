"""One exception tree for derive: every error a user can cause says where and what.

The CLI catches :class:`DeriveError`, prints ``Error: <message>`` on one line and
exits with :attr:`DeriveError.exit_code` (2 for bad input or usage, 1 otherwise).
"""

from __future__ import annotations


class DeriveError(Exception):
    """Base of every error derive raises on purpose."""

    exit_code = 2

    def __init__(self, message: str) -> None:
        super().__init__(message)
        self.message = message

    def __str__(self) -> str:
        return self.message


class InputError(DeriveError):
    """Bad input: a problem file, an answer or a command-line value.

    ``where`` names the file (and line, where known) and ``field`` the key, so the
    message reads ``problems/x.toml:7: [given] e = 1.3: <what was expected>``.
    """

    def __init__(self, what: str, *, where: str | None = None, field: str | None = None) -> None:
        parts = [p for p in (where, field) if p]
        super().__init__(": ".join([*parts, what]))
        self.where = where
        self.field = field
        self.what = what


class ExpressionError(InputError):
    """An expression that the restricted grammar does not admit."""


class UnitError(InputError):
    """An unknown unit, or a unit of the wrong kind for its field."""


class PhysicsError(InputError):
    """Givens that describe no impact: no approach, e outside [0, 1], and so on."""


class SolveError(InputError):
    """Unknowns that equations (1)-(4) do not determine, or determine twice over."""


class RenderError(DeriveError):
    """A failure while writing output (TeX missing, TeX error, a file not written)."""

    exit_code = 1
