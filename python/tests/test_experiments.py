"""Experiments from Python: run, read back, tables for pandas."""

from __future__ import annotations

from pathlib import Path

import mit_star

EXPERIMENT = """
name = "python-test"
runs = 2
planners = ["mit-star", "eit-star"]
[[problems]]
name = "dividing-walls"
dimensions = [2]
time = 0.05
"""


def test_run_an_experiment_file_and_read_it_back(tmp_path: Path) -> None:
    file = tmp_path / "experiment.toml"
    file.write_text(EXPERIMENT)
    output = tmp_path / "results"
    results = mit_star.run_experiment(str(file), output=output, threads=2, batch_size=50)
    assert results.run_count == 4 and not results.interrupted
    assert results.planners == ["MIT*", "EIT*"]
    records = results.records()
    assert len(records) == 4
    row = records[0]
    for key in ("instance", "planner", "seed", "status", "final_cost", "iterations", "valid"):
        assert key in row, key
    assert all(r["valid"] for r in records if r["final_cost"] is not None)
    assert "path" not in row and "path" in results.records(paths=True)[0]
    # The independent check's time, apart from the planner's.
    assert all(r["validation_seconds"] > 0 for r in records if r["final_cost"] is not None)
    table = results.table()
    assert len(table["planner"]) == 4 and set(table["planner"]) == {"MIT*", "EIT*"}
    assert "| dividing-walls" in results.kpi_markdown()
    again = mit_star.read_results(output)
    assert again.run_count == 4
    assert sorted(r["final_cost"] or 0 for r in again.records()) == sorted(
        r["final_cost"] or 0 for r in records
    )


def test_a_shipped_experiment_with_fewer_runs() -> None:
    results = mit_star.run_experiment("smoke", runs=1, threads=2)
    assert results.run_count >= len(results.planners)


def test_unknown_experiments_are_value_errors() -> None:
    import pytest

    with pytest.raises(ValueError, match="no-such"):
        mit_star.run_experiment("no-such-experiment")
