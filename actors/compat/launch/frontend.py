"""XML and YAML launch files, read into the same actions the Python front end makes.

Both front ends are trees of tags with attributes (``<node pkg="x" exec="y">``,
``- node: {pkg: x, exec: y}``); :class:`Tag` is that tree with each tag's line,
whatever the file's syntax.  Attribute values may hold substitutions,
``$(var name)``, ``$(env NAME [default])``, ``$(find-pkg-share pkg)``,
``$(find-pkg-prefix pkg)``, ``$(dirname)``, ``$(filename)``, ``$(eval expr)``,
``$(not x)``, ``$(and x y)``, ``$(or x y)``, nested as ROS allows.  Every error
is a LaunchFileError naming file and line.
"""

from __future__ import annotations

import os
import shlex
import xml.parsers.expat
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import yaml

import actors.compat.launch.actions as actions
import actors.compat.launch.conditions as conditions
import actors.compat.launch.substitutions as substitutions
import actors.compat.launch_ros.actions as ros_actions
import actors.compat.launch_ros.substitutions as ros_substitutions
from actors.compat.launch.entities import Action, LaunchDescription, LaunchDescriptionEntity, Substitution
from actors.compat.launch.launch_description_sources import AnyLaunchDescriptionSource
from actors.errors import LaunchFileError

__all__ = ["Tag", "load_xml", "load_yaml", "parse_substitutions"]


@dataclass
class Tag:
    """One tag of a launch file: its kind, attributes, child tags and line."""

    kind: str
    attributes: dict[str, Any]
    children: list[Tag] = field(default_factory=list)
    line: int = 0
    path: str = ""

    @property
    def where(self) -> str:
        """``file:line``."""
        return f"{self.path}:{self.line}"

    def get(self, name: str, default: Any = None) -> Any:
        """An attribute's raw value."""
        return self.attributes.get(name, default)

    def need(self, name: str) -> Any:
        """An attribute that must be there."""
        if name not in self.attributes:
            raise LaunchFileError(f"{self.where}: <{self.kind}> needs the attribute {name!r}")
        return self.attributes[name]

    def subs(self, kind: str) -> list[Tag]:
        """The child tags of ``kind`` (``<param>`` of a node, ``<arg>`` of an include)."""
        return [child for child in self.children if child.kind == kind]


# --------------------------------------------------------------------------- reading the files


def load_xml(path: str) -> LaunchDescription:
    """The description of an XML launch file."""
    path = os.path.abspath(path)
    parser = xml.parsers.expat.ParserCreate()
    stack: list[Tag] = []
    roots: list[Tag] = []

    def start(name: str, attributes: dict[str, str]) -> None:
        tag = Tag(name, dict(attributes), [], parser.CurrentLineNumber, path)
        (stack[-1].children if stack else roots).append(tag)
        stack.append(tag)

    parser.StartElementHandler = start
    parser.EndElementHandler = lambda name: stack.pop()
    try:
        with open(path, "rb") as file:
            parser.ParseFile(file)
    except xml.parsers.expat.ExpatError as exc:
        raise LaunchFileError(
            f"{path}:{exc.lineno}: not well-formed XML: {xml.parsers.expat.errors.messages[exc.code]}"
        ) from None
    root = roots[0]
    if root.kind != "launch":
        raise LaunchFileError(f"{root.where}: the root tag must be <launch>, got <{root.kind}>")
    return _description(root)


def load_yaml(path: str) -> LaunchDescription:
    """The description of a YAML launch file."""
    path = os.path.abspath(path)
    with open(path, encoding="utf-8") as file:
        text = file.read()
    loader = yaml.SafeLoader(text)
    try:
        node = loader.get_single_node()
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        line = mark.line + 1 if mark is not None else 0
        raise LaunchFileError(f"{path}:{line}: not YAML: {getattr(exc, 'problem', exc)}") from None
    finally:
        loader.dispose()
    if not isinstance(node, yaml.MappingNode) or len(node.value) != 1 or node.value[0][0].value != "launch":
        raise LaunchFileError(f"{path}:1: a YAML launch file is one mapping, 'launch:' and a list of actions")
    constructor = yaml.SafeLoader("")
    root = Tag("launch", {}, _yaml_children(node.value[0][1], path, constructor), node.start_mark.line + 1, path)
    return _description(root)


