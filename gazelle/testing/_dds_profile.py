"""The Fast DDS settings of a test process's own writers: a reliable writer asks its subscribers for their
acknowledgements every 5 ms instead of Fast DDS's 3 s, so that a step waiting for what the test published
to be acknowledged (``Publisher.wait_for_all_acked``) waits milliseconds.

Fast DDS reads its default profiles file once per process, when the process's first participant is made:
the variable has to be set before that (gazelle's pytest plugin sets it when pytest starts, before any
test made an rclpy node). No rclpy here: the plugin imports this.
"""

from __future__ import annotations

import os
from pathlib import Path

WRITER_PROFILE = Path(__file__).with_name("fastdds_test_node.xml")
"""Fast DDS's settings for the test's node: heartbeats every 5 ms, so acknowledgements come at once."""

PROFILE_VARIABLES = ("FASTRTPS_DEFAULT_PROFILES_FILE", "FASTDDS_DEFAULT_PROFILES_FILE")


def writer_profile() -> dict[str, str]:
    """The environment that gives this process's Fast DDS participants :data:`WRITER_PROFILE`: nothing when
    the user set a profile file of their own (each step after a publish may then wait for Fast DDS's 3 s
    heartbeat) or uses another RMW."""
    if any(os.environ.get(v) for v in PROFILE_VARIABLES) or not WRITER_PROFILE.is_file():
        return {}
    if os.environ.get("RMW_IMPLEMENTATION", "rmw_fastrtps_cpp") not in ("rmw_fastrtps_cpp", "rmw_fastrtps_dynamic_cpp"):
        return {}
    # the second variable tells gazelle's own processes the test starts that this profile is not the user's
    # (gazelle/ros/_dds.py's announce_often then still gives them theirs)
    return {"FASTRTPS_DEFAULT_PROFILES_FILE": str(WRITER_PROFILE), "GAZELLE_TEST_WRITER_PROFILE": str(WRITER_PROFILE)}


def without_writer_profile(env: dict[str, str]) -> dict[str, str]:
    """``env`` for a process the test starts (the server, a user's node): the test process's own writer
    profile taken out, so those processes keep Fast DDS's defaults (or the user's own file)."""
    return {k: v for k, v in env.items() if not (k in PROFILE_VARIABLES and v == str(WRITER_PROFILE))}
