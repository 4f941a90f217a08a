"""Every description file of the shared real fixtures loads with zero errors and exactly the
warnings listed here.

The walk covers every file under ``REAL`` whose suffix names a description format
(:func:`gazelle.description.format_for_path`); a file that is not in :data:`EXPECTED`, or an
entry whose file is gone, fails the test, so nothing is skipped silently.

How each file is loaded (the fixtures' README):

- ``GAZELLE_RESOURCE_PATH`` holds the case folder (``package://PKG`` and ``$(find PKG)`` resolve
  to ``<case>/PKG``) and the case's model path (``model://NAME``);
- files under ``_xacro_expanded/`` are reference outputs of the real xacro with the case folder
  written as ``@CASE_ROOT@``: that placeholder is put back before loading;
- ``diffbot.mock.urdf`` was expanded with ``use_mock_hardware:=true``.

Include fragments (files of macros, properties, materials or ``<gazebo>`` blocks that define
no link or joint) load as an empty :class:`Model` with one ``FRAGMENT`` warning; the physics
layer refuses to spawn them.
"""

from __future__ import annotations

import os
from collections import Counter
from pathlib import Path

import pytest
from _paths import REAL

from gazelle.description import (
    Model,
    ModelLoadError,
    Semantics,
    Severity,
    World,
    format_for_path,
    load,
    load_string,
)

pytestmark = pytest.mark.skipif(not REAL.is_dir(), reason="shared real fixtures not available")

MODEL_PATHS = {"turtlebot3": ("turtlebot3_gazebo/models",), "gazebo_models": ("models",)}
"""Folders of each case whose sub-folders are Gazebo models (``model://NAME``)."""

PANDA_DYNAMICS = {"ATTRIBUTE_UNSUPPORTED": 4}
"""Franka's ``<dynamics D K mu_coulomb mu_viscous>``: one warning per attribute, at its first joint."""

