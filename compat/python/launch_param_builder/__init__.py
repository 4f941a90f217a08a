"""launch_param_builder (PickNik's, which MoveIt's ``moveit_configs_utils`` builds on): gazelle's stand-in, written
from its behaviour. A :class:`ParameterBuilder` collects a node's parameters from a package's share folder (YAML
files, xacro files expanded, file paths) into the dict a launch file's ``Node(parameters=[...])`` takes."""

from .launch_param_builder import ParameterBuilder
from .utils import ParameterBuilderFileNotFoundError, get_path, load_file, load_xacro, load_yaml

__all__ = [
    "ParameterBuilder",
    "ParameterBuilderFileNotFoundError",
    "get_path",
    "load_file",
    "load_xacro",
    "load_yaml",
]
