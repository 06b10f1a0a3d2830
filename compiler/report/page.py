"""The HTML of report.html, from the cards: every text from the inputs escaped, every link quoted.

Built with the standard library (html.escape, urllib.parse.quote): the page is small and fixed in
shape, and sovarc has no templating dependency to bring in for it.
"""

from __future__ import annotations

import html
import json
from collections import Counter
from typing import TYPE_CHECKING, Any
from urllib.parse import quote

from sovarc.compiler.report.assets import SCRIPT, STYLE

if TYPE_CHECKING:  # the package imports this module; the types are only for the checker
    from sovarc.compiler.report import Card, ScenarioInfo

PICTURE = "plan.png"
ANIMATION_NOTE = (
    "The crash replayed from the plan's samples: each body as the plan places it, its heading line "
    "from its centre through its front; the key gives each one's role and speed. The view follows the bodies and stops "
    "at impact (the collision area turns solid, the impact point is crossed), then starts again. "
    "Drag the slider to scrub; the button pauses."
)


def esc(text: Any) -> str:
    return html.escape(str(text), quote=True)


def href(path: str) -> str:
    """A relative link to a file beside the page: each path segment percent-quoted, then escaped."""
    return esc(quote(path, safe="/"))


def script_json(data: Any) -> str:
    """JSON safe inside <script>: no '<', '>' or '&' that could end the element or start a comment."""
    text = json.dumps(data, sort_keys=True, separators=(",", ":"), ensure_ascii=False)
    return text.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")


def anchor(name: str) -> str:
    return "s-" + "".join(c if c.isalnum() or c in "-_" else "_" for c in name)


def render_page(title: str, targets: tuple[str, ...], infos: list[ScenarioInfo], cards: list[Card]) -> str:
    maps = sorted({c.map for c in cards if c.map})
    planned = sum(c.kind != "-" for c in cards)
    parts = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        '<meta name="viewport" content="width=device-width, initial-scale=1">',
        f"<title>{esc(title)}</title>",
        f"<style>{STYLE}</style></head><body>",
        f"<header><h1>{esc(title)}</h1>",
        f"<p>{len(cards)} scenario-site(s) of {len(infos)} scenario(s), {planned} planned, on "
        f"{esc(', '.join(_name(m) for m in maps) or 'no map')}; targets: {esc(', '.join(targets) or 'none')}.</p>",
        '<p class="hint">Each card: the plan picture (the whole plan, and a close-up of the last seconds) '
        "and the crash replayed from the plan's samples. Striker red, victim blue.</p></header>",
        summary_table(targets, cards),
        '<nav class="toc"><b>Scenarios:</b> '
        + " · ".join(f'<a href="#{esc(anchor(i.name))}">{esc(i.name)}</a>' for i in infos)
        + "</nav>",
    ]
    for k, info in enumerate(infos):
        own = [c for c in cards if c.scenario == info.name]
        parts.append(scenario_section(info, own, targets, k))
    parts.append(f"<script>{SCRIPT}</script></body></html>")
    return "\n".join(parts) + "\n"


def summary_table(targets: tuple[str, ...], cards: list[Card]) -> str:
    """Per road kind (sorted; sites not planned last): how many sites, and per target passed/checked."""
    kinds = sorted({c.kind for c in cards}, key=lambda k: (k == "-", k))
    head = "".join(f"<th>{esc(t)}</th>" for t in targets)
    rows = []
    for kind in [*kinds, "all"]:
        own = [c for c in cards if kind in ("all", c.kind)]
        cells = [f"<td>{_count(own, t)}</td>" for t in targets]
        label = "not planned" if kind == "-" else kind
        rows.append(f'<tr class="{"total" if kind == "all" else ""}"><th>{esc(label)}</th>'
                    f"<td>{len(own)}</td>{''.join(cells)}</tr>")  # fmt: skip
    return (
        '<section id="summary"><h2>Verdicts by target and road kind</h2>'
        f"<table><thead><tr><th>road kind</th><th>sites</th>{head}</tr></thead>"
        f"<tbody>{''.join(rows)}</tbody></table>"
        '<p class="hint">passed / checked; a site not planned has no verdict.</p></section>'
    )


