"""Every duration and core-hour figure the README and the docs quote, held to its source.

A figure such as "about 7 minutes", "0.22 core-hours" or "1.7 ms" in README.md, the
Makefile's comments or a page of docs/ (the dated page docs/measurements.md apart, which *is* the source) must
be listed in :data:`QUOTES` with where it comes from:

* :class:`Model`: computed here from the cost model (``yade_scripts.launch.slurm.estimate``)
  or the presets, and equal to the quote at the quote's own precision;
* :class:`Measured`: a dated record on docs/measurements.md (the anchor text must be
  there, in a section that carries a date), and the measured value(s) typed beside it
  must round to the quote (or lie in its range);
* :class:`Setting`: a value of the code or of the test cluster's configuration;
* :class:`External`: a behaviour of another program, named with where it is documented;
* :class:`Transcript`: a time printed in a command's shown output (inside code), the
  run it came from;
* :class:`NotADuration`: an "h" or "s" that is a length or a symbol.

The scan fails on a figure that is not listed (a new sentence must say where its number
comes from), on a listed figure no longer in its page (the list must follow the pages),
and on a figure whose source no longer gives it. The committed results the README quotes
(the claims table) are held by ``tests/test_results.py`` and ``make compare``.
"""
import math
import os
import re
from dataclasses import dataclass
from typing import Callable, Optional, Sequence, Union

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MEASUREMENTS = os.path.join(ROOT, "docs", "measurements.md")

_NUM = r"\d+(?:\.\d+)?"
UNITS = r"core-hours?|minutes?|min|hours?|h|seconds?|s|µs|ms"
FIGURE = re.compile(rf"(?<![\w.×/^-])({_NUM})(?:\s?(?:–|to)\s?({_NUM}))?\s?({UNITS})(?![\w-])")
DATE = re.compile(r"20\d\d-\d\d-\d\d")
#: durations in words, and the value (minutes) and half-width each stands for
WORDS = {"half an hour": (30.0, 7.5), "an hour": (60.0, 15.0), "a minute and a half": (1.5, 0.25),
         "a minute": (1.0, 0.25)}
WORD_FIGURE = re.compile(r"\b(" + "|".join(sorted(WORDS, key=len, reverse=True)) + r")\b")


@dataclass
class Model:
    compute: Callable[[], float]       # in the quote's unit


@dataclass
class Measured:
    anchor: str                        # text of docs/measurements.md (whitespace-insensitive)
    values: Optional[Sequence[float]] = None   # the measured value(s), in the quote's unit


@dataclass
class Setting:
    compute: Callable[[], float]


@dataclass
class External:
    where: str


@dataclass
class Transcript:
    run: str


@dataclass
class NotADuration:
    why: str


Source = Union[Model, Measured, Setting, External, Transcript, NotADuration]


def core_hours(preset, sample, kernel_path="plugin", **overrides):
    from yade_scripts.campaign.presets import resolve
    from yade_scripts.launch.slurm import estimate
    return estimate(resolve(preset, sample, overrides or None), kernel_path)["core_hours"]


def seed_pair(preset):
    return core_hours(preset, "polyhedra") + core_hours(preset, "spheres")


def front_core_hours(plan="default"):
    from yade_scripts.campaign.sweeps import PLANS
    from yade_scripts.campaign.presets import resolve
    from yade_scripts.launch.slurm import estimate
    p = PLANS[plan]
    return sum(estimate(resolve(p["preset"], sample, {**p.get("common", {}), **overrides}))["core_hours"]
               for sample in ("polyhedra", "spheres") for _, overrides in p[sample])


def front_runs(plan="default"):
    from yade_scripts.campaign.sweeps import PLANS
    return sum(len(PLANS[plan][s]) for s in ("polyhedra", "spheres"))


def slurm_node(key):
    with open(os.path.join(ROOT, ".ci", "slurm-node")) as fh:
        m = re.search(rf"{key}=(\d+)", fh.read())
    return float(m.group(1))


# The serial share of a step at 5000 grains on one thread and the kernel's speed-up on 16
# threads, as docs/scenes.md quotes them beside its Amdahl estimates (their records:
# docs/measurements.md, "The kernel inside YADE's step" and "Cost at scale").
SERIAL_PLUGIN, SERIAL_PYRUNNER, SPEEDUP_16 = 0.045, 0.37, 7.1