def _yaml_children(node: Any, path: str, constructor: Any) -> list[Tag]:
    if not isinstance(node, yaml.SequenceNode):
        raise LaunchFileError(f"{path}:{node.start_mark.line + 1}: expected a list of actions")
    return [_yaml_tag(item, path, constructor) for item in node.value]


def _yaml_tag(node: Any, path: str, constructor: Any) -> Tag:
    line = node.start_mark.line + 1
    if not isinstance(node, yaml.MappingNode) or len(node.value) != 1:
        raise LaunchFileError(f"{path}:{line}: expected one action, as 'node: {{...}}'")
    key, value = node.value[0]
    tag = Tag(key.value, {}, [], line, path)
    if isinstance(value, yaml.SequenceNode):
        tag.children = _yaml_children(value, path, constructor)
        return tag
    if not isinstance(value, yaml.MappingNode):
        raise LaunchFileError(f"{path}:{line}: {key.value}: expected its attributes as a mapping")
    for attribute, item in value.value:
        name = attribute.value
        if name == "children":
            tag.children += _yaml_children(item, path, constructor)
        elif isinstance(item, yaml.SequenceNode) and item.value and isinstance(item.value[0], yaml.MappingNode):
            # A node's param/remap/env list, an include's arg list: each item a tag of that kind.
            for entry in item.value:
                tag.children.append(
                    Tag(name, constructor.construct_object(entry, deep=True), [], entry.start_mark.line + 1, path)
                )
        else:
            tag.attributes[name] = constructor.construct_object(item, deep=True)
    return tag


# --------------------------------------------------------------------------- substitutions


def parse_substitutions(text: Any, tag: Tag) -> list[Any]:
    """An attribute's value as text and substitutions (``$(var x)``...)."""
    if not isinstance(text, str):
        return [str(text).lower() if isinstance(text, bool) else str(text)]
    return _parse(text, 0, tag, inside=False)[0]


def _parse(text: str, i: int, tag: Tag, *, inside: bool) -> tuple[list[Any], int]:
    parts: list[Any] = []
    plain = ""
    while i < len(text):
        if text.startswith("$(", i):
            if plain:
                parts.append(plain)
                plain = ""
            substitution, i = _one(text, i + 2, tag)
            parts.append(substitution)
            continue
        char = text[i]
        if inside and char in " )":
            break
        plain += char
        i += 1
    if plain:
        parts.append(plain)
    return parts, i


def _one(text: str, i: int, tag: Tag) -> tuple[Substitution, int]:
    j = i
    while j < len(text) and text[j] not in " )":
        j += 1
    name = text[i:j]
    args: list[list[Any]] = []
    while j < len(text) and text[j] == " ":
        j += 1
        if text[j : j + 1] in ("'", '"'):
            quote = text[j]
            close = text.find(quote, j + 1)
            if close < 0:
                raise LaunchFileError(f"{tag.where}: unclosed quote in {text!r}")
            args.append(_parse(text[j + 1 : close], 0, tag, inside=False)[0])
            j = close + 1
            continue
        arg, j = _parse(text, j, tag, inside=True)
        if arg:
            args.append(arg)
    if j >= len(text) or text[j] != ")":
        raise LaunchFileError(f"{tag.where}: unclosed $( in {text!r}")
    return _make(name, args, tag, text), j + 1


def _this_file(kind: type[substitutions.ThisLaunchFile], tag: Tag) -> Substitution:
    found = kind()
    found.path = tag.path  # the file being read, whoever reads it
    return found


def _second(args: list[list[Any]]) -> Any:
    return args[1] if len(args) > 1 else None


# Each substitution by its name in $(...): how many arguments it takes, and what it makes of them.
_SUBSTITUTIONS: dict[str, tuple[int, int, Callable[[list[list[Any]], Tag], Substitution]]] = {
    "var": (1, 2, lambda a, t: substitutions.LaunchConfiguration(a[0], default=_second(a))),
    "env": (1, 2, lambda a, t: substitutions.EnvironmentVariable(a[0], default_value=_second(a))),
    "find-pkg-share": (1, 1, lambda a, t: ros_substitutions.FindPackageShare(a[0])),
    "find-pkg-prefix": (1, 1, lambda a, t: ros_substitutions.FindPackagePrefix(a[0])),
    "dirname": (0, 0, lambda a, t: _this_file(substitutions.ThisLaunchFileDir, t)),
    "filename": (0, 0, lambda a, t: _this_file(substitutions.ThisLaunchFile, t)),
    "eval": (1, 1, lambda a, t: substitutions.PythonExpression(a[0])),
    "find-exec": (1, 1, lambda a, t: substitutions.FindExecutable(name=a[0])),
    "not": (1, 1, lambda a, t: substitutions.NotSubstitution(a[0])),
    "and": (2, 2, lambda a, t: substitutions.AndSubstitution(a[0], a[1])),
    "or": (2, 2, lambda a, t: substitutions.OrSubstitution(a[0], a[1])),
}


