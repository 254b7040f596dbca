"""Every module's summary (the first sentence of its docstring, which the API pages and
``help()`` show) is a whole sentence, not cut at an abbreviation such as "eq."."""
from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[2] / "viscocontact"

#: Abbreviations after which a period does not end a sentence; Sphinx's autosummary cuts a
#: summary at the first period followed by a space unless it ends one of its own few ("e.g.",
#: "i.e.", "Mr.", "Mrs.", "Dr."), which are therefore allowed here.
ABBREVIATIONS = ("eq", "eqs", "Eq", "Eqs", "fig", "Fig", "Figs", "ref", "Ref", "sec", "Sec",
                 "ch", "Ch", "cf", "vs", "no", "No", "al", "approx", "resp", "etc")


def _modules() -> list[Path]:
    return sorted(p for p in PACKAGE.rglob("*.py") if "__pycache__" not in p.parts)


def first_sentence(docstring: str) -> str:
    """The text up to the first period followed by white space, in the first paragraph."""
    paragraph = docstring.strip().split("\n\n")[0]
    return re.split(r"\.\s", " ".join(paragraph.split()) + " ")[0]


@pytest.mark.parametrize("path", _modules(), ids=lambda p: p.relative_to(PACKAGE).as_posix())
def test_module_summary_is_a_whole_sentence(path):
    docstring = ast.get_docstring(ast.parse(path.read_text()))
    if docstring is None:
        assert path.name.startswith("_") and path.name != "__init__.py", \
            f"{path.name}: public modules need a docstring"
        return
    sentence = first_sentence(docstring)
    last_word = re.split(r"[\s(]", sentence)[-1]
    assert last_word not in ABBREVIATIONS, f"summary cut at {last_word!r}: {sentence!r}"


@pytest.mark.parametrize("text, expected", [
    ("Periodic kernels (thesis eqs. 2.40-2.47).\n\nMore.", "Periodic kernels (thesis eqs"),
    ("One line.", "One line"),
    ("Wrapped\nover two lines. Second.", "Wrapped over two lines"),
])
def test_first_sentence(text, expected):
    assert first_sentence(text) == expected


def _api_page_objects():
    """The objects the public API page lists, as (name, object)."""
    import importlib

    import viscocontact as vc

    text = (PACKAGE.parent / "docs" / "api.rst").read_text()
    names = re.findall(r"^   ([\w.]+)$", text, flags=re.M)
    out = []
    for name in names:
        if "." in name:
            module, attribute = name.rsplit(".", 1)
            out.append((name, getattr(importlib.import_module(f"viscocontact.{module}"),
                                      attribute)))
        else:
            out.append((name, getattr(vc, name)))
    return out


def test_the_api_pages_summaries_are_whole_sentences():
    """The curated API page shows the first sentence of every object it lists."""
    import inspect

    cut = []
    for name, obj in _api_page_objects():
        sentence = first_sentence(inspect.getdoc(obj) or "")
        if not sentence or re.split(r"[\s(]", sentence)[-1] in ABBREVIATIONS:
            cut.append(f"{name}: {sentence[-50:]!r}")
    assert not cut, cut
