"""Issue 28: a world without arms runs on the set-up's first tier of interface packages alone, so
``./demo.sh`` starts the demo before ros2_control's and MoveIt's packages are built
(scripts/build_interfaces.sh ``first``); a robot that needs them then gets an error saying how to build them.

The second tier is hidden from a real process (a ``sitecustomize`` on its path refuses to import it), which
is a venv where only the first tier was built, as far as Python can tell."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from _paths import REPO, SEED_XACRO
from _r6bot import R6BOT, URDF

BLOCKER = """
import sys
from importlib.abc import MetaPathFinder

HIDDEN = {"control_msgs", "controller_manager_msgs", "moveit_msgs", "octomap_msgs", "object_recognition_msgs"}


class Hide(MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        if name.split(".")[0] in HIDDEN:
            raise ModuleNotFoundError(f"No module named {name!r}", name=name)
        return None


sys.meta_path.insert(0, Hide())
"""

WORLD_WITHOUT_ARMS = f"""
import sys
sys.path.insert(0, {str(Path(__file__).parents[1])!r})
from sim.test_failed_spawns import fingerprint
from gazelle.description import load
from gazelle.physics import WorldError
from gazelle.ros._bridge import RosBridge
from gazelle.ros._convert import ARM_PACKAGES
from gazelle.sim import Simulation
from gazelle.worlds import default_world

sim = Simulation(default_world(), rtf=0)
bridge = RosBridge(sim)
try:
    robot = sim.spawn(load({str(SEED_XACRO)!r}).model, name="seed")
    sim.step(200)
    print("stepped to", round(float(sim.world.data.time), 3))
    print("second tier loaded:", sorted(m for m in sys.modules if m.split(".")[0] in ARM_PACKAGES))
    before = fingerprint(sim)
    try:
        sim.spawn(load({str(URDF)!r}).model, name="r6bot")
    except WorldError as e:
        print("r6bot:", e)
    print("world unchanged:", fingerprint(sim) == before)
finally:
    bridge.shutdown()
"""


def test_a_world_without_arms_runs_without_the_second_tier_and_an_arm_says_how_to_build_it(tmp_path: Path) -> None:
    (tmp_path / "sitecustomize.py").write_text(BLOCKER)
    env = {
        **os.environ,
        "PYTHONPATH": str(tmp_path),
        "GAZELLE_RESOURCE_PATH": str(R6BOT),
        "ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST",
    }
    run = subprocess.run(
        [sys.executable, "-c", WORLD_WITHOUT_ARMS], cwd=REPO, env=env, capture_output=True, text=True, timeout=120
    )
    out = run.stdout + run.stderr
    assert run.returncode == 0, out
    assert "stepped to 0.2" in out
    assert "second tier loaded: []" in out
    # the arm is refused whole, naming the package and the command that builds it; the world stays as it was
    assert "control_msgs is not built in this venv yet" in out and "run scripts/setup.sh" in out, out
    assert "world unchanged: True" in out, out
    assert "Traceback" not in out, out
