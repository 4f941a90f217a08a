"""Systems (Gazebo-style plugins) with configure/reset/pre_update/update/post_update phases."""

from ._base import PHYSICS as PHYSICS
from ._base import PRE_PHYSICS as PRE_PHYSICS
from ._base import RateGate as RateGate
from ._base import System as System
from ._base import SystemContext as SystemContext
from ._base import SystemManager as SystemManager
from ._base import UpdateInfo as UpdateInfo
from ._bus import Bus as Bus
from ._bus import Endpoint as Endpoint
from ._bus import MsgType as MsgType
from ._registry import create_system as create_system
from ._registry import supported_plugins as supported_plugins
