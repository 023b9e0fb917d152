"""What every benchmark shares: repetitions, medians with min–max, ratios, one printed table."""

from __future__ import annotations

import statistics
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

__all__ = ["Result", "repeat", "table"]


@dataclass
class Result:
    """One measured case: its samples in ``unit`` (higher is better when ``higher_better``)."""

    scenario: str
    case: str
    unit: str
    samples: list[float]
    higher_better: bool = True
    note: str = ""
    baselines: dict[str, str] = field(default_factory=dict)  # name of a baseline -> its case name

    @property
    def median(self) -> float:
        return statistics.median(self.samples)


def repeat(fn: Callable[[], float], times: int) -> list[float]:
    """Call ``fn`` ``times`` times (after one warm-up call) and return its results."""
    fn()
    return [fn() for _ in range(times)]


def _fmt(value: float) -> str:
    if value >= 100_000:
        return f"{value:,.0f}"
    if value >= 100:
        return f"{value:.0f}"
    return f"{value:.3g}"


def table(results: Sequence[Result]) -> str:
    """A Markdown table: median, min–max, and each case's ratio to its baselines."""
    by_case = {(r.scenario, r.case): r for r in results}
    lines = [
        "| scenario | case | median | min–max | unit | vs baselines |",
        "|---|---|---:|---:|---|---|",
    ]
    for r in results:
        ratios = []
        for label, case in r.baselines.items():
            base = by_case.get((r.scenario, case))
            if base is None:
                ratios.append(f"{label}: n/a")
                continue
            ratio = r.median / base.median if r.higher_better else base.median / r.median
            ratios.append(f"{ratio:.2f}× {label}")
        span = f"{_fmt(min(r.samples))}–{_fmt(max(r.samples))}"
        extra = "; ".join(ratios + ([r.note] if r.note else []))
        lines.append(f"| {r.scenario} | {r.case} | {_fmt(r.median)} | {span} | {r.unit} | {extra} |")
    return "\n".join(lines)
