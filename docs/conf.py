"""Sphinx configuration of acausal's documentation.

Build: ``sphinx-build -W -b html docs docs/_build/html`` (``ACAUSAL_DOCS_GALLERY=0`` skips
running the examples for the gallery)."""
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path[:0] = [str(HERE.parent / "src"), str(HERE / "_ext")]

project = "acausal"
author = "acausal contributors"
copyright = "acausal contributors"

# MathJax served from the built site itself (sphinx-mathjax-offline copies it into _static):
# the pages read offline and load nothing from elsewhere
extensions = ["sphinx.ext.autodoc", "sphinx.ext.napoleon", "sphinx.ext.mathjax",
              "sphinx-mathjax-offline", "myst_parser", "acausal_docs"]
source_suffix = {".md": "markdown", ".rst": "restructuredtext"}
exclude_patterns = ["_build", "_ext"]
myst_enable_extensions = ["dollarmath", "colon_fence"]
myst_heading_anchors = 3

# the docstrings of components end with numpydoc sections generated from their declarations
napoleon_google_docstring = False
napoleon_numpy_docstring = True
napoleon_custom_sections = [("Options", "params_style"), ("Ports", "params_style")]
autodoc_member_order = "bysource"
autodoc_typehints = "description"
autodoc_default_options = {"members": True, "show-inheritance": False}

html_theme = "furo"
html_title = "acausal"
html_static_path = ["_static"]
html_css_files = ["acausal.css"]
