"""The viewer layer without a browser: its import boundaries, geometry, and the scene/controls it keeps."""

from __future__ import annotations

import subprocess
import sys
from typing import Any, cast

import numpy as np
import pytest
import trimesh
from _paths import REPO, SEED_XACRO

from gazelle.description import Box, Capsule, Cylinder, Ellipsoid, Mesh, Plane, Pose, Sphere, load
from gazelle.viewer._geometry import to_trimesh


def test_layers_viewer_never_imports_rclpy_and_core_never_imports_viewer() -> None:
    code = (
        "import sys, gazelle.physics, gazelle.systems, gazelle.description, gazelle.cli._sim\n"
        "assert 'gazelle.viewer' not in sys.modules, 'the core imported the viewer'\n"
        "import gazelle.viewer, gazelle.viewer._browser, gazelle.viewer._snapshot\n"
        "bad = sorted(m for m in sys.modules if m.split('.')[0] == 'rclpy')\n"
        "assert not bad, bad\n"
    )
    res = subprocess.run([sys.executable, "-c", code], cwd=REPO, capture_output=True, text=True, timeout=60)
    assert res.returncode == 0, res.stderr


@pytest.mark.parametrize(
    ("geometry", "extents"),
    [
        (Box((0.3, 0.2, 0.1)), (0.3, 0.2, 0.1)),
        (Cylinder(0.05, 0.04), (0.1, 0.1, 0.04)),  # along z, as in URDF/SDF
        (Sphere(0.1), (0.2, 0.2, 0.2)),
        (Capsule(0.1, 0.5), (0.2, 0.2, 0.7)),
        (Ellipsoid((0.1, 0.2, 0.3)), (0.2, 0.4, 0.6)),
    ],
)
def test_primitives_have_their_description_size(geometry: object, extents: tuple[float, float, float]) -> None:
    tm = to_trimesh(geometry)
    assert tm is not None
    np.testing.assert_allclose(tm.vertices.max(0) - tm.vertices.min(0), extents, rtol=0.02)


def test_plane_sits_just_below_zero_so_the_grid_shows() -> None:
    tm = to_trimesh(Plane(size=(10.0, 4.0)))
    assert tm is not None
    assert tm.vertices[:, 2].max() < 0.0 and tm.vertices[:, 2].min() > -0.01
    np.testing.assert_allclose(tm.vertices.max(0)[:2] - tm.vertices.min(0)[:2], (10.0, 4.0))


@pytest.mark.parametrize("ext", ["stl", "obj"])
def test_mesh_files_load_with_their_scale(tmp_path, ext: str) -> None:
    path = tmp_path / f"box.{ext}"
    trimesh.creation.box(extents=(1.0, 2.0, 3.0)).export(path)
    tm = to_trimesh(Mesh(uri=str(path), path=str(path), scale=(0.5, 0.5, 2.0)))
    assert tm is not None
    np.testing.assert_allclose(tm.vertices.max(0) - tm.vertices.min(0), (0.5, 1.0, 6.0), rtol=1e-6)


def test_a_collada_file_in_inches_is_drawn_the_size_the_physics_gives_it() -> None:
    """Issue 26 item 8: TurtleBot3's arena wall and hexagons are COLLADA files with <unit meter="0.0254"/>.
    The physics converted them to metres; the viewer drew them 39x too large, off screen."""
    from _paths import REAL

    from gazelle.description import load_mesh

    wall = REAL / "turtlebot3/turtlebot3_gazebo/models/turtlebot3_world/meshes/wall.dae"
    assert 'meter="0.0254"' in wall.read_text()
    tm = to_trimesh(Mesh(uri=str(wall), path=str(wall)))
    assert tm is not None
    physics_vertices, _faces = load_mesh(str(wall))
    np.testing.assert_allclose(tm.vertices.max(0), physics_vertices.max(0), rtol=1e-5)
    np.testing.assert_allclose(tm.vertices.min(0), physics_vertices.min(0), rtol=1e-5)
    # 900 inches across (model.sdf scales it by 0.25 to TurtleBot3's 5.7 m arena); unconverted, 900 m
    np.testing.assert_allclose(tm.vertices.max(0)[0] - tm.vertices.min(0)[0], 900 * 0.0254, rtol=1e-5)


