"""The ``realsim`` command line: a thin layer over the library.

Exit codes: 0 success, 1 a commanded task failed, 2 bad input or usage. User errors print one
line, never a traceback.
"""

from __future__ import annotations

import argparse
import math
import os
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any, NoReturn

import yaml


def _parse_set(values: list[str]) -> dict[str, dict[str, Any]]:
    """``stage.param=value`` pairs into pipeline overrides (values parsed as YAML scalars; a dotted
    ``stage.group.param`` reaches a nested parameter dataclass)."""
    from realsim.errors import InputError

    overrides: dict[str, dict[str, Any]] = {}
    for item in values:
        key, sep, raw = item.partition("=")
        stage, *path = key.split(".")
        if not sep or not stage or not path or not all(path):
            raise InputError(f"--set {item!r}: expected stage.param=value, e.g. --set planes.distance_threshold=0.008")
        try:
            value = yaml.safe_load(raw)
        except yaml.YAMLError:
            value = raw
        node = overrides.setdefault(stage, {})
        for part in path[:-1]:
            node = node.setdefault(part, {})
            if not isinstance(node, dict):
                raise InputError(f"--set {item!r}: {part} is set twice, as a value and as a group")
        node[path[-1]] = value
    return overrides


def _parse_pose(text: str) -> tuple[float, float, float]:
    """``x,y,yaw`` (metres, metres, radians) for ``--robot-pose``."""
    from realsim.errors import InputError

    try:
        x, y, yaw = (float(v) for v in text.split(","))
    except ValueError:
        raise InputError(f"--robot-pose {text!r}: expected x,y,yaw in metres and radians, e.g. --robot-pose -0.9,0,0") from None
    if not all(math.isfinite(v) for v in (x, y, yaw)):
        raise InputError(f"--robot-pose {text!r}: x, y and yaw must be finite numbers")
    return x, y, yaw


def seed_arg(text: str) -> int:
    """argparse type of ``--seed``: an integer from 0 to 2**32 - 1."""
    from realsim.validation import MAX_SEED

    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not an integer") from None
    if not 0 <= value <= MAX_SEED:
        raise argparse.ArgumentTypeError(f"{value} is out of range 0..{MAX_SEED}")
    return value


def bounded(kind: type[int] | type[float], low: float, high: float) -> Callable[[str], float]:
    """An argparse type: a finite ``kind`` number in [low, high]."""

    def parse(text: str) -> float:
        try:
            value: float = kind(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r} is not a {kind.__name__}") from None
        if not (math.isfinite(value) and low <= value <= high):
            raise argparse.ArgumentTypeError(f"{text} is out of range {low:g}..{high:g}")
        return value

    parse.__name__ = kind.__name__  # argparse names the type in its messages
    return parse


def cmd_convert(args: argparse.Namespace) -> int:
    """``realsim convert``: a capture (or --text, a photo) into a scene folder."""
    from realsim.text.photo_input import check_photo_offline

    check_photo_offline(args.source, args.text)  # a photo alone without a key fails before the heavy imports
    from rich.console import Console

    from realsim.errors import InputError
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
    if args.photo:
        overrides.setdefault("objects", {}).setdefault("understanding", {})["photo"] = args.photo
    if args.robot_pose:
        overrides.setdefault("robot", {})["pose"] = _parse_pose(args.robot_pose)
    if args.text is not None:
        if not args.text.strip():
            raise InputError('--text is empty: describe the scene, e.g. --text "a table with a mug and two soda cans"')
        load["text"] = args.text
    elif args.source is None:
        raise InputError('convert needs a capture (file or folder) or --text "a table with a mug"')
    scene = convert(Path(args.source) if args.source else None, args.output, force=args.force, check_only=args.check,
                    pipeline=args.pipeline, seed=args.seed, overrides=overrides, console=console if args.verbose else None)
    if scene is None:
        if not args.quiet:
            print(f"realsim: the capture, the flags and {args.output} are valid; nothing was run (--check)")
        return 0
    if not args.quiet:
        print_conversion(scene, Path(args.output), Console())
    for warning in scene.warnings:  # also in scene.json
        print(f"realsim: warning: {warning}", file=sys.stderr)
    return 0