QUOTES = {
    "Makefile": {
        "a minute": Measured("69 s of g++ and", [69 / 60]),
        "4 minutes": Measured("3 min 49 s wall (user 3 min 17 s, sys 14 s)", [3.82]),
        "1.9 core-hours": Model(front_core_hours),
    },
    "README.md": {
        "7 to 16 minutes": Measured("15:36 wall, of which 591 s of pytest", [6.58, 15.6]),
        "half an hour": Measured("took 31 min 34 s on two quiet cores", [31.57]),
    },
    "docs/contact-types.md": {
        "5 h": NotADuration("h: the overlap's thickness along the normal"),
        "0.5–23 h": NotADuration("h: the overlap's thickness"),
        "0.4 h": NotADuration("h: the overlap's thickness"),
        "0 to 6 h": NotADuration("h: the overlap's thickness"),
    },
    "docs/dump-format.md": {
        "1.5 ms": Measured("the crc32 about 1.5 ms of it", [1.5]),
        "7–13 ms": Measured("`read()` of that snapshot from the page cache 7–13 ms", None),
    },
    "docs/front.md": {
        "1.9 core-hours": Model(front_core_hours),
        "1 hour": Model(lambda: front_core_hours() / 2),
        "4.2 core-hours": Measured("(4.2 core-hours in all: S1 3.2, S2 1.05)", [4.25]),
        "22 s": Measured("median of 22 s a step, the 1e-2 run over the same steps", [22.19]),
        "0.9 s": Measured("the 1e-2 run over the same steps 10 iterations and 0.9 s a step", [0.88]),
    },
    "docs/kernel.md": {
        "250–350 µs": Measured("| stock | 1.04 | 2788 | 344 |", [344, 254.9]),
        "0.72 h": NotADuration("h: the cubes' overlap depth"),
        "2 h": NotADuration("2h: a footprint's width, h the cubes' overlap depth"),
        "1 µs": Measured("1.05 µs per touching and 0.031 µs per separated", [1.05]),
        "0.03 µs": Measured("1.05 µs per touching and 0.031 µs per separated", [0.031]),
        "0.8 µs": Measured("**0.82 µs per body-step**", [0.82]),
        "5.0 to 0.13 µs": Measured("0.13 against 5.0 µs per body-step at 5000", None),
        "1.7 ms": Measured("It cost 1.39 ms (collider) + 0.33 ms (loop) per step", [1.72]),
        "0.16 ms": Measured("against 0.16 ms for everything the plugin does", [0.16]),
    },
    "docs/lmgc90-contacts.md": {
        "1 ms": Measured("LMGC90's face topology of the 1000 library shapes", [1.1]),
    },
    "docs/lmgc90.md": {
        "4 minutes": Measured("3 min 49 s wall (user 3 min 17 s, sys 14 s)", [3.82]),
    },
    "docs/scenes.md": {
        "0.22 core-hours": Model(lambda: seed_pair("default")),
        "0.01–0.03 s": Measured("both checkpoint files of a tiny run (20 grains)", None),
        "20 minutes": Model(lambda: 60 * 3 * seed_pair("default") / 2),
        "half an hour": Measured("took 31 min 34 s on two quiet cores", [31.57]),
        "30 s": External("SLURM: the batch shell's --signal warning is checked once every "
                         "30 s (sbatch(1), --signal: 'may be sent up to 60 seconds earlier'); "
                         "measured by tests/test_slurm_cluster.py"),
        "120 s": External("slurm.conf(5), AuthInfo cred_expire: default 120 seconds"),
        "10 s": Setting(lambda: slurm_node("cred_expire")),
        "4.5–8.5 min": Measured("| 36 933 | 1 | 460.78 | 12.48 |", [4.55, 8.49]),
        "6 µs": Measured("| 36 933 | 1 | 460.78 | 12.48 | 1.00 | 148.45 | 224.49 |", [224.49e3 / 36933]),
        "71 core-hours": Model(lambda: core_hours("paper", "polyhedra")),
        "71 hours": Model(lambda: core_hours("paper", "polyhedra")),
        "4 hours": Model(lambda: core_hours("paper", "polyhedra") * (SERIAL_PLUGIN + (1 - SERIAL_PLUGIN) / 64)),
        "13 hours": Model(lambda: core_hours("paper", "polyhedra") * (SERIAL_PLUGIN + (1 - SERIAL_PLUGIN) / SPEEDUP_16)),
        "49 hours": Model(lambda: core_hours("paper", "polyhedra", "pyrunner")
                          * (SERIAL_PYRUNNER + (1 - SERIAL_PYRUNNER) / SPEEDUP_16)),
        "3.9 core-hours": Model(lambda: 3 * seed_pair("intermediate")),
        "5 to 9 hours": Measured("take about 5 hours at that speed", [5]),
        "21 core-hours": Model(lambda: 16 * seed_pair("intermediate")),
    },
    "docs/shapes-import.md": {
        "5.1 s": Transcript("python -m shapes import on the example folder"),
        "147.5 s": Measured("147 grains in 147.5 s", [147.5]),
        "14 s": Measured("| 655 362 | 13.8 s | 0.07 / 1.6 / 10.0 / 1.6 s |", [13.8]),
        "0.14 s": Measured("0.14 s of CPU for the scanned stone of 1 310 720 triangles", [0.14]),
        "0.04 s": Measured("vertices; 0.04 s before", [0.04]),
        "3.3 s": Measured("3.3 s for the smooth ellipsoid of 655 362 hull vertices", [3.3]),
        "1.6 s": Measured("(1.6 s before)", [1.6]),
        "1.06 s": NotADuration("s: the sample's standard deviation in Silverman's rule"),
        "111 s": Measured("made 200 grains in 111 s", [111]),
        "136 s": Transcript("python -m shapes build --like with --n 1000"),
        "30 s": Setting(lambda: _shapes_slow_report()),
        "97 s": Measured("the 30 draws of the flat slab's grain took 97 s", [97]),
        "50 minutes": Measured("450 in 2977 s", [2977 / 60]),
        "3 s": Measured("(a draw then takes about 3 s)", [3]),
        "17 minutes": Measured("stopped after 1010 s", [1010 / 60]),
        "110 s": Measured("147 stones in 106.9 s on one core", [106.9]),
        "10 s": Measured("| 655 362 | 13.8 s | 0.07 / 1.6 / 10.0 / 1.6 s |", [10.0]),
    },
    "docs/shapes.md": {
        "20 s": Measured("`make shapes` (1000 grains from seed 0, the report included)", [19.5]),
    },
    "docs/study.md": {
        "5 to 6 hours": Measured("about 900 shear steps × 22 s, 5 to\n6 hours on this host", [5.5]),
        "19 to 35 minutes": Measured("| S1, 3 | 301 766 | 2917 | 1265 | 2116 |", [1162 / 60, 2116 / 60]),
        "4.0 core-hours": Model(lambda: 18 * seed_pair("default")),
        "3.9 core-hours": Model(lambda: 3 * seed_pair("intermediate")),
    },
}