def test_unresolved_or_broken_mesh_is_skipped(tmp_path) -> None:
    assert to_trimesh(Mesh(uri="package://nowhere/x.stl", path=None)) is None
    bad = tmp_path / "bad.stl"
    bad.write_text("not a mesh")
    assert to_trimesh(Mesh(uri=str(bad), path=str(bad))) is None


def test_scene_follows_spawn_and_delete_and_drive_reaches_the_diff_drive(make_sim) -> None:
    from gazelle.viewer import Viewer

    sim = make_sim()
    sim.start()
    viewer = Viewer(sim, port=0)  # no thread: frames are pulled by hand
    try:
        assert viewer.server.get_host() == "127.0.0.1"
        viewer.update()
        before = set(viewer._nodes)
        sim.spawn(load(SEED_XACRO).model, name="r1", pose=Pose((1.0, 0.0, 0.0)))
        snap = viewer.update()
        assert snap is not None and set(viewer._nodes) == before | {"r1"}
        assert set(viewer._nodes["r1"].links) == {"base_link", "left_wheel", "right_wheel"}
        assert "r1" in viewer._entity_dd.options
        x0 = snap.poses["r1"]["base_link"][0][0]
        assert viewer.drive(0.5, 0.0, "r1") == 1
        assert viewer.drive(0.5, 0.0, "ground_plane") == 0
        deadline = sim.call(lambda: sim.world.time) + 2.0
        while sim.call(lambda: sim.world.time) < deadline:
            snap = viewer.update()
        assert snap is not None and snap.poses["r1"]["base_link"][0][0] > x0 + 0.3
        assert viewer._nodes["r1"].links["base_link"].frame.position[0] > x0 + 0.3
        sim.delete("r1")
        viewer.update()
        assert set(viewer._nodes) == before and "r1" not in viewer._entity_dd.options
    finally:
        viewer.stop()
        sim.stop()


def _click(handle) -> None:
    """What viser does with a SceneNodeClickMessage for ``handle``: call its click callbacks with the event."""
    from viser._scene_handles import SceneNodePointerEvent

    event = SceneNodePointerEvent(
        client=cast(Any, None),  # no client: the callbacks under test do not read it
        client_id=0,
        event="click",
        target=handle,
        ray_origin=(0.0, 0.0, 1.0),
        ray_direction=(0.0, 0.0, -1.0),
        screen_pos=(0.5, 0.5),
        instance_index=None,
        modifier=None,
    )
    for entry in list(handle._impl.click_cb):
        entry.callback(event)


