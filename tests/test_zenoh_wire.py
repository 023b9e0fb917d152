"""What the Zenoh transport puts on the wire, pinned: keys, tokens, QoS strings, attachments, CDR.

The references are rmw_zenoh_cpp's rules and what an independent
implementation (zenoh-ros2-sdk, recorded in tests/goldens/zenoh_ros2_sdk.json)
actually sent, so CI needs no third-party peer.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from actors import codec
from actors.ros.qos import DurabilityPolicy, HistoryPolicy, LivelinessPolicy, QoSSnapshot, ReliabilityPolicy
from actors.transport.zenoh import attachment
from actors.transport.zenoh.keys import (
    data_key,
    dds_type_name,
    endpoint_token,
    node_token,
    parse_qos,
    parse_token,
    qos_string,
    ros_type_name,
)
from interfaces.example_interfaces.srv import AddTwoInts
from interfaces.std_msgs.msg import String

SDK = json.loads((Path(__file__).parent / "goldens" / "zenoh_ros2_sdk.json").read_text())
STRING_HASH = "RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18"
ADD_HASH = "RIHS01_e118de6bf5eeb66a2491b5bda11202e7b68f198d6f67922cf30364858239c81a"


def sdk_token(kind: str, node: str = "") -> str:
    return next(t for t in SDK["tokens"] if f"/{kind}/" in t and f"/{node}" in t)


def test_type_names_and_data_keys_are_rmw_zenohs():
    assert dds_type_name("std_msgs/msg/String") == "std_msgs::msg::dds_::String_"
    assert dds_type_name("example_interfaces/srv/AddTwoInts") == "example_interfaces::srv::dds_::AddTwoInts_"
    assert (
        ros_type_name("example_interfaces::action::dds_::Fibonacci_SendGoal_")
        == "example_interfaces/action/Fibonacci_SendGoal"
    )
    assert codec.type_hash(String) == STRING_HASH
    assert data_key(0, "/topic", "std_msgs/msg/String", STRING_HASH) == SDK["samples"][0]["key"]
    assert data_key(0, "/add_two_ints", "example_interfaces/srv/AddTwoInts", ADD_HASH) == SDK["queries"][0]["key"]
    assert data_key(7, "/robot1/cmd_vel", "geometry_msgs/msg/Twist", "RIHS01_x") == (
        "7/robot1/cmd_vel/geometry_msgs::msg::dds_::Twist_/RIHS01_x"
    )
    with pytest.raises(ValueError, match="not a ROS type"):
        ros_type_name("String")


def test_our_tokens_are_the_sdks_for_the_same_entities():
    zid = sdk_token("MP").split("/")[2]
    assert node_token(0, zid, 0, "/sdk_talker") == sdk_token("NN", "sdk_talker")
    talker = endpoint_token(
        0, zid, 0, 0, "MP", "/sdk_talker", "/topic", "std_msgs/msg/String", STRING_HASH, QoSSnapshot()
    )
    assert talker == sdk_token("MP")
    caller_zid = sdk_token("SC").split("/")[2]
    caller = endpoint_token(
        0,
        caller_zid,
        0,
        0,
        "SC",
        "/sdk_caller",
        "/add_two_ints",
        "example_interfaces/srv/AddTwoInts",
        ADD_HASH,
        QoSSnapshot(),
    )
    assert caller == sdk_token("SC")


def test_tokens_name_namespaces_enclaves_and_node_ids_as_rmw_zenoh_does():
    token = endpoint_token(
        3,
        "ab12",
        5,
        9,
        "MS",
        "/robot1/nav/planner",
        "/robot1/odom",
        "nav_msgs/msg/Odometry",
        "RIHS01_h",
        QoSSnapshot(depth=5),
    )
    assert (
        token == "@ros2_lv/3/ab12/5/9/MS/%/%robot1%nav/planner/%robot1%odom/"
        "nav_msgs::msg::dds_::Odometry_/RIHS01_h/::,5:,:,:,,"
    )
    assert node_token(3, "ab12", 5, "/planner") == "@ros2_lv/3/ab12/5/5/NN/%/%/planner"


def test_parsing_reads_back_every_sdk_token():
    talker = parse_token(sdk_token("MP"))
    assert (talker.kind, talker.node, talker.name, talker.type, talker.type_hash) == (
        "MP",
        "/sdk_talker",
        "/topic",
        "std_msgs/msg/String",
        STRING_HASH,
    )
    assert talker.qos == QoSSnapshot(depth=10)
    node = parse_token(sdk_token("NN", "sdk_caller"))
    assert (node.kind, node.node, node.name) == ("NN", "/sdk_caller", "")
    deep = parse_token(
        "@ros2_lv/0/z/1/2/SS/%/%ns%deeper/srv_node/%ns%add/example_interfaces::srv::dds_::AddTwoInts_/h/::,:,:,:,,"
    )
    assert (deep.node, deep.name, deep.qos.depth) == ("/ns/deeper/srv_node", "/ns/add", 42)


@pytest.mark.parametrize(
    "key, why",
    [
        ("@ros2_lv/0/z/1/1/NN/%/%", "not an rmw_zenoh liveliness token"),
        ("@ros2_lv/0/z/1/1/XX/%/%/n", "unknown kind 'XX'"),
        ("@ros2_lv/x/z/1/1/NN/%/%/n", "domain that is not a number"),
        ("@ros2_lv/0/z/1/1/MP/%/%/n/%t", "13"),
        ("@ros2_lv/0/z/1/1/MP/%/%/n/%t/std_msgs::msg::dds_::String_/h/bogus", "QoS string"),
        ("@ros2_lv/0/z/1/1/MP/%/%/n/%t/String/h/::,:,:,:,,", "not a ROS type"),
    ],
)
def test_a_malformed_token_is_refused_with_the_reason(key, why):
    with pytest.raises(ValueError, match=why):
        parse_token(key)


@pytest.mark.parametrize(
    "qos, text",
    [
        (QoSSnapshot(depth=10), "::,10:,:,:,,"),
        (QoSSnapshot(depth=42), "::,:,:,:,,"),
        (QoSSnapshot(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL), ":1:,1:,:,:,,"),
        (QoSSnapshot(depth=5, reliability=ReliabilityPolicy.BEST_EFFORT), "2::,5:,:,:,,"),
        (QoSSnapshot(history=HistoryPolicy.KEEP_ALL), "::2,:,:,:,,"),
        (
            QoSSnapshot(
                depth=10,
                deadline_ns=1_500_000_000,
                liveliness=LivelinessPolicy.MANUAL_BY_TOPIC,
                liveliness_lease_duration_ns=2_000_000_000,
            ),
            "::,10:1,500000000:,:3,2,0",
        ),
    ],
)
def test_qos_strings_leave_rmw_zenohs_defaults_empty_and_read_back(qos, text):
    assert qos_string(qos) == text
    back = parse_qos(text)
    assert (back.reliability, back.durability, back.history, back.deadline_ns) == (
        qos.reliability,
        qos.durability,
        qos.history,
        qos.deadline_ns,
    )
    if qos.history == HistoryPolicy.KEEP_LAST:
        assert back.depth == qos.depth


def test_attachments_are_the_sdks_byte_for_byte():
    for recorded in (*SDK["samples"], *SDK["queries"]):
        raw = bytes.fromhex(recorded["attachment"])
        sequence, stamp, gid = attachment.unpack(raw)
        assert attachment.pack(sequence, stamp, gid) == raw
    assert [attachment.unpack(bytes.fromhex(s["attachment"]))[0] for s in SDK["samples"]] == [0, 1]
    assert attachment.unpack(bytes.fromhex(SDK["queries"][0]["attachment"]))[0] == 1  # a client counts from 1


def test_the_attachment_layout_is_zenohs_own_serialization():
    zenoh_ext = pytest.importorskip("zenoh.ext")
    gid = bytes(range(16))
    ours = attachment.pack(7, -3, gid)
    theirs = zenoh_ext.z_serialize((zenoh_ext.Int64(7), zenoh_ext.Int64(-3), gid)).to_bytes()
    assert ours == theirs
    assert len(ours) == attachment.SIZE == 33


@pytest.mark.parametrize(
    "data, why",
    [(b"", "0 bytes"), (bytes(32), "32 bytes"), (bytes(16) + b"\x0f" + bytes(16), "GID of 15 bytes")],
)
def test_a_malformed_attachment_is_refused_with_the_reason(data, why):
    with pytest.raises(ValueError, match=why):
        attachment.unpack(data)


def test_gids_are_the_xxh3_128_of_the_token_low_half_first():
    xxhash = pytest.importorskip("xxhash")
    token = sdk_token("MP")
    canonical = xxhash.xxh3_128_digest(token.encode())  # big-endian: high 64 bits first
    assert attachment.gid_of(token) == canonical[8:][::-1] + canonical[:8][::-1]
    assert attachment.gid_of(token) != attachment.gid_of(sdk_token("NN", "sdk_talker"))


def test_payloads_are_cdr_both_ways():
    first = SDK["samples"][0]
    assert codec.decode_cdr(bytes.fromhex(first["payload"]), String) == String(data="SDK says 0")
    assert codec.encode_cdr(String(data="SDK says 0")).hex() == first["payload"]
    query = SDK["queries"][0]
    assert codec.decode_cdr(bytes.fromhex(query["payload"]), AddTwoInts.Request) == AddTwoInts.Request(a=20, b=22)
    assert codec.encode_cdr(AddTwoInts.Request(a=20, b=22)).hex() == query["payload"]


def test_an_endpoint_of_another_process_carries_the_gid_of_its_token():
    xxhash = pytest.importorskip("xxhash")
    from actors.transport.zenoh.discovery import Discovery

    key = (
        "@ros2_lv/0/1f2e3d4c5b6a79880123456789abcdef/3/7/MP/%/%/chatter_node/%chatter/std_msgs::msg::dds_::String_/"
        "RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18/::,10:,:,:,,"
    )
    found = Discovery("0" * 32, lambda token, appeared: None, lambda kind, why: None)
    found.put(key)
    [node] = found.remote_nodes()
    [publisher] = node.endpoints
    digest = xxhash.xxh3_128(key.encode()).digest()  # big-endian; rmw_zenoh lays it out low half first
    assert publisher.kind == "publisher" and publisher.gid == digest[8:][::-1] + digest[:8][::-1]
