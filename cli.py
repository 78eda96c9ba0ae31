"""The ``realsim`` command line: a thin layer over the library.

Exit codes: 0 success, 1 a commanded task failed, 2 bad input or usage. User errors print one
line, never a traceback.
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path
from typing import Any

import yaml

os.environ.setdefault("MUJOCO_GL", "egl")


def _parse_set(values: list[str]) -> dict[str, dict[str, Any]]:
    """``stage.param=value`` pairs into pipeline overrides (values parsed as YAML scalars)."""
    from realsim.errors import InputError

    overrides: dict[str, dict[str, Any]] = {}
    for item in values:
        key, sep, raw = item.partition("=")
        stage, dot, param = key.partition(".")
        if not sep or not dot or not stage or not param:
            raise InputError(f"--set {item!r}: expected stage.param=value, e.g. --set planes.distance_threshold=0.008")
        overrides.setdefault(stage, {})[param] = yaml.safe_load(raw)
    return overrides


def _parse_pose(text: str) -> tuple[float, float, float]:
    """``x,y,yaw`` (metres, metres, radians) for ``--robot-pose``."""
    from realsim.errors import InputError

    try:
        x, y, yaw = (float(v) for v in text.split(","))
    except ValueError:
        raise InputError(f"--robot-pose {text!r}: expected x,y,yaw in metres and radians, e.g. --robot-pose -0.9,0,0") from None
    return x, y, yaw


def cmd_convert(args: argparse.Namespace) -> int:
    from rich.console import Console

    from realsim.pipeline import convert
    from realsim.report import print_conversion

    console = Console(stderr=True, quiet=args.quiet)
    overrides = _parse_set(args.set)
    load = overrides.setdefault("load", {})
    if args.units:
        load["units"] = args.units
    if args.up:
        load["up"] = args.up
    if args.no_robot:
        overrides.setdefault("robot", {})["enabled"] = False
    if args.robot_pose:
        overrides.setdefault("robot", {})["pose"] = _parse_pose(args.robot_pose)
    scene = convert(Path(args.source), Path(args.output), pipeline=args.pipeline, seed=args.seed, overrides=overrides,
                    console=console if args.verbose else None)
    if not args.quiet:
        print_conversion(scene, Path(args.output), Console())
    return 0


def cmd_example(args: argparse.Namespace) -> int:
    from realsim.synthetic import make_tabletop_capture

    path = make_tabletop_capture(Path(args.dest), seed=args.seed)
    print(f"wrote synthetic tabletop capture to {path}")
    return 0


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="realsim", description="Turn a captured real scene into a settled MuJoCo simulation.")
    parser.add_argument("--debug", action="store_true", help="show tracebacks of internal errors")
    sub = parser.add_subparsers(dest="command", required=True)

    convert = sub.add_parser("convert", help="convert a capture (file or folder) into a MuJoCo scene folder")
    convert.add_argument("source", help="a point cloud / mesh file, or a capture folder (scene.*, objects/*, capture.yaml)")
    convert.add_argument("-o", "--output", required=True, help="output folder (replaced atomically)")
    convert.add_argument("--seed", type=int, default=0, help="seed of every random source (default 0)")
    convert.add_argument("--units", choices=["m", "cm", "mm"], help="input units (detected by default)")
    convert.add_argument("--up", choices=["+x", "-x", "+y", "-y", "+z", "-z"], help="input up axis (detected by default)")
    convert.add_argument("--robot-pose", metavar="X,Y,YAW", help="place the Panda's base here (m, m, rad) instead of searching")
    convert.add_argument("--no-robot", action="store_true", help="compose the scene without the Panda")
    convert.add_argument("--pipeline", help="pipeline name in pipelines/ or a YAML path (chosen from the input by default)")
    convert.add_argument("--set", action="append", default=[], metavar="STAGE.PARAM=VALUE", help="override a stage parameter")
    convert.add_argument("-q", "--quiet", action="store_true", help="print nothing on success")
    convert.add_argument("-v", "--verbose", action="store_true", help="log each stage as it starts")
    convert.set_defaults(func=cmd_convert)

    example = sub.add_parser("example", help="render the bundled synthetic tabletop capture (with ground truth)")
    example.add_argument("dest", help="folder to write the capture into")
    example.add_argument("--seed", type=int, default=0)
    example.set_defaults(func=cmd_example)
    return parser


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``realsim`` command."""
    from realsim.errors import RealsimError

    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return args.func(args)
    except RealsimError as exc:
        print(f"realsim: error: {exc}", file=sys.stderr)
        return exc.exit_code
    except KeyboardInterrupt:
        print("realsim: interrupted", file=sys.stderr)
        return 130
    except Exception as exc:  # an internal error: one line unless --debug
        if args.debug:
            raise
        print(f"realsim: internal error: {type(exc).__name__}: {exc} (rerun with --debug for the traceback)", file=sys.stderr)
        return 3


if __name__ == "__main__":
    sys.exit(main())