def test_clicking_an_entity_selects_it_but_not_the_ground_plane_or_collision_overlays(make_sim) -> None:
    from gazelle.viewer import Viewer
    from gazelle.viewer._overlays import NO_SELECTION

    here = REPO / "examples" / "chessboard"
    sim = make_sim()
    sim.start()
    viewer = Viewer(sim, port=0)  # no thread: frames are pulled by hand
    try:
        sim.spawn(load(SEED_XACRO).model, name="r1", pose=Pose((1.0, 0.0, 0.0)))
        sim.spawn(load(here / "chess_board.sdf").model, name="board", pose=Pose((0.0, 2.0, 0.0)))  # static, spawned
        sim.spawn(load(here / "chess_piece.sdf").model, name="piece", pose=Pose((0.0, 2.0, 0.05)))
        viewer.update()
        nodes = viewer._nodes
        assert viewer._entity_dd.value == NO_SELECTION
        # the world's static scenery is not clickable: a click on the ground must not select it
        assert sim.world.entities["ground_plane"].static and nodes["ground_plane"].visuals
        assert not nodes["ground_plane"].selectable
        assert all(not h._impl.click_cb for h in nodes["ground_plane"].visuals)
        _click(nodes["ground_plane"].visuals[0])
        assert viewer._entity_dd.value == NO_SELECTION
        # every visual of the robot (base box, 2 casters, 2 wheels) selects it; collision overlays select nothing
        assert len(nodes["r1"].visuals) == 5 and all(h._impl.click_cb for h in nodes["r1"].visuals)
        assert nodes["r1"].collisions and all(not h._impl.click_cb for h in nodes["r1"].collisions)
        for h in nodes["r1"].visuals:
            viewer._entity_dd.value = NO_SELECTION
            _click(h)
            assert viewer._entity_dd.value == "r1"
        _click(nodes["r1"].visuals[0])  # clicking the selection again keeps it selected
        assert viewer._entity_dd.value == "r1"
        # what follows the dropdown follows the click: pose text, drive target, trail
        snap = viewer.update()
        assert snap is not None
        viewer._update_gui(snap)
        assert viewer._pose_text.value.startswith("x 1.0")
        assert viewer.drive(0.0, 0.0) == 1 and viewer._drive_text.value.startswith("r1:")
        # a static model that was spawned (the chess board) is selectable, and so is each piece
        _click(nodes["board"].visuals[0])
        assert viewer._entity_dd.value == "board" and viewer.trail_target() == "board"
        _click(nodes["piece"].visuals[0])
        assert viewer._entity_dd.value == "piece"
        # a click arriving for an entity deleted meanwhile changes nothing
        r1_visual = nodes["r1"].visuals[0]
        sim.delete("r1")
        viewer.update()
        _click(r1_visual)
        assert viewer._entity_dd.value == "piece" and not viewer.select("r1")
    finally:
        viewer.stop()
        sim.stop()


def test_find_models_lists_model_folders_and_description_files(tmp_path) -> None:
    from gazelle.description import ResourceResolver
    from gazelle.viewer._models import find_models

    box = tmp_path / "my_box"
    box.mkdir()
    (box / "model.config").write_text("<model><name>my_box</name><sdf version='1.6'>model.sdf</sdf></model>")
    (box / "model.sdf").write_text("<sdf version='1.6'><model name='my_box'/></sdf>")
    (box / "ignored.sdf").write_text("<sdf/>")  # model.config names the model's file
    (tmp_path / "robots").mkdir()
    (tmp_path / "robots" / "r.urdf.xacro").write_text("<robot/>")  # never offered: the server runs no xacro
    (tmp_path / "robots" / "r.urdf").write_text("<robot/>")
    (tmp_path / "notes.txt").write_text("")
    labels = {m.label for m in find_models(ResourceResolver(extra_paths=[tmp_path], env={}))}
    assert labels == {"my_box/model.sdf", "robots/r.urdf"}


def test_find_models_lists_a_model_colcon_symlink_installed(tmp_path) -> None:
    """``colcon build --symlink-install`` links a model's model.config and model.sdf into the install prefix
    (issue 49): the model is offered, its SDF read through the link; a model whose SDF links out of the
    workspace is not."""
    from gazelle.description import ResourceResolver
    from gazelle.viewer._models import find_models

    ws = tmp_path / "ws"
    (ws / "install").mkdir(parents=True)
    (ws / "install" / ".colcon_install_layout").write_text("isolated\n")
    (ws / "build").mkdir()
    (ws / "build" / ".built_by").write_text("colcon\n")
    models, src = ws / "install" / "pkg" / "share" / "pkg" / "models", ws / "src" / "pkg" / "models"
    (tmp_path / "elsewhere.sdf").write_text("<sdf version='1.6'><model name='x'/></sdf>")
    for name, sdf in (("arena", src / "arena" / "model.sdf"), ("leak", tmp_path / "elsewhere.sdf")):
        (src / name).mkdir(parents=True)
        (src / name / "model.config").write_text(
            f"<model><name>{name}</name><sdf version='1.6'>model.sdf</sdf></model>"
        )
        if not sdf.exists():
            sdf.write_text(f"<sdf version='1.6'><model name='{name}'/></sdf>")
        (models / name).mkdir(parents=True)
        (models / name / "model.config").symlink_to(src / name / "model.config")
        (models / name / "model.sdf").symlink_to(sdf)
    found = find_models(ResourceResolver(extra_paths=[models], env={}))
    assert [m.label for m in found] == ["arena/model.sdf"]
    assert found[0].path.resolve() == src / "arena" / "model.sdf"


