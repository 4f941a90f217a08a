"""Issue 26: launch files that run `gzserver` and `gzclient` directly (Husky's, Clearpath's, tutorials')
failed with `No such file or directory: 'gzserver'`."""

from __future__ import annotations

import os
import sys
from pathlib import Path

from _harness import start, wait_for

from gazelle.cli._gzserver import gzserver_args


def test_gzserver_options_map_to_gazelle_sim(monkeypatch) -> None:
    monkeypatch.delenv("GAZELLE_GZSERVER_VIEWER", raising=False)
    args, ignored = gzserver_args(
        ["-u", "--verbose", "-s", "libgazebo_ros_init.so", "-s", "/opt/x/libgazebo_ros_factory.so", "w.world",
         "-e", "ode", "-s", "libmy_plugin.so"]
    )  # fmt: skip
    assert args == ["w.world", "--paused"]
    assert ignored == ["--verbose", "-e ode", "-s libmy_plugin.so"]


def test_gzserver_and_gzclient_run_as_a_launch_file_runs_them(tmp_path: Path) -> None:
    bin_dir = Path(sys.executable).parent  # the venv's console scripts
    world = tmp_path / "empty.world"
    world.write_text(
        '<sdf version="1.6"><world name="empty"><include><uri>model://ground_plane</uri></include></world></sdf>'
    )
    env = {**os.environ, "GAZELLE_GZSERVER_VIEWER": "0"}
    server = start(
        [str(bin_dir / "gzserver"), str(world), "-u", "-s", "libgazebo_ros_init.so", "--verbose"], "gzserver", env
    )
    client = start([str(bin_dir / "gzclient")], "gzclient", env)
    try:
        server.wait_line("gazelle: ready: world 'empty'", 60)
        assert "not used: --verbose" in server.output
        # started paused (-u), it says so and how to run it: a world that stood still silently looked broken
        assert "PAUSED: time stands still until" in server.output
        client.wait_line("the simulation is drawn in the browser", 30)
    finally:
        assert client.interrupt() == 0, client.output
        assert server.interrupt() == 0, server.output


def test_gzclient_prints_the_viewer_address_the_server_really_took(tmp_path: Path) -> None:
    """Issue 49: gzclient always printed http://127.0.0.1:8080, even when that port was taken and the server's
    viewer went to the next one, so the user watched another simulation. The server announces its viewer's real
    address; gzclient, started first here, prints that one when it comes."""
    import socket

    bin_dir = Path(sys.executable).parent
    held = socket.socket()
    held.bind(("127.0.0.1", 0))
    held.listen()
    port = held.getsockname()[1]
    client = start([str(bin_dir / "gzclient")], "gzclient")
    server = start([str(bin_dir / "gazelle"), "sim", "--viewer-port", str(port)], "gazelle sim")
    try:
        server.wait_line("gazelle: viewer at ", 60)
        url = server.output.split("gazelle: viewer at ", 1)[1].split()[0]
        assert not url.endswith(f":{port}"), url  # the port was taken: the viewer is elsewhere
        client.wait_line(f"open {url}", 30)
        assert ":8080" not in client.output or url.endswith(":8080")
    finally:
        held.close()
        assert client.interrupt() == 0, client.output
        assert server.interrupt() == 0, server.output


def test_rviz2_stand_in_points_at_the_viewer_and_stays_up(tmp_path: Path) -> None:
    """A launch file that starts rviz2 (`-d config.rviz`) aborted on the missing package; the stand-in says
    once where the viewer is (none yet here: it says what it waits for) and stays up until stopped."""
    ros2 = str(Path(sys.executable).parent / "ros2")
    rviz = start([ros2, "run", "rviz2", "rviz2", "-d", str(tmp_path / "view.rviz")], "rviz2")
    try:
        rviz.wait_line("RViz is not part of gazelle", 30)
        assert "view.rviz is not read" in rviz.output
        assert rviz.popen.poll() is None
    finally:
        assert rviz.interrupt() == 0, rviz.output


def test_image_bridge_says_where_images_are_and_relays_a_remapped_topic(ros_client) -> None:
    """ros_gz_image's image_bridge was missing and aborted the launch. gazelle publishes camera images under the
    gz topic's name already: the stand-in says so, and relays a topic its remapping rules rename."""
    from sensor_msgs.msg import Image

    ros2 = str(Path(sys.executable).parent / "ros2")
    plain = start([ros2, "run", "ros_gz_image", "image_bridge", "/rgbd_camera/image"], "image_bridge")
    renamed = start(
        [ros2, "run", "ros_gz_image", "image_bridge", "/cam/image", "--ros-args", "-r", "/cam/image:=/cam/renamed"],
        "image_bridge remapped",
    )
    try:
        plain.wait_line("/rgbd_camera/image already; nothing to bridge", 30)
        renamed.wait_line("relaying /cam/image -> /cam/renamed", 30)
        got: list[Image] = []
        ros_client.node.create_subscription(Image, "/cam/renamed", got.append, 10)
        pub = ros_client.node.create_publisher(Image, "/cam/image", 10)

        def relayed() -> bool:
            pub.publish(Image(width=2, height=1, encoding="mono8", step=2, data=[1, 2]))
            return bool(got)

        wait_for(relayed, 30, "an image relayed to /cam/renamed", interval=0.1)
        assert got[0].width == 2
    finally:
        assert plain.interrupt() == 0, plain.output
        assert renamed.interrupt() == 0, renamed.output
