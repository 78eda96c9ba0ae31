"""RGB-D frame sequences (phone scanner exports) fused into one coloured mesh with Open3D's TSDF.

The accepted layout is Stray Scanner's (iPhone/iPad LiDAR), a folder holding::

    rgb/000000.png ...        colour frames (PNG or JPG), or instead one video ``rgb.mp4`` (any
                              codec ffmpeg reads; its i-th decoded picture is frame i)
    depth/000000.png ...      depth, uint16 millimetres, 0 = no depth (or ``.npy`` float metres);
                              may be smaller than the colour frames (e.g. 256x192)
    camera_matrix.csv         3x3 intrinsics of the colour frames, comma separated, one row a line
    odometry.csv              header line, then per frame: timestamp, frame, x, y, z, qx, qy, qz, qw
                              (camera-to-world; ARKit camera axes x right, y up, z backward;
                              world gravity-aligned, Y up, metres)
    confidence/000000.png     optional, ARKit depth confidence 0/1/2; pixels below 1 are dropped

Frames are matched by number (a video's frames by their order, decoded one at a time, so a
long 1920x1440 recording is never held in memory); depth beyond ``max_depth`` is dropped. The frames are fused into
a truncated signed distance field, at a voxel the size of the rays' spacing on the surface (the
frames' own resolution), and its zero level is the capture's surface, in the poses'
frame (Y up, metres), so the load stage knows units and up without detection.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from realsim.errors import InputError
from realsim.perception.unique_keys import unique_inverse

_ARKIT_TO_OPTICAL = np.diag([1.0, -1.0, -1.0, 1.0])


RAYS_ACROSS = 240  # rays cast across a frame's shorter side (about 320 x 240 a frame)


@dataclass(frozen=True)
class FusionParams:
    """TSDF fusion settings (metres)."""

    voxel: float | None = None  # TSDF voxel; None: the spacing of the rays on the surface (:func:`ray_spacing`)
    trunc_voxels: float = 3.0  # truncation distance, in voxels
    max_depth: float = 3.0
    min_confidence: int = 1


def _stride(h: int, w: int) -> int:
    """Pixel step between the rays cast in a (h, w) depth frame."""
    return max(1, int(round(min(h, w) / RAYS_ACROSS)))


def ray_spacing(depth: np.ndarray, focal: float) -> float:
    """Distance (m) between neighbouring rays of a depth frame where they meet the surface: its
    median depth times the ray step over the focal length (pixels); NaN for a frame without depth.
    A TSDF voxel this size holds about one ray's sample: the fused surface is as fine as the frames
    see it (the crease between two touching objects stays a crease), never finer."""
    seen = depth[depth > 0]
    return float(np.median(seen)) * _stride(*depth.shape) / focal if len(seen) else float("nan")


def is_rgbd_sequence(folder: Path) -> bool:
    """True for a folder in the layout above."""
    folder = Path(folder)
    return (folder.is_dir() and (folder / "depth").is_dir() and (folder / "odometry.csv").is_file()
            and (folder / "camera_matrix.csv").is_file() and ((folder / "rgb").is_dir() or (folder / "rgb.mp4").is_file()))


def _read_csv_rows(path: Path, skip_header: bool) -> np.ndarray:
    try:
        lines = [ln for ln in path.read_text().splitlines() if ln.strip()]
        rows = [[float(v) for v in ln.replace(",", " ").split()] for ln in lines[1 if skip_header else 0:]]
        return np.asarray(rows, dtype=np.float64)
    except ValueError as exc:
        raise InputError(f"{path}: not a comma-separated table of numbers ({exc})") from None


def read_poses(folder: Path) -> dict[int, np.ndarray]:
    """Frame number -> 4x4 optical camera (x right, y down, z forward) to world."""
    from scipy.spatial.transform import Rotation

    rows = _read_csv_rows(folder / "odometry.csv", skip_header=True)
    if rows.ndim != 2 or rows.shape[1] < 9:
        raise InputError(f"{folder / 'odometry.csv'}: expected columns timestamp, frame, x, y, z, qx, qy, qz, qw")
    poses = {}
    for r in rows:
        t = np.eye(4)
        t[:3, :3] = Rotation.from_quat(r[5:9]).as_matrix()
        t[:3, 3] = r[2:5]
        poses[int(r[1])] = t @ _ARKIT_TO_OPTICAL
    return poses


def _frames(folder: Path, sub: str, suffixes: tuple[str, ...]) -> dict[int, Path]:
    out = {}
    for p in sorted((folder / sub).glob("*")):
        if p.suffix.lower() in suffixes and p.stem.isdigit():
            out[int(p.stem)] = p
    return out


class _VideoFrames:
    """The pictures of a colour video by number, decoded in order as they are asked for (a frame
    is asked for once, in increasing order); the frame numbers are the depth frames' until the
    video ends (a video's frame count is only known once decoded)."""

    def __init__(self, path: Path, numbers: list[int]) -> None:
        import imageio.v3 as iio

        self.path = path
        self.numbers = set(numbers)
        self._pictures = enumerate(iio.imiter(path))  # a generator: the file is opened on the first frame
        self.decoded = 0

    def __contains__(self, i: object) -> bool:
        return i in self.numbers

    def __iter__(self) -> Iterator[int]:
        return iter(sorted(self.numbers))

    def __len__(self) -> int:
        return len(self.numbers)

    def __getitem__(self, i: int) -> np.ndarray | None:
        """Frame ``i`` (H, W, 3), or None when the video ends before it."""
        try:
            for k, picture in self._pictures:
                self.decoded = k + 1
                if k == i:
                    return np.asarray(picture)
        except (OSError, RuntimeError) as exc:  # imageio-ffmpeg: "Could not load meta information", or a stream cut short
            where = f"breaks off after frame {self.decoded - 1}" if self.decoded else "cannot be read"
            raise InputError(f"{self.path}: the colour video {where} ({str(exc).splitlines()[0][:80]}); re-export it") from None
        return None


def _color_frames(folder: Path, depth_numbers: list[int]) -> dict[int, Path] | _VideoFrames:
    if (folder / "rgb").is_dir():
        return _frames(folder, "rgb", (".png", ".jpg", ".jpeg"))
    return _VideoFrames(folder / "rgb.mp4", depth_numbers)


def _image(p: Path | np.ndarray) -> np.ndarray:
    if isinstance(p, np.ndarray):
        return p
    try:
        if p.suffix == ".npy":
            return np.asarray(np.load(p))
        from PIL import Image

        return np.asarray(Image.open(p))
    except (OSError, ValueError, SyntaxError) as exc:  # PIL and numpy report corrupt files so
        raise InputError(f"{p}: cannot read the frame ({str(exc)[:80] or type(exc).__name__}); re-export or remove it") from None


def _frame_depth(depth: Path, conf: Path | None, params: FusionParams) -> np.ndarray:
    """Depth (H, W) metres, 0 where none, unconfident or beyond ``max_depth``."""
    raw = _image(depth)
    depth_m = raw.astype(np.float32) / (1000.0 if raw.dtype.kind in "ui" else 1.0)
    if conf is not None:
        depth_m[_image(conf) < params.min_confidence] = 0.0
    depth_m[~np.isfinite(depth_m) | (depth_m > params.max_depth)] = 0.0
    return depth_m


def _frame_rgbd(k: np.ndarray, depth_m: np.ndarray, color: Path | np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Depth (H, W) metres (0 none, :func:`_frame_depth`), colour (H, W, 3) uint8 at the depth
    resolution, intrinsics scaled to it."""
    rgb = _image(color)[..., :3]
    h, w = depth_m.shape
    kk = k.copy()
    if rgb.shape[:2] != (h, w):  # intrinsics are for the colour frame: scale them to the depth frame
        from PIL import Image

        kk[0] *= w / rgb.shape[1]
        kk[1] *= h / rgb.shape[0]
        rgb = np.asarray(Image.fromarray(np.ascontiguousarray(rgb)).resize((w, h), Image.Resampling.BILINEAR))
    return depth_m, rgb, kk


def fuse_sequence(folder: Path, params: FusionParams = FusionParams()) -> tuple[np.ndarray, np.ndarray]:
    """Fuse every frame into a sparse TSDF; return the zero-level surface as points and colours.

    Projective TSDF on a hashed voxel grid (numpy): along each pixel's ray, voxels within
    ``trunc`` of the measured depth get the truncated signed distance, weighted by 1/depth^2 and
    averaged over frames with their colour; surface points are the interpolated sign changes
    between neighbouring voxels. (Open3D 0.20's hashed volumes, ScalableTSDFVolume and
    VoxelBlockGrid, return empty meshes in the pip build used here, and its UniformTSDFVolume
    costs 0.1 s per frame per 0.5 m tile, so the same method is written out here.)
    Returns (N, 3) world points (the poses' frame) and (N, 3) colours in [0, 1].
    """
    folder = Path(folder)
    if not is_rgbd_sequence(folder):
        raise InputError(f"{folder}: not an RGB-D sequence (needs rgb/ or rgb.mp4, depth/, camera_matrix.csv, odometry.csv)")
    k = _read_csv_rows(folder / "camera_matrix.csv", skip_header=False)
    if k.shape != (3, 3):
        raise InputError(f"{folder / 'camera_matrix.csv'}: expected a 3x3 matrix")
    poses = read_poses(folder)
    depths = _frames(folder, "depth", (".png", ".npy"))
    colors = _color_frames(folder, sorted(depths))
    conf = _frames(folder, "confidence", (".png",)) if (folder / "confidence").is_dir() else {}
    frames = sorted(set(depths) & set(colors) & set(poses))
    if not frames:
        raise InputError(f"{folder}: no frame has colour, depth and a pose (frames are matched by number)")
    if len(frames) < 0.5 * max(len(depths), len(colors)):
        raise InputError(f"{folder}: only {len(frames)} frame(s) have colour, depth and a pose ({len(colors)} colour, "
                         f"{len(depths)} depth, {len(poses)} poses): the export is incomplete; re-export the sequence")
    v = params.voxel
    read: dict[int, np.ndarray] = {}  # frame -> depth read for the spacing, decoded once
    if v is None:  # the frames' own resolution: their depth is read first (cheap beside the colour)
        spacing = []
        for i in frames:
            depth = read[i] = _frame_depth(depths[i], conf.get(i), params)
            # the intrinsics are the colour frames' (principal point at their centre), scaled to the depth frame
            spacing.append(ray_spacing(depth, float(np.sqrt(k[0, 0] * k[1, 1])) * depth.shape[1] / (2.0 * k[0, 2])))
        if np.isnan(spacing).all():
            raise InputError(f"{folder}: no frame holds depth within {params.max_depth} m (check depth units: uint16 millimetres)")
        v = float(np.nanmedian(spacing))
    trunc = params.trunc_voxels * v
    steps = np.arange(-trunc, trunc + 1e-9 * v, v)
    keys, sdfs, weights, cols = [], [], [], []
    fused = 0
    for i in frames:
        color = colors[i]
        if color is None:  # the colour video ended
            break
        fused += 1
        depth = read.pop(i) if i in read else _frame_depth(depths[i], conf.get(i), params)
        depth, rgb, kk = _frame_rgbd(k, depth, color)
        h, w = depth.shape
        stride = _stride(h, w)
        vv, uu = np.mgrid[0:h:stride, 0:w:stride]
        d = depth[vv, uu].ravel()
        ok = d > 0
        d, uu, vv = d[ok], uu.ravel()[ok], vv.ravel()[ok]
        ray = np.stack([(uu - kk[0, 2]) / kk[0, 0], (vv - kk[1, 2]) / kk[1, 1], np.ones_like(d)], axis=1)
        length = np.linalg.norm(ray, axis=1)
        pose = poses[i]
        for s in steps:  # sample s metres along the ray behind (+) or in front of (-) the surface
            z = d + s / length
            pts = (ray * z[:, None]) @ pose[:3, :3].T + pose[:3, 3]
            keys.append(np.floor(pts / v).astype(np.int64))
        # per ray, the same for every step: the samples run step by step, all rays each
        sdfs.append(np.repeat(-steps, len(d)).astype(np.float32))
        weights.append(np.tile((1.0 / d**2).astype(np.float32), len(steps)))
        cols.append(np.tile(rgb[vv, uu], (len(steps), 1)))
    if fused < 0.5 * len(frames):
        raise InputError(f"{folder / 'rgb.mp4'}: the video holds {fused} frame(s) for {len(frames)} depth frames: "
                         "the export is incomplete; re-export the sequence")
    if not any(len(c) for c in keys):
        raise InputError(f"{folder}: no frame holds depth within {params.max_depth} m (check depth units: uint16 millimetres)")
    keys = [c for c in keys if len(c)]
    lo = np.min([c.min(axis=0) for c in keys], axis=0)
    span = np.max([c.max(axis=0) for c in keys], axis=0) - lo + 3
    flat = np.concatenate([((c[:, 0] - lo[0] + 1) * span[1] + (c[:, 1] - lo[1] + 1)) * span[2] + (c[:, 2] - lo[2] + 1) for c in keys])
    del keys
    uniq, inv = unique_inverse(flat)
    del flat
    w = np.concatenate(weights)
    sdf = np.concatenate(sdfs)
    wsum = np.bincount(inv, w, minlength=len(uniq))
    tsdf = np.bincount(inv, w * sdf, minlength=len(uniq)) / wsum
    col = np.concatenate(cols)
    w64 = w.astype(np.float64)  # colour sums in float64, as uint8 colours times float32 weights
    rgbsum = np.stack([np.bincount(inv, w64 * col[:, c], minlength=len(uniq)) for c in range(3)], axis=1) / wsum[:, None] / 255.0
    seen = np.bincount(inv, minlength=len(uniq))
    keep = seen >= 2
    uniq, tsdf, rgbsum = uniq[keep], tsdf[keep], rgbsum[keep]
    iz = uniq % span[2]
    iy = (uniq // span[2]) % span[1]
    ix = uniq // (span[1] * span[2])
    centres = (np.stack([ix, iy, iz], axis=1) - 1 + lo + 0.5) * v
    out_p, out_c = [], []
    for step in (span[1] * span[2], span[2], 1):
        j = np.searchsorted(uniq, uniq + step)
        j = np.minimum(j, len(uniq) - 1)
        has = uniq[j] == uniq + step
        a, b = np.flatnonzero(has), j[has]
        cross = (tsdf[a] * tsdf[b] < 0) & (np.abs(tsdf[a] - tsdf[b]) < 2.5 * v)
        a, b = a[cross], b[cross]
        t = tsdf[a] / (tsdf[a] - tsdf[b])
        out_p.append(centres[a] + (centres[b] - centres[a]) * t[:, None])
        out_c.append(rgbsum[a] + (rgbsum[b] - rgbsum[a]) * t[:, None])
    points = np.concatenate(out_p)
    if len(points) == 0:
        raise InputError(f"{folder}: the fused sequence holds no surface (check depth units: uint16 millimetres)")
    return points, np.clip(np.concatenate(out_c), 0, 1)
