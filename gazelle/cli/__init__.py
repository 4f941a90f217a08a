"""The ``gazelle`` command."""

from ._gz import gz_sim_args as gz_sim_args
from ._main import app as app
from ._main import main as main
