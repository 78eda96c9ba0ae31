"""The conversion report printed by ``realsim convert``."""

from __future__ import annotations

from pathlib import Path

from rich.console import Console
from rich.table import Table

from realsim.scene import Scene


def print_conversion(scene: Scene, dest: Path, console: Console) -> None:
    """Supports, objects, settling figures and stage timings as rich tables (warnings go to stderr: see cli.py)."""
    planes = Table(title="supports", title_justify="left")
    for col in ("id", "kind", "height m", "size m", "points"):
        planes.add_column(col)
    for p in scene.planes:
        planes.add_row(str(p.id), p.kind + ("" if p.observed else " (assumed)"), f"{p.height:.3f}", f"{p.rect_size[0]:.2f} x {p.rect_size[1]:.2f}", str(p.inlier_count))
    console.print(planes)
    objects = Table(title="objects", title_justify="left")
    for col in ("id", "body", "label", "on", "size mm", "mass kg", "moved after settle mm"):
        objects.add_column(col)
    moved = scene.settle_report.get("displacement", {})
    for o in scene.objects:
        on = f"obj {o.resting_on}" if o.resting_on is not None else f"support {o.support_id}"
        size = " x ".join(f"{v * 1000:.0f}" for v in o.size)
        objects.add_row(str(o.id), o.name, o.label, on, size, f"{o.mass:.3f}" if o.mass else "-", f"{moved.get(o.name, 0.0) * 1000:.2f}")
    console.print(objects)
    timings = ", ".join(f"{k} {v:.2f}s" for k, v in scene.timings.items())
    console.print(f"timings: {timings}")
    if scene.llm:
        llm = scene.llm
        console.print(f"claude ({llm['model']}): {llm['calls']} call(s), {llm['cache_hits']} cached, "
                      f"{llm['input_tokens']} + {llm['output_tokens']} tokens, ~${llm['cost_usd']:.4f}, {len(llm['failures'])} failed")
    written = ["scene.json"] + (["labels.npy"] if scene.labels is not None else []) + ["preview.png", "assets/"]
    console.print(f"wrote {dest}/scene.xml (keyframe 'initial'), {', '.join(written)}")
