"""The `ros2` introspection verbs against a running simulation, as a user types them (gazelle's ros2
command: no ROS installation)."""

from __future__ import annotations

import re
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest
import yaml
from _harness import GAZELLE, SEED_XACRO, run_or_dump, start, wait_for
from rosgraph_msgs.msg import Clock

ROS2 = str(Path(sys.prefix) / "bin" / "ros2")


def ros2(*args: str, timeout: float = 60) -> subprocess.CompletedProcess:
    return run_or_dump([ROS2, *args], timeout)


def ros2_many(commands: dict[str, tuple[str, ...]], at_once: int = 13) -> dict[str, subprocess.CompletedProcess]:
    """Run independent ``ros2`` commands side by side (each mostly waits for discovery), ``at_once`` at a time."""
    with ThreadPoolExecutor(at_once) as pool:
        futures = {name: pool.submit(ros2, *args) for name, args in commands.items()}
        return {name: f.result() for name, f in futures.items()}


@pytest.mark.slow
def test_topic_service_node_and_interface_verbs_on_a_running_simulation(sim_factory, ros_client):
    sim_factory("--no-viewer")
    spawn = start([*GAZELLE, "spawn", "-entity", "bot", "-file", str(SEED_XACRO)], "spawn")
    assert spawn.wait(60) == 0, spawn.output

    r = ros2_many(
        {
            "topic list": ("topic", "list", "-t"),
            "echo": ("topic", "echo", "/odom", "--once"),
            "echo full": ("topic", "echo", "/odom", "--once", "-l", "5", "--full-length"),
            "echo short": ("topic", "echo", "/odom", "--once", "-l", "5"),
            "echo sensor_data": (
                "topic",
                "echo",
                "/odom",
                "--once",
                "--qos-profile",
                "sensor_data",
                "--field",
                "child_frame_id",
            ),
            # ros2cli Jazzy's echo flags (gazelle refused them before)
            "echo raw": ("topic", "echo", "/odom", "--once", "--raw"),
            "echo info": ("topic", "echo", "/odom", "--once", "-i", "--field", "child_frame_id"),
            "echo filter": (
                "topic",
                "echo",
                "/odom",
                "--once",
                "--no-lost-messages",
                "--filter",
                "m.child_frame_id == 'base_link' and m.header.frame_id == 'odom'",
            ),
            "hz clock": ("topic", "hz", "/clock", "--count", "1"),
            "info cmd_vel": ("topic", "info", "/cmd_vel", "-v"),
            "info odom": ("topic", "info", "-v", "/odom"),
            "find": ("topic", "find", "nav_msgs/msg/Odometry"),
            "bw": ("topic", "bw", "/odom", "--count", "1"),
            "delay": ("topic", "delay", "/odom", "--count", "1", "--use-sim-time"),
            "call": ("service", "call", "/get_model_list", "gazebo_msgs/srv/GetModelList"),
            "service list": ("service", "list", "-t"),
            # a fresh look at the graph: the run's warm daemon may still hold an earlier test file's server and client
            # for their lease (as ros2cli's daemon does; a full suite once listed /gazelle twice that way)
            "node list": ("node", "list", "--no-daemon"),
            "node info gazelle": ("node", "info", "/gazelle"),
            "node info drive": ("node", "info", "/differential_drive"),
            "show srv": ("interface", "show", "gazebo_msgs/srv/SpawnEntity"),
            "show odom": ("interface", "show", "nav_msgs/msg/Odometry"),
            "proto": ("interface", "proto", "geometry_msgs/msg/Twist"),
            "param get": ("param", "get", "/differential_drive", "wheel_separation"),
            "param set": ("param", "set", "/differential_drive", "wheel_separation", "0.5"),
            "param dump": ("param", "dump", "/differential_drive"),
            "param describe": ("param", "describe", "/differential_drive", "wheel_diameter"),
            "param list": ("param", "list", "/differential_drive"),
            "param nope": ("param", "get", "/nope", "x"),
            "bad type": ("topic", "pub", "--once", "/cmd_vel", "geometry_msgs/msg/Twst", "{}"),
            "bad field": ("topic", "pub", "--once", "/cmd_vel", "geometry_msgs/msg/Twist", "{linear: {w: 1}}"),
            "unknown topic": ("topic", "echo", "/no_such_topic"),
            "unknown package": ("interface", "package", "no_such_msgs"),
        }
    )
    listed = r["topic list"].stdout
    assert "/odom [nav_msgs/msg/Odometry]" in listed and "/clock [rosgraph_msgs/msg/Clock]" in listed
    assert "/_gazelle/servers" not in listed  # hidden unless asked
    assert r["echo"].returncode == 0, r["echo"].stderr
    first = yaml.safe_load(r["echo"].stdout.split("---")[0])
    assert first["header"]["frame_id"] == "odom" and first["child_frame_id"] == "base_link"
    assert len(first["pose"]["covariance"]) == 36
    # --full-length / -f (issue 26: it was rejected) prints arrays whole whatever -l says
    assert r["echo full"].returncode == 0, r["echo full"].stderr
    assert len(yaml.safe_load(r["echo full"].stdout.split("---")[0])["pose"]["covariance"]) == 36
    assert yaml.safe_load(r["echo short"].stdout.split("---")[0])["pose"]["covariance"][-1] == "..."
    best_effort = r["echo sensor_data"]
    assert best_effort.stdout.split("---")[0].strip() == "base_link", best_effort.stdout + best_effort.stderr
    raw = r["echo raw"].stdout
    assert raw.startswith("b'\\x00\\x01") and raw.endswith("\n---\n"), raw  # CDR's little-endian header
    info = r["echo info"].stdout.split("---\n")
    assert "source_timestamp:" in info[0] and info[1].strip() == "base_link", r["echo info"].stdout
    assert yaml.safe_load(r["echo filter"].stdout.split("---")[0])["child_frame_id"] == "base_link"
    assert "average rate:" in r["hz clock"].stdout
    info = r["info cmd_vel"].stdout
    assert "Subscription count: 1" in info and "Node name: differential_drive" in info
    assert "Node name: differential_drive" in r["info odom"].stdout
    assert r["find"].stdout.split() == ["/odom"]
    bw = r["bw"].stdout
    assert re.search(r"[\d.]+ K?B/s from \d+ messages\n\tMessage size mean: 724.00 B min: 724.00 B", bw), bw
    assert re.search(r"average delay: -?[\d.]+\n\tmin: ", r["delay"].stdout), r["delay"].stdout

    call = r["call"]
    assert call.returncode == 0, call.stderr
    # Jazzy's ros2cli prints the response's repr (ros2service/verb/call.py)
    assert "response:\ngazebo_msgs.srv.GetModelList_Response(" in call.stdout, call.stdout
    assert "model_names=['ground_plane', 'bot']" in call.stdout and "success=True" in call.stdout, call.stdout
    assert "/spawn_entity [gazebo_msgs/srv/SpawnEntity]" in r["service list"].stdout
    # the diff drive plugin is its own node, named as in Gazebo, its configuration its parameters
    nodes = r["node list"].stdout.split()
    assert {"/gazelle", "/differential_drive"} <= set(nodes)
    # one /gazelle: an earlier test's in-process bridge once left a half-destroyed one in the graph (its
    # simulate_steps action alone), and node info described that one (7 of 83 endpoints)
    assert nodes.count("/gazelle") == 1, nodes
    node = r["node info gazelle"].stdout
    if "/spawn_entity:" not in node:
        # 13 ros2 processes discovering at once on 2 cores: run alone, as a user would re-run it
        node = ros2("node", "info", "/gazelle").stdout
    assert "/clock: rosgraph_msgs/msg/Clock" in node and "/spawn_entity: gazebo_msgs/srv/SpawnEntity" in node, node
    assert "/cmd_vel" not in node  # the diff drive's own node subscribes to it
    # ros2node Jazzy's info: the node's actions in sections of their own, their hidden topics and services
    # (/simulate_steps/_action/...) left out unless --include-hidden
    actions = node.split("  Action Servers:\n", 1)[-1]
    assert "/gazelle/simulate_steps: simulation_interfaces/action/SimulateSteps" in actions, node
    assert "_action" not in node and "  Action Clients:\n" in node, node
    drive_info = r["node info drive"].stdout
    assert "/cmd_vel: geometry_msgs/msg/Twist" in drive_info and "/odom: nav_msgs/msg/Odometry" in drive_info
    shown = r["show srv"].stdout
    assert "string xml" in shown and "---" in shown
    odom_def = r["show odom"].stdout
    assert "string child_frame_id" in odom_def and "geometry_msgs/PoseWithCovariance pose" in odom_def
    assert yaml.safe_load(r["proto"].stdout.strip().strip('"')) == {
        "linear": {"x": 0.0, "y": 0.0, "z": 0.0},
        "angular": {"x": 0.0, "y": 0.0, "z": 0.0},
    }
    got = r["param get"]
    assert got.stdout.strip() == "Double value is: 0.34", got.stdout + got.stderr
    refused = r["param set"]
    assert refused.returncode == 1
    assert refused.stderr.strip() == "Setting parameter failed: Trying to set a read-only parameter: wheel_separation."
    dumped = yaml.safe_load(r["param dump"].stdout)
    assert dumped["/differential_drive"]["ros__parameters"]["odometry_frame"] == "odom"
    assert "Read only: true" in r["param describe"].stdout
    params = set(r["param list"].stdout.split())
    assert {"wheel_separation", "wheel_diameter", "odometry_frame", "use_sim_time"} <= params, params
    assert r["param nope"].stderr.strip() == "Node not found"
    bad_type, bad_field = r["bad type"], r["bad field"]
    assert bad_type.returncode == 1 and "The passed msg type 'geometry_msgs/msg/Twst' is invalid" in bad_type.stderr
    assert bad_field.returncode == 1 and "has no field 'linear.w'" in bad_field.stderr
    unknown_topic, unknown_package = r["unknown topic"], r["unknown package"]
    assert unknown_topic.returncode == 1
    assert unknown_topic.stderr.strip() == "Could not determine the type for the passed topic /no_such_topic"
    assert unknown_package.returncode == 1 and unknown_package.stderr.strip() == "Unknown package 'no_such_msgs'"
    for bad in (bad_type, bad_field, unknown_topic, unknown_package):
        assert "Traceback" not in bad.stderr and len(bad.stderr.strip().splitlines()) == 1, bad.stderr

    pub = start(
        [ROS2, "topic", "pub", "-r", "10", "/cmd_vel", "geometry_msgs/msg/Twist", "{linear: {x: 0.3}}"], "ros2 pub"
    )
    try:
        wait_for(lambda: ros_client.entity_state("bot").state.pose.position.x > 0.2, 30, "the robot to drive")
    finally:
        pub.interrupt()

    # /odom at 100 Hz (the plugin's update rate), measured in simulated time (-s, as ros2cli's hz measures
    # with its node's clock), so a loaded machine does not change it (on the wall clock a busy CI machine
    # saw 92 and 115 Hz); --filter as ros2cli's (a Python expression of the message `m`). The verb subscribes
    # as ros2cli's does (sensor data: best effort, depth 5), so on a starved CPU it can miss messages: a
    # fresh clone beside a CPU hog read 74, 87 and 91 Hz in windows of 75, 175 and 275 intervals (lost at
    # start-up), another under load 100, 100, then 96 and 91 (lost later: intervals of 0.18 and 0.28 s).
    # A lost message only lengthens an interval. What can shorten the measured time is the clock itself: the
    # verb stamps each arrival with its node's sim time, which moves only when a /clock message comes, so a
    # short window can read high (a fresh clone beside other test runs: 109 Hz in the first 109 intervals,
    # with intervals of 0 s between messages that came under one clock value, then 104.5, 100, 99.3). Over a
    # full 300-interval window (3 s) that error is under half a percent: there, no report reads above 100.5,
    # and one without a loss reads 100
    hz = ros2(
        "topic",
        "hz",
        "-s",
        "/odom",
        "-w",
        "300",
        "--count",
        "4",
        "--filter",
        "m.header.frame_id == 'odom'",
        timeout=120,
    )
    rates = [float(line.split(":")[1]) for line in hz.stdout.splitlines() if line.startswith("average rate:")]
    windows = [int(line.rsplit(":", 1)[1]) for line in hz.stdout.splitlines() if "window:" in line]
    assert len(rates) == 4 and windows[-1] == 300, hz.stdout + hz.stderr
    full = [r for r, w in zip(rates, windows, strict=True) if w == 300]
    assert full and max(full) <= 100.5, hz.stdout + hz.stderr
    assert any(r == pytest.approx(100.0, rel=0.01) for r in full), hz.stdout + hz.stderr

    # pausing from the command line stops /clock
    clocks: list = []
    ros_client.node.create_subscription(Clock, "/clock", clocks.append, 10)
    wait_for(lambda: clocks, 10, "/clock")
    paused = ros2("service", "call", "/pause_physics", "std_srvs/srv/Empty")
    assert paused.returncode == 0 and "response:" in paused.stdout, paused.stderr
    ros_client.entity_state("bot")  # a round trip: a /clock sent before the pause has arrived by now
    at_pause = clocks[-1].clock
    ros2("topic", "echo", "/clock", "--once", "--timeout", "2")  # 2 s of /clock, seen by a second node too
    assert clocks[-1].clock == at_pause, "/clock still advances while paused"
    ros2("service", "call", "/unpause_physics", "std_srvs/srv/Empty")