def _make(name: str, args: list[list[Any]], tag: Tag, text: str) -> Substitution:
    if name not in _SUBSTITUTIONS:
        known = ", ".join(_SUBSTITUTIONS)
        raise LaunchFileError(f"{tag.where}: unknown substitution $({name} ...) in {text!r} (actors knows {known})")
    low, high, make = _SUBSTITUTIONS[name]
    if not low <= len(args) <= high:
        raise LaunchFileError(
            f"{tag.where}: $({name} ...) takes {low} to {high} arguments, got {len(args)} in {text!r}"
        )
    return make(args, tag)


# --------------------------------------------------------------------------- tags to actions


def _description(root: Tag) -> LaunchDescription:
    description = LaunchDescription([_entity(child) for child in root.children])
    description.where = root.where
    return description


def _entities(tags: list[Tag]) -> list[LaunchDescriptionEntity]:
    return [_entity(tag) for tag in tags]


def _condition(tag: Tag) -> Any:
    if "if" in tag.attributes and "unless" in tag.attributes:
        raise LaunchFileError(f"{tag.where}: <{tag.kind}> has both if and unless")
    if "if" in tag.attributes:
        return conditions.IfCondition(parse_substitutions(tag.attributes["if"], tag))
    if "unless" in tag.attributes:
        return conditions.UnlessCondition(parse_substitutions(tag.attributes["unless"], tag))
    return None


def _text(tag: Tag, name: str, default: Any = None) -> Any:
    value = tag.get(name)
    return default if value is None else parse_substitutions(value, tag)


def _flag(tag: Tag, name: str, default: bool) -> bool:
    value = tag.get(name)
    if value is None:
        return default
    if isinstance(value, bool):
        return value
    text = str(value).strip().lower()
    if text not in ("true", "false", "1", "0"):
        raise LaunchFileError(f"{tag.where}: {name}={value!r}: expected true or false")
    return text in ("true", "1")


def _entity(tag: Tag) -> LaunchDescriptionEntity:
    build = _BUILDERS.get(tag.kind)
    if build is None:
        known = ", ".join(sorted(_BUILDERS))
        raise LaunchFileError(f"{tag.where}: unknown tag <{tag.kind}> (actors knows {known})")
    entity = build(tag)
    entity.where = tag.where
    if isinstance(entity, Action) and entity.condition is None:
        entity.condition = _condition(tag)
    return entity


def _arg(tag: Tag) -> LaunchDescriptionEntity:
    choices = tag.get("choices")
    if isinstance(choices, str):
        choices = [part.strip() for part in choices.split("|")]
    return actions.DeclareLaunchArgument(
        tag.need("name"), default_value=_text(tag, "default"), description=tag.get("description"), choices=choices
    )


def _include(tag: Tag) -> LaunchDescriptionEntity:
    arguments = [(arg.need("name"), parse_substitutions(arg.need("value"), arg)) for arg in tag.subs("arg")]
    return actions.IncludeLaunchDescription(
        AnyLaunchDescriptionSource(parse_substitutions(tag.need("file"), tag)), launch_arguments=arguments
    )


def _group(tag: Tag) -> LaunchDescriptionEntity:
    inside = _entities([child for child in tag.children if child.kind != "keep"])
    namespace = tag.get("namespace") or tag.get("ns")
    if namespace is not None:
        inside.insert(0, ros_actions.PushRosNamespace(parse_substitutions(namespace, tag)))
    return actions.GroupAction(inside, scoped=_flag(tag, "scoped", True), forwarding=_flag(tag, "forwarding", True))


