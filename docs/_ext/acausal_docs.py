"""Sphinx directives of acausal's documentation, generated from the code when the docs build.

``component-tables`` (argument: a module of ``acausal.components``)
    for every component class the module exports: its description, a table of its parameters
    (default, unit, description, from the ``Parameter`` declarations), its ports and its
    structural options; then the differences from the MSL its docstrings state.
``example-figure`` (argument: an example's name)
    the figures that example saved;
``gallery``
    every script of ``examples/`` with its description and the figures it saved. The scripts
    run when the docs build (``MPLBACKEND=Agg``, ``ACAUSAL_OUT`` a folder of the build
    directory); ``ACAUSAL_DOCS_GALLERY=0`` skips running them (a quick build: the gallery then
    shows the figures of an earlier full build, if any).

Docstrings are read as reStructuredText, with ``|x|`` an absolute value (not a substitution);
a paragraph that is not valid reStructuredText (a hand-aligned table of arguments, say) is
shown as it is written, as preformatted text, instead of failing the build (``readable``).
"""
from __future__ import annotations

import html
import importlib
import inspect
import io
import os
import re
import subprocess
import sys
import time
from pathlib import Path

import docutils.core
from docutils import nodes
from docutils.parsers.rst import Parser as RstParser
from docutils.utils import new_document
from sphinx.util import logging
from sphinx.util.docutils import SphinxDirective

from acausal.core.component import Component, port_rows
from acausal.core.documentation import SECTIONS, parameter_rows, shown

logger = logging.getLogger(__name__)

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
GALLERY = "_gallery"                      # folder of the html output holding the figures
#: Where a docstring says how a component differs from its MSL / PlanarMechanics original.
DIFFERENCE = re.compile(r"(Differences? from (the )?(MSL|PlanarMechanics|Modelica)|"
                        r"(MSL|PlanarMechanics) differences|[Nn]ot an MSL (class|component|block))")


def escape_bars(text: str) -> str:
    """``text`` with every ``|`` outside ``literal`` spans escaped (an absolute value, not a
    substitution reference)."""
    parts = text.split("``")
    return "``".join(p if i % 2 else p.replace("|", r"\|") for i, p in enumerate(parts))


def valid_rst(text: str) -> bool:
    """Whether docutils parses ``text`` without a warning (Sphinx's own roles and directives,
    unknown to plain docutils, aside)."""
    report = io.StringIO()
    docutils.core.publish_doctree(text, settings_overrides={
        "warning_stream": report, "report_level": 2, "halt_level": 5})
    problems = re.findall(r"\((?:WARNING|ERROR|SEVERE)/\d\) (.*)", report.getvalue())
    return all(p.startswith(("Unknown interpreted text role", "Unknown directive type"))
               for p in problems)


def chunks(text: str) -> list[str]:
    """``text`` split at the blank lines followed by an unindented line (an indented block
    stays with the paragraph that introduces it)."""
    out, lines = [], text.splitlines()
    start = 0
    for i in range(1, len(lines)):
        if not lines[i - 1].strip() and lines[i].strip() and not lines[i][0].isspace():
            out.append("\n".join(lines[start:i]))
            start = i
    out.append("\n".join(lines[start:]))
    return out


def readable(text: str) -> str:
    """``text`` as reStructuredText to parse: each paragraph as written (bars escaped) where
    it is valid, else as a literal block of it, shown as written."""
    out = []
    for chunk in chunks(text):
        escaped = escape_bars(chunk)
        if valid_rst(escaped):
            out.append(escaped)
        else:
            out.append("::\n\n" + "\n".join("    " + line for line in chunk.splitlines()) + "\n")
    return "\n".join(out)


def description(cls) -> str:
    """A component's docstring without the sections generated from its declarations."""
    doc = inspect.cleandoc(cls.__doc__ or "")
    for title in SECTIONS:
        doc = doc.split(f"\n{title}\n{'-' * len(title)}")[0]
    return doc.strip()


def summary(text: str, width: int = 160) -> str:
    """The first sentence of ``text``, on one line, as plain text, at most about ``width``
    characters."""
    first = " ".join(text.split("\n\n")[0].split()).replace("``", "")
    end = re.search(r"\.(\s|$)", first)
    first = first[:end.start() + 1] if end else first.rstrip(":;, ") + " …"
    return first if len(first) <= width else first[:first.rfind(" ", 0, width)] + " …"


def differences(text: str) -> list[str]:
    """The paragraphs of ``text`` from where they state a difference from the MSL."""
    out = []
    for paragraph in text.split("\n\n"):
        flat = " ".join(paragraph.split())
        found = DIFFERENCE.search(flat)
        if found:
            out.append(flat[found.start():])
    return out


def namespace(name: str):
    """The module ``name``, or the namespace class ``module.Class`` (MSL's subpackages of
    blocks whose names repeat others', e.g. ``logical.MathBoolean``)."""
    try:
        return importlib.import_module(name)
    except ModuleNotFoundError:
        parent, _, attr = name.rpartition(".")
        return getattr(importlib.import_module(parent), attr)


