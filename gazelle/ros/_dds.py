"""DDS settings of gazelle's own long-lived processes.

A ROS process that starts finds the participants already running when they next announce themselves,
and Fast DDS announces every 3 s: a new node waited 0-3 s (uniformly: measured 0.00-2.75 s for
``gazelle arm`` to find move_group's parameter service) before it could call anything. gazelle's
servers (the simulation, move_group, robot_state_publisher, and the Foxglove bridge the simulation
starts) announce every 0.1 s instead, so users' nodes, ``gazelle spawn`` and the tests find them at
once. Users' own processes are left as they are.
"""

from __future__ import annotations

import os
from pathlib import Path

ANNOUNCE_PROFILE = Path(__file__).with_name("fastdds_announce.xml")
PROFILE_VARIABLES = ("FASTRTPS_DEFAULT_PROFILES_FILE", "FASTDDS_DEFAULT_PROFILES_FILE")
TEST_PROFILE_VARIABLE = "GAZELLE_TEST_WRITER_PROFILE"
"""Names the profile a gazelle test process set for its own writers (gazelle/testing/_dds_profile.py)."""
FAST_DDS = ("rmw_fastrtps_cpp", "rmw_fastrtps_dynamic_cpp")


def announce_often() -> bool:
    """Before this process's first DDS participant: have its participants announce every 0.1 s.

    Nothing changes when the user gave Fast DDS a profile of their own or chose another RMW. The profile a
    gazelle test process gives its own writers (named in ``GAZELLE_TEST_WRITER_PROFILE`` by the pytest plugin)
    is not the user's: a server or node the test starts inherits it, and still announces often (without it, a
    ``ros2`` verb the test ran found the server at its 3 s announcement, or missed it).
    Returns whether the profile was set (the children this process starts inherit it)."""
    inherited = os.environ.get(TEST_PROFILE_VARIABLE)
    if any(os.environ.get(v) and os.environ.get(v) != inherited for v in PROFILE_VARIABLES):
        return False
    if os.environ.get("RMW_IMPLEMENTATION", FAST_DDS[0]) not in FAST_DDS or not ANNOUNCE_PROFILE.is_file():
        return False
    os.environ["FASTRTPS_DEFAULT_PROFILES_FILE"] = str(ANNOUNCE_PROFILE)
    return True
