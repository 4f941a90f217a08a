"""gazelle's ``launch_yaml`` (ROS 2 Jazzy's package name): YAML launch files are read by ``launch.frontend``;
this package keeps the import paths launch files use (``launch_yaml.launch_description_sources``)."""