def components(module) -> list[tuple[str, type]]:
    """The component classes ``module`` exports, partial (base) classes last."""
    names = getattr(module, "__all__", None) or [n for n in vars(module) if not n.startswith("_")]
    found = [(n, getattr(module, n)) for n in names]
    found = [(n, c) for n, c in found if inspect.isclass(c) and issubclass(c, Component)]
    return sorted(found, key=lambda nc: nc[0].lower().startswith("partial"))


def table(header: list[str], rows: list[list[str]], widths: list[int]) -> nodes.table:
    """A table of plain text cells (no markup is parsed in them)."""
    group = nodes.tgroup(cols=len(header))
    group += [nodes.colspec(colwidth=w) for w in widths]
    head, body = nodes.thead(), nodes.tbody()
    for cells, part in [(header, head)] + [(r, body) for r in rows]:
        row = nodes.row()
        for cell in cells:
            entry = nodes.entry()
            entry += nodes.paragraph(text=cell)
            row += entry
        part += row
    group += head
    group += body
    out = nodes.table(classes=["component-table"])
    out += group
    return out


def parse_rst(directive: SphinxDirective, text: str, source: str) -> list[nodes.Node]:
    """A docstring ``readable`` as reStructuredText (the page itself may be Markdown)."""
    document = new_document(source, directive.state.document.settings)
    RstParser().parse(readable(text), document)
    return document.children


class ComponentTables(SphinxDirective):
    """The reference of every component of a module (see the module's docstring)."""
    required_arguments = 1

    def parse(self, text: str) -> list[nodes.Node]:
        return parse_rst(self, text, self.arguments[0])

    def section(self, key: str, title: str) -> nodes.section:
        sec = nodes.section(ids=[nodes.make_id(key)], names=[nodes.fully_normalize_name(key)])
        sec += nodes.title(text=title)
        self.state.document.note_implicit_target(sec)
        return sec

    def run(self) -> list[nodes.Node]:
        name = self.arguments[0]
        module = namespace(name)
        self.env.note_dependency(inspect.getsourcefile(module))
        short = name.rsplit(".", 1)[-1]
        out: list[nodes.Node] = self.parse(inspect.cleandoc(module.__doc__ or ""))
        found = components(module)
        rows = [[n, summary(description(c))] for n, c in found]
        out.append(table(["component", "what it is"], rows, [20, 80]))
        notes = [(f"{short} (the module)", d)
                 for d in differences(inspect.cleandoc(module.__doc__ or ""))]
        for cname, cls in found:
            sec = self.section(f"{short}-{cname}", cname)
            sec += nodes.paragraph("", "", nodes.literal(text=f"{name}.{cname}"))
            text = description(cls)
            sec += self.parse(text)
            params = parameter_rows(cls.parameters(), cls.required)
            if params:
                sec += nodes.rubric(text="Parameters")
                sec += table(["name", "default", "unit", "description"],
                             [list(r) for r in params], [18, 16, 12, 54])
            ports = port_rows(cls)
            if ports:
                sec += nodes.rubric(text="Ports")
                sec += table(["name", "type", "description", "exists if"],
                             [list(r) for r in ports], [18, 20, 46, 16])
            options = cls.all_options()
            if options:
                sec += nodes.rubric(text="Options (structural)")
                sec += table(["name", "default", "values"],
                             [[k, shown(v), ", ".join(repr(m.value) for m in type(v))
                               if hasattr(type(v), "__members__") else "True, False"]
                              for k, v in options.items()], [25, 25, 50])
            out.append(sec)
            notes += [(cname, d) for d in differences(text)]
        if notes:
            sec = self.section(f"{short}-differences", "Differences from the MSL")
            items = nodes.bullet_list()
            for cname, text in notes:
                item = nodes.list_item()
                item += nodes.paragraph("", "", nodes.strong(text=cname), nodes.Text(": "))
                item += self.parse(text)
                items += item
            sec += items
            out.append(sec)
        return out


def example_scripts() -> list[Path]:
    return sorted(EXAMPLES.glob("*.py"))


