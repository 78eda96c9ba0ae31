"""Re-export an RGB-D sequence folder (``write_rgbd_sequence``) the ways phone apps vary it:
JPG colour, depth smaller than colour, one ``rgb.mp4``, confidence maps, ``.npy`` metres, and
odometry far from the origin (ARKit/georeferenced coordinates)."""

from __future__ import annotations

from pathlib import Path

import numpy as np


def restyle_sequence(folder: Path, jpg: bool = False, depth_size: tuple[int, int] | None = None, mp4: bool = False,
                     confidence: bool = False, npy: bool = False, offset_m: tuple[float, float, float] | None = None) -> np.ndarray:
    """Rewrite ``folder`` in place; returns the 4x4 taking the new odometry world to the old one
    (identity unless ``offset_m`` moved the origin). ``depth_size`` is (width, height)."""
    from PIL import Image

    folder = Path(folder)
    rgb_files = sorted((folder / "rgb").glob("*.png"))
    depth_files = sorted((folder / "depth").glob("*.png"))
    if confidence:
        (folder / "confidence").mkdir(exist_ok=True)
    for p in depth_files:
        mm = np.asarray(Image.open(p))
        if depth_size is not None:
            mm = np.asarray(Image.fromarray(mm).resize(depth_size, Image.NEAREST))
        if confidence:  # ARKit: 2 where depth is sure, 0 at depth edges (dropped)
            edge = np.zeros(mm.shape, bool)
            d = mm.astype(np.float64)
            edge[:, 1:] |= np.abs(np.diff(d, axis=1)) > 50
            edge[1:] |= np.abs(np.diff(d, axis=0)) > 50
            Image.fromarray(np.where(edge, 0, 2).astype(np.uint8)).save(folder / "confidence" / p.name)
        if npy:
            np.save(p.with_suffix(".npy"), np.where(mm > 0, mm / 1000.0, 0.0).astype(np.float32))
            p.unlink()
        else:
            Image.fromarray(mm).save(p)
    if mp4:
        import imageio.v3 as iio

        frames = np.stack([np.asarray(Image.open(p))[..., :3] for p in rgb_files])
        iio.imwrite(folder / "rgb.mp4", frames, fps=30, codec="libx265", quality=9)  # HEVC, as Stray Scanner writes
        for p in rgb_files:
            p.unlink()
        (folder / "rgb").rmdir()
    elif jpg:
        for p in rgb_files:
            Image.open(p).convert("RGB").save(p.with_suffix(".jpg"), quality=90)
            p.unlink()
    back = np.eye(4)
    if offset_m is not None:
        odo = folder / "odometry.csv"
        lines = odo.read_text().splitlines()
        rows = [lines[0]]
        for ln in lines[1:]:
            v = [s.strip() for s in ln.split(",")]
            v[2:5] = [f"{float(v[2 + i]) + offset_m[i]:.6f}" for i in range(3)]
            rows.append(", ".join(v))
        odo.write_text("\n".join(rows) + "\n")
        back[:3, 3] = -np.asarray(offset_m, dtype=np.float64)
    return back
