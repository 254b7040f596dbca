"""``benchmarks/campaign.py``: the table counts outcomes and passes by component."""
from campaign import GROUPS, table


def _record(seed, adhesion, outcome, failures, seconds):
    scene = {"profile": {"kind": "sinusoid", "amplitude": 0.1}, "rheology": {"kind": "elastic"},
             "kernel": {"kind": "half-plane"}, "adhesion": {"kind": adhesion},
             "load": {"mean_pressure": 0.3}, "sliding": {"zeta": 1.0},
             "solver": {"kind": "newton"}}
    return {"seed": seed, "scene": scene, "method": "bem", "outcome": outcome,
            "failures": failures, "seconds": seconds,
            "power_tolerance": "fallback" if outcome == "converged" else ""}


def test_table_counts_by_component():
    records = [_record(0, "none", "converged", [], 1.0),
               _record(1, "none", "path", ["not converged (path): budget"], 3.0),
               _record(2, "energy-balance", "scene", [], 2.0),
               _record(3, "energy-balance", "time-limit", ["time limit 45 s"], 45.0)]
    text = table(records)
    assert text.startswith("4 scenes, 2 pass;")
    assert "the fallback 1" in text
    rows = {tuple(c.strip() for c in line.strip("|").split("|")[:2]): line
            for line in text.splitlines() if line.startswith("| adhesion")}
    none = [c.strip() for c in rows[("adhesion", "none")].strip("|").split("|")]
    assert none[2:5] == ["2", "1", "1"]                 # scenes, pass, converged
    assert none[-2:] == ["2.00", "3.0"]                 # median and largest seconds
    eb = [c.strip() for c in rows[("adhesion", "energy-balance")].strip("|").split("|")]
    assert eb[2:4] == ["2", "1"] and eb[6] == "1" and eb[9] == "1"   # scene, time limit
    assert sum(line.startswith("| group") for line in text.splitlines()) == len(GROUPS)
