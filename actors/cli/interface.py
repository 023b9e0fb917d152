"""``actors interface list|packages|package|show|proto|generate``: interface types, as ``ros2 interface``."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

__all__ = ["register"]


def register(subparsers: Any) -> None:
    """Add the ``interface`` group and its verbs to the command line."""
    parser = subparsers.add_parser("interface", help="list, show and generate interface types")
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)
    root_help = "also search this generated interface root (repeatable)"

    listing = verbs.add_parser("list", help="list every message, service and action type")
    # Not exclusive, as ros2's: -m -s lists messages, then services.
    listing.add_argument("-m", "--only-msgs", action="store_true", help="list the messages")
    listing.add_argument("-s", "--only-srvs", action="store_true", help="list the services")
    listing.add_argument("-a", "--only-actions", action="store_true", help="list the actions")
    listing.add_argument("--root", action="append", default=[], type=Path, help=root_help)
    listing.set_defaults(func=list_types)

    show = verbs.add_parser("show", help="print a type's definition, nested types expanded")
    show.add_argument("type", metavar="TYPE", help="pkg/msg/Name, pkg/srv/Name, pkg/action/Name or pkg/Name")
    show.add_argument("--no-comments", action="store_true", help="leave out comments and blank lines")
    show.add_argument("--hash", action="store_true", help="print the type's RIHS01 hash (REP 2016) instead")
    show.add_argument("--root", action="append", default=[], type=Path, help=root_help)
    show.set_defaults(func=show_type)

    packages = verbs.add_parser("packages", help="list the packages that define interfaces")
    package = verbs.add_parser("package", help="list the interfaces of one package")
    package.add_argument("package", metavar="PACKAGE", help="e.g. std_msgs")
    for parser_ in (packages, package):
        only = parser_.add_mutually_exclusive_group()
        only.add_argument("-m", "--only-msgs", action="store_true", help="messages only")
        only.add_argument("-s", "--only-srvs", action="store_true", help="services only")
        only.add_argument("-a", "--only-actions", action="store_true", help="actions only")
        parser_.add_argument("--root", action="append", default=[], type=Path, help=root_help)
    packages.set_defaults(func=list_packages)
    package.set_defaults(func=list_package)

    proto = verbs.add_parser("proto", help="print a YAML prototype of a type (a service's request, an action's goal)")
    proto.add_argument("type", metavar="TYPE", help="e.g. geometry_msgs/msg/Twist")
    proto.add_argument("--no-quotes", action="store_true", help="without the outer quotes")
    proto.add_argument("--root", action="append", default=[], type=Path, help=root_help)
    proto.set_defaults(func=show_prototype)

    generate = verbs.add_parser("generate", help="generate Python modules beside .msg/.srv/.action sources")
    generate.add_argument(
        "roots",
        nargs="*",
        metavar="ROOT",
        type=Path,
        help="a folder of packages <ROOT>/<pkg>/msg/*.msg, srv/*.srv, action/*.action "
        "(default: the shipped interfaces)",
    )
    generate.set_defaults(func=generate_modules)


def list_types(args: argparse.Namespace) -> None:
    """Print ``Messages:``, ``Services:`` and ``Actions:`` (those that ``-m``/``-s``/``-a`` ask for),
    each followed by its types indented four spaces."""
    from actors import codec

    _register_roots(args.root)
    names = codec.list_types()
    sections = [
        (title, kind)
        for title, kind, only in (
            ("Messages", "/msg/", args.only_msgs),
            ("Services", "/srv/", args.only_srvs),
            ("Actions", "/action/", args.only_actions),
        )
        if only or not (args.only_msgs or args.only_srvs or args.only_actions)
    ]
    for title, kind in sections:
        print(f"{title}:")
        for name in names:
            if kind in name:
                print(f"    {name}")


def list_packages(args: argparse.Namespace) -> None:
    """Print each package that defines interfaces (of one kind with ``-m``/``-s``/``-a``), sorted."""
    print(*sorted({name.split("/")[0] for name in _types(args)}), sep="\n")


def list_package(args: argparse.Namespace) -> None:
    """Print ``PACKAGE/msg/Name`` and the like for each of its interfaces (of one kind with ``-m``...).

    UnknownInterfaceError for a package that defines no interface at all.
    """
    from actors.errors import UnknownInterfaceError

    if not any(name.split("/")[0] == args.package for name in _types(args, kinds=_KINDS)):
        raise UnknownInterfaceError(f"unknown package {args.package!r}")
    names = [name for name in _types(args) if name.split("/")[0] == args.package]
    order = {kind: i for i, kind in enumerate(_KINDS)}
    for name in sorted(names, key=lambda n: (order[n.split("/")[1]], n)):
        print(name)


_KINDS = ("msg", "srv", "action")


def _types(args: argparse.Namespace, kinds: tuple[str, ...] = ()) -> list[str]:
    """Every known type of ``kinds`` (by default: those ``-m``/``-s``/``-a`` ask for, else all)."""
    from actors import codec

    _register_roots(args.root)
    if not kinds:
        asked = [kind for kind, flag in zip(_KINDS, (args.only_msgs, args.only_srvs, args.only_actions)) if flag]
        kinds = tuple(asked) or _KINDS
    return [name for name in codec.list_types() if name.split("/")[1] in kinds]


def show_prototype(args: argparse.Namespace) -> None:
    """Print a default instance as YAML in double quotes, ready to paste into ``topic pub``.

    As ``ros2 interface proto``: a service's request, an action's goal.
    Raises UnknownInterfaceError for an unknown type.
    """
    from actors import codec

    _register_roots(args.root)
    cls = codec.get_type(args.type)
    cls = getattr(cls, "Goal", None) or getattr(cls, "Request", None) or cls
    text = codec.to_yaml(cls())
    print(text if args.no_quotes else f'"{text}"')


def show_type(args: argparse.Namespace) -> None:
    """Print a type's definition; raises UnknownInterfaceError for an unknown type."""
    from actors import codec

    _register_roots(args.root)
    cls = codec.get_type(args.type)
    if args.hash:
        print(codec.type_hash(cls))
        return
    comments = not args.no_comments
    if hasattr(cls, "Goal"):
        parts = [cls.Goal, cls.Result, cls.Feedback]
    elif hasattr(cls, "Request"):
        parts = [cls.Request, cls.Response]
    else:
        parts = [cls]
    lines = _expand(parts[0], comments)
    for part in parts[1:]:
        lines += ["---", *_expand(part, comments)]
    for line in lines:
        print(line)


