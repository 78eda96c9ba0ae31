"""Colour words a person would use for captured colours: hue bins for chromatic colours,
lightness for white, grey and black, brown for dark oranges. One namer for the scan's offline
names and for the planner's colour words."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

# Hue bins (degrees) of the chromatic colour words; achromatic words come from value alone.
HUES = ((15, "red"), (40, "orange"), (70, "yellow"), (165, "green"), (255, "blue"), (290, "purple"), (345, "pink"), (361, "red"))
CHROMA_MIN = 0.22  # saturation below which a pixel is white / grey / black
def colour_words(rgb: np.ndarray) -> np.ndarray:
    """A colour word per pixel ((N, 3) balanced RGB in [0, 1])."""
    rgb = np.nan_to_num(np.asarray(rgb, float))
    mx, mn = rgb.max(axis=1), rgb.min(axis=1)
    sat = (mx - mn) / np.maximum(mx, 1e-6)
    r, g, b = rgb.T
    delta = np.maximum(mx - mn, 1e-6)
    hue = np.where(mx == r, ((g - b) / delta) % 6, np.where(mx == g, (b - r) / delta + 2, (r - g) / delta + 4)) * 60.0
    words = np.empty(len(rgb), dtype=object)
    edges = np.array([h for h, _ in HUES])
    names = np.array([n for _, n in HUES], dtype=object)
    words[:] = names[np.searchsorted(edges, hue, side="right").clip(0, len(names) - 1)]
    brown = (hue >= 10) & (hue < 45) & (mx < 0.55) & (sat >= CHROMA_MIN)
    words[brown] = "brown"
    grey = sat < CHROMA_MIN
    words[grey & (mx >= 0.62)] = "white"
    words[grey & (mx < 0.62)] = "grey"
    words[mx < 0.18] = "black"
    return words


def colour_name(rgb: Sequence[float] | None) -> str | None:
    """The colour word of one RGB triple (0-1), or None."""
    if rgb is None or len(rgb) < 3 or not all(np.isfinite(float(v)) for v in rgb[:3]):
        return None
    return str(colour_words(np.asarray([rgb[:3]], float))[0])
