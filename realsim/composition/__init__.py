"""Composition: physics-ready objects placed in an arena, the captured look on the visual layer,
the MJCF composed with MjSpec, the Panda mounted where it reaches, and the settled keyframe."""
