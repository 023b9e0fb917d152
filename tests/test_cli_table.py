"""docs/ros2cli.md stays true: each ros2 verb and flag it lists is ours exactly as its status says.

"yes" and "partly" rows name a verb (and flag) our parser has, "no" rows one it has not; every
"yes" names the test that compares our output with ros2cli's, and that test exists.
"""

from __future__ import annotations

import argparse
import re

import pytest
from conftest import ROOT

from actors.cli import build_parser

TABLE = ROOT / "docs" / "ros2cli.md"
ROW = re.compile(
    r"^\| `(?P<command>[^`]+)` \| (?:`(?P<flag>[^`]+)`|\(the verb\)) \| "
    r"(?P<status>[a-z/]+) \| (?:`(?P<test>[^`]+)`)? \|"
)
STATUSES = {"yes", "partly", "no", "n/a"}


def rows() -> list[dict[str, str | None]]:
    found = [m.groupdict() for line in TABLE.read_text(encoding="utf-8").splitlines() if (m := ROW.match(line))]
    assert len(found) > 200  # every verb and flag of twelve commands
    return found


def _subcommands(parser: argparse.ArgumentParser) -> dict[str, argparse.ArgumentParser]:
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            return dict(action.choices)
    return {}


def ours(command: str) -> argparse.ArgumentParser | None:
    """Our parser for ``command`` ("topic echo", "doctor"), or None when we have no such command."""
    parser: argparse.ArgumentParser | None = build_parser()
    for word in command.split():
        parser = _subcommands(parser).get(word) if parser is not None else None
    return parser


def options(parser: argparse.ArgumentParser) -> set[str]:
    return {option for action in parser._actions for option in action.option_strings}


@pytest.mark.parametrize("row", rows(), ids=lambda row: f"{row['command']} {row['flag'] or ''}".strip())
def test_the_table_says_what_the_command_line_has(row):
    assert row["status"] in STATUSES
    if row["status"] == "n/a":
        return
    parser = ours(row["command"])
    names = set(row["flag"].split("/")) if row["flag"] else set()
    have = names & options(parser) if parser is not None else set()
    if row["status"] == "no":
        assert parser is None or (names and not have), "the table says no, the command line has it"
        return
    assert parser is not None, f"no command {row['command']}"
    if row["status"] == "yes":
        assert have == names, f"missing {names - have}"
        file, _, test = (row["test"] or "").partition("::")
        assert test, "a yes names the test that compares the output with ros2cli's"
        source = (ROOT / "tests" / file).read_text(encoding="utf-8")
        assert re.search(rf"^(async )?def {test}\(", source, re.M), f"{row['test']} does not exist"
    else:
        assert not names or have, f"none of {names}"
