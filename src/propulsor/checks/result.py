"""The check type of the checks layer: :class:`propulsor.check.Check` (one type everywhere)."""

from ..check import Check, all_passed, failures

__all__ = ["Check", "all_passed", "failures"]
