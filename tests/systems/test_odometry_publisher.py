"""gz-sim's OdometryPublisher (gz-sim 8, src/systems/odometry_publisher/OdometryPublisher.cc): the model frame's
odometry on `/model/<model>/odometry`, its covariance twin and the odom -> base transform, in-process."""

from __future__ import annotations

import logging

import pytest
from _sim import new_simulation

from gazelle.description import Pose, load_string
from gazelle.systems.gz_diff_drive import GzDiffDrive
from gazelle.systems.odometry_publisher import OdometryPublisher

from .test_systems import gz_plugin, seed_urdf, system

ODOM = '<plugin filename="gz-sim-odometry-publisher-system" name="gz::sim::systems::OdometryPublisher">{}</plugin>'


def _listen(sim, topic: str) -> list:
    got: list = []
    next(e for e in sim.bus.endpoints() if e.topic == topic).add_sink(got.append)
    return got


def test_it_publishes_the_model_frames_odometry_on_gz_topics_at_50_hz() -> None:
    sim = new_simulation()
    # the DiffDrive's encoder odometry defaults to the same topic, as in gz: moved out of the way here
    model = load_string(seed_urdf(gz_plugin("<odom_topic>wheel_odom</odom_topic>") + ODOM.format(""))).model
    entity = sim.spawn(model, name="robot", pose=Pose((0.0, 0.0, 0.05)))
    pub = system(entity, OdometryPublisher)
    assert (pub.frame_id, pub.child_frame_id) == ("robot/odom", "robot/base_footprint")
    odom, cov, tf = (_listen(sim, f"/model/robot/{t}") for t in ("odometry", "odometry_with_covariance", "pose"))
    system(entity, GzDiffDrive).command(0.3, 0.4)
    sim.step(2000)
    assert len(odom) == len(cov) == len(tf) == pytest.approx(100, abs=1)  # 2 s at 50 Hz
    last = odom[-1]
    truth = sim.world.entity_state("robot")
    assert last.pose.position[:2] == pytest.approx(truth.pose.position[:2], abs=0.01)
    assert last.pose.position[2] == 0.0  # 2 dimensions: the height is left out
    assert last.pose.rpy[2] == pytest.approx(truth.pose.rpy[2], abs=0.02)
    assert last.twist.linear[0] == pytest.approx(0.3, rel=0.05)  # in the body frame, not the world's
    assert abs(last.twist.linear[1]) < 0.02
    assert last.twist.angular[2] == pytest.approx(0.4, rel=0.1)
    assert cov[-1].pose_covariance == (0.0,) * 36
    assert (tf[-1].transforms[0].parent, tf[-1].transforms[0].child) == ("robot/odom", "robot/base_footprint")


def test_an_sdf_models_frame_not_its_link_and_the_offsets_noise_and_dimensions() -> None:
    """The pose is the model frame's (the chassis sits 0.15 m behind it), times the offset in the body frame; with
    noise, both covariance diagonals of the covariance twin carry its variance and the pose stays exact."""
    sdf = """<sdf version="1.9"><model name="cart"><link name="chassis"><pose>-0.15 0 0.1 0 0 0</pose>
      <collision name="c"><geometry><box><size>0.4 0.3 0.1</size></box></geometry></collision></link>
      <plugin filename="gz-sim-odometry-publisher-system" name="gz::sim::systems::OdometryPublisher">
        <odom_topic>odom</odom_topic><dimensions>3</dimensions><xyz_offset>0 0 0.5</xyz_offset>
        <gaussian_noise>0.01</gaussian_noise><odom_publish_frequency>10</odom_publish_frequency></plugin>
      </model></sdf>"""
    sim = new_simulation()
    entity = sim.spawn(load_string(sdf).model, name="cart", pose=Pose((1.0, 2.0, 0.0)))
    odom, cov = _listen(sim, "/odom"), _listen(sim, "/model/cart/odometry_with_covariance")
    sim.step(500)
    assert len(odom) == pytest.approx(5, abs=1)
    truth = sim.world.entity_state("cart", "chassis").pose
    assert odom[-1].pose.position == pytest.approx(
        (truth.position[0] + 0.15, truth.position[1], truth.position[2] + 0.4), abs=1e-6
    )
    assert cov[-1].pose_covariance[0] == cov[-1].twist_covariance[35] == pytest.approx(1e-4)
    assert odom[-1].twist.linear != (0.0, 0.0, 0.0)  # noise on a cart at rest
    assert system(entity, OdometryPublisher).config.dimensions == 3


def test_dimensions_other_than_2_or_3_leave_it_off_with_upstreams_error(caplog) -> None:
    sim = new_simulation()
    with caplog.at_level(logging.ERROR):
        model = load_string(seed_urdf(gz_plugin() + ODOM.format("<dimensions>4</dimensions>"))).model
        sim.spawn(model, name="robot", pose=Pose((0.0, 0.0, 0.05)))
    assert "must be 2D or 3D not 4D" in caplog.text
    assert "/model/robot/odometry_with_covariance" not in {e.topic for e in sim.bus.endpoints()}
