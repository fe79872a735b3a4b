"""Sphinx configuration of ivy's documentation site.

Build it from the repository's root (the guides in ``docs/`` and the notebooks in ``notebooks/``
are read where they are, so their relative links work as on GitHub)::

    .venv/bin/python -m sphinx -W --keep-going -c docs/site . build/site

then open ``build/site/index.html``. Needs the ``docs`` extra (``pip install -e ".[all,docs]"``).
The notebooks are rendered with their stored outputs, never executed; the API reference is
generated from the docstrings (``_ext/ivy_api.py``) and imports no framework.
"""

from __future__ import annotations

import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, ROOT)
sys.path.insert(0, os.path.join(HERE, "_ext"))

project = "ivy"
author = "the ivy developers"
copyright = "Apache-2.0, the ivy developers"
release = version = "0.1.0"

extensions = ["sphinx.ext.autodoc", "sphinx.ext.napoleon", "myst_nb", "ivy_api"]

# The source directory is the repository's root; only these files are pages.
root_doc = "docs/site/index"
include_patterns = ["docs/*.md", "docs/site/**.md", "docs/site/**.rst", "notebooks/*.ipynb"]
exclude_patterns = [
    ".venv*", ".git", "build", "dist", "demo_out", "benchmarks", "scripts", "tests",
    "ivy*", "**/.ipynb_checkpoints",
]  # fmt: skip

# Markdown and notebooks: stored outputs only, no kernel at build time.
nb_execution_mode = "off"
nb_merge_streams = True
myst_heading_anchors = 4
myst_enable_extensions = ["colon_fence", "dollarmath"]

# The reference: Google-style docstrings (Args, Returns, Example), signatures as written.
autodoc_member_order = "bysource"
autodoc_typehints = "signature"
napoleon_google_docstring = True
napoleon_numpy_docstring = False
napoleon_use_rtype = False
napoleon_use_ivar = True  # "Attributes:" as fields: NamedTuple fields are documented once

#: Docstrings shown verbatim (as a literal block) because their markup does not parse, kept
#: apart from the packages whose files this site's maintainers may not edit at the moment
#: (ivy_rl is being rewritten). Each entry is a defect to fix in its docstring, then remove here.
VERBATIM_DOCSTRINGS: set[str] = set()


def _verbatim(app, what, name, obj, options, lines):
    qualname = f"{getattr(obj, '__module__', '')}.{getattr(obj, '__qualname__', '')}"
    if qualname in VERBATIM_DOCSTRINGS and lines:
        lines[:] = ["::", ""] + ["   " + line for line in lines] + [""]


def setup(app):
    app.connect("autodoc-process-docstring", _verbatim, priority=400)  # before napoleon (500)


add_module_names = True
python_display_short_literal_types = True

toc_object_entries = False  # the pages' tables of contents list sections, not every entry

html_theme = "furo"
html_title = "ivy"
html_extra_path = ["_root"]  # index.html at the output's root, pointing at the entry page
html_show_sourcelink = False
