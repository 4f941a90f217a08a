"""Scenarios for bench_sweep.py: the seed robot driving for a given span of sim time."""

from pathlib import Path

from gazelle.description import DiagnosticSink, Pose, ResourceResolver, expand_xacro_bounded, load_string
from gazelle.systems.diff_drive import DiffDrive

ROBOT = Path(__file__).resolve().parents[1] / "examples" / "simple_robot" / "simple_robot" / "robot.urdf.xacro"
_URDF: list[str] = []


def _urdf() -> str:
    if not _URDF:
        sink = DiagnosticSink()
        text = expand_xacro_bounded(
            ROBOT.read_text(), source=str(ROBOT), sink=sink, resolver=ResourceResolver().trusting(ROBOT.parent)
        )
        assert text is not None, sink.items
        _URDF.append(text)
    return _URDF[0]


def drive(sim, params, seed):
    """Drive forward and turn for ``seconds`` of sim time; the metric is where the robot ends."""
    entity = sim.spawn(load_string(_urdf(), format="urdf").value, name="robot", pose=Pose((0.0, 0.0, 0.07)))
    drive = next(s for s in entity.systems if isinstance(s, DiffDrive))
    drive.command(0.2, 0.1 * (seed % 5))
    sim.step(round(float(params.get("seconds", 5.0)) / sim.world.timestep))
    x, y, _z = sim.world.entity_state("robot").pose.position
    return {"x": x, "y": y}
