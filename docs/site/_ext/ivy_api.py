"""The API reference, generated at build time from each package's public-name listing.

Directives (each expands to autodoc directives, so the reference follows ``__all__`` as the code
changes and a new public name needs no edit here):

- ``.. public-api:: MODULE`` documents every name of ``MODULE.__all__``; ``:namespace: NS``
  documents them under another name (``ivy.core.elementwise``'s functions as ``ivy.clip``), and
  ``:exclude:`` leaves names out. A module listed in ``__all__`` (``ivy_rl.agents``) becomes a
  section of its own, with those of its names that the package does not export itself.
- ``.. ivy-core-groups::`` documents the core's functions group by group, in the order of
  ``ivy.core.GROUPS``, each group a section with its module's summary.

A post-transform also links inline code that names a documented object (```ivy.clip```,
```ivy_gym.rollout(env, ...)```) to its entry, in the guides and in the docstrings alike.
"""

from __future__ import annotations

import importlib
import inspect
import re

from docutils import nodes
from docutils.parsers.rst import directives
from docutils.statemachine import StringList
from sphinx.transforms.post_transforms import SphinxPostTransform
from sphinx.util.docutils import SphinxDirective
from sphinx.util.nodes import make_refnode, nested_parse_with_titles

#: the section underlines of the generated sections, by depth below the page's title
UNDERLINES = "-~^"


def public_names(module) -> list[str]:
    """The names a module lists in ``__all__``, in its order."""
    return list(getattr(module, "__all__", ()))


def entry(qualname: str, obj, doc: str | None = None) -> list[str]:
    """The reST of one reference entry: a class with its public methods, a function, or data."""
    if inspect.isclass(obj):
        return [f".. autoclass:: {qualname}", "   :members:", ""]
    if inspect.isfunction(obj) or inspect.isbuiltin(obj) or isinstance(obj, type(len)):
        return [f".. autofunction:: {qualname}", ""]
    if callable(obj) and hasattr(obj, "__wrapped__"):  # functools wrappers (lru_cache, ...)
        return [f".. autofunction:: {qualname}", ""]
    module, _, name = qualname.rpartition(".")
    lines = [f".. py:data:: {name}", f"   :module: {module}"]
    if not inspect.ismodule(obj):
        value = repr(obj)
        if len(value) > 60:
            value = f"{type(obj).__name__} of {len(obj)}" if hasattr(obj, "__len__") else ""
        if value:
            lines.append(f"   :value: {value}")
    lines.append("")
    if doc:
        lines += ["   " + line for line in doc.splitlines()] + [""]
    return lines


def module_lines(module_name: str, namespace: str | None, exclude=(), depth=0) -> list[str]:
    """The reST of every public name of ``module_name``, documented under ``namespace``."""
    module = importlib.import_module(module_name)
    namespace = namespace or module_name
    lines: list[str] = []
    submodules = []
    for name in public_names(module):
        if name in exclude:
            continue
        obj = getattr(module, name)
        if inspect.ismodule(obj):
            submodules.append((name, obj))
            continue
        lines += entry(f"{namespace}.{name}", obj)
    for name, sub in submodules:
        title = f"``{namespace}.{name}``"
        summary = (inspect.getdoc(sub) or "").split("\n\n")[0]
        lines += [title, UNDERLINES[depth] * len(title), ""]
        lines += [f".. py:module:: {namespace}.{name}", ""]
        if summary:
            lines += [summary, ""]
        flat = [n for n in public_names(sub) if getattr(module, n, None) is getattr(sub, n)]
        if flat:
            refs = ", ".join(f":py:obj:`~{namespace}.{n}`" for n in flat)
            lines += [f"Exported by ``{namespace}`` itself and documented above: {refs}.", ""]
        for n in public_names(sub):
            if n not in flat:
                lines += entry(f"{namespace}.{name}.{n}", getattr(sub, n))
    return lines


class PublicApi(SphinxDirective):
    required_arguments = 1
    option_spec = {"namespace": directives.unchanged, "exclude": directives.unchanged}

    def run(self):
        exclude = set((self.options.get("exclude") or "").split())
        lines = module_lines(self.arguments[0], self.options.get("namespace"), exclude)
        return self._parse(lines)

    def _parse(self, lines):
        node = nodes.section()
        node.document = self.state.document
        nested_parse_with_titles(self.state, StringList(lines, self.get_source_info()[0]), node)
        return node.children


class IvyCoreGroups(PublicApi):
    required_arguments = 0
    option_spec = {"exclude": directives.unchanged}

    def run(self):
        import ivy.core

        exclude = set((self.options.get("exclude") or "").split())
        lines: list[str] = []
        for group in ivy.core.GROUPS:
            name = group.__name__.rpartition(".")[2]
            title = name.replace("_", " ").capitalize()
            summary = (inspect.getdoc(group) or "").split("\n\n")[0]
            lines += [title, UNDERLINES[0] * len(title), ""]
            lines += [f"From ``ivy/core/{name}.py``. {summary}", ""]
            # names whose ``ivy.<name>`` is another object (``ivy.fft``, the extension's
            # namespace) are documented with that object
            moved = {
                n for n in public_names(group) if getattr(ivy, n, None) is not getattr(group, n)
            }
            lines += module_lines(group.__name__, "ivy", exclude | moved)
        return self._parse(lines)


class LinkInlineCode(SphinxPostTransform):
    """Inline code naming a documented object becomes a link to its entry."""

    default_priority = 5  # before the references are resolved and reported
    PATTERN = re.compile(r"^(ivy[a-z_]*(?:\.[A-Za-z_]\w*)+)(?:\(.*\))?$")

    def run(self, **kwargs):
        objects = self.env.get_domain("py").objects
        builder = self.app.builder
        for literal in list(self.document.findall(nodes.literal)):
            if isinstance(literal.parent, (nodes.reference, nodes.literal_block)):
                continue
            if "xref" in literal.get("classes", []):
                continue
            match = self.PATTERN.match(literal.astext())
            if not match or match.group(1) not in objects:
                continue
            target = objects[match.group(1)]
            ref = make_refnode(
                builder, self.env.docname, target.docname, target.node_id, literal.deepcopy()
            )
            literal.replace_self(ref)


def setup(app):
    app.add_directive("public-api", PublicApi)
    app.add_directive("ivy-core-groups", IvyCoreGroups)
    app.add_post_transform(LinkInlineCode)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