@pytest.mark.parametrize("sig", ["SIGINT", "SIGTERM"])
def test_echo_and_record_end_on_a_signal_without_a_traceback(sig: str, tmp_path: Path, ros_client) -> None:
    """Issue 26: `ros2 topic echo` and `ros2 bag record` printed a traceback on Ctrl-C or SIGTERM."""
    import signal as signals

    commands = (
        [ROS2, "topic", "echo", "/clock"],
        # still waiting for the topic's type: the signal lands in a graph wait, not in a spin (CI saw
        # rcl's "failed to initialize wait set: the given context is not valid" traceback there)
        [ROS2, "topic", "echo", "/not_published_yet"],
        [ROS2, "bag", "record", "-o", str(tmp_path / sig), "/clock"],
    )
    for cmd in commands:
        proc = start(cmd, " ".join(cmd[1:3]))
        pid = str(proc.popen.pid)
        # up and spinning: its node (named with its pid) is in the graph
        wait_for(lambda pid=pid: any(pid in n for n in ros_client.node.get_node_names()), 30, "the verb's node")
        proc.popen.send_signal(getattr(signals, sig))
        rc = proc.wait(20)
        assert "Traceback" not in proc.output, proc.output
        assert rc in (0, int(signals.SIGINT)), (rc, proc.output)


