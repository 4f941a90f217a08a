#!@PYTHON@
"""gazebo_ros's spawn_entity.py: gazelle spawn, with the same flags."""

import sys

from gazelle.ros import spawn_main

sys.exit(spawn_main(sys.argv[1:]))