def _node(tag: Tag) -> LaunchDescriptionEntity:
    parameters: list[Any] = []
    for param in tag.subs("param"):
        if "from" in param.attributes:
            parameters.append(parse_substitutions(param.attributes["from"], param))
        else:
            parameters.append({param.need("name"): _param_value(param)})
    remappings = [
        (parse_substitutions(r.need("from"), r), parse_substitutions(r.need("to"), r)) for r in tag.subs("remap")
    ]
    arguments = str(tag.get("args", "")).split() if tag.get("args") else []
    ros_arguments = str(tag.get("ros_args", "")).split() if tag.get("ros_args") else []
    return ros_actions.Node(
        package=_text(tag, "pkg"),
        executable=parse_substitutions(tag.need("exec"), tag),
        name=_text(tag, "name"),
        namespace=_text(tag, "namespace", _text(tag, "ns")),
        exec_name=_text(tag, "exec_name"),
        parameters=parameters,
        remappings=remappings,
        arguments=[parse_substitutions(a, tag) for a in arguments],
        ros_arguments=[parse_substitutions(a, tag) for a in ros_arguments],
        output=tag.get("output", "log"),
        respawn=_flag(tag, "respawn", False),
        respawn_delay=float(tag.get("respawn_delay", 0.0)),
    )


def _param_value(param: Tag) -> Any:
    value = param.need("value")
    if isinstance(value, str) and "$(" in value:
        return parse_substitutions(value, param)
    if isinstance(value, str):
        try:
            return yaml.safe_load(value) if value else value
        except yaml.YAMLError:
            return value
    return value


def _executable(tag: Tag) -> LaunchDescriptionEntity:
    environment = {env.need("name"): parse_substitutions(env.need("value"), env) for env in tag.subs("env")}
    command = str(tag.need("cmd"))
    return actions.ExecuteProcess(
        cmd=_command_words(command, tag),
        name=_text(tag, "name"),
        cwd=_text(tag, "cwd"),
        additional_env=environment,
        shell=_flag(tag, "shell", False),
        output=tag.get("output", "log"),
    )


def _command_words(command: str, tag: Tag) -> list[list[Any]]:
    """A ``cmd`` as ROS's launch splits it: its text by shell quoting rules, a substitution part of the
    word it touches."""
    words: list[list[Any]] = []
    word: list[Any] = []

    def close() -> None:
        nonlocal word
        if word:
            words.append(word)
        word = []

    for part in parse_substitutions(command, tag):
        if not isinstance(part, str):
            word.append(part)
            continue
        try:
            tokens = shlex.split(part)
        except ValueError as exc:
            raise LaunchFileError(f"{tag.where}: cmd {command!r}: {exc}") from None
        if part[0].isspace():
            close()
        for index, token in enumerate(tokens):
            if index:
                close()
            word.append(token)
        if part[-1].isspace():
            close()
    close()
    return words


def _timer(tag: Tag) -> LaunchDescriptionEntity:
    return actions.TimerAction(period=parse_substitutions(tag.need("period"), tag), actions=_entities(tag.children))


def _let(tag: Tag) -> LaunchDescriptionEntity:
    return actions.SetLaunchConfiguration(tag.need("name"), parse_substitutions(tag.need("value"), tag))


_BUILDERS: dict[str, Callable[[Tag], LaunchDescriptionEntity]] = {
    "arg": _arg,
    "let": _let,
    "include": _include,
    "group": _group,
    "node": _node,
    "executable": _executable,
    "timer": _timer,
    "log": lambda tag: actions.LogInfo(msg=parse_substitutions(tag.need("message"), tag)),
    "push-ros-namespace": lambda tag: ros_actions.PushRosNamespace(parse_substitutions(tag.need("namespace"), tag)),
    "push_ros_namespace": lambda tag: ros_actions.PushRosNamespace(parse_substitutions(tag.need("namespace"), tag)),
    "set_parameter": lambda tag: ros_actions.SetParameter(tag.need("name"), _param_value(tag)),
    "set_remap": lambda tag: ros_actions.SetRemap(
        parse_substitutions(tag.need("from"), tag), parse_substitutions(tag.need("to"), tag)
    ),
    "set_env": lambda tag: actions.SetEnvironmentVariable(
        parse_substitutions(tag.need("name"), tag), parse_substitutions(tag.need("value"), tag)
    ),
    "shutdown": lambda tag: actions.Shutdown(reason=str(tag.get("reason", "reason not given"))),
}
