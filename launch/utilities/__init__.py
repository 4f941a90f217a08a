"""launch.utilities (Jazzy): the helpers launch files and their Python packages import from launch
(``from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions``: nav2_common's
substitutions, many bring-ups' own). One missing name aborted the whole launch at its import.

Not here: ``AsyncSafeSignalManager`` and ``visit_all_entities_and_collect_futures``, launch's own machinery,
which gazelle's launch service does its own way.
"""

from .class_tools import is_a, is_a_subclass, isclassinstance
from .ensure_argument_type import ensure_argument_type
from .normalize_to_list_of_entities import normalize_to_list_of_entities
from .normalize_to_list_of_substitutions_impl import normalize_to_list_of_substitutions
from .perform_substitutions_impl import perform_substitutions

__all__ = [
    "ensure_argument_type",
    "is_a",
    "is_a_subclass",
    "isclassinstance",
    "normalize_to_list_of_entities",
    "normalize_to_list_of_substitutions",
    "perform_substitutions",
]
