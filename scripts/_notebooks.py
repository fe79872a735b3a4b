"""Writing a notebook from its cells, shared by the ``scripts/make_*_notebook.py`` scripts."""

from __future__ import annotations

import argparse
import pathlib

import nbformat


def write_notebook(cells, name: str, description: str, timeout: int = 3000) -> pathlib.Path:
    """Write ``notebooks/<name>`` from ``cells`` (``(kind, source)`` pairs, ``kind`` 'code' or
    'markdown'); with ``--execute`` on the command line, run it first (nbclient, from the
    repository's root) so that it is saved with its outputs. Returns the path."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--execute", action="store_true", help="run it and save the outputs")
    args = parser.parse_args()
    nb = nbformat.v4.new_notebook()
    nb.metadata["kernelspec"] = {
        "name": "python3",
        "display_name": "Python 3",
        "language": "python",
    }
    for kind, source in cells:
        make = nbformat.v4.new_code_cell if kind == "code" else nbformat.v4.new_markdown_cell
        nb.cells.append(make(source))
    root = pathlib.Path(__file__).resolve().parents[1]
    path = root / "notebooks" / name
    path.parent.mkdir(exist_ok=True)
    if args.execute:
        from nbclient import NotebookClient

        NotebookClient(
            nb, timeout=timeout, kernel_name="python3", resources={"metadata": {"path": str(root)}}
        ).execute()
    nbformat.write(nb, path)
    print(path)
    return path