def test_trail_contacts_and_spawn_from_the_resource_paths(monkeypatch, make_sim) -> None:
    from gazelle.viewer import Viewer

    monkeypatch.setenv("GAZELLE_RESOURCE_PATH", str(REPO / "examples"))
    sim = make_sim()
    sim.start()
    viewer = Viewer(sim, port=0)
    try:
        labels = {m.label for m in viewer._models}
        assert "chessboard/chess_board.sdf" in labels and "simple_robot/robot.urdf.xacro" not in labels
        assert "chessboard/chess_board.sdf" in viewer._model_dd.options
        viewer.sample_trail()
        assert viewer.trail == [] and viewer.trail_target() is None
        sim.spawn(load(SEED_XACRO).model, name="r1")
        assert viewer.trail_target() == "r1"  # no selection: the first diff-drive robot
        viewer.drive(0.5, 0.0, "r1")
        t_end = sim.call(lambda: sim.world.time) + 2.0
        while sim.call(lambda: sim.world.time) < t_end:  # rtf 0: the sim runs on its own
            viewer.sample_trail()
        xs = [p[0] for p in viewer.trail]
        assert len(xs) >= 5 and xs[-1] > xs[0] + 0.05
        # forward along the path; settling after the spawn drop may move x back by a fraction of a mm
        assert all(b > a - 1e-3 for a, b in zip(xs, xs[1:])), xs[:20]
        # the seed's odometry is gazebo_ros' world odometry: its odom frame is the world, so the /odom trail is truth
        assert viewer.overlays._trail_text.value == "r1 (/odom)"
        sim.call(lambda: setattr(sim, "paused", True))  # the last point and the truth at the same instant
        viewer.sample_trail()
        truth = sim.call(lambda: sim.world.entity_state("r1").pose.position)
        assert viewer.trail[-1][:2] == pytest.approx(truth[:2], abs=0.02)  # the message is <= 10 ms old
        sim.call(lambda: setattr(sim, "paused", False))
        viewer.overlays.redraw_trail(force=True)
        assert viewer.overlays._trail_handle is not None
        viewer.overlays._contact_box.value = True
        pts = viewer.overlays._update_contacts()
        assert (
            pts is not None and len(pts) >= 2 and np.all(np.abs(pts[:, 2]) < 0.05)
        )  # wheels (and caster) on the ground
        name = viewer.spawn_model(str(REPO / "examples/chessboard/chess_piece.sdf"), xyz=(2.0, 0.0, 0.1), yaw=0.5)
        name2 = viewer.spawn_model(str(REPO / "examples/chessboard/chess_piece.sdf"), xyz=(2.5, 0.0, 0.1))
        assert name2 == f"{name}_2" and {name, name2} <= set(sim.world.entities)
        x = sim.call(lambda: sim.world.entity_state(name).pose.position[0])
        assert x == pytest.approx(2.0, abs=0.01)
    finally:
        viewer.stop()
        sim.stop()


