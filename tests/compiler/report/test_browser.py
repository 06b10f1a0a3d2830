"""report.html in a real browser: Debian's Chromium, headless, loads a run's page from disk. The
cards and the animations are there, every canvas drew and kept drawing, nothing failed to load,
no script error, and the screenshot shows the pictures."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest
from PIL import Image
from sovarc.compiler.plan_picture import STRIKER, VICTIM
from sovarc.compiler.report import REPORT

from tests.compiler.report.test_page import Page

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
pytestmark = [
    pytest.mark.slow,
    pytest.mark.skipif(CHROMIUM is None, reason="Chromium is not installed (apt-get install chromium)"),
]
# As root and on a closed network: no sandbox, no GPU, and none of the background calls home.
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--hide-scrollbars", "--enable-logging=stderr", "--v=0"]  # fmt: skip


def chromium(tmp_path: Path, *args: str) -> subprocess.CompletedProcess[str]:
    profile = tmp_path / f"profile-{len(list(tmp_path.glob('profile-*')))}"
    command = [str(CHROMIUM), *FLAGS, f"--user-data-dir={profile}", *args]
    return subprocess.run(command, capture_output=True, text=True, timeout=180)


def console_errors(stderr: str) -> list[str]:
    """Chromium's log lines of the page's console that say something went wrong."""
    return [
        line for line in stderr.splitlines()
        if "CONSOLE" in line and re.search(r"Uncaught|Error|Failed to load|net::ERR_", line)
    ]  # fmt: skip


def test_the_report_opens_plays_and_shows_its_cards_in_chromium(run_out: Path, tmp_path: Path) -> None:
    url = (run_out / REPORT).resolve().as_uri()
    # only the canvases on screen play (a batch's page may hold hundreds): a window tall enough for both cards
    dom = chromium(tmp_path, "--window-size=1280,4000", "--virtual-time-budget=4000", "--dump-dom", url)
    assert dom.returncode == 0, dom.stderr[-2000:]
    assert console_errors(dom.stderr) == []
    page = Page(dom.stdout)
    (body,) = page.all("body")
    assert body.get("data-errors") is None  # the page counts any script error there
    cards = page.all("article", "card")
    canvases = page.all("canvas")
    assert len(cards) == len(canvases) == 2 and body.get("data-players") == "2"
    for canvas in canvases:
        assert int(canvas["data-frames"] or 0) > 10
        assert int(canvas["data-drawn"] or 0) > 1  # drawn at load, then played on

    shot = tmp_path / "report.png"
    taken = chromium(tmp_path, "--window-size=1280,1600", f"--screenshot={shot}", "--virtual-time-budget=2000", url)
    assert taken.returncode == 0 and shot.is_file(), taken.stderr[-2000:]
    assert console_errors(taken.stderr) == []
    if os.environ.get("SOVARC_REPORT_SCREENSHOT"):  # to look at it: the path to keep a copy at
        shutil.copyfile(shot, os.environ["SOVARC_REPORT_SCREENSHOT"])
    colours = {c for _, c in Image.open(shot).convert("RGB").getcolors(maxcolors=1 << 24) or []}
    for colour in (STRIKER, VICTIM):  # the bodies, in the pictures and on the canvases
        assert tuple(int(colour[k : k + 2], 16) for k in (1, 3, 5)) in colours, colour