def cmd_example(args: argparse.Namespace) -> int:
    """``realsim example``: write the bundled example capture to a new folder."""
    from realsim.destination import atomic_folder, check_destination

    dest = check_destination(args.dest, force=args.force)
    with atomic_folder(dest, force=args.force, kind="example") as tmp:
        if args.layout:  # YCB scans on a table, counter or floor, in every capture form (realsim.synth)
            from realsim.synth import SceneSpec, make_scene, write_all

            objects = tuple(args.objects.split(",")) if args.objects else None
            scene = make_scene(SceneSpec(layout=args.layout, objects=objects, n_objects=args.count, seed=args.seed))
            write_all(scene, tmp, forms=tuple(args.forms.split(",")), cloud_points=args.points, seed=args.seed)
            what = f"{args.layout} capture ({args.forms}) with ground truth"
        else:
            from realsim.synth.tabletop import make_tabletop_capture

            make_tabletop_capture(tmp, seed=args.seed)
            what = "tabletop capture"
    print(f"wrote synthetic {what} to {args.dest}")
    return 0


def cmd_export(args: argparse.Namespace) -> int:
    """``realsim export``: a scene folder as an MJCF folder, per-object MJCF or USD."""
    from realsim.errors import InputError
    from realsim.export import export_mjcf, export_objects, export_usd

    if args.format == "usd":
        if args.objects_only:
            raise InputError("--objects-only works with --format mjcf only")
        result = export_usd(Path(args.scene), args.output, force=args.force)
        for warning in result.warnings:
            print(f"realsim: warning: {warning}", file=sys.stderr)
        print(f"wrote {result.path} ({len(result.rigid_bodies)} rigid bodies, {len(result.static_colliders)} static colliders)")
    elif args.objects_only:
        objects = export_objects(Path(args.scene), args.output, force=args.force)
        print(f"wrote {len(objects)} object MJCF file(s) to {args.output}: " + ", ".join(str(o.xml) for o in objects))
    else:
        export_mjcf(Path(args.scene), args.output, force=args.force)
        print(f"wrote {Path(args.output) / 'scene.xml'} with its assets/")
    return 0


def cmd_view(args: argparse.Namespace) -> int:
    """``realsim view``: serve the scene in the browser viewer."""
    from realsim.viewer import serve

    serve(Path(args.scene), host=args.host, port=args.port, splat=Path(args.splat) if args.splat else None,
          paused=args.paused, duration=args.duration, status_port=args.status_port)
    return 0


def cmd_render(args: argparse.Namespace) -> int:
    """``realsim render``: a PNG of the scene from a camera, at keyframe ``initial``."""
    from realsim.destination import check_file_destination
    from realsim.render import render_scene

    output = check_file_destination(args.output, inputs=[Path(args.scene)], force=args.force)
    out = render_scene(Path(args.scene), output, camera=args.camera, width=args.width, height=args.height)
    print(f"wrote {out}")
    return 0


def cmd_run(args: argparse.Namespace) -> int:
    """``realsim run``: a sentence or a program, run in the sandbox and checked in simulation."""
    from realsim.destination import check_file_destination
    from realsim.runtime.console import run_cli

    for flag, path in (("--video", args.video), ("--log", args.log)):
        if path is not None:
            check_file_destination(path, force=args.force, flag=flag)

    return run_cli(args.scene, args.text, args.program, planner=args.planner, seed=args.seed, video=args.video, log=args.log,
                   video_fps=args.video_fps)


