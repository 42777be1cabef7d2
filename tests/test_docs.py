"""The documentation cannot rot: every ```python block of the docs' pages and of README.md runs
(the blocks of a page in order, in one namespace, in a temporary directory), the site builds
with warnings as errors, and nothing in it points outside the repository."""
from __future__ import annotations

import html
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
BLOCK = re.compile(r"^```python\n(.*?)^```", re.S | re.M)


def pages() -> list[Path]:
    found = [ROOT / "README.md"] + sorted(DOCS.rglob("*.md")) + sorted(DOCS.rglob("*.rst"))
    return [p for p in found if "_build" not in p.parts]


def python_blocks(page: Path) -> list[tuple[int, str]]:
    """(line, code) of each ```python block of a Markdown page."""
    text = page.read_text()
    return [(text[:m.start(1)].count("\n") + 1, m.group(1)) for m in BLOCK.finditer(text)]


@pytest.mark.parametrize("page", [p for p in pages() if python_blocks(p)],
                         ids=lambda p: str(p.relative_to(ROOT)))
def test_code_blocks_run(page, tmp_path, monkeypatch):
    import matplotlib
    matplotlib.use("Agg")
    monkeypatch.chdir(tmp_path)
    namespace = {"__name__": "__docs__"}
    for line, code in python_blocks(page):
        # the block's own line numbers in a traceback
        exec(compile("\n" * (line - 1) + code, str(page), "exec"), namespace)
    import matplotlib.pyplot as plt
    plt.close("all")


def test_docs_stay_inside_the_repository():
    """No page links to a local path outside the repository (public web links are fine)."""
    outside = re.compile(r"(file://|/work/|/tmp/|/home/|\.\./\.\./\.\./)")
    for page in pages() + sorted(DOCS.rglob("*.py")):
        for n, line in enumerate(page.read_text().splitlines(), start=1):
            assert not outside.search(line), f"{page.relative_to(ROOT)}:{n} points outside: {line}"


def test_docs_build_without_warnings(tmp_path):
    """sphinx-build -W, the gallery's examples not run (ACAUSAL_DOCS_GALLERY=0); the
    component pages list what the classes declare."""
    for module in ("sphinx", "myst_parser", "furo", "sphinx-mathjax-offline"):
        pytest.importorskip(module, reason=f"{module} is in the docs extra: pip install '.[docs]'")
    out = tmp_path / "html"
    env = dict(os.environ, ACAUSAL_DOCS_GALLERY="0")
    run = subprocess.run([sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-b",
                          "html", str(DOCS), str(out)], capture_output=True, text=True, env=env)
    assert run.returncode == 0, run.stderr[-5000:]

    theory = (out / "theory.html").read_text()          # math typeset by the site's own copy
    assert 'src="_static/mathjax/tex-chtml.js"' in theory and (out / "_static" / "mathjax"
                                                               / "tex-chtml.js").exists()
    scripts = re.compile(r'<script[^>]*src="(https?:)?//')
    for page in out.rglob("*.html"):
        assert not scripts.search(page.read_text()), f"{page.name} loads a script from elsewhere"

    from acausal.components.multibody import Revolute
    from acausal.components.translational import Mass
    page = html.unescape((out / "components" / "translational.html").read_text())
    mass = page[page.index('id="translational-mass"'):]
    mass = mass[:mass.index("</section>")]
    declared = Mass.parameters()["m"]
    for cell in ("m", "1", declared.unit, declared.description, "flange_a", "flange_b"):
        assert f"<p>{cell}</p>" in mass, f"Mass's table lacks {cell!r}"
    differences = page[page.index('id="translational-differences"'):]
    assert "HardStop" in differences and "Not an MSL class" in differences
    vehicle = page[page.index('id="translational-vehicle"'):]
    assert "<p>useInclinationInput = True</p>" in vehicle          # the input's option
    assert 'id="translational-rollingresistance"' in page
    assert "Vehicle" in differences and "written directly" in differences
    page = html.unescape((out / "components" / "thermal.html").read_text())
    for section in ("thermal-thermalcollector", "thermal-convectiveresistor",
                    "thermal-conditionalfixedheatflowsensor", "celsius-fixedtemperature",
                    "celsius-tokelvin", "fahrenheit-fixedtemperature", "rankine-tokelvin"):
        assert f'id="{section}"' in page, f"the thermal page lacks {section}"
    page = html.unescape((out / "components" / "electrical.html").read_text())
    for section in ("electrical-idealthyristor", "electrical-idealgtothyristor",
                    "electrical-idealtwowayswitch", "electrical-controlledidealintermediateswitch",
                    "electrical-saturatinginductor", "electrical-zdiode",
                    "electrical-sawtoothvoltage", "electrical-exponentialscurrent",
                    "electrical-tablevoltage", "electrical-m-transformer",
                    "electrical-opamplimited", "electrical-supplyvoltage",
                    "electrical-thyristor", "electrical-idealtriac", "electrical-npn",
                    "electrical-nmos", "electrical-diode2",
                    "electrical-sinevoltagevariablefrequencyandamplitude"):
        assert f'id="{section}"' in page, f"the electrical page lacks {section}"
    page = html.unescape((out / "components" / "rotational.html").read_text())
    gearbox = page[page.index('id="rotational-gearbox"'):]
    assert "<p>useHeatPort = True</p>" in gearbox and 'id="rotational-signtorque"' in page
    assert 'id="rotational-generalangletotorqueadaptor"' in page
    page = html.unescape((out / "components" / "multibody.html").read_text())
    revolute = page[page.index('id="joints-revolute"'):]
    assert "<p>useAxisFlange = True</p>" in revolute          # axis exists only with the option
    assert Revolute.parameters()["n"].description in revolute
    page = html.unescape((out / "components" / "signals.html").read_text())
    for section in ("signals-replicator", "signals-extractsignal", "signals-multiplex",
                    "signals-multiplex6", "signals-demultiplex2", "signals-realpassthrough"):
        assert f'id="{section}"' in page, f"the signals page lacks {section}"
    page = html.unescape((out / "components" / "logical.html").read_text())
    for section in ("logical-and", "mathboolean-and", "mathboolean-ondelay",
                    "mathboolean-xor", "logical-triggeredtrapezoid", "logical-zerocrossing",
                    "logical-logicaldelay", "logical-booleanreplicator"):
        assert f'id="{section}"' in page, f"the logical page lacks {section}"
    on_delay = page[page.index('id="mathboolean-ondelay"'):]
    assert "<p>delayTime</p>" in on_delay[:on_delay.index("</section>")]
