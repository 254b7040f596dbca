"""``benchmarks/results_table.py``: the recorded results load with their schema, select and print."""
import json

import pytest

import results_table as tab


def _write(tmp_path, rows):
    path = tmp_path / "r.json"
    path.write_text(json.dumps(rows))
    return path


ROWS = [
    {"date": "2026-11-26", "commit": "034fe99", "benchmark": "rough point", "quantity": "median",
     "value": 2.6, "unit": "s"},
    {"date": "2026-11-29", "commit": "a48d27a", "benchmark": "rough point", "quantity": "median",
     "value": "2.16", "unit": "s"},
    {"date": "", "commit": "", "benchmark": "crowded corner", "quantity": "evaluations",
     "value": 539, "unit": "evaluations"},
]


def test_load_select_and_format(tmp_path):
    rows = tab.load([_write(tmp_path, ROWS)])
    assert [r["value"] for r in rows] == [2.6, 2.16, 539.0]
    assert [r["commit"] for r in tab.select(rows, benchmark="ROUGH", since="2026-11-27")] \
        == ["a48d27a"]
    assert len(tab.select(rows, unit="evaluations")) == 1
    assert tab.select(rows, until="2026-12-01") == rows[:2]      # undated rows need no date filter
    text = tab.format_table(rows[:2], tab.COLUMNS, markdown=True)
    assert text.splitlines()[0] == "| date | commit | benchmark | quantity | value | unit |"
    assert "| 2026-11-29 | a48d27a | rough point | median | 2.16 | s |" in text
    (line,) = [s for s in tab.summary(rows) if s["benchmark"] == "rough point"]
    assert line["rows"] == 2 and line["dates"] == "2026-11-26 … 2026-11-29"


@pytest.mark.parametrize("change, message", [
    ({"value": "fast"}, "value = 'fast' is not a number"),
    ({"date": "27 Nov"}, "is not an ISO day"),
    ({"unit": None, "commit": None}, None),
])
def test_schema_errors_name_file_row_and_column(tmp_path, change, message):
    path = _write(tmp_path, [{**ROWS[0], **change}])
    if message is None:
        assert tab.load([path])[0]["unit"] == ""
        return
    with pytest.raises(tab.ResultsError, match=f"r.json row 1: .*{message}"):
        tab.load([path])
    assert tab.main([str(path)]) == 2


def test_the_shipped_results_follow_the_schema(capsys):
    rows = tab.load()
    assert len(rows) > 1000
    assert {r["unit"] for r in rows} >= {"s", "evaluations"}
    assert tab.main(["--benchmark", "performance: 9.", "--unit", "s", "--format", "csv"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0] == "date,commit,benchmark,quantity,value,unit" and len(out) > 5
