#!/usr/bin/env bash
# One command: set everything up, render the bundled synthetic tabletop capture (MuJoCo depth
# camera, known ground truth), convert it into a settled MuJoCo scene and render a preview.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
export MUJOCO_GL="${MUJOCO_GL:-egl}"
# The Panda comes from the mujoco-menagerie package (downloaded on first use); offline, point
# MENAGERIE_ROOT at a folder holding franka_emika_panda/ (this repository's ../shared/data).
if [ -z "${MENAGERIE_ROOT:-}" ] && [ -d ../shared/data/franka_emika_panda ]; then
  export MENAGERIE_ROOT="$(cd ../shared/data && pwd)"
fi
.venv/bin/realsim example examples/generated/tabletop --force
.venv/bin/realsim convert examples/generated/tabletop -o out/tabletop --force  # --force: a rerun replaces its own earlier output
.venv/bin/python - <<'PY'
import mujoco
m = mujoco.MjModel.from_xml_path("out/tabletop/scene.xml")
print(f"out/tabletop/scene.xml loads: {m.nbody} bodies, {m.ngeom} geoms, keyframe {m.key('initial').name!r}")
PY
