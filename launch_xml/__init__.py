"""gazelle's ``launch_xml`` (ROS 2 Jazzy's package name): XML launch files are read by ``launch.frontend``;
this package keeps the import paths launch files use (``launch_xml.launch_description_sources``)."""
