"""moveit_configs_utils.substitutions: ``Xacro``, a file expanded by xacro at launch time."""

from .xacro import Xacro

__all__ = ["Xacro"]