def _shapes_slow_report():
    import inspect
    from shapes.match import generate_like
    return float(inspect.signature(generate_like).parameters["heartbeat"].default)


def pages():
    out = [os.path.join(ROOT, "README.md"), os.path.join(ROOT, "Makefile")]
    docs = os.path.join(ROOT, "docs")
    out += sorted(os.path.join(docs, f) for f in os.listdir(docs)
                  if f.endswith(".md") and f not in ("measurements.md", "api.md"))
    return out


def _text(path):
    with open(path, encoding="utf-8") as fh:
        return fh.read()


def _flat(text):
    return re.sub(r"\s+", " ", text)


def figures(text):
    """The duration figures of a page: {quote: count}, whitespace flattened, links' targets dropped."""
    text = re.sub(r"\]\([^)]*\)", "]", _flat(text))
    found = {}
    for m in FIGURE.finditer(text):
        lo, hi, unit = m.groups()
        quote = lo + (f"{m.group(0)[len(lo):m.group(0).index(hi, len(lo))]}{hi}" if hi else "") + " " + unit
        quote = re.sub(r"\s+", " ", quote).replace(" – ", "–")
        found[quote] = found.get(quote, 0) + 1
    for m in WORD_FIGURE.finditer(text):
        found[m.group(1)] = found.get(m.group(1), 0) + 1
    return found


def _precision(number):
    """Half a unit of the quote's last digit (an integer's trailing zeros count as rounding)."""
    if "." in number:
        return 0.5 * 10 ** -len(number.split(".")[1])
    zeros = len(number) - len(number.rstrip("0")) if number != "0" else 0
    return 0.5 * 10 ** zeros


def _agrees(quote, value):
    if quote in WORDS:
        centre, half = WORDS[quote]
        return abs(value - centre) <= half
    nums = re.findall(_NUM, quote)
    if len(nums) == 2:
        lo, hi = float(nums[0]), float(nums[1])
        return min(lo, hi) - _precision(nums[0]) <= value <= max(lo, hi) + _precision(nums[1])
    return abs(value - float(nums[0])) <= _precision(nums[0]) + 1e-12


def _dated_section(anchor):
    """The section of docs/measurements.md holding anchor has a date (None: anchor absent)."""
    text = _text(MEASUREMENTS)
    sections = re.split(r"\n(?=#{2,4} )", text)
    anchor = _flat(anchor)
    for s in sections:
        if anchor in _flat(s):
            return bool(DATE.search(s))
    return None


