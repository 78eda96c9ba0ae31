"""Mapping physical quantities to MuJoCo contact parameters."""

from __future__ import annotations

import math


def damping_ratio_from_restitution(e: float) -> float:
    """Damping ratio of a linear spring-damper contact with coefficient of restitution ``e``.

    For an underdamped oscillator the rebound ratio is ``exp(-zeta*pi/sqrt(1-zeta^2))``; solving
    for zeta gives ``-ln e / sqrt(pi^2 + ln^2 e)``. ``e <= 0`` -> critically damped (1.0).
    """
    if e <= 1e-3:
        return 1.0
    e = min(e, 0.95)
    ln = math.log(e)
    return max(0.1, min(1.0, -ln / math.sqrt(math.pi**2 + ln**2)))


def solref_from_restitution(e: float, timeconst: float = 0.02) -> tuple[float, float]:
    """MuJoCo ``solref`` (timeconst, dampratio) for restitution ``e``."""
    return (float(timeconst), float(round(damping_ratio_from_restitution(e), 4)))
