"""launch_ros's tags and substitutions for XML and YAML launch files, read as launch_ros's own ``parse``
classmethods read them (Jazzy: launch_ros/actions/node.py, push_ros_namespace.py, set_parameter.py,
set_remap.py, set_parameters_from_file.py, substitutions/find_package.py, executable_in_package.py).

Tags: ``node`` (``pkg``, ``exec``, ``name``, ``namespace``, ``args``, ``ros_args``, ``exec_name``, nested
``param`` / ``remap`` / ``env``, and what ``executable`` takes), ``push_ros_namespace`` /
``push-ros-namespace``, ``set_parameter``, ``set_remap``, ``set_parameters_from_file``.
Substitutions: ``find-pkg-share``, ``find-pkg-prefix``, ``exec-in-pkg``."""

from __future__ import annotations

from typing import Any

from launch.frontend.entity import Entity
from launch.frontend.expose import expose_action, expose_substitution
from launch.frontend.type_utils import data_type_from_identifier
from launch.launch_exposures import condition_kwargs, parse_cmdline, process_kwargs

from . import actions, substitutions
from .parameter_descriptions import ParameterFile, ParameterValue

ENTITIES = list[Entity]


def _nested_parameters(params: list[Entity], parser: Any) -> dict[tuple[Any, ...], Any]:
    """``<param name value [type]>`` and ``<param name>`` holding more of them, as one nested dict keyed by
    name substitutions (node.py ``get_nested_dictionary_from_nested_key_value_pairs``)."""
    out: dict[tuple[Any, ...], Any] = {}
    for param in params:
        name = tuple(parser.parse_substitution(param.get_attr("name")))
        identifier = param.get_attr("type", optional=True)
        data_type = None if identifier is None else data_type_from_identifier(identifier)
        value = param.get_attr("value", data_type=data_type, optional=True)
        nested = param.get_attr("param", data_type=ENTITIES, optional=True)
        param.assert_entity_completely_parsed()
        if value is not None and nested:
            raise ValueError("nested parameters and value attributes are mutually exclusive")
        if data_type is not None and nested:
            raise ValueError("nested parameters and type attributes are mutually exclusive")
        if value is not None:
            out[name] = ParameterValue(parser.parse_if_substitutions(value), value_type=data_type)
        elif nested:
            out[name] = _nested_parameters(nested, parser)
        else:
            raise ValueError(f"<param name='{param.get_attr('name')}'> needs a value attribute or nested params")
    return out


def parse_parameters(params: list[Entity], parser: Any) -> list[Any]:
    """Each ``<param>`` of a node: ``from`` a parameters file (``allow_substs`` only there) or ``name``."""
    normalized: list[Any] = []
    for param in params:
        from_attr = param.get_attr("from", optional=True)
        allow_substs = param.get_attr("allow_substs", data_type=bool, optional=True)
        name = param.get_attr("name", optional=True)
        if from_attr is not None and name is not None:
            raise ValueError("<param>: name and from attributes are mutually exclusive")
        if from_attr is not None:
            param.assert_entity_completely_parsed()
            allow = parser.parse_substitution(allow_substs) if isinstance(allow_substs, str) else bool(allow_substs)
            normalized.append(ParameterFile(parser.parse_substitution(from_attr), allow_substs=allow))
        elif name is not None:
            if allow_substs is not None:
                raise ValueError("<param>: 'allow_substs' can only be used together with 'from'")
            normalized.append(_nested_parameters([param], parser))
        else:
            raise ValueError("<param> needs a name or a from attribute")
    return normalized


