"""Bad interface files: ``actors interface generate`` says what is wrong in one line, exits 2, writes nothing."""

from __future__ import annotations

import pytest

from actors.cli import main

# (file under the root, its bytes, what the one line says)
CASES = [
    ("pkg/msg/None.msg", b"int32 a\n", "None.msg: the type name 'None' is reserved in Python"),
    ("pkg/msg/True.msg", b"int32 a\n", "True.msg: the type name 'True' is reserved in Python"),
    ("pkg/msg/Annotated.msg", b"int32 a\n", "the type name 'Annotated' is reserved"),
    ("pkg/msg/lower.msg", b"int32 a\n", "lower.msg: a type name must be CamelCase"),
    ("pkg/msg/Big.msg", b"int32[99999999999999999999] a\n", "Big.msg:1: an array's size must be from 1 to 4294967295"),
    ("pkg/msg/Zero.msg", b"int32 a\nint32[0] b\n", "Zero.msg:2: an array's size must be from 1"),
    ("pkg/msg/Upper.msg", b"int32[<=0] a\n", "Upper.msg:1: an array's size must be from 1"),
    ("pkg/msg/Text.msg", b"string<=4294967296 a\n", "Text.msg:1: a string's bound must be from 1 to 4294967295"),
    ("pkg/msg/Latin.msg", b"int32 a\nstring b # caf\xe9\n", "Latin.msg:2: not UTF-8 text (byte 0xe9)"),
    ("pkg/msg/Twice.msg", b"int32 a\nint32 a\n", "Twice.msg:2: duplicate name 'a'"),
    ("pkg/msg/Keyword.msg", b"int32 for\n", "Keyword.msg:1: field name 'for' is reserved in Python"),
    ("pkg/msg/Caps.msg", b"int32 A\n", "Caps.msg:1: invalid field name 'A'"),
    ("pkg/msg/Unknown.msg", b"foo a\n", "Unknown.msg:1: unknown type 'foo'"),
    ("pkg/msg/Elsewhere.msg", b"other_pkg/Thing a\n", "Elsewhere.msg:1: unknown type 'other_pkg/msg/Thing'"),
    ("pkg/msg/Range.msg", b"int8 a 300\n", "Range.msg:1: 300 is out of range for int8"),
    ("pkg/msg/Value.msg", b"int32 a 1.5\n", "Value.msg:1: expected a int32 value, got '1.5'"),
    ("pkg/msg/Const.msg", b"int32 LIMIT=\n", "Const.msg:1: constant 'LIMIT' has no value"),
    ("pkg/srv/Half.srv", b"int32 a\n", "Half.srv:1: a service needs exactly one '---' line"),
    ("pkg/action/Short.action", b"int32 a\n---\nint32 b\n", "Short.action:3: an action needs exactly 2 '---' lines"),
    ("pkg/msg/Wrong.srv", b"int32 a\n---\n", "Wrong.srv: a .srv file belongs in srv/, not msg/"),
    ("pkg/srv/Wrong.msg", b"int32 a\n", "Wrong.msg: a .msg file belongs in msg/, not srv/"),
    ("Pkg/msg/Fine.msg", b"int32 a\n", "invalid package name 'Pkg'"),
]


@pytest.mark.parametrize(("where", "data", "said"), CASES, ids=[case[0] for case in CASES])
def test_a_bad_file_is_one_line_exit_2_and_nothing_written(tmp_path, capsys, where, data, said):
    root = tmp_path / "my_root"
    (root / "good" / "msg").mkdir(parents=True)
    (root / "good" / "msg" / "Fine.msg").write_text("int32 a\n")  # a good package beside: not written either
    path = root / where
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(data)
    assert main(["interface", "generate", str(root)]) == 2
    out, err = capsys.readouterr()
    assert out == ""
    assert err.count("\n") == 1 and said in err, err
    assert sorted(p.name for p in root.rglob("*.py")) == []


def test_a_folder_named_like_an_interface_file_is_one_line(tmp_path, capsys):
    root = tmp_path / "my_root"
    (root / "pkg" / "msg" / "Foo.msg").mkdir(parents=True)
    assert main(["interface", "generate", str(root)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Foo.msg: not a file" in err
    assert list(root.rglob("*.py")) == []
