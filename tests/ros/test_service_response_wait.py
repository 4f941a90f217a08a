"""The server side of a dropped first service response (issue 50's CI failure: ``set_parameters`` unanswered
for 15 s beside the suite). rmw_fastrtps sends a response only once the server's response writer has matched
the client's response reader, and waits for that at most the response writer's ``max_blocking_time``
(rmw_fastrtps_shared_cpp/src/rmw_response.cpp, ``check_for_subscription``): Fast DDS's default is 0.1 s, and a
fresh client calling a busy server at once lost its response. gazelle's processes load ``fastdds_announce.xml``,
whose ``service`` profile (the one rmw_fastrtps_cpp/src/rmw_service.cpp loads for every service's response
writer) waits up to 5 s.

The test makes the match impossible (a client whose response reader asks for transient-local durability, which
the server's volatile response writer never offers; its request still reaches the server) and times how long a
gazelle process's service waits before it gives the response up: 0.100 s before, 5 s after. ~8 s."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap

from _ros_domain import reserved_domain_id

from gazelle.testing._dds_profile import without_writer_profile

SERVER = textwrap.dedent(
    """
    import sys, time
    from gazelle.ros._dds import announce_often
    announce_often()  # what gazelle's processes do before their first participant
    import rclpy
    from rclpy.service import Service
    from std_srvs.srv import Trigger
    sent = Service.send_response
    def timed(self, response, header):
        t = time.monotonic()
        sent(self, response, header)
        print(f"send_response {time.monotonic() - t:.3f}", flush=True)
        sys.exit(0)
    Service.send_response = timed
    rclpy.init()
    node = rclpy.create_node("gazelle_probe_server")
    node.create_service(Trigger, "/gazelle_probe", lambda req, res: res)
    print("ready", flush=True)
    end = time.monotonic() + 30
    while time.monotonic() < end:
        rclpy.spin_once(node, timeout_sec=0.1)
    """
)

CLIENT = textwrap.dedent(
    """
    import time
    import rclpy
    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
    from std_srvs.srv import Trigger
    rclpy.init()
    node = rclpy.create_node("probe_client")
    qos = QoSProfile(depth=10, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE)
    client = node.create_client(Trigger, "/gazelle_probe", qos_profile=qos)
    end = time.monotonic() + 25
    while time.monotonic() < end:  # one request a second until the server has taken one (it then exits)
        client.call_async(Trigger.Request())
        rclpy.spin_once(node, timeout_sec=1.0)
    """
)


def test_a_gazelle_process_waits_for_the_client_s_response_reader_before_giving_a_response_up() -> None:
    env = {**without_writer_profile(dict(os.environ)), "ROS_DOMAIN_ID": str(reserved_domain_id())}
    env.pop("FASTRTPS_DEFAULT_PROFILES_FILE", None)
    server = subprocess.Popen(
        [sys.executable, "-c", SERVER], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env
    )
    client = None
    try:
        assert server.stdout is not None
        assert server.stdout.readline().strip() == "ready"
        client = subprocess.Popen(
            [sys.executable, "-c", CLIENT], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env
        )
        out, err = server.communicate(timeout=40)
    finally:
        for proc in (server, client):
            if proc is not None and proc.poll() is None:
                proc.kill()
    assert "XMLPARSER" not in err, f"gazelle's Fast DDS profile did not parse (all of it is then ignored): {err}"
    waited = float(out.split("send_response")[-1].split()[0])
    assert waited >= 4.5, f"the response writer gave the response up after {waited} s (Fast DDS's default: 0.1 s)"