def test_odom_trail_shows_what_odometry_reports_and_ground_truth_on_request(tmp_path, make_sim) -> None:
    """A robot whose encoder odometry over-reports distance by 10 % (its plugin's wheels are 10 % too big)."""
    import re
    from xml.dom.minidom import Document

    import xacro
    from _paths import BOX

    from gazelle.description import load_string
    from gazelle.viewer import Viewer
    from gazelle.viewer._overlays import TRAIL_TRUTH

    document = xacro.process_file(str(SEED_XACRO))
    assert isinstance(document, Document)  # (xacro's annotation says a file)
    urdf = document.toxml()
    urdf, n = re.subn(
        r"<wheel_diameter>([\d.]+)</wheel_diameter>",
        lambda m: f"<wheel_diameter>{float(m.group(1)) * 1.1}</wheel_diameter><odometry_source>0</odometry_source>",
        urdf,
    )
    assert n == 1
    (tmp_path / "enc.urdf").write_text(urdf)
    sim = make_sim()
    sim.start()
    viewer = Viewer(sim, port=0)
    try:

        def drive(seconds: float) -> None:  # samples the trail at least once (rtf 0: the sim runs on its own)
            t_end = sim.call(lambda: sim.world.time) + seconds
            viewer.sample_trail()
            while sim.call(lambda: sim.world.time) < t_end:
                viewer.sample_trail()

        def truth_xy() -> tuple[float, float]:
            x, y, _z = sim.call(lambda: sim.world.entity_state("r1").pose.position)
            return (x, y)

        def pause_and_sample() -> None:  # the trail's last point and the truth at the same instant
            sim.call(lambda: setattr(sim, "paused", True))
            viewer.sample_trail()

        sim.spawn(load(tmp_path / "enc.urdf").model, name="r1", pose=Pose((1.0, 2.0, 0.05)))
        drive(0.5)  # at rest on the ground; the trail (and its odom frame) starts here
        x0, y0 = truth_xy()
        viewer.drive(0.5, 0.0, "r1")
        drive(2.0)
        pause_and_sample()
        x1, y1 = truth_xy()
        assert viewer.overlays._trail_text.value == "r1 (/odom)"
        end = viewer.trail[-1]
        moved, reported = x1 - x0, end[0] - x0
        assert moved > 0.5, f"the robot moved {moved:.3f} m"
        assert reported == pytest.approx(1.1 * moved, rel=0.03), f"odom trail {reported:.3f} m for {moved:.3f} m moved"
        assert abs(end[1] - y0) < 0.02  # anchored where the robot started: (1, 2), not the odom origin (0, 0)

        viewer.overlays._trail_source.value = TRAIL_TRUTH
        sim.call(lambda: setattr(sim, "paused", False))
        drive(1.0)
        pause_and_sample()
        assert viewer.overlays._trail_text.value == "r1 (ground truth)"
        assert viewer.trail[0][0] > x1 - 0.05  # a new trail, from where the robot was
        assert viewer.trail[-1][:2] == pytest.approx(truth_xy(), abs=0.006)  # within a trail step (5 mm)
        sim.call(lambda: setattr(sim, "paused", False))

        sim.spawn(load_string(BOX).model, name="box", pose=Pose((-1.0, 0.0, 0.2)))
        viewer.overlays._trail_source.value = "odom"
        viewer.update()  # the scene and the Entities dropdown catch up with the spawn
        assert viewer.select("box")
        drive(0.2)
        assert viewer.overlays._trail_text.value == "box (ground truth: no odometry topic)"
        assert viewer.trail[-1][:2] == pytest.approx((-1.0, 0.0), abs=0.01)

        # a reset puts the robot back and zeroes its encoder odometry: a new trail from (1, 2)
        assert viewer.select("r1")
        drive(0.2)
        assert viewer.trail[-1][0] > x1  # the over-reported path so far
        sim.call(lambda: setattr(sim, "paused", True))
        sim.reset(time_=True, state=True, spawned=False)
        viewer.sample_trail()  # no step since the reset: the last odom message is from before it, not a point
        assert viewer.trail == []
        sim.call(lambda: setattr(sim, "paused", False))
        drive(0.3)
        assert viewer.overlays._trail_text.value == "r1 (/odom)"
        assert viewer.trail and all(p[:2] == pytest.approx((1.0, 2.0), abs=0.02) for p in viewer.trail), viewer.trail[
            :3
        ]
    finally:
        viewer.stop()
        sim.stop()


