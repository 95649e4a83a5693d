# Sphinx configuration of the Möbius Registration documentation: MyST markdown pages,
# built from Debian's python3-sphinx and python3-myst-parser without the network.
from pygments.lexers.python import PythonLexer
from sphinx.highlighting import lexers

project = "Möbius Registration for VTK and ParaView"
author = "the Möbius Registration authors"
copyright = "the Möbius Registration authors, BSD-3-Clause"

extensions = ["myst_parser"]
source_suffix = {".md": "markdown"}
exclude_patterns = ["_build"]
# Headings up to level 3 get anchors, so that pages can link to sections (page.md#section).
myst_heading_anchors = 3
html_theme = "alabaster"
html_static_path = []
# Code blocks run by pvpython (Testing/Documentation/test_readme_snippets.py) are Python.
lexers["pvpython"] = PythonLexer()