def run_examples(app) -> None:
    """Run every example into ``<html output>/_gallery/<example>/`` (its working directory
    and ``ACAUSAL_OUT``) unless ``ACAUSAL_DOCS_GALLERY=0``; an example already run since the
    last change of it or of the package is not run again."""
    if os.environ.get("ACAUSAL_DOCS_GALLERY", "1") == "0" or app.builder.format != "html":
        return
    env = dict(os.environ, MPLBACKEND="Agg",
               PYTHONPATH=os.pathsep.join([str(ROOT / "src"), os.environ.get("PYTHONPATH", "")]))
    package = max(p.stat().st_mtime for p in (ROOT / "src").rglob("*.py"))
    for script in example_scripts():
        out = Path(app.outdir) / GALLERY / script.stem
        stamp = out / ".done"
        if stamp.exists() and stamp.stat().st_mtime > max(package, script.stat().st_mtime):
            continue
        out.mkdir(parents=True, exist_ok=True)
        t0 = time.perf_counter()
        run = subprocess.run([sys.executable, str(script)], cwd=out, capture_output=True,
                             text=True, env=dict(env, ACAUSAL_OUT=str(out)), timeout=1800)
        printed = (run.stdout + run.stderr).replace(str(out), ".").replace(f"{ROOT}/", "")
        (out / "output.txt").write_text(printed)
        if run.returncode:
            logger.warning(f"example {script.name} failed (exit {run.returncode}): "
                           f"{run.stderr.strip().splitlines()[-1:]}")
            continue
        stamp.touch()
        logger.info(f"gallery: {script.name} ran in {time.perf_counter() - t0:.1f} s")


def figures(directive: SphinxDirective, stem: str) -> list[nodes.Node]:
    """The figures example ``stem`` saved in the gallery's folder, as images linked from the
    page that ``directive`` is on (none in a build that did not run the examples)."""
    folder = Path(directive.env.app.outdir) / GALLERY / stem
    up = "../" * directive.env.docname.count("/")
    out = []
    for figure in sorted(folder.glob("*.png")) + sorted(folder.glob("*.gif")):
        uri = f"{up}{GALLERY}/{stem}/{figure.name}"
        out.append(nodes.raw("", f'<a href="{uri}"><img class="gallery-figure" src="{uri}" '
                                 f'alt="{figure.name}"/></a>', format="html"))
    return out


class ExampleFigure(SphinxDirective):
    """The figures of one example (argument: its file name without .py)."""
    required_arguments = 1

    def run(self) -> list[nodes.Node]:
        self.env.note_dependency(str(EXAMPLES / f"{self.arguments[0]}.py"))
        return figures(self, self.arguments[0]) or [nodes.paragraph(
            text=f"(The figure of examples/{self.arguments[0]}.py appears here when the "
                 f"documentation is built with the gallery.)")]


class Gallery(SphinxDirective):
    """Every example: its description, how to run it, the figures it saved."""

    def run(self) -> list[nodes.Node]:
        out: list[nodes.Node] = [self.thumbnails()]
        for script in example_scripts():
            self.env.note_dependency(str(script))
            doc = inspect.cleandoc(_module_docstring(script))
            sec = nodes.section(ids=[nodes.make_id(f"example-{script.stem}")],
                                names=[script.name])
            sec += nodes.title(text=script.name)
            self.state.document.note_implicit_target(sec)
            sec += parse_rst(self, doc, str(script.relative_to(ROOT)))
            sec += nodes.literal_block(text=f"python examples/{script.name}",
                                       language="console")
            sec += figures(self, script.stem)
            printed = Path(self.env.app.outdir) / GALLERY / script.stem / "output.txt"
            if printed.exists():
                sec += nodes.raw("", "<details><summary>what it printed</summary><pre>"
                                     + html.escape(printed.read_text()) + "</pre></details>",
                                 format="html")
            out.append(sec)
        return out


    def thumbnails(self) -> nodes.raw:
        """A grid of the examples' first figures, each a link to the example's section."""
        cells = []
        for script in example_scripts():
            shown = figures(self, script.stem)[:1]
            image = re.search(r'<img [^>]*/>', shown[0].astext()).group(0) if shown \
                else '<span class="gallery-none">prints only</span>'
            cells.append(f'<a class="gallery-thumb" href="#{nodes.make_id("example-" + script.stem)}">'
                         f'{image}<span>{script.stem}</span></a>')
        return nodes.raw("", '<div class="gallery-grid">' + "".join(cells) + "</div>",
                         format="html")


def _module_docstring(script: Path) -> str:
    import ast
    return ast.get_docstring(ast.parse(script.read_text())) or ""


def readable_docstring(app, what, name, obj, options, lines) -> None:
    """autodoc, before napoleon reads the sections: the prose of a docstring made
    ``readable``; the sections generated from a component's declarations kept for napoleon."""
    text = "\n".join(lines)
    cut = min([text.find(f"\n{t}\n{'-' * len(t)}") for t in SECTIONS
               if f"\n{t}\n{'-' * len(t)}" in text] or [len(text)])
    lines[:] = (readable(text[:cut]).rstrip("\n") + "\n\n" + text[cut:].lstrip("\n")).split("\n")


def setup(app):
    app.add_directive("component-tables", ComponentTables)
    app.add_directive("gallery", Gallery)
    app.add_directive("example-figure", ExampleFigure)
    app.connect("builder-inited", run_examples)
    app.connect("autodoc-process-docstring", readable_docstring, priority=400)
    return {"parallel_read_safe": True, "version": "1"}