@expose_action("node")
def parse_node(entity: Entity, parser: Any) -> tuple[type, dict[str, Any]]:
    """node.py ``Node.parse``."""
    kwargs = process_kwargs(entity, parser, ignore=("cmd",))
    for key, attr in (("arguments", "args"), ("ros_arguments", "ros_args")):
        value = entity.get_attr(attr, optional=True)
        if value is not None:
            kwargs[key] = parse_cmdline(value, parser)
    kwargs.pop("name", None)
    for key, attr in (("node_name", "node-name"), ("name", "name"), ("exec_name", "exec_name")):
        value = entity.get_attr(attr, optional=True)
        if value is not None:
            kwargs[key] = parser.parse_substitution(value)
    package = entity.get_attr("pkg", optional=True)
    if package is not None:
        kwargs["package"] = parser.parse_substitution(package)
    kwargs["executable"] = parser.parse_substitution(entity.get_attr("exec"))
    namespace = entity.get_attr("namespace", optional=True)
    if namespace is not None:
        kwargs["namespace"] = parser.parse_substitution(namespace)
    remaps = entity.get_attr("remap", data_type=ENTITIES, optional=True)
    if remaps is not None:
        kwargs["remappings"] = [
            (parser.parse_substitution(r.get_attr("from")), parser.parse_substitution(r.get_attr("to"))) for r in remaps
        ]
        for r in remaps:
            r.assert_entity_completely_parsed()
    params = entity.get_attr("param", data_type=ENTITIES, optional=True)
    if params is not None:
        kwargs["parameters"] = parse_parameters(params, parser)
    return actions.Node, kwargs


def _push_ros_namespace(entity: Entity, parser: Any) -> tuple[type, dict[str, Any]]:
    """push_ros_namespace.py: ``namespace``."""
    kwargs = condition_kwargs(entity, parser)
    kwargs["namespace"] = parser.parse_substitution(entity.get_attr("namespace"))
    return actions.PushRosNamespace, kwargs


expose_action("push_ros_namespace")(_push_ros_namespace)
expose_action("push-ros-namespace")(_push_ros_namespace)


@expose_action("set_parameter")
def parse_set_parameter(entity: Entity, parser: Any) -> tuple[type, dict[str, Any]]:
    """set_parameter.py: ``name``, ``value``."""
    kwargs = condition_kwargs(entity, parser)
    kwargs["name"] = parser.parse_substitution(entity.get_attr("name"))
    kwargs["value"] = parser.parse_substitution(entity.get_attr("value"))
    return actions.SetParameter, kwargs


@expose_action("set_remap")
def parse_set_remap(entity: Entity, parser: Any) -> tuple[type, dict[str, Any]]:
    """set_remap.py: ``from``, ``to``."""
    kwargs = condition_kwargs(entity, parser)
    kwargs["src"] = parser.parse_substitution(entity.get_attr("from"))
    kwargs["dst"] = parser.parse_substitution(entity.get_attr("to"))
    return actions.SetRemap, kwargs


@expose_action("set_parameters_from_file")
def parse_set_parameters_from_file(entity: Entity, parser: Any) -> tuple[type, dict[str, Any]]:
    """set_parameters_from_file.py: ``filename``."""
    kwargs = condition_kwargs(entity, parser)
    kwargs["filename"] = parser.parse_substitution(entity.get_attr("filename"))
    return actions.SetParametersFromFile, kwargs


def _one_package(name: str, kind: type) -> Any:
    def parse(data: list[Any]) -> tuple[Any, dict[str, Any]]:
        if len(data) != 1:
            raise ValueError(f"$({name}) takes 1 argument (the package), got {len(data)}")
        return kind, {"package": data[0]}

    return parse


expose_substitution("find-pkg-share")(_one_package("find-pkg-share", substitutions.FindPackageShare))
expose_substitution("find-pkg-prefix")(_one_package("find-pkg-prefix", substitutions.FindPackagePrefix))


@expose_substitution("exec-in-pkg")
def parse_exec_in_pkg(data: list[Any]) -> tuple[Any, dict[str, Any]]:
    """executable_in_package.py: ``$(exec-in-pkg executable package)``."""
    if len(data) != 2:
        raise ValueError(f"$(exec-in-pkg) takes 2 arguments (executable, package), got {len(data)}")
    return substitutions.ExecutableInPackage, {"executable": data[0], "package": data[1]}


__all__ = ["parse_parameters"]
