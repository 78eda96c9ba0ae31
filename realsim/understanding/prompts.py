"""The prompt files realsim.understanding sends (versioned: first line ``version: ...``)."""

from __future__ import annotations

from realsim.resources import load_prompt

__all__ = ["PHOTO_PROMPT", "RECORD_PROMPT", "VALUES_PROMPT", "load_prompt"]

PHOTO_PROMPT = "photo_objects.md"
RECORD_PROMPT = "manifest_record.md"
VALUES_PROMPT = "manifest_values.md"
