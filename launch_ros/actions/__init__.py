"""launch_ros.actions: Node, PushRosNamespace, SetParameter, SetRemap, SetParametersFromFile."""

from __future__ import annotations

import os
import tempfile
from typing import Any

import yaml

from launch.action import Action
from launch.actions import ExecuteProcess
from launch.launch_context import LaunchContext
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

from ..parameter_descriptions import ParameterFile, ParameterValue, evaluate_parameter_value
from ..substitutions import find_executable

_NS_KEY = "ros_namespace"


def _ros_state(context: LaunchContext) -> dict[str, Any]:
    """The ROS scope carried in the launch configurations' scope (pushed/popped with groups)."""
    key = "__gazelle_launch_ros__"
    state = context.launch_configurations.get(key)
    if state is None or not isinstance(state, dict):
        state = {"namespace": "", "params": [], "remaps": []}
    return state


def _set_ros_state(context: LaunchContext, state: dict[str, Any]) -> None:
    context.launch_configurations["__gazelle_launch_ros__"] = state  # type: ignore[assignment] - launch's configurations are typed str -> str; this key holds our state


class PushRosNamespace(Action):
    """Nodes after it (in the same group) get this namespace (relative ones nest)."""

    def __init__(self, namespace: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.namespace = normalize_to_list_of_substitutions(namespace)

    def execute(self, context: LaunchContext) -> None:
        ns = perform_substitutions(context, self.namespace).strip()
        state = dict(_ros_state(context))
        if ns.startswith("/"):
            state["namespace"] = ns.rstrip("/")
        elif ns:
            state["namespace"] = f"{state['namespace'].rstrip('/')}/{ns.strip('/')}"
        _set_ros_state(context, state)


PushROSNamespace = PushRosNamespace


class SetParameter(Action):
    """A parameter every node after it (in the group) gets (``SetParameter('use_sim_time', True)``)."""

    def __init__(self, name: Any, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = normalize_to_list_of_substitutions(name)
        self.value = value

    def execute(self, context: LaunchContext) -> None:
        state = dict(_ros_state(context))
        state["params"] = [
            *state["params"],
            {perform_substitutions(context, self.name): evaluate_parameter_value(context, self.value)},
        ]
        _set_ros_state(context, state)


class SetParametersFromFile(Action):
    def __init__(self, filename: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.filename = normalize_to_list_of_substitutions(filename)

    def execute(self, context: LaunchContext) -> None:
        state = dict(_ros_state(context))
        state["params"] = [*state["params"], perform_substitutions(context, self.filename)]
        _set_ros_state(context, state)


class SetRemap(Action):
    """A remapping every node after it (in the group) gets."""

    def __init__(self, src: Any, dst: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.src, self.dst = normalize_to_list_of_substitutions(src), normalize_to_list_of_substitutions(dst)

    def execute(self, context: LaunchContext) -> None:
        state = dict(_ros_state(context))
        state["remaps"] = [
            *state["remaps"],
            (perform_substitutions(context, self.src), perform_substitutions(context, self.dst)),
        ]
        _set_ros_state(context, state)


class Node(ExecuteProcess):
    """A ROS node: ``package``/``executable`` found through the ament index (or colcon's ``bin/``), with
    ``name``, ``namespace``, ``parameters`` (dicts, YAML files, ParameterFile, ParameterValue),
    ``remappings``, ``arguments`` and ``ros_arguments`` passed on its ``--ros-args`` command line."""

    def __init__(
        self,
        *,
        executable: Any,
        package: Any = None,
        name: Any = None,
        namespace: Any = None,
        exec_name: Any = None,
        parameters: Any = None,
        remappings: Any = None,
        ros_arguments: Any = None,
        arguments: Any = None,
        node_name: Any = None,
        node_executable: Any = None,
        node_namespace: Any = None,
        **kwargs: Any,
    ) -> None:
        self.package = None if package is None else normalize_to_list_of_substitutions(package)
        self.executable = normalize_to_list_of_substitutions(executable if node_executable is None else node_executable)
        name = name if name is not None else node_name
        namespace = namespace if namespace is not None else node_namespace
        self.node_name = None if name is None else normalize_to_list_of_substitutions(name)
        self.node_namespace = None if namespace is None else normalize_to_list_of_substitutions(namespace)
        self.parameters = list(parameters or [])
        self.remappings = list(remappings or [])
        self.ros_arguments = list(ros_arguments or [])
        self.arguments = list(arguments or [])
        super().__init__(cmd=["<node>"], name=exec_name, **kwargs)

    def _command(self, context: LaunchContext) -> list[str]:
        exe = perform_substitutions(context, self.executable)
        if self.package is not None:
            path = find_executable(perform_substitutions(context, self.package), exe)
        else:
            import shutil

            path = shutil.which(exe, path=context.environment.get("PATH")) or exe
        cmd = [path, *(perform_substitutions(context, normalize_to_list_of_substitutions(a)) for a in self.arguments)]
        ros: list[str] = []
        state = _ros_state(context)
        if self.node_name is not None:
            ros += ["-r", f"__node:={perform_substitutions(context, self.node_name)}"]
        ns = state["namespace"]
        if self.node_namespace is not None:
            own = perform_substitutions(context, self.node_namespace)
            ns = own if own.startswith("/") else (f"{ns.rstrip('/')}/{own.strip('/')}" if own.strip("/") else ns)
        if ns:
            ros += ["-r", f"__ns:={'/' + ns.strip('/')}"]
        for p in [*state["params"], *self.parameters]:
            ros += self._param_args(context, p)
        for src, dst in [*state["remaps"], *self.remappings]:
            s = src if isinstance(src, str) else perform_substitutions(context, normalize_to_list_of_substitutions(src))
            d = dst if isinstance(dst, str) else perform_substitutions(context, normalize_to_list_of_substitutions(dst))
            ros += ["-r", f"{s}:={d}"]
        ros += [perform_substitutions(context, normalize_to_list_of_substitutions(a)) for a in self.ros_arguments]
        return cmd + (["--ros-args", *ros] if ros else [])

    def _param_args(self, context: LaunchContext, p: Any) -> list[str]:
        if isinstance(p, dict):
            nested = _evaluate_parameter_dict(context, p)
            fd, path = tempfile.mkstemp(prefix="launch_params_", suffix=".yaml")
            with os.fdopen(fd, "w") as f:
                yaml.safe_dump({"/**": {"ros__parameters": nested}}, f)
            return ["--params-file", path]
        if isinstance(p, ParameterFile):
            return ["--params-file", p.evaluate(context)]
        path = p if isinstance(p, str) else perform_substitutions(context, normalize_to_list_of_substitutions(p))
        return ["--params-file", path]

    def execute(self, context: LaunchContext) -> None:
        if self.name is None:
            base = perform_substitutions(context, self.executable)
            self.name = normalize_to_list_of_substitutions(os.path.basename(base))
        return super().execute(context)


def _evaluate_parameter_dict(context: LaunchContext, params: dict[Any, Any]) -> dict[str, Any]:
    """A node's ``{name: value}`` with names and values performed; a value that is itself a dict is a group of
    nested names (XML's ``<param name="a"><param name="b" value="1"/></param>`` is ``a.b``), dumped as nested
    YAML, which rcl reads as ``a.b`` (launch_ros's normalize_parameters flattens it to the same names)."""
    out: dict[str, Any] = {}
    for k, v in params.items():
        name = k if isinstance(k, str) else perform_substitutions(context, normalize_to_list_of_substitutions(k))
        if isinstance(v, dict):
            out[name] = _evaluate_parameter_dict(context, v)
        elif isinstance(v, ParameterValue):
            out[name] = v.evaluate(context)
        else:
            out[name] = evaluate_parameter_value(context, v)
    return out


class LifecycleNode(Node):
    def __init__(self, **kwargs: Any) -> None:
        raise NotImplementedError("launch_ros.actions.LifecycleNode is not supported by gazelle's launch yet")


class ComposableNodeContainer(Node):
    def __init__(self, **kwargs: Any) -> None:
        raise NotImplementedError("launch_ros.actions.ComposableNodeContainer is not supported by gazelle's launch yet")


__all__ = [
    "ComposableNodeContainer",
    "LifecycleNode",
    "Node",
    "PushROSNamespace",
    "PushRosNamespace",
    "SetParameter",
    "SetParametersFromFile",
    "SetRemap",
]