def _count(cards: list[Card], target: str) -> str:
    tally = Counter(c.verdicts.get(target, "-") for c in cards)
    checked = tally["pass"] + tally["fail"]
    if not checked:
        return "-"
    cls = "pass" if tally["fail"] == 0 else "fail"
    return f'<span class="{cls}">{tally["pass"]} / {checked}</span>'


def scenario_section(info: ScenarioInfo, cards: list[Card], targets: tuple[str, ...], index: int) -> str:
    sov = f'<a href="{href(info.sov)}">{esc(_name(info.sov))}</a>' if info.sov else "<i>no .sov kept</i>"
    prov = "".join(f"<dt>{esc(k)}</dt><dd>{esc(v)}</dd>" for k, v in info.provenance.items())
    body = "".join(card_html(c, targets, f"{index}-{k}") for k, c in enumerate(cards))
    return (
        f'<section class="scenario" id="{esc(anchor(info.name))}"><h2>{esc(info.name)}</h2>'
        f'<p class="source">input <code>{esc(info.input)}</code> · scenario {sov}</p>'
        f'<details class="provenance"><summary>provenance</summary><dl>{prov or "<dt>-</dt><dd>none recorded</dd>"}'
        f"</dl></details>"
        f'<div class="cards">{body}</div></section>'
    )


def card_html(card: Card, targets: tuple[str, ...], key: str) -> str:
    badges = "".join(_badge(card, t) for t in targets)
    head = (
        f"<header><h3>{esc(card.site or 'no site')}</h3>"
        f'<p class="meta">{esc(card.kind)} · map <code title="{esc(card.map)}">{esc(_name(card.map))}</code>'
        + (f" · impact at {card.impact_s:.2f} s" if card.impact_s is not None else "")
        + f'</p><p class="badges">{badges}</p>'
        + (f'<p class="crash">{esc(card.crash)}</p>' if card.crash else "")
        + "</header>"
    )
    if card.impact_s is None or card.folder is None:
        error = f'<p class="error">{esc(card.error or "not planned")}</p>'
        return f'<article class="card failed" data-site="{esc(card.site)}">{head}{error}{_files(card)}</article>'
    picture = f"{card.folder}/{PICTURE}"
    views = f'<a href="{href(picture)}"><img src="{href(picture)}" alt="plan of {esc(card.site)}" width="1000"></a>'
    if card.scene is not None:
        views += (
            f'<figure class="anim"><canvas width="480" height="480" data-scene="scene-{esc(key)}"></canvas>'
            '<figcaption><button type="button" class="play">pause</button>'
            '<input type="range" class="scrub" min="0" max="1000" value="0" aria-label="time">'
            '<span class="clock">0.0 s</span></figcaption></figure>'
            f'<script type="application/json" id="scene-{esc(key)}">{script_json(card.scene)}</script>'
            f'<p class="anim-note">{ANIMATION_NOTE}</p>'
        )
    note = f'<p class="error">{esc(card.error)}</p>' if card.error else ""
    body = f'{head}<div class="views">{views}</div>{note}{_files(card)}'
    return f'<article class="card" data-site="{esc(card.site)}">{body}</article>'


def _files(card: Card) -> str:
    """The site's files, each a link (folded: a target's folder holds many)."""
    if card.folder is None:
        return ""
    folder = card.folder
    items = "".join(f'<li><a href="{href(f)}">{esc(_short(f, folder))}</a></li>' for f in card.files)
    summary = f"{len(card.files)} file(s) in <code>{esc(folder)}/</code>"
    return f'<details class="files"><summary>{summary}</summary><ul>{items}</ul></details>'


def _name(path: str) -> str:
    return path.rsplit("/", 1)[-1]


def _short(path: str, folder: str) -> str:
    return path[len(folder) + 1 :] if path.startswith(folder + "/") else path


def _badge(card: Card, target: str) -> str:
    verdict = card.verdicts.get(target, "-")
    cls = {"pass": "pass", "fail": "fail"}.get(verdict, "none")
    text = f"{esc(target)}: {esc(verdict)}"
    verdict_file = f"{card.folder}/verdict-{target}.json" if card.folder else None
    if verdict_file and verdict_file in card.files:
        return f'<a class="badge {cls}" href="{href(verdict_file)}">{text}</a>'
    return f'<span class="badge {cls}">{text}</span>'
