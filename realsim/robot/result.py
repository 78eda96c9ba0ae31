"""What a primitive returns, and the two ways a primitive's body stops early."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

__all__ = ["ActionResult", "BudgetExceeded", "PlanFailure"]


@dataclass
class ActionResult:
    """What a primitive did: success, why, and the measured values."""

    primitive: str
    success: bool
    reason: str
    sim_time: float = 0.0
    attempts: int = 0
    values: dict[str, Any] = field(default_factory=dict)


class BudgetExceeded(Exception):
    """The primitive's simulated-time budget ran out."""


class PlanFailure(Exception):
    """A motion could not be planned or carried out; the message says why."""
