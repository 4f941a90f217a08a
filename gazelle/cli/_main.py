"""``gazelle sim | spawn | check | demo``: Gazebo's workflow from one pip-installed command."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Annotated

import typer

app = typer.Typer(
    add_completion=False,
    no_args_is_help=True,
    help="Gazebo-style robot simulation for ROS 2 on MuJoCo. Headless first.",
)


def _load_world_or_exit(world: Path | None, arg: list[str]):
    """The world to show (see ``gazelle sim``), or exit 1 with the diagnostics."""
    from ..description import ModelLoadError
    from ._sim import load_world

    try:
        return load_world(world, _parse_args(arg))
    except ModelLoadError as err:
        print(str(err), file=sys.stderr)
        raise typer.Exit(1) from None


def _parse_args(values: list[str]) -> dict[str, str]:
    """xacro arguments given as ``NAME:=VALUE`` (ros2 launch's spelling) as a mapping; anything else is
    typer's usage error naming it."""
    out: dict[str, str] = {}
    for v in values:
        if ":=" not in v:
            raise typer.BadParameter(f"expected NAME:=VALUE, got {v!r}")
        k, val = v.split(":=", 1)
        out[k] = val
    return out


# `gazelle sim`'s options with long help, declared once here so that the command reads as its parameters
SimWorld = Annotated[
    Path | None,
    typer.Argument(
        help="World file (.sdf/.world), found as gz sim finds it (as given, then on GZ_SIM_RESOURCE_PATH, then "
        "the installed empty.sdf), or a model (.urdf/.xacro/.sdf); default: the embedded empty world."
    ),
]
SimRtf = Annotated[
    float | None,
    typer.Option(
        "--rtf",
        help="Real-time factor (default: the world's, 1.0); 0 = as fast as possible. While /clock has "
        "subscribers, the clock keeps its resolution: at most 1000 /clock messages per wall second, "
        "so at most 10x real time at the default --clock-rate 100.",
    ),
]
SimSeed = Annotated[
    int | None,
    typer.Option(
        "--seed",
        help="Seed of the sensors' and plugins' noise (as gz sim --seed): a run repeats bit for bit. "
        "Default: fresh entropy, so runs with noise differ.",
    ),
]
SimDropWhenBehind = Annotated[
    bool,
    typer.Option(
        "--drop-when-behind",
        help="When publishing falls behind the simulation, drop the oldest messages (counted on "
        "/gazelle/dropped_messages) instead of slowing the simulation down (the default: nothing dropped).",
    ),
]
SimRosDiscovery = Annotated[
    str | None,
    typer.Option(
        "--ros-discovery",
        help="ROS discovery range of the server: localhost (default unless ROS_AUTOMATIC_DISCOVERY_RANGE, "
        "ROS_LOCALHOST_ONLY or ROS_STATIC_PEERS is set), subnet (anyone on the network can call its services), "
        "or off.",
    ),
]
SimAllowOrigin = Annotated[
    list[str] | None,
    typer.Option(
        "--viewer-allow-origin",
        help="A web origin (http://host:port, or '*') besides the viewer's own whose pages may connect to it "
        "(repeatable); see docs/security.md.",
    ),
]
SimFoxglove = Annotated[
    int | None,
    typer.Option(
        "--foxglove",
        help="Also serve the Foxglove WebSocket protocol on this port (8765 when given without one), on the "
        "viewer's interface, to the Foxglove app's origin and --viewer-allow-origin ones.",
    ),
]
SimReplay = Annotated[
    Path | None,
    typer.Option(
        "--replay",
        help="Record where every body is (30 times a sim second) and, at shutdown (or at once on SIGUSR1), write "
        "a replay of the run since the last world reset: a page that opens from disk in a browser (FILE.html), "
        "or its data (FILE.json). gazelle's pytest plugin keeps one for each failing test. An earlier replay "
        "there is replaced; any other file is refused unless --force.",
    ),
]
SimForce = Annotated[
    bool,
    typer.Option("--force", help="Let --replay FILE replace a file that is not a replay (or a link, itself)."),
]
SimNamedPoses = Annotated[
    list[Path],
    typer.Option(
        "--named-poses",
        help="An SDF file whose world <frame>s are added to the world's named poses (GetNamedPoses; repeatable).",
    ),
]


@app.command()
def sim(
    world: SimWorld = None,
    rtf: SimRtf = None,
    clock_rate: float = typer.Option(
        100.0, "--clock-rate", help="/clock publish rate in sim-time Hz (0 = every step); default 100."
    ),
    paused: bool = typer.Option(False, "--paused", help="Start paused (unpause with /unpause_physics)."),
    seed: SimSeed = None,
    arg: list[str] = typer.Option([], "--arg", help="xacro argument NAME:=VALUE (repeatable)."),
    drop_when_behind: SimDropWhenBehind = False,
    no_viewer: bool = typer.Option(False, "--no-viewer", help="Do not serve the browser viewer."),
    viewer_host: str = typer.Option(
        "127.0.0.1", "--viewer-host", help="Interface the viewer binds to (0.0.0.0: every interface; think twice)."
    ),
    viewer_port: int = typer.Option(
        8080, "--viewer-port", help="Viewer port; the next free one if taken; 0 = any free port."
    ),
    ros_discovery: SimRosDiscovery = None,
    viewer_allow_origin: SimAllowOrigin = None,
    foxglove: SimFoxglove = None,
    replay: SimReplay = None,
    replay_topic: list[str] = typer.Option(
        [], "--replay-topic", help="A topic of the simulation's whose values the replay shows (repeatable)."
    ),
    force: SimForce = False,
    named_poses: SimNamedPoses = [],  # noqa: B006 (typer reads the default; it is never mutated)
) -> None:
    """Run a simulation server: /clock, /spawn_entity, /delete_entity, every plugin's topics, and the browser viewer."""
    from ._sim import run_sim

    raise typer.Exit(
        run_sim(
            world,
            rtf=rtf,
            clock_rate_hz=clock_rate,
            paused=paused,
            args=_parse_args(arg),
            viewer=not no_viewer,
            viewer_host=viewer_host,
            viewer_port=viewer_port,
            viewer_allow_origins=_origins(viewer_allow_origin or []),
            ros_discovery=_discovery(ros_discovery),
            foxglove_port=foxglove,
            seed=seed,
            drop_when_behind=drop_when_behind,
            replay=replay,
            replay_topics=tuple(replay_topic),
            replay_force=force,
            named_poses=tuple(named_poses),
        )
    )


@app.command()
def foxglove(
    port: int = typer.Option(8765, "--port", help="WebSocket port (foxglove_bridge's 8765 by default)."),
    host: str = typer.Option("127.0.0.1", "--host", help="Interface to bind (0.0.0.0: every interface; think twice)."),
    allow_origin: list[str] = typer.Option(
        [],
        "--allow-origin",
        help="A web origin (http(s)://host:port, or '*') besides the Foxglove app's whose pages may connect "
        "(repeatable).",
    ),
) -> None:
    """Serve the ROS graph's topics over the Foxglove WebSocket protocol, as foxglove_bridge does."""
    from ._foxglove import run as foxglove_main
    from .ros2cli import ensure_ament_prefix

    ensure_ament_prefix()  # the interface definitions (schemas) are found through it

    raise typer.Exit(foxglove_main(host, port, _origins(allow_origin)))


def _discovery(value: str | None) -> str | None:
    """``--ros-discovery``: ROS_AUTOMATIC_DISCOVERY_RANGE's values (localhost, subnet, off), any case;
    None leaves the environment's (and LOCALHOST when it says nothing: see ros/_exposure.py)."""
    if value is not None and value.lower() not in ("localhost", "subnet", "off"):
        raise typer.BadParameter(f"--ros-discovery is localhost, subnet or off, got {value!r}")
    return value.lower() if value is not None else None


def _origins(values: list[str]) -> tuple[str, ...]:
    """``--viewer-allow-origin``: the browser origins the viewer accepts besides its own (``http(s)://HOST[:PORT]``
    or ``*``; anything else is a usage error)."""
    if not values:  # the usual case, without importing the viewer (websockets: 0.1 s of every start)
        return ()
    from ..viewer import allowed_origins

    try:
        return allowed_origins(values)
    except ValueError as err:
        raise typer.BadParameter(str(err)) from None


@app.command(
    context_settings={"allow_extra_args": True, "ignore_unknown_options": True, "help_option_names": []},
    add_help_option=False,
)
def spawn(ctx: typer.Context) -> None:
    """Spawn an entity like gazebo_ros's spawn_entity.py (-entity NAME -file F | -topic T | -string XML ...)."""
    from ..ros import spawn_main

    raise typer.Exit(spawn_main(list(ctx.args)))


@app.command(
    context_settings={"allow_extra_args": True, "ignore_unknown_options": True, "help_option_names": []},
    add_help_option=False,
)
def launch(ctx: typer.Context) -> None:
    """Run a launch file: the same as ``ros2 launch`` (PKG FILE [name:=value ...] | PATH, --show-args)."""
    from .ros2cli import ensure_ament_prefix
    from .ros2cli._launch import main as launch_main

    ensure_ament_prefix()
    raise typer.Exit(launch_main(list(ctx.args)))


@app.command(
    context_settings={"allow_extra_args": True, "ignore_unknown_options": True, "help_option_names": []},
    add_help_option=False,
)
def run(ctx: typer.Context) -> None:
    """Run a package's executable: the same as ``ros2 run PKG EXECUTABLE [args]``."""
    from .ros2cli import ensure_ament_prefix
    from .ros2cli._run import main as run_main

    ensure_ament_prefix()
    raise typer.Exit(run_main(list(ctx.args)))


@app.command(
    context_settings={"allow_extra_args": True, "ignore_unknown_options": True, "help_option_names": []},
    add_help_option=False,
)
def spawner(ctx: typer.Context) -> None:
    """Load, configure and activate ros2_control controllers, like ``ros2 run controller_manager spawner``
    (NAME... [-c MANAGER] [-p PARAM_FILE] [--inactive] [--controller-manager-timeout S] ...)."""
    from ..ros import spawner_main

    raise typer.Exit(spawner_main(list(ctx.args)))


@app.command(
    context_settings={"allow_extra_args": True, "ignore_unknown_options": True, "help_option_names": []},
    add_help_option=False,
)
def arm(ctx: typer.Context) -> None:
    """Move an arm through a running move_group: GROUP x y z roll pitch yaw [--frame F] [--link L] |
    GROUP --named NAME | GROUP --joints V... [--velocity S] [--plan-only]."""
    from ..ros import arm_main

    raise typer.Exit(arm_main(list(ctx.args)))


@app.command(
    name="move_group",
    context_settings={"allow_extra_args": True, "ignore_unknown_options": True, "help_option_names": []},
    add_help_option=False,
)
def move_group(ctx: typer.Context) -> None:
    """MoveIt's move_group interfaces (MoveGroup and ExecuteTrajectory actions, IK/FK, planning services) for
    one robot, planned with roboplan ([--urdf F] [--srdf F] [--config MOVEIT_CONFIG_DIR] [--ros-args ...])."""
    from ..ros import move_group_main

    raise typer.Exit(move_group_main(list(ctx.args)))


@app.command(
    context_settings={"allow_extra_args": True, "ignore_unknown_options": True, "help_option_names": []},
    add_help_option=False,
)
def unspawner(ctx: typer.Context) -> None:
    """Deactivate and unload ros2_control controllers, like ``ros2 run controller_manager unspawner``."""
    from ..ros import unspawner_main

    raise typer.Exit(unspawner_main(list(ctx.args)))


@app.command()
def sweep(
    scenario: str = typer.Argument(..., help="FILE.py::FUNCTION, a function (sim, params, seed) -> metrics."),
    param: list[str] = typer.Option(
        [], "--param", help="NAME=a,b,c or NAME=start:stop:count (repeatable; every combination runs)."
    ),
    seeds: str = typer.Option("0", "--seeds", help="START:STOP (STOP excluded), N, or a,b,c."),
    jobs: int | None = typer.Option(None, "-j", "--jobs", help="Worker processes (default: one per core)."),
    ray: str | None = typer.Option(
        None,
        "--ray",
        help="Run on Ray: local (a Ray instance of -j CPUs here, on 127.0.0.1 only), auto (RAY_ADDRESS, or the "
        "cluster `ray start` recorded here), or ray://HOST:PORT.",
    ),
    out: Path | None = typer.Option(None, "--out", help="Results folder (default: out/sweep_FUNCTION)."),
    resume: bool = typer.Option(False, "--resume", help="Keep the runs already in --out and run the others."),
    timeout: float | None = typer.Option(
        None, "--timeout", help="Seconds of wall time a run may take (then it is stopped and recorded as a timeout)."
    ),
    start: Path | None = typer.Option(
        None,
        "--from",
        help="A checkpoint (Simulation.checkpoint) every run goes on from, its noise reseeded by the run's seed.",
    ),
) -> None:
    """Run a scenario over a grid of parameters and seeds; a row per run and an HTML report."""
    from ._sweep import run_sweep

    raise typer.Exit(
        run_sweep(scenario, param, seeds, jobs=jobs, ray=ray, out=out, resume=resume, timeout=timeout, start=start)
    )


@app.command()
def check(
    file: Path = typer.Argument(..., help="A URDF, xacro, SDF or SRDF file."),
    arg: list[str] = typer.Option([], "--arg", help="xacro argument NAME:=VALUE (repeatable)."),
    strict: bool = typer.Option(False, "--strict", help="Treat warnings as errors."),
) -> None:
    """Print a description's diagnostics and a summary; exit non-zero on errors."""
    from ._check import run_check

    raise typer.Exit(run_check(file, args=_parse_args(arg), strict=strict))


@app.command()
def demo(
    out: Path = typer.Option(Path("out/demo"), "--out", help="Where to write the path image and logs."),
    rtf: float = typer.Option(
        1.0, "--rtf", help="Real-time factor of the demo (0 = as fast as possible, with sim time)."
    ),
    snapshot: bool = typer.Option(
        False, "--snapshot", help="Also write a PNG of the viewer (the square's path trail) to OUT/viewer.png."
    ),
    record: bool = typer.Option(
        False, "--record", help="Also record an MP4 of the viewer during the square to OUT/square.mp4."
    ),
) -> None:
    """Start the sim and its viewer, spawn the seed robot, drive one square with square_movement.py, report, stop."""
    from ._demo import run_demo

    raise typer.Exit(run_demo(out, rtf=rtf, snapshot=snapshot, record=record))


@app.command()
def snapshot(
    world: Path | None = typer.Option(None, "--world", help="World or model file to show (default: the empty world)."),
    out: Path = typer.Option(Path("out/snapshot.png"), "--out", help="PNG to write."),
    attach: str | None = typer.Option(
        None,
        "--attach",
        help="Viewer URL of a running `gazelle sim` (e.g. http://127.0.0.1:8080) instead of a new sim.",
    ),
    settle: float = typer.Option(1.0, "--settle", help="Seconds to let the scene load and settle before the shot."),
    arg: list[str] = typer.Option([], "--arg", help="xacro argument NAME:=VALUE (repeatable)."),
    panel: bool = typer.Option(
        True, "--panel/--no-panel", help="Show the control panel, or minimize it so the scene fills the view."
    ),
) -> None:
    """Write a PNG of the browser view, headlessly (Debian's chromium), for docs and bug reports."""
    from ..viewer import run_snapshot

    loaded = None if attach is not None else _load_world_or_exit(world, arg)
    raise typer.Exit(run_snapshot(loaded, out, attach=attach, settle_sec=settle, panel=panel))


@app.command("record-video")
def record_video(
    world: Path | None = typer.Option(None, "--world", help="World or model file to show (default: the empty world)."),
    out: Path = typer.Option(
        Path("out/video.mp4"), "--out", help="Video to write; its extension picks the format: .mp4 (H.264) or .gif."
    ),
    attach: str | None = typer.Option(
        None, "--attach", help="Viewer URL of a running `gazelle sim` instead of a new sim."
    ),
    seconds: float = typer.Option(5.0, "--seconds", help="Wall seconds to record."),
    fps: float = typer.Option(
        4.0, "--fps", help="Frames per second (headless chromium renders in software: keep it modest)."
    ),
    drive: str | None = typer.Option(
        None,
        "--drive",
        help="V,W: send this Twist (m/s, rad/s) to the first diff-drive robot of --world before recording.",
    ),
    arg: list[str] = typer.Option([], "--arg", help="xacro argument NAME:=VALUE (repeatable)."),
    panel: bool = typer.Option(
        True, "--panel/--no-panel", help="Show the control panel, or minimize it so the scene fills the view."
    ),
) -> None:
    """Record an MP4 (H.264) or an animated GIF of the browser view, headlessly (Debian's chromium)."""
    from ..viewer import run_record, video_format

    try:
        video_format(out)  # before loading the world or starting anything
    except ValueError as err:
        print(f"gazelle record-video: {err}", file=sys.stderr)
        raise typer.Exit(2) from None
    twist = None
    if drive is not None:
        try:
            v, w = (float(x) for x in drive.split(","))
        except ValueError:
            raise typer.BadParameter(f"--drive expects V,W (e.g. 0.2,0.3), got {drive!r}") from None
        twist = (v, w)
    loaded = None if attach is not None else _load_world_or_exit(world, arg)
    raise typer.Exit(run_record(loaded, out, attach=attach, seconds=seconds, fps=fps, drive=twist, panel=panel))


FOXGLOVE_DEFAULT_PORT = 8765
"""The Foxglove WebSocket port of a bare ``--foxglove`` (the Foxglove app's default)."""


def _bare_foxglove(args: list[str]) -> list[str]:
    """``--foxglove`` with no port (last, or followed by another option) given its default port: typer 0.29
    reads no optional option values (click's ``flag_value``), so it refused the bare flag its help offers."""
    out = list(args)
    for i, a in enumerate(out):
        if a == "--":
            break
        if a == "--foxglove" and (i + 1 == len(out) or out[i + 1].startswith("-")):
            out.insert(i + 1, str(FOXGLOVE_DEFAULT_PORT))
            break
    return out


def main(argv: list[str] | None = None) -> None:
    """Entry point of the ``gazelle`` console script."""
    app(args=_bare_foxglove(argv if argv is not None else sys.argv[1:]), prog_name="gazelle")
