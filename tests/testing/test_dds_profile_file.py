"""The test process's Fast DDS profile (gazelle/testing/fastdds_test_node.xml) parses, and keeps
intra-process delivery off: with it on, Fast DDS 2.14 deadlocked a test's teardown once beside a CPU hog (a
writer's removal delivered to another participant of the process under the writer's lock while that
participant's event thread held its discovery lock and waited for the writer). A file Fast DDS cannot parse
is ignored whole, so the heartbeat and the setting would both be lost without a word but this test."""

from __future__ import annotations

import os
import subprocess
import sys
import xml.etree.ElementTree as ET

from gazelle.testing._dds_profile import WRITER_PROFILE

NS = "{http://www.eprosima.com}"


def test_the_test_node_profile_turns_intraprocess_delivery_off() -> None:
    root = ET.parse(WRITER_PROFILE).getroot()
    setting = root.find(f"{NS}library_settings/{NS}intraprocess_delivery")
    assert setting is not None and (setting.text or "").strip() == "OFF"


def test_fast_dds_parses_the_test_node_profile_without_an_error() -> None:
    env = {**os.environ, "FASTRTPS_DEFAULT_PROFILES_FILE": str(WRITER_PROFILE), "ROS_DOMAIN_ID": "231"}
    env.pop("FASTDDS_DEFAULT_PROFILES_FILE", None)
    code = "import rclpy; rclpy.init(); n = rclpy.create_node('profile_check'); n.destroy_node(); rclpy.shutdown()"
    done = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr[-2000:]
    assert "XMLPARSER" not in done.stderr, done.stderr[-2000:]