def cmd_params(args: argparse.Namespace) -> int:
    """``realsim params``: every stage parameter with its type, default and meaning."""
    from realsim.params_doc import stage_param_docs
    from realsim.pipeline import load_pipeline
    from realsim.stages import STAGES
    from realsim.validation import unknown_names

    stages = [name for name, _ in load_pipeline(args.pipeline).stages] if args.pipeline else list(STAGES)
    if args.stage:
        unknown_names([args.stage], STAGES, "stage")
        stages = [args.stage]
    for doc in stage_param_docs(stages):
        print(f"{doc.name:48s} {doc.type:24s} {doc.default!r:14s} {doc.doc}".rstrip())
    return 0


def cmd_bench_sim(args: argparse.Namespace) -> int:
    """``realsim bench-sim``: steps per second of a scene (MuJoCo Warp when installed, else the C engine)."""
    from realsim.physics.throughput import bench_scene

    result = bench_scene(Path(args.scene), worlds=args.worlds, steps=args.steps, engine=args.engine)
    cap = f"nconmax {result.nconmax}, njmax {result.njmax}" if result.nconmax else "no recorded capacity"
    print(f"{result.engine}: {result.worlds} world(s) x {result.steps} steps in {result.seconds:.2f} s = "
          f"{result.steps_per_second:,.0f} steps/s; peak per world: {result.peak_ncon} contacts, {result.peak_nefc} rows ({cap})"
          + ("; OVERFLOW: raise the scene's <size nconmax/njmax>" if result.overflow else ""))
    return 1 if result.overflow else 0


def cmd_batch(args: argparse.Namespace) -> int:
    """``realsim batch``: many captures into many scene folders on Ray."""
    from realsim.batch import print_summary, run_batch

    overrides = _parse_set(args.set)
    if args.no_robot:
        overrides.setdefault("robot", {})["enabled"] = False
    jobs, summary = run_batch(args.captures, Path(args.output), seed=args.seed, overrides=overrides, address=args.address,
                              workers=args.workers, force=args.force, retry_failed=args.retry_failed)
    print_summary(jobs, summary, Path(args.output).expanduser().resolve())
    return 1 if summary["failed"] else 0