SHUT_DOWN_UNDER_A_WAIT = """
import rclpy
from gazelle.cli.ros2cli._graph import ShutDown, cli_node, wait_until
try:
    with cli_node("shutdown_probe") as node:
        rclpy.get_default_context().shutdown()  # what rclpy's signal handler does
        wait_until(node, lambda: None, 1.0)
except ShutDown:
    print("orderly end")
"""


def test_a_context_shut_down_between_two_graph_waits_is_an_orderly_end() -> None:
    """CI saw `ros2 topic echo` print rcl's "the given context is not valid" traceback when SIGTERM landed
    between two spins of a graph wait (the signal test above hits that window only now and then)."""
    out = subprocess.run([sys.executable, "-c", SHUT_DOWN_UNDER_A_WAIT], capture_output=True, text=True, timeout=60)
    assert out.stdout.strip() == "orderly end", out.stdout + out.stderr


SIGNAL_WHILE_SETTING_UP = """
import os, signal
import rclpy.executors as executors

made = executors.SingleThreadedExecutor.__init__


def init(self, *args, **kwargs):
    os.kill(os.getpid(), signal.SIGTERM)  # lands while the verb makes its executor
    made(self, *args, **kwargs)


executors.SingleThreadedExecutor.__init__ = init
from gazelle.cli.ros2cli import main

print("exit", main(["topic", "echo", "/nothing_here"]), flush=True)
"""


