"""Sphinx configuration: the Markdown pages of docs/ (MyST), the executed tutorials (MyST-NB) and
a curated API reference from the docstrings.

Build (warnings as errors): ``python -m sphinx -W --keep-going -b html docs docs/_build/html``
"""
from importlib.metadata import version as _version

project = "viscocontact"
author = "the viscocontact developers"
copyright = "2026, the viscocontact developers"
release = _version("viscocontact")
version = ".".join(release.split(".")[:2])

extensions = [
    "myst_nb",  # MyST markdown, and executes the pages written as notebooks (tutorials)
    "numpydoc",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "sphinx.ext.viewcode",
]

root_doc = "index"
# README.md is the folder's index on a forge; index.md includes it, so it is not a page of its own.
exclude_patterns = ["_build", "README.md"]
templates_path = ["_templates"]

# MyST: headings get anchors for the pages' "#section" links.
myst_heading_anchors = 3

# Tutorials: a page with a ``file_format: mystnb`` header is a notebook, executed at every build
# (its outputs and figures come from the build, none are committed); a failing cell fails the
# build. The pages run with the documentation's folder as working directory.
nb_execution_mode = "force"
nb_execution_raise_on_error = True
nb_execution_timeout = 120
nb_execution_show_tb = True
nb_merge_streams = True

# API reference: one page per public name, generated at build time into api/ (not committed).
autosummary_generate = True
autosummary_imported_members = False
autodoc_default_options = {
    "members": True,
    "show-inheritance": True,
    # An object is documented in the module that defines it; a package's __all__ re-exports it.
    "ignore-module-all": True,
}
autodoc_member_order = "bysource"
autodoc_typehints = "none"  # the numpydoc Parameters sections carry the types
numpydoc_show_class_members = False
numpydoc_validation_checks: set[str] = set()

html_theme = "alabaster"
html_static_path: list[str] = []
