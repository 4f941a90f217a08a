"""nav2_common.launch (navigation2 Jazzy): the substitutions Nav2-style bring-ups build their parameter files
with, and the multi-robot pose argument's parser."""

from .has_node_params import HasNodeParams
from .parse_multirobot_pose import ParseMultiRobotPose
from .replace_string import ReplaceString
from .rewritten_yaml import RewrittenYaml

__all__ = ["HasNodeParams", "ParseMultiRobotPose", "ReplaceString", "RewrittenYaml"]
