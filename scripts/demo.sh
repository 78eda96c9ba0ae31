#!/usr/bin/env bash
# One command: set everything up, render the bundled synthetic tabletop capture (MuJoCo depth
# camera, known ground truth), convert it into a settled MuJoCo scene and render a preview.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
export MUJOCO_GL="${MUJOCO_GL:-egl}"
.venv/bin/realsim example examples/generated/tabletop
.venv/bin/realsim convert examples/generated/tabletop -o out/tabletop
.venv/bin/python -c "import mujoco; m = mujoco.MjModel.from_xml_path('out/tabletop/scene.xml'); print(f'out/tabletop/scene.xml loads: {m.nbody} bodies, {m.ngeom} geoms, keyframe {m.key(0).name!r}')"
