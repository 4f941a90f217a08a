"""gz topic names that ROS refuses: gz-sim's JointPositionController listens on
/model/<m>/joint/<j>/0/cmd_pos, and a ROS token must not start with a digit. The arm spawns, the topic
is on ROS as .../n0/cmd_pos and moves the joint; a name ROS cannot take at all is an error naming it, and
the entity still spawns."""

from __future__ import annotations

import logging

import pytest
from _harness import wait_for
from std_msgs.msg import Float64
from systems.test_systems import ARM

pytestmark = pytest.mark.ros


def test_gz_names_get_an_n_before_tokens_that_start_with_a_digit():
    from gazelle.ros._names import gz_topic_on_ros

    assert gz_topic_on_ros("/model/arm/joint/shoulder/0/cmd_pos") == "/model/arm/joint/shoulder/n0/cmd_pos"
    assert (
        gz_topic_on_ros("/world/default/model/r/link/l/sensor/s/scan") == "/world/default/model/r/link/l/sensor/s/scan"
    )
    assert gz_topic_on_ros("/a/12b/c3") == "/a/n12b/c3"


def test_a_gz_position_controller_on_its_default_topic_spawns_and_is_commanded_over_ros(ros_client, caplog, make_sim):
    from gazelle.description import load_string
    from gazelle.ros import RosBridge

    plugins = (
        '<plugin filename="gz-sim-joint-position-controller-system" name="gz::sim::systems::JointPositionController">'
        "<joint_name>shoulder</joint_name><p_gain>200</p_gain><i_gain>50</i_gain><d_gain>10</d_gain>"
        "<i_max>10</i_max><i_min>-10</i_min></plugin>"
        '<plugin filename="gz-sim-joint-controller-system" name="gz::sim::systems::JointController">'
        "<joint_name>spin</joint_name><topic>/arm/spin cmd</topic></plugin>"
    )
    sim = make_sim(rtf=1.0)
    bridge = RosBridge(sim)
    try:
        with caplog.at_level(logging.ERROR):
            sim.spawn(load_string(ARM % plugins).model, name="arm")  # raised InvalidTopicNameException before
        errors = [r.getMessage() for r in caplog.records if "not a valid ROS name" in r.getMessage()]
        assert len(errors) == 1 and "'/arm/spin cmd'" in errors[0] and errors[0].startswith("'arm'"), errors
        sim.start()
        topic = "/model/arm/joint/shoulder/n0/cmd_pos"
        wait_for(lambda: ros_client.node.count_subscribers(topic) == 1, 15, f"the simulation subscribed to {topic}")
        pub = ros_client.node.create_publisher(Float64, topic, 10)

        def shoulder() -> float:
            qadr, _ = sim.world.joint_address("arm", "shoulder")
            return float(sim.world.data.qpos[qadr])

        def moved() -> bool:
            pub.publish(Float64(data=-0.8))
            return abs(sim.call(shoulder) + 0.8) < 0.01

        wait_for(moved, 20, "the shoulder at -0.8 rad", interval=0.2)
        ros_client.node.destroy_publisher(pub)
    finally:
        sim.stop()
        bridge.shutdown()


def test_a_gz_air_pressure_sensor_is_heard_over_ros_as_sensor_msgs_fluid_pressure(tmp_path) -> None:
    """The new sensor kind's own declared message goes through the ROS bridge's generic conversion:
    a real `gazelle sim` and a plain subscriber."""
    from sensor_msgs.msg import FluidPressure

    from gazelle.testing import Sim, reserve_domain

    world = tmp_path / "baro.sdf"
    world.write_text(
        '<?xml version="1.0"?><sdf version="1.9"><world name="w">'
        '<plugin filename="gz-sim-air-pressure-system" name="gz::sim::systems::AirPressure"/>'
        '<model name="baro"><static>true</static><pose>0 0 1 0 0 0</pose><link name="l">'
        '<sensor name="p" type="air_pressure"><update_rate>10</update_rate><topic>baro</topic></sensor>'
        "</link></model></world></sdf>"
    )
    domain = reserve_domain()
    sim = Sim(domain_id=domain.domain_id, world=world)
    try:
        heard = sim.ros.subscribe("/baro", FluidPressure)
        sim.run_for(1.0)
        heard.wait(5, 30)
        assert heard.last.header.frame_id == "baro::l::p"
        assert heard.last.fluid_pressure == pytest.approx(101313.0, abs=1.0)  # 1 m above sea level
    finally:
        sim.close()
        domain.release()
