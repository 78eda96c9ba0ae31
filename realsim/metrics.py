"""Quality measures against ground truth: plane error and Hungarian-matched point IoU."""

from __future__ import annotations

import numpy as np
from scipy.optimize import linear_sum_assignment

from realsim.geometry import fit_plane


def plane_error(gt_points: np.ndarray, normal: np.ndarray, height: float) -> tuple[float, float]:
    """(mean distance of ``gt_points`` to the plane z-normal form, angle to their own fit in degrees).

    The plane is ``normal . x = normal_z * height`` (a support at ``height``).
    """
    dist = np.abs(gt_points @ normal - normal[2] * height)
    gt_normal, _ = fit_plane(gt_points)
    angle = float(np.degrees(np.arccos(np.clip(abs(gt_normal @ normal), -1.0, 1.0))))
    return float(dist.mean()), angle


def matched_iou(pred: np.ndarray, gt: np.ndarray) -> tuple[np.ndarray, list[tuple[int, int]]]:
    """IoU per ground-truth object (ids > 0 in ``gt``), Hungarian-matched to predicted ids > 0.

    Unmatched ground-truth objects get IoU 0. Returns the IoUs (in sorted gt-id order) and the
    matched (gt id, predicted id) pairs.
    """
    gt_ids = np.unique(gt[gt > 0])
    pred_ids = np.unique(pred[pred > 0])
    if len(gt_ids) == 0:
        return np.zeros(0), []
    both = (gt > 0) & (pred > 0)
    gi = np.searchsorted(gt_ids, gt[both])
    pj = np.searchsorted(pred_ids, pred[both])
    inter = np.zeros((len(gt_ids), max(len(pred_ids), 1)))
    np.add.at(inter, (gi, pj), 1)
    gt_sizes = np.array([(gt == g).sum() for g in gt_ids])
    pred_sizes = np.array([(pred == p).sum() for p in pred_ids]) if len(pred_ids) else np.zeros(1)
    union = gt_sizes[:, None] + pred_sizes[None, :] - inter
    iou = np.where(union > 0, inter / np.maximum(union, 1), 0.0)
    rows, cols = linear_sum_assignment(-iou)
    per_gt = np.zeros(len(gt_ids))
    pairs = []
    for r, c in zip(rows, cols):
        if len(pred_ids) and iou[r, c] > 0:
            per_gt[r] = iou[r, c]
            pairs.append((int(gt_ids[r]), int(pred_ids[c])))
    return per_gt, pairs


def mosd_object_ids(labels: np.ndarray) -> np.ndarray:
    """mOSD ground truth to object ids: label // 10 for labels >= 20, else 0."""
    return np.where(labels >= 20, labels // 10, 0)