def test_lidar_points_land_on_the_wall_and_the_camera_panel_shows_the_camera_image(make_sim) -> None:
    from gazelle.description import load_string
    from gazelle.viewer import Viewer

    wall = """<?xml version="1.0"?><sdf version="1.9"><model name="wall"><static>true</static><pose>2.1 0 0.5 0 0 0</pose>
      <link name="l"><collision name="c"><geometry><box><size>0.2 6 1</size></box></geometry></collision>
      <visual name="v"><geometry><box><size>0.2 6 1</size></box></geometry><material><diffuse>1 0 0 1</diffuse></material></visual>
      </link></model></sdf>"""
    sim = make_sim()
    sim.spawn(load_string(wall).model, name="wall")
    sim.spawn(load(REPO / "examples/sensor_bot/sensor_bot.urdf").model, name="bot", pose=Pose((0.0, 0.0, 0.07)))
    sim.step(200)
    viewer = Viewer(sim, port=0)  # no thread: the panel is updated by hand
    sim.start()
    try:
        pts = viewer.overlays._update_lidars()
        p = pts["bot/lidar"]
        assert len(p) > 50
        assert np.all(np.abs(p[:, 0] - 2.0) < 0.01)  # every hit on the wall's face, x = 2.0 m
        assert "bot/lidar" in viewer.overlays._lidar_handles
        viewer.overlays._lidar_box.value = False
        assert viewer.overlays._update_lidars() == {} and not viewer.overlays._lidar_handles
        assert viewer.overlays._update_camera() is None  # no camera chosen: nothing rendered
        assert "bot/camera" in viewer.overlays._camera_dd.options
        viewer.overlays._camera_dd.value = "bot/camera"
        image = viewer.overlays._update_camera()
        assert image is not None and image.shape == (240, 320, 3)
        red = (image[..., 0] > 100) & (image[..., 1] < 60) & (image[..., 2] < 60)
        assert red[90:125, 140:180].mean() > 0.9  # the red wall straight ahead (its foot is ~15 px below centre)
    finally:
        viewer.stop()
        sim.stop()


TWO_LINK_ARM = """<robot name="arm2">
  <link name="world"/>
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <visual><geometry><box size="0.1 0.1 0.1"/></geometry></visual></link>
  <link name="link1"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <visual><origin xyz="0.25 0 0"/><geometry><box size="0.5 0.05 0.05"/></geometry></visual></link>
  <link name="link2"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <visual><origin xyz="0.15 0 0"/><geometry><box size="0.3 0.05 0.05"/></geometry></visual></link>
  <link name="tool"/>
  <joint name="fix" type="fixed"><parent link="world"/><child link="base"/><origin xyz="0 0 1"/></joint>
  <joint name="j1" type="revolute"><parent link="base"/><child link="link1"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="10" velocity="1"/></joint>
  <joint name="j2" type="revolute"><parent link="link1"/><child link="link2"/><origin xyz="0.5 0 0"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="10" velocity="1"/></joint>
  <joint name="tool_joint" type="fixed"><parent link="link2"/><child link="tool"/><origin xyz="0.3 0 0"/></joint>
</robot>"""


