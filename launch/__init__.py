"""gazelle's implementation of ROS 2's ``launch`` package (Python launch files), for environments
without a ROS installation. A sourced ROS installation puts its own ``launch`` first on the path.

The API follows launch (Jazzy): substitutions are evaluated lazily in a LaunchContext, actions are
visited in order, processes run with their output prefixed ``[name-N]``, Ctrl-C stops the tree.
"""

from . import (
    actions,
    conditions,
    event_handlers,
    events,
    frontend,
    launch_description_sources,
    launch_exposures,  # noqa: F401 - exposes launch's tags and substitutions to XML and YAML files
    substitutions,
    utilities,
)
from .action import Action
from .condition import Condition
from .event import Event, EventHandler
from .invalid_launch_file_error import InvalidLaunchFileError
from .launch_context import LaunchContext
from .launch_description import LaunchDescription
from .launch_service import LaunchService
from .substitution import SomeSubstitutionsType, Substitution

SomeActionsType = object
SomeSubstitutionsType_types_tuple = (str, Substitution)

__all__ = [
    "Action",
    "Condition",
    "Event",
    "EventHandler",
    "InvalidLaunchFileError",
    "LaunchContext",
    "LaunchDescription",
    "LaunchService",
    "SomeSubstitutionsType",
    "Substitution",
    "actions",
    "conditions",
    "event_handlers",
    "events",
    "frontend",
    "launch_description_sources",
    "substitutions",
    "utilities",
]
