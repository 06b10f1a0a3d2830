"""report.html without a browser: one card per site, every text escaped, every link to a real file,
and the same bytes for the same inputs."""

from __future__ import annotations

import re
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote

import pytest
from sovarc.compiler.batch import BatchOptions, run_batch
from sovarc.compiler.batch.executors import LocalExecutor
from sovarc.compiler.report import REPORT, Card, ScenarioInfo, write_report
from sovarc.compiler.report.page import render_page, script_json

from tests.compiler.batch.test_batch import TOWN, rules
from tests.conftest import EXAMPLES

HOSTILE = '<script>alert("x")</script>&amp;'


class Page(HTMLParser):
    """The parts of the page the tests read: tags with their attributes, and the scripts' text."""

    def __init__(self, text: str) -> None:
        super().__init__()
        self.tags: list[tuple[str, dict[str, str | None]]] = []
        self.scripts: list[str] = []
        self._in_script = False
        self.feed(text)

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.tags.append((tag, dict(attrs)))
        self._in_script = tag == "script"

    def handle_endtag(self, tag: str) -> None:
        self._in_script = False

    def handle_data(self, data: str) -> None:
        if self._in_script:
            self.scripts.append(data)

    def all(self, tag: str, cls: str | None = None) -> list[dict[str, str | None]]:
        return [a for t, a in self.tags if t == tag and (cls is None or cls in (a.get("class") or "").split())]


def _cards(n: int, name: str = "s") -> list[Card]:
    return [Card(scenario=name, site=f"junction:J{k}", map="town.net.xml", verdicts={"sumo": "pass"}) for k in range(n)]


@pytest.mark.slow  # the run behind it replays SUMO
def test_a_run_writes_one_card_per_site_with_its_picture_animation_and_links(run_out: Path) -> None:
    text = (run_out / REPORT).read_text(encoding="utf-8")
    page = Page(text)
    sites = sorted(p.name for p in run_out.iterdir() if p.is_dir())
    cards = page.all("article", "card")
    assert len(cards) == len(sites) == 2
    assert len(page.all("canvas")) == 2 and len(page.all("img")) == 2
    links = [a["href"] for a in page.all("a") if a.get("href") and not a["href"].startswith("#")]
    assert links and all((run_out / unquote(h)).is_file() for h in links), [
        h for h in links if not (run_out / unquote(h)).is_file()
    ]
    for site in sites:
        assert f"{site}/plan.png" in links and f"{site}/verdict-sumo.json" in links
    assert any(h.endswith("/intersection_left_turn_across_path_side.sov") for h in links)  # the scenario, as given
    assert not re.search(r"""(src|href)=["'](https?:)?//""", text)  # nothing loaded from a network


def test_every_text_from_the_inputs_is_escaped(tmp_path: Path) -> None:
    card = Card(scenario=HOSTILE, site=HOSTILE, map=HOSTILE, verdicts={"sumo": "fail"}, error=HOSTILE)
    info = ScenarioInfo(HOSTILE, HOSTILE, f"{HOSTILE}.sov", {"report": HOSTILE})
    text = render_page(HOSTILE, ("sumo",), [info], [card])
    assert "<script>alert" not in text and "&amp;amp;" in text
    assert text.count("<script>") == 1  # the page's own
    assert 'href="%3Cscript%3Ealert%28%22x%22%29%3C/script%3E%26amp%3B.sov"' in text


def test_scene_json_cannot_close_its_script_element() -> None:
    text = script_json({"name": "</script><!--", "a&b": 1})
    assert "</" not in text and "<!--" not in text and "&" not in text


def test_the_summary_counts_verdicts_per_road_kind_and_target() -> None:
    cards = [
        Card("a", "junction:J1", "m", {"sumo": "pass", "fmu": "fail"}, kind="intersection", impact_s=5.0, folder="f"),
        Card("a", "junction:J2", "m", {"sumo": "fail", "fmu": "pass"}, kind="intersection", impact_s=5.0, folder="f"),
        Card("b", "edge:E1", "m", {"sumo": "pass", "fmu": "pass"}, kind="straight", impact_s=5.0, folder="f"),
        Card("b", "", "m", {"sumo": "-", "fmu": "-"}, error="no site"),
    ]
    text = render_page(
        "t", ("sumo", "fmu"), [ScenarioInfo("a", "a.sov", None), ScenarioInfo("b", "b.sov", None)], cards
    )
    table = re.search(r"<tbody>(.*)</tbody>", text).group(1)  # type: ignore[union-attr]
    rows = [re.sub(r"(<[^>]+>)+", "|", r).strip("|") for r in table.split("</tr>") if r]
    assert rows == [
        "intersection|2|1 / 2|1 / 2",
        "straight|1|1 / 1|1 / 1",
        "not planned|1|-|-",
        "all|4|2 / 3|2 / 3",
    ]
    assert len(Page(text).all("article", "card")) == 4 and len(Page(text).all("article", "failed")) == 1


def test_same_cards_same_bytes(tmp_path: Path) -> None:
    infos = [ScenarioInfo("s", "s.sov", "s.sov", {"report": "r.txt"})]
    first = write_report(tmp_path / "a", "t", ("sumo",), infos, _cards(3)).read_bytes()
    second = write_report(tmp_path / "b", "t", ("sumo",), infos, _cards(3)).read_bytes()
    assert first == second and b"<article" in first


@pytest.mark.slow  # SUMO replays the good scenario
def test_a_batch_report_has_a_card_per_manifest_row_and_links_the_kept_scenarios(tmp_path: Path) -> None:
    bad = tmp_path / "broken.sov"
    bad.write_text("scenario broken {\n  road { kind nowhere }\n}\n", encoding="utf-8")
    good = EXAMPLES / "scenarios" / "straight_rear_end_stopped_traffic.sov"
    out = tmp_path / "o"
    executor = LocalExecutor(1)
    try:
        result = run_batch([str(bad), str(good)], BatchOptions(maps=(str(TOWN),), out=out, roads=2), executor, rules)
    finally:
        executor.close()
    page = Page((out / REPORT).read_text(encoding="utf-8"))
    assert len(page.all("article", "card")) == len(result.rows) == 3
    assert len(page.all("article", "failed")) == 1 and len(page.all("canvas")) == 2
    links = [a["href"] or "" for a in page.all("a") if not (a.get("href") or "#").startswith("#")]
    assert all((out / unquote(h)).resolve().is_file() for h in links)
    assert any(h.endswith("straight_rear_end_stopped_traffic.sov") for h in links)
