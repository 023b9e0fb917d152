"""ROS name rules: relative, absolute and private names, namespaces, remapping."""

import pytest

from actors.errors import InvalidNameError
from actors.ros.names import Resolver, expand, normalize_namespace, validate_node_name


@pytest.mark.parametrize(
    ("name", "namespace", "expected"),
    [
        ("topic", "/", "/topic"),
        ("topic", "/robot1", "/robot1/topic"),
        ("/topic", "/robot1", "/topic"),
        ("~/status", "/robot1", "/robot1/talker/status"),
        ("~", "/", "/talker"),
        ("a/b", "/ns", "/ns/a/b"),
    ],
)
def test_expand(name, namespace, expected):
    assert expand(name, namespace, "talker") == expected


@pytest.mark.parametrize("bad", ["", "1topic", "a//b", "topic/", "with space", "a-b"])
def test_invalid_topic_names_are_refused(bad):
    with pytest.raises(InvalidNameError, match=r"topic name .* is invalid"):
        expand(bad, "/", "node")


def test_substitutions_name_the_node_and_its_namespace():
    assert expand("{node}/status", "/robot1", "talker") == "/robot1/talker/status"
    assert expand("/{ns}/{namespace}/x", "/robot1", "talker") == "/robot1/robot1/x"
    with pytest.raises(InvalidNameError, match=r"'/a/\{colour\}' is invalid: unknown substitution: \{colour\}"):
        expand("/a/{colour}", "/", "talker")


def test_a_name_that_is_no_string_is_a_type_error():
    with pytest.raises(TypeError, match="must be a str, got 42"):
        expand(42, "/", "talker")  # type: ignore[arg-type]


def test_namespaces_are_normalized():
    assert normalize_namespace("") == "/"
    assert normalize_namespace("robot1") == "/robot1"
    assert normalize_namespace("/a/b/") == "/a/b"
    with pytest.raises(InvalidNameError):
        normalize_namespace("/9lives")


def test_node_names():
    assert validate_node_name("minimal_publisher") == "minimal_publisher"
    with pytest.raises(InvalidNameError, match="invalid node name"):
        validate_node_name("has/slash")


def test_remapping_matches_expanded_names():
    resolver = Resolver("/robot1", "talker", {"topic": "chatter", "/abs": "/elsewhere"})
    assert resolver.resolve("topic") == "/robot1/chatter"
    assert resolver.resolve("/robot1/topic") == "/robot1/chatter"
    assert resolver.resolve("/abs") == "/elsewhere"
    assert resolver.resolve("other") == "/robot1/other"