def test_a_signal_while_a_verb_sets_up_is_an_orderly_end() -> None:
    """CI: SIGTERM landed while `ros2 bag record` made its executor; the half-made executor's GuardCondition
    failed and its __del__ printed a traceback. Signals now wait until the verb is set up."""
    out = subprocess.run([sys.executable, "-c", SIGNAL_WHILE_SETTING_UP], capture_output=True, text=True, timeout=60)
    assert "exit 0" in out.stdout, out.stdout + out.stderr
    assert "Traceback" not in out.stderr, out.stderr


def test_a_reader_that_goes_away_ends_a_verb_quietly() -> None:
    """`ros2 interface list | head -2`: the reader closes the pipe; the verb ends as a Unix tool does (the
    status of a SIGPIPE, 141), with no BrokenPipeError traceback."""
    ros2 = subprocess.Popen([ROS2, "interface", "list"], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    assert ros2.stdout is not None and ros2.stderr is not None
    ros2.stdout.close()  # the reader goes away before the first line (after one, the rest may fit the pipe)
    assert ros2.wait(60) == 141
    assert "Traceback" not in ros2.stderr.read().decode()


def test_topic_pub_waits_for_its_subscriber_and_stamps_header_auto_as_ros2cli(ros_client) -> None:
    """ros2cli Jazzy's `ros2 topic pub` (ros2topic/verb/pub.py, rosidl_runtime_py/set_message.py): `--once`
    waits for a matching subscription however long it takes (gazelle's gave up after 5 s and published to
    nobody), `--max-wait-time-secs` bounds that wait, and `header: auto` is stamped with the node's clock at
    each publish (`-s`: /clock's time, which this test drives). Before: `header: auto` did not fit the field,
    and the two flags were unknown."""
    import os

    from builtin_interfaces.msg import Time
    from geometry_msgs.msg import TwistStamped

    topic = f"/stamped_{os.getpid()}"
    timed_out = ros2("topic", "pub", "--once", "--max-wait-time-secs", "1", topic, "geometry_msgs/msg/TwistStamped")
    assert timed_out.returncode == 1, timed_out.stdout + timed_out.stderr
    assert "Timed out waiting for subscribers: Expected 1 subcribers but only got 0" in timed_out.stderr
    assert "Waiting for at least 1 matching subscription(s)..." in timed_out.stdout

    values = "{header: auto, twist: {linear: {x: 0.25}}}"
    pub = start([ROS2, "topic", "pub", "--once", "-s", topic, "geometry_msgs/msg/TwistStamped", values], "ros2 pub")
    pub.wait_line("Waiting for at least 1 matching subscription(s)...", 30)
    clock = ros_client.node.create_publisher(Clock, "/clock", 10)
    ticks_after_match: list[int] = []

    def tick() -> bool:  # the simulated time stands at 42.5 s; the verb's clock hears it a few times
        clock.publish(Clock(clock=Time(sec=42, nanosec=500_000_000)))
        if clock.get_subscription_count() > 0:
            ticks_after_match.append(1)
        return len(ticks_after_match) >= 25

    wait_for(tick, 30, "the verb's clock to hear /clock")
    got: list[TwistStamped] = []
    ros_client.node.create_subscription(TwistStamped, topic, got.append, 10)
    wait_for(lambda: got, 30, "the message, published once the subscription matched")
    assert pub.wait(30) == 0, pub.output
    assert got[0].twist.linear.x == 0.25
    assert (got[0].header.stamp.sec, got[0].header.stamp.nanosec) == (42, 500_000_000)
    assert len(got) == 1 and "publishing #1: geometry_msgs.msg.TwistStamped(" in pub.output


def test_service_call_waits_for_its_service_and_prints_as_ros2cli(ros_client) -> None:
    """ros2cli Jazzy's `ros2 service call` (ros2service/verb/call.py) waits for the service however long it
    takes, saying "waiting for service to become available..." (gazelle's gave up after 10 s), and prints
    the request and the response as their reprs (gazelle's printed YAML)."""
    import os

    from std_srvs.srv import SetBool

    name = f"/switch_{os.getpid()}"
    call = start([ROS2, "service", "call", name, "std_srvs/srv/SetBool", "{data: true}"], "ros2 service call")
    call.wait_line("waiting for service to become available...", 30)
    asked: list = []

    def answer(request, response):
        asked.append(request.data)
        response.success, response.message = True, "switched"
        return response

    ros_client.node.create_service(SetBool, name, answer)
    assert call.wait(30) == 0, call.output
    assert asked == [True]
    assert "requester: making request: std_srvs.srv.SetBool_Request(data=True)" in call.output, call.output
    assert "response:\nstd_srvs.srv.SetBool_Response(success=True, message='switched')" in call.output, call.output
    piped = subprocess.run(  # the values from standard input (ros2cli's --stdin)
        [ROS2, "service", "call", name, "std_srvs/srv/SetBool", "--stdin"],
        input="data: false\n",
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert piped.returncode == 0 and asked == [True, False], piped.stdout + piped.stderr


def test_param_load_lets_the_nodes_own_section_win_over_the_wildcard(ros_client, tmp_path: Path) -> None:
    """rclpy's parameter_dict_from_yaml_file (Jazzy) reads the `/**` section first and the node's own after
    it, so the node's value wins; gazelle's `ros2 param load` read them the other way round."""
    ros_client.node.declare_parameter("gain", 0.0)
    params = tmp_path / "gains.yaml"
    params.write_text(
        "/**:\n  ros__parameters:\n    gain: 1.0\n    wild_only: 3\n"
        f"{ros_client.node.get_fully_qualified_name()}:\n  ros__parameters:\n    gain: 2.0\n"
    )
    ros_client.node.declare_parameter("wild_only", 0)
    loaded = ros2("param", "load", ros_client.node.get_fully_qualified_name(), str(params))
    assert loaded.returncode == 0, loaded.stdout + loaded.stderr
    assert ros_client.node.get_parameter("gain").value == 2.0
    assert ros_client.node.get_parameter("wild_only").value == 3


def test_interface_show_expands_nested_types_and_packages_lists_them_as_jazzy() -> None:
    """ros2interface Jazzy's show (verb/show.py) prints each message field's own definition a tab further
    in, the top level's comments unless --no-comments; `packages` lists the packages with interfaces.
    gazelle printed the file alone and had no `packages`."""
    shown = ros2("interface", "show", "geometry_msgs/msg/PoseStamped")
    assert shown.returncode == 0, shown.stderr
    assert shown.stdout.startswith("# A Pose with reference coordinate frame and timestamp\n\nstd_msgs/Header header\n")
    assert "\tbuiltin_interfaces/Time stamp\n\t\tint32 sec\n\t\tuint32 nanosec\n\tstring frame_id\n" in shown.stdout
    assert "\tQuaternion orientation\n\t\tfloat64 x 0\n" in shown.stdout
    bare = ros2("interface", "show", "--no-comments", "std_srvs/srv/SetBool").stdout
    assert bare == "bool data\n---\nbool success\nstring message\n", bare
    piped = subprocess.run(
        [ROS2, "interface", "show", "-"], input="std_srvs/srv/Trigger\n", capture_output=True, text=True, timeout=60
    )
    assert piped.returncode == 0 and "string message" in piped.stdout, piped.stderr
    packages = ros2("interface", "packages").stdout.split()
    assert {"geometry_msgs", "moveit_msgs", "std_srvs"} <= set(packages) and packages == sorted(packages)
    assert "geometry_msgs" not in ros2("interface", "packages", "-a").stdout.split()
