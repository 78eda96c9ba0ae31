"""Bodies lying on other bodies in generated camera views (real YCB meshes, scenes at rest) are
objects of their own, not parts of what they lie on (realsim.perception.attached_parts): a thin
marker lying on a cracker box meets the box top at a depth-continuous crease at its foot (its far
outline only passes over the top behind it); a strawberry lying on a lying mustard bottle, seen in
two pieces, meets an upward face of it. The scenes are bench_view_objects' seeds 0 and 2, first scene."""

from __future__ import annotations

from pathlib import Path

import pytest

from realsim.synth.scene import ycb_root
from tests.test_view_drill import assert_found_once

pytestmark = pytest.mark.skipif(not ycb_root().is_dir(), reason="needs ../shared/data/ycb_google16k")


def test_a_marker_lying_on_a_box_is_found_once(tmp_path: Path) -> None:
    objects = ("021_bleach_cleanser", "024_bowl", "011_banana", "003_cracker_box", "040_large_marker")
    assert_found_once(tmp_path, objects, 0, "040_large_marker")


def test_a_strawberry_lying_on_a_lying_bottle_is_found_once(tmp_path: Path) -> None:
    objects = ("006_mustard_bottle", "010_potted_meat_can", "019_pitcher_base", "037_scissors", "012_strawberry")
    assert_found_once(tmp_path, objects, 2, "012_strawberry")