def generate_modules(args: argparse.Namespace) -> None:
    """Generate the modules of each root and print the files written; raises IdlError."""
    from actors.messages import generate as idl_gen

    written = idl_gen.generate(args.roots)
    for path in written:
        print(f"wrote {path}")
    if not written:
        print("generated modules are up to date")


def _expand(cls: type[Any], comments: bool, depth: int = 0) -> list[str]:
    """The lines of ``cls``'s definition, each nested type's fields under its field, one tab deeper.

    As ``ros2 interface show`` does, nested types are shown without comments.
    """
    from actors import codec
    from actors.messages import idl

    pkg, kind, name = cls.__ros_type__.split("/")
    text = cls.__ros_definition__
    spec = idl.parse_message(text, path=cls.__ros_type__, pkg=pkg, name=name, kind=kind)
    nested = {field.line: field.type.ros_type for field in spec.fields if field.type.is_nested}
    keep_comments = comments and depth == 0
    lines = []
    for number, raw in enumerate(text.splitlines(), 1):
        line = raw if keep_comments else idl.strip_comment(raw).rstrip()
        if keep_comments or line.strip():
            lines.append("\t" * depth + line if line else "")
        if number in nested:
            lines += _expand(codec.get_type(nested[number]), comments, depth + 1)
    return lines


def _register_roots(roots: list[Path]) -> None:
    from actors import codec

    for root in roots:
        codec.register_root(root)
