"""gz-sim's PosePublisher (src/systems/pose_publisher/PosePublisher.cc): a model's poses, each in its parent's
frame, on `/model/<model>/pose` (and `_static`), in-process against the simulated pendulum's own poses."""

from __future__ import annotations

import logging

import pytest
from _sim import new_simulation

from gazelle.description import Pose, load_string
from gazelle.systems._registry import plugin_table
from gazelle.systems.gz_pose_publisher import PosePublisher

# a pendulum welded to the world: 'base' (the canonical link) holds the hinge, 'arm' swings half a metre from it
PENDULUM = """<sdf version="1.9"><model name="pendulum">
  <joint name="weld" type="fixed"><parent>world</parent><child>base</child></joint>
  <link name="base"><pose>0 0 1 0 0 0</pose><inertial><mass>1</mass></inertial>
    <visual name="v"><pose>0 0 0.1 0 0 0</pose><geometry><box><size>0.1 0.1 0.1</size></box></geometry></visual>
  </link>
  <link name="arm"><pose>0.5 0 1 0 0 0</pose><inertial><mass>1</mass></inertial>
    <collision name="c"><geometry><sphere><radius>0.05</radius></sphere></geometry></collision>
    <sensor name="imu" type="imu"><pose>0 0 0.2 0 0 0</pose></sensor>
  </link>
  <joint name="hinge" type="revolute"><pose relative_to="base"/><parent>base</parent><child>arm</child>
    <axis><xyz>0 1 0</xyz></axis></joint>
  <plugin filename="gz-sim-pose-publisher-system" name="gz::sim::systems::PosePublisher">{}</plugin>
</model></sdf>"""
SPAWN = Pose((1.0, 2.0, 0.0))


def _spawn(params: str = ""):
    sim = new_simulation()
    entity = sim.spawn(load_string(PENDULUM.format(params)).model, name="p", pose=SPAWN)
    return sim, next(s for s in entity.systems if isinstance(s, PosePublisher))


def _listen(sim, topic: str) -> list:
    got: list = []
    next(e for e in sim.bus.endpoints() if e.topic == topic).add_sink(got.append)
    return got


def test_every_gz_and_ignition_spelling_runs_it() -> None:
    table = plugin_table()
    for name in (
        "gz-sim-pose-publisher-system",
        "gz::sim::systems::PosePublisher",
        "ignition-gazebo-pose-publisher-system",
        "ignition::gazebo::systems::PosePublisher",
    ):
        assert table[name] is PosePublisher


def test_by_default_each_links_pose_in_the_model_frame_at_every_step_one_message_each() -> None:
    """Upstream's defaults: links only, ``<update_frequency>`` -1 (every step), one gz Pose (here a TFMessage of
    one transform) per link, frame_id the model and child_frame_id ``model::link``."""
    sim, pub = _spawn()
    assert pub.config.publish_link_pose and not pub.config.publish_model_pose and pub.config.update_frequency == -1
    got = _listen(sim, "/model/p/pose")
    sim.step(300)
    assert len(got) == 2 * 300
    assert all(len(m.transforms) == 1 for m in got)
    assert [(tf.parent, tf.child) for m in got[-2:] for tf in m.transforms] == [("p", "p::base"), ("p", "p::arm")]
    base, arm = got[-2].transforms[0], got[-1].transforms[0]
    assert base.stamp_sec == arm.stamp_sec == pytest.approx(float(sim.world.data.time))
    assert base.pose.position == pytest.approx((0.0, 0.0, 1.0), abs=1e-9)  # welded: where the file put it
    # the arm swung: its pose in the model frame is the spawn pose's inverse times its world pose
    X_WA = sim.world.entity_state("p", "arm").pose
    assert arm.pose.position == pytest.approx((SPAWN.inverse() * X_WA).position, abs=1e-9)
    assert arm.pose.position[2] < 0.9  # it fell from 1 m
    hinge_to_arm = [a - b for a, b in zip(arm.pose.position, base.pose.position, strict=True)]
    assert sum(d * d for d in hinge_to_arm) == pytest.approx(0.25, rel=1e-3)  # half a metre from the hinge


def test_a_static_publisher_sends_what_no_joint_moves_on_pose_static_in_one_vector() -> None:
    """``<static_publisher>``: the arm (moved by the hinge) on the topic at 100 Hz; the model, the canonical base,
    its visual and the arm's sensor on ``_static`` at 10 Hz; ``<use_pose_vector_msg>``: one message an update."""
    sim, pub = _spawn(
        "<static_publisher>true</static_publisher><use_pose_vector_msg>true</use_pose_vector_msg>"
        "<publish_model_pose>true</publish_model_pose><publish_visual_pose>true</publish_visual_pose>"
        "<publish_sensor_pose>true</publish_sensor_pose><update_frequency>100</update_frequency>"
        "<static_update_frequency>10</static_update_frequency>"
    )
    dynamic, static = _listen(sim, "/model/p/pose"), _listen(sim, "/model/p/pose_static")
    sim.step(500)
    assert len(dynamic) == pytest.approx(50, abs=1) and len(static) == pytest.approx(5, abs=1)
    assert [(tf.parent, tf.child) for tf in dynamic[-1].transforms] == [("p", "p::arm")]
    assert [(tf.parent, tf.child) for tf in static[-1].transforms] == [
        ("world", "p"),
        ("p", "p::base"),
        ("p::base", "p::base::v"),
        ("p::arm", "p::arm::imu"),
    ]
    model, _base, visual, imu = static[-1].transforms
    assert model.pose.position == pytest.approx(SPAWN.position, abs=1e-9)
    assert visual.pose.position == pytest.approx((0.0, 0.0, 0.1)) and imu.pose.position == pytest.approx((0, 0, 0.2))


def test_an_invalid_topic_is_upstreams_error_and_the_model_pose_follows_the_nested_flag(caplog) -> None:
    with caplog.at_level(logging.ERROR):
        sim, pub = _spawn("<topic>bad topic</topic><publish_nested_model_pose>true</publish_nested_model_pose>")
    assert "Provided topic: bad topic is not a valid topic." in caplog.text
    assert pub.config.publish_model_pose  # upstream's default: publish_nested_model_pose's value
    got = _listen(sim, "/model/p/pose")
    sim.step(1)
    assert [m.transforms[0].child for m in got] == ["p", "p::base", "p::arm"]
