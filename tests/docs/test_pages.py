"""The documentation site's structure: pages by kind, an executed tutorial, a curated API page,
pages a reader can load (under 40 kB) and without development diaries."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

DOCS = Path(__file__).resolve().parents[2] / "docs"

#: The page kinds of the index (tutorials, how-to guides, reference, explanation).
KINDS = ("Tutorials", "How-to guides", "Reference", "Explanation")


def _pages() -> list[Path]:
    return sorted(p for p in DOCS.rglob("*.md") if "_build" not in p.parts and "api" not in p.parts)


def _toctrees() -> dict[str, list[str]]:
    """caption -> entries of every toctree of the index."""
    text = (DOCS / "index.md").read_text()
    trees = {}
    for block in re.findall(r"```\{toctree\}\n(.*?)```", text, flags=re.S):
        caption = re.search(r":caption: (.+)", block).group(1).strip()
        trees[caption] = [line.strip() for line in block.splitlines()
                          if line.strip() and not line.strip().startswith(":")]
    return trees


def test_the_index_sorts_pages_by_what_the_reader_wants():
    trees = _toctrees()
    assert all(kind in trees for kind in KINDS), sorted(trees)
    assert trees["Tutorials"][:2] == ["install", "getting-started"]
    assert {"api", "scene", "results", "changelog"} <= set(trees["Reference"])
    assert {"howto/choose-a-method", "howto/dask", "howto/plugin", "howto/si-units"} \
        <= set(trees["How-to guides"])


def test_every_page_is_in_a_toctree():
    listed = {entry for entries in _toctrees().values() for entry in entries}
    pages = {p.relative_to(DOCS).with_suffix("").as_posix() for p in _pages()}
    pages -= {"index", "README"}
    assert pages <= listed, sorted(pages - listed)
    assert (DOCS / "api.rst").is_file() and "api" in listed


@pytest.mark.parametrize("page", _pages(), ids=lambda p: p.relative_to(DOCS).as_posix())
def test_pages_stay_under_40_kB(page):
    assert page.stat().st_size < 40_000, f"{page.name}: {page.stat().st_size} bytes"


#: Development text that does not belong in the user's documentation.
DIARY = [r"branch `md`", r"being written", r"\bcommit [0-9a-f]{7,40}\b",
         r"\bat [0-9a-f]{7}\b", r"\b20\d\d-\d\d-\d\d\b"]


@pytest.mark.parametrize("page", _pages(), ids=lambda p: p.relative_to(DOCS).as_posix())
def test_pages_carry_no_development_diary(page):
    text = page.read_text()
    found = [m.group(0) for pattern in DIARY for m in re.finditer(pattern, text, flags=re.M)]
    assert not found, f"{page.name}: {found[:5]}"


def test_the_tutorial_is_an_executed_notebook():
    """The newcomer's page runs at every docs build (MyST-NB), and a failing cell fails it."""
    head = (DOCS / "getting-started.md").read_text().split("---")[1]
    assert "file_format: mystnb" in head
    conf = (DOCS / "conf.py").read_text()
    assert '"myst_nb"' in conf
    assert 'nb_execution_mode = "force"' in conf
    assert "nb_execution_raise_on_error = True" in conf


def test_the_tutorial_walks_the_newcomers_path():
    """Install, first solve, sweep, Dataset, figure, Maugis–Dugdale: one page, in that order,
    closed by its own timing."""
    text = (DOCS / "getting-started.md").read_text()
    steps = ["pip install", "vc.solve(\"examples/scenes/sinusoid.toml\")", "vc.ContactProblem(",
             "vc.Sweep(",
             "vc.run_study(", ".to_xarray()", "vc.plot_study(", "examples/scenes/maugis_dugdale.toml"]
    positions = [text.find(step) for step in steps]
    assert -1 not in positions, [s for s, p in zip(steps, positions) if p == -1]
    assert positions == sorted(positions)
    closing = text.split("## How long this page takes")[1]
    assert "perf_counter" in closing and "_started" in closing     # the page times its cells


def test_the_api_page_lists_every_public_name():
    import viscocontact as vc

    text = (DOCS / "api.rst").read_text()
    listed = set(re.findall(r"^   (\w+)$", text, flags=re.M))
    public = set(vc.__all__) - {"__version__"}
    assert public - listed == set()
    # Run-time names besides the plugin authors' section (which gives dotted paths) are exports.
    assert listed - public == set()


def test_the_result_columns_page_names_every_column():
    """Every column of a study file's records (``studies.point.COLUMNS``, read from the source so
    that the docs tests import nothing heavy) is named on the result-columns page."""
    import ast

    source = (DOCS.parent / "viscocontact" / "studies" / "point.py").read_text()
    (node,) = [n for n in ast.parse(source).body if isinstance(n, ast.AnnAssign)
               and getattr(n.target, "id", "") == "COLUMNS"]
    COLUMNS = ast.literal_eval(node.value)
    assert "area" in COLUMNS and "started_from" in COLUMNS
    text = (DOCS / "results.md").read_text()
    missing = [c for c in COLUMNS if f"`{c}`" not in text]
    assert not missing


def test_the_changelog_has_one_short_entry_per_change():
    """History goes in the changelog one entry per user-visible change; measurements go into
    ``benchmarks/results/`` and commit messages, not into the entries."""
    text = (DOCS.parent / "CHANGELOG.md").read_text()
    entries = [" ".join(e.split()) for e in
               re.findall(r"^- .*?(?=\n- |\n#|\Z)", text, flags=re.S | re.M)]
    assert len(entries) > 10
    long = [e[:80] for e in entries if len(e) > 300]
    assert not long, long


#: Ã is the contact length times q0 (2π in full contact), not a fraction of the period.
AREA_AS_FRACTION = (r"fraction\s+Ã(?!\s*/\s*2π)"
                    r"|Ã\s*(?:=|is|,)?\s*(?:the\s+)?(?:contact\s+)?area\s+fraction")


@pytest.mark.parametrize("page", [*_pages(), DOCS.parent / "README.md"],
                         ids=lambda p: p.relative_to(DOCS.parent).as_posix())
def test_no_page_calls_the_contact_length_a_fraction(page):
    found = re.findall(AREA_AS_FRACTION, page.read_text())
    assert not found, f"{page.name}: {found}"


def test_the_si_how_to_reads_results_back_in_si():
    text = (DOCS / "howto" / "si-units.md").read_text()
    assert ".physical(scene)" in text and "--si" in text


def test_the_tutorials_shown_cells_run_on_their_own():
    """A reader pastes the cells that are shown: none may use a name that only a hidden set-up
    cell (``remove-cell``) defines (the page's closing timing cell excepted)."""
    import ast
    import builtins

    text = (DOCS / "getting-started.md").read_text().split("## How long this page takes")[0]
    bound = set(dir(builtins))
    for cell in re.findall(r"```\{code-cell\} ipython3\n(.*?)```", text, flags=re.S):
        if "remove-cell" in cell.split("\n\n")[0]:
            continue
        tree = ast.parse(cell)
        here = {n.id for n in ast.walk(tree) if isinstance(n, ast.Name)
                and isinstance(n.ctx, ast.Store)}
        here |= {(a.asname or a.name).split(".")[0] for n in ast.walk(tree)
                 if isinstance(n, (ast.Import, ast.ImportFrom)) for a in n.names}
        used = {n.id for n in ast.walk(tree) if isinstance(n, ast.Name)
                and isinstance(n.ctx, ast.Load)}
        missing = used - bound - here
        assert not missing, f"{sorted(missing)} in: {cell[:60]!r}"
        bound |= here
