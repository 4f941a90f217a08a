"""``python -m gazelle.cli`` = the ``gazelle`` command."""

from . import main

main()
