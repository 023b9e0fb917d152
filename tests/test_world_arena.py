"""World files: the shipped worlds, the errors a malformed file gives, and the static geometry."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from actors.errors import WorldFileError
from world.arena import WORLDS_DIR, Box, World, load_world, posts, solids

MINIMAL = "bounds = { min = [-1, -1], max = [1, 1] }\n"
BOX = "[[boxes]]\ncenter = [0, 0]\nsize = [1, 1]\n"


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "x.toml"
    path.write_text(text)
    return path


@pytest.mark.parametrize("name", ["empty", "signs"])
def test_shipped_worlds_load_by_name_and_by_path(name: str) -> None:
    world = load_world(name)
    assert world == load_world(WORLDS_DIR / f"{name}.toml")
    assert len(world.walls) == 4


def test_signs_world_has_the_course_layout() -> None:
    world = load_world("signs")
    assert [sign.position for sign in world.stop_signs] == [(0.15, -2.0)]
    assert [(box.center, box.size, box.angle) for box in world.boxes] == [
        ((1.61, 0.0), (0.5, 0.4), 0.0),
        ((-1.0, -0.5), (0.5, 0.4), 1.2),
    ]


def test_empty_world_is_a_10_m_square_around_the_origin() -> None:
    walls = [s for s in solids(load_world("empty")) if s.kind == "wall"]
    xs = [x for s in walls for x, _ in s.vertices]
    # Inner faces at +-5 m, outer at +-5.1 m (centre lines at +-5.05, 0.1 m thick).
    assert min(xs) == pytest.approx(-5.1) and max(xs) == pytest.approx(5.1)
    south = walls[0].vertices
    assert max(y for _, y in south) == pytest.approx(-5.0)


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (MINIMAL + "colour = 1\n", "colour: unknown key"),
        (MINIMAL + "[[boxs]]\n", "boxs: unknown key (did you mean 'boxes'?)"),
        (MINIMAL + BOX + BOX + "colour = 'red'\n", "boxes[1].colour: unknown key"),
        (
            MINIMAL + BOX + BOX.replace("[1, 1]", "[1, 2, 3]"),
            "boxes[1].size: expected an array of 2 items, got 3",
        ),
        (
            MINIMAL + "[[boxes]]\ncenter = [0, 0]\nsize = 'big'\n",
            "boxes[0].size: expected an array, got the string 'big'",
        ),
        (MINIMAL + "[[boxes]]\nsize = [1, 1]\n", "boxes[0].center: missing required key"),
        (
            MINIMAL + "[[walls]]\nstart = [0, 0]\nend = [1, 0]\nthickness = -0.1\n",
            "walls[0].thickness: expected a number > 0.0",
        ),
        (
            MINIMAL + "[[walls]]\nstart = [nan, 0]\nend = [1, 0]\n",
            "walls[0].start[0]: expected a number >= -10000.0",
        ),
        (
            MINIMAL + "[[walls]]\nstart = [1, 0]\nend = [1, 0]\n",
            "walls[0]: start and end are the same point",
        ),
        (
            MINIMAL + "[[stop_signs]]\nposition = [0, 'north']\n",
            "stop_signs[0].position[1]: expected a number, got the string 'north'",
        ),
        (
            MINIMAL + "[[polygons]]\nvertices = [[0, 0], [1, 1], [1, 0], [0, 1]]\n",
            "polygons[0]: vertices: edges cross each other",
        ),
        (
            MINIMAL + "[[polygons]]\nvertices = [[0, 0], [1, 1]]\n",
            "polygons[0].vertices: expected at least 3 items, got 2",
        ),
        (
            "bounds = { min = [1, -1], max = [1, 1] }\n",
            "bounds: min must be below max on both axes",
        ),
        ("walls = []\n", "bounds: missing required key"),
        ("bounds = { min = [-1, -1], max = [1, 1]\n", "TOML syntax error: "),
    ],
)
def test_malformed_world_names_file_and_key_path(tmp_path: Path, text: str, expected: str) -> None:
    path = write(tmp_path, text)
    with pytest.raises(WorldFileError) as caught:
        load_world(path)
    message = str(caught.value)
    assert message.startswith(f"{path}: {expected}")
    assert "\n" not in message and "$" not in message and "`" not in message


def test_missing_world_file(tmp_path: Path) -> None:
    with pytest.raises(WorldFileError, match=r"nowhere\.toml: cannot read: No such file"):
        load_world(tmp_path / "nowhere.toml")


def test_an_unknown_world_name_lists_the_shipped_ones() -> None:
    with pytest.raises(WorldFileError) as caught:
        load_world("sign")
    assert str(caught.value) == (
        "unknown world 'sign' (did you mean 'signs'?); the shipped worlds are empty, signs "
        "(or give the path of a world file)"
    )


def test_defaults_and_frozen(tmp_path: Path) -> None:
    world = load_world(write(tmp_path, MINIMAL + "[[walls]]\nstart = [0, 0]\nend = [1, 0]\n"))
    assert world.walls[0].thickness == 0.05 and world.boxes == [] and world.description == ""
    with pytest.raises(AttributeError):
        world.description = "changed"  # type: ignore[misc]


def area(vertices: tuple[tuple[float, float], ...]) -> float:
    n = len(vertices)
    return 0.5 * sum(
        vertices[i][0] * vertices[(i + 1) % n][1] - vertices[(i + 1) % n][0] * vertices[i][1] for i in range(n)
    )


def test_solids_wind_counter_clockwise_and_keep_kind_and_name(tmp_path: Path) -> None:
    clockwise = "[[polygons]]\nname = 'ell'\nvertices = [[0, 0], [0, 2], [1, 2], [1, 1], [2, 1], [2, 0]]\n"
    world = load_world(write(tmp_path, MINIMAL + clockwise))
    (ell,) = solids(world)
    assert ell.kind == "obstacle" and ell.name == "ell"
    assert area(ell.vertices) == pytest.approx(3.0)
    assert all(area(s.vertices) > 0 for s in solids(load_world("signs")))


def test_box_outline_is_turned_about_its_centre() -> None:
    world = World(
        bounds=load_world("empty").bounds,
        boxes=[Box(center=(1.0, 2.0), size=(2.0, 1.0), angle=math.pi / 2)],
    )
    (box,) = solids(world)
    xs, ys = zip(*box.vertices)
    assert (min(xs), max(xs), min(ys), max(ys)) == pytest.approx((0.5, 1.5, 1.0, 3.0))


def test_wall_outline_has_square_caps() -> None:
    (wall,) = solids(World(bounds=load_world("empty").bounds, walls=[load_world("empty").walls[0]]))
    xs = [x for x, _ in wall.vertices]
    assert (min(xs), max(xs)) == pytest.approx((-5.1, 5.1))  # 5.05 plus half the thickness


def test_posts_are_the_stop_signs() -> None:
    (post,) = posts(load_world("signs"))
    assert post.center == (0.15, -2.0) and post.radius == 0.05 and post.name == "stop_sign"