class OneLineParser(argparse.ArgumentParser):
    """argparse with usage errors on one line (exit 2) and a pointer to ``--help``."""

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of every subcommand (one-line errors, exit code 2)."""
    parser = OneLineParser(prog="realsim", description="Turn a captured real scene into a settled MuJoCo simulation.")
    parser.add_argument("--debug", action="store_true", help="show tracebacks of internal errors")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=OneLineParser)

    convert = sub.add_parser("convert", help="convert a capture (file or folder) into a MuJoCo scene folder")
    convert.add_argument("source", nargs="?", help="a point cloud / mesh file, or a capture folder (scene.*, objects/*, capture.yaml); optional with --text")
    convert.add_argument("--text", metavar="DESCRIPTION", help='build the scene from a description, e.g. "a kitchen table with a mug and two soda cans"')
    convert.add_argument("-o", "--output", required=True, help="output folder: a new path, an empty folder, or earlier realsim output (with --force)")
    convert.add_argument("--force", action="store_true", help="replace an output folder realsim wrote before (atomically; nothing else is touched)")
    convert.add_argument("--seed", type=seed_arg, default=0, help="seed of every random source (default 0)")
    convert.add_argument("--units", choices=["m", "cm", "mm", "in", "ft"], help="input units (m, cm or mm detected by default; name in or ft)")
    convert.add_argument("--up", choices=["+x", "-x", "+y", "-y", "+z", "-z"], help="input up axis (detected by default)")
    convert.add_argument("--robot-pose", metavar="X,Y,YAW", help="place the Panda's base here (m, m, rad) instead of searching")
    convert.add_argument("--no-robot", action="store_true", help="compose the scene without the Panda")
    convert.add_argument("--photo", metavar="PATH", help="a photo of the scene: Claude names the objects in it (default: photo.* in the capture folder)")
    convert.add_argument("--pipeline", help="pipeline name in pipelines/ or a YAML path (chosen from the input by default)")
    convert.add_argument("--set", action="append", default=[], metavar="STAGE.PARAM=VALUE", help="override a stage parameter")
    convert.add_argument("--check", action="store_true", help="validate the capture, the flags and the output path, then stop")
    convert.add_argument("-q", "--quiet", action="store_true", help="print nothing on success")
    convert.add_argument("-v", "--verbose", action="store_true", help="log each stage as it starts")
    convert.set_defaults(func=cmd_convert)

    params = sub.add_parser("params", help="list every stage parameter --set can change: name, type, default, meaning")
    params.add_argument("stage", nargs="?", help="only this stage (e.g. planes)")
    params.add_argument("--pipeline", help="only the stages of this pipeline (scan, objects, text, photo or a YAML path)")
    params.set_defaults(func=cmd_params)

    example = sub.add_parser("example", help="render the bundled synthetic tabletop capture (with ground truth)")
    example.add_argument("dest", help="folder to write the capture into (new, empty, or an earlier example with --force)")
    example.add_argument("--force", action="store_true", help="replace an example realsim wrote before")
    example.add_argument("--seed", type=seed_arg, default=0)
    example.add_argument("--layout", choices=["table", "counter", "floor", "rooms"], help="YCB scans on this support (rooms: several tables at different heights), in every capture form")
    example.add_argument("--objects", help="with --layout: comma-separated YCB names (default: --count drawn)")
    example.add_argument("--count", type=int, default=4, help="with --layout: objects drawn when --objects is absent")
    example.add_argument("--forms", default="view,sequence,cloud,mesh", help="with --layout: any of view,sequence,cloud,mesh,splat")
    example.add_argument("--points", type=int, default=200_000, help="with --layout: points of cloud.ply (and splats of splat.ply)")
    example.set_defaults(func=cmd_example)

    export = sub.add_parser("export", help="export a converted scene as self-contained MJCF or as USD")
    export.add_argument("scene", help="an output folder of `realsim convert`")
    export.add_argument("--format", choices=["mjcf", "usd"], default="mjcf", help="mjcf (a folder) or usd (a .usda/.usd file)")
    export.add_argument("-o", "--output", required=True, help="destination folder (mjcf) or file (usd)")
    export.add_argument("--objects-only", action="store_true", help="mjcf: one MJCF per object, for MjSpec.attach into another scene")
    export.add_argument("--force", action="store_true", help="replace an export realsim wrote before")
    export.set_defaults(func=cmd_export)

    view = sub.add_parser("view", help="view a converted scene live in the browser (viser) and send it commands")
    view.add_argument("scene", help="an output folder of `realsim convert`")
    view.add_argument("--host", default="127.0.0.1", help="address to serve on (default 127.0.0.1)")
    view.add_argument("--port", type=bounded(int, 1, 65535), default=8080, help="port to serve on (default 8080)")
    view.add_argument("--splat", help="a Gaussian splat .ply shown as a backdrop (found next to the capture by default)")
    view.add_argument("--paused", action="store_true", help="start with the physics paused")
    view.add_argument("--duration", type=bounded(float, 0.0, 1e7), help="stop serving after this many seconds (default: until Ctrl-C)")
    view.add_argument("--status-port", type=bounded(int, 1, 65535), help="also serve GET /status (JSON: sim time, frames sent, body poses) on this port")
    view.set_defaults(func=cmd_view)

    render = sub.add_parser("render", help="render a converted scene at keyframe 'initial' to a PNG")
    render.add_argument("scene", help="an output folder of `realsim convert` (or its scene.xml)")
    render.add_argument("-o", "--output", default="preview.png", help="PNG to write (default preview.png)")
    render.add_argument("--force", action="store_true", help="replace an existing file at -o")
    render.add_argument("--camera", help="a camera of the model, e.g. 'capture' (default: an overview)")
    render.add_argument("--width", type=bounded(int, 16, 8192), default=960)
    render.add_argument("--height", type=bounded(int, 16, 8192), default=720)
    render.set_defaults(func=cmd_render)

    run = sub.add_parser("run", help="command the Panda in a converted scene in plain English (or run a program)")
    run.add_argument("scene", help="an output folder of `realsim convert`")
    run.add_argument("text", nargs="?", metavar="COMMAND", help='what to do, e.g. "put the mug in the bowl"')
    run.add_argument("--program", metavar="FILE", help="run this Python program over the primitives instead (same sandbox)")
    run.add_argument("--planner", choices=["auto", "rules", "claude"], default="auto", help="auto: Claude when ANTHROPIC_API_KEY is set, else rules")
    run.add_argument("--video", metavar="OUT.mp4", help="record an MP4 (30 fps of simulated time)")
    run.add_argument("--video-fps", type=bounded(float, 1.0, 240.0), default=30.0, metavar="FPS", help="frames per simulated second of --video (default 30)")
    run.add_argument("--log", metavar="PATH", help="JSON log path (default <scene>/runs/run_<n>.json)")
    run.add_argument("--force", action="store_true", help="replace existing files at --video / --log")
    run.add_argument("--seed", type=seed_arg, default=0, help="seed of the grasp search (default 0)")
    run.set_defaults(func=cmd_run)

    bench = sub.add_parser("bench-sim", help="steps per second of a converted scene over N worlds (MuJoCo Warp if installed, else C)")
    bench.add_argument("scene", help="an output folder of `realsim convert`")
    bench.add_argument("--worlds", type=bounded(int, 1, 1_000_000), default=1, help="parallel worlds (default 1)")
    bench.add_argument("--steps", type=bounded(int, 1, 10_000_000), default=200, help="steps per world (default 200)")
    bench.add_argument("--engine", choices=["auto", "warp", "c"], default="auto", help="auto: MuJoCo Warp when installed, else the C engine")
    bench.set_defaults(func=cmd_bench_sim)

    batch = sub.add_parser("batch", help="convert many captures (a folder, a glob or a list file) on Ray, resumably")
    batch.add_argument("captures", nargs="+", help="a folder of captures, a glob, a text file listing one capture per line, or captures")
    batch.add_argument("-o", "--output", required=True, help="folder that receives one scene folder per capture (and batch.json)")
    batch.add_argument("--address", help="an existing Ray cluster (default: a local one)")
    batch.add_argument("--workers", type=bounded(int, 1, 4096), help="parallel conversions (default: the CPUs Ray sees)")
    batch.add_argument("--seed", type=seed_arg, default=0, help="seed of every conversion (default 0)")
    batch.add_argument("--set", action="append", default=[], metavar="STAGE.PARAM=VALUE", help="override a stage parameter for all")
    batch.add_argument("--no-robot", action="store_true", help="compose the scenes without the Panda")
    batch.add_argument("--force", action="store_true", help="reconvert captures whose scene is already written and unchanged")
    batch.add_argument("--retry-failed", action="store_true", help="run captures that failed last time although unchanged")
    batch.set_defaults(func=cmd_batch)
    return parser


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``realsim`` command."""
    from realsim.errors import RealsimError

    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return int(args.func(args))
    except RealsimError as exc:
        print(f"realsim: error: {exc}", file=sys.stderr)
        return exc.exit_code
    except KeyboardInterrupt:
        print("realsim: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:  # the reader went away (realsim params | head): nothing more to say
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # no second error when Python flushes at exit
        return 0
    except Exception as exc:  # an internal error: one line unless --debug
        if args.debug:
            raise
        print(f"realsim: internal error: {type(exc).__name__}: {exc} (rerun with --debug for the traceback)", file=sys.stderr)
        return 3


if __name__ == "__main__":
    sys.exit(main())
