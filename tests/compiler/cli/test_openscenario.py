"""`sovarc REPORT -t openscenario --osc-version V`: the file written declares V and passes its oracle."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from lxml import etree
from sovarc.targets import contract, registry
from sovarc.targets.openscenario import DEFAULT_VERSION, VERSIONS, check
from sovarc.targets.openscenario.readback import read_scenario
from sovarc.targets.openscenario.validation import xsd_finding

from tests.compiler.cli.test_cli import LEFT_TURN, sovarc


def test_the_cli_offers_the_versions_the_target_writes() -> None:
    (version_flag,) = (f for f in contract.flags(registry.get("openscenario")) if f.choices)
    assert version_flag.choices == VERSIONS
    assert VERSIONS[-1] == DEFAULT_VERSION
    assert "--osc-version {1.0,1.1,1.2,1.3}" in sovarc("run", "--help").stdout.replace("\n", " ")


def test_an_unknown_version_is_a_usage_error(tmp_path: Path) -> None:
    result = sovarc(str(LEFT_TURN), "-t", "openscenario", "--osc-version", "2.0", "-o", str(tmp_path / "x"))
    assert result.returncode == 2 and "invalid choice: '2.0'" in result.stderr
    assert not (tmp_path / "x").exists()


def _header(xosc: Path) -> tuple[str, str]:
    header = etree.parse(str(xosc)).getroot().find("FileHeader")
    return header.get("revMajor"), header.get("revMinor")


@pytest.mark.slow  # lowering, synthesis and netconvert
@pytest.mark.parametrize(("args", "minor"), [((), "3"), (("--osc-version", "1.0"), "0")])
def test_the_file_declares_the_chosen_version_and_validates(tmp_path: Path, args: tuple[str, ...], minor: str) -> None:
    out = tmp_path / "out"
    result = sovarc(str(LEFT_TURN), "-t", "openscenario", *args, "-o", str(out))
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines()[0].split() == ["site", "impact", "openscenario"]
    (site,) = [p for p in out.iterdir() if p.is_dir()]
    xosc = site / "openscenario" / "scenario.xosc"
    assert _header(xosc) == ("1", minor)
    xsd = xsd_finding(read_scenario(xosc))
    assert xsd.passed and f"1.{minor}" in xsd.message, xsd.message
    written = json.loads((site / "verdict-openscenario.json").read_text())
    assert written["passed"] is True and written["facts"]["version"] == f"1.{minor}"
    assert check(xosc).passed  # the file alone, read back