def test_every_figure_of_the_pages_is_listed_with_its_source():
    unlisted, stale = [], []
    for path in pages():
        rel = os.path.relpath(path, ROOT)
        found = figures(_text(path))
        listed = QUOTES.get(rel, {})
        unlisted += [f"{rel}: '{q}'" for q in found if q not in listed]
        stale += [f"{rel}: '{q}'" for q in listed if q not in found]
    assert not unlisted, f"figures without a source in tests/test_quoted_numbers.py QUOTES: {unlisted}"
    assert not stale, f"listed figures no longer in their page: {stale}"


@pytest.mark.parametrize("page,quote", [(p, q) for p, qs in QUOTES.items() for q in qs])
def test_each_figure_agrees_with_its_source(page, quote):
    src = QUOTES[page][quote]
    if isinstance(src, (Model, Setting)):
        value = src.compute()
        assert math.isfinite(value)
        assert _agrees(quote, value), f"{page}: '{quote}' but its source gives {value:.4g}"
    elif isinstance(src, Measured):
        dated = _dated_section(src.anchor)
        assert dated is not None, f"{page}: '{quote}': docs/measurements.md has no '{src.anchor}'"
        assert dated, f"{page}: '{quote}': the record '{src.anchor}' is in a section without a date"
        for v in src.values or ():
            assert _agrees(quote, v), f"{page}: '{quote}' but its record says {v:.4g}"
    elif isinstance(src, Transcript):
        flat = _flat(_text(os.path.join(ROOT, page)))
        spans = re.findall(r"```.*?```|`[^`]*`", flat)
        assert any(quote in s for s in spans), \
            f"{page}: '{quote}' is listed as a command's output but is not inside code"
    else:
        assert isinstance(src, (External, NotADuration)) and (getattr(src, "where", None) or src.why)


def test_the_scan_finds_figures_and_their_precision():
    found = figures("takes about 7 minutes, 2 to 4 minutes and 0.01–0.03 s; lmgc90s, a 5 h depth, "
                    "[x](measurements.md#a-2026-11-26) 1.5 ms\nand 0.22\ncore-hours")
    assert found == {"7 minutes": 1, "2 to 4 minutes": 1, "0.01–0.03 s": 1, "5 h": 1,
                     "1.5 ms": 1, "0.22 core-hours": 1}
    assert _agrees("7 minutes", 6.58) and not _agrees("7 minutes", 6.4)
    assert _agrees("110 s", 106.9) and not _agrees("110 s", 104)
    assert _agrees("2 to 4 minutes", 3.82) and not _agrees("2 to 4 minutes", 4.6)
    assert _agrees("0.22 core-hours", 0.2208) and not _agrees("0.22 core-hours", 0.226)


def _committed(name):
    import json
    with open(os.path.join(ROOT, "reference_data", name)) as fh:
        return json.load(fh)


def _proportions(name):
    rows = {r["quantity"]: r["ours"] for r in _committed(name)["comparison"] if r["sample"] == "polyhedra"}
    return " / ".join(f"{rows[f'proportion of {t} contacts']:.3f}" for t in ("simple", "double", "triple"))


def _leaning(name, count, factor, which):
    (row,) = [r for r in _committed(name)["claim6"] if r["count"] == count and r["factor"] == factor]
    value, interval = row[which].split(" ", 1)
    sign = "+" if not value.startswith("-") else "−"
    return f"{which} {sign}{value.lstrip('-')} {interval.replace('-', '−')}"


#: committed results the docs quote (the README's table: tests/test_results.py):
#: (page, the function of reference_data giving the text the page must hold)
COMMITTED = [
    ("docs/study.md", lambda: _proportions("default-study.json") + " simple / double / triple"),
    ("docs/front.md", lambda: "double / triple " + _proportions("default-study.json") + " at 1000"),
    ("docs/study.md", lambda: _leaning("claim6-5000.json", "lmgc90", 1.0, "VF")),
    ("docs/study.md", lambda: _leaning("claim6-5000.json", "lmgc90", 1.0, "EE")),
    ("docs/front.md", lambda: _leaning("claim6-5000.json", "lmgc90", 1.0, "VF")),
    ("docs/front.md", lambda: _leaning("claim6-5000.json", "lmgc90", 1.0, "EE")),
]


@pytest.mark.parametrize("k", range(len(COMMITTED)))
def test_committed_numbers_the_docs_quote_are_the_committed_ones(k):
    page, text = COMMITTED[k]
    expected = text()
    assert expected in _flat(_text(os.path.join(ROOT, page))), \
        f"{page} does not quote '{expected}' (reference_data gives it)"