# rel path -> (kind, warning codes with their counts). Change a count here only with a reason.
EXPECTED: dict[str, tuple[type, dict[str, int]]] = {
    # ---- gazebo_models: SDF 1.2 .. 1.6, clean
    **{
        f"gazebo_models/models/{m}/{f}": (World if m == "sun" else Model, {})
        for m in ("coke_can", "ground_plane", "sun", "table")
        for f in ("model.sdf", "model-1_2.sdf", "model-1_3.sdf", "model-1_4.sdf")
    },
    # ---- moveit_panda
    # dual arm: its links carry no <inertial> (its 4 <ros2_control> blocks are read: spawn and check
    # say they are not simulated yet)
    "moveit_panda/_xacro_expanded/dual_arm_panda.urdf": (Model, {"INERTIA_MISSING": 22}),
    "moveit_panda/_xacro_expanded/panda_arm.srdf": (Semantics, {}),
    "moveit_panda/_xacro_expanded/panda_arm_hand.srdf": (Semantics, {}),
    "moveit_panda/_xacro_expanded/panda_description.urdf": (Model, PANDA_DYNAMICS),
    "moveit_panda/_xacro_expanded/panda_moveit_config.urdf": (Model, PANDA_DYNAMICS),
    "moveit_panda/dual_arm_panda_moveit_config/config/hand.xacro": (Model, {"FRAGMENT": 1}),
    "moveit_panda/dual_arm_panda_moveit_config/config/panda.ros2_control.xacro": (Model, {"FRAGMENT": 1}),
    # the dual-arm SRDF names two links that its URDF does not have (upstream as is)
    "moveit_panda/dual_arm_panda_moveit_config/config/panda.srdf": (Semantics, {"SRDF_REFERENCE_INVALID": 2}),
    "moveit_panda/dual_arm_panda_moveit_config/config/panda.urdf.xacro": (Model, {"INERTIA_MISSING": 22}),
    "moveit_panda/dual_arm_panda_moveit_config/config/panda_arm_macro.xacro": (Model, {"FRAGMENT": 1}),
    "moveit_panda/dual_arm_panda_moveit_config/config/panda_hand.ros2_control.xacro": (Model, {"FRAGMENT": 1}),
    # the plain panda.urdf has no <inertial> at all: derived from the collision meshes
    "moveit_panda/moveit_resources_panda_description/urdf/panda.urdf": (Model, {"INERTIA_MISSING": 11}),
    "moveit_panda/moveit_resources_panda_description/urdf/panda.urdf.xacro": (Model, PANDA_DYNAMICS),
    "moveit_panda/moveit_resources_panda_moveit_config/config/hand.xacro": (Model, {"FRAGMENT": 1}),
    "moveit_panda/moveit_resources_panda_moveit_config/config/panda.ros2_control.xacro": (Model, {"FRAGMENT": 1}),
    "moveit_panda/moveit_resources_panda_moveit_config/config/panda.srdf": (Semantics, {}),
    "moveit_panda/moveit_resources_panda_moveit_config/config/panda.urdf.xacro": (Model, PANDA_DYNAMICS),
    "moveit_panda/moveit_resources_panda_moveit_config/config/panda_arm.srdf.xacro": (Semantics, {}),
    "moveit_panda/moveit_resources_panda_moveit_config/config/panda_arm.xacro": (Model, {"FRAGMENT": 1}),
    "moveit_panda/moveit_resources_panda_moveit_config/config/panda_arm_hand.srdf.xacro": (Semantics, {}),
    "moveit_panda/moveit_resources_panda_moveit_config/config/panda_hand.ros2_control.xacro": (Model, {"FRAGMENT": 1}),
    # ---- ros2_control_diffbot: the <ros2_control> block is read (spawn and check say it is not simulated yet)
    "ros2_control_diffbot/_xacro_expanded/diffbot.mock.urdf": (Model, {}),
    "ros2_control_diffbot/_xacro_expanded/diffbot.urdf": (Model, {}),
    "ros2_control_diffbot/ros2_control_demo_description/diffbot/urdf/diffbot.materials.xacro": (
        Model,
        {"FRAGMENT": 1},
    ),
    "ros2_control_diffbot/ros2_control_demo_description/diffbot/urdf/diffbot_description.urdf.xacro": (
        Model,
        {"FRAGMENT": 1},
    ),
    "ros2_control_diffbot/ros2_control_demo_example_2/ros2_control/diffbot.ros2_control.xacro": (
        Model,
        {"FRAGMENT": 1},
    ),
    "ros2_control_diffbot/ros2_control_demo_example_2/urdf/diffbot.urdf.xacro": (Model, {}),
    # ---- ros2_control_r6bot
    "ros2_control_r6bot/_xacro_expanded/r6bot.urdf": (Model, {}),
    "ros2_control_r6bot/ros2_control_demo_description/r6bot/srdf/r6bot.srdf": (Semantics, {}),
    "ros2_control_r6bot/ros2_control_demo_description/r6bot/urdf/inc/create_link.xacro": (Model, {"FRAGMENT": 1}),
    "ros2_control_r6bot/ros2_control_demo_description/r6bot/urdf/r6bot_description.urdf.xacro": (
        Model,
        {"FRAGMENT": 1},
    ),
    "ros2_control_r6bot/ros2_control_demo_example_7/ros2_control/r6bot.ros2_control.xacro": (Model, {"FRAGMENT": 1}),
    "ros2_control_r6bot/ros2_control_demo_example_7/urdf/r6bot.urdf.xacro": (Model, {}),
    # ---- turtlebot3
    "turtlebot3/_xacro_expanded/turtlebot3_burger.from_urdf.urdf": (Model, {}),
    "turtlebot3/_xacro_expanded/turtlebot3_burger.noetic_xacro.urdf": (Model, {}),
    "turtlebot3/turtlebot3_description/urdf/common_properties.urdf": (Model, {"FRAGMENT": 1}),
    "turtlebot3/turtlebot3_description/urdf/common_properties.xacro": (Model, {"FRAGMENT": 1}),
    # only <gazebo> blocks for links defined in turtlebot3_burger.urdf.xacro
    "turtlebot3/turtlebot3_description/urdf/turtlebot3_burger.gazebo.xacro": (Model, {"FRAGMENT": 1}),
    "turtlebot3/turtlebot3_description/urdf/turtlebot3_burger.urdf": (Model, {}),
    "turtlebot3/turtlebot3_description/urdf/turtlebot3_burger.urdf.xacro": (Model, {}),
    "turtlebot3/turtlebot3_gazebo/models/turtlebot3_burger/model-1_4.sdf": (Model, {}),
    "turtlebot3/turtlebot3_gazebo/models/turtlebot3_burger/model.sdf": (Model, {}),
    "turtlebot3/turtlebot3_gazebo/models/turtlebot3_world/model-1_4.sdf": (Model, {}),
    "turtlebot3/turtlebot3_gazebo/models/turtlebot3_world/model.sdf": (Model, {}),
    "turtlebot3/turtlebot3_gazebo/urdf/common_properties.urdf": (Model, {"FRAGMENT": 1}),
    "turtlebot3/turtlebot3_gazebo/urdf/turtlebot3_burger.urdf": (Model, {}),
    # Fuel's Ground Plane and Sun are built in (nothing is fetched); empty_world also has a <gui> block
    "turtlebot3/turtlebot3_gazebo/worlds/empty_world.world": (World, {"ELEMENT_UNSUPPORTED": 1}),
    "turtlebot3/turtlebot3_gazebo/worlds/turtlebot3_world.world": (World, {}),
}

