"""InvalidLaunchFileError: a launch file that cannot be read (Jazzy: launch/invalid_launch_file_error.py). On the
ground floor: the description sources raise it, and the XML and YAML front end's error derives from it."""


class InvalidLaunchFileError(Exception):
    pass


__all__ = ["InvalidLaunchFileError"]