def test_a_planned_arm_motion_is_drawn_as_its_tools_path_and_goal_and_the_arm_does_not_move(make_sim) -> None:
    """What move_group publishes on /display_planned_path (moveit_msgs/DisplayTrajectory) is drawn: the
    path of the tool (the moving chain's last link, down its fixed joints) by forward kinematics of the
    simulated robot, and the goal as axes at the path's end. Drawing it moves nothing."""
    from gazelle.description import load_string
    from gazelle.systems import DisplayTrajectory, JointTrajectory, MsgType, TrajectoryPoint
    from gazelle.viewer import Viewer
    from gazelle.viewer._overlays import PLAN_TOPIC

    sim = make_sim()
    sim.start()
    viewer = Viewer(sim, port=0)
    try:
        sim.spawn(load_string(TWO_LINK_ARM).model, name="arm", pose=Pose())
        viewer.update()
        assert viewer.update_plan() is None and not viewer.overlays._plan_handles  # nothing planned yet
        rows = [(0.0, 0.0), (np.pi / 4, 0.0), (np.pi / 2, 0.0), (np.pi / 2, np.pi / 2)]
        points = tuple(TrajectoryPoint(i * 0.5, r) for i, r in enumerate(rows))
        plan = DisplayTrajectory("arm2", (JointTrajectory(0.0, ("j1", "j2"), points),))
        assert sim.bus.inject(PLAN_TOPIC, MsgType.DISPLAY_TRAJECTORY, plan) == 1
        planned = viewer.update_plan()
        assert planned is not None and planned.entity == "arm" and planned.tips == ("tool",)
        expected = [(0.8, 0.0, 1.0), (0.8 / np.sqrt(2), 0.8 / np.sqrt(2), 1.0), (0.0, 0.8, 1.0), (-0.3, 0.5, 1.0)]
        np.testing.assert_allclose(planned.paths[0], expected, atol=1e-5)
        goal = planned.goals[0]
        np.testing.assert_allclose(goal.position, (-0.3, 0.5, 1.0), atol=1e-5)
        # yaw of pi (j1 + j2): the tool's x axis points along -x
        assert abs(abs(goal.orientation[3]) - 1.0) < 1e-5, goal.orientation
        assert len(viewer.overlays._plan_handles) == 2  # the path and the goal's axes
        # the simulated arm did not move
        arm = sim.call(lambda: sim.world.entity_state("arm", "tool").pose.position)
        np.testing.assert_allclose(arm, (0.8, 0.0, 1.0), atol=1e-3)
        viewer.overlays._plan_box.value = False
        viewer.update_plan()
        assert not viewer.overlays._plan_handles
        viewer.overlays._plan_box.value = True
        viewer.update_plan()
        assert len(viewer.overlays._plan_handles) == 2
        # a plan for joints no entity has is not drawn, and the older one goes (it is not the latest)
        other = DisplayTrajectory("ghost", (JointTrajectory(0.0, ("nope",), (TrajectoryPoint(0.0, (1.0,)),)),))
        sim.bus.inject(PLAN_TOPIC, MsgType.DISPLAY_TRAJECTORY, other)
        assert viewer.update_plan() is None and not viewer.overlays._plan_handles
        sim.bus.inject(PLAN_TOPIC, MsgType.DISPLAY_TRAJECTORY, plan)
        assert viewer.update_plan() is not None
        # issue 27: the next plan of another length replaces the drawn one (comparing the two raised
        # "operands could not be broadcast" on every redraw, and the old path stayed)
        longer = DisplayTrajectory(
            "arm2", (JointTrajectory(0.0, ("j1", "j2"), (*points, TrajectoryPoint(2.0, (0.0, 0.0)))),)
        )
        sim.bus.inject(PLAN_TOPIC, MsgType.DISPLAY_TRAJECTORY, longer)
        redrawn = viewer.update_plan()
        assert redrawn is not None and len(redrawn.paths[0]) == 5 and len(viewer.overlays._plan_handles) == 2
        sim.bus.inject(PLAN_TOPIC, MsgType.DISPLAY_TRAJECTORY, plan)
        assert len(viewer.update_plan().paths[0]) == 4  # type: ignore[union-attr]
        sim.delete("arm")
        viewer.update()
        assert viewer.update_plan() is None and not viewer.overlays._plan_handles  # its robot is gone
    finally:
        viewer.stop()
        sim.stop()
