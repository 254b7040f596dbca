"""`python -m viscocontact.reports.validation --quick`: sections, figures, closed-form errors."""
from __future__ import annotations

import pytest

from viscocontact.reports import validation


def _table(text: str, marker: str) -> list[list[str]]:
    """The rows (cells) of the markdown table that follows ``<!-- table: marker -->``."""
    lines = text.split(f"<!-- table: {marker} -->", 1)[1].strip().splitlines()
    rows = []
    for line in lines[2:]:                              # skip header and rule
        if not line.startswith("|"):
            break
        rows.append([c.strip() for c in line.strip().strip("|").split("|")])
    return rows


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    out = tmp_path_factory.mktemp("validation")
    assert validation.main(["--quick", "--out", str(out)]) == 0
    return out


@pytest.mark.slow
def test_quick_report_has_every_section_and_figure(report):
    text = (report / "validation.md").read_text(encoding="utf-8")
    for heading in validation.SECTIONS:
        assert heading in text
    for marker in ("closed-form-errors", "johnson-dx0", "mesh-convergence", "rough-area",
                   "wavy-friction-peaks", "rough-friction", "elastic-limits", "models"):
        assert _table(text, marker), marker
    for name in ("closed_forms", "rough_area", "friction", "limits"):
        png = report / "figures" / f"validation_{name}.png"
        assert png.stat().st_size > 1000
        assert f"figures/validation_{name}.png" in text
    assert "A_Persson/A_BEM" in text
    assert not list(report.glob(".*")) and not list((report / "figures").glob(".*"))  # no temps


@pytest.mark.slow
def test_quoted_closed_form_errors_are_small(report):
    text = (report / "validation.md").read_text(encoding="utf-8")
    rows = _table(text, "closed-form-errors")
    assert any(r[0].startswith("Westergaard") for r in rows)
    assert any(r[0].startswith("Johnson") for r in rows)
    errors = [float(c) for r in rows for c in r[3:] if c != "—"]
    assert len(errors) >= len(rows)                     # a failed solve would show "—"
    assert max(abs(e) for e in errors) < 1e-3, rows
    for row in _table(text, "mesh-convergence"):      # second order (Westergaard, Johnson δX = 0)
        assert float(row[-1]) > 1.8, row


def test_number_format():
    assert validation.fmt(2.4e-4, 2, True) == "+2.4e-4"
    assert validation.fmt(1e-8) == "1e-8"
    assert validation.fmt(1280.27, 4) == "1280"
    assert validation.fmt(0.3) == "0.3"
    assert validation.fmt(float("nan")) == "—"


def test_observed_order_of_a_second_order_sequence():
    order, pairs = validation.observed_order([16, 32, 64], [1e-2, 2.5e-3, 6.25e-4])
    assert order == pytest.approx(2.0) and pairs == pytest.approx([2.0, 2.0])


def test_time_limit_stops_a_solve_at_its_next_check():
    import time

    from viscocontact.deadline import check
    from viscocontact.errors import TimeLimitExceeded

    with pytest.raises(TimeLimitExceeded):
        with validation.time_limit(0.05):
            time.sleep(0.1)
            check()         # where every solver checks: at each residual evaluation
    with validation.time_limit(0):  # no limit
        check()


def test_cli_validate_refuses_zero_workers(capsys, tmp_path):
    from viscocontact.cli import main

    assert main(["validate", "--workers", "0", "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "--workers" in err and ">= 1" in err
    assert not list(tmp_path.iterdir())
