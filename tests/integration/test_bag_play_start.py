"""Issue 50 item 7: ``ros2 bag play`` loses nothing at its start. A listener started before play lost the first
~1.1 s of a bag (387 and 397 of 503 /odom messages): the player published while discovery had not yet
matched it with the listener. Play now waits until the readers already in the graph are matched."""

from __future__ import annotations

import os
import struct
import subprocess
import sys
from pathlib import Path

import pytest
import yaml
from _harness import start

ROS2 = str(Path(sys.prefix) / "bin" / "ros2")
pytestmark = pytest.mark.slow

COUNT = 300

LISTENER = """
import sys, time
import rclpy
from std_msgs.msg import Int32

rclpy.init()
node = rclpy.create_node("counted_listener")
got = []
node.create_subscription(Int32, "/counted", lambda m: got.append(m.data), 1000)
print("ready", flush=True)
deadline = time.monotonic() + 60
while len(got) < {count} and time.monotonic() < deadline:
    rclpy.spin_once(node, timeout_sec=0.05)
    if got and time.monotonic() - last > 5:
        break
    last = time.monotonic() if not got else last
print("got", ",".join(map(str, got)), flush=True)
"""


def _bag(folder: Path, count: int) -> Path:
    """A rosbag2 MCAP bag of ``count`` std_msgs/Int32 on /counted, 0..count-1, 10 ms apart."""
    from mcap.writer import Writer

    folder.mkdir(parents=True)
    with open(folder / f"{folder.name}_0.mcap", "wb") as f:
        writer = Writer(f)
        writer.start(profile="ros2", library="test")
        schema = writer.register_schema(name="std_msgs/msg/Int32", encoding="ros2msg", data=b"int32 data\n")
        channel = writer.register_channel(topic="/counted", message_encoding="cdr", schema_id=schema)
        for i in range(count):
            t = 1_000_000_000 + i * 10_000_000
            writer.add_message(
                channel_id=channel, log_time=t, publish_time=t, data=b"\x00\x01\x00\x00" + struct.pack("<i", i)
            )
        writer.finish()
    meta = {
        "rosbag2_bagfile_information": {
            "version": 9,
            "storage_identifier": "mcap",
            "duration": {"nanoseconds": (count - 1) * 10_000_000},
            "starting_time": {"nanoseconds_since_epoch": 1_000_000_000},
            "message_count": count,
            "topics_with_message_count": [
                {
                    "topic_metadata": {
                        "name": "/counted",
                        "type": "std_msgs/msg/Int32",
                        "serialization_format": "cdr",
                        "offered_qos_profiles": "",
                    },
                    "message_count": count,
                }
            ],
            "relative_file_paths": [f"{folder.name}_0.mcap"],
            "ros_distro": "jazzy",
        }
    }
    (folder / "metadata.yaml").write_text(yaml.safe_dump(meta))
    return folder


@pytest.mark.parametrize("run", range(3))
def test_a_listener_started_before_play_gets_every_message(tmp_path: Path, ros_env, run: int) -> None:
    """Three plays of a 3 s bag, each to a listener that said it was ready first, with no ``--delay``: every
    message arrives, in order (before: the first ones were lost whenever discovery was slower than the
    player's fixed 0.5 s look at the graph)."""
    bag = _bag(tmp_path / "bag", COUNT)
    script = tmp_path / "listener.py"
    script.write_text(LISTENER.replace("{count}", str(COUNT)).replace("deadline = ", "last = 0\ndeadline = "))
    listener = start([sys.executable, str(script)], "listener")
    listener.wait_line("ready", 30)
    play = subprocess.run([ROS2, "bag", "play", str(bag)], capture_output=True, text=True, timeout=60, env=os.environ)
    assert play.returncode == 0, play.stdout + play.stderr
    assert listener.wait(30) == 0
    (line,) = [ln for ln in listener.lines if ln.startswith("got")]
    got = [int(x) for x in line.split(" ", 1)[1].split(",") if x]
    assert got == list(range(COUNT)), f"{len(got)} of {COUNT}, the first {got[:1]}"