XACRO_ARGS = {"ros2_control_diffbot/_xacro_expanded/diffbot.mock.urdf": {"use_mock_hardware": "true"}}


def description_files() -> list[str]:
    """Every file under REAL whose suffix names a description format, relative to REAL."""
    if not REAL.is_dir():
        return []
    return sorted(
        p.relative_to(REAL).as_posix() for p in REAL.rglob("*") if p.is_file() and format_for_path(p) is not None
    )


def set_resource_path(monkeypatch: pytest.MonkeyPatch, case: str) -> None:
    """GAZELLE_RESOURCE_PATH = the case folder and its model paths; other search variables cleared."""
    for var in ("GZ_SIM_RESOURCE_PATH", "IGN_GAZEBO_RESOURCE_PATH", "GAZEBO_MODEL_PATH", "ROS_PACKAGE_PATH"):
        monkeypatch.delenv(var, raising=False)
    folders = [REAL / case, *(REAL / case / p for p in MODEL_PATHS.get(case, ()))]
    monkeypatch.setenv("GAZELLE_RESOURCE_PATH", os.pathsep.join(str(f) for f in folders))


def load_fixture(monkeypatch: pytest.MonkeyPatch, rel: str, args: dict[str, str] | None = None):
    """Load one fixture file the way the README says it resolves."""
    case = rel.split("/", 1)[0]
    set_resource_path(monkeypatch, case)
    path = REAL / rel
    if "/_xacro_expanded/" in f"/{rel}":
        text = path.read_text(encoding="utf-8").replace("@CASE_ROOT@", str(REAL / case))
        return load_string(text, format=format_for_path(path) or "auto", source=str(path))
    return load(path, args=args)


def formatted(diagnostics) -> str:
    return "\n".join(d.format() for d in diagnostics)


def test_the_table_lists_exactly_the_description_files() -> None:
    found = set(description_files())
    assert found, f"no description files under {REAL}"
    assert sorted(found - set(EXPECTED)) == [], "files without an expectation (add them to EXPECTED)"
    assert sorted(set(EXPECTED) - found) == [], "expectations for files that are gone"


@pytest.mark.parametrize("rel", description_files())
def test_real_file_loads_without_errors_and_with_the_listed_warnings(monkeypatch: pytest.MonkeyPatch, rel: str) -> None:
    kind, warnings = EXPECTED.get(rel, (None, None))
    try:
        result = load_fixture(monkeypatch, rel)
    except ModelLoadError as err:
        pytest.fail(f"{rel} failed to load:\n{formatted(err.diagnostics)}")
    assert all(d.severity is Severity.WARNING for d in result.diagnostics)
    assert kind is not None, f"{rel} is not in EXPECTED; it loads with:\n{formatted(result.diagnostics)}"
    assert isinstance(result.value, kind)
    got = dict(Counter(d.code.value for d in result.diagnostics))
    assert got == warnings, formatted(result.diagnostics)
    # every warning is located, and xacro-expanded ones point into a real file
    for d in result.diagnostics:
        assert d.location is not None and d.location.line is not None, d.format()
        assert Path(d.location.file).is_file(), d.format()


# --------------------------------------------------------------------------- xacro expansions
# source (expanded with the real xacro here) -> reference expansion stored in _xacro_expanded
EXPANSIONS = [
    ("turtlebot3/turtlebot3_description/urdf/turtlebot3_burger.urdf", "turtlebot3_burger.from_urdf.urdf", None),
    (
        "turtlebot3/turtlebot3_description/urdf/turtlebot3_burger.urdf.xacro",
        "turtlebot3_burger.noetic_xacro.urdf",
        None,
    ),
    ("moveit_panda/moveit_resources_panda_description/urdf/panda.urdf.xacro", "panda_description.urdf", None),
    ("moveit_panda/moveit_resources_panda_moveit_config/config/panda.urdf.xacro", "panda_moveit_config.urdf", None),
    ("moveit_panda/dual_arm_panda_moveit_config/config/panda.urdf.xacro", "dual_arm_panda.urdf", None),
    ("ros2_control_diffbot/ros2_control_demo_example_2/urdf/diffbot.urdf.xacro", "diffbot.urdf", None),
    (
        "ros2_control_diffbot/ros2_control_demo_example_2/urdf/diffbot.urdf.xacro",
        "diffbot.mock.urdf",
        {"use_mock_hardware": "true"},
    ),
    ("ros2_control_r6bot/ros2_control_demo_example_7/urdf/r6bot.urdf.xacro", "r6bot.urdf", None),
]
EXPECTED_COUNTS = {  # (links, joints), from the fixtures' README
    "turtlebot3_burger.from_urdf.urdf": (7, 6),
    "turtlebot3_burger.noetic_xacro.urdf": (7, 6),
    "panda_description.urdf": (12, 11),
    "panda_moveit_config.urdf": (12, 11),
    "dual_arm_panda.urdf": (25, 24),
    "diffbot.urdf": (5, 4),
    "diffbot.mock.urdf": (5, 4),
    "r6bot.urdf": (10, 9),
}


