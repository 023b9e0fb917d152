"""rclpy's name helpers on the overlay: validate_*, expand_topic_name, topic_or_service_is_hidden."""

from __future__ import annotations

import pytest

from actors.compat.rclpy.exceptions import (
    InvalidNamespaceException,
    InvalidNodeNameException,
    InvalidServiceNameException,
    InvalidTopicNameException,
)
from actors.compat.rclpy.expand_topic_name import expand_topic_name
from actors.compat.rclpy.topic_or_service_is_hidden import topic_or_service_is_hidden
from actors.compat.rclpy.validate_full_topic_name import validate_full_topic_name
from actors.compat.rclpy.validate_namespace import validate_namespace
from actors.compat.rclpy.validate_node_name import validate_node_name
from actors.compat.rclpy.validate_topic_name import validate_topic_name


@pytest.mark.parametrize("name", ["scan", "/robot/scan", "~/odom", "{node}/status", "~"])
def test_names_before_expansion_may_be_relative_private_or_substituted(name):
    assert validate_topic_name(name) is True


@pytest.mark.parametrize(
    ("name", "rule"),
    [
        ("", "must not be empty"),
        ("cmd_vel/", "must not end with a forward slash"),
        ("speed!", "must not contain characters"),
        ("a/~b", "'~' only as its first character"),
        ("{node/x", "balanced"),
        ("robot/2d", "must not start with a number"),
        ("a//b", "repeated '/'"),
    ],
)
def test_each_broken_rule_is_named(name, rule):
    with pytest.raises(InvalidTopicNameException, match=rule):
        validate_topic_name(name)
    with pytest.raises(InvalidServiceNameException, match=rule):
        validate_topic_name(name, is_service=True)


def test_a_full_name_must_be_absolute_and_plain():
    assert validate_full_topic_name("/ns/node/scan")
    with pytest.raises(InvalidTopicNameException, match="must be absolute"):
        validate_full_topic_name("scan")
    with pytest.raises(InvalidServiceNameException, match="must not contain characters"):
        validate_full_topic_name("/ns/{node}", is_service=True)


def test_namespaces_and_node_names():
    assert validate_namespace("/") and validate_namespace("/fleet/r2")
    for namespace, rule in [("", "empty"), ("fleet", "absolute"), ("/fleet/", "end with"), ("/1st", "number")]:
        with pytest.raises(InvalidNamespaceException, match=rule):
            validate_namespace(namespace)
    assert validate_node_name("talker_2")
    for name, rule in [("", "empty"), ("2talker", "number"), ("talk.er", "characters"), ("/talker", "characters")]:
        with pytest.raises(InvalidNodeNameException, match=rule):
            validate_node_name(name)


def test_expansion_follows_the_node_and_its_namespace():
    assert expand_topic_name("scan", "lidar", "/robot") == "/robot/scan"
    assert expand_topic_name("~/status", "lidar", "/") == "/lidar/status"
    assert expand_topic_name("{node}/raw", "lidar", "/robot") == "/robot/lidar/raw"
    assert expand_topic_name("/abs", "lidar", "/robot") == "/abs"
    for args, what in [
        (("x", "bad?", "/"), "node name"),
        (("x", "n", "rel"), "namespace"),
        (("x?", "n", "/"), "topic"),
    ]:
        with pytest.raises(ValueError, match=what):
            expand_topic_name(*args)


@pytest.mark.parametrize(
    ("name", "hidden"), [("/scan", False), ("/_scan", True), ("/a/_b/c", True), ("/a_/b", False), ("", False)]
)
def test_a_name_is_hidden_when_a_part_starts_with_an_underscore(name, hidden):
    assert topic_or_service_is_hidden(name) is hidden
