"""Epsilon-greedy search over grasp parameters for retries.

The parameters are an approach tilt (rad, about the closing axis), a height offset (m) and a
yaw offset (rad, about the approach axis). The first proposal is the nominal grasp (all zero);
after that, with probability epsilon (decaying by ``decay`` per attempt) a random perturbation of
the best parameters so far is explored, otherwise the best parameters are exploited with a small
jitter. Seeded: the same seed and rewards give the same proposals.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


@dataclass(frozen=True)
class GraspParams:
    """Perturbations of a grasp tried after a failed attempt: hand tilt, height and yaw offsets, which candidate."""

    tilt: float = 0.0
    height_offset: float = 0.0
    yaw_offset: float = 0.0
    candidate: int = 0  # index into the ranked candidate list


@dataclass
class EpsilonGreedy:
    """Seeded epsilon-greedy search over grasp perturbations: explore with a decaying probability, else refine the best so far."""

    seed: int = 0
    epsilon: float = 0.6
    decay: float = 0.6
    n_candidates: int = 1
    tilt_range: float = 0.35
    height_range: tuple[float, float] = (-0.012, 0.02)
    yaw_range: float = 0.4
    history: list[tuple[GraspParams, float]] = field(default_factory=list)

    def __post_init__(self) -> None:
        self.rng = np.random.default_rng(self.seed)

    @property
    def best(self) -> tuple[GraspParams, float] | None:
        if not self.history:
            return None
        return max(self.history, key=lambda h: h[1])  # first best kept on ties

    def propose(self) -> GraspParams:
        if not self.history:
            return GraspParams()
        best, _ = self.best  # type: ignore[misc]
        eps = self.epsilon * self.decay ** (len(self.history) - 1)
        r = self.rng
        if r.random() < eps:
            cand = int(r.integers(0, max(self.n_candidates, 1)))
            return GraspParams(
                tilt=float(r.uniform(-self.tilt_range, self.tilt_range)),
                height_offset=float(r.uniform(*self.height_range)),
                yaw_offset=float(r.uniform(-self.yaw_range, self.yaw_range)),
                candidate=cand,
            )
        tried = {h[0].candidate for h in self.history}
        untried = [c for c in range(self.n_candidates) if c not in tried]
        if untried and self.best[1] <= 0.0:  # type: ignore[index]
            return GraspParams(candidate=untried[0])
        return GraspParams(
            tilt=best.tilt + float(r.normal(0, 0.05)),
            height_offset=float(np.clip(best.height_offset + r.normal(0, 0.004), *self.height_range)),
            yaw_offset=best.yaw_offset + float(r.normal(0, 0.08)),
            candidate=best.candidate,
        )

    def update(self, params: GraspParams, reward: float) -> None:
        self.history.append((params, float(reward)))