@pytest.mark.parametrize(("rel", "reference", "args"), EXPANSIONS, ids=[e[1] for e in EXPANSIONS])
def test_links_and_joints_match_the_real_xacro_expansion(
    monkeypatch: pytest.MonkeyPatch, rel: str, reference: str, args: dict[str, str] | None
) -> None:
    case = rel.split("/", 1)[0]
    ours = load_fixture(monkeypatch, rel, args).value
    theirs = load_fixture(monkeypatch, f"{case}/_xacro_expanded/{reference}").value
    assert isinstance(ours, Model) and isinstance(theirs, Model)
    assert (len(ours.links), len(ours.joints)) == EXPECTED_COUNTS[reference]
    assert [lk.name for lk in ours.links] == [lk.name for lk in theirs.links]
    assert [(j.name, j.type, j.parent, j.child) for j in ours.joints] == [
        (j.name, j.type, j.parent, j.child) for j in theirs.joints
    ]
    assert len(ours.plugins) == len(theirs.plugins)


@pytest.mark.parametrize(
    ("rel", "reference", "groups", "disabled"),
    [
        (
            "moveit_panda/moveit_resources_panda_moveit_config/config/panda_arm_hand.srdf.xacro",
            "panda_arm_hand.srdf",
            3,
            34,
        ),
        ("moveit_panda/moveit_resources_panda_moveit_config/config/panda_arm.srdf.xacro", "panda_arm.srdf", 1, 19),
    ],
)
def test_srdf_xacro_matches_the_real_expansion(
    monkeypatch: pytest.MonkeyPatch, rel: str, reference: str, groups: int, disabled: int
) -> None:
    ours = load_fixture(monkeypatch, rel).value
    theirs = load_fixture(monkeypatch, f"moveit_panda/_xacro_expanded/{reference}").value
    assert isinstance(ours, Semantics) and isinstance(theirs, Semantics)
    assert (len(ours.groups), len(ours.disabled_collisions)) == (groups, disabled)
    assert ours.groups == theirs.groups
    assert [(d.link1, d.link2) for d in ours.disabled_collisions] == [
        (d.link1, d.link2) for d in theirs.disabled_collisions
    ]


# --------------------------------------------------------------------------- fragments
def test_fragment_is_an_empty_model_with_one_located_warning(monkeypatch: pytest.MonkeyPatch) -> None:
    rel = "turtlebot3/turtlebot3_description/urdf/turtlebot3_burger.gazebo.xacro"
    result = load_fixture(monkeypatch, rel)
    model = result.value
    assert isinstance(model, Model) and model.links == () and model.joints == ()
    (warning,) = result.diagnostics
    assert warning.format() == (
        f"{REAL / rel}:2: warning: [FRAGMENT] robot 'turtlebot3_burger_sim' defines no links (an include "
        "fragment?): it holds 8 <gazebo> block(s), for links defined elsewhere; it cannot be simulated on its own"
    )
    # every block is kept raw (those for links defined elsewhere are not applied); robot-level plugins are read
    assert len(model.gazebo) == 8
    assert [p.filename for p in model.plugins] == ["libgazebo_ros_diff_drive.so", "libgazebo_ros_imu.so"]


def test_nameless_macro_fragment_loads(monkeypatch: pytest.MonkeyPatch) -> None:
    rel = "ros2_control_r6bot/ros2_control_demo_description/r6bot/urdf/inc/create_link.xacro"
    result = load_fixture(monkeypatch, rel)
    assert isinstance(result.value, Model) and result.value.name == "" and result.value.links == ()
    assert "macros or properties only" in result.diagnostics[0].message


def test_fragment_is_an_error_in_strict_mode(monkeypatch: pytest.MonkeyPatch) -> None:
    set_resource_path(monkeypatch, "turtlebot3")
    with pytest.raises(ModelLoadError) as info:
        load(REAL / "turtlebot3/turtlebot3_description/urdf/common_properties.xacro", strict=True)
    assert [d.code.value for d in info.value.diagnostics] == ["FRAGMENT"]


def test_physics_refuses_to_spawn_a_fragment(monkeypatch: pytest.MonkeyPatch) -> None:
    mujoco = pytest.importorskip("mujoco")
    from gazelle.description import Pose
    from gazelle.physics import BuildError
    from gazelle.physics._bodies import add_model

    model = load_fixture(monkeypatch, "moveit_panda/moveit_resources_panda_moveit_config/config/hand.xacro").value
    assert isinstance(model, Model)
    with pytest.raises(BuildError, match="has no links"):
        add_model(mujoco.MjSpec(), model, "hand", Pose())
