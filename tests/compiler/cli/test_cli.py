"""The `sovarc` command, run through its installed entry point as a user runs it."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.conftest import EXAMPLES

# The script installed beside this interpreter (a venv need not be on PATH), else the one on PATH.
_BESIDE = Path(sys.executable).with_name("sovarc")
SOVARC = str(_BESIDE) if _BESIDE.exists() else shutil.which("sovarc") or pytest.fail("sovarc is not installed")
SCENARIOS = sorted(str(p) for p in (EXAMPLES / "scenarios").glob("*.sov"))
LEFT_TURN = EXAMPLES / "scenarios" / "intersection_left_turn_across_path_side.sov"


def sovarc(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([SOVARC, *args], capture_output=True, text=True, cwd=cwd, timeout=60)


def test_version_and_help() -> None:
    assert sovarc("--version").stdout.strip() == "sovarc 0.1.0"
    out = sovarc("--help").stdout
    assert "sovarc check examples/scenarios/*.sov" in out and "Exit codes" in out
    for command in ("check", "fmt", "diff", "convert", "schema", "run"):
        result = sovarc(command, "--help")
        assert result.returncode == 0 and "example" in result.stdout, command


def test_help_examples_name_real_files_and_stages() -> None:
    from sovarc.compiler.pipeline import STAGE_NAMES

    texts = [sovarc("--help").stdout] + [sovarc(c, "--help").stdout for c in ("run", "check", "fmt", "extract")]
    for text in texts:
        for path in re.findall(r"(examples/[\w/.-]+\.(?:sov|txt))", text):
            assert (EXAMPLES.parent / path).exists(), path
        for stage in re.findall(r"--dump-ir-after=(\w+)", text):
            assert stage in STAGE_NAMES, stage


def test_no_command_is_a_usage_error() -> None:
    assert sovarc().returncode == 2
    assert sovarc("fmt").returncode == 2
    bad = sovarc("check", "--no-such-flag", str(LEFT_TURN))
    assert bad.returncode == 2 and "unrecognized arguments" in bad.stderr


def test_check_and_fmt_pass_on_every_example() -> None:
    checked = sovarc("check", *SCENARIOS)
    assert checked.returncode == 0, checked.stderr
    assert f"{len(SCENARIOS)} of {len(SCENARIOS)} file(s) ok" in checked.stderr
    formatted = sovarc("fmt", "--check", *SCENARIOS)
    assert formatted.returncode == 0, formatted.stderr


def test_check_reports_a_hand_broken_file_with_a_caret(tmp_path: Path) -> None:
    broken = tmp_path / "broken.sov"
    broken.write_text(LEFT_TURN.read_text().replace("turn_left", "turn_lefft"))
    result = sovarc("check", str(broken))
    assert result.returncode == 1
    lines = result.stderr.splitlines()
    assert lines[0] == f"{broken}:18:7: error: unknown action 'turn_lefft'; expected one of: " + (
        "follow_lane, turn_left, turn_right, change_lane, go_across, stop, u_turn, drive_into, "
        "drive_off, retrograde, cross, walk, reverse, parked"
    )
    assert lines[1] == "  18 |       turn_lefft"
    assert lines[2] == "     |       ^~~~~~~~~~"
    assert lines[3] == "  hint: did you mean 'turn_left'?"


def test_unreadable_inputs_get_one_clear_line(tmp_path: Path) -> None:
    (tmp_path / "empty.sov").write_text("  \n")
    (tmp_path / "binary.sov").write_bytes(b"scen\x00ario")
    (tmp_path / "latin1.sov").write_bytes("scenario caf\xe9 {}".encode("latin-1"))
    (tmp_path / "folder.sov").mkdir()
    result = sovarc("check", "empty.sov", "binary.sov", "latin1.sov", "folder.sov", "missing.sov", cwd=tmp_path)
    assert result.returncode == 1
    assert result.stderr.splitlines() == [
        "empty.sov: error: is empty",
        "binary.sov: error: is a binary file, expected a scenario file",
        "latin1.sov: error: is not valid UTF-8 (byte 0xe9 on line 1)",
        "folder.sov: error: is a directory, expected a scenario file",
        "missing.sov: error: no such file",
        "0 of 5 file(s) ok",
    ]


def test_strict_check_fails_on_warnings(tmp_path: Path) -> None:
    path = tmp_path / "w.sov"
    path.write_text(LEFT_TURN.read_text().replace("striker V2", "striker unknown"))
    assert sovarc("check", str(path)).returncode == 0
    strict = sovarc("check", "--strict", str(path))
    assert strict.returncode == 1 and "warning: the crash striker is unknown" in strict.stderr


def test_fmt_rewrites_in_place_and_leaves_canonical_files_alone(tmp_path: Path) -> None:
    messy = tmp_path / "messy.sov"
    messy.write_text(LEFT_TURN.read_text().replace("    lanes 4\n", "lanes   4\n"))
    clean = tmp_path / "clean.sov"
    shutil.copy(LEFT_TURN, clean)
    before = clean.stat().st_mtime_ns
    check = sovarc("fmt", "--check", str(messy), str(clean))
    assert check.returncode == 1 and f"would reformat {messy}" in check.stderr
    assert sovarc("fmt", str(messy), str(clean)).returncode == 0
    assert messy.read_text() == LEFT_TURN.read_text()
    assert clean.stat().st_mtime_ns == before
    assert sovarc("fmt", "--check", str(messy)).returncode == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["clean.sov", "messy.sov"]


def test_fmt_leaves_a_broken_file_untouched(tmp_path: Path) -> None:
    path = tmp_path / "b.sov"
    text = LEFT_TURN.read_text().replace("lanes 4", "lanes four;")
    path.write_text(text)
    result = sovarc("fmt", str(path))
    assert result.returncode == 1 and "unexpected character ';'" in result.stderr
    assert path.read_text() == text


def test_diff_by_meaning_text_and_json(tmp_path: Path) -> None:
    new = tmp_path / "new.sov"
    new.write_text(LEFT_TURN.read_text().replace("go_across", "turn_right"))
    result = sovarc("diff", str(LEFT_TURN), str(new))
    assert result.returncode == 0 and result.stdout == "V2 action 1: go_across → turn_right\n"
    as_json = json.loads(sovarc("diff", "--json", str(LEFT_TURN), str(new)).stdout)
    assert as_json == [
        {
            "path": "V2.actions[1]",
            "old": "go_across",
            "new": "turn_right",
            "message": "V2 action 1: go_across → turn_right",
        }
    ]
    assert sovarc("diff", "--exit-code", str(LEFT_TURN), str(new)).returncode == 1
    same = sovarc("diff", "--exit-code", str(LEFT_TURN), str(LEFT_TURN))
    assert same.returncode == 0 and same.stdout == "no semantic changes\n"


def test_convert_to_json_and_back_and_schema(tmp_path: Path) -> None:
    as_json = tmp_path / "s.json"
    assert sovarc("convert", str(LEFT_TURN), "-o", str(as_json)).returncode == 0
    back = sovarc("convert", str(as_json), "--to", "sov")
    assert back.returncode == 0
    # comments are not facts: they do not survive JSON, everything else does
    assert back.stdout == "".join(line for line in LEFT_TURN.read_text().splitlines(True) if not line.startswith("#"))
    assert sovarc("check", str(as_json)).returncode == 0
    assert sovarc("diff", str(LEFT_TURN), str(as_json)).stdout == "no semantic changes\n"
    schema = json.loads(sovarc("schema").stdout)
    assert schema["title"] == "sovarc scenario IR"
    assert sovarc("convert", str(LEFT_TURN)).returncode == 2


def test_main_job_runs_the_pipeline_and_dumps_ir(tmp_path: Path) -> None:
    result = sovarc(str(LEFT_TURN))
    assert result.returncode == 0 and result.stdout == LEFT_TURN.read_text()
    dumped = sovarc(str(LEFT_TURN), "--dump-ir-after=read", "--dump-ir-after=verify")
    assert dumped.stdout.count("// ----- IR after") == 2
    out = tmp_path / "out" / "x.sov"
    assert sovarc(str(LEFT_TURN), "-o", str(out)).returncode == 0
    assert out.read_text() == LEFT_TURN.read_text()
    assert sovarc(str(LEFT_TURN), "--dump-ir-after=nope").returncode == 2


@pytest.mark.slow
def test_main_job_stages_emits_and_checks_a_target(tmp_path: Path) -> None:
    out = tmp_path / "out"
    result = sovarc(str(LEFT_TURN), "-t", "sumo", "-o", str(out))
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines()[0].split() == ["site", "impact", "sumo"]
    assert result.stdout.splitlines()[1].endswith("pass")
    (site,) = [p for p in out.iterdir() if p.is_dir()]
    for name in ("plan.txt", "plan.json", "plan.png", "verdict-sumo.json", "sumo/scenario.sumocfg"):
        assert (site / name).is_file(), name
    assert json.loads((site / "verdict-sumo.json").read_text())["passed"] is True
    again = tmp_path / "again"
    assert sovarc(str(LEFT_TURN), "-t", "sumo", "-o", str(again)).returncode == 0
    assert (again / site.name / "plan.json").read_bytes() == (site / "plan.json").read_bytes()  # deterministic


def test_main_job_names_its_mistakes(tmp_path: Path) -> None:
    target = sovarc(str(LEFT_TURN), "-t", "carla", "-o", str(tmp_path / "x"))
    assert target.returncode == 2 and "unknown target 'carla'" in target.stderr
    assert not (tmp_path / "x").exists()
    pdf = tmp_path / "r.pdf"
    pdf.write_text("V1 struck V2.")
    kind = sovarc(str(pdf))
    assert kind.returncode == 1 and "unknown input kind '.pdf'" in kind.stderr
    assert sovarc(str(LEFT_TURN), "--llm", "gpt-9").returncode == 2


def test_main_job_errors_leave_no_output(tmp_path: Path) -> None:
    broken = tmp_path / "broken.sov"
    broken.write_text(LEFT_TURN.read_text().replace("lane 2", "lane 9", 1))
    out = tmp_path / "result.sov"
    result = sovarc(str(broken), "-o", str(out))
    assert result.returncode == 1 and "V1 starts in lane 9, but the road has 4 lanes" in result.stderr
    assert not out.exists()


def test_module_entry_point_matches_script() -> None:
    result = subprocess.run(
        [sys.executable, "-m", "sovarc.compiler.cli", "--version"], capture_output=True, text=True, timeout=60
    )
    assert result.stdout.strip() == "sovarc 0.1.0"


def test_two_reports_of_one_file_name_are_refused_before_anything_is_written(tmp_path: Path) -> None:
    """a/30.txt and b/30.txt would both become out/report_30.sov: the second would overwrite the first."""
    for folder in ("a", "b"):
        (tmp_path / folder).mkdir()
        shutil.copy(EXAMPLES / "reports" / "left_turn_oncoming_pickup.txt", tmp_path / folder / "30.txt")
    out = tmp_path / "out"
    done = sovarc("extract", str(tmp_path / "a" / "30.txt"), str(tmp_path / "b" / "30.txt"), "-o", str(out),
                  "--llm", "none")  # fmt: skip
    assert done.returncode == 2
    assert f"{tmp_path / 'a' / '30.txt'} and {tmp_path / 'b' / '30.txt'} would both be written to " in done.stderr
    assert f"{out / 'report_30.sov'}" in done.stderr
    assert not out.exists()


def test_two_truth_records_of_one_name_are_refused_before_anything_is_written(tmp_path: Path) -> None:
    record = {"weather": ["clear"], "lighting": ["bright"], "speedlimit": 0, "intersection": "no", "T": "no",
              "carCount": 2, "laneCount": 2, "striker": "V1", "impactPart": 3,
              "carInformation": {"V1": {"behaviors": [["follow lane"]], "direction": 1, "laneNumber": 1},
                                 "V2": {"behaviors": [["stop"]], "direction": 1, "laneNumber": 1}}}  # fmt: skip
    for root in ("one", "two"):
        (tmp_path / root / "t").mkdir(parents=True)
        (tmp_path / root / "t" / "3.json").write_text(json.dumps(record))
    out = tmp_path / "out"
    done = sovarc("import-truth", str(tmp_path / "one"), str(tmp_path / "two"), "-o", str(out))
    assert done.returncode == 2 and "would both be written to" in done.stderr and "t_3.sov" in done.stderr
    assert not out.exists()
