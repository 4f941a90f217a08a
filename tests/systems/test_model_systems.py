"""gz-sim systems a model carries (issue 55 item 3): gz-sim loads a ``<plugin>`` of a model as it does one of
the world (gz-sim8 ``SdfEntityCreator::LoadModelPlugins`` -> ``SimulationRunner::LoadPlugins`` ->
``SystemManager::LoadPlugin``), and its sensor systems run sensors whatever entity they are attached to
(``Sensors::Configure`` ignores it; ``ImuPrivate::CreateSensors`` takes every IMU). A robot carrying them
publishes its sensors in a world that has none, under every spelling gz-sim 8 loads."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from gazelle.description import Pose, load_string
from gazelle.sim import Simulation
from gazelle.systems import Imu, LaserScan, audit_model
from gazelle.worlds import default_world

_LIDAR = """<update_rate>10</update_rate><topic>scan</topic>
  <lidar><scan><horizontal><samples>181</samples><resolution>1</resolution>
    <min_angle>-1.5707963</min_angle><max_angle>1.5707963</max_angle></horizontal></scan>
    <range><min>0.1</min><max>10</max></range></lidar>"""
_IMU = "<update_rate>100</update_rate><topic>imu</topic>"


def _sdf_robot(sensors: tuple[str, str], imu: tuple[str, str]) -> str:
    """A box robot with a gpu_lidar and an IMU and no gazebo_ros plugin, carrying the two gz-sim systems
    (filename, name) as model plugins."""
    return f"""<?xml version="1.0"?>
<sdf version="1.9"><model name="bot">
  <plugin filename="{sensors[0]}" name="{sensors[1]}"><render_engine>ogre2</render_engine></plugin>
  <plugin filename="{imu[0]}" name="{imu[1]}"/>
  <link name="base">
    <pose>0 0 0.1 0 0 0</pose>
    <inertial><mass>2.0</mass><inertia><ixx>0.02</ixx><iyy>0.02</iyy><izz>0.02</izz></inertia></inertial>
    <collision name="c"><geometry><box><size>0.3 0.3 0.2</size></box></geometry></collision>
    <sensor name="lidar" type="gpu_lidar"><pose>0 0 0.2 0 0 0</pose>{_LIDAR}</sensor>
    <sensor name="imu" type="imu">{_IMU}</sensor>
  </link>
</model></sdf>"""


def _urdf_robot(sensors: tuple[str, str], imu: tuple[str, str]) -> str:
    """The same robot as a URDF: the systems in ``<gazebo><plugin>``, the sensors in ``<gazebo reference>``."""
    return f"""<?xml version="1.0"?>
<robot name="bot">
  <link name="base">
    <inertial><mass value="2.0"/><inertia ixx="0.02" iyy="0.02" izz="0.02" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0 0 0.1"/><geometry><box size="0.3 0.3 0.2"/></geometry></collision>
  </link>
  <gazebo><plugin filename="{sensors[0]}" name="{sensors[1]}"><render_engine>ogre2</render_engine></plugin></gazebo>
  <gazebo><plugin filename="{imu[0]}" name="{imu[1]}"/></gazebo>
  <gazebo reference="base">
    <sensor name="lidar" type="gpu_lidar"><pose>0 0 0.3 0 0 0</pose>{_LIDAR}</sensor>
    <sensor name="imu" type="imu">{_IMU}</sensor>
  </gazebo>
</robot>"""


_SPELLINGS = [
    (  # Fortress's file names, as robots written for it carry them
        ("ignition-gazebo-sensors-system", "ignition::gazebo::systems::Sensors"),
        ("ignition-gazebo-imu-system", "ignition::gazebo::systems::Imu"),
    ),
    (("gz-sim-sensors-system", "gz::sim::systems::Sensors"), ("gz-sim-imu-system", "gz::sim::systems::Imu")),
    (  # the library's file name with its prefix and suffix; the class names in the name attribute
        ("libgz-sim-sensors-system.so", "gz::sim::systems::Sensors"),
        ("libignition-gazebo-imu-system.so", "ignition::gazebo::systems::Imu"),
    ),
]


def _bare_world():
    """The default world without its gz-sim sensor systems: nothing of the world runs a sensor."""
    world = default_world()
    return dataclasses.replace(world, plugins=())


def _record(sim: Simulation, topic: str) -> list:
    got: list = []
    ep = next((e for e in sim.bus.endpoints() if e.topic == topic and e.is_publisher), None)
    assert ep is not None, f"nothing publishes {topic}"
    ep.add_sink(got.append)
    return got


@pytest.mark.parametrize("make_xml", [_sdf_robot, _urdf_robot], ids=["sdf", "urdf"])
@pytest.mark.parametrize("spelling", _SPELLINGS, ids=["ignition", "gz", "lib-so"])
def test_a_robot_carrying_the_sensors_and_imu_systems_publishes_its_lidar_and_imu_in_a_world_without_them(
    make_xml, spelling, make_sim
):
    """A wall 2 m ahead: the lidar's middle ray reads it (the lidar is 0.3 m above the ground on a robot at
    rest), the IMU reads +g; and nothing about the two plugins is warned."""
    sensors, imu = spelling
    result = load_string(make_xml(sensors, imu))
    sim = make_sim(_bare_world())
    wall = """<?xml version="1.0"?><sdf version="1.9"><model name="wall"><static>true</static>
      <pose>2.1 0 1 0 0 0</pose><link name="l"><collision name="c"><geometry><box><size>0.2 4 2</size></box>
      </geometry></collision></link></model></sdf>"""
    sim.spawn(load_string(wall).model, name="wall", pose=Pose())
    sim.spawn(result.model, name="bot", pose=Pose())
    scans, imus = _record(sim, "/scan"), _record(sim, "/imu")
    sim.step(500)
    assert len(scans) >= 4 and len(imus) >= 45
    scan: LaserScan = scans[-1]
    ranges = np.frombuffer(scan.ranges, dtype=np.float32)
    middle = float(ranges[len(ranges) // 2])
    assert middle == pytest.approx(2.0, abs=1e-3)
    last: Imu = imus[-1]
    assert np.allclose(last.linear_acceleration, (0.0, 0.0, 9.8), atol=0.05)
    assert not math.isnan(last.orientation[0])
    assert [d.format() for d in audit_model(result.model, ())] == []


def test_a_gz_sensor_system_in_a_model_is_neither_refused_nor_offered_under_its_own_name():
    """The message used to be "plugin ... (ignition-gazebo-sensors-system) is not supported; did you mean
    'ignition-gazebo-sensors-system'?". A typo of it still gets the right name."""
    ok = _sdf_robot(
        ("ignition-gazebo-sensors-system", "ignition::gazebo::systems::Sensors"),
        ("ignition-gazebo-imu-system", "ignition::gazebo::systems::Imu"),
    )
    assert [d.format() for d in audit_model(load_string(ok).model, ())] == []
    typo = ok.replace(  # a deliberate typo (QQQ) of the file name
        'filename="ignition-gazebo-imu-system" name="ignition::gazebo::systems::Imu"',
        'filename="ignition-gazebo-imu-sytem" name="imu"',
    )
    problems = [d.message for d in audit_model(load_string(typo).model, ())]
    assert any("did you mean 'ignition-gazebo-imu-system'?" in m for m in problems), problems
    assert not any(m.count("ignition-gazebo-imu-sytem") > 1 for m in problems), problems
