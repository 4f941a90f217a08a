# gazelle virtualenv: the venv is a ROS prefix, set up by activating it (bin/activate). This file is the
# prefix's local_setup.{sh,bash,zsh}, which colcon chains before a workspace built over the venv, and which
# bin/activate sources: it defines the shell functions that /opt/ros/<distro>/setup.bash leaves defined and
# packages' environment hooks call (ament_package's template/prefix_level: local_setup.sh.in defines
# ament_prepend_unique_value, setup.sh.in ament_append_unique_value). A package's hook from a .sh.in
# (`ament_environment_hooks(env-hooks/my_pkg.sh.in)`: `ament_prepend_unique_value GZ_SIM_RESOURCE_PATH ...`)
# failed with "command not found" without them, and its addition was lost.
# Written for any POSIX shell (sh, bash, zsh): no word splitting is relied on. Installed by
# scripts/install_ros_packages.py from scripts/ament_prefix_setup.sh.

# ament_prepend_unique_value NAME VALUE: VALUE first in the ':'-separated list NAME, exported, unless it is
# already one of its entries; no trailing ':' when NAME was empty.
ament_prepend_unique_value() {
  case "$1" in
    '' | [0-9]* | *[!A-Za-z0-9_]*)
      echo "ament_prepend_unique_value: '$1' is not a variable name" >&2
      return 1
      ;;
  esac
  eval "_gazelle_ament_values=\"\${$1:-}\""
  case ":$_gazelle_ament_values:" in
    *":$2:"*) ;;
    *)
      if [ -z "$_gazelle_ament_values" ]; then
        eval "export $1=\"\$2\""
      else
        eval "export $1=\"\$2:\$_gazelle_ament_values\""
      fi
      ;;
  esac
  unset _gazelle_ament_values
}

# ament_append_unique_value NAME VALUE: VALUE last in the ':'-separated list NAME unless it is already one of
# its entries; no leading ':' when NAME was empty. Like ament's, it does not export NAME (a variable the
# environment already has stays exported).
ament_append_unique_value() {
  case "$1" in
    '' | [0-9]* | *[!A-Za-z0-9_]*)
      echo "ament_append_unique_value: '$1' is not a variable name" >&2
      return 1
      ;;
  esac
  eval "_gazelle_ament_values=\"\${$1:-}\""
  case ":$_gazelle_ament_values:" in
    *":$2:"*) ;;
    *)
      if [ -z "$_gazelle_ament_values" ]; then
        eval "$1=\"\$2\""
      else
        eval "$1=\"\$_gazelle_ament_values:\$2\""
      fi
      ;;
  esac
  unset _gazelle_ament_values
}
