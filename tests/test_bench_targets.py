"""The benchmark's target table reads each target the right way round."""

from __future__ import annotations

from bench.harness import Result
from bench.targets import check

SEQ, CONC = "c. service sequential", "c. service 100 callers"


def _calls(actors: float, timeout: float, future: float) -> list[Result]:
    # µs per call: lower is better.
    return [
        Result(scenario, case, "µs/call", [value], higher_better=False)
        for scenario in (SEQ, CONC)
        for case, value in (("actors", actors), ("actors, timeout=5", timeout), ("future+Queue", future))
    ]


def _row(table: str, goal: str) -> str:
    return next(line for line in table.splitlines() if goal in line)


def test_a_round_trip_is_shown_as_its_cost_against_the_bare_future() -> None:
    table = check(_calls(actors=9.0, timeout=12.0, future=10.0), "c")
    assert _row(table, "with a timeout ≤ 1.3×") == (
        "| c | round trip with a timeout ≤ 1.3× the bare future's (sequential, 100 callers) | 1.20×, 1.20× | met |"
    )
    assert _row(table, "without a timeout ≤ 1.0×").endswith("| 0.90×, 0.90× | met |")


def test_a_round_trip_dearer_than_its_limit_is_not_met() -> None:
    table = check(_calls(actors=10.5, timeout=13.5, future=10.0), "c")
    assert _row(table, "with a timeout ≤ 1.3×").endswith("| 1.35×, 1.35× | **not met** |")
    assert _row(table, "without a timeout ≤ 1.0×").endswith("| 1.05×, 1.05× | **not met** |")
    assert _row(table, "round trip ≤ 2×").endswith("| 1.05×, 1.05× | met |")


def test_a_target_whose_rows_are_missing_is_not_measured() -> None:
    assert _row(check([], "g"), "real-time factor").endswith("| not measured | — |")


def test_the_table_of_a_full_run_has_every_scenarios_targets() -> None:
    scenarios = {line.split(" | ")[0].lstrip("| ") for line in check([]).splitlines()[2:]}
    assert scenarios == set("abcdefghijklmn")


def test_recording_and_cross_process_targets_read_their_rows() -> None:
    zenoh, recording = "k. zenoh (2 processes)", "l. recording: one-way"
    results = [
        Result(zenoh, "latency p50: actors (Zenoh)", "µs", [300.0], higher_better=False),
        Result(zenoh, "latency p50: rclpy (Fast DDS)", "µs", [200.0], higher_better=False),
        Result(zenoh, "latency p50: bare zenoh (floor)", "µs", [150.0], higher_better=False),
        Result(zenoh, "round trip: actors (Zenoh)", "µs/call", [250.0], higher_better=False),
        Result(zenoh, "round trip: bare zenoh (floor)", "µs/call", [200.0], higher_better=False),
        Result(zenoh, "one-way: actors (Zenoh)", "deliveries/s", [90.0]),
        Result(zenoh, "one-way: bare zenoh (floor)", "deliveries/s", [100.0]),
        Result(recording, "recording on", "deliveries/s", [60.0]),
        Result(recording, "recording off", "deliveries/s", [100.0]),
    ]
    table = check(results, "kl")
    assert _row(table, "latency p50 ≤ rclpy's").endswith("| 0.67× | **not met** |")
    assert _row(table, "≥ 0.8× the bare-zenoh floor").endswith("| 0.90×, 0.80×, 0.50× | **not met** |")
    assert _row(table, "recorder on ≥ 0.5× off").endswith("| 0.60× | met |")
    assert _row(table, "LaserScan writing").endswith("| not measured | — |")


def _cdr_rows(copying_decode: float, views_decode: float) -> list[Result]:
    """Scenario i's rows: each sample's encode and rclpy's decode at 1 µs against 2 µs, the decodes as given."""
    from bench.cdr import SCENARIO, VIEWS, samples

    rows = {"rclpy encode": 2.0, "rosbags encode": 2.0, "rclpy decode": 2.0, "rosbags decode": 2.0}
    rows |= {"actors encode": 1.0, "actors decode": copying_decode, f"actors {VIEWS}": views_decode}
    return [
        Result(f"{SCENARIO} {name}", case, "µs/msg", [value], higher_better=False)
        for name in samples()
        for case, value in rows.items()
    ]


def test_the_rosbags_decode_target_reads_the_views_row_and_rclpys_the_copying_one():
    # Copying decode slow (as an Image's against rosbags' views), views fast: rosbags met, rclpy not.
    table = check(_cdr_rows(copying_decode=8.0, views_decode=0.5), "i")
    assert _row(table, "≥ rosbags' serializer").endswith("| worst 2.00× (Image 640×480 rgb8 encode) | met |")
    assert _row(table, "≥ rclpy's serialize").endswith("| worst 0.25× (Image 640×480 rgb8 decode) | **not met** |")
    # The other way round: the copying row alone can never meet the rosbags target.
    table = check(_cdr_rows(copying_decode=0.5, views_decode=8.0), "i")
    assert _row(table, "≥ rosbags' serializer").endswith(
        "| worst 0.25× (Image 640×480 rgb8 decode, zero-copy views) | **not met** |"
    )
    assert _row(table, "≥ rclpy's serialize").endswith("| worst 2.00× (Image 640×480 rgb8 encode) | met |")
