"""ASAM's own OpenSCENARIO checker, run on the emitted file.

    qc_finding(xosc_path) -> Finding     check 'asam_qc'

The ASAM Quality Checker's OpenSCENARIO XML bundle (PyPI `asam-qc-openscenarioxml`) checks what a
player needs beyond the XSD: every entityRef, actor and storyboard-element reference resolves,
element names are unique on each level, variables and parameters resolve, operators and durations
are legal. Issues of level error or warning fail the finding; so does a checker that crashes.
Rules newer than the file's version are skipped by the bundle itself and counted in the message.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType
from typing import Any

from lxml import etree
from sovarc.targets.verdict import Finding

CHECK = "asam_qc"
PACKAGE = "asam-qc-openscenarioxml"
_FAILING_LEVELS = (1, 2)  # qc_baselib IssueSeverity: ERROR, WARNING (3 is INFORMATION)


@dataclass(frozen=True)
class Issue:
    rule: str  # the rule UID's last part: 'reference_control.resolvable_entity_references'
    description: str
    where: str  # 'line 42' or an XPath, '' when the checker names no place


def qc_finding(xosc_path: str | Path, doc: etree._ElementTree | None = None) -> Finding:
    """`doc`, the file as already parsed, turns the checker's XPaths into line numbers."""
    path = Path(xosc_path)
    bundle = _bundle()
    if bundle is None:
        return Finding(CHECK, False, f"the ASAM OpenSCENARIO checker is not installed: pip install {PACKAGE}")
    ran, skipped, crashed, issues = _run(bundle, path, doc)
    if crashed:
        return Finding(CHECK, False, "ASAM checker failed to run: " + "; ".join(crashed))
    if issues:
        shown = "; ".join(f"{i.rule}: {i.description}" + (f" ({i.where})" if i.where else "") for i in issues[:5])
        more = f" (and {len(issues) - 5} more)" if len(issues) > 5 else ""
        return Finding(CHECK, False, f"ASAM Quality Checker: {len(issues)} issue(s): {shown}{more}")
    return Finding(CHECK, True, f"ASAM Quality Checker: {ran} rules pass ({skipped} not applicable)")


def _bundle() -> ModuleType | None:
    """qc_openscenario.main, imported without its import-time logging.basicConfig(INFO) taking
    over this process's root logger (it would print every rule it runs)."""
    root = logging.getLogger()
    saved = root.handlers[:], root.level
    try:
        import qc_openscenario.main as bundle
    except ImportError:
        return None
    finally:
        root.handlers[:], root.level = saved[0], saved[1]
    return bundle


def _run(bundle: ModuleType, path: Path, doc: etree._ElementTree | None) -> tuple[int, int, list[str], list[Issue]]:
    from qc_baselib import Configuration, Result, StatusType
    from qc_openscenario import constants

    config = Configuration()
    config.set_config_param("InputFile", str(path))
    result = Result()
    result.register_checker_bundle(
        name=constants.BUNDLE_NAME, description="sovarc oracle", version=constants.BUNDLE_VERSION, summary=""
    )
    result.set_result_version(version=constants.BUNDLE_VERSION)
    bundle.run_checks(config, result)

    ran = skipped = 0
    crashed: list[str] = []
    issues: list[Issue] = []
    for checker in result.get_checker_bundle_result(constants.BUNDLE_NAME).checkers:
        if checker.status == StatusType.SKIPPED:
            skipped += 1
            continue
        if checker.status == StatusType.ERROR:
            crashed.append(f"{checker.checker_id}: {checker.summary}")
            continue
        ran += 1
        issues += [_issue(i, doc) for i in checker.issues if int(i.level) in _FAILING_LEVELS]
    return ran, skipped, crashed, issues


def _issue(issue: Any, doc: etree._ElementTree | None) -> Issue:  # issue: a qc_baselib IssueType
    rows = [f.row for loc in issue.locations for f in loc.file_location if f.row is not None]
    xpaths = [x.xpath for loc in issue.locations for x in loc.xml_location]
    where = f"line {rows[0]}" if rows else _line_of(doc, xpaths[0]) if xpaths else ""
    return Issue(issue.rule_uid.rsplit(":", 1)[-1], issue.description, where)


def _line_of(doc: etree._ElementTree | None, xpath: str) -> str:
    """'line N' of the element an XPath names, or the XPath itself when it cannot be resolved."""
    try:
        found = doc.xpath(xpath) if doc is not None else []
    except etree.XPathError:
        found = []
    element = found[0] if isinstance(found, list) and found else None
    if isinstance(element, etree._Element) and element.sourceline:
        return f"line {element.sourceline}: <{element.tag}>"
    return xpath
